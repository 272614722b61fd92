/* ----------------------------------------------------------------------
   cellmech: pair style cell/virtual

   For each wall triangle (a, b, c) -- an angle of the topology -- a virtual
   particle sits at B = (x_a + x_b + x_c)/3 with velocity (v_a + v_b + v_c)/3.
   A fluid particle k within r0 of B feels the 8-4 force of Eq. 12 (plus
   contact damping along k-B); the three nodes each take -1/3 of it. This
   is the exact gradient of E(|x_k - B|), so linear and angular momentum are
   conserved and the virial is (x_k - B) F_k.
   Fluid near a triangle is found in the full neighbor list of the
   triangle's central node (the angle's atom 2, which owns the angle with
   newton_bond on) with cutoff r0 + reach, reach >= |B - x_b|. Forces on
   ghost nodes and ghost fluid reach their owners by the reverse
   communication of newton_pair on.
------------------------------------------------------------------------- */

#include "pair_cell_virtual.h"

#include "atom.h"
#include "atom_vec.h"
#include "cell_physics.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace CellPhysics;

PairCellVirtual::PairCellVirtual(LAMMPS *_lmp) :
    Pair(_lmp), reach(0.0), f0(nullptr), r0(nullptr), gamma(nullptr)
{
  // forces act on three nodes per virtual particle; the fdotr virial over all owned and ghost
  // atoms is exact for them
  no_virial_fdotr_compute = 0;
}

PairCellVirtual::~PairCellVirtual()
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

void PairCellVirtual::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  int *type = atom->type;
  tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  int **anglelist = neighbor->anglelist;
  const int nanglelist = neighbor->nanglelist;
  int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  const double reachsq = reach * reach;

  for (int n = 0; n < nanglelist; n++) {
    if (anglelist[n][3] <= 0) continue;    // triangle of a broken wall carries no virtual particle
    const int a = anglelist[n][0], b = anglelist[n][1], c = anglelist[n][2];
    if (b >= nlocal) continue;    // only with newton_bond off; init_style forbids it
    double B[3], VB[3];
    for (int d = 0; d < 3; d++) {
      B[d] = (x[a][d] + x[b][d] + x[c][d]) / 3.0;
      VB[d] = (v[a][d] + v[b][d] + v[c][d]) / 3.0;
    }
    const double ox = B[0] - x[b][0], oy = B[1] - x[b][1], oz = B[2] - x[b][2];
    if (ox * ox + oy * oy + oz * oz > reachsq)
      error->one(FLERR,
                 "Pair style cell/virtual: triangle {}-{}-{} has its barycentre {:.4g} from its "
                 "central node, beyond reach {}; increase reach in pair_style cell/virtual",
                 tag[a], tag[b], tag[c], sqrt(ox * ox + oy * oy + oz * oz), reach);
    const int btype = type[b];
    int *jlist = firstneigh[b];
    const int jnum = numneigh[b];

    for (int jj = 0; jj < jnum; jj++) {
      const int k = jlist[jj] & NEIGHMASK;
      const int ktype = type[k];
      if (!setflag[btype][ktype] && !setflag[ktype][btype]) continue;
      const double dx = x[k][0] - B[0];
      const double dy = x[k][1] - B[1];
      const double dz = x[k][2] - B[2];
      const double rsq = dx * dx + dy * dy + dz * dz;
      const double r0bk = r0[btype][ktype];
      if (rsq >= r0bk * r0bk) continue;

      double fpair = repulsion84_fpair(f0[btype][ktype], r0bk, rsq);
      if (gamma[btype][ktype] > 0.0) {
        const double dot = dx * (v[k][0] - VB[0]) + dy * (v[k][1] - VB[1]) + dz * (v[k][2] - VB[2]);
        fpair -= gamma[btype][ktype] * dot / rsq;
      }
      const double fx = fpair * dx, fy = fpair * dy, fz = fpair * dz;
      f[k][0] += fx;
      f[k][1] += fy;
      f[k][2] += fz;
      for (int node : {a, b, c}) {
        f[node][0] -= fx / 3.0;
        f[node][1] -= fy / 3.0;
        f[node][2] -= fz / 3.0;
      }
      if (eflag) {
        const double e = repulsion84_energy(f0[btype][ktype], r0bk, rsq);
        if (eflag_global) eng_vdwl += e;
        if (eflag_atom) {
          eatom[k] += 0.5 * e;
          for (int node : {a, b, c}) eatom[node] += e / 6.0;
        }
      }
      if (vflag_global && !vflag_fdotr) {
        virial[0] += dx * fx;
        virial[1] += dy * fy;
        virial[2] += dz * fz;
        virial[3] += dx * fy;
        virial[4] += dx * fz;
        virial[5] += dy * fz;
      }
    }
  }

  if (vflag_fdotr) virial_fdotr_compute();
}

/* ---------------------------------------------------------------------- */

void PairCellVirtual::allocate()
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

/* ----------------------------------------------------------------------
   pair_style cell/virtual reach
------------------------------------------------------------------------- */

