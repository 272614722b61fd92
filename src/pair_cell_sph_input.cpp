/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: pair style cell/sph, its input: the pair_style keywords and the pair_coeff
   coefficients, and the checks at init (the respa level, the kernel's reach of the fluid spacing,
   the acoustic time step, the fluid atoms' mass, density and bonds): kept apart from the
   reference style's equations, as the pair machinery is (cell_sph_pairs.cpp)
------------------------------------------------------------------------- */

#include "pair_cell_sph.h"

#include "cell_checks.h"
#include "cell_coeff.h"
#include "cell_sph_pairs.h"

#include "atom.h"
#include "error.h"
#include "physics/tait.h"
#include "modify.h"
#include "respa.h"
#include "update.h"

#include <cmath>
#include <string>
#include <vector>

using namespace LAMMPS_NS;
using namespace CellPhysics;

/* ----------------------------------------------------------------------
   pair_style cell/sph [search auto|branch|branchless] [stress eps n dp] [cohesion gamma]
   search: the kind of the distance test of the pair search (cell_sph_pairs.h; auto, the default:
   the faster one, measured as the run goes). Every kind gives the same bits, so the choice is for
   tests and timing. stress: Monaghan's artificial stress (physics/sph.h), off by default.
   cohesion: the protoplasm's surface tension gamma (Eqs. C1-C2, physics/sph.h), off by default.
   A pair_style command given again starts from the defaults.
------------------------------------------------------------------------- */

void PairCellSPH::settings(int narg, char **arg)
{
  pairs->set_search(CellMech::SPHPairs::AUTO);
  stress_eps = stress_dp = 0.0;
  stress_n = 0;
  coh_gamma = 0.0;
  int iarg = 0;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "search") {
      if (iarg + 2 > narg)
        error->all(FLERR, "Illegal pair_style cell/sph command: 'search' needs a kind");
      const int search = CellMech::SPHPairs::search_named(arg[iarg + 1]);
      if (search < 0)
        error->all(FLERR,
                   "pair_style cell/sph search: expected auto, branch or branchless, got '{}'",
                   arg[iarg + 1]);
      pairs->set_search(search);
      iarg += 2;
    } else if (key == "stress") {
      if (iarg + 4 > narg)
        error->all(FLERR, "Illegal pair_style cell/sph command: 'stress' needs eps n dp, got {}",
                   narg - iarg - 1);
      stress_settings(3, arg + iarg + 1);
      iarg += 4;
    } else if (key == "cohesion") {
      if (iarg + 2 > narg)
        error->all(FLERR, "Illegal pair_style cell/sph command: 'cohesion' needs gamma");
      coh_gamma = CellMech::coefficient(lmp, "pair_style cell/sph cohesion", "surface tension gamma",
                                        arg[iarg + 1], CellMech::Sign::POSITIVE);
      iarg += 2;
    } else
      error->all(FLERR,
                 "Illegal pair_style cell/sph command: expected keyword 'search', 'stress' or "
                 "'cohesion', got '{}'",
                 key);
  }
}

// stress eps n dp: eps > 0, an integer n >= 1, dp > 0 (checked against the supports in init_one)
void PairCellSPH::stress_settings(int, char **arg)
{
  const char *cmd = "pair_style cell/sph stress";
  using CellMech::coefficient;
  using CellMech::Sign;
  stress_eps = coefficient(lmp, cmd, "strength eps", arg[0], Sign::POSITIVE);
  stress_n = utils::inumeric(FLERR, arg[1], false, lmp);
  if (stress_n < 1)
    error->all(FLERR, "{}: exponent n must be an integer >= 1, got {}", cmd, arg[1]);
  stress_dp = coefficient(lmp, cmd, "particle spacing dp", arg[2], Sign::POSITIVE);
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
    const char *cmd = "pair_coeff cell/sph";
    using CellMech::coefficient;
    using CellMech::Sign;
    const double rho0_one = coefficient(lmp, cmd, "reference density rho0", arg[2], Sign::POSITIVE);
    const double c_one = coefficient(lmp, cmd, "sound speed c", arg[3], Sign::POSITIVE);
    const double P0_one = coefficient(lmp, cmd, "background pressure P0", arg[4], Sign::ANY);
    const double mu_one = coefficient(lmp, cmd, "viscosity mu", arg[5], Sign::NON_NEGATIVE);
    const double s_one = coefficient(lmp, cmd, "smoothing length s", arg[6], Sign::POSITIVE);
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
    const double s_one = CellMech::coefficient(lmp, "pair_coeff cell/sph", "smoothing length s",
                                               arg[2], CellMech::Sign::POSITIVE);
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
