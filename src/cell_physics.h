/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   Pure physics of the SPH-DEM plant cell model (Van Liedekerke et al.,
   Phys. Rev. E 81, 061906 (2010)), free of LAMMPS so tests can call it.
   Equation numbers refer to that paper; docs/model.md describes the model.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_PHYSICS_H
#define CELLMECH_CELL_PHYSICS_H

#include <cmath>

namespace CellPhysics {

constexpr double SQRT3 = 1.7320508075688772;

/* ---------------------------------------------------------------------
   Neo-Hookean tether (Eq. 19). A tether of rest length l0 in a wall of
   shear modulus G and thickness t0 carries the tension
     f(lam) = (G l0 t0 / sqrt3) (lam - lam^-5),  lam = l / l0,
   derived from the equibiaxial Neo-Hookean stress with the incompressible
   thinning l t = l0 t0 / lam (Eq. 18). Positive = tensile.
------------------------------------------------------------------------ */

// The tension's factor G l0 t0 / sqrt3, fixed for a tether: a driver may compute it once per
// tether (bond style cell/tether, per neighbour-list build) and pass it to tether_tension_scaled.
inline double tether_tension_scale(double G, double t0, double l0)
{
  return G * l0 * t0 / SQRT3;
}

inline double tether_tension_scaled(double scale, double lam)
{
  const double lam2 = lam * lam;
  const double lam5 = lam2 * lam2 * lam;
  return scale * (lam - 1.0 / lam5);
}

inline double tether_tension(double G, double t0, double l0, double lam)
{
  return tether_tension_scaled(tether_tension_scale(G, t0, l0), lam);
}

// Energy is the exact integral of the tension over l = lam l0, zero at rest, so that
// minimisation and energy conservation see the same law as the dynamics:
//   U = (G t0 l0^2 / sqrt3) [(u - 1)/2 + (u^-2 - 1)/4] = (G t0 l0^2 / sqrt3) (u-1)^2 (2u+1) / (4u^2),
// u = lam^2. The factored form avoids the cancellation of the first near rest.
inline double tether_energy(double G, double t0, double l0, double lam)
{
  const double u = lam * lam;
  const double um1 = (lam - 1.0) * (lam + 1.0);
  return G * t0 * l0 * l0 / SQRT3 * um1 * um1 * (2.0 * u + 1.0) / (4.0 * u * u);
}

// Small-strain stiffness d f / d l at lam = 1 (Eq. 20): 6 G t0 / sqrt3, independent of l0.
inline double tether_stiffness(double G, double t0)
{
  return 6.0 * G * t0 / SQRT3;
}

// Membrane tension (force per length) of an equilateral tether network under equibiaxial
// stretch lam: T = sqrt3 f / l = G t0 (1 - lam^-6), the Neo-Hookean sheet of Eq. 15
// with t = t0 / lam^2. Used for Young-Laplace checks: P R / 2 = T.
inline double equibiaxial_tension(double G, double t0, double lam)
{
  const double lam2 = lam * lam;
  return G * t0 * (1.0 - 1.0 / (lam2 * lam2 * lam2));
}

/* ---------------------------------------------------------------------
   8-4 excluded-volume repulsion (Eq. 12), cut at r0 (repulsive part only):
     F_vec = f0 [(r0/r)^8 - (r0/r)^4] / r^2 * r_vec
   repulsion84_fpair returns the factor multiplying r_vec (LAMMPS "fpair").
------------------------------------------------------------------------ */

inline double repulsion84_fpair(double f0, double r0, double rsq)
{
  if (rsq >= r0 * r0) return 0.0;
  const double s2 = r0 * r0 / rsq;
  const double s4 = s2 * s2;
  return f0 * (s4 * s4 - s4) / rsq;
}

// Energy shifted to vanish at the cutoff r0: E = f0 [s^8/8 - s^4/4 + 1/8], s = r0 / r.
inline double repulsion84_energy(double f0, double r0, double rsq)
{
  if (rsq >= r0 * r0) return 0.0;
  const double s2 = r0 * r0 / rsq;
  const double s4 = s2 * s2;
  return f0 * (0.125 * s4 * s4 - 0.25 * s4 + 0.125);
}

/* ---------------------------------------------------------------------
   Damping (Eq. 11): -gamma v_ij on a bonded pair (wall tethers, lamella
   bonds) and the contact damping f'_k v_ik of an 8-4 contact, both taken
   along the line of centres so that, like the elastic forces, they conserve
   angular momentum. damping_fpair returns the factor multiplying
   r_ij = x_i - x_j in the force on i (LAMMPS "fpair"):
     F_i = -gamma (v_ij . r_ij) / r^2 r_ij = -gamma (v_ij . e_ij) e_ij,
   with rdotv = r_ij . v_ij. It dissipates -gamma (v_ij . e_ij)^2 <= 0.
------------------------------------------------------------------------ */

inline double damping_fpair(double gamma, double rdotv, double rsq)
{
  return -gamma * rdotv / rsq;
}

/* ---------------------------------------------------------------------
   Thin spherical shell, breathing mode in vacuo (Eq. A5):
     omega = (1/R) sqrt(4 E / rho_s),  rho_s = M_wall / (4 pi R^2 t0).
------------------------------------------------------------------------ */

inline double breathing_omega_vacuo(double E, double R, double wall_mass, double t0)
{
  const double rho_s = wall_mass / (4.0 * M_PI * R * R * t0);
  return std::sqrt(4.0 * E / rho_s) / R;
}

/* Uniaxial stretch of a flat tether sheet (paper, Appendix 1): boundary force for a sheet
   whose loaded edge has length L0. Eq. A1 and Eq. A2 as printed in the paper. */
inline double sheet_force_A1(double G, double L0, double t0, double lam)
{
  return G * L0 * t0 * (lam * lam - 1.0 / (lam * lam));
}

inline double sheet_force_A2(double G, double L0, double t0, double lam)
{
  return G * L0 * t0 * (lam * lam - 1.0 / lam) * std::sqrt(lam);
}

/* ---------------------------------------------------------------------
   SPH protoplasm (Eqs. 3-10)
------------------------------------------------------------------------ */

// Cubic-spline kernel of smoothing length s, support 2s. Eq. 3 (unit integral) fixes the
// prefactor at 3 / (2 pi s^3) for this bracket; the 2 / (3 pi s^3) printed in Eq. 4 does not
// integrate to one (docs/model.md, section 5).
inline double kernel_w(double r, double s)
{
  const double q = r / s;
  const double norm = 3.0 / (2.0 * M_PI * s * s * s);
  if (q < 1.0) return norm * (2.0 / 3.0 - q * q + 0.5 * q * q * q);
  if (q < 2.0) {
    const double u = 2.0 - q;
    return norm * u * u * u / 6.0;
  }
  return 0.0;
}

// dW/dr; the gradient is dW/dr times the unit vector r_ij / r. Its prefactor depends on s only: a
// pair loop computes it once per type pair (kernel_dwdr_norm) and passes it, with the same bits.
inline double kernel_dwdr_norm(double s)
{
  return 3.0 / (2.0 * M_PI * s * s * s * s);
}

inline double kernel_dwdr(double r, double s, double norm)
{
  const double q = r / s;
  if (q < 1.0) return norm * (-2.0 * q + 1.5 * q * q);
  if (q < 2.0) {
    const double u = 2.0 - q;
    return -norm * 0.5 * u * u;
  }
  return 0.0;
}

inline double kernel_dwdr(double r, double s)
{
  return kernel_dwdr(r, s, kernel_dwdr_norm(s));
}

// (dW/dr) / r from r^2: the factor wr of grad_i W_ij = wr r_ij (Eq. 5, Eq. 7) that the pair loops
// use, with 1/s and kernel_wr_norm(s) = kernel_dwdr_norm(s) / s of the type pair computed once.
// Inside q < 1 the 1/r cancels, so no division is left there; both brackets are evaluated and one
// is selected, with no branch, so that a loop over pairs calling it runs in SIMD lanes. It equals
// kernel_dwdr(r, s) / r to a few ulp, not bit for bit (tests/unit: Kernel.PairFactorIsdWdrOverR).
inline double kernel_wr_norm(double s)
{
  return kernel_dwdr_norm(s) / s;
}

inline double kernel_wr(double rsq, double inv_s, double wr_norm)
{
  const double q = std::sqrt(rsq) * inv_s;
  const double u = 2.0 - q;
  const double inner = wr_norm * (-2.0 + 1.5 * q);
  const double outer = -wr_norm * 0.5 * u * u / q;
  return q < 1.0 ? inner : (q < 2.0 ? outer : 0.0);
}

// Tait equation of state with background turgor P0 (Eq. 6), kappa = rho0 c^2 / 7.
// A driver computes kappa once per fluid type and calls tait_pressure_kappa once per particle.
inline double tait_kappa(double rho0, double c)
{
  return rho0 * c * c / 7.0;
}

inline double tait_pressure_kappa(double rho, double rho0, double kappa, double P0)
{
  const double x = rho / rho0;
  const double x2 = x * x;
  const double x7 = x2 * x2 * x2 * x;
  return P0 + kappa * (x7 - 1.0);
}

inline double tait_pressure(double rho, double rho0, double c, double P0)
{
  return tait_pressure_kappa(rho, rho0, tait_kappa(rho0, c), P0);
}

// dP/drho of the Tait law: c^2 (rho/rho0)^6, the squared local sound speed.
inline double tait_dpdrho(double rho, double rho0, double c)
{
  const double x = rho / rho0;
  const double x2 = x * x;
  return c * c * x2 * x2 * x2;
}

// Internal energy per mass of the Tait fluid (Eq. 6), e(rho) = int_rho0^rho P(r) / r^2 dr, zero at
// rho0. With de/drho = P / rho^2 the pressure force of Eq. 5 and the continuity rate of Eq. 7
// conserve kinetic + internal energy of the inviscid fluid: the pair energy of pair cell/sph.
inline double tait_internal_energy(double rho, double rho0, double c, double P0)
{
  const double k = rho0 * c * c / 7.0;
  const double r6 = std::pow(rho / rho0, 6.0);
  return (P0 - k) * (1.0 / rho0 - 1.0 / rho) + k / rho0 * (r6 - 1.0) / 6.0;
}

// SPH pair force (Eq. 5) on particle i from j, F_ij = fp r_ij + fv v_ij with r_ij = x_i - x_j,
// v_ij = v_i - v_j and grad_i W_ij = wr r_ij, wr = (dW/dr) / r (kernel_wr). The pressure part fp
// is central, with prho2 = P / rho^2 of each particle (computed once per particle):
inline double sph_pressure_fpair(double mi, double mj, double prho2_i, double prho2_j, double wr)
{
  return -mi * mj * (prho2_i + prho2_j) * wr;
}

// and the Morris laminar viscosity of Eq. 5 acts along v_ij: fv = m_i m_j (mu_i + mu_j) /
// (rho_i rho_j) wr, here from the inverse densities 1/rho_i, 1/rho_j, which a pair loop computes
// once per particle (no division per pair; the quotient form to a few roundings, tests/unit).
// Both parts are symmetric in i, j, so F_ji = -F_ij (momentum is conserved); wr <= 0 makes
// fv v_ij . v_ij <= 0 (the viscosity only dissipates).
inline double sph_viscous_fvel(double mi, double mj, double mu_i, double mu_j, double inv_rho_i,
                               double inv_rho_j, double wr)
{
  return mi * mj * (mu_i + mu_j) * (inv_rho_i * inv_rho_j) * wr;
}

// One pair's term of the continuity equation (Eq. 7): v_ij . grad_i W_ij, with dv = v_i - v_j and
// del = x_i - x_j. drho_i/dt gains m_j times it and drho_j/dt m_i times it (grad_j W_ji =
// -grad_i W_ij and v_ji = -v_ij).
inline double continuity_term(double dvx, double dvy, double dvz, double delx, double dely,
                              double delz, double wr)
{
  return (dvx * delx + dvy * dely + dvz * delz) * wr;
}

// Density change over a step dt (Eq. 9): the continuity rate drho_dt (Eq. 7) plus the density
// the mass change dm brings at constant particle volume, (rho / m) dm, from rho = m / V (Eq. 8).
// With drho_dt = 0 the particle's volume m / rho is kept to round-off.
inline double density_increment(double rho, double m, double drho_dt, double dt, double dm)
{
  return dt * drho_dt + rho / m * dm;
}

// Coefficient k = A_c L_p rho / N_f of the osmotic exchange of one fluid particle (Eq. 10):
// dm/dt = -k (P + Pi). A_c is the current wall area of its cell, N_f the cell's fluid count.
inline double osmotic_coefficient(double area, double Lp, double rho, double nfluid)
{
  return area * Lp * rho / nfluid;
}

// Osmotic mass rate of one fluid particle (Eq. 10): dm/dt = -(A_c L_p rho / N_f)(P + Pi), with
// Pi < 0 the osmotic potential; water flows in while P < -Pi.
inline double osmotic_mass_rate(double area, double Lp, double rho, int nfluid, double P, double Pi)
{
  return -osmotic_coefficient(area, Lp, rho, nfluid) * (P + Pi);
}

// Mass taken up in one step dt by a particle of mass m and density rho at pressure P, with
// k = A_c L_p rho / N_f: Eq. 10 linearised in the step's own mass change,
//   dm = -k dt (P + Pi + dP/drho (rho/m) dm),
// because the uptake raises the density (Eq. 9) and so the pressure. Explicit Euler diverges once
// k dt dP/drho rho/m > 2, i.e. for the large conductivities that inflate a cell quickly. This form
// tends to Eq. 10 as k dt -> 0 and, as k dt -> infinity, becomes a Newton step towards P = -Pi:
// the error contracts every step for any k dt (the convex Tait law makes the first large step
// overshoot by its curvature, 1.4% from 0 to 364 kPa, which the next steps remove).
inline double osmotic_mass_step(double k, double dt, double P, double Pi, double dPdrho, double rho,
                                double m)
{
  return -k * dt * (P + Pi) / (1.0 + k * dt * dPdrho * rho / m);
}

/* ---------------------------------------------------------------------
   Water in a tissue (fix cell/fluid options solute, exchange, external;
   not in the paper, which has one cell in pure water: docs/fix_cell_fluid.rst)
------------------------------------------------------------------------ */

// Solutes kept in their cell (Eq. W1, Boyle-van 't Hoff): the osmotic potential is proportional to
// the solute concentration, so Pi W = Pi0 W0 with W the cell's water (fluid) mass.
inline double solute_osmotic_potential(double Pi0, double W0, double W)
{
  return Pi0 * W0 / W;
}

// Conductivity of the wall two cells share (Eq. W2): water crosses both cells' walls in series,
// 1/Lp = 1/Lp_a + 1/Lp_b; zero when either wall is closed to water.
inline double series_conductivity(double Lp_a, double Lp_b)
{
  return (Lp_a > 0.0 && Lp_b > 0.0) ? Lp_a * Lp_b / (Lp_a + Lp_b) : 0.0;
}

// Mass that cell a gives cell b in one step dt (Eq. W3): dM_b/dt = -dM_a/dt = k (psi_a - psi_b),
// k = A_ab Lp_ab rho, psi = P + Pi the water potentials, linearised in the step's own effect on
// them as osmotic_mass_step is (dpsi/dM of each cell, > 0: a cell's potential rises as it gains
// water), so that a large k dt brings the two potentials together without overshoot.
inline double exchange_mass_step(double k, double dt, double psi_a, double psi_b, double dpsi_dM_a,
                                 double dpsi_dM_b)
{
  return k * dt * (psi_a - psi_b) / (1.0 + k * dt * (dpsi_dM_a + dpsi_dM_b));
}

// Wall area of a cell open to the outside by Eq. W4's 'exposed unglued' (every space between cells
// counts as outside): the current area A less the glued part, whose rest area A_glued_ref (the
// lamella areas d_alam) is scaled by the wall's areal stretch A / A_ref (A_ref the rest area of its
// triangles); never below zero.
inline double exposed_area(double A, double A_ref, double A_glued_ref)
{
  if (A_ref <= 0.0) return A;
  const double open = 1.0 - A_glued_ref / A_ref;
  return open > 0.0 ? A * open : 0.0;
}

// Whether a point at offset d from the centroid of a wall triangle (unit outward normal n, longest
// edge h) lies in front of it, so that a wall through that point hides the triangle from the
// outside (Eq. W4, exposed outside): on its outer side (d.n > 0) within 45 degrees of the normal,
// or, close to the wall, within h of the normal line. The cone alone would miss a facing wall
// nearer than its node spacing (the glued walls are 2.56 um apart, the coarse nodes 3.3-5.5 um):
// the normal line crosses that wall inside one of its triangles, within h/sqrt(3) of a node.
inline bool hides_triangle(const double *d, const double *n, double h)
{
  const double s = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
  if (s <= 0.0) return false;
  const double lateral2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - s * s;
  const double r = s > h ? s : h;
  return lateral2 <= r * r;
}

/* ---------------------------------------------------------------------
   Triangulated closed surfaces
------------------------------------------------------------------------ */

// Area of the triangle spanned by edge vectors u and w from one vertex.
inline double triangle_area(const double *u, const double *w)
{
  const double cx = u[1] * w[2] - u[2] * w[1];
  const double cy = u[2] * w[0] - u[0] * w[2];
  const double cz = u[0] * w[1] - u[1] * w[0];
  return 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
}

// Signed volume of the cone from the origin over the triangle (a, a + u, a + w): a . (u x w) / 6.
// Summed over a closed mesh whose triangles are in right-hand order seen from outside (outward
// normals, the contract of cell_fields.h) it is the enclosed volume (divergence theorem).
inline double cone_volume(const double *a, const double *u, const double *w)
{
  const double cx = u[1] * w[2] - u[2] * w[1];
  const double cy = u[2] * w[0] - u[0] * w[2];
  const double cz = u[0] * w[1] - u[1] * w[0];
  return (a[0] * cx + a[1] * cy + a[2] * cz) / 6.0;
}

// Signed solid angle of triangle (a, b, c) seen from the origin (van Oosterom & Strackee 1983).
// Summed over a closed outward-oriented mesh it is 4 pi for a point inside, 0 outside.
inline double solid_angle(const double *a, const double *b, const double *c)
{
  const double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  const double lc = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  const double bxc[3] = {b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2],
                         b[0] * c[1] - b[1] * c[0]};
  const double num = a[0] * bxc[0] + a[1] * bxc[1] + a[2] * bxc[2];
  const double ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const double ac = a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
  const double bc = b[0] * c[0] + b[1] * c[1] + b[2] * c[2];
  const double den = la * lb * lc + ab * lc + ac * lb + bc * la;
  return 2.0 * std::atan2(num, den);
}

