/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the per-type coefficient arrays of a bonded style in a binary
   restart file. Each array holds types 1..n; they are written one after
   the other, read by rank 0 and sent to all ranks, in the same order.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_RESTART_H
#define CELLMECH_CELL_RESTART_H

#include "error.h"
#include "utils.h"

#include <cstdio>
#include <initializer_list>
#include <mpi.h>

namespace CellMech {

inline void write_type_arrays(FILE *fp, int n, std::initializer_list<double *> arrays)
{
  for (double *a : arrays) fwrite(&a[1], sizeof(double), n, fp);
}

inline void read_type_arrays(FILE *fp, int n, std::initializer_list<double *> arrays, int me,
                             MPI_Comm world, LAMMPS_NS::Error *error)
{
  if (me == 0)
    for (double *a : arrays)
      LAMMPS_NS::utils::sfread(FLERR, &a[1], sizeof(double), n, fp, nullptr, error);
  for (double *a : arrays) MPI_Bcast(&a[1], n, MPI_DOUBLE, 0, world);
}

}    // namespace CellMech

#endif
