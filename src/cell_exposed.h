/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the wall triangles that face the outside, for fix cell/fluid
   exposed outside (Eq. W4). A triangle faces the outside unless it is
   glued (two of its nodes hold intact lamella bonds: the cells' turgor
   peels glued faces up to the lamella's critical opening, 12 um in the
   coarse block, and they are no less glued) or a wall node of another
   cell lies in front of it (hides_triangle) within a distance D of its
   central node (walls that touch or face each other across a narrow
   space, glued or not). The central node is owned (the rank that owns it
   lists the triangle) and, at a neighbour-list build, inside this rank's
   subdomain, so every node within D <= the ghost cutoff (fix cell/fluid
   raises it) is here as an owned atom or a ghost: the same answer on any
   number of ranks. Found at each build, with the ghosts just
   communicated; between builds the walls move less than the skin.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_EXPOSED_H
#define CELLMECH_CELL_EXPOSED_H

#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
class PairCellSPH;
}    // namespace LAMMPS_NS

namespace CellMech {

// Intact lamella bonds at each local and ghost atom, counted at both nodes of each bond in the
// bond list; the caller sums them onto the owners and sends them to the ghosts.
void count_glued_nodes(LAMMPS_NS::LAMMPS *, std::vector<double> &node_glued);

// open[n] for each triangle n of neighbor->anglelist whose cell slot[n] is >= 1 and that is
// intact: 0 glued or hidden, 1 facing the outside (the others keep theirs). node_glued: the
// summed counts of count_glued_nodes, owners and ghosts; depth: D.
void find_open_triangles(LAMMPS_NS::LAMMPS *, const LAMMPS_NS::PairCellSPH *, double depth,
                         const std::vector<double> &node_glued, const std::vector<int> &slot,
                         std::vector<char> &open);

}    // namespace CellMech

#endif
