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
#include "physics/surface.h"
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

void FixCellVTK::write()
{
  double **x = atom->x;
  double **ref = atom->darray[iref];
  tagint *tag = atom->tag;
  tagint *molecule = atom->molecule;
  int *mask = atom->mask;

  // points: id, molecule, unwrapped position, displacement from the reference, broken tethers
  const double *nbroken = FixCellFailure::synced_counts(lmp, FixCellTetherBreak::ID);
  const double *ndebonded = FixCellFailure::synced_counts(lmp, FixCellLamellaBreak::ID);
  const CellMech::WallNodes is_wall(lmp);
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || !is_wall(i)) continue;
    double xu[3];
    domain->unmap(x[i], atom->image[i], xu);
    mine.insert(mine.end(),
                {(double) tag[i], (double) molecule[i], xu[0], xu[1], xu[2], xu[0] - ref[i][0],
                 xu[1] - ref[i][1], xu[2] - ref[i][2], nbroken ? nbroken[i] : 0.0,
                 ndebonded ? ndebonded[i] : 0.0});
  }
  // triangles: three IDs, molecule, area strain, largest tether stretch (a broken tether has
  // taken its triangles out of the topology: the crack is a hole in the surface). Their order
  // gives the outward normal and their central node the group (contract: cell_fields.h).
  std::vector<double> tris;
  CellMech::for_each_wall_triangle(
      neighbor->anglelist, neighbor->nanglelist, [&](int, int a, int b, int c) {
        const int v[3] = {a, b, c};
        if (!(mask[v[1]] & groupbit)) return;
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
                     (double) molecule[v[1]], strain, stretch});
      });

  auto gather = [&](std::vector<double> &local) {
    int n = local.size();
    std::vector<int> counts(comm->nprocs), displs(comm->nprocs, 0);
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
    int total = 0;
    if (comm->me == 0)
      for (int p = 0; p < comm->nprocs; p++) {
        displs[p] = total;
        total += counts[p];
      }
    std::vector<double> all(comm->me == 0 ? total : 0);
    MPI_Gatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE,
                0, world);
    return all;
  };
  std::vector<double> points = gather(mine), cells = gather(tris);
  if (comm->me != 0) return;

  const int NP = 10;    // values per point
  const int np = points.size() / NP, nt = cells.size() / 6;
  std::unordered_map<tagint, int> index;
  for (int p = 0; p < np; p++) index[(tagint) points[NP * p]] = p;

  const std::string file = fmt::format("{}.{}.vtk", prefix, update->ntimestep);
  FILE *fp = fopen(file.c_str(), "w");
  if (!fp) error->one(FLERR, "fix cell/vtk: cannot open {} for writing", file);
  fmt::print(fp, "# vtk DataFile Version 3.0\ncellmech walls, step {}\nASCII\nDATASET POLYDATA\n",
             update->ntimestep);
  fmt::print(fp, "POINTS {} double\n", np);
  for (int p = 0; p < np; p++)
    fmt::print(fp, "{:.10g} {:.10g} {:.10g}\n", points[NP * p + 2], points[NP * p + 3],
               points[NP * p + 4]);
  int nkept = 0;
  std::string polys;
  for (int t = 0; t < nt; t++) {
    const double *c = &cells[6 * t];
    auto a = index.find((tagint) c[0]), b = index.find((tagint) c[1]),
         d = index.find((tagint) c[2]);
    if (a == index.end() || b == index.end() || d == index.end()) continue;    // node not in group
    polys += fmt::format("3 {} {} {}\n", a->second, b->second, d->second);
    nkept++;
  }
  fmt::print(fp, "POLYGONS {} {}\n{}", nkept, 4 * nkept, polys);
  fmt::print(fp, "POINT_DATA {}\nSCALARS id int 1\nLOOKUP_TABLE default\n", np);
  for (int p = 0; p < np; p++) fmt::print(fp, "{}\n", (tagint) points[NP * p]);
  fmt::print(fp, "SCALARS cell int 1\nLOOKUP_TABLE default\n");
  for (int p = 0; p < np; p++) fmt::print(fp, "{}\n", (tagint) points[NP * p + 1]);
  fmt::print(fp, "VECTORS displacement double\n");
  for (int p = 0; p < np; p++)
    fmt::print(fp, "{:.10g} {:.10g} {:.10g}\n", points[NP * p + 5], points[NP * p + 6],
               points[NP * p + 7]);
  fmt::print(fp, "SCALARS broken int 1\nLOOKUP_TABLE default\n");
  for (int p = 0; p < np; p++) fmt::print(fp, "{}\n", (int) points[NP * p + 8]);
  fmt::print(fp, "SCALARS debonded int 1\nLOOKUP_TABLE default\n");
  for (int p = 0; p < np; p++) fmt::print(fp, "{}\n", (int) points[NP * p + 9]);
  fmt::print(fp, "CELL_DATA {}\n", nkept);
  const char *names[3] = {"cell", "area_strain", "max_stretch"};
  for (int f = 0; f < 3; f++) {
    fmt::print(fp, "SCALARS {} {} 1\nLOOKUP_TABLE default\n", names[f], f == 0 ? "int" : "double");
    for (int t = 0; t < nt; t++) {
      const double *c = &cells[6 * t];
      if (!index.count((tagint) c[0]) || !index.count((tagint) c[1]) || !index.count((tagint) c[2]))
        continue;
      if (f == 0)
        fmt::print(fp, "{}\n", (int) c[3]);
      else
        fmt::print(fp, "{:.10g}\n", c[3 + f]);
    }
  }
  fclose(fp);
}
