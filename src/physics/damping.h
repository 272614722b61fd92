/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_damping.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: the damping of bonded pairs and contacts along the line of centres (Eq. 11).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_DAMPING_H
#define CELLMECH_PHYSICS_DAMPING_H

namespace CellPhysics {

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

}    // namespace CellPhysics

#endif