// Squared distance from the origin to triangle (a, b, c): the closest point by Voronoi regions of
// the vertices, edges and face (Ericson, Real-Time Collision Detection, 5.1.5).
inline double origin_triangle_dist_sq(const double *a, const double *b, const double *c)
{
  auto dot = [](const double *u, const double *v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  };
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double ap[3] = {-a[0], -a[1], -a[2]};
  const double bp[3] = {-b[0], -b[1], -b[2]};
  const double cp[3] = {-c[0], -c[1], -c[2]};
  double q[3];
  auto at = [&](double u, double v) {    // a + u ab + v ac
    for (int d = 0; d < 3; d++) q[d] = a[d] + u * ab[d] + v * ac[d];
    return dot(q, q);
  };
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return dot(a, a);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return dot(b, b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return at(d1 / (d1 - d3), 0.0);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return dot(c, c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return at(0.0, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return at(1.0 - w, w);
  }
  const double den = 1.0 / (va + vb + vc);
  return at(vb * den, vc * den);
}

/* ---------------------------------------------------------------------
   Observables of the paper
------------------------------------------------------------------------ */

// Equatorial force (Eq. 23): the internal force that the bonds crossing the plane through the
// cell centre carry from one hemisphere to the other. The hemisphere is the nodes at height
// s = (x - centre) . n > 0, so a node on the plane belongs to exactly one side.
inline bool crosses_equator(double s1, double s2)
{
  return (s1 > 0.0) != (s2 > 0.0);
}

// One bond's share of Eq. 23: the force on the node above the plane from the one below, along
// -n; positive in tension. fpair is the bond's force factor (force on node 1 = fpair (x1 - x2),
// negative in tension), dn = (x1 - x2) . n, s1 and s2 the nodes' heights. Zero if the bond does
// not cross, and the same whichever node is called 1.
inline double equatorial_force_term(double fpair, double dn, double s1, double s2)
{
  if (!crosses_equator(s1, s2)) return 0.0;
  return (s1 > s2) ? -fpair * dn : fpair * dn;
}

// A membrane triangle's share of Eq. 23 (angle style cell/membrane): the force its element
// exerts on its nodes above the plane, along -n; positive in tension. f[k] are the element's
// forces on its three nodes (summing to zero), s[k] the nodes' heights. Zero for a triangle
// wholly on one side; for forces that are pair forces along the edges it is the sum of the
// edges' equatorial_force_term.
inline double equatorial_force_triangle(const double f[3][3], const double s[3], const double n[3])
{
  double share = 0.0;
  for (int k = 0; k < 3; k++)
    if (s[k] > 0.0) share -= f[k][0] * n[0] + f[k][1] * n[1] + f[k][2] * n[2];
  return share;
}

// Protoplasm shear stress (Eqs. 24-26). Eq. 25 estimates the velocity gradient of particle i as
//   g[a][b] = sum_j (m_j / rho_j) v_ji^b dW_ij/dx_i^a,  v_ji = v_j - v_i,
// with dW_ij/dx_i^a = (dW/dr / r) del^a, del = x_i - x_j; this adds neighbour j's term with
// w = (m_j / rho_j) (dW/dr) / r.
inline void velocity_gradient_add(double g[3][3], double w, const double *del, const double *vji)
{
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) g[a][b] += w * del[a] * vji[b];
}

// Off-diagonal viscous stress tau^ab = mu (dv^b/dx^a + dv^a/dx^b) (Eq. 24) from that gradient.
inline double viscous_shear(double mu, const double g[3][3], int a, int b)
{
  return mu * (g[a][b] + g[b][a]);
}

// Total effective shear stress (Eq. 26).
inline double shear_stress_magnitude(double txy, double txz, double tyz)
{
  return std::sqrt(txy * txy + txz * txz + tyz * tyz);
}

/* ---------------------------------------------------------------------
   Middle lamella: cohesive traction-separation law between the walls of
   two neighbouring cells (exponential law of Xu & Needleman, J. Mech. Phys.
   Solids 42, 1397 (1994), normal opening only). A lamella bond carries the
   traction T (force per area, positive = tensile) at the opening
   delta = r - r_rest:
     T = sigma_c (delta/delta_c) exp(1 - delta/delta_c),   delta >= 0   (Eq. L1)
     T = sigma_c e delta/delta_c,                          delta <  0   (Eq. L2)
   The peak sigma_c is reached at delta_c; the compressive branch continues
   the initial stiffness sigma_c e / delta_c linearly. The bond breaks once
   delta > COHESIVE_BREAK delta_c (Eq. L4), where the traction has fallen to
   10 e^-9 sigma_c = 1.2e-3 sigma_c.
------------------------------------------------------------------------ */

constexpr double COHESIVE_BREAK = 10.0;    // break opening in units of delta_c (Eq. L4)

// Opening above which a bond of characteristic opening delta_c is broken (Eq. L4).
inline double cohesive_break_opening(double delta_c)
{
  return COHESIVE_BREAK * delta_c;
}

// Work per area to open a bond from 0 to the break, in units of sigma_c e delta_c:
// integral_0^10 x e^-x dx = 1 - 11 e^-10.
inline double cohesive_work_fraction()
{
  return 1.0 - (1.0 + COHESIVE_BREAK) * std::exp(-COHESIVE_BREAK);
}

// Characteristic opening delta_c chosen so that the work to break a bond is exactly the
// fracture energy Gc (Eq. L3): Gc = sigma_c e delta_c (1 - 11 e^-10). Cutting the exponential
// tail at 10 delta_c would otherwise lose 5e-4 of Gc.
inline double cohesive_length(double sigma_c, double Gc)
{
  return Gc / (sigma_c * M_E * cohesive_work_fraction());
}

// Traction at the opening delta (Eqs. L1, L2).
inline double cohesive_traction(double sigma_c, double delta_c, double delta)
{
  const double x = delta / delta_c;
  if (x < 0.0) return sigma_c * M_E * x;
  return sigma_c * x * std::exp(1.0 - x);
}

// Energy per area, the exact integral of the traction from 0 to delta (Eq. L5):
//   E = sigma_c e delta_c [1 - (1 + x) e^-x],  x = delta/delta_c >= 0
//   E = sigma_c e delta_c x^2 / 2,             x < 0
// equal to Gc at the break. 1 - (1 + x) e^-x = e^-x (e^x - 1 - x) loses all its digits to
// cancellation as x -> 0 (it is x^2/2 there), so small openings sum the series of e^x - 1 - x;
// the forces are then derivatives of the energy to round-off at every opening.
inline double cohesive_energy(double sigma_c, double delta_c, double delta)
{
  const double x = delta / delta_c;
  const double scale = sigma_c * M_E * delta_c;
  if (x < 0.0) return 0.5 * scale * x * x;
  if (x < 0.5) {
    double term = 0.5 * x * x, sum = term;
    for (int k = 3; term > 1e-17 * sum; k++) {
      term *= x / k;
      sum += term;
    }
    return scale * std::exp(-x) * sum;
  }
  return scale * (1.0 - (1.0 + x) * std::exp(-x));
}

/* ---------------------------------------------------------------------
   Membrane wall (angle style cell/membrane): the incompressible thin
   Neo-Hookean sheet that the paper's tethers stand for (Eq. 15), on each
   wall triangle as a constant-strain element. Eqs. M1-M2 are the package's
   own numbering (docs/angle_cell_membrane.rst). The triangle a-b-c has reference edges A = X_a - X_b,
   C = X_c - X_b and current edges a = x_a - x_b, c = x_c - x_b. In an
   orthonormal frame (e1, e2) of the reference plane the reference edges are
   the columns of the 2x2 matrix D; the 3x2 deformation gradient is
   F = [a c] D^-1 and C2 = F^T F its in-plane right Cauchy-Green tensor.
   Incompressibility gives the thickness stretch lam3^2 = 1 / det C2, so
     W = (G t0 A0 / 2) (tr C2 + 1 / det C2 - 3)                    (Eq. M1)
   per triangle of reference area A0 (G the shear modulus, E = 3G).
   Its exact gradient with respect to the current edges is
     dW/d[a c] = G t0 A0 F (I - C2^-1 / det C2) D^-T                 (Eq. M2)
   so that the forces are f_a = -dW/da, f_c = -dW/dc, f_b = -(f_a + f_c):
   they sum to zero, and W depends on F only through C2, so rigid motion
   costs nothing and angular momentum is conserved.
------------------------------------------------------------------------ */

// Reference shape of a triangle: D^-1 (row-major 2x2) and the area A0. Returns false for a
// reference triangle without area (collinear or coincident nodes).
struct MembraneRest {
  double e1[3], e2[3];    // orthonormal frame of the reference plane (diagnostics)
  double Dinv[2][2];
  double area;
};

inline bool membrane_rest(const double A[3], const double C[3], MembraneRest &rest)
{
  const double la = std::sqrt(A[0] * A[0] + A[1] * A[1] + A[2] * A[2]);
  const double n[3] = {A[1] * C[2] - A[2] * C[1], A[2] * C[0] - A[0] * C[2],
                       A[0] * C[1] - A[1] * C[0]};
  const double ln = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  // relative to the edge lengths, so that the test does not depend on the units
  const double lc = std::sqrt(C[0] * C[0] + C[1] * C[1] + C[2] * C[2]);
  if (!(la > 0.0) || !(ln > 1e-12 * la * lc)) return false;
  for (int d = 0; d < 3; d++) rest.e1[d] = A[d] / la;
  // e2 = (n / |n|) x e1
  rest.e2[0] = (n[1] * rest.e1[2] - n[2] * rest.e1[1]) / ln;
  rest.e2[1] = (n[2] * rest.e1[0] - n[0] * rest.e1[2]) / ln;
  rest.e2[2] = (n[0] * rest.e1[1] - n[1] * rest.e1[0]) / ln;
  // D = [[A.e1, C.e1], [0, C.e2]] is upper triangular
  const double d11 = la, d12 = C[0] * rest.e1[0] + C[1] * rest.e1[1] + C[2] * rest.e1[2];
  const double d22 = C[0] * rest.e2[0] + C[1] * rest.e2[1] + C[2] * rest.e2[2];
  rest.Dinv[0][0] = 1.0 / d11;
  rest.Dinv[0][1] = -d12 / (d11 * d22);
  rest.Dinv[1][0] = 0.0;
  rest.Dinv[1][1] = 1.0 / d22;
  rest.area = 0.5 * ln;
  return true;
}

// In-plane invariants of the current edges a, c against the rest shape: C2 = F^T F.
struct MembraneStrain {
  double F[3][2];     // deformation gradient (current 3D vectors per reference direction)
  double C2[2][2];    // right Cauchy-Green tensor, in the reference frame
  double J2;          // det C2 = (current area / reference area)^2
};

inline void membrane_strain(const MembraneRest &rest, const double a[3], const double c[3],
                            MembraneStrain &s)
{
  for (int d = 0; d < 3; d++) {
    s.F[d][0] = a[d] * rest.Dinv[0][0] + c[d] * rest.Dinv[1][0];
    s.F[d][1] = a[d] * rest.Dinv[0][1] + c[d] * rest.Dinv[1][1];
  }
  for (int p = 0; p < 2; p++)
    for (int q = 0; q < 2; q++)
      s.C2[p][q] = s.F[0][p] * s.F[0][q] + s.F[1][p] * s.F[1][q] + s.F[2][p] * s.F[2][q];
  s.J2 = s.C2[0][0] * s.C2[1][1] - s.C2[0][1] * s.C2[1][0];
}

/* Tension-field theory (Eq. M3): a wall much thinner than a triangle wrinkles at a scale below the
   mesh rather than carry compression, so with `wrinkle yes` the element stores Pipkin's relaxed
   energy (Pipkin, IMA J. Appl. Math. 36, 85 (1986)) of the sheet, with principal stretches
   lam1 >= lam2:
     taut      lam2 >= lam1^-1/2:          W of Eq. M1
     wrinkled  lam1 > 1, lam2 < lam1^-1/2: W = (G t0 A0 / 2) (lam1^2 + 2 / lam1 - 3)   (Eq. M3)
     slack     lam1 <= 1:                  W = 0
   The wrinkled energy is the sheet's in uniaxial tension with free sides, where the minor tension
   vanishes (lam2 = lam1^-1/2), so the stress is continuous across every boundary: a tension field
   along the major direction v only. This is the membrane that the quasistatic reference
   (tools/membrane.py) solves, whose contact disc lies slack on the plate. */

// The response of the triangle as P = G t0 A0 F K (first Piola stress times volume, K a symmetric
// 2x2 in the reference frame) and W = G t0 A0 dev / 2. Without relax, K = I - C2^-1 / det C2
// (Eq. M2) and dev = I1 - 3 (Eq. M1), formed from the deviations so that it keeps its digits near
// rest; with relax, Eq. M3.
// The larger eigenvalue of C2, lam1^2 (the principal stretches: membrane_stretches).
inline double membrane_major(const MembraneStrain &s)
{
  const double tr = s.C2[0][0] + s.C2[1][1];
  const double dif = s.C2[0][0] - s.C2[1][1];
  const double root = std::sqrt(0.25 * dif * dif + s.C2[0][1] * s.C2[1][0]);
  return 0.5 * tr + root;
}

inline void membrane_response(const MembraneStrain &s, bool relax, double K[2][2], double &dev)
{
  if (relax) {
    const double off = s.C2[0][1];
    const double e1 = membrane_major(s);    // lam1^2
    const double lam1 = std::sqrt(e1);
    if (!(lam1 > 1.0)) {    // slack
      K[0][0] = K[0][1] = K[1][0] = K[1][1] = 0.0;
      dev = 0.0;
      return;
    }
    // lam2^2 lam1 < 1 (with lam2^2 = J2 / e1): wrinkled
    if (s.J2 < lam1) {
      // unit eigenvector of C2 for e1; of the two equivalent forms the longer one keeps its digits
      double v0 = off, v1 = e1 - s.C2[0][0];
      const double w0 = e1 - s.C2[1][1], w1 = off;
      if (w0 * w0 + w1 * w1 > v0 * v0 + v1 * v1) {
        v0 = w0;
        v1 = w1;
      }
      const double vn = std::sqrt(v0 * v0 + v1 * v1);
      if (vn > 0.0) {
        v0 /= vn;
        v1 /= vn;
      } else {    // e1 = e2 cannot be wrinkled (lam1 > 1 >= lam2); kept for safety
        v0 = 1.0;
        v1 = 0.0;
      }
      // dW/dC2 = (G t0 A0 / 2) (1 - lam1^-3) v v^T, and P = 2 F dW/dC2
      const double k = 1.0 - 1.0 / (e1 * lam1);
      K[0][0] = k * v0 * v0;
      K[0][1] = K[1][0] = k * v0 * v1;
      K[1][1] = k * v1 * v1;
      dev = (e1 - 1.0) + 2.0 * (1.0 - lam1) / lam1;
      return;
    }
  }
  // C2^-1 / det C2 = adj(C2) / J2^2
  const double inv = 1.0 / (s.J2 * s.J2);
  K[0][0] = 1.0 - s.C2[1][1] * inv;
  K[0][1] = s.C2[0][1] * inv;
  K[1][0] = s.C2[1][0] * inv;
  K[1][1] = 1.0 - s.C2[0][0] * inv;
  dev = (s.C2[0][0] - 1.0) + (s.C2[1][1] - 1.0) + (1.0 - s.J2) / s.J2;
}

// Energy of the triangle (Eq. M1, or Eq. M3 with relax).
inline double membrane_energy(double G, double t0, const MembraneRest &rest,
                              const MembraneStrain &s, bool relax = false)
{
  double K[2][2], dev;
  membrane_response(s, relax, K, dev);
  return 0.5 * G * t0 * rest.area * dev;
}

// Forces on the two outer nodes of the triangle (Eq. M2, or the gradient of Eq. M3 with relax):
// fa = -dW/da, fc = -dW/dc; the central node takes -(fa + fc). Needs J2 > 0 (a triangle with
// area). Returns the energy W, which the response gives at no extra cost.
inline double membrane_forces(double G, double t0, const MembraneRest &rest,
                              const MembraneStrain &s, double fa[3], double fc[3],
                              bool relax = false)
{
  double K[2][2], dev;
  membrane_response(s, relax, K, dev);
  const double k = G * t0 * rest.area;
  for (int d = 0; d < 3; d++) {
    // P = k F K (first Piola stress times volume), then dW/d[a c] = P D^-T
    const double P0 = k * (s.F[d][0] * K[0][0] + s.F[d][1] * K[1][0]);
    const double P1 = k * (s.F[d][0] * K[0][1] + s.F[d][1] * K[1][1]);
    fa[d] = -(P0 * rest.Dinv[0][0] + P1 * rest.Dinv[0][1]);
    fc[d] = -(P0 * rest.Dinv[1][0] + P1 * rest.Dinv[1][1]);
  }
  return 0.5 * G * t0 * rest.area * dev;    // as membrane_energy, to the bit
}

// Principal in-plane stretches (lam1 >= lam2) of the triangle: square roots of the eigenvalues
// of C2 (for failure by the largest stretch and for diagnostics).
inline void membrane_stretches(const MembraneStrain &s, double &lam1, double &lam2)
{
  const double e1 = membrane_major(s);
  lam1 = std::sqrt(e1);
  lam2 = std::sqrt(s.J2 / e1);
}

/* ---------------------------------------------------------------------
   Bending of the wall (dihedral style cell/bending), the package's own
   Eqs. B1-B3 (docs/dihedral_cell_bending.rst). A hinge is a LAMMPS dihedral
   i-j-k-l: two wall triangles (i, j, k) and (j, k, l) sharing the edge j-k.
   The wall is a plate of bending stiffness
     D = E t0^3 / (12 (1 - nu^2)) = G t0^3 / 3,  E = 3G, nu = 1/2     (Eq. B1)
   and each hinge stores the discrete-shells energy (Grinspun et al. 2003)
     W = (D / 2) (phi - phi0)^2 |e0|^2 / A0                            (Eq. B2)
   with phi the dihedral angle, phi0 its rest value from the reference
   positions, |e0| the rest length of the shared edge and A0 the rest area
   of both triangles together. The forces are its exact gradient,
     f_a = -D (phi - phi0) |e0|^2 / A0  dphi/dx_a                     (Eq. B3)
   with the dihedral-angle derivatives of Blondel & Karplus (J. Comput.
   Chem. 17, 1132 (1996)).
   Why the prefactor is D / 2: on a mesh of equilateral triangles of side h
   whose nodes move onto a smooth surface, a hinge's angle changes by
     phi - phi0 = h (3 kn - kt) / (2 sqrt3)
   (its four nodes on the quadratic surface; kn, kt the changes of normal
   curvature across and along its edge), |e0|^2 / A0 = 2 / sqrt3, and there
   are 2 sqrt3 / h^2 edges per area in three directions 60 degrees apart.
   Averaged over them, the energy k (phi - phi0)^2 |e0|^2 / A0 tends to the density
     k [(k1 + k2)^2 - (8/3) k1 k2]       (k1, k2 principal changes)
   (3 |e|^2 / A on a sphere gives the Willmore density (k1 + k2)^2, as
   Wardetzky et al. 2007 state), against the plate's (D / 2) [(k1 + k2)^2 -
   2 (1 - nu) k1 k2]. k = D / 2 makes the two equal for every bending
   without Gaussian curvature (a plate bent onto a cylinder of radius R
   stores D / (2 R^2) per area, whatever the mesh orientation) and in the
   mean-curvature term of any bending. The Gaussian term is that of nu =
   -1/3, not 1/2; no single hinge constant matches both: an equal change of
   both curvatures (a sphere's) stores 4/9 of the nu = 1/2 plate's energy.
------------------------------------------------------------------------ */

// Bending stiffness of the wall (Eq. B1).
inline double bending_stiffness(double G, double t0)
{
  return G * t0 * t0 * t0 / 3.0;
}

// Dihedral angle phi in (-pi, pi] of the hinge with edge vectors b1 = x_i - x_j, b2 = x_k - x_j
// (the shared edge) and b3 = x_l - x_k (LAMMPS's vb1, vb2, vb3), pi for a flat hinge; with grad
// non-null also dphi/dx for the four nodes i, j, k, l. Returns false for a hinge whose triangles
// have no area (collinear nodes): the angle is then undefined and its derivative infinite.
inline bool hinge_angle(const double b1[3], const double b2[3], const double b3[3], double &phi,
                        double grad[4][3] = nullptr)
{
  // F = x_i - x_j, G = x_j - x_k, H = x_l - x_k; A = F x G, B = H x G the triangles' normals
  const double g[3] = {-b2[0], -b2[1], -b2[2]};
  const double A[3] = {b1[1] * g[2] - b1[2] * g[1], b1[2] * g[0] - b1[0] * g[2],
                       b1[0] * g[1] - b1[1] * g[0]};
  const double B[3] = {b3[1] * g[2] - b3[2] * g[1], b3[2] * g[0] - b3[0] * g[2],
                       b3[0] * g[1] - b3[1] * g[0]};
  const double a2 = A[0] * A[0] + A[1] * A[1] + A[2] * A[2];
  const double b2n = B[0] * B[0] + B[1] * B[1] + B[2] * B[2];
  const double g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
  const double f2 = b1[0] * b1[0] + b1[1] * b1[1] + b1[2] * b1[2];
  const double h2 = b3[0] * b3[0] + b3[1] * b3[1] + b3[2] * b3[2];
  // relative to the edge lengths, so that the test does not depend on the units
  if (!(g2 > 0.0) || !(a2 > 1e-24 * f2 * g2) || !(b2n > 1e-24 * h2 * g2)) return false;
  const double gn = std::sqrt(g2);
  const double BxA[3] = {B[1] * A[2] - B[2] * A[1], B[2] * A[0] - B[0] * A[2],
                         B[0] * A[1] - B[1] * A[0]};
  const double y = (BxA[0] * g[0] + BxA[1] * g[1] + BxA[2] * g[2]) / gn;
  const double x = A[0] * B[0] + A[1] * B[1] + A[2] * B[2];
  phi = std::atan2(y, x);
  if (grad) {
    const double fg = (b1[0] * g[0] + b1[1] * g[1] + b1[2] * g[2]) / (a2 * gn);
    const double hg = (b3[0] * g[0] + b3[1] * g[1] + b3[2] * g[2]) / (b2n * gn);
    for (int d = 0; d < 3; d++) {
      grad[0][d] = -gn / a2 * A[d];
      grad[3][d] = gn / b2n * B[d];
      grad[1][d] = gn / a2 * A[d] + fg * A[d] - hg * B[d];
      grad[2][d] = -(grad[0][d] + grad[1][d] + grad[3][d]);
    }
  }
  return true;
}

// Rest state of a hinge: its rest dihedral angle and the weight |e0|^2 / A0 of Eq. B2, from the
// reference edge vectors (as hinge_angle). Returns false for a reference hinge without area.
struct HingeRest {
  double phi0;
  double weight;
};

inline bool hinge_rest(const double B1[3], const double B2[3], const double B3[3], HingeRest &rest)
{
  if (!hinge_angle(B1, B2, B3, rest.phi0)) return false;
  // the triangles' areas: |B1 x B2| / 2 and |B2 x B3| / 2
  const double n1[3] = {B1[1] * B2[2] - B1[2] * B2[1], B1[2] * B2[0] - B1[0] * B2[2],
                        B1[0] * B2[1] - B1[1] * B2[0]};
  const double n2[3] = {B2[1] * B3[2] - B2[2] * B3[1], B2[2] * B3[0] - B2[0] * B3[2],
                        B2[0] * B3[1] - B2[1] * B3[0]};
  const double area = 0.5 *
      (std::sqrt(n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]) +
       std::sqrt(n2[0] * n2[0] + n2[1] * n2[1] + n2[2] * n2[2]));
  rest.weight = (B2[0] * B2[0] + B2[1] * B2[1] + B2[2] * B2[2]) / area;
  return true;
}

