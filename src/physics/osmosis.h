/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_osmosis.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: the osmotic water uptake of a fluid particle through its cell wall (Eq. 10).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_OSMOSIS_H
#define CELLMECH_PHYSICS_OSMOSIS_H

namespace CellPhysics {

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

}    // namespace CellPhysics

#endif
