/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_lamella.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: the middle lamella, the cohesive traction-separation law between neighbouring walls
   (Eqs. L1-L5).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_LAMELLA_H
#define CELLMECH_PHYSICS_LAMELLA_H

#include <cmath>

namespace CellPhysics {

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

}    // namespace CellPhysics

#endif
