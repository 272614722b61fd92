/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: bond style cell/lamella

   The middle lamella glues the walls of neighbouring cells. A lamella bond
   joins two wall nodes of DIFFERENT cells (molecule IDs) and carries the
   cohesive law of physics/lamella.h (Xu & Needleman, Eqs. L1-L5) over the
   wall area it stands for, A = (alam_i + alam_j)/2, where d_alam is each
   node's tributary wall area divided by its number of lamella bonds: the
   force of an interface is then the traction times its area whatever the
   wall resolution. The rest length is the distance of the two nodes'
   reference positions d2_cellref, as for bond style cell/tether, so both
   per-bond quantities travel with the atoms (MPI, restart, write_data)
   without per-bond storage.

   The law is elastic up to complete separation; debonding at 10 delta_c is
   irreversible: the bond leaves the bond arrays and the internal fix
   cell_debonded (CELL_LAMELLA_BREAK) updates the special lists and the
   per-cell-pair record on every rank.
------------------------------------------------------------------------- */

#include "bond_cell_lamella.h"

#include "cell_checks.h"
#include "cell_coeff.h"
#include "cell_compat.h"
#include "cell_fields.h"

#include "atom.h"
#include "cell_mpi.h"
#include "cell_restart.h"
#include "cell_topology.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "physics/damping.h"
#include "physics/lamella.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace CellPhysics;

/* ---------------------------------------------------------------------- */

BondCellLamella::BondCellLamella(LAMMPS *_lmp) :
    Bond(_lmp), sigma(nullptr), Gc(nullptr), gamma(nullptr), dc(nullptr), iref(-1), ialam(-1),
    lmax(0.0), breaker(nullptr)
{
  born_matrix_enable = 0;
}

BondCellLamella::~BondCellLamella()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(sigma);
    memory->destroy(Gc);
    memory->destroy(gamma);
    memory->destroy(dc);
  }
}

/* ---------------------------------------------------------------------- */

// delta_c follows sigma_c and Gc, also when fix adapt changes them during a run
void BondCellLamella::update_dc()
{
  for (int i = 1; i <= atom->nbondtypes; i++)
    if (setflag[i]) dc[i] = cohesive_length(sigma[i], Gc[i]);
}

/* ---------------------------------------------------------------------- */

void BondCellLamella::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  update_dc();
  // the setup of a run, with the bond list and the ghosts' masses and areas in place
  if (update->setupflag) check_stiffness();

  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  tagint *tag = atom->tag;
  tagint *mol = atom->molecule;
  const double *alam = atom->dvector[ialam];
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;
  double ebond = 0.0;

  for (int n = 0; n < nbondlist; n++) {
    const int i1 = bondlist[n][0];
    const int i2 = bondlist[n][1];
    const int type = bondlist[n][2];
    if (type <= 0) continue;    // debonded

    if (mol[i1] == mol[i2])
      error->one(FLERR,
                 "Bond style cell/lamella: bond {}-{} joins two nodes of the same cell (molecule "
                 "{}); lamella bonds join the walls of different cells",
                 tag[i1], tag[i2], mol[i1]);
    if (!(alam[i1] > 0.0) || !(alam[i2] > 0.0))
      error->one(FLERR,
                 "Bond style cell/lamella: bond {}-{} has no area (d_alam {} and {}); is d_alam "
                 "set for every node with lamella bonds and communicated to ghosts (ghost yes)?{}",
                 tag[i1], tag[i2], alam[i1], alam[i2], CellMech::RESTART_FIELDS_HINT);
    const double r0 = CellMech::rest_length(atom->darray[iref], i1, i2);
    if (!(r0 > 0.0))
      error->one(FLERR,
                 "Bond style cell/lamella: bond {}-{} has zero rest length; are the d2_cellref "
                 "reference positions set and communicated to ghosts (ghost yes)?{}",
                 tag[i1], tag[i2], CellMech::RESTART_FIELDS_HINT);

    const double delx = x[i1][0] - x[i2][0];
    const double dely = x[i1][1] - x[i2][1];
    const double delz = x[i1][2] - x[i2][2];
    const double rsq = delx * delx + dely * dely + delz * delz;
    const double r = sqrt(rsq);
    const double delta = r - r0;
    const double A = CellMech::lamella_area(alam, i1, i2);

    // Debonding is irreversible: the bond leaves the bond list and the bond arrays of the
    // atom(s) storing it now; fix CELL_LAMELLA_BREAK updates the special lists and the record on
    // every rank
    if (delta > cohesive_break_opening(dc[type])) {
      bondlist[n][2] = 0;
      CellMech::remove_bond(atom, i1, tag[i2]);
      if (!newton_bond && i2 < nlocal) CellMech::remove_bond(atom, i2, tag[i1]);
      const bool first = tag[i1] < tag[i2];
      breaker->debonded(first ? tag[i1] : tag[i2], first ? tag[i2] : tag[i1],
                        first ? mol[i1] : mol[i2], first ? mol[i2] : mol[i1], A);
      continue;
    }

    double fbond = -A * cohesive_traction(sigma[type], dc[type], delta) / r;
    if (gamma[type] > 0.0) {
      const double dvx = v[i1][0] - v[i2][0];
      const double dvy = v[i1][1] - v[i2][1];
      const double dvz = v[i1][2] - v[i2][2];
      fbond += damping_fpair(A * gamma[type], delx * dvx + dely * dvy + delz * dvz, rsq);
    }
    if (eflag) ebond = A * cohesive_energy(sigma[type], dc[type], delta);

    if (newton_bond || i1 < nlocal) {
      f[i1][0] += delx * fbond;
      f[i1][1] += dely * fbond;
      f[i1][2] += delz * fbond;
    }
    if (newton_bond || i2 < nlocal) {
      f[i2][0] -= delx * fbond;
      f[i2][1] -= dely * fbond;
      f[i2][2] -= delz * fbond;
    }
    if (evflag) ev_tally(i1, i2, nlocal, newton_bond, ebond, fbond, delx, dely, delz);
  }
  breaker->computed();
}

