/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: bond style cell/tether

   Each tether's rest length l0 is the distance between the REFERENCE
   positions of its two wall nodes, a per-atom array d2_cellref (3 columns)
   of fix property/atom. Storing the reference geometry per atom rather than
   a length per bond keeps l0 with the atoms through MPI migration, restart
   files and write_data with no bond bookkeeping, and lets every tether have
   its own rest length (an icosahedral sphere is not equilateral).
------------------------------------------------------------------------- */

#include "bond_cell_tether.h"

#include "cell_coeff.h"
#include "cell_compat.h"
#include "cell_fields.h"

#include "atom.h"
#include "cell_checks.h"
#include "cell_restart.h"
#include "cell_tether_sweep.h"
#include "cell_topology.h"
#include "comm.h"
#include "error.h"
#include "fix_cell_tether_break.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "physics/damping.h"
#include "physics/tether.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace CellPhysics;

/* ---------------------------------------------------------------------- */

BondCellTether::BondCellTether(LAMMPS *_lmp) :
    Bond(_lmp), G(nullptr), t0(nullptr), gamma(nullptr), lamf(nullptr), iref(-1), lmax(0.0),
    checked(0), breaker(nullptr), tethers(new CellMech::TetherSweep(_lmp))
{
  born_matrix_enable = 0;
}

BondCellTether::~BondCellTether()
{
  delete tethers;
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(G);
    memory->destroy(t0);
    memory->destroy(gamma);
    memory->destroy(lamf);
  }
}

/* ----------------------------------------------------------------------
   The forces in the bond list's order, with each tether's stretch and force factor from the
   sweep (cell_tether_sweep.h), so that every force adds up as before, bit for bit.
------------------------------------------------------------------------- */

void BondCellTether::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  // every cell run has tethers: the one place that sees each step of each of them
  CellMech::check_step_motion(lmp, "Bond style cell/tether");

  const CellMech::TetherStep t = tethers->sweep({G, t0, gamma, iref});
  double **f = atom->f;
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;
  double ebond = 0.0;
  for (int n = 0; n < nbondlist; n++) {
    const int i1 = bondlist[n][0];
    const int i2 = bondlist[n][1];
    const int type = bondlist[n][2];
    if (type <= 0) continue;    // broken
    if (!checked && (t.lam[n] > 5.0 || t.lam[n] < 0.2)) wrong_reference(i1, i2, t.lam[n]);
    if (lamf[type] > 0.0 && t.lam[n] > lamf[type]) {
      break_tether(n);
      continue;
    }
    const double fb = t.fbond[n];
    if (eflag) ebond = tether_energy(G[type], t0[type], t.rest[n], t.lam[n]);
    if (newton_bond || i1 < nlocal) {
      f[i1][0] += t.dx[n] * fb;
      f[i1][1] += t.dy[n] * fb;
      f[i1][2] += t.dz[n] * fb;
    }
    if (newton_bond || i2 < nlocal) {
      f[i2][0] -= t.dx[n] * fb;
      f[i2][1] -= t.dy[n] * fb;
      f[i2][2] -= t.dz[n] * fb;
    }
    if (evflag) ev_tally(i1, i2, nlocal, newton_bond, ebond, fb, t.dx[n], t.dy[n], t.dz[n]);
  }
  checked = 1;
  if (breaker) breaker->computed();
}

// at the start of a run, a tether far from its rest length has wrong reference positions
void BondCellTether::wrong_reference(int i1, int i2, double lam)
{
  error->one(FLERR,
             "Bond style cell/tether: tether {}-{} is stretched {:.4g} times its rest length at "
             "the start of a run; the reference positions d2_cellref are wrong for it (is the "
             "fix property/atom defined with 'ghost yes'?){}",
             atom->tag[i1], atom->tag[i2], lam, CellMech::RESTART_FIELDS_HINT);
}

/* ----------------------------------------------------------------------
   Failure is tension only: a compressed tether never breaks. The bond leaves the bond list and
   the bond arrays of the atom(s) storing it now; fix CELL_TETHER_BREAK takes the rest of the
   topology with it on every rank.
------------------------------------------------------------------------- */

void BondCellTether::break_tether(int n)
{
  int **bondlist = neighbor->bondlist;
  const int i1 = bondlist[n][0];
  const int i2 = bondlist[n][1];
  tagint *tag = atom->tag;
  bondlist[n][2] = 0;
  CellMech::remove_bond(atom, i1, tag[i2]);
  if (!force->newton_bond && i2 < atom->nlocal) CellMech::remove_bond(atom, i2, tag[i1]);
  breaker->tether_broke(tag[i1], tag[i2]);
}

