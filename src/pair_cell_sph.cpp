/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: pair style cell/sph

   Weakly compressible SPH for the protoplasm (Van Liedekerke et al. 2010):
     dv_i/dt = - sum_j m_j (P_i/rho_i^2 + P_j/rho_j^2) grad_i W_ij
               + sum_j m_j (mu_i + mu_j) / (rho_i rho_j) v_ij (1/r) dW/dr     (Eq. 5)
     P = P0 + rho0 c^2/7 [(rho/rho0)^7 - 1]                                   (Eq. 6)
     drho_i/dt (continuity part) = sum_j m_j v_ij . grad_i W_ij               (Eq. 7)
   Particles of different molecule IDs (cells) do not interact.
   Per-particle mass is atom->rmass (osmosis changes it, fix cell/fluid);
   density and its rate live in fix property/atom as d_rho and d_drho.
   fix cell/fluid advances density and mass before the forces (using
   continuity() below), so both are forward-communicated to ghosts at the
   start of compute(); the rate is reverse-communicated in continuity().
   The pair energy is the fluid's internal energy sum_i m_i e(rho_i) with
   de/drho = P/rho^2, so that kinetic + potential energy is the conserved
   total of the inviscid equations.
------------------------------------------------------------------------- */

#include "pair_cell_sph.h"

#include "cell_checks.h"
#include "cell_compat.h"
#include "cell_fields.h"
#include "cell_simd.h"

#include "atom.h"
#include "cell_topology.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "physics/kernel.h"
#include "physics/sph.h"
#include "physics/tait.h"
#include "respa.h"
#include "update.h"

#include <chrono>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;
using namespace CellPhysics;

/* ---------------------------------------------------------------------- */

PairCellSPH::PairCellSPH(LAMMPS *_lmp) :
    Pair(_lmp), fluid(nullptr), rho0(nullptr), c(nullptr), P0(nullptr), mu(nullptr), kappa(nullptr),
    s(nullptr), sinv(nullptr), wrnorm(nullptr), irho(-1), idrho(-1), nmax(0), quant(nullptr),
    pairs_step(-1), pairs_build(-1), pairs_nall(-1), pair_first(nullptr), pair_j(nullptr),
    pair_wr(nullptr), maxfirst(0), maxpair(0), cand_build(-1), cand_nall(-1), cand_first(nullptr),
    cand_j(nullptr), maxcand_first(0), maxcand(0), s_uniform(false), sinv_uniform(0.0),
    wrnorm_uniform(0.0)
{
  comm_forward = 2;
  comm_reverse = 1;
  // the viscous force is not along r_ij; the virial is tallied per pair with its full vector
  no_virial_fdotr_compute = 0;
}

