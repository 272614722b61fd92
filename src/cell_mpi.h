/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: every rank's entries of a variable-length list, on every rank.
   The per-cell and per-pair tables (cell index, lamella areas, contact
   rows, wall triangles) are built from what each rank owns and must come
   out the same on all ranks: the entries are concatenated in rank order,
   so sums taken over them in that order agree to the bit everywhere.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_MPI_H
#define CELLMECH_CELL_MPI_H

#include <mpi.h>

#include <vector>

namespace CellMech {

template <typename T>
std::vector<T> allgather_list(const std::vector<T> &mine, MPI_Datatype type, MPI_Comm world)
{
  int nprocs;
  MPI_Comm_size(world, &nprocs);
  if (nprocs == 1) return mine;    // one rank has nobody to tell
  const int nmine = (int) mine.size();
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  MPI_Allgather(&nmine, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  int total = 0;
  for (int p = 0; p < nprocs; p++) {
    displs[p] = total;
    total += counts[p];
  }
  std::vector<T> all(total);
  MPI_Allgatherv(mine.data(), nmine, type, all.data(), counts.data(), displs.data(), type, world);
  return all;
}

// Whether n > 0 on any rank: one reduction of an int, none on one rank. The cheap question before
// a gather that is rarely needed (the failures of fix CELL_TETHER_BREAK and CELL_LAMELLA_BREAK).
inline bool any_rank_has(int n, MPI_Comm world)
{
  int nprocs;
  MPI_Comm_size(world, &nprocs);
  if (nprocs == 1) return n > 0;
  int all = 0;
  MPI_Allreduce(&n, &all, 1, MPI_INT, MPI_SUM, world);
  return all > 0;
}

}    // namespace CellMech

#endif