/* ---------------------------------------------------------------------- */

void BondCellTether::allocate()
{
  allocated = 1;
  const int np1 = atom->nbondtypes + 1;
  memory->create(G, np1, "bond:G");
  memory->create(t0, np1, "bond:t0");
  memory->create(gamma, np1, "bond:gamma");
  memory->create(lamf, np1, "bond:lamf");
  memory->create(setflag, np1, "bond:setflag");
  for (int i = 1; i < np1; i++) setflag[i] = 0;
}

void BondCellTether::settings(int narg, char ** /*arg*/)
{
  if (narg != 0)
    error->all(FLERR, "Illegal bond_style cell/tether command: expected no arguments, got {}",
               narg);
}

/* ----------------------------------------------------------------------
   bond_coeff N G t0 gamma [lamf value]
------------------------------------------------------------------------- */

void BondCellTether::coeff(int narg, char **arg)
{
  if (narg != 4 && narg != 6)
    error->all(FLERR,
               "Incorrect number of args for bond_coeff cell/tether: expected "
               "'bond_coeff N G t0 gamma [lamf value]', got {} arguments",
               narg);
  if (!allocated) allocate();

  int ilo, ihi;
  utils::bounds(FLERR, arg[0], 1, atom->nbondtypes, ilo, ihi, error);

  const char *cmd = "bond_coeff cell/tether";
  const CellMech::WallCoefficients wall = CellMech::wall_coefficients(lmp, cmd, arg + 1, true);
  double lamf_one = 0.0;
  if (narg == 6) {
    if (strcmp(arg[4], "lamf") != 0)
      error->all(FLERR, "Unknown keyword '{}' in bond_coeff cell/tether: expected 'lamf'", arg[4]);
    lamf_one = utils::numeric(FLERR, arg[5], false, lmp);
    if (lamf_one <= 1.0)
      error->all(FLERR,
                 "bond_coeff cell/tether: critical stretch lamf must be > 1 (a tether breaks "
                 "when l/l0 > lamf), got {}",
                 lamf_one);
  }
  CellMech::require_magnitude(lmp, cmd, "critical stretch lamf", lamf_one);
  if (CellMech::set_types(ilo, ihi, setflag,
                          {{G, wall.G}, {t0, wall.t0}, {gamma, wall.gamma}, {lamf, lamf_one}}) == 0)
    error->all(FLERR, "Incorrect args for bond coefficients");
  // created now, so that its count (f_cell_broken) can be used in thermo and variables at once
  if (lamf_one > 0.0) add_break_fix();
}

/* ----------------------------------------------------------------------
   the topology bookkeeping of broken tethers; when it is created after
   read_restart it picks up its data from the restart file
------------------------------------------------------------------------- */

void BondCellTether::add_break_fix()
{
  FixCellTetherBreak::ensure(lmp);
}

/* ---------------------------------------------------------------------- */

void BondCellTether::init_style()
{
  CellMech::require_unit_consistency(lmp, "Bond style cell/tether");
  checked = 0;
  iref = CellMech::reference_positions(lmp, "Bond style cell/tether");
  if (CellMech::any_positive(setflag, gamma, atom->nbondtypes))
    CellMech::require_ghost_velocities(lmp, "Bond style cell/tether with damping gamma > 0");

  // longest rest length of the local bonds, for LAMMPS's bond-extent sanity check
  double lmax_local = 0.0;
  if (atom->darray[iref]) {
    for (int i = 0; i < atom->nlocal; i++)
      for (int m = 0; m < atom->num_bond[i]; m++) {
        const int j = atom->map(atom->bond_atom[i][m]);
        if (j >= 0) lmax_local = MAX(lmax_local, CellMech::rest_length(atom->darray[iref], i, j));
      }
  }
  MPI_Allreduce(&lmax_local, &lmax, 1, MPI_DOUBLE, MPI_MAX, world);

  // tethers that can break need the topology bookkeeping of fix CELL_TETHER_BREAK (made by
  // bond_coeff, or here for coefficients from a restart file, before the fixes are initialised)
  breaker = nullptr;
  if (CellMech::any_positive(setflag, lamf, atom->nbondtypes)) {
    // a broken tether's nodes leave each other's 1-2 list and become an ordinary pair (or 1-3
    // when the special list is rebuilt from the bonds)
    CellMech::require_special_lj_011(lmp, "Bond style cell/tether with a critical stretch lamf",
                                     "broken tethers turn their nodes into a non-bonded pair");
    breaker = FixCellTetherBreak::ensure(lmp);
  }
  check_timestep();
  CellMech::check_drag(lmp);
}

