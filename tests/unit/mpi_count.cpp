/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech test helper: counts the collective calls a run makes, through
   MPI's profiling interface. Preloaded into lmp (LD_PRELOAD); at
   MPI_Finalize each rank writes "allreduce allgather allgatherv" to
   $CELLMECH_MPI_COUNT.RANK. Used by test_collectives.py.
------------------------------------------------------------------------- */

#include <mpi.h>

#include <cstdio>
#include <cstdlib>

static long nallreduce = 0, nallgather = 0, nallgatherv = 0;

int MPI_Allreduce(const void *send, void *recv, int count, MPI_Datatype type, MPI_Op op,
                  MPI_Comm comm)
{
  nallreduce++;
  return PMPI_Allreduce(send, recv, count, type, op, comm);
}

int MPI_Allgather(const void *send, int scount, MPI_Datatype stype, void *recv, int rcount,
                  MPI_Datatype rtype, MPI_Comm comm)
{
  nallgather++;
  return PMPI_Allgather(send, scount, stype, recv, rcount, rtype, comm);
}

int MPI_Allgatherv(const void *send, int scount, MPI_Datatype stype, void *recv,
                   const int rcounts[], const int displs[], MPI_Datatype rtype, MPI_Comm comm)
{
  nallgatherv++;
  return PMPI_Allgatherv(send, scount, stype, recv, rcounts, displs, rtype, comm);
}

int MPI_Finalize()
{
  const char *base = std::getenv("CELLMECH_MPI_COUNT");
  if (base) {
    int me = 0;
    PMPI_Comm_rank(MPI_COMM_WORLD, &me);
    char name[4096];
    std::snprintf(name, sizeof(name), "%s.%d", base, me);
    if (FILE *fp = std::fopen(name, "w")) {
      std::fprintf(fp, "%ld %ld %ld\n", nallreduce, nallgather, nallgatherv);
      std::fclose(fp);
    }
  }
  return PMPI_Finalize();
}
