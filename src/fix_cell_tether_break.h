/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: internal fix CELL_TETHER_BREAK, the bookkeeping of wall
   failure: broken tethers and failed membrane triangles. Created by bond
   style cell/tether or angle style cell/membrane when a type has a
   critical stretch (bond_coeff / angle_coeff ... lamf v), with the ID
   cell_broken.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(CELL_TETHER_BREAK,FixCellTetherBreak);
// clang-format on
#else

#ifndef LMP_FIX_CELL_TETHER_BREAK_H
#define LMP_FIX_CELL_TETHER_BREAK_H

#include "fix_cell_failure.h"

#include <array>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class FixCellTetherBreak : public FixCellFailure {
 public:
  static constexpr const char *ID = "cell_broken";

  FixCellTetherBreak(class LAMMPS *, int, char **);
  double compute_scalar() override;

  // the fix of this run, created if there is none yet (bond and angle styles that can fail)
  static FixCellTetherBreak *ensure(class LAMMPS *lmp);
  // a tether (tags a, b) broke on this rank; it has left the bond list and the bond arrays of
  // the atom(s) storing it here
  void tether_broke(tagint a, tagint b);
  // a wall triangle failed on this rank (angle style cell/membrane); it has left the angle list
  void triangle_failed(tagint a, tagint b, tagint c);

 protected:
  // found on this rank since the last sync (FixCellFailure)
  std::vector<std::pair<tagint, tagint>> pending_tethers;
  std::vector<std::array<tagint, 3>> pending_triangles;
  bool flush() override;
  // every rank calls these with the same list: the tag pairs of the broken tethers, and the
  // failed wall triangles (tags sorted within each)
  void apply(const std::vector<std::pair<tagint, tagint>> &pairs);
  void apply_triangles(const std::vector<std::array<tagint, 3>> &triangles);
};

}    // namespace LAMMPS_NS

#endif
#endif
