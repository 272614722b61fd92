/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the fluid pairs of pair style cell/sph (cell_sph_pairs.h)
------------------------------------------------------------------------- */

#include "cell_sph_pairs.h"

#include "cell_simd.h"

#include "atom.h"
#include "cell_topology.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "physics/kernel.h"
#include "physics/sph.h"
#include "update.h"

#include <chrono>
#include <cmath>

using namespace LAMMPS_NS;
using namespace CellPhysics;

namespace CellMech {

/* ---------------------------------------------------------------------- */

int SPHPairs::search_named(const std::string &name)
{
  if (name == "auto") return AUTO;
  if (name == "branch") return BRANCH;
  if (name == "branchless") return BRANCHLESS;
  return -1;
}

SPHPairs::SPHPairs(LAMMPS *_lmp) :
    Pointers(_lmp), list(nullptr), types{nullptr, nullptr, nullptr, nullptr}, pairs_step(-1),
    pairs_build(-1), pairs_nall(-1), pair_first(nullptr), pair_j(nullptr), pair_wr(nullptr),
    maxfirst(0), maxpair(0), cand_build(-1), cand_nall(-1), cand_first(nullptr), cand_j(nullptr),
    maxcand_first(0), maxcand(0), s_uniform(false), sinv_uniform(0.0), wrnorm_uniform(0.0)
{
}

SPHPairs::~SPHPairs()
{
  memory->destroy(pair_first);
  memory->destroy(pair_j);
  memory->destroy(pair_wr);
  memory->destroy(cand_first);
  memory->destroy(cand_j);
}

double SPHPairs::memory_usage() const
{
  return (double) maxfirst * sizeof(int) + (double) maxpair * (sizeof(int) + sizeof(double)) +
      (double) (maxcand_first + maxcand) * sizeof(int);
}

/* ---------------------------------------------------------------------- */

void SPHPairs::find_with_continuity(NeighList *nlist, const SPHTypeData &data, double *drho)
{
  list = nlist;
  types = data;
  // keep the interacting pairs for the force call that follows at the same positions
  pairs_step = update->ntimestep;
  pairs_build = neighbor->ncalls;
  pairs_nall = atom->nlocal + atom->nghost;
  find_pairs<true>(drho);
}

void SPHPairs::find_for_forces(NeighList *nlist, const SPHTypeData &data)
{
  list = nlist;
  types = data;
  if (!kept_for_forces()) find_pairs<false>(nullptr);
}

/* ----------------------------------------------------------------------
   The coupling with fix cell/fluid. It calls the continuity pass in pre_force, after this step's
   neighbour lists are built and before the forces, so that the density leapfrogs the velocity;
   the pass keeps the fluid pairs and kernel gradients it finds, and the force call that follows
   at the same positions takes them instead of searching the neighbour list again. True when
   they are this step's. They are used once: any later force call in the step (run 0 after
   moving atoms, a line search) searches again. The pairs are atom indices, valid only while the
   atoms keep them: a neighbour-list build in between (a fix re-neighbouring in pre_force after
   cell/fluid) would point them at other atoms, so that is an error.
------------------------------------------------------------------------- */

bool SPHPairs::kept_for_forces()
{
  if (pairs_step != update->ntimestep) return false;
  pairs_step = -1;
  if (neighbor->ncalls != pairs_build || atom->nlocal + atom->nghost != pairs_nall)
    error->one(FLERR,
               "Pair style cell/sph: the neighbour lists were rebuilt between fix cell/fluid's "
               "continuity pass (pre_force) and the pair forces of step {}; the fluid pairs kept "
               "for the forces no longer match the atoms",
               update->ntimestep);
  return true;
}

/* ---------------------------------------------------------------------- */

void SPHPairs::find_candidates()
{
  const int *const fluid = types.fluid;
  const int *const type = atom->type;
  // the protoplasm of one cell never meets another cell's (CellMech::same_cell), even across two
  // glued walls within the kernel's support
  const tagint *const molecule = atom->molecule;
  const int inum = list->inum;
  const int *const ilist = list->ilist;
  const int *const numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  if (inum + 1 > maxcand_first) {
    maxcand_first = inum + 1;
    memory->destroy(cand_first);
    memory->create(cand_first, maxcand_first, "pair:cand_first");
  }
  int ncand = 0;
  for (int ii = 0; ii < inum; ii++) {
    cand_first[ii] = ncand;
    const int i = ilist[ii];
    if (!fluid[type[i]]) continue;
    const int *const jlist = firstneigh[i];
    const int jnum = numneigh[i];
    if (ncand + jnum > maxcand) {
      maxcand = MAX(ncand + jnum, 2 * maxcand);
      memory->grow(cand_j, maxcand, "pair:cand_j");
    }
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!fluid[type[j]]) continue;
      if (!same_cell(molecule, i, j)) continue;
      cand_j[ncand++] = j;
    }
  }
  cand_first[inum] = ncand;
  // the most pairs find_pairs can keep
  if (ncand > maxpair) {
    maxpair = ncand;
    memory->destroy(pair_j);
    memory->destroy(pair_wr);
    memory->create(pair_j, maxpair, "pair:pair_j");
    memory->create(pair_wr, maxpair, "pair:pair_wr");
  }
  if (inum + 1 > maxfirst) {
    maxfirst = inum + 1;
    memory->destroy(pair_first);
    memory->create(pair_first, maxfirst, "pair:pair_first");
  }
  cand_build = neighbor->ncalls;
  cand_nall = atom->nlocal + atom->nghost;
  check_uniform_s();
}

