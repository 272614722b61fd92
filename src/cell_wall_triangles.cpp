/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the wall triangles as fix cell/fluid measures them
   (cell_wall_triangles.h)
------------------------------------------------------------------------- */

#include "cell_wall_triangles.h"

#include "atom.h"
#include "cell_exposed.h"
#include "cell_fields.h"
#include "cell_index.h"
#include "cell_sums.h"
#include "cell_topology.h"
#include "neighbor.h"
#include "physics/surface.h"

using namespace LAMMPS_NS;
using namespace CellPhysics;

namespace CellMech {

bool WallTriangles::stale(LAMMPS *lmp)
{
  return list_rebuilt(lmp, build, slot.size(), lmp->neighbor->nanglelist);
}

void WallTriangles::index(LAMMPS *lmp, const CellIndex &cells, double *const *ref)
{
  int **anglelist = lmp->neighbor->anglelist;
  const int nangle = lmp->neighbor->nanglelist;
  slot.assign(nangle, 0);
  rest_area.assign(nangle, 0.0);
  for (int n = 0; n < nangle; n++) {
    const int a = anglelist[n][0], b = anglelist[n][1], c = anglelist[n][2];
    slot[n] = cells.slot(lmp->atom->molecule[b]);
    if (!ref) continue;
    double u[3], w[3];
    for (int d = 0; d < 3; d++) {
      u[d] = ref[b][d] - ref[a][d];
      w[d] = ref[c][d] - ref[a][d];
    }
    rest_area[n] = triangle_area(u, w);
  }
  open.assign(nangle, 1);
}

void WallTriangles::find_open(LAMMPS *lmp, const PairCellSPH *sph, double depth,
                              const std::vector<double> &node_glued)
{
  find_open_triangles(lmp, sph, depth, node_glued, slot, open);
}

void WallTriangles::add_areas(LAMMPS *lmp, bool with_rest, CellSums &sums) const
{
  double **x = lmp->atom->x;
  for_each_wall_triangle(lmp->neighbor->anglelist, lmp->neighbor->nanglelist,
                         [&](int n, int a, int b, int c) {
                           const int m = slot[n];
                           if (m < 1) return;
                           double u[3], w[3];
                           for (int d = 0; d < 3; d++) {
                             u[d] = x[b][d] - x[a][d];
                             w[d] = x[c][d] - x[a][d];
                           }
                           const double A = triangle_area(u, w);
                           CellSum &s = sums[m];
                           s.area += A;
                           if (with_rest) s.rest_area += rest_area[n];
                           if (open[n]) s.open_area += A;
                         });
}

}    // namespace CellMech
