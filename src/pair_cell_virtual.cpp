/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: pair style cell/virtual

   For each wall triangle (a, b, c) -- an angle of the topology -- a virtual
   particle sits at B = (x_a + x_b + x_c)/3 with velocity (v_a + v_b + v_c)/3.
   A fluid particle k within r0 of B feels the 8-4 force of Eq. 12 (plus
   contact damping along k-B); the three nodes each take -1/3 of it. This
   is the exact gradient of E(|x_k - B|), so linear and angular momentum are
   conserved and the virial is (x_k - B) F_k.
   Fluid near a triangle is found in the full neighbor list of the
   triangle's central node (the angle's atom 2, which owns the angle with
   newton_bond on: the triangle contract of cell_fields.h) with cutoff
   r0 + reach, reach >= |B - x_b|, once per build: each step walks only
   what lay within r0 + skin of B then (cell_near_list.h). Forces on
   ghost nodes and ghost fluid reach their owners by the reverse
   communication of newton_pair on.
   pair_coeff I J f0 r0 [gamma] (as cell/lj84): triangles whose central node
   has type I (or J) repel particles of type J (or I). With adhere Fa delta
   they also hold the particles of their own cell (molecule) out to
   r0 + delta (Eq. A1, physics/adhesion.h), which grows the cutoff to
   r0 + delta + reach.
------------------------------------------------------------------------- */

#include "pair_cell_virtual.h"

#include "cell_checks.h"
#include "cell_coeff.h"
#include "cell_compat.h"

#include "atom.h"
#include "atom_vec.h"
#include "cell_topology.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "physics/adhesion.h"
#include "physics/damping.h"
#include "physics/lj84.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace CellPhysics;

PairCellVirtual::PairCellVirtual(LAMMPS *_lmp) :
    PairCellLJ84(_lmp, "cell/virtual"), reach(0.0), fa(nullptr), delta(nullptr), adhering(false)
{
  coeff_args = "f0 r0 [gamma] [adhere Fa delta]";
  // forces act on three nodes per virtual particle; the fdotr virial over all owned and ghost
  // atoms is exact for them. A pair of atoms means nothing here: no single(), no pair_write,
  // and the coefficients are between wall and fluid types, not per type for write_data.
  single_enable = 0;
  writedata = 0;
}

PairCellVirtual::~PairCellVirtual()
{
  if (allocated) {
    memory->destroy(fa);
    memory->destroy(delta);
  }
}

void PairCellVirtual::allocate()
{
  PairCellLJ84::allocate();
  const int np1 = atom->ntypes + 1;
  memory->create(fa, np1, np1, "pair:fa");
  memory->create(delta, np1, np1, "pair:delta");
  for (int i = 0; i < np1; i++)
    for (int j = 0; j < np1; j++) fa[i][j] = delta[i][j] = 0.0;
}

/* ---------------------------------------------------------------------- */

void PairCellVirtual::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const int nlocal = atom->nlocal;
  // the setup of a run, with the triangle list and the ghost nodes in place
  if (update->setupflag) check_contact_distance();
  if (near.stale(lmp)) find_near();
  CellMech::for_each_wall_triangle(
      neighbor->anglelist, neighbor->nanglelist, [&](int n, int a, int b, int c) {
        if (b >= nlocal) return;    // only with newton_bond off; init_style forbids it
        repel_fluid(n, a, b, c, eflag);
      });
  // a pass of its own: a run without adhesion does what it did, as fast
  if (adhering)
    CellMech::for_each_wall_triangle(neighbor->anglelist, neighbor->nanglelist,
                                     [&](int, int a, int b, int c) {
                                       if (b < nlocal) hold_fluid(a, b, c, eflag);
                                     });
  if (vflag_fdotr) virial_fdotr_compute();
}

// the virtual particle of triangle a-b-c, at its barycentre
void PairCellVirtual::barycentre(int a, int b, int c, double *B) const
{
  double **x = atom->x;
  for (int d = 0; d < 3; d++) B[d] = (x[a][d] + x[b][d] + x[c][d]) / 3.0;
}