PairCellSPH::~PairCellSPH()
{
  memory->destroy(quant);
  memory->destroy(pair_first);
  memory->destroy(pair_j);
  memory->destroy(pair_wr);
  memory->destroy(cand_first);
  memory->destroy(cand_j);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(fluid);
    memory->destroy(rho0);
    memory->destroy(c);
    memory->destroy(P0);
    memory->destroy(mu);
    memory->destroy(kappa);
    memory->destroy(s);
    memory->destroy(sinv);
    memory->destroy(wrnorm);
  }
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::find_candidates()
{
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
      if (!CellMech::same_cell(molecule, i, j)) continue;
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

  // whether one smoothing length serves every fluid type pair (pair_coeff may change between runs,
  // and a run's init always builds the neighbour lists anew, so this is the place to look)
  s_uniform = true;
  bool seen = false;
  for (int it = 1; it <= atom->ntypes; it++)
    for (int jt = it; jt <= atom->ntypes; jt++) {
      if (!fluid[it] || !fluid[jt]) continue;
      if (!seen) {
        seen = true;
        sinv_uniform = sinv[it][jt];
        wrnorm_uniform = wrnorm[it][jt];
      } else if (sinv[it][jt] != sinv_uniform)    // 1/s, and so norm/s, follows from s
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

int PairCellSPH::search_kind()
{
  if (search_choice != SEARCH_AUTO) return search_choice;
  if (update->setupflag || ++search_count >= SEARCH_REPLAN) {
    search_count = 0;
    search_trials = SEARCH_PLAN;
    search_time[SEARCH_BRANCH] = search_time[SEARCH_BRANCHLESS] = HUGE_VAL;
  }
  if (search_trials == 0 || search_trials == SEARCH_PLAN) return search_mode;
  return search_trials > SEARCH_TIMED ? SEARCH_BRANCHLESS : SEARCH_BRANCH;
}

void PairCellSPH::search_took(int kind, double seconds)
{
  if (search_trials == 0) return;
  if (search_trials < SEARCH_PLAN) search_time[kind] = MIN(search_time[kind], seconds);
  if (--search_trials == 0)
    search_mode = search_time[SEARCH_BRANCHLESS] < search_time[SEARCH_BRANCH] ? SEARCH_BRANCHLESS
                                                                              : SEARCH_BRANCH;
}

/* ---------------------------------------------------------------------- */

template <bool CONTINUITY> void PairCellSPH::find_pairs()
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
  double *const drho = atom->dvector[idrho];
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
    const double *const cutsqi = cutsq[itype];
    const double *const sinvi = sinv[itype];
    const double *const normi = wrnorm[itype];
    // three sweeps over i's pairs, so that the square roots and divisions of the kernel, which
    // the loop waits on, run side by side in SIMD lanes: the distance test writes the pairs inside
    // the support with their r^2, the kernel sweep turns r^2 into wr in place, the continuity
    // sweep adds the terms of Eq. 7.
    const int first = npair;
    if (kind == SEARCH_BRANCH)
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

/* ---------------------------------------------------------------------- */

void PairCellSPH::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (update->setupflag) check_respa_level();

  // fix cell/fluid advanced density and mass in pre_force: refresh the ghosts
  comm->forward_comm(this);

  double *rmass = atom->rmass;
  int *type = atom->type;
  double *rho = atom->dvector[irho];
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int newton_pair = force->newton_pair;

  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(quant);
    memory->create(quant, NQUANT * nmax, "pair:quant");
  }

  // quantities of one particle only: once per particle, not per pair, side by side for the
  // pair loop's gathers: P / rho^2, m, rho, mu
  for (int i = 0; i < nall; i++) {
    const int t = type[i];
    double *const q = quant + NQUANT * i;
    if (fluid[t]) {
      const double inv_rho = 1.0 / rho[i];
      q[0] = pressure(t, rho[i]) * inv_rho * inv_rho;
      q[1] = rmass[i];
      q[2] = inv_rho;
      q[3] = mu[t];
      if (i < nlocal && eflag) {
        const double ei = rmass[i] * tait_internal_energy(rho[i], rho0[t], c[t], P0[t]);
        if (eflag_global) eng_vdwl += ei;
        if (eflag_atom) eatom[i] += ei;
      }
    } else
      q[0] = q[1] = q[2] = q[3] = 0.0;
  }

  // the pairs of fix cell/fluid's continuity pass at these positions, or a search of our own
  if (!pairs_of_continuity()) find_pairs<false>();

  const double *const x = atom->x ? atom->x[0] : nullptr;
  const double *const vf = atom->v ? atom->v[0] : nullptr;
  double *const ff = atom->f ? atom->f[0] : nullptr;
  const int *const ilist = list->ilist;
  const int inum = list->inum;
  for (int ii = 0; ii < inum; ii++) {
    const int kend = pair_first[ii + 1];
    if (pair_first[ii] == kend) continue;
    const int i = ilist[ii];
    const double xi = x[3 * i], yi = x[3 * i + 1], zi = x[3 * i + 2];
    const double vxi = vf[3 * i], vyi = vf[3 * i + 1], vzi = vf[3 * i + 2];
    const double *const qi = quant + NQUANT * i;
    const double prho2i = qi[0], mi = qi[1], irhoi = qi[2], mui = qi[3];
    // as drho[i] in find_pairs: the same additions in the same order, in registers
    double fxi = ff[3 * i], fyi = ff[3 * i + 1], fzi = ff[3 * i + 2];
    for (int k = pair_first[ii]; k < kend; k++) {
      const int j = pair_j[k];
      const double wr = pair_wr[k];
      const double *const qj = quant + NQUANT * j;
      const double mj = qj[1];
      // the same differences as in the search, so the same bits
      const double delx = xi - x[3 * j];
      const double dely = yi - x[3 * j + 1];
      const double delz = zi - x[3 * j + 2];
      const double dvx = vxi - vf[3 * j];
      const double dvy = vyi - vf[3 * j + 1];
      const double dvz = vzi - vf[3 * j + 2];

      // Eq. 5: pressure (central) and Morris viscosity (along v_ij), both antisymmetric in i, j
      const double fp = sph_pressure_fpair(mi, mj, prho2i, qj[0], wr);
      const double fv = sph_viscous_fvel(mi, mj, mui, qj[3], irhoi, qj[2], wr);
      const double fx = fp * delx + fv * dvx;
      const double fy = fp * dely + fv * dvy;
      const double fz = fp * delz + fv * dvz;

      fxi += fx;
      fyi += fy;
      fzi += fz;
      if (newton_pair || j < nlocal) {
        ff[3 * j] -= fx;
        ff[3 * j + 1] -= fy;
        ff[3 * j + 2] -= fz;
      }
      if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
    }
    ff[3 * i] = fxi;
    ff[3 * i + 1] = fyi;
    ff[3 * i + 2] = fzi;
  }

  if (vflag_fdotr) virial_fdotr_compute();
}