// phi - phi0 wrapped into (-pi, pi]: a hinge passing through its fully folded state (phi = 0 for
// a flat rest shape) keeps an energy continuous in the positions.
inline double hinge_deviation(double phi, double phi0)
{
  constexpr double PI = 3.14159265358979323846;
  double dphi = phi - phi0;
  if (dphi > PI)
    dphi -= 2.0 * PI;
  else if (dphi <= -PI)
    dphi += 2.0 * PI;
  return dphi;
}

// Energy of a hinge (Eq. B2) with bending stiffness D (Eq. B1).
inline double hinge_energy(double D, const HingeRest &rest, double phi)
{
  const double dphi = hinge_deviation(phi, rest.phi0);
  return 0.5 * D * rest.weight * dphi * dphi;
}

// Forces on the hinge's nodes i, j, k, l (Eq. B3) from the angle's gradient (hinge_angle).
inline void hinge_forces(double D, const HingeRest &rest, double phi, const double grad[4][3],
                         double f[4][3])
{
  const double c = -D * rest.weight * hinge_deviation(phi, rest.phi0);
  for (int a = 0; a < 4; a++)
    for (int d = 0; d < 3; d++) f[a][d] = c * grad[a][d];
}

/* ----------------------------------------------------------------------
   Classical buckling of a spherical shell (Eqs. S1-S5): Zoelly (1915), Timoshenko & Gere,
   Theory of Elastic Stability (1961) sec. 11.3, Hutchinson, J. Appl. Mech. 34, 49 (1967).
   A shell of radius R, thickness t, modulus E, Poisson ratio nu under an equibiaxial membrane
   stress sigma (compression positive). A shallow dimple w ~ cos(k x) with k R >> 1 is in
   equilibrium (the shallow-shell equation) when
     sigma t k^2 = D k^4 + E t / R^2,     D = E t^3 / (12 (1 - nu^2))  (Eq. B1)
   the bending resisting at short waves, the hoop stretching of the curved shell at long ones.
   The least stress for which some k balances (d/dk = 0: k_c^4 = E t / (D R^2)) is (Eq. S1)
     sigma_c = E t / (R sqrt(3 (1 - nu^2))),
   the buckle's wavelength is (Eq. S4)  lambda_c = 2 pi / k_c = 2 pi sqrt(R t) / (12 (1 - nu^2))^(1/4),
   the equibiaxial strain of sigma_c (Hooke, plane stress) is (Eq. S2)
     eps_c = (1 - nu) sigma_c / E          (t / (3 R) for nu = 1/2),
   and the external pressure that makes it (Laplace, sigma = p R / (2 t)) is (Eq. S3)
     p_c = 2 E t^2 / (R^2 sqrt(3 (1 - nu^2))).
   Above sigma_c a band of k grows; in time a mode of wall density rho grows at the rate
   rho t s^2 = sigma t k^2 - D k^4 - E t / R^2, fastest at k^2 = sigma t / (2 D), so a shell held
   (or swung) to sigma = a sigma_c buckles first at (Eq. S5)  lambda = lambda_c / sqrt(a).
   The hinges of Eqs. B2-B3 have D in the mean-curvature term, the only one that enters here (the
   Gaussian term integrates to the boundary of a dimple), so the wall meets S1-S5 with E = 3G,
   nu = 1/2 (the incompressible membrane).
------------------------------------------------------------------------- */