// the virtual particle at B must be within reach of the central node b, in whose neighbour list
// the fluid near it is looked for
void PairCellVirtual::check_reach(int a, int b, int c, const double *B)
{
  double **x = atom->x;
  const double ox = B[0] - x[b][0], oy = B[1] - x[b][1], oz = B[2] - x[b][2];
  if (!(ox * ox + oy * oy + oz * oz > reach * reach))
    return;    // a NaN is no reach problem
  // a wall that deforms strongly needs a larger reach; a node that jumped more than the skin in
  // one step means the run blew up, and a larger reach would not help
  const int nodes[3] = {a, b, c};
  const auto moved = CellMech::fastest_step(lmp, nodes, 3);
  const std::string why = moved.dist > neighbor->skin
      ? "its " + CellMech::blow_up_advice(lmp, moved)
      : fmt::format("its nodes moved at most {:.4g} in the last step (neighbor skin {:g}), "
                    "so the wall is deformed, not blown up: increase reach in pair_style "
                    "cell/virtual",
                    moved.dist, neighbor->skin);
  error->one(FLERR,
             "Pair style cell/virtual: triangle {}-{}-{} has its barycentre {:.4g} from its "
             "central node, beyond reach {}; {}",
             atom->tag[a], atom->tag[b], atom->tag[c], sqrt(ox * ox + oy * oy + oz * oz), reach,
             why);
}

// The fluid that can come within r0 of each triangle's virtual particle before the next
// neighbour-list build (cell_near_list.h): what lies within r0 + skin of its barycentre at the
// build, in the order of the central node's list, so that repel_fluid finds the same contacts in
// the same order as a walk of the whole list (reach + r0 + skin) would.
void PairCellVirtual::find_near()
{
  double **x = atom->x;
  const int *type = atom->type;
  int **anglelist = neighbor->anglelist;
  const int nangle = neighbor->nanglelist;
  // rounding must not drop a contact at the margin's edge
  const double margin = neighbor->skin * (1.0 + 1.0e-12);
  near.start(nangle);
  for (int n = 0; n < nangle; n++) {
    near.open(n);
    const int a = anglelist[n][0], b = anglelist[n][1], c = anglelist[n][2];
    const int btype = type[b];
    if (b >= atom->nlocal || !listed[btype]) continue;
    double B[3];
    barycentre(a, b, c, B);
    const int *jlist = list->firstneigh[b];
    const int jnum = list->numneigh[b];
    for (int jj = 0; jj < jnum; jj++) {
      const int k = jlist[jj] & NEIGHMASK;
      const int ktype = type[k];
      if (!setflag[btype][ktype] && !setflag[ktype][btype]) continue;
      const double dx = x[k][0] - B[0], dy = x[k][1] - B[1], dz = x[k][2] - B[2];
      const double rc = r0[btype][ktype] + margin;
      if (dx * dx + dy * dy + dz * dz < rc * rc) near.add(k);
    }
  }
  near.close();
}

// the virtual particle of triangle n, a-b-c (central node b), repels the fluid near it
void PairCellVirtual::repel_fluid(int n, int a, int b, int c, int eflag)
{
  double **x = atom->x;
  double **v = atom->v;
  int *type = atom->type;
  double B[3], VB[3];
  barycentre(a, b, c, B);
  check_reach(a, b, c, B);
  const int btype = type[b];
  if (!listed[btype])
    error->one(FLERR,
               "Pair style cell/virtual: triangle {}-{}-{} has its central node {} of type {}, "
               "which has no cell/virtual coefficients; give them for the wall type and the "
               "fluid type (pair_coeff WALL FLUID cell/virtual f0 r0 [gamma])",
               atom->tag[a], atom->tag[b], atom->tag[c], atom->tag[b], btype);
  bool have_vb = false;

  for (const int *kp = near.begin(n); kp != near.end(n); ++kp) {
    const int k = *kp;
    const int ktype = type[k];
    const double dx = x[k][0] - B[0];
    const double dy = x[k][1] - B[1];
    const double dz = x[k][2] - B[2];
    const double rsq = dx * dx + dy * dy + dz * dz;
    const double r0bk = r0[btype][ktype];
    if (rsq >= r0bk * r0bk) continue;
    // the virtual particle's velocity only where fluid touches it: most triangles have none,
    // and its three divisions are a fair part of a triangle's cost
    if (!have_vb) {
      for (int d = 0; d < 3; d++) VB[d] = (v[a][d] + v[b][d] + v[c][d]) / 3.0;
      have_vb = true;
    }

    double fpair = repulsion84_fpair(f0[btype][ktype], r0bk, rsq);
    if (gamma[btype][ktype] > 0.0) {
      const double dot = dx * (v[k][0] - VB[0]) + dy * (v[k][1] - VB[1]) + dz * (v[k][2] - VB[2]);
      fpair += damping_fpair(gamma[btype][ktype], dot, rsq);
    }
    const double del[3] = {dx, dy, dz};
    tally_contact(k, a, b, c, del, fpair,
                  eflag ? repulsion84_energy(f0[btype][ktype], r0bk, rsq) : 0.0, eflag);
  }
}

