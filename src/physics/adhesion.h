/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_adhesion.cpp.
   This header: the adhesion of the protoplasm to its own wall (not in the paper; Eq. A1 of
   docs/pair_cell_virtual.rst), attached to the 8-4 contact of Eq. 12 at r0.
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_ADHESION_H
#define CELLMECH_PHYSICS_ADHESION_H

#include <cmath>

namespace CellPhysics {

/* ---------------------------------------------------------------------
   Adhesion well (Eq. A1), xi = (r - r0) / delta, for r0 <= r < r0 + delta:
     F(r) = -4 Fa xi (1 - xi)      E(r) = -(2/3) Fa delta (1 - 3 xi^2 + 2 xi^3)
   E = -(2/3) Fa delta for r < r0, 0 beyond r0 + delta (F < 0 pulls toward the wall).
   A drying cell's protoplasm must hold on to its wall against the suction of a negative turgor:
   the contact then carries a tension, and its strength Fa must be set by that tension (Fa >= |P|
   A_c, docs/model.md), independently of the repulsion. The 8-4 law's own attractive branch
   cannot do this: its largest pull, 0.213 f0/r0 at 1.158 r0, is fixed by f0, which is chosen to
   keep the fluid out of the wall, and its r^-5 tail must be cut somewhere with a jump of the
   force. This well starts and ends with zero force (at r0, where the repulsion ends, and at
   r0 + delta), so the total force is continuous, velocity Verlet conserves energy, and its
   largest pull is Fa itself, at r0 + delta/2. Below r0 it adds only its depth to the energy, so
   that repulsion plus adhesion is one continuous potential.
   adhesion_fpair returns the factor multiplying r_vec (LAMMPS "fpair"); negative attracts.
------------------------------------------------------------------------ */

inline double adhesion_fpair(double fa, double r0, double delta, double rsq)
{
  const double rc = r0 + delta;
  if (rsq <= r0 * r0 || rsq >= rc * rc) return 0.0;
  const double r = std::sqrt(rsq);
  const double xi = (r - r0) / delta;
  return -4.0 * fa * xi * (1.0 - xi) / r;
}

inline double adhesion_energy(double fa, double r0, double delta, double rsq)
{
  const double depth = 2.0 / 3.0 * fa * delta;
  const double rc = r0 + delta;
  if (rsq <= r0 * r0) return -depth;
  if (rsq >= rc * rc) return 0.0;
  const double xi = (std::sqrt(rsq) - r0) / delta;
  return -depth * (1.0 - xi * xi * (3.0 - 2.0 * xi));
}

}    // namespace CellPhysics

#endif