// Critical equibiaxial membrane stress of a spherical shell (Eq. S1).
inline double shell_critical_stress(double E, double t, double R, double nu)
{
  return E * t / (R * std::sqrt(3.0 * (1.0 - nu * nu)));
}

// Equibiaxial compressive strain at the critical stress (Eq. S2).
inline double shell_critical_strain(double E, double t, double R, double nu)
{
  return (1.0 - nu) * shell_critical_stress(E, t, R, nu) / E;
}

// Classical buckling pressure of a spherical shell (Eq. S3).
inline double shell_critical_pressure(double E, double t, double R, double nu)
{
  return 2.0 * t * shell_critical_stress(E, t, R, nu) / R;
}

// Wavelength of the classical buckle (Eq. S4).
inline double shell_buckle_wavelength(double t, double R, double nu)
{
  constexpr double PI = 3.14159265358979323846;
  return 2.0 * PI * std::sqrt(R * t) / std::pow(12.0 * (1.0 - nu * nu), 0.25);
}

// Fastest-growing wavelength at a compressive stress a times the critical one, a >= 1 (Eq. S5).
inline double shell_fastest_wavelength(double t, double R, double nu, double a)
{
  return shell_buckle_wavelength(t, R, nu) / std::sqrt(a);
}

}    // namespace CellPhysics

#endif
