/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: internal fix CELL_TETHER_BREAK

   A tether broken in bond style cell/tether, or a triangle failed in angle
   style cell/membrane, leaves its rank's bond or angle list at once; the
   style hands it to tether_broke() or triangle_failed(). When every rank
   has them (FixCellFailure: at the neighbor build of the next step, or
   earlier for an output), each rank brings its own atoms' topology in line
   (the surgery itself is CellMech's, cell_topology.cpp):
   - the two nodes leave each other's 1-2 special list, so that after the
     re-neighboring they are an ordinary wall-wall pair and the 8-4
     contact repels them (their 1-3 and 1-4 weights are 1, as for any pair);
   - each triangle (angle) that has the broken tether as an edge leaves
     the topology: pair cell/virtual no longer puts a virtual particle on
     it, so fluid can pass, and fix cell/fluid takes it out of the osmotic
     wall area. Deleting it (rather than giving it type 0) matters: LAMMPS
     lists angles of type 0 until the next run starts and then drops them,
     and would stop with "Angle atoms missing" when the nodes of a torn
     triangle drift apart farther than the ghost cutoff.
   - each hinge (dihedral) with one of those triangles as a wing leaves
     the topology with it.
   The neighbor lists in use keep these until that build, on every rank
   alike. Removing the bond itself too keeps a special list rebuilt from
   the bonds -- after read_restart or special_bonds -- equal to the one
   updated here, and write_data writes the torn wall as it is.
   Failed membrane triangles (angle style cell/membrane) go through the
   same steps in apply_triangles(): the triangle leaves the topology here,
   and an edge of it is counted as broken (the wall is open along it) from
   its first failed triangle and leaves the bond arrays and special lists
   with its last.
   The per-atom count of broken tethers travels with the atoms and is
   written to restart files; the global scalar, the total, is half their sum.
------------------------------------------------------------------------- */

#include "fix_cell_tether_break.h"

#include "atom.h"
#include "atom_vec.h"
#include "cell_mpi.h"
#include "cell_topology.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"

#include <algorithm>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixCellTetherBreak::FixCellTetherBreak(LAMMPS *_lmp, int narg, char **arg) :
    FixCellFailure(_lmp, narg, arg)
{
  if (narg != 3) error->all(FLERR, "Illegal fix CELL_TETHER_BREAK command: expected no arguments");
  scalar_flag = 1;
  global_freq = 1;
  extscalar = 0;
  add_counts();    // count: the broken tethers (opened wall edges) that ended at each node
}

double FixCellTetherBreak::compute_scalar()
{
  sync();
  // every broken tether is counted at both of its nodes
  double mine = 0.0, all = 0.0;
  for (int i = 0; i < atom->nlocal; i++) mine += count[i];
  MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, world);
  return 0.5 * all;
}

/* ---------------------------------------------------------------------- */

FixCellTetherBreak *FixCellTetherBreak::ensure(LAMMPS *lmp)
{
  Fix *fix = lmp->modify->get_fix_by_id(ID);
  if (!fix) fix = lmp->modify->add_fix(fmt::format("{} all CELL_TETHER_BREAK", ID));
  auto *mine = dynamic_cast<FixCellTetherBreak *>(fix);
  if (!mine)
    lmp->error->all(FLERR,
                    "Fix ID {} is cellmech's bookkeeping of wall failure, but fix style {} has it",
                    ID, fix->style);
  return mine;
}

void FixCellTetherBreak::tether_broke(tagint a, tagint b)
{
  pending_tethers.emplace_back(std::min(a, b), std::max(a, b));
  failed();
}

void FixCellTetherBreak::triangle_failed(tagint a, tagint b, tagint c)
{
  std::array<tagint, 3> t = {a, b, c};
  std::sort(t.begin(), t.end());
  pending_triangles.push_back(t);
  failed();
}

/* ----------------------------------------------------------------------
   all ranks' failures on all ranks, in rank order, then sorted: the same
   lists, and so the same updates, on any number of ranks. With newton_bond
   off both owners of a tether (every owner of a triangle) found it.
------------------------------------------------------------------------- */

bool FixCellTetherBreak::flush()
{
  std::vector<tagint> pairs_flat, triangles_flat;
  for (const auto &p : pending_tethers) pairs_flat.insert(pairs_flat.end(), {p.first, p.second});
  for (const auto &t : pending_triangles)
    triangles_flat.insert(triangles_flat.end(), t.begin(), t.end());
  pending_tethers.clear();
  pending_triangles.clear();
  // the one collective of a build without failures
  if (!CellMech::any_rank_has((int) (pairs_flat.size() + triangles_flat.size()), world))
    return false;
  pairs_flat = CellMech::allgather_list(pairs_flat, MPI_LMP_TAGINT, world);
  triangles_flat = CellMech::allgather_list(triangles_flat, MPI_LMP_TAGINT, world);

  std::vector<std::pair<tagint, tagint>> pairs;
  for (size_t k = 0; k + 1 < pairs_flat.size(); k += 2)
    pairs.emplace_back(pairs_flat[k], pairs_flat[k + 1]);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<std::array<tagint, 3>> triangles;
  for (size_t k = 0; k + 2 < triangles_flat.size(); k += 3)
    triangles.push_back({triangles_flat[k], triangles_flat[k + 1], triangles_flat[k + 2]});
  std::sort(triangles.begin(), triangles.end());
  triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());

  atom->nbonds -= (bigint) pairs.size();
  apply(pairs);
  apply_triangles(triangles);
  return true;
}

