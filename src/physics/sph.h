/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_sph.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: the SPH pair force (Eq. 5), the continuity equation (Eq. 7), the density update
   of a particle whose mass changes (Eqs. 8-9), Monaghan's artificial stress (not the paper's:
   the remedy of the tensile instability, pair_style cell/sph stress) and the cohesion of the
   protoplasm (not the paper's: a surface tension that keeps a cell's fluid one body, pair_style
   cell/sph cohesion).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_SPH_H
#define CELLMECH_PHYSICS_SPH_H

#include <cmath>

namespace CellPhysics {

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

// Monaghan's artificial stress (J. J. Monaghan, J. Comput. Phys. 159, 290 (2000); Gray, Monaghan
// & Swift, Comput. Methods Appl. Mech. Eng. 190, 6641 (2001)), not in the paper. Under tension the
// pressure term of Eq. 5 attracts every pair, most strongly the close ones, and the particles clump
// (the tensile instability). A pair repulsion that grows steeply as a pair closes in,
//   F_ij = -m_i m_j (R_i + R_j) f_ij^n grad_i W_ij,   f_ij = W(r_ij) / W(dp),
// with dp the particle spacing, keeps them apart. R_i = eps |P_i| / rho_i^2 where P_i < 0, and 0
// where P_i >= 0, so that the term acts only in tension (here from 1 / rho_i, which the pair
// loop computes once per particle):
inline double sph_stress_r(double P, double inv_rho, double eps)
{
  return P < 0.0 ? -eps * P * inv_rho * inv_rho : 0.0;
}

// f^n of f = W(r) / W(dp) (kernel_w_q with the prefactor over W(dp)); n >= 1 (Monaghan's n = 4
// for the cubic spline)
inline double sph_stress_fn(double f, int n)
{
  double fn = f;
  for (int k = 1; k < n; k++) fn *= f;
  return fn;
}

// The pair force along r_ij = x_i - x_j, F_ij = fs r_ij, with fn = f^n and wr = (dW/dr) / r: fs >= 0
// (a repulsion) since wr <= 0 and R >= 0. Symmetric in i, j, so momentum is conserved. For fixed
// R_i + R_j it is -dU/dr of the pair energy sph_stress_energy (d f^(n+1) / dr = (n+1) f^n W' / W(dp)).
inline double sph_stress_fpair(double mi, double mj, double ri, double rj, double fn, double wr)
{
  return -mi * mj * (ri + rj) * fn * wr;
}

// U_ij = m_i m_j (R_i + R_j) W(dp) f^(n+1) / (n + 1), from fn1 = f^(n+1) and W(dp): zero where the
// kernel is (r >= 2s) and where neither particle is in tension
inline double sph_stress_energy(double mi, double mj, double ri, double rj, double fn1, double wdp,
                                int n)
{
  return mi * mj * (ri + rj) * wdp * fn1 / (n + 1);
}

// Cohesion of the protoplasm (Eqs. C1-C2; pair_style cell/sph cohesion gamma), not in the paper.
// A fluid in tension relieves it by clumping, since in SPH a void inside the fluid costs nothing;
// in a liquid it costs its surface tension gamma per area. A pair force between particles of the
// same cell, with the particles' volumes V = m / rho,
//   dU/dr = A V_i V_j (r - a) (r_c - r)^2   for r < r_c = 2s, 0 beyond,          (Eq. C1)
// is repulsive inside a = 4 r_c / 7 and attractive beyond. a is the root of int r^3 U' dr = 0: in
// a uniform fluid (pair distribution 1) the law adds nothing to the pressure, so it does not move
// the turgor or the equation of state. Its surface tension (Kirkwood-Buff, gamma = (pi/8) n^2
// int r^4 U' dr with n V = 1) is gamma = pi A r_c^8 / 15680, so
//   A = 15680 gamma / (pi r_c^8).                                                 (Eq. C2)
// The V_i V_j makes gamma independent of the particles' size, so that it stays the same as a
// drying cell's particles lose mass.
constexpr double COHESION_ROOT = 4.0 / 7.0;    // a / r_c
constexpr double COHESION_KB = 15680.0;    // 8 x 1960, 1 / 1960 = int_0^1 x^4 (x - 4/7)(1 - x)^2 dx

inline double cohesion_amplitude(double gamma, double rc)    // Eq. C2
{
  const double rc2 = rc * rc, rc4 = rc2 * rc2;
  return COHESION_KB * gamma / (M_PI * rc4 * rc4);
}

// The pair force along r_ij = x_i - x_j, F_ij = fc r_ij (Eq. C1: fc = -U'(r) / r): attractive
// (fc < 0) beyond a, repulsive inside; symmetric in i, j, so momentum is conserved. Two particles
// on top of each other (r = 0) have no direction between them: no force
inline double cohesion_fpair(double A, double vi, double vj, double r, double rc)
{
  const double u = rc - r;
  return r > 0.0 && r < rc ? -A * vi * vj * (r - COHESION_ROOT * rc) * u * u / r : 0.0;
}

// U_ij = -A V_i V_j [(r_c - a) L^3 / 3 - L^4 / 4], L = r_c - r: zero at r_c, dU/dr = Eq. C1
inline double cohesion_energy(double A, double vi, double vj, double r, double rc)
{
  if (r >= rc) return 0.0;
  const double L = rc - r, L3 = L * L * L;
  return -A * vi * vj * ((1.0 - COHESION_ROOT) * rc * L3 / 3.0 - 0.25 * L3 * L);
}

}    // namespace CellPhysics

#endif