// whether one smoothing length serves every fluid type pair (pair_coeff may change between runs,
// and a run's init always builds the neighbour lists anew, so a build is the place to look)
void SPHPairs::check_uniform_s()
{
  s_uniform = true;
  bool seen = false;
  for (int it = 1; it <= atom->ntypes; it++)
    for (int jt = it; jt <= atom->ntypes; jt++) {
      if (!types.fluid[it] || !types.fluid[jt]) continue;
      if (!seen) {
        seen = true;
        sinv_uniform = types.sinv[it][jt];
        wrnorm_uniform = types.wrnorm[it][jt];
      } else if (types.sinv[it][jt] != sinv_uniform)    // 1/s, and so norm/s, follows from s
        s_uniform = false;
    }
}

/* ----------------------------------------------------------------------
   The kernel factor wr = (dW/dr) / r (kernel_wr) of n pairs of one type pair (1 / s and
   kernel_wr_norm(s)), from r^2 in place. The compiler turns the kernel's two brackets
   into a select and runs the loop in SIMD lanes, for the baseline and for AVX2 (cell_simd.h),
   with the bits of one pair at a time.
------------------------------------------------------------------------- */

CELLMECH_SIMD_CLONES static void kernel_wr_sweep(double *__restrict w, int n, double inv_s,
                                                 double wr_norm)
{
  for (int k = 0; k < n; k++) w[k] = kernel_wr(w[k], inv_s, wr_norm);
}

/* ----------------------------------------------------------------------
   The candidates k0 .. kend-1 of a particle at (xi, yi, zi) that lie inside the support, appended
   to the pair list from npair with their r^2; returns the new count. With BRANCHLESS every
   candidate is stored and the count moves past it only if it is inside, without a branch.
------------------------------------------------------------------------- */

template <bool BRANCHLESS>
static inline int keep_inside(const int *cand_j, int k0, int kend, const double *x, double xi,
                              double yi, double zi, const int *type, const double *cutsqi,
                              int *pair_j, double *pair_wr, int npair)
{
  for (int k = k0; k < kend; k++) {
    const int j = cand_j[k];
    const double delx = xi - x[3 * j];
    const double dely = yi - x[3 * j + 1];
    const double delz = zi - x[3 * j + 2];
    const double rsq = delx * delx + dely * dely + delz * delz;
    if constexpr (BRANCHLESS) {
      pair_j[npair] = j;
      pair_wr[npair] = rsq;
      npair += (rsq < cutsqi[type[j]]);
    } else {
      if (rsq >= cutsqi[type[j]]) continue;
      pair_j[npair] = j;
      pair_wr[npair] = rsq;
      npair++;
    }
  }
  return npair;
}

/* ----------------------------------------------------------------------
   The kind of distance test for this search. Which candidates lie inside the support: a branch
   on it is nearly free where the CPU's predictor learns the pattern (the regular lists of a
   lattice at rest) and mispredicted at every turn where it cannot (a moving fluid's lists, atoms
   re-sorted: a tenth of the full cell's step); a test without a branch costs a little in the
   first case and saves that in the second. With search auto the faster is measured, as FFTW's
   planner measures its plans: at each setup and every SEARCH_REPLAN searches, one search
   untimed, then SEARCH_PLAN - SEARCH_TIMED - 1 without a branch and SEARCH_TIMED with one (the
   predictor learns over a few); search_took keeps the shortest time of each kind and, at the
   plan's end, the faster kind, which serves until the next plan. Both kinds keep the same pairs
   in the same order, so the choice changes no bit, only the time.
------------------------------------------------------------------------- */