/* ----------------------------------------------------------------------
   A lamella bond is a spring of stiffness A sigma_c e / delta_c (the slope of Eqs. L1-L2 at zero
   opening, the steepest of the law) between two wall nodes; a small critical opening delta_c
   makes it stiffer than the time step can follow. A spring alone is integrated stably by velocity
   Verlet only while omega dt < 2, omega^2 = k (1/m1 + 1/m2); beyond that the run blows up within
   a few steps, and the blow-up is reported far from its cause. Stops the run at its start,
   naming the bond type's delta_c and what would keep it stable. Collective: at the setup, where
   every rank computes the bonds.
------------------------------------------------------------------------- */

void BondCellLamella::check_stiffness()
{
  const double *alam = atom->dvector[ialam];
  const double dt = CellMech::bond_step(lmp);
  int **bondlist = neighbor->bondlist;
  struct {
    double w;
    int rank;
  } mine = {0.0, comm->me}, worst;
  int nmax = -1;
  double kmax = 0.0;
  for (int n = 0; n < neighbor->nbondlist; n++) {
    const int i1 = bondlist[n][0], i2 = bondlist[n][1], type = bondlist[n][2];
    if (type <= 0 || !setflag[type] || !(dc[type] > 0.0)) continue;
    const double m1 = CellMech::atom_mass(atom, i1);
    const double m2 = CellMech::atom_mass(atom, i2);
    const double k = CellMech::lamella_area(alam, i1, i2) * sigma[type] * M_E / dc[type];
    const double w = sqrt(k * (1.0 / m1 + 1.0 / m2)) * dt;
    if (!(w <= mine.w)) {
      mine.w = w;
      nmax = n;
      kmax = k;
    }
  }
  MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
  // type, tags, area, masses, stiffness of the stiffest bond, from the rank that has it
  double info[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  if (worst.rank == comm->me && nmax >= 0) {
    const int i1 = bondlist[nmax][0], i2 = bondlist[nmax][1];
    info[0] = bondlist[nmax][2];
    info[1] = (double) atom->tag[i1];
    info[2] = (double) atom->tag[i2];
    info[3] = CellMech::lamella_area(alam, i1, i2);
    info[4] = CellMech::atom_mass(atom, i1);
    info[5] = CellMech::atom_mass(atom, i2);
    info[6] = kmax;
  }
  MPI_Bcast(info, 7, MPI_DOUBLE, worst.rank, world);
  const int type = (int) info[0];
  stiff = {type, type > 0 ? dc[type] : 0.0, worst.w};
  if (!(worst.w >= 2.0) || !CellMech::will_step(lmp)) return;
  // omega dt < 2 at delta_c > A sigma_c e dt^2 / (4 mu), mu the reduced mass
  const double mu = info[4] * info[5] / (info[4] + info[5]);
  const double dc_min = info[3] * sigma[type] * M_E * dt * dt / (4.0 * mu);
  error->all(FLERR,
             "Bond style cell/lamella: bond type {} (sigma_c {:g}, Gc {:g}) has a critical opening "
             "delta_c = {:.4g} too small for the time step {:g}: its bond {}-{} (area {:.4g}, "
             "node masses {:.4g} and {:.4g}) is a spring of stiffness A sigma_c e / delta_c = "
             "{:.4g} with omega dt = {:.4g}, and velocity Verlet needs omega dt < 2 (the run would "
             "blow up). Stable: delta_c > {:.4g}, i.e. Gc > {:.4g} at this sigma_c (delta_c = Gc / "
             "(e sigma_c)), or a time step below {:.4g}",
             type, sigma[type], Gc[type], dc[type], dt, (long) info[1], (long) info[2], info[3],
             info[4], info[5], info[6], worst.w, dc_min, Gc[type] * dc_min / dc[type],
             2.0 * dt / worst.w);
}

/* ---------------------------------------------------------------------- */

FixCellLamellaBreak *BondCellLamella::break_fix()
{
  auto *fix = dynamic_cast<FixCellLamellaBreak *>(modify->get_fix_by_id(FixCellLamellaBreak::ID));
  if (!fix)
    error->all(FLERR, "Bond style cell/lamella: internal fix {} is missing",
               FixCellLamellaBreak::ID);
  return fix;
}

/* ---------------------------------------------------------------------- */

void BondCellLamella::allocate()
{
  allocated = 1;
  const int np1 = atom->nbondtypes + 1;
  memory->create(sigma, np1, "bond:sigma");
  memory->create(Gc, np1, "bond:Gc");
  memory->create(gamma, np1, "bond:gamma");
  memory->create(dc, np1, "bond:dc");
  memory->create(setflag, np1, "bond:setflag");
  for (int i = 1; i < np1; i++) setflag[i] = 0;
}

/* ----------------------------------------------------------------------
   bond_style cell/lamella [log FILE]
------------------------------------------------------------------------- */

void BondCellLamella::settings(int narg, char **arg)
{
  if (narg == 0) return;
  if (narg != 2 || strcmp(arg[0], "log") != 0)
    error->all(FLERR,
               "Illegal bond_style cell/lamella command: expected 'bond_style cell/lamella [log "
               "FILE]', got {} arguments{}{}",
               narg, narg ? " starting with " : "", narg ? arg[0] : "");
  logfile = arg[1];
}

/* ----------------------------------------------------------------------
   bond_coeff N sigma_c Gc [gamma]
------------------------------------------------------------------------- */

void BondCellLamella::coeff(int narg, char **arg)
{
  if (narg != 3 && narg != 4)
    error->all(FLERR,
               "Incorrect number of args for bond_coeff cell/lamella: expected 'bond_coeff N "
               "sigma_c Gc [gamma]', got {} arguments",
               narg);
  if (!allocated) allocate();

  int ilo, ihi;
  utils::bounds(FLERR, arg[0], 1, atom->nbondtypes, ilo, ihi, error);

  const char *cmd = "bond_coeff cell/lamella";
  using CellMech::Sign;
  const double sigma_one =
      CellMech::coefficient(lmp, cmd, "strength sigma_c", arg[1], Sign::POSITIVE);
  const double Gc_one =
      CellMech::coefficient(lmp, cmd, "fracture energy Gc", arg[2], Sign::POSITIVE);
  const double gamma_one = narg == 4
      ? CellMech::coefficient(lmp, cmd, "damping gamma", arg[3], Sign::NON_NEGATIVE)
      : 0.0;
  if (CellMech::set_types(ilo, ihi, setflag,
                          {{sigma, sigma_one},
                           {Gc, Gc_one},
                           {gamma, gamma_one},
                           {dc, cohesive_length(sigma_one, Gc_one)}}) == 0)
    error->all(FLERR, "Incorrect args for bond coefficients");
  // created now, so that f_cell_debonded can be used in thermo and variables at once; after
  // read_restart it picks up the per-pair table and the per-atom counts of the restart file
  add_break_fix();
}

/* ----------------------------------------------------------------------
   the debond bookkeeping; when it is created after read_restart it picks
   up its data from the restart file
------------------------------------------------------------------------- */

void BondCellLamella::add_break_fix()
{
  if (!modify->get_fix_by_id(FixCellLamellaBreak::ID))
    modify->add_fix(fmt::format("{} all CELL_LAMELLA_BREAK", FixCellLamellaBreak::ID));
}

/* ---------------------------------------------------------------------- */

void BondCellLamella::init_style()
{
  CellMech::require_unit_consistency(lmp, "Bond style cell/lamella");
  if (!atom->molecule_flag)
    error->all(FLERR,
               "Bond style cell/lamella requires molecule IDs (the cells), e.g. atom_style "
               "molecular");

  int flag, cols, ghost;
  iref = atom->find_custom_ghost(CellMech::REF_FIELD, flag, cols, ghost);
  if (iref < 0 || flag != 1 || cols != 3 || !ghost)
    error->all(FLERR,
               "Bond style cell/lamella requires the wall reference positions as a per-atom array "
               "communicated to ghosts: 'fix cell all property/atom rmass d_rho d_drho d2_{} 3 "
               "d_{} ghost yes' before read_data",
               CellMech::REF_FIELD, CellMech::AREA_FIELD);
  ialam = atom->find_custom_ghost(CellMech::AREA_FIELD, flag, cols, ghost);
  if (ialam < 0 || flag != 1 || cols != 0 || !ghost)
    error->all(FLERR,
               "Bond style cell/lamella requires the area share of each node's lamella bonds as a "
               "per-atom vector communicated to ghosts: 'fix cell all property/atom rmass d_rho "
               "d_drho d2_{} 3 d_{} ghost yes' before read_data",
               CellMech::REF_FIELD, CellMech::AREA_FIELD);

  if (CellMech::any_positive(setflag, gamma, atom->nbondtypes))
    CellMech::require_ghost_velocities(lmp, "Bond style cell/lamella with damping gamma > 0");
  // a debonded pair leaves the 1-2 list and becomes an ordinary contact pair (or a 1-3 pair when
  // the special list is rebuilt from the bonds)
  CellMech::require_special_lj_011(lmp, "Bond style cell/lamella",
                                   "debonded nodes become a contact pair of the pair style");

  // longest rest length of the local lamella bonds, for LAMMPS's bond-extent sanity check
  double lmax_local = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < atom->num_bond[i]; m++) {
      const int type = atom->bond_type[i][m];
      const int j = atom->map(atom->bond_atom[i][m]);
      if (type > 0 && setflag[type] && j >= 0)
        lmax_local = MAX(lmax_local, CellMech::rest_length(atom->darray[iref], i, j));
    }
  MPI_Allreduce(&lmax_local, &lmax, 1, MPI_DOUBLE, MPI_MAX, world);

  update_dc();
  // made by bond_coeff, or here for coefficients from a restart file, before the fixes are
  // initialised
  add_break_fix();
  breaker = break_fix();
  breaker->set_log(logfile);
}

