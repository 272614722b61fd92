/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: compute cell/props

   compute ID group cell/props [normal nx ny nz] [leaks yes|no]

   Global array, one row per cell (molecule ID >= 1) in ascending order of
   the IDs: row m is molecule m when the IDs are 1..N (cell_index.h):
     1 volume (divergence theorem over the wall triangles)  2 wall area
     3 mean fluid pressure  4 fluid mass  5 number of fluid particles
     6 mean and 7 max tether stretch l/l0 (of the wall edges)
     8 equatorial force: net tether force across the plane through the
       cell centre with the given normal (Eq. 23), positive in tension;
       with angle style cell/membrane also that of the membrane triangles
       the plane cuts
     9 fluid particles outside their own wall (winding number of the
       closed wall mesh)  10-12 cell centre (mean of the wall nodes)
     13 broken tethers (wall rupture; with failing membrane triangles the
        wall edges along which the wall is open)
     14 intact middle-lamella bonds to other cells, 15 their glued area
     16 debonded lamella bonds, 17 their area (from fix cell_debonded)
     18 the cell's molecule ID
   Bonds between two cells (molecule IDs) are lamella bonds: they count in
   14-17 only, never in the wall's stretch or equatorial force.
   Triangles are the angles of the topology, counted once (newton_bond on).
   Fluid are atoms of the types that pair cell/sph treats as fluid.
------------------------------------------------------------------------- */

#include "compute_cell_props.h"

#include "cell_compat.h"
#include "cell_fields.h"

#include "angle_cell_membrane.h"
#include "atom.h"
#include "bond.h"
#include "bond_cell_tether.h"
#include "cell_mpi.h"
#include "cell_sums.h"
#include "cell_topology.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fix_cell_lamella_break.h"
#include "fix_cell_tether_break.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "pair_cell_sph.h"
#include "physics/observables.h"
#include "physics/surface.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace CellPhysics;

static constexpr double BIG = 1.0e300;

ComputeCellProps::ComputeCellProps(LAMMPS *_lmp, int narg, char **arg) :
    Compute(_lmp, narg, arg), leaks(1), ncells(0), sph(nullptr), tether(nullptr), membrane(nullptr),
    ialam(-1), iref(-1)
{
  normal[0] = normal[1] = 0.0;
  normal[2] = 1.0;
  int iarg = 3;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "normal") == 0) {
      if (iarg + 4 > narg)
        error->all(FLERR, "compute cell/props: 'normal' expects three components nx ny nz");
      // scaled by its largest component first: squaring 1e200 would overflow to a zero normal
      double big = 0.0, len = 0.0;
      for (int d = 0; d < 3; d++) {
        normal[d] = utils::numeric(FLERR, arg[iarg + 1 + d], false, lmp);
        big = MAX(big, fabs(normal[d]));
      }
      if (!(big > 0.0) || !std::isfinite(big))
        error->all(FLERR,
                   "compute cell/props: 'normal' must be a finite non-zero vector, got {} {} {}",
                   arg[iarg + 1], arg[iarg + 2], arg[iarg + 3]);
      for (int d = 0; d < 3; d++) {
        normal[d] /= big;
        len += normal[d] * normal[d];
      }
      for (int d = 0; d < 3; d++) normal[d] /= sqrt(len);
      iarg += 4;
    } else if (strcmp(arg[iarg], "leaks") == 0) {
      if (iarg + 2 > narg) error->all(FLERR, "compute cell/props: 'leaks' expects yes or no");
      leaks = utils::logical(FLERR, arg[iarg + 1], false, lmp);
      iarg += 2;
    } else
      error->all(FLERR, "Unknown keyword '{}' for compute cell/props: expected 'normal' or 'leaks'",
                 arg[iarg]);
  }
  if (!atom->molecule_flag)
    error->all(FLERR,
               "Compute cell/props requires molecule IDs (one per cell): atom_style molecular");
  array_flag = 1;
  size_array_cols = NCOL;
  size_array_rows = 0;
  size_array_rows_variable = 1;
  extarray = 0;
}

ComputeCellProps::~ComputeCellProps()
{
  memory->destroy(array);
}