/* ---------------------------------------------------------------------- */

void FixCellTetherBreak::apply(const std::vector<std::pair<tagint, tagint>> &pairs)
{
  if (pairs.empty()) return;
  for (const auto &p : pairs)
    for (const tagint t : {p.first, p.second}) {
      const int i = atom->map(t);
      if (i >= 0 && i < atom->nlocal) count[i] += 1.0;
    }
  // the bond style has taken the tethers out of the bond arrays already
  CellMech::release_edges(lmp, pairs, false);

  auto edge_of = [&pairs](tagint t1, tagint t2, tagint t3) {
    for (const auto &p : pairs) {
      const int hits = (t1 == p.first || t2 == p.first || t3 == p.first) +
          (t1 == p.second || t2 == p.second || t3 == p.second);
      if (hits == 2) return true;
    }
    return false;
  };
  CellMech::remove_triangles(lmp, edge_of);
}

/* ----------------------------------------------------------------------
   Failed membrane triangles. An edge of the wall is open (counted as broken
   at both its nodes, as a broken tether is) from the step the first of its
   two triangles fails: the hole lies along it. It stays in the topology --
   bond and 1-2 special -- while a triangle still holds its nodes, and leaves
   it with the last one, so that its nodes meet by the 8-4 contact again. An
   edge of an open sheet's border (one triangle) leaves with its triangle and
   is not counted: it never closed a wall.
------------------------------------------------------------------------- */

void FixCellTetherBreak::apply_triangles(const std::vector<std::array<tagint, 3>> &triangles)
{
  if (triangles.empty()) return;
  using Edge = std::pair<tagint, tagint>;
  auto sorted3 = [](tagint a, tagint b, tagint c) {
    std::array<tagint, 3> t = {a, b, c};
    std::sort(t.begin(), t.end());
    return t;
  };
  auto edges_of = [](const std::array<tagint, 3> &t) {
    return std::array<Edge, 3>{Edge(t[0], t[1]), Edge(t[0], t[2]), Edge(t[1], t[2])};
  };

  std::vector<Edge> all;
  for (const auto &t : triangles)
    for (const auto &e : edges_of(t)) all.push_back(e);
  std::sort(all.begin(), all.end());
  std::vector<Edge> edges;
  std::vector<int> nfail;
  for (const auto &e : all) {
    if (edges.empty() || edges.back() != e) {
      edges.push_back(e);
      nfail.push_back(0);
    }
    nfail.back()++;
  }
  auto find = [&edges](const Edge &e) {
    const auto it = std::lower_bound(edges.begin(), edges.end(), e);
    return (it != edges.end() && *it == e) ? (int) (it - edges.begin()) : -1;
  };

  // triangles along each of these edges before these failures, on all ranks (each triangle counted
  // once: at its central atom, which alone stores it with newton_bond on)
  const int nlocal = atom->nlocal;
  tagint *tag = atom->tag;
  std::vector<int> mine(edges.size(), 0), before(edges.size(), 0);
  for (int i = 0; i < nlocal && atom->avec->angles_allow; i++)
    for (int m = 0; m < atom->num_angle[i]; m++) {
      if (!force->newton_bond && tag[i] != atom->angle_atom2[i][m]) continue;
      const auto t =
          sorted3(atom->angle_atom1[i][m], atom->angle_atom2[i][m], atom->angle_atom3[i][m]);
      for (const auto &e : edges_of(t)) {
        const int k = find(e);
        if (k >= 0) mine[k]++;
      }
    }
  MPI_Allreduce(mine.data(), before.data(), (int) edges.size(), MPI_INT, MPI_SUM, world);

  CellMech::remove_triangles(lmp, [&](tagint a, tagint b, tagint c) {
    return std::binary_search(triangles.begin(), triangles.end(), sorted3(a, b, c));
  });

  std::vector<Edge> released;
  for (size_t k = 0; k < edges.size(); k++) {
    const int after = before[k] - nfail[k];
    if (before[k] >= 2 && after < 2)
      for (const tagint t : {edges[k].first, edges[k].second}) {
        const int i = atom->map(t);
        if (i >= 0 && i < nlocal) count[i] += 1.0;
      }
    if (after <= 0) released.push_back(edges[k]);
  }
  CellMech::release_edges(lmp, released, true);
}
