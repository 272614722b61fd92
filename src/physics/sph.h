/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_sph.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: the SPH pair force (Eq. 5), the continuity equation (Eq. 7), the density update
   of a particle whose mass changes (Eqs. 8-9), and Monaghan's artificial stress (not the paper's:
   the remedy of the tensile instability, pair_style cell/sph stress).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_SPH_H
#define CELLMECH_PHYSICS_SPH_H

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

}    // namespace CellPhysics

#endif
