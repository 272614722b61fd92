/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_sph.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: the SPH pair force (Eq. 5), the continuity equation (Eq. 7) and the density update
   of a particle whose mass changes (Eqs. 8-9).
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

}    // namespace CellPhysics

#endif