/* ----------------------------------------------------------------------
   fix cell/fluid advances the density on respa's outermost level, with the continuity pass whose
   pairs these forces reuse. With respa's 'hybrid' keyword only Respa knows which sub-style is
   on which level; the level that computes now is the outermost iff it tallies global energies.
------------------------------------------------------------------------- */

void PairCellSPH::check_respa_level()
{
  // a minimisation's setup calls the pair directly, outside respa's levels
  if (update->whichflag != 1 || !utils::strmatch(update->integrate_style, "^respa")) return;
  auto respa = dynamic_cast<Respa *>(update->integrate);
  if (!respa || respa->nhybrid_styles == 0 || respa->tally_global) return;
  if (!modify->get_fix_by_style("^cell/fluid").empty())
    error->all(FLERR,
               "Pair style cell/sph with fix cell/fluid under run_style respa must be on the "
               "outermost level, where the fix advances the density: expected level {} for "
               "cell/sph in the respa 'hybrid' keyword, got an inner level",
               respa->nlevels);
}

/* ----------------------------------------------------------------------
   continuity rate drho_i/dt = sum_j m_j v_ij . grad_i W_ij (Eq. 7) into d_drho
   of local atoms. Called by fix cell/fluid before the forces, with the
   velocities of the half step, so that the density leapfrogs the velocity.
------------------------------------------------------------------------- */

void PairCellSPH::continuity()
{
  double *drho = atom->dvector[idrho];
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const int nall = nlocal + atom->nghost;
  for (int i = 0; i < (newton_pair ? nall : nlocal); i++) drho[i] = 0.0;

  // keep the interacting pairs for the force call that follows at the same positions
  pairs_step = update->ntimestep;
  pairs_build = neighbor->ncalls;
  pairs_nall = nall;
  find_pairs<true>();
  if (newton_pair) comm->reverse_comm(this);
}

/* ----------------------------------------------------------------------
   The coupling with fix cell/fluid. It calls continuity() in pre_force, after this step's
   neighbour lists are built and before the forces, so that the density leapfrogs the velocity;
   continuity() keeps the fluid pairs and kernel gradients it finds, and the force call that
   follows at the same positions takes them instead of searching the neighbour list again.
   True when they are this step's. They are used once: any later force call in the step (run 0
   after moving atoms, a line search) searches again. The pairs are atom indices, valid only
   while the atoms keep them: a neighbour-list build in between (a fix re-neighbouring in
   pre_force after cell/fluid) would point them at other atoms, so that is an error.
------------------------------------------------------------------------- */

bool PairCellSPH::pairs_of_continuity()
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

void PairCellSPH::allocate()
{
  allocated = 1;
  const int np1 = atom->ntypes + 1;
  memory->create(setflag, np1, np1, "pair:setflag");
  memory->create(cutsq, np1, np1, "pair:cutsq");
  memory->create(s, np1, np1, "pair:s");
  memory->create(sinv, np1, np1, "pair:sinv");
  memory->create(wrnorm, np1, np1, "pair:wrnorm");
  memory->create(fluid, np1, "pair:fluid");
  memory->create(rho0, np1, "pair:rho0");
  memory->create(c, np1, "pair:c");
  memory->create(P0, np1, "pair:P0");
  memory->create(mu, np1, "pair:mu");
  memory->create(kappa, np1, "pair:kappa");
  for (int i = 1; i < np1; i++) {
    fluid[i] = 0;
    rho0[i] = c[i] = P0[i] = mu[i] = kappa[i] = 0.0;
    for (int j = i; j < np1; j++) setflag[i][j] = 0;
  }
}

