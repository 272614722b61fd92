/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the rules of a cell's topology, each written once and called
   by every style that needs it. A cell is a molecule ID; its wall is the
   wall triangles (angles, contract in cell_fields.h) and tethers, glued to
   other cells by lamella bonds. Nothing here includes a style, so that any
   style -- and any new per-pair consumer -- can call these without
   pulling in another. The surgery a failure makes on the topology (the
   tethers and triangles of bond style cell/tether and angle style
   cell/membrane, the lamella bonds of bond style cell/lamella) is here
   too, in cell_topology.cpp; the failure fixes decide when it is made.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_TOPOLOGY_H
#define CELLMECH_CELL_TOPOLOGY_H

#include "lmptype.h"

#include <functional>
#include <utility>
#include <vector>

namespace LAMMPS_NS {
class Atom;
class LAMMPS;
}    // namespace LAMMPS_NS

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

// An edge of a wall, or a bond: the tags of its two atoms.
using Edge = std::pair<LAMMPS_NS::tagint, LAMMPS_NS::tagint>;
// Whether the triangle (or a hinge's wing) with these three tags, in any order, is gone.
using TrianglePredicate =
    std::function<bool(LAMMPS_NS::tagint, LAMMPS_NS::tagint, LAMMPS_NS::tagint)>;

// Drop the atom with tag other from the 1-2 special list of local atom i; false when it is not a
// 1-2 neighbour (a second bond between them broke before).
bool remove_special12(LAMMPS_NS::Atom *, int i, LAMMPS_NS::tagint other);
// Drop the bond to partner from atom i's bond arrays (the last bond takes its slot); false when
// atom i stores no such bond.
bool remove_bond(LAMMPS_NS::Atom *, int i, LAMMPS_NS::tagint partner);
// Collective: the nodes of each edge leave each other's 1-2 list and, with bonds, the bond arrays
// and the global bond count. Every rank calls it with the same edges.
void release_edges(LAMMPS_NS::LAMMPS *, const std::vector<Edge> &edges, bool bonds);
// Collective: the triangles for which is_gone holds leave the angle arrays and the global angle
// count, and the hinges (dihedrals) with such a triangle as a wing leave with them.
void remove_triangles(LAMMPS_NS::LAMMPS *, const TrianglePredicate &is_gone);

}    // namespace CellMech

#endif
