/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: a list inside LAMMPS's neighbour list (cell_near_list.h)
------------------------------------------------------------------------- */

#include "cell_near_list.h"

#include "atom.h"
#include "cell_fields.h"
#include "lammps.h"
#include "neighbor.h"

using namespace LAMMPS_NS;

namespace CellMech {

bool NearList::stale(LAMMPS *lmp)
{
  const int now = lmp->atom->nlocal + lmp->atom->nghost;
  const bool rebuilt =
      list_rebuilt(lmp, build, first.empty() ? 0 : first.size() - 1, lmp->neighbor->nanglelist);
  if (!rebuilt && now == nall) return false;
  nall = now;
  return true;
}

void NearList::start(int nentries)
{
  first.assign(nentries + 1, 0);
  atoms.clear();
}

double NearList::memory_usage() const
{
  return (double) (first.capacity() + atoms.capacity()) * sizeof(int);
}

}    // namespace CellMech
