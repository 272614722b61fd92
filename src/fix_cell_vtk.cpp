/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: fix cell/vtk

   fix ID group cell/vtk N prefix

   Every N steps (and at the start of a run) writes prefix.STEP.vtk, a
   legacy-format VTK PolyData file with the wall nodes of the group as
   points (unwrapped coordinates) and the wall triangles (the angles of the
   topology) as polygons:
     point data: id (atom ID), cell (molecule ID), displacement from the
                 reference (rest) position, broken (tethers the node has
                 lost, bond style cell/tether with lamf: wall rupture),
                 debonded (middle-lamella bonds to other cells the node
                 has lost, bond style cell/lamella: cells coming apart)
     cell data:  cell (molecule ID), area_strain (area / rest area - 1),
                 max_stretch (largest l/l0 of its three tethers)
   A broken tether takes its triangles out of the wall: a crack is a hole.
   ParaView opens the series directly (prefix..vtk groups the steps).
   Rank 0 gathers the data and writes; the files are for viewing, not for
   restarting.
------------------------------------------------------------------------- */

#include "fix_cell_vtk.h"

#include "atom.h"
#include "cell_fields.h"
#include "cell_topology.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_cell_lamella_break.h"
#include "fix_cell_tether_break.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "neighbor.h"
#include "physics/surface.h"
#include "update.h"

#include <cmath>
#include <cstdio>
#include <unordered_map>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

FixCellVTK::FixCellVTK(LAMMPS *_lmp, int narg, char **arg) : Fix(_lmp, narg, arg), iref(-1)
{
  if (narg != 5)
    error->all(FLERR,
               "Illegal fix cell/vtk command: expected 'fix ID group cell/vtk N prefix', got "
               "{} arguments after the group",
               narg - 3);
  nevery = utils::inumeric(FLERR, arg[3], false, lmp);
  if (nevery <= 0) error->all(FLERR, "fix cell/vtk: N must be > 0, got {}", nevery);
  prefix = arg[4];
  if (!atom->molecular) error->all(FLERR, "Fix cell/vtk requires a molecular atom style");
}

int FixCellVTK::setmask()
{
  return END_OF_STEP;
}

void FixCellVTK::init()
{
  int flag, cols;
  iref = atom->find_custom(CellMech::REF_FIELD, flag, cols);
  if (iref < 0 || flag != 1 || cols != 3)
    error->all(FLERR,
               "Fix cell/vtk requires the reference positions d2_cellref (3 columns) of "
               "fix property/atom");
  if (!force->angle)
    error->all(FLERR,
               "Fix cell/vtk requires an angle style (angle_style zero nocoeff) so that "
               "LAMMPS lists the wall triangles");
  if (!force->newton_bond) error->all(FLERR, "Fix cell/vtk requires newton_bond on");
  // a group without wall nodes (e.g. the fluid) would give files with no surface in them
  const CellMech::WallNodes is_wall(lmp);
  bigint nwall_local = 0, nwall = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && is_wall(i)) nwall_local++;
  MPI_Allreduce(&nwall_local, &nwall, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (nwall == 0)
    error->all(FLERR,
               "Fix cell/vtk {}: group {} holds no wall nodes (atoms bonded by tethers); its "
               "files would hold no surface. Use the group of the walls (e.g. 'group wall type 1')",
               id, group->names[igroup]);
}

void FixCellVTK::setup(int /*vflag*/)
{
  write();
}

void FixCellVTK::end_of_step()
{
  write();
}

