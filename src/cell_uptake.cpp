/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the per-cell books of fix cell/fluid (cell_uptake.h)
------------------------------------------------------------------------- */

#include "cell_uptake.h"

#include "cell_index.h"

using namespace LAMMPS_NS;

namespace {
// tag of the restart record: not an integer, so that the records of development versions, which
// opened with a cell count, are told apart and refused
constexpr double RESTART_TAG = -0.5;
}    // namespace

namespace CellMech {

bool UptakeBooks::reindex(const std::vector<tagint> &old_ids, const CellIndex &cells, int me)
{
  if (cells.molecule_ids() == old_ids && restart_uptake.empty() && restart_water0.empty() &&
      !local.empty())
    return false;
  const int n = cells.size();
  std::vector<double> uptake(n + 1, 0.0), w0(n + 1, 0.0);
  for (int k = 1; k <= (int) old_ids.size(); k++) {
    uptake[cells.slot(old_ids[k - 1])] += local[k];
    w0[cells.slot(old_ids[k - 1])] = water0[k];
  }
  // the record's totals were kept on rank 0 only, so they are summed once
  if (me == 0)
    for (const auto &kv : restart_uptake) uptake[cells.slot(kv.first)] += kv.second;
  for (const auto &kv : restart_water0) w0[cells.slot(kv.first)] = kv.second;
  restart_uptake.clear();
  restart_water0.clear();
  uptake[0] = 0.0;    // slot 0: IDs that left
  w0[0] = 0.0;
  water0 = w0;
  local = uptake;
  all.assign(n + 1, 0.0);
  stale = true;
  return true;
}

double UptakeBooks::total(int m, MPI_Comm world)
{
  if (stale) {
    MPI_Allreduce(local.data(), all.data(), (int) local.size(), MPI_DOUBLE, MPI_SUM, world);
    stale = false;
  }
  return all[m];
}

void UptakeBooks::write(FILE *fp, const CellIndex &cells, int me, MPI_Comm world) const
{
  const int ncells = cells.size();
  std::vector<double> sum(ncells + 1), list(2 + 3 * ncells);
  MPI_Allreduce(local.data(), sum.data(), ncells + 1, MPI_DOUBLE, MPI_SUM, world);
  list[0] = RESTART_TAG;
  list[1] = ncells;
  for (int m = 1; m <= ncells; m++) {
    list[3 * m - 1] = (double) cells.id(m);
    list[3 * m] = sum[m];
    list[3 * m + 1] = water0[m];
  }
  if (me == 0) {
    int size = list.size() * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list.data(), sizeof(double), list.size(), fp);
  }
}

bool UptakeBooks::read(const double *list)
{
  if (list[0] != RESTART_TAG) return false;
  restart_uptake.clear();
  restart_water0.clear();
  const int n = (int) list[1];
  for (int m = 1; m <= n; m++) {
    restart_uptake[(tagint) list[3 * m - 1]] += list[3 * m];
    restart_water0[(tagint) list[3 * m - 1]] = list[3 * m + 1];
  }
  return true;
}

}    // namespace CellMech
