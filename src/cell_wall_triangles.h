/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the wall triangles (angles of the topology, each listed once
   with newton_bond on) as fix cell/fluid measures them: per entry of
   neighbor->anglelist, the cell of the triangle, its rest area and whether
   it faces the outside. They change only with the angle list and the cell
   index, so they are found at a neighbour-list build or a setup and kept
   until the next, and each step sums only the current areas.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_WALL_TRIANGLES_H
#define CELLMECH_CELL_WALL_TRIANGLES_H

#include "lmptype.h"

#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
class PairCellSPH;
}    // namespace LAMMPS_NS

namespace CellMech {

class CellIndex;
class CellSums;

class WallTriangles {
 public:
  // whether the angle list was built since the last index() (or a run is being set up)
  bool stale(LAMMPS_NS::LAMMPS *);
  // each triangle's cell (that of its central node, contract: cell_fields.h) and rest area on
  // the rest shape ref (none if null); all face the outside until find_open()
  void index(LAMMPS_NS::LAMMPS *, const CellIndex &, double *const *ref);
  // exposed outside (Eq. W4): which triangles face the outside, at the distance depth;
  // node_glued: the intact lamella bonds of each local and ghost atom (cell_exposed.h)
  void find_open(LAMMPS_NS::LAMMPS *, const LAMMPS_NS::PairCellSPH *, double depth,
                 const std::vector<double> &node_glued);
  // the current area of each cell's intact triangles, its rest area (with_rest) and the area of
  // those that face the outside, added to sums
  void add_areas(LAMMPS_NS::LAMMPS *, bool with_rest, CellSums &sums) const;

 private:
  LAMMPS_NS::bigint build = -1;    // the timestep of the build they were found for
  std::vector<int> slot;
  std::vector<double> rest_area;
  std::vector<char> open;
};

}    // namespace CellMech

#endif