int SPHPairs::search_kind()
{
  if (search_choice != AUTO) return search_choice;
  if (update->setupflag || ++search_count >= SEARCH_REPLAN) {
    search_count = 0;
    search_trials = SEARCH_PLAN;
    search_time[BRANCH] = search_time[BRANCHLESS] = HUGE_VAL;
  }
  if (search_trials == 0 || search_trials == SEARCH_PLAN) return search_mode;
  return search_trials > SEARCH_TIMED ? BRANCHLESS : BRANCH;
}

void SPHPairs::search_took(int kind, double seconds)
{
  if (search_trials == 0) return;
  if (search_trials < SEARCH_PLAN) search_time[kind] = MIN(search_time[kind], seconds);
  if (--search_trials == 0)
    search_mode = search_time[BRANCHLESS] < search_time[BRANCH] ? BRANCHLESS : BRANCH;
}

/* ---------------------------------------------------------------------- */

template <bool CONTINUITY> void SPHPairs::find_pairs(double *drho)
{
  // the candidates change only when the neighbour list does: atoms keep their indices between
  // builds, and within a run every build counts up neighbor->ncalls. Every setup (of a run, a
  // minimisation, a rerun frame) builds the lists anew and then sets that count back to 0, so a
  // run after a run 0 would see the count it ended with although the atoms were re-sorted or
  // moved in between (displace_atoms, read_dump, the sort of the setup): a setup always searches.
  if (update->setupflag || neighbor->ncalls != cand_build ||
      atom->nlocal + atom->nghost != cand_nall)
    find_candidates();

  // atom->x and atom->v are contiguous N x 3 blocks: one load per coordinate, not two
  const double *const x = atom->x ? atom->x[0] : nullptr;
  const double *const v = atom->v ? atom->v[0] : nullptr;
  const double *const rmass = atom->rmass;
  const int *const type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const int inum = list->inum;
  const int *const ilist = list->ilist;

  const int kind = search_kind();
  const auto start = std::chrono::steady_clock::now();
  int npair = 0;
  for (int ii = 0; ii < inum; ii++) {
    pair_first[ii] = npair;
    const int kend = cand_first[ii + 1];
    if (cand_first[ii] == kend) continue;
    const int i = ilist[ii];
    const int itype = type[i];
    const double xi = x[3 * i], yi = x[3 * i + 1], zi = x[3 * i + 2];
    const double vxi = v[3 * i], vyi = v[3 * i + 1], vzi = v[3 * i + 2];
    const double mi = rmass[i];
    const double *const cutsqi = types.cutsq[itype];
    const double *const sinvi = types.sinv[itype];
    const double *const normi = types.wrnorm[itype];
    // three sweeps over i's pairs, so that the square roots and divisions of the kernel, which
    // the loop waits on, run side by side in SIMD lanes: the distance test writes the pairs inside
    // the support with their r^2, the kernel sweep turns r^2 into wr in place, the continuity
    // sweep adds the terms of Eq. 7.
    const int first = npair;
    if (kind == BRANCH)
      npair = keep_inside<false>(cand_j, cand_first[ii], kend, x, xi, yi, zi, type, cutsqi, pair_j,
                                 pair_wr, npair);
    else
      npair = keep_inside<true>(cand_j, cand_first[ii], kend, x, xi, yi, zi, type, cutsqi, pair_j,
                                pair_wr, npair);
    if (s_uniform)
      kernel_wr_sweep(pair_wr + first, npair - first, sinv_uniform, wrnorm_uniform);
    else
      for (int k = first; k < npair; k++) {
        const int jtype = type[pair_j[k]];
        pair_wr[k] = kernel_wr(pair_wr[k], sinvi[jtype], normi[jtype]);
      }
    if (!CONTINUITY) continue;
    // i's sum in a register: no neighbour is i itself, and starting from what earlier particles
    // added keeps the order of additions, and so every bit, of adding to drho[i] pair by pair
    double drhoi = drho[i];
    for (int k = first; k < npair; k++) {
      const int j = pair_j[k];
      const double vdotw =
          continuity_term(vxi - v[3 * j], vyi - v[3 * j + 1], vzi - v[3 * j + 2], xi - x[3 * j],
                          yi - x[3 * j + 1], zi - x[3 * j + 2], pair_wr[k]);
      drhoi += rmass[j] * vdotw;
      if (newton_pair || j < nlocal) drho[j] += mi * vdotw;
    }
    drho[i] = drhoi;
  }
  pair_first[inum] = npair;
  search_took(kind,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

}    // namespace CellMech
