/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the books fix cell/fluid keeps of each cell across runs: the
   mass it has taken up through its wall since the fix was defined (the
   fix's global vector) and its water W0 when the fix first ran (Eq. W1).
   They are kept by molecule ID: they follow a cell to its new slot when
   cells appear or disappear, and they go to and come from restart files.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_UPTAKE_H
#define CELLMECH_CELL_UPTAKE_H

#include "lmptype.h"

#include <cstdio>
#include <map>
#include <mpi.h>
#include <vector>

namespace CellMech {

class CellIndex;

class UptakeBooks {
 public:
  // The cells were indexed again, from old_ids (ascending, slots 1..): the books follow their
  // molecule IDs and take up a restart file's record. False, and nothing done, when the IDs are
  // the same and no record waits. me: this rank, which keeps a record's totals if it is 0.
  bool reindex(const std::vector<LAMMPS_NS::tagint> &old_ids, const CellIndex &cells, int me);
  // dm taken up by a fluid particle of cell m on this rank
  void add(int m, double dm)
  {
    local[m] += dm;
    stale = true;
  }
  // collective: all that cell m has taken up
  double total(int m, MPI_Comm world);
  // the restart record: the tag, the number of cells, then (molecule ID, uptake, W0) of each.
  // Collective; rank 0 writes it.
  void write(FILE *fp, const CellIndex &cells, int me, MPI_Comm world) const;
  // false if the record is not of that format
  bool read(const double *list);

  std::vector<double> water0;    // per slot: W0 of Eq. W1, 0 until the cell's first setup

 private:
  std::vector<double> local, all;    // per slot: this rank's uptake, all ranks' (if not stale)
  bool stale = true;
  // by molecule ID, from a restart file, until the next reindex()
  std::map<LAMMPS_NS::tagint, double> restart_uptake, restart_water0;
};

}    // namespace CellMech

#endif