// The virtual particle of triangle a-b-c holds the fluid of its own cell only (the molecule of
// the central node b): fluid that left a broken cell is merely kept out of the others.
void PairCellVirtual::hold_fluid(int a, int b, int c, int eflag)
{
  double **x = atom->x;
  const int *type = atom->type;
  const tagint *molecule = atom->molecule;
  double B[3];
  barycentre(a, b, c, B);
  const int btype = type[b];
  int *jlist = list->firstneigh[b];
  const int jnum = list->numneigh[b];

  for (int jj = 0; jj < jnum; jj++) {
    const int k = jlist[jj] & NEIGHMASK;
    const int ktype = type[k];
    // fa is zero for type pairs without coefficients
    const double fabk = fa[btype][ktype];
    if (fabk <= 0.0 || !CellMech::same_cell(molecule, k, b)) continue;
    const double del[3] = {x[k][0] - B[0], x[k][1] - B[1], x[k][2] - B[2]};
    const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
    const double r0bk = r0[btype][ktype], dbk = delta[btype][ktype];
    if (rsq >= (r0bk + dbk) * (r0bk + dbk)) continue;
    // within r0 the well adds no force, only its depth to the energy: most contacts are there,
    // and without an energy to tally there is nothing to do for them
    if (!eflag && rsq <= r0bk * r0bk) continue;
    tally_contact(k, a, b, c, del, adhesion_fpair(fabk, r0bk, dbk, rsq),
                  eflag ? adhesion_energy(fabk, r0bk, dbk, rsq) : 0.0, eflag);
  }
}