/* ----------------------------------------------------------------------
   pair_style cell/sph [search auto|branch|branchless]: the kind of the distance test of
   find_pairs (auto, the default: the faster one, measured as the run goes). Every kind gives the
   same bits, so the choice is for tests and timing.
------------------------------------------------------------------------- */

void PairCellSPH::settings(int narg, char **arg)
{
  if (narg != 0 && narg != 2)
    error->all(FLERR,
               "Illegal pair_style cell/sph command: expected no arguments or 'search KIND', got "
               "{} arguments",
               narg);
  search_choice = SEARCH_AUTO;
  if (narg == 0) return;
  const std::string key = arg[0], kind = arg[1];
  if (key != "search")
    error->all(FLERR, "Illegal pair_style cell/sph command: expected keyword 'search', got '{}'",
               key);
  if (kind == "auto")
    search_choice = SEARCH_AUTO;
  else if (kind == "branch")
    search_choice = SEARCH_BRANCH;
  else if (kind == "branchless")
    search_choice = SEARCH_BRANCHLESS;
  else
    error->all(FLERR, "pair_style cell/sph search: expected auto, branch or branchless, got '{}'",
               kind);
}

/* ----------------------------------------------------------------------
   pair_coeff I I rho0 c P0 mu s    a fluid type: equation of state, viscosity, smoothing length
   pair_coeff I J s                 smoothing length between two fluid types (default: mean)
------------------------------------------------------------------------- */

