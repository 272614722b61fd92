/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_lj84.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: the 8-4 excluded-volume repulsion of contacts (Eq. 12).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_LJ84_H
#define CELLMECH_PHYSICS_LJ84_H

namespace CellPhysics {

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

}    // namespace CellPhysics

#endif
