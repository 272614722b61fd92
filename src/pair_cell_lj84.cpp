/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: pair style cell/lj84

   F_ik = f0 [(r0/r)^8 - (r0/r)^4] / r^2 r_ik - gamma (v_ik . e_ik) e_ik,  r < r0
   The repulsive branch only (cut at r0, where the force changes sign), as
   in the paper. The damping acts along the line of centres so that, like
   the conservative part, it conserves angular momentum.
------------------------------------------------------------------------- */

#include "pair_cell_lj84.h"

#include "cell_checks.h"
#include "cell_coeff.h"
#include "cell_compat.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "physics/damping.h"
#include "physics/lj84.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace CellPhysics;

/* ---------------------------------------------------------------------- */

PairCellLJ84::PairCellLJ84(LAMMPS *_lmp, const char *name) :
    Pair(_lmp), style_name(name), coeff_args("f0 r0 [gamma]"), f0(nullptr), r0(nullptr),
    gamma(nullptr)
{
  writedata = 1;
}

PairCellLJ84::~PairCellLJ84()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(f0);
    memory->destroy(r0);
    memory->destroy(gamma);
  }
}

/* ---------------------------------------------------------------------- */

void PairCellLJ84::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  double *special_lj = force->special_lj;
  double evdwl = 0.0;

  const int inum = list->inum;
  int *ilist = list->ilist;
  int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xtmp = x[i][0];
    const double ytmp = x[i][1];
    const double ztmp = x[i][2];
    const int itype = type[i];
    int *jlist = firstneigh[i];
    const int jnum = numneigh[i];

    for (int jj = 0; jj < jnum; jj++) {
      int j = jlist[jj];
      const double factor_lj = special_lj[sbmask(j)];
      j &= NEIGHMASK;

      const double delx = xtmp - x[j][0];
      const double dely = ytmp - x[j][1];
      const double delz = ztmp - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const int jtype = type[j];
      if (rsq >= cutsq[itype][jtype]) continue;

      double fpair = repulsion84_fpair(f0[itype][jtype], r0[itype][jtype], rsq);
      if (gamma[itype][jtype] > 0.0) {
        const double dvx = v[i][0] - v[j][0];
        const double dvy = v[i][1] - v[j][1];
        const double dvz = v[i][2] - v[j][2];
        fpair += damping_fpair(gamma[itype][jtype], delx * dvx + dely * dvy + delz * dvz, rsq);
      }
      fpair *= factor_lj;

      f[i][0] += delx * fpair;
      f[i][1] += dely * fpair;
      f[i][2] += delz * fpair;
      if (newton_pair || j < nlocal) {
        f[j][0] -= delx * fpair;
        f[j][1] -= dely * fpair;
        f[j][2] -= delz * fpair;
      }
      if (eflag) evdwl = factor_lj * repulsion84_energy(f0[itype][jtype], r0[itype][jtype], rsq);
      if (evflag) ev_tally(i, j, nlocal, newton_pair, evdwl, 0.0, fpair, delx, dely, delz);
    }
  }

  if (vflag_fdotr) virial_fdotr_compute();
}

/* ---------------------------------------------------------------------- */

void PairCellLJ84::allocate()
{
  allocated = 1;
  const int np1 = atom->ntypes + 1;
  memory->create(setflag, np1, np1, "pair:setflag");
  for (int i = 1; i < np1; i++)
    for (int j = i; j < np1; j++) setflag[i][j] = 0;
  memory->create(cutsq, np1, np1, "pair:cutsq");
  memory->create(f0, np1, np1, "pair:f0");
  memory->create(r0, np1, np1, "pair:r0");
  memory->create(gamma, np1, np1, "pair:gamma");
}

void PairCellLJ84::settings(int narg, char ** /*arg*/)
{
  if (narg != 0)
    error->all(FLERR, "Illegal pair_style cell/lj84 command: expected no arguments, got {}", narg);
}

/* ----------------------------------------------------------------------
   pair_coeff I J f0 r0 [gamma]
------------------------------------------------------------------------- */

void PairCellLJ84::coeff(int narg, char **arg)
{
  if (narg != 4 && narg != 5)
    error->all(FLERR,
               "Incorrect number of args for pair_coeff {}: expected 'pair_coeff I J {}', got {} "
               "arguments",
               style_name, coeff_args, narg);
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  const std::string cmd = std::string("pair_coeff ") + style_name;
  using CellMech::Sign;
  const double f0_one = CellMech::coefficient(lmp, cmd, "strength f0", arg[2], Sign::NON_NEGATIVE);
  const double r0_one =
      CellMech::coefficient(lmp, cmd, "contact distance r0", arg[3], Sign::POSITIVE);
  const double gamma_one = (narg == 5)
      ? CellMech::coefficient(lmp, cmd, "contact damping gamma", arg[4], Sign::NON_NEGATIVE)
      : 0.0;

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      f0[i][j] = f0_one;
      r0[i][j] = r0_one;
      gamma[i][j] = gamma_one;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* ---------------------------------------------------------------------- */

void PairCellLJ84::require_ghost_velocities()
{
  bool damped = false;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && gamma[i][j] > 0.0) damped = true;
  if (damped)
    CellMech::require_ghost_velocities(
        lmp, fmt::format("Pair style {} with contact damping gamma > 0", style_name));
}

