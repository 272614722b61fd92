/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the cells of a system and their per-cell array slots.
   A cell is a molecule ID >= 1; the IDs need not be 1..N. Per-cell arrays
   are indexed by slot 1..N, the rank of the cell's ID among the IDs
   present, so their size is the number of cells whatever the IDs are
   (sizing them by the largest ID made one cell with molecule ID 1e8 ask
   for gigabytes and reduce them every step).
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_INDEX_H
#define CELLMECH_CELL_INDEX_H

#include "lmptype.h"

#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace CellMech {

class CellIndex {
 public:
  // Collective: the distinct molecule IDs >= 1 of the local atoms of all ranks, the same list on
  // every rank. Atoms change rank or disappear only when LAMMPS re-neighbors, and molecule IDs
  // only between runs, so a caller needs to build it only then.
  void build(LAMMPS_NS::LAMMPS *lmp);

  int size() const { return (int) ids.size(); }
  // slot 1..size() of the cell with molecule ID m; 0 for molecule 0 or an ID not present
  int slot(LAMMPS_NS::tagint m) const;
  // molecule ID of slot 1..size()
  LAMMPS_NS::tagint id(int slot) const { return ids[slot - 1]; }
  const std::vector<LAMMPS_NS::tagint> &molecule_ids() const { return ids; }

 private:
  std::vector<LAMMPS_NS::tagint> ids;    // ascending
  bool dense = true;                     // ids are 1..N: the slot is the ID
};

}    // namespace CellMech

#endif