/* ----------------------------------------------------------------------
   A time step far above the stability limit of a tether (cell_checks.h: FAR_ABOVE_LIMIT): the
   tension's slope at rest is 2 sqrt(3) G t0 whatever the rest length (Eq. 19), and two nodes of
   mass m joined by it oscillate at omega^2 = 2 k / m; velocity Verlet needs omega dt < 2.
------------------------------------------------------------------------- */

void BondCellTether::check_timestep()
{
  if (!CellMech::will_step(lmp)) return;
  double kmax = 0.0;
  int tmax = 0;
  for (int t = 1; t <= atom->nbondtypes; t++)
    if (setflag[t] && 2.0 * SQRT3 * G[t] * t0[t] > kmax)
      kmax = 2.0 * SQRT3 * G[t] * t0[t], tmax = t;
  double mlocal = HUGE_VAL, mmin;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < atom->num_bond[i]; m++) {
      const int type = atom->bond_type[i][m];
      if (type > 0 && setflag[type]) mlocal = MIN(mlocal, CellMech::atom_mass(atom, i));
    }
  MPI_Allreduce(&mlocal, &mmin, 1, MPI_DOUBLE, MPI_MIN, world);
  if (kmax == 0.0 || !(mmin > 0.0) || mmin == HUGE_VAL) return;
  const double limit = 2.0 / sqrt(2.0 * kmax / mmin);
  if (update->dt <= CellMech::FAR_ABOVE_LIMIT * limit) return;
  error->all(FLERR,
             "Bond style cell/tether: the time step {:g} is {:.3g} times the stability limit "
             "2/omega = {:.4g} of a tether (bond type {}: G {:g}, t0 {:g}, stiffness 2 sqrt(3) G "
             "t0 = {:.4g} between nodes of mass {:.4g}): the wall would blow the run up in its "
             "first steps; {}",
             update->dt, update->dt / limit, limit, tmax, G[tmax], t0[tmax], kmax, mmin,
             CellMech::timestep_hint(lmp));
}

/* ---------------------------------------------------------------------- */

double BondCellTether::equilibrium_distance(int /*i*/)
{
  return lmax;
}

/* ---------------------------------------------------------------------- */

void BondCellTether::write_restart(FILE *fp)
{
  CellMech::write_type_arrays(fp, atom->nbondtypes, {G, t0, gamma, lamf});
}

void BondCellTether::read_restart(FILE *fp)
{
  allocate();
  const int n = atom->nbondtypes;
  CellMech::read_type_arrays(fp, n, {G, t0, gamma, lamf}, comm->me, world, error);
  for (int i = 1; i <= n; i++) setflag[i] = 1;
}

void BondCellTether::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->nbondtypes; i++) {
    if (lamf[i] > 0.0)
      fprintf(fp, "%d %.15g %.15g %.15g lamf %.15g\n", i, G[i], t0[i], gamma[i], lamf[i]);
    else
      fprintf(fp, "%d %.15g %.15g %.15g\n", i, G[i], t0[i], gamma[i]);
  }
}

/* ---------------------------------------------------------------------- */

double BondCellTether::single(int type, double rsq, int i, int j, double &fforce)
{
  const double r = sqrt(rsq);
  const double l0 = CellMech::rest_length(atom->darray[iref], i, j);
  const double lam = r / l0;
  fforce = -tether_tension(G[type], t0[type], l0, lam) / r;
  if (gamma[type] > 0.0)
    fforce += damping_fpair(gamma[type], CellMech::radial_rate(atom->x, atom->v, i, j), rsq);
  return tether_energy(G[type], t0[type], l0, lam);
}

/* ---------------------------------------------------------------------- */

void *BondCellTether::extract(const char *str, int &dim)
{
  dim = 1;
  if (strcmp(str, "G") == 0) return (void *) G;
  if (strcmp(str, "t0") == 0) return (void *) t0;
  if (strcmp(str, "gamma") == 0) return (void *) gamma;
  if (strcmp(str, "lamf") == 0) return (void *) lamf;
  return nullptr;
}