void PairCellLJ84::init_style()
{
  CellMech::require_unit_consistency(lmp, "Pair style cell/lj84");
  require_ghost_velocities();
  neighbor->add_request(this);
}

/* ----------------------------------------------------------------------
   unset pairs mix: f0 is an energy scale (geometric), r0 a distance
------------------------------------------------------------------------- */

double PairCellLJ84::init_one(int i, int j)
{
  if (setflag[i][j] == 0) {
    f0[i][j] = mix_energy(f0[i][i], f0[j][j], r0[i][i], r0[j][j]);
    r0[i][j] = mix_distance(r0[i][i], r0[j][j]);
    gamma[i][j] = sqrt(gamma[i][i] * gamma[j][j]);
  }
  f0[j][i] = f0[i][j];
  r0[j][i] = r0[i][j];
  gamma[j][i] = gamma[i][j];
  return r0[i][j];
}

/* ---------------------------------------------------------------------- */

void PairCellLJ84::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  const auto extra = extra_coeffs();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      int record = setflag[i][j];
      for (double **e : extra)
        if (record && e[i][j] != 0.0) record = 2;
      fwrite(&record, sizeof(int), 1, fp);
      if (record) {
        fwrite(&f0[i][j], sizeof(double), 1, fp);
        fwrite(&r0[i][j], sizeof(double), 1, fp);
        fwrite(&gamma[i][j], sizeof(double), 1, fp);
      }
      if (record == 2)
        for (double **e : extra) fwrite(&e[i][j], sizeof(double), 1, fp);
    }
}

void PairCellLJ84::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const auto extra = extra_coeffs();
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      int record = 0;
      if (me == 0) utils::sfread(FLERR, &record, sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&record, 1, MPI_INT, 0, world);
      setflag[i][j] = record ? 1 : 0;
      if (record) {
        if (me == 0) {
          utils::sfread(FLERR, &f0[i][j], sizeof(double), 1, fp, nullptr, error);
          utils::sfread(FLERR, &r0[i][j], sizeof(double), 1, fp, nullptr, error);
          utils::sfread(FLERR, &gamma[i][j], sizeof(double), 1, fp, nullptr, error);
        }
        MPI_Bcast(&f0[i][j], 1, MPI_DOUBLE, 0, world);
        MPI_Bcast(&r0[i][j], 1, MPI_DOUBLE, 0, world);
        MPI_Bcast(&gamma[i][j], 1, MPI_DOUBLE, 0, world);
      }
      for (double **e : extra) {
        e[i][j] = 0.0;
        if (record == 2 && me == 0)
          utils::sfread(FLERR, &e[i][j], sizeof(double), 1, fp, nullptr, error);
        MPI_Bcast(&e[i][j], 1, MPI_DOUBLE, 0, world);
      }
    }
}

void PairCellLJ84::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    fprintf(fp, "%d %.15g %.15g %.15g\n", i, f0[i][i], r0[i][i], gamma[i][i]);
}

void PairCellLJ84::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      fprintf(fp, "%d %d %.15g %.15g %.15g\n", i, j, f0[i][j], r0[i][j], gamma[i][j]);
}

/* ---------------------------------------------------------------------- */

double PairCellLJ84::single(int i, int j, int itype, int jtype, double rsq, double /*factor_coul*/,
                            double factor_lj, double &fforce)
{
  fforce = repulsion84_fpair(f0[itype][jtype], r0[itype][jtype], rsq);
  if (gamma[itype][jtype] > 0.0)
    fforce -= gamma[itype][jtype] * CellMech::radial_rate(atom->x, atom->v, i, j) / rsq;
  fforce *= factor_lj;
  return factor_lj * repulsion84_energy(f0[itype][jtype], r0[itype][jtype], rsq);
}

void *PairCellLJ84::extract(const char *str, int &dim)
{
  dim = 2;
  if (strcmp(str, "f0") == 0) return (void *) f0;
  if (strcmp(str, "r0") == 0) return (void *) r0;
  if (strcmp(str, "gamma") == 0) return (void *) gamma;
  return nullptr;
}
