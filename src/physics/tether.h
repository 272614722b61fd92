/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_tether.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: the Neo-Hookean tether of the wall (Eqs. 18-20), its equibiaxial network tension
   (Eq. 15) and the uniaxial stretch of a flat tether sheet (Appendix 1, Eqs. A1-A2).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_TETHER_H
#define CELLMECH_PHYSICS_TETHER_H

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

}    // namespace CellPhysics

#endif