// The records gathered to rank 0, as doubles: per wall node of the group its ID, molecule,
// unwrapped position, displacement from the reference and failure counts; per wall triangle its
// three node IDs (in the order that gives the outward normal, cell_fields.h), the molecule of its
// central node, its area strain and its largest tether stretch.
namespace {
enum PointField { P_ID, P_MOL, P_X, P_DX = P_X + 3, P_BROKEN = P_DX + 3, P_DEBONDED, NP };
enum TriangleField { T_NODES, T_MOL = T_NODES + 3, T_STRAIN, T_STRETCH, NT };

// every rank's records concatenated in rank order on rank 0 (empty elsewhere)
std::vector<double> gather_to_root(const std::vector<double> &local, int me, int nprocs,
                                   MPI_Comm world)
{
  int n = local.size();
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
  int total = 0;
  if (me == 0)
    for (int p = 0; p < nprocs; p++) {
      displs[p] = total;
      total += counts[p];
    }
  std::vector<double> all(me == 0 ? total : 0);
  MPI_Gatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, 0,
              world);
  return all;
}

void write_points(FILE *fp, const std::vector<double> &points)
{
  const int np = points.size() / NP;
  fmt::print(fp, "POINTS {} double\n", np);
  for (int p = 0; p < np; p++)
    fmt::print(fp, "{:.10g} {:.10g} {:.10g}\n", points[NP * p + P_X], points[NP * p + P_X + 1],
               points[NP * p + P_X + 2]);
}

// The triangles as polygons over the points' indices; returns the triangles written: those whose
// three nodes are all points (all in the group).
std::vector<int> write_polygons(FILE *fp, const std::vector<double> &points,
                                const std::vector<double> &triangles)
{
  const int np = points.size() / NP, nt = triangles.size() / NT;
  std::unordered_map<tagint, int> index;
  for (int p = 0; p < np; p++) index[(tagint) points[NP * p + P_ID]] = p;
  std::vector<int> kept;
  std::string polys;
  for (int t = 0; t < nt; t++) {
    const double *c = &triangles[NT * t + T_NODES];
    auto a = index.find((tagint) c[0]), b = index.find((tagint) c[1]),
         d = index.find((tagint) c[2]);
    if (a == index.end() || b == index.end() || d == index.end()) continue;    // node not in group
    polys += fmt::format("3 {} {} {}\n", a->second, b->second, d->second);
    kept.push_back(t);
  }
  fmt::print(fp, "POLYGONS {} {}\n{}", kept.size(), 4 * kept.size(), polys);
  return kept;
}

void write_point_data(FILE *fp, const std::vector<double> &points)
{
  const int np = points.size() / NP;
  fmt::print(fp, "POINT_DATA {}\nSCALARS id int 1\nLOOKUP_TABLE default\n", np);
  for (int p = 0; p < np; p++) fmt::print(fp, "{}\n", (tagint) points[NP * p + P_ID]);
  fmt::print(fp, "SCALARS cell int 1\nLOOKUP_TABLE default\n");
  for (int p = 0; p < np; p++) fmt::print(fp, "{}\n", (tagint) points[NP * p + P_MOL]);
  fmt::print(fp, "VECTORS displacement double\n");
  for (int p = 0; p < np; p++)
    fmt::print(fp, "{:.10g} {:.10g} {:.10g}\n", points[NP * p + P_DX], points[NP * p + P_DX + 1],
               points[NP * p + P_DX + 2]);
  fmt::print(fp, "SCALARS broken int 1\nLOOKUP_TABLE default\n");
  for (int p = 0; p < np; p++) fmt::print(fp, "{}\n", (int) points[NP * p + P_BROKEN]);
  fmt::print(fp, "SCALARS debonded int 1\nLOOKUP_TABLE default\n");
  for (int p = 0; p < np; p++) fmt::print(fp, "{}\n", (int) points[NP * p + P_DEBONDED]);
}