void PairCellSPH::coeff(int narg, char **arg)
{
  if (narg != 7 && narg != 3)
    error->all(FLERR,
               "Incorrect number of args for pair_coeff cell/sph: expected "
               "'pair_coeff I I rho0 c P0 mu s' or 'pair_coeff I J s', got {} arguments",
               narg);
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  int count = 0;
  if (narg == 7) {
    if (ilo != jlo || ihi != jhi)
      error->all(FLERR,
                 "pair_coeff cell/sph: the equation of state belongs to one fluid type; use "
                 "'pair_coeff I I rho0 c P0 mu s' (and 'pair_coeff I J s' between fluid types)");
    const double rho0_one = utils::numeric(FLERR, arg[2], false, lmp);
    const double c_one = utils::numeric(FLERR, arg[3], false, lmp);
    const double P0_one = utils::numeric(FLERR, arg[4], false, lmp);
    const double mu_one = utils::numeric(FLERR, arg[5], false, lmp);
    const double s_one = utils::numeric(FLERR, arg[6], false, lmp);
    if (rho0_one <= 0.0)
      error->all(FLERR, "pair_coeff cell/sph: reference density rho0 must be > 0, got {}",
                 rho0_one);
    if (c_one <= 0.0)
      error->all(FLERR, "pair_coeff cell/sph: sound speed c must be > 0, got {}", c_one);
    if (mu_one < 0.0)
      error->all(FLERR, "pair_coeff cell/sph: viscosity mu must be >= 0, got {}", mu_one);
    if (s_one <= 0.0)
      error->all(FLERR, "pair_coeff cell/sph: smoothing length s must be > 0, got {}", s_one);
    const char *cmd = "pair_coeff cell/sph";
    CellMech::require_magnitude(lmp, cmd, "reference density rho0", rho0_one);
    CellMech::require_magnitude(lmp, cmd, "sound speed c", c_one);
    CellMech::require_magnitude(lmp, cmd, "background pressure P0", P0_one);
    CellMech::require_magnitude(lmp, cmd, "viscosity mu", mu_one);
    CellMech::require_magnitude(lmp, cmd, "smoothing length s", s_one);
    for (int i = ilo; i <= ihi; i++) {
      fluid[i] = 1;
      rho0[i] = rho0_one;
      c[i] = c_one;
      kappa[i] = tait_kappa(rho0_one, c_one);
      P0[i] = P0_one;
      mu[i] = mu_one;
      s[i][i] = s_one;
      setflag[i][i] = 1;
      count++;
    }
  } else {
    const double s_one = utils::numeric(FLERR, arg[2], false, lmp);
    if (s_one <= 0.0)
      error->all(FLERR, "pair_coeff cell/sph: smoothing length s must be > 0, got {}", s_one);
    for (int i = ilo; i <= ihi; i++)
      for (int j = MAX(jlo, i); j <= jhi; j++) {
        if (i == j)
          error->all(FLERR, "pair_coeff cell/sph: type {} needs 'pair_coeff {} {} rho0 c P0 mu s'",
                     i, i, i);
        s[i][j] = s_one;
        setflag[i][j] = 1;
        count++;
      }
  }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::init_style()
{
  CellMech::require_unit_consistency(lmp, "Pair style cell/sph");
  if (!atom->rmass_flag)
    error->all(FLERR,
               "Pair style cell/sph requires per-atom masses: add rmass to the fix property/atom "
               "(fix ID all property/atom rmass d_rho d_drho ...)");
  int flag, cols;
  irho = atom->find_custom(CellMech::RHO_FIELD, flag, cols);
  if (irho < 0 || flag != 1 || cols != 0)
    error->all(FLERR,
               "Pair style cell/sph requires the per-atom density d_rho of fix property/atom");
  idrho = atom->find_custom(CellMech::DRHO_FIELD, flag, cols);
  if (idrho < 0 || flag != 1 || cols != 0)
    error->all(
        FLERR,
        "Pair style cell/sph requires the per-atom density rate d_drho of fix property/atom");
  if (!comm->ghost_velocity)
    error->all(FLERR,
               "Pair style cell/sph requires 'comm_modify vel yes' (viscosity and continuity use "
               "ghost velocities)");
  check_fluid_atoms();
  check_spacing();
  check_timestep();
  CellMech::check_drag(lmp);
  // without fix cell/fluid the continuity equation is never integrated: a frozen density is
  // legal (a fixed boundary of SPH particles) but rarely meant for a whole system
  if (modify->get_fix_by_style("^cell/fluid").empty() && comm->me == 0)
    error->warning(FLERR, "Pair style cell/sph without fix cell/fluid: densities stay constant");
  neighbor->add_request(this);
}

/* ----------------------------------------------------------------------
   The kernel must reach the neighbours. A fluid particle stands for the volume mass/rho, so the
   fluid's spacing is dx = (mass/rho)^(1/3) (mean over each type's particles, all ranks); at
   2s = 1.25 dx the six nearest neighbours sit at r = 1.6 s, where the kernel has fallen to 1% of
   its peak, and the fluid has next to no pressure to hold its volume: the walls stay slack and the
   particles leave the cell (a coarse tissue with the paper's s = 3.2 um: 2s/dx = 1.21). The
   lengths of the levels give 2s/dx = 2.1 to 2.4 in a generated cell and about 2 once inflated.
------------------------------------------------------------------------- */

void PairCellSPH::check_spacing()
{
  const int ntypes = atom->ntypes;
  std::vector<double> local(2 * (ntypes + 1), 0.0), all(2 * (ntypes + 1));
  const double *rho = atom->dvector[irho];
  for (int i = 0; i < atom->nlocal; i++) {
    const int t = atom->type[i];
    if (!fluid[t]) continue;
    local[t] += atom->rmass[i] / rho[i];
    local[ntypes + 1 + t] += 1.0;
  }
  MPI_Allreduce(local.data(), all.data(), 2 * (ntypes + 1), MPI_DOUBLE, MPI_SUM, world);
  for (int t = 1; t <= ntypes; t++) {
    const double n = all[ntypes + 1 + t];
    if (!fluid[t] || n == 0.0) continue;
    const double dx = cbrt(all[t] / n);
    if (2.0 * s[t][t] >= MIN_SUPPORT_SPACINGS * dx) continue;
    error->all(FLERR,
               "Pair style cell/sph: the kernel support 2s = {:g} of fluid type {} (pair_coeff {} "
               "{} cell/sph ... s = {:g}) spans {:.3g} fluid spacings, below {:g}: its {:.0f} "
               "particles stand for (mass/density)^(1/3) = {:.4g} each, and a support that short "
               "hardly reaches the nearest neighbours, so the fluid holds no pressure and leaves "
               "its walls. Use s >= {:.4g}: the lengths of the wall's level (cellgen.py writes "
               "them beside the data file, DATA.lmp; tools/cellmech/params.py LEVELS)",
               2.0 * s[t][t], t, t, t, s[t][t], 2.0 * s[t][t] / dx, MIN_SUPPORT_SPACINGS, n, dx,
               0.5 * MIN_SUPPORT_SPACINGS * dx);
  }
}

// a time step far above the acoustic limit (cell_checks.h: FAR_ABOVE_LIMIT)
void PairCellSPH::check_timestep()
{
  if (!CellMech::will_step(lmp)) return;
  const double dt = update->dt;
  for (int t = 1; t <= atom->ntypes; t++) {
    if (!fluid[t] || !setflag[t][t]) continue;
    const double limit = 0.25 * s[t][t] / c[t];
    if (dt <= CellMech::FAR_ABOVE_LIMIT * limit) continue;
    error->all(FLERR,
               "Pair style cell/sph: the time step {:g} is {:.3g} times the acoustic limit 0.25 "
               "s/c = {:.4g} of fluid type {} (s {:g}, c {:g}): the fluid would blow the run up "
               "in its first steps; {}",
               dt, dt / limit, limit, t, s[t][t], c[t], CellMech::timestep_hint(lmp));
  }
}

/* ----------------------------------------------------------------------
   a fluid particle without mass or density turns every SPH sum it enters into NaN with no
   error; a wall node of a fluid type (pair_coeff * * cell/sph) would be pushed by the fluid's
   pressure as if it were fluid. Both stop the run, naming the first such atom.
------------------------------------------------------------------------- */

void PairCellSPH::check_fluid_atoms()
{
  const double *rho = atom->dvector[irho];
  const double *rmass = atom->rmass;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  tagint first_local[3] = {MAXTAGINT, MAXTAGINT, MAXTAGINT}, first[3];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!fluid[type[i]]) continue;
    if (!(rmass[i] > 0.0) || !std::isfinite(rmass[i])) first_local[0] = MIN(first_local[0], tag[i]);
    if (!(rho[i] > 0.0) || !std::isfinite(rho[i])) first_local[1] = MIN(first_local[1], tag[i]);
    if (atom->molecular == Atom::MOLECULAR && atom->nspecial && atom->nspecial[i][0] > 0)
      first_local[2] = MIN(first_local[2], tag[i]);
  }
  MPI_Allreduce(first_local, first, 3, MPI_LMP_TAGINT, MPI_MIN, world);
  auto value = [&](tagint id, int what) {
    const int i = atom->map(id);
    double v = (i >= 0 && i < atom->nlocal) ? (what == 0 ? rmass[i] : rho[i]) : -HUGE_VAL;
    double all;
    MPI_Allreduce(&v, &all, 1, MPI_DOUBLE, MPI_MAX, world);
    return all;
  };
  // the wall node of a fluid type first: its zero density is a consequence
  if (first[2] != MAXTAGINT) {
    const int i = atom->map(first[2]);
    int t = (i >= 0 && i < atom->nlocal) ? type[i] : 0, tall;
    MPI_Allreduce(&t, &tall, 1, MPI_INT, MPI_MAX, world);
    error->all(FLERR,
               "Pair style cell/sph: atom {} is bonded (a wall node) but its type {} is a fluid "
               "type (pair_coeff {} {} cell/sph); give cell/sph coefficients to the fluid types "
               "only",
               first[2], tall, tall, tall);
  }
  if (first[0] != MAXTAGINT)
    error->all(FLERR,
               "Pair style cell/sph: fluid particle {} has mass {} (rmass must be > 0: set it in "
               "the data file's cell section or with 'set ... mass'){}",
               first[0], value(first[0], 0), CellMech::RESTART_FIELDS_HINT);
  if (first[1] != MAXTAGINT)
    error->all(FLERR,
               "Pair style cell/sph: fluid particle {} has density d_rho {} (must be > 0: the "
               "rest density rho0 for a new particle){}",
               first[1], value(first[1], 1), CellMech::RESTART_FIELDS_HINT);
}

