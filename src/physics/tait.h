/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_tait.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: the Tait equation of state of the protoplasm and its internal energy (Eq. 6).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_TAIT_H
#define CELLMECH_PHYSICS_TAIT_H

#include <cmath>

namespace CellPhysics {

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

}    // namespace CellPhysics

#endif