void PairCellVirtual::settings(int narg, char **arg)
{
  if (narg != 1)
    error->all(FLERR,
               "Illegal pair_style cell/virtual command: expected 'pair_style cell/virtual reach', "
               "got {} arguments",
               narg);
  reach = utils::numeric(FLERR, arg[0], false, lmp);
  if (reach <= 0.0)
    error->all(FLERR,
               "pair_style cell/virtual: reach (largest barycentre-to-node distance) must be > 0, "
               "got {}",
               reach);
}

/* ----------------------------------------------------------------------
   pair_coeff I J f0 r0 [gamma]: triangles with central node of type I
   (or J) repel particles of type J (or I)
------------------------------------------------------------------------- */

void PairCellVirtual::coeff(int narg, char **arg)
{
  if (narg != 4 && narg != 5)
    error->all(FLERR,
               "Incorrect number of args for pair_coeff cell/virtual: expected "
               "'pair_coeff I J f0 r0 [gamma]', got {} arguments",
               narg);
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double f0_one = utils::numeric(FLERR, arg[2], false, lmp);
  const double r0_one = utils::numeric(FLERR, arg[3], false, lmp);
  const double gamma_one = (narg == 5) ? utils::numeric(FLERR, arg[4], false, lmp) : 0.0;
  if (f0_one < 0.0)
    error->all(FLERR, "pair_coeff cell/virtual: strength f0 must be >= 0, got {}", f0_one);
  if (r0_one <= 0.0)
    error->all(FLERR, "pair_coeff cell/virtual: contact distance r0 must be > 0, got {}", r0_one);
  if (gamma_one < 0.0)
    error->all(FLERR, "pair_coeff cell/virtual: contact damping gamma must be >= 0, got {}",
               gamma_one);
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      f0[i][j] = f0_one;
      r0[i][j] = r0_one;
      gamma[i][j] = gamma_one;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

void PairCellVirtual::init_style()
{
  if (!atom->molecular || !atom->avec->angles_allow)
    error->all(FLERR,
               "Pair style cell/virtual requires an atom style with angles (the wall "
               "triangles), e.g. atom_style molecular");
  if (!force->angle)
    error->all(FLERR,
               "Pair style cell/virtual requires an angle style (angle_style zero nocoeff): "
               "without one LAMMPS lists no triangles and the wall has no virtual particles");
  if (!force->newton_bond)
    error->all(FLERR, "Pair style cell/virtual requires newton_bond on (each triangle once)");
  if (!force->newton_pair)
    error->all(FLERR, "Pair style cell/virtual requires newton_pair on (forces on ghost nodes)");
  bool damped = false;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && gamma[i][j] > 0.0) damped = true;
  if (damped && !comm->ghost_velocity)
    error->all(FLERR, "Pair style cell/virtual with gamma > 0 requires 'comm_modify vel yes'");
  neighbor->add_request(this, NeighConst::REQ_FULL);
}

double PairCellVirtual::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, "Pair style cell/virtual: no coefficients for types {} {}", i, j);
  f0[j][i] = f0[i][j];
  r0[j][i] = r0[i][j];
  gamma[j][i] = gamma[i][j];
  setflag[j][i] = setflag[i][j];
  return r0[i][j] + reach;
}

/* ---------------------------------------------------------------------- */

void PairCellVirtual::write_restart_settings(FILE *fp)
{
  fwrite(&reach, sizeof(double), 1, fp);
}

void PairCellVirtual::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) utils::sfread(FLERR, &reach, sizeof(double), 1, fp, nullptr, error);
  MPI_Bcast(&reach, 1, MPI_DOUBLE, 0, world);
}

void PairCellVirtual::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) {
        fwrite(&f0[i][j], sizeof(double), 1, fp);
        fwrite(&r0[i][j], sizeof(double), 1, fp);
        fwrite(&gamma[i][j], sizeof(double), 1, fp);
      }
    }
}

void PairCellVirtual::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (setflag[i][j]) {
        if (me == 0) {
          utils::sfread(FLERR, &f0[i][j], sizeof(double), 1, fp, nullptr, error);
          utils::sfread(FLERR, &r0[i][j], sizeof(double), 1, fp, nullptr, error);
          utils::sfread(FLERR, &gamma[i][j], sizeof(double), 1, fp, nullptr, error);
        }
        MPI_Bcast(&f0[i][j], 1, MPI_DOUBLE, 0, world);
        MPI_Bcast(&r0[i][j], 1, MPI_DOUBLE, 0, world);
        MPI_Bcast(&gamma[i][j], 1, MPI_DOUBLE, 0, world);
      }
    }
}

void *PairCellVirtual::extract(const char *str, int &dim)
{
  dim = 2;
  if (strcmp(str, "f0") == 0) return (void *) f0;
  if (strcmp(str, "r0") == 0) return (void *) r0;
  if (strcmp(str, "gamma") == 0) return (void *) gamma;
  return nullptr;
}
