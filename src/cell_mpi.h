/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: every rank's entries of a variable-length list, on every rank.
   The per-cell and per-pair tables (cell index, lamella areas, contact
   rows, wall triangles) are built from what each rank owns and must come
   out the same on all ranks: the entries are concatenated in rank order,
   so sums taken over them in that order agree to the bit everywhere.
   PairSums: sums per pair of cells kept by their IDs, summed so.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_MPI_H
#define CELLMECH_CELL_MPI_H

#include "lmptype.h"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <type_traits>
#include <utility>
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

// Sums of N doubles per unordered pair of cells, taken on each rank and added up over all ranks.
// The keys stay tagint, as molecule IDs are (an int cast folds IDs past 2^31 onto others); a
// caller may key by slots too. Each rank's rows, gathered in rank order, are added into an ordered
// map, so every rank gets the same sums to the bit.
template <int N> class PairSums {
 public:
  using Key = std::pair<LAMMPS_NS::tagint, LAMMPS_NS::tagint>;
  using Row = std::array<double, N>;

  // the row of the pair (a, b), either order; zeros when new
  Row &operator()(LAMMPS_NS::tagint a, LAMMPS_NS::tagint b)
  {
    const Key key(std::min(a, b), std::max(a, b));
    auto it = rows.find(key);
    if (it == rows.end()) it = rows.emplace(key, Row{}).first;
    return it->second;
  }
  // by key, lower ID first
  const std::map<Key, Row> &all() const { return rows; }

  // collective: the rows of all ranks added up, the same on every rank (one gather, as bytes, so
  // that the keys keep every bit)
  PairSums summed(MPI_Comm world) const
  {
    std::vector<char> mine(rows.size() * sizeof(Entry));
    size_t k = 0;
    for (const auto &kv : rows) {
      const Entry e = {{kv.first.first, kv.first.second}, kv.second};
      std::memcpy(&mine[k++ * sizeof(Entry)], &e, sizeof(Entry));
    }
    const std::vector<char> all = allgather_list(mine, MPI_BYTE, world);
    PairSums total;
    for (size_t at = 0; at < all.size(); at += sizeof(Entry)) {
      Entry e;
      std::memcpy(&e, &all[at], sizeof(Entry));
      Row &r = total(e.key[0], e.key[1]);
      for (int d = 0; d < N; d++) r[d] += e.value[d];
    }
    return total;
  }

 private:
  struct Entry {
    LAMMPS_NS::tagint key[2];
    Row value;
  };
  static_assert(std::is_trivially_copyable<Entry>::value, "PairSums entries travel as bytes");
  std::map<Key, Row> rows;
};

}    // namespace CellMech

#endif
