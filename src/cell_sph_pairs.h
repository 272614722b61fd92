/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the interacting fluid pairs of pair style cell/sph (within
   the kernel support 2s, same cell) as a compact list with their kernel
   factors, shared by fix cell/fluid's continuity pass and the forces.

   A helper the style owns, as LAMMPS's pair styles own their NeighList,
   and not an accelerator variant in LAMMPS's OPT convention
   (pair_lj_cut_opt: a subclass registered as a second style, "cell/sph/opt",
   that replaces compute() and is chosen by the suffix): cell/sph has one
   search, which every run uses and which the continuity pass and the
   forces share, so there is nothing to choose between, and the style
   keeps the physics (Eqs. 5-7) while this class keeps how the pairs are
   found: the candidates once per neighbour-list build, the pairs and
   their kernel factors once per step, kept from the continuity pass for
   the forces, and the run-time choice of the distance test.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_SPH_PAIRS_H
#define CELLMECH_CELL_SPH_PAIRS_H

#include "lmptype.h"
#include "pointers.h"

#include <string>

namespace LAMMPS_NS {
class NeighList;
}

namespace CellMech {

// the pair style's per-type data the search reads (its arrays, not copies): fluid types,
// squared cutoff (2s)^2, 1 / s and kernel_wr_norm(s) per type pair
struct SPHTypeData {
  const int *fluid;
  double **cutsq, **sinv, **wrnorm;
};

class SPHPairs : protected LAMMPS_NS::Pointers {
 public:
  // the distance test of the search: with a branch, without one, or the faster one measured
  // as the run goes (pair_style cell/sph search)
  enum Search { BRANCH = 0, BRANCHLESS = 1, AUTO = 2 };
  // the kind named in the pair_style command (auto, branch, branchless), or -1
  static int search_named(const std::string &name);

  SPHPairs(LAMMPS_NS::LAMMPS *);
  ~SPHPairs() override;
  void set_search(int kind) { search_choice = kind; }

  // the continuity pass (fix cell/fluid's pre_force): this step's pairs, with each pair's terms
  // of Eq. 7 added to drho, kept for the force call that follows at the same positions
  void find_with_continuity(LAMMPS_NS::NeighList *, const SPHTypeData &, double *drho);
  // the force call: the pairs kept by this step's continuity pass, else a search of its own
  void find_for_forces(LAMMPS_NS::NeighList *, const SPHTypeData &);

  // the pairs of ilist[ii] are neighbour()[k], wr()[k] (grad_i W = wr r_ij) for k in
  // first()[ii] .. first()[ii + 1] - 1
  const int *first() const { return pair_first; }
  const int *neighbour() const { return pair_j; }
  const double *wr() const { return pair_wr; }
  double memory_usage() const;

 private:
  LAMMPS_NS::NeighList *list;
  SPHTypeData types;
  // the pair list; the step, and the neighbour-list build and atom count, the continuity pass
  // found it with
  LAMMPS_NS::bigint pairs_step, pairs_build;
  int pairs_nall;
  int *pair_first, *pair_j;
  double *pair_wr;
  int maxfirst, maxpair;
  // the candidates: the fluid pairs of one cell in the neighbour list (any distance), those of
  // ilist[ii] cand_j[k] for k in cand_first[ii] .. cand_first[ii + 1] - 1, found once per
  // neighbour-list build (the build count and atom count they were found with; every setup)
  LAMMPS_NS::bigint cand_build;
  int cand_nall;
  int *cand_first, *cand_j;
  int maxcand_first, maxcand;
  // one smoothing length for every pair of fluid types (the usual one fluid type): it and its
  // 1 / s and kernel_wr_norm(s), for the kernel sweep of all of an atom's pairs at once
  bool s_uniform;
  double sinv_uniform, wrnorm_uniform;
  // the planner of the distance test (search_kind): the kind in use, the searches since it was
  // chosen, the searches of the plan still to make, and the shortest time of each kind in the
  // plan (s)
  int search_choice = AUTO;
  static constexpr int SEARCH_TIMED = 6, SEARCH_PLAN = 10, SEARCH_REPLAN = 1000;
  int search_mode = BRANCHLESS, search_count = 0, search_trials = 0;
  double search_time[2] = {0.0, 0.0};

  bool kept_for_forces();
  void find_candidates();
  void check_uniform_s();
  int search_kind();
  void search_took(int kind, double seconds);
  // the one search both passes share: fills the pair list and, with CONTINUITY, adds each
  // pair's continuity terms (Eq. 7) to drho
  template <bool CONTINUITY> void find_pairs(double *drho);
};

}    // namespace CellMech

#endif
