/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: pair style cell/sph, its input checks at init (the respa level, the kernel's reach
   of the fluid spacing, the acoustic time step, the fluid atoms' mass, density and bonds): kept
   apart from the reference style's equations, as the pair machinery is (cell_sph_pairs.cpp)
------------------------------------------------------------------------- */

#include "pair_cell_sph.h"

#include "cell_checks.h"

#include "atom.h"
#include "error.h"
#include "modify.h"
#include "respa.h"
#include "update.h"

#include <cmath>
#include <vector>

using namespace LAMMPS_NS;

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
