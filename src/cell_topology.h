/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the rules of a cell's topology, each written once and called
   by every style that needs it. A cell is a molecule ID; its wall is the
   wall triangles (angles, contract in cell_fields.h) and tethers, glued to
   other cells by lamella bonds. Nothing here includes a style, so that any
   style -- and any new per-pair consumer -- can call these without
   pulling in another.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_TOPOLOGY_H
#define CELLMECH_CELL_TOPOLOGY_H

#include "lmptype.h"

namespace CellMech {

// Whether two particles belong to one cell (molecule ID), so that SPH may pair them: the wall
// between two cells is closed, so no pressure, viscosity, density rate or shear of one cell's
// protoplasm comes from another's, even where glued walls bring them within the kernel support.
// Without molecule IDs all particles are one body of fluid. The rule of every consumer of SPH
// pairs (pair cell/sph, compute cell/shear/atom) and the test that tells a tether from a lamella
// bond and a contact within a wall from one between walls.
inline bool same_cell(const LAMMPS_NS::tagint *molecule, int i, int j)
{
  return !molecule || molecule[i] == molecule[j];
}

// Each triangle of the walls in the angle list (contract in cell_fields.h): fn(n, a, b, c), n its
// entry in the list, b its central node. A triangle whose angle type is <= 0 has left the wall (a
// broken tether took it out, or it failed: angle style cell/membrane) but stays listed until the
// next neighbor build; it is skipped here, the one place that says which listed triangles are wall.
template <typename Fn> void for_each_wall_triangle(int *const *anglelist, int nanglelist, Fn &&fn)
{
  for (int n = 0; n < nanglelist; n++)
    if (anglelist[n][3] > 0) fn(n, anglelist[n][0], anglelist[n][1], anglelist[n][2]);
}

}    // namespace CellMech

#endif