/* ---------------------------------------------------------------------- */

double BondCellLamella::equilibrium_distance(int /*i*/)
{
  return lmax;
}

/* ---------------------------------------------------------------------- */

void BondCellLamella::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  CellMech::write_type_arrays(fp, atom->nbondtypes, {sigma, Gc, gamma});
}

void BondCellLamella::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int n = atom->nbondtypes;
  CellMech::read_type_arrays(fp, n, {sigma, Gc, gamma}, comm->me, world, error);
  for (int i = 1; i <= n; i++) {
    setflag[i] = 1;
    dc[i] = cohesive_length(sigma[i], Gc[i]);
  }
}

// the log file name, so that a continued run appends to the record of the run that wrote the
// restart file (bond_style hybrid stores only this part of its sub-styles)
void BondCellLamella::write_restart_settings(FILE *fp)
{
  const int n = (int) logfile.size() + 1;
  fwrite(&n, sizeof(int), 1, fp);
  fwrite(logfile.c_str(), sizeof(char), n, fp);
}

void BondCellLamella::read_restart_settings(FILE *fp)
{
  int n = 0;
  if (comm->me == 0) utils::sfread(FLERR, &n, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&n, 1, MPI_INT, 0, world);
  std::vector<char> buf(n);
  if (comm->me == 0) utils::sfread(FLERR, buf.data(), sizeof(char), n, fp, nullptr, error);
  MPI_Bcast(buf.data(), n, MPI_CHAR, 0, world);
  logfile = buf.data();
}

void BondCellLamella::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->nbondtypes; i++)
    fprintf(fp, "%d %.15g %.15g %.15g\n", i, sigma[i], Gc[i], gamma[i]);
}

/* ---------------------------------------------------------------------- */

double BondCellLamella::single(int type, double rsq, int i, int j, double &fforce)
{
  const double r = sqrt(rsq);
  const double delta = r - CellMech::rest_length(atom->darray[iref], i, j);
  const double A = CellMech::lamella_area(atom->dvector[ialam], i, j);
  const double delta_c = cohesive_length(sigma[type], Gc[type]);
  fforce = -A * cohesive_traction(sigma[type], delta_c, delta) / r;
  if (gamma[type] > 0.0)
    fforce += damping_fpair(A * gamma[type], CellMech::radial_rate(atom->x, atom->v, i, j), rsq);
  return A * cohesive_energy(sigma[type], delta_c, delta);
}

/* ---------------------------------------------------------------------- */

void *BondCellLamella::extract(const char *str, int &dim)
{
  dim = 1;
  if (strcmp(str, "sigma") == 0) return (void *) sigma;
  if (strcmp(str, "Gc") == 0) return (void *) Gc;
  if (strcmp(str, "gamma") == 0) return (void *) gamma;
  return nullptr;
}