void ComputeCellProps::init()
{
  sph = dynamic_cast<PairCellSPH *>(force->pair_match("^cell/sph", 0));
  tether = dynamic_cast<BondCellTether *>(force->bond_match("cell/tether"));
  membrane = dynamic_cast<AngleCellMembrane *>(force->angle_match("cell/membrane"));
  if (!tether && !membrane)
    error->all(FLERR,
               "Compute cell/props requires a cell wall: bond style cell/tether or angle style "
               "cell/membrane");
  if (!force->newton_bond)
    error->all(FLERR, "Compute cell/props requires newton_bond on (each bond and triangle once)");
  if (!force->angle)
    error->all(FLERR,
               "Compute cell/props requires an angle style (angle_style zero nocoeff) so "
               "that LAMMPS lists the wall triangles");
  // volume, area and leaks are sums over the triangles: without them they would read 0
  if (atom->nbonds > 0 && atom->nangles == 0)
    error->all(FLERR,
               "Compute cell/props: the walls have {} tethers (bonds) but no triangles (angles); "
               "volume, area and leak counts are sums over the triangles and would read 0 (give "
               "the data file's Angles section, as cellgen.py writes it)",
               atom->nbonds);
  int flag, cols;
  // bond style cell/tether or angle style cell/membrane (required above) has checked that the
  // reference positions exist
  iref = atom->find_custom(CellMech::REF_FIELD, flag, cols);
  ialam = atom->find_custom(CellMech::AREA_FIELD, flag, cols);
  if (ialam >= 0 && (flag != 1 || cols != 0)) ialam = -1;
}

void ComputeCellProps::allocate(int n)
{
  if (n == ncells && array) return;
  memory->destroy(array);
  ncells = n;
  memory->create(array, MAX(ncells, 1), NCOL, "cell/props:array");
  size_array_rows = ncells;
}

/* ----------------------------------------------------------------------
   centre of each cell: mean of its unwrapped wall nodes (atoms in bonds)
------------------------------------------------------------------------- */

void ComputeCellProps::wall_centres(LAMMPS *lmp, const CellMech::CellIndex &cells,
                                    const PairCellSPH *sph, std::vector<double> &c)
{
  Atom *atom = lmp->atom;
  const int ncells = cells.size();
  std::vector<double> local(4 * (ncells + 1), 0.0), all(4 * (ncells + 1));
  double **x = atom->x;
  const CellMech::WallNodes is_wall(lmp);
  for (int i = 0; i < atom->nlocal; i++) {
    const int m = cells.slot(atom->molecule[i]);
    if (m < 1 || (sph && sph->is_fluid(atom->type[i])) || !is_wall(i)) continue;
    double xu[3];
    lmp->domain->unmap(x[i], atom->image[i], xu);
    for (int d = 0; d < 3; d++) local[4 * m + d] += xu[d];
    local[4 * m + 3] += 1.0;
  }
  MPI_Allreduce(local.data(), all.data(), 4 * (ncells + 1), MPI_DOUBLE, MPI_SUM, lmp->world);
  c.assign(3 * (ncells + 1), 0.0);
  for (int m = 1; m <= ncells; m++)
    if (all[4 * m + 3] > 0)
      for (int d = 0; d < 3; d++) c[3 * m + d] = all[4 * m + d] / all[4 * m + 3];
}

/* ----------------------------------------------------------------------
   fix ave/time mode vector asks a variable-length array for its row count before it reads
   the rows; the count is known only after the rows are computed
------------------------------------------------------------------------- */

int ComputeCellProps::lock_length()
{
  if (invoked_array != update->ntimestep) compute_array();
  return size_array_rows;
}

/* ---------------------------------------------------------------------- */

void ComputeCellProps::compute_array()
{
  invoked_array = update->ntimestep;
  // the failures found so far reach every rank's topology and counts first
  const double *nbroken = FixCellFailure::synced_counts(lmp, FixCellTetherBreak::ID);
  auto *debonded = FixCellFailure::synced(lmp, FixCellLamellaBreak::ID);

  cells.build(lmp);
  allocate(cells.size());

  std::vector<double> c;
  wall_centres(lmp, cells, sph, c);

  sums.clear(ncells);
  std::vector<double> lmax(ncells + 1, 0.0);    // max tether stretch
  add_triangles(c);
  sums.add_broken_tethers(lmp, cells, nbroken);
  if (sph) sums.add_fluid(lmp, sph, cells, groupbit);
  add_bonds(c, lmax);
  sums.reduce(world);
  MPI_Allreduce(MPI_IN_PLACE, lmax.data(), ncells + 1, MPI_DOUBLE, MPI_MAX, world);

  for (int m = 1; m <= ncells; m++) fill_row(m, sums[m], lmax[m], c);
  if (debonded && debonded->array_flag) add_debonded(debonded);
  if (leaks) count_leaks(c);
}

// a point of cell m relative to its centre c, in the minimum image
void ComputeCellProps::relative(int i, int m, const std::vector<double> &c, double *out) const
{
  for (int d = 0; d < 3; d++) out[d] = atom->x[i][d] - c[3 * m + d];
  CellMech::minimum_image(domain, FLERR, out[0], out[1], out[2]);
}