// the force fpair del on fluid particle k (del = x_k - B), -1/3 of it on each node of the
// triangle a-b-c, and the contact's energy e (if eflag) and virial
void PairCellVirtual::tally_contact(int k, int a, int b, int c, const double *del, double fpair,
                                    double e, int eflag)
{
  double **f = atom->f;
  const double dx = del[0], dy = del[1], dz = del[2];
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
    if (eflag_global) eng_vdwl += e;
    if (eflag_atom) {
      eatom[k] += 0.5 * e;
      for (int node : {a, b, c}) eatom[node] += e / 6.0;
    }
  }
  if (vflag_atom) {
    // the interaction's virial (x_k - B) F_k, split as its energy: half to the fluid
    // particle, a sixth to each node (sums to the global virial)
    const double vv[6] = {dx * fx, dy * fy, dz * fz, dx * fy, dx * fz, dy * fz};
    for (int q = 0; q < 6; q++) {
      vatom[k][q] += 0.5 * vv[q];
      for (int node : {a, b, c}) vatom[node][q] += vv[q] / 6.0;
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

/* ----------------------------------------------------------------------
   The contacts must close the wall's holes. A fluid particle crosses a triangle where it keeps r0
   from its three nodes and its virtual particle; on an edge the point farthest from those is a
   third of the edge from each, so a triangle with edges above about 3 r0 lets fluid through, and
   the fluid leaves the cell (a coarse tissue with the paper's r0 = 1.6 um against triangles of
   mean edge 4.7 um: half its fluid outside its walls, the walls slack). Stops the run at its
   start when r0 is below half the mean edge of the triangles of a wall type that meets fluid of
   that pair: the lengths of the levels give r0 = 0.7 times the mean edge. Collective: at the
   setup, where every rank computes the triangles.
------------------------------------------------------------------------- */

void PairCellVirtual::check_contact_distance()
{
  const int ntypes = atom->ntypes;
  double **x = atom->x;
  const int *type = atom->type;
  // per type: sum and count of triangle edges of central nodes of that type, atoms of that type
  std::vector<double> local(3 * (ntypes + 1), 0.0), all(3 * (ntypes + 1));
  auto dist = [&](int i, int j) {
    const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
    return sqrt(dx * dx + dy * dy + dz * dz);
  };
  CellMech::for_each_wall_triangle(neighbor->anglelist, neighbor->nanglelist,
                                   [&](int, int a, int b, int c) {
                                     if (b >= atom->nlocal) return;
                                     local[type[b]] += dist(a, b) + dist(b, c) + dist(a, c);
                                     local[ntypes + 1 + type[b]] += 3.0;
                                   });
  for (int i = 0; i < atom->nlocal; i++) local[2 * (ntypes + 1) + type[i]] += 1.0;
  MPI_Allreduce(local.data(), all.data(), 3 * (ntypes + 1), MPI_DOUBLE, MPI_SUM, world);
  for (int w = 1; w <= ntypes; w++) {
    const double nedge = all[ntypes + 1 + w];
    // a wall type without coefficients: compute() names it
    if (nedge == 0.0 || !listed[w]) continue;
    const double edge = all[w] / nedge;
    for (int k = 1; k <= ntypes; k++) {
      // coefficients are kept for I <= J
      if (k == w || !setflag[MIN(w, k)][MAX(w, k)] || all[2 * (ntypes + 1) + k] == 0.0) continue;
      const double r0wk = r0[MIN(w, k)][MAX(w, k)];
      if (r0wk >= MIN_R0_EDGE * edge) continue;
      error->all(FLERR,
                 "Pair style cell/virtual: the contact distance r0 = {:g} of wall type {} and "
                 "fluid type {} (pair_coeff {} {} cell/virtual f0 r0) is below {:g} times the "
                 "mean edge {:.4g} of the wall's {:.0f} triangles (r0 >= {:.4g}): fluid passes "
                 "between the nodes and the virtual particles of triangles that large and leaves "
                 "its cell. Use the contact lengths of the wall's level (cellgen.py writes them "
                 "beside the data file, DATA.lmp; tools/cellmech/params.py LEVELS)",
                 r0wk, w, k, MIN(w, k), MAX(w, k), MIN_R0_EDGE, edge, nedge / 3.0,
                 MIN_R0_EDGE * edge);
    }
  }
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
  CellMech::require_magnitude(lmp, "pair_style cell/virtual", "reach", reach);
}

/* ----------------------------------------------------------------------
   pair_coeff I J f0 r0 [gamma] [adhere Fa delta]
------------------------------------------------------------------------- */

void PairCellVirtual::coeff(int narg, char **arg)
{
  // f0 r0 [gamma] as cell/lj84; keywords follow
  const int nplain = (narg > 4 && utils::is_double(arg[4])) ? 5 : MIN(narg, 4);
  PairCellLJ84::coeff(nplain, arg);

  const std::string cmd = "pair_coeff cell/virtual";
  double fa_one = 0.0, delta_one = 0.0;
  for (int iarg = nplain; iarg < narg; iarg += 3) {
    if (strcmp(arg[iarg], "adhere") != 0)
      error->all(FLERR, "{}: unknown keyword '{}' (expected 'pair_coeff I J {}')", cmd, arg[iarg],
                 coeff_args);
    if (iarg + 2 >= narg)
      error->all(FLERR, "{}: keyword adhere needs two values, Fa delta; got {}", cmd,
                 narg - iarg - 1);
    using CellMech::Sign;
    fa_one =
        CellMech::coefficient(lmp, cmd, "adhesion strength Fa", arg[iarg + 1], Sign::NON_NEGATIVE);
    delta_one =
        CellMech::coefficient(lmp, cmd, "adhesion range delta", arg[iarg + 2], Sign::POSITIVE);
  }
  if (fa_one > 0.0 && !atom->molecule_flag)
    error->all(FLERR,
               "{}: adhere Fa = {} needs molecule IDs, which tell a cell's own wall from the "
               "others; use an atom style with molecules (atom_style molecular)",
               cmd, fa_one);

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      fa[i][j] = fa_one;
      delta[i][j] = delta_one;
    }
}

void PairCellVirtual::init_style()
{
  CellMech::require_unit_consistency(lmp, "Pair style cell/virtual");
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
  require_ghost_velocities();
  neighbor->add_request(this, NeighConst::REQ_FULL);

  const int ntypes = atom->ntypes;
  listed.assign(ntypes + 1, 0);
  adhering = false;
  for (int i = 1; i <= ntypes; i++)
    for (int j = 1; j <= ntypes; j++)
      if (setflag[MIN(i, j)][MAX(i, j)]) {
        listed[i] = 1;
        if (fa[MIN(i, j)][MAX(i, j)] > 0.0) adhering = true;
      }
}

double PairCellVirtual::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, "Pair style cell/virtual: no coefficients for types {} {}", i, j);
  f0[j][i] = f0[i][j];
  r0[j][i] = r0[i][j];
  gamma[j][i] = gamma[i][j];
  fa[j][i] = fa[i][j];
  delta[j][i] = delta[i][j];
  setflag[j][i] = setflag[i][j];
  // fluid within r0 (+ delta where it adheres) of a barycentre within reach of the central node
  return r0[i][j] + (fa[i][j] > 0.0 ? delta[i][j] : 0.0) + reach;
}

/* ---------------------------------------------------------------------- */

void PairCellVirtual::write_restart_settings(FILE *fp)
{
  fwrite(&reach, sizeof(double), 1, fp);
}

double PairCellVirtual::memory_usage()
{
  return PairCellLJ84::memory_usage() + near.memory_usage();
}

void PairCellVirtual::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) utils::sfread(FLERR, &reach, sizeof(double), 1, fp, nullptr, error);
  MPI_Bcast(&reach, 1, MPI_DOUBLE, 0, world);
}
