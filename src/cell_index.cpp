/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the cells of a system and their per-cell array slots (see
   cell_index.h)
------------------------------------------------------------------------- */

#include "cell_index.h"

#include "atom.h"
#include "cell_mpi.h"
#include "comm.h"
#include "lammps.h"

#include <algorithm>

using namespace LAMMPS_NS;

namespace CellMech {

void CellIndex::build(LAMMPS *lmp)
{
  const Atom *atom = lmp->atom;
  // the atoms of a cell are mostly neighbours in memory: drop repeats before sorting
  std::vector<tagint> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    const tagint m = atom->molecule[i];
    if (m >= 1 && (mine.empty() || mine.back() != m)) mine.push_back(m);
  }
  std::sort(mine.begin(), mine.end());
  mine.erase(std::unique(mine.begin(), mine.end()), mine.end());

  ids = CellMech::allgather_list(mine, MPI_LMP_TAGINT, lmp->world);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  dense = ids.empty() || ids.back() == (tagint) ids.size();
}

int CellIndex::slot(tagint m) const
{
  if (m < 1) return 0;
  if (dense) return m <= (tagint) ids.size() ? (int) m : 0;
  auto it = std::lower_bound(ids.begin(), ids.end(), m);
  return (it != ids.end() && *it == m) ? (int) (it - ids.begin()) + 1 : 0;
}

}    // namespace CellMech