// A broken tether takes its two triangles out of the wall (bond style cell/tether): after a
// failure the volume is that of the cones from the centre over the remaining triangles. The
// triangles' orientation and cell follow the contract of cell_fields.h.
void ComputeCellProps::add_triangles(const std::vector<double> &c)
{
  tagint *molecule = atom->molecule;
  int **anglelist = neighbor->anglelist;
  CellMech::for_each_wall_triangle(
      anglelist, neighbor->nanglelist, [&](int n, int a, int b, int cc) {
        const int m = cells.slot(molecule[b]);
        if (m < 1) return;
        double pa[3], pb[3], pc[3];
        relative(a, m, c, pa);
        relative(b, m, c, pb);
        relative(cc, m, c, pc);
        const double u[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
        const double w[3] = {pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]};
        CellMech::CellSum &s = sums[m];
        s.volume += cone_volume(pa, u, w);
        s.area += triangle_area(u, w);
        if (membrane) {
          double h[3];
          const double *p[3] = {pa, pb, pc};
          for (int k = 0; k < 3; k++)
            h[k] = p[k][0] * normal[0] + p[k][1] * normal[1] + p[k][2] * normal[2];
          const int above = (h[0] > 0.0) + (h[1] > 0.0) + (h[2] > 0.0);
          double f[3][3];
          // only a triangle the plane cuts carries force across it
          if (above % 3 != 0 && membrane->triangle_forces(anglelist[n][3], a, b, cc, f))
            s.feq += equatorial_force_triangle(f, h, normal);
        }
      });
}

// the wall's tethers (stretch, Eq. 23) and the middle-lamella bonds to other cells
void ComputeCellProps::add_bonds(const std::vector<double> &c, std::vector<double> &lmax)
{
  double **x = atom->x;
  double **ref = atom->darray[iref];
  tagint *molecule = atom->molecule;
  const double *alam = ialam >= 0 ? atom->dvector[ialam] : nullptr;
  int **bondlist = neighbor->bondlist;
  for (int n = 0; n < neighbor->nbondlist; n++) {
    const int i1 = bondlist[n][0], i2 = bondlist[n][1], type = bondlist[n][2];
    if (type <= 0) continue;
    const int m = cells.slot(molecule[i1]);
    if (m < 1) continue;
    if (!CellMech::same_cell(molecule, i1, i2)) {
      // a middle-lamella bond glues this cell to another: both cells count it and its area
      const double area = alam ? CellMech::lamella_area(alam, i1, i2) : 0.0;
      for (const int mm : {m, cells.slot(molecule[i2])})
        if (mm >= 1) {
          sums[mm].nlamella += 1.0;
          sums[mm].glued_area += area;
        }
      continue;
    }
    double del[3] = {x[i1][0] - x[i2][0], x[i1][1] - x[i2][1], x[i1][2] - x[i2][2]};
    const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
    const double lam = sqrt(rsq) / CellMech::rest_length(ref, i1, i2);
    sums[m].stretch += lam;
    sums[m].ntethers += 1.0;
    lmax[m] = MAX(lmax[m], lam);
    double p1[3], p2[3];
    relative(i1, m, c, p1);
    relative(i2, m, c, p2);
    const double s1 = p1[0] * normal[0] + p1[1] * normal[1] + p1[2] * normal[2];
    const double s2 = p2[0] * normal[0] + p2[1] * normal[1] + p2[2] * normal[2];
    if (crosses_equator(s1, s2)) {
      double fforce = 0.0;    // bond style zero (a membrane wall's tethers) leaves it unset
      force->bond->single(type, rsq, i1, i2, fforce);
      const double dn = del[0] * normal[0] + del[1] * normal[1] + del[2] * normal[2];
      sums[m].feq += equatorial_force_term(fforce, dn, s1, s2);
    }
  }
}

void ComputeCellProps::fill_row(int m, const CellMech::CellSum &s, double lmax,
                                const std::vector<double> &c)
{
  double *row = array[m - 1];
  row[VOLUME] = s.volume;
  row[AREA] = s.area;
  row[PRESSURE] = s.nfluid > 0 ? s.pressure / s.nfluid : 0.0;
  row[MASS] = s.mass;
  row[NFLUID] = s.nfluid;
  row[LAM_MEAN] = s.ntethers > 0 ? s.stretch / s.ntethers : 0.0;
  row[LAM_MAX] = lmax;
  row[FEQ] = s.feq;
  row[XC] = c[3 * m];
  row[YC] = c[3 * m + 1];
  row[ZC] = c[3 * m + 2];
  row[NLEAK] = 0.0;
  row[NBROKEN] = s.broken;
  row[NLAMELLA] = s.nlamella;
  row[GLUED_AREA] = s.glued_area;
  row[NDEBONDED] = row[DEBONDED_AREA] = 0.0;
  row[MOLECULE] = (double) cells.id(m);
}