void write_cell_data(FILE *fp, const std::vector<double> &triangles, const std::vector<int> &kept)
{
  fmt::print(fp, "CELL_DATA {}\n", kept.size());
  fmt::print(fp, "SCALARS cell int 1\nLOOKUP_TABLE default\n");
  for (int t : kept) fmt::print(fp, "{}\n", (int) triangles[NT * t + T_MOL]);
  fmt::print(fp, "SCALARS area_strain double 1\nLOOKUP_TABLE default\n");
  for (int t : kept) fmt::print(fp, "{:.10g}\n", triangles[NT * t + T_STRAIN]);
  fmt::print(fp, "SCALARS max_stretch double 1\nLOOKUP_TABLE default\n");
  for (int t : kept) fmt::print(fp, "{:.10g}\n", triangles[NT * t + T_STRETCH]);
}
}    // namespace

void FixCellVTK::write()
{
  const std::vector<double> points = gather_to_root(local_points(), comm->me, comm->nprocs, world);
  const std::vector<double> triangles =
      gather_to_root(local_triangles(), comm->me, comm->nprocs, world);
  if (comm->me != 0) return;

  const std::string file = fmt::format("{}.{}.vtk", prefix, update->ntimestep);
  FILE *fp = fopen(file.c_str(), "w");
  if (!fp) error->one(FLERR, "fix cell/vtk: cannot open {} for writing", file);
  fmt::print(fp, "# vtk DataFile Version 3.0\ncellmech walls, step {}\nASCII\nDATASET POLYDATA\n",
             update->ntimestep);
  write_points(fp, points);
  const std::vector<int> kept = write_polygons(fp, points, triangles);
  write_point_data(fp, points);
  write_cell_data(fp, triangles, kept);
  fclose(fp);
}

// this rank's wall nodes of the group (PointField records)
std::vector<double> FixCellVTK::local_points()
{
  double **x = atom->x;
  double **ref = atom->darray[iref];
  const double *nbroken = FixCellFailure::synced_counts(lmp, FixCellTetherBreak::ID);
  const double *ndebonded = FixCellFailure::synced_counts(lmp, FixCellLamellaBreak::ID);
  const CellMech::WallNodes is_wall(lmp);
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || !is_wall(i)) continue;
    double xu[3];
    domain->unmap(x[i], atom->image[i], xu);
    mine.insert(mine.end(),
                {(double) atom->tag[i], (double) atom->molecule[i], xu[0], xu[1], xu[2],
                 xu[0] - ref[i][0], xu[1] - ref[i][1], xu[2] - ref[i][2],
                 nbroken ? nbroken[i] : 0.0, ndebonded ? ndebonded[i] : 0.0});
  }
  return mine;
}

// this rank's wall triangles whose central node is in the group (TriangleField records). A broken
// tether has taken its triangles out of the topology: the crack is a hole in the surface.
std::vector<double> FixCellVTK::local_triangles()
{
  double **x = atom->x;
  double **ref = atom->darray[iref];
  tagint *tag = atom->tag;
  std::vector<double> tris;
  CellMech::for_each_wall_triangle(
      neighbor->anglelist, neighbor->nanglelist, [&](int, int a, int b, int c) {
        const int v[3] = {a, b, c};
        if (!(atom->mask[v[1]] & groupbit)) return;
        double e[3][3], e0[3][3], stretch = 0.0;
        for (int k = 0; k < 3; k++) {
          const int a = v[k], b = v[(k + 1) % 3];
          double len = 0.0, len0 = 0.0;
          for (int d = 0; d < 3; d++) {
            e[k][d] = x[b][d] - x[a][d];
            e0[k][d] = ref[b][d] - ref[a][d];
            len += e[k][d] * e[k][d];
            len0 += e0[k][d] * e0[k][d];
          }
          stretch = MAX(stretch, sqrt(len / len0));
        }
        const double strain =
            CellPhysics::triangle_area(e[0], e[1]) / CellPhysics::triangle_area(e0[0], e0[1]) - 1.0;
        tris.insert(tris.end(),
                    {(double) tag[v[0]], (double) tag[v[1]], (double) tag[v[2]],
                     (double) atom->molecule[v[1]], strain, stretch});
      });
  return tris;
}