double PairCellSPH::init_one(int i, int j)
{
  if (!fluid[i] || !fluid[j])
    error->all(FLERR, "Pair style cell/sph: types {} and {} are not both fluid types", i, j);
  if (setflag[i][j] == 0) s[i][j] = 0.5 * (s[i][i] + s[j][j]);
  s[j][i] = s[i][j];
  sinv[i][j] = sinv[j][i] = 1.0 / s[i][j];
  wrnorm[i][j] = wrnorm[j][i] = kernel_wr_norm(s[i][j]);
  return 2.0 * s[i][j];
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::write_restart(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++) {
    fwrite(&fluid[i], sizeof(int), 1, fp);
    fwrite(&rho0[i], sizeof(double), 1, fp);
    fwrite(&c[i], sizeof(double), 1, fp);
    fwrite(&P0[i], sizeof(double), 1, fp);
    fwrite(&mu[i], sizeof(double), 1, fp);
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      fwrite(&s[i][j], sizeof(double), 1, fp);
    }
  }
}

void PairCellSPH::read_restart(FILE *fp)
{
  allocate();
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++) {
    if (me == 0) {
      utils::sfread(FLERR, &fluid[i], sizeof(int), 1, fp, nullptr, error);
      utils::sfread(FLERR, &rho0[i], sizeof(double), 1, fp, nullptr, error);
      utils::sfread(FLERR, &c[i], sizeof(double), 1, fp, nullptr, error);
      utils::sfread(FLERR, &P0[i], sizeof(double), 1, fp, nullptr, error);
      utils::sfread(FLERR, &mu[i], sizeof(double), 1, fp, nullptr, error);
    }
    MPI_Bcast(&fluid[i], 1, MPI_INT, 0, world);
    MPI_Bcast(&rho0[i], 1, MPI_DOUBLE, 0, world);
    MPI_Bcast(&c[i], 1, MPI_DOUBLE, 0, world);
    MPI_Bcast(&P0[i], 1, MPI_DOUBLE, 0, world);
    MPI_Bcast(&mu[i], 1, MPI_DOUBLE, 0, world);
    kappa[i] = tait_kappa(rho0[i], c[i]);
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) {
        utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
        utils::sfread(FLERR, &s[i][j], sizeof(double), 1, fp, nullptr, error);
      }
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      MPI_Bcast(&s[i][j], 1, MPI_DOUBLE, 0, world);
    }
  }
}