// debonded lamella: the per-cell-pair table of fix cell_debonded (identical on every rank;
// columns cell i, cell j, bonds, area, ...) counted for both cells of each pair
void ComputeCellProps::add_debonded(Fix *debonded)
{
  for (int r = 0; r < debonded->size_array_rows; r++)
    for (int side = 0; side < 2; side++) {
      const int m = cells.slot((tagint) debonded->compute_array(r, side));
      if (m < 1) continue;
      array[m - 1][NDEBONDED] += debonded->compute_array(r, 2);
      array[m - 1][DEBONDED_AREA] += debonded->compute_array(r, 3);
    }
}

/* ----------------------------------------------------------------------
   fluid outside its own wall: every rank gets all triangles (relative to
   their cell centre) and sums, for its fluid, the solid angles of its own
   cell's triangles; 4 pi inside a closed mesh, 0 outside.
------------------------------------------------------------------------- */

void ComputeCellProps::count_leaks(const std::vector<double> &c)
{
  double **x = atom->x;
  tagint *molecule = atom->molecule;
  std::vector<double> mine;
  CellMech::for_each_wall_triangle(neighbor->anglelist, neighbor->nanglelist,
                                   [&](int, int a, int b, int cc) {
                                     const int m = cells.slot(molecule[b]);
                                     if (m < 1) return;
                                     mine.push_back((double) m);
                                     for (const int node : {a, b, cc}) {
                                       double p[3];
                                       for (int d = 0; d < 3; d++) p[d] = x[node][d] - c[3 * m + d];
                                       CellMech::minimum_image(domain, FLERR, p[0], p[1], p[2]);
                                       mine.insert(mine.end(), p, p + 3);
                                     }
                                   });
  const std::vector<double> tris = CellMech::allgather_list(mine, MPI_DOUBLE, world);
  const int total = tris.size();

  // group the triangles by cell
  const int ntri = total / 10;
  std::vector<int> start(ncells + 2, 0);
  for (int t = 0; t < ntri; t++) start[(int) tris[10 * t] + 1]++;
  for (int m = 1; m <= ncells + 1; m++) start[m] += start[m - 1];
  std::vector<double> sorted(9 * ntri);
  std::vector<int> fill(start.begin(), start.end());
  for (int t = 0; t < ntri; t++) {
    const int m = (int) tris[10 * t];
    std::copy(&tris[10 * t + 1], &tris[10 * t + 10], &sorted[9 * fill[m]++]);
  }

  // A ball around the centre that touches no triangle lies wholly inside the closed wall (the
  // centre being inside): its fluid needs no solid angles. That is most of the fluid.
  std::vector<double> rin_sq(ncells + 1, BIG);
  for (int m = 1; m <= ncells; m++)
    for (int t = start[m]; t < start[m + 1]; t++)
      rin_sq[m] =
          MIN(rin_sq[m],
              origin_triangle_dist_sq(&sorted[9 * t], &sorted[9 * t + 3], &sorted[9 * t + 6]));

  std::vector<double> out_local(ncells + 1, 0.0), out_all(ncells + 1);
  for (int i = 0; i < atom->nlocal; i++) {
    const int m = cells.slot(molecule[i]);
    if (m < 1 || !sph || !sph->is_fluid(atom->type[i]) || !(atom->mask[i] & groupbit)) continue;
    double p[3];
    for (int d = 0; d < 3; d++) p[d] = x[i][d] - c[3 * m + d];
    CellMech::minimum_image(domain, FLERR, p[0], p[1], p[2]);
    if (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] < rin_sq[m]) continue;
    double omega = 0.0;
    for (int t = start[m]; t < start[m + 1]; t++) {
      const double *v = &sorted[9 * t];
      const double a[3] = {v[0] - p[0], v[1] - p[1], v[2] - p[2]};
      const double b[3] = {v[3] - p[0], v[4] - p[1], v[5] - p[2]};
      const double cc[3] = {v[6] - p[0], v[7] - p[1], v[8] - p[2]};
      omega += solid_angle(a, b, cc);
    }
    if (omega < 2.0 * M_PI) out_local[m] += 1.0;
  }
  MPI_Allreduce(out_local.data(), out_all.data(), ncells + 1, MPI_DOUBLE, MPI_SUM, world);
  for (int m = 1; m <= ncells; m++) array[m - 1][NLEAK] = out_all[m];
}