/* ---------------------------------------------------------------------- */

double PairCellSPH::single(int i, int j, int itype, int jtype, double rsq, double /*factor_coul*/,
                           double /*factor_lj*/, double &fforce)
{
  // central (pressure) part only; the viscous force is not along r_ij
  if (!CellMech::same_cell(atom->molecule, i, j)) {
    fforce = 0.0;
    return 0.0;
  }
  const double *rho = atom->dvector[irho];
  const double wr = kernel_wr(rsq, sinv[itype][jtype], wrnorm[itype][jtype]);
  fforce = sph_pressure_fpair(atom->rmass[i], atom->rmass[j],
                              pressure(itype, rho[i]) / (rho[i] * rho[i]),
                              pressure(jtype, rho[j]) / (rho[j] * rho[j]), wr);
  return 0.0;
}

void *PairCellSPH::extract(const char *str, int &dim)
{
  dim = 1;
  if (strcmp(str, "rho0") == 0) return (void *) rho0;
  if (strcmp(str, "c") == 0) return (void *) c;
  if (strcmp(str, "P0") == 0) return (void *) P0;
  if (strcmp(str, "mu") == 0) return (void *) mu;
  dim = 2;
  if (strcmp(str, "s") == 0) return (void *) s;
  return nullptr;
}

/* ---------------------------------------------------------------------- */

int PairCellSPH::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  double *rho = atom->dvector[irho];
  double *rmass = atom->rmass;
  int m = 0;
  for (int k = 0; k < n; k++) {
    buf[m++] = rho[list[k]];
    buf[m++] = rmass[list[k]];
  }
  return m;
}

void PairCellSPH::unpack_forward_comm(int n, int first, double *buf)
{
  double *rho = atom->dvector[irho];
  double *rmass = atom->rmass;
  int m = 0;
  for (int i = first; i < first + n; i++) {
    rho[i] = buf[m++];
    rmass[i] = buf[m++];
  }
}

int PairCellSPH::pack_reverse_comm(int n, int first, double *buf)
{
  double *drho = atom->dvector[idrho];
  int m = 0;
  for (int i = first; i < first + n; i++) buf[m++] = drho[i];
  return m;
}

void PairCellSPH::unpack_reverse_comm(int n, int *list, double *buf)
{
  double *drho = atom->dvector[idrho];
  int m = 0;
  for (int k = 0; k < n; k++) drho[list[k]] += buf[m++];
}

double PairCellSPH::memory_usage()
{
  return Pair::memory_usage() + (double) NQUANT * nmax * sizeof(double) +
      (double) maxfirst * sizeof(int) + (double) maxpair * (sizeof(int) + sizeof(double)) +
      (double) (maxcand_first + maxcand) * sizeof(int);
}
