/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the wall triangles that face the outside (cell_exposed.h)
------------------------------------------------------------------------- */

#include "cell_exposed.h"

#include "atom.h"
#include "cell_topology.h"
#include "lammps.h"
#include "neighbor.h"
#include "pair_cell_sph.h"
#include "physics/water.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace CellPhysics;

namespace {

// The wall nodes of all cells (a cell's local and ghost atoms that are not fluid), binned in cubes
// of side D (smaller bins, fewer nodes to test, cost more in bins visited: 2x the time at D/2).
class WallNodeBins {
 public:
  WallNodeBins(LAMMPS *lmp, const PairCellSPH *sph, double D);
  bool empty() const { return sorted.empty(); }
  // the bin along d of a point, clamped to the grid
  int bin_of(const double *p, int d) const
  {
    const int k = (int) ((p[d] - lo[d]) / side);
    return k < 0 ? 0 : (k >= nb[d] ? nb[d] - 1 : k);
  }
  int bin_index(int kx, int ky, int kz) const { return (kz * nb[1] + ky) * nb[0] + kx; }
  int bin_at(const double *p) const { return bin_index(bin_of(p, 0), bin_of(p, 1), bin_of(p, 2)); }

  double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {0.0, 0.0, 0.0};
  double side;
  int nb[3];
  std::vector<int> start, sorted;    // the nodes of bin k: sorted[start[k] .. start[k + 1] - 1]
};

WallNodeBins::WallNodeBins(LAMMPS *lmp, const PairCellSPH *sph, double D) : side(D)
{
  double **x = lmp->atom->x;
  const tagint *molecule = lmp->atom->molecule;
  const int *type = lmp->atom->type;
  const int nall = lmp->atom->nlocal + lmp->atom->nghost;
  std::vector<int> node;
  for (int j = 0; j < nall; j++) {
    if (molecule[j] < 1 || sph->is_fluid(type[j])) continue;
    for (int d = 0; d < 3; d++) {
      lo[d] = node.empty() ? x[j][d] : MIN(lo[d], x[j][d]);
      hi[d] = node.empty() ? x[j][d] : MAX(hi[d], x[j][d]);
    }
    node.push_back(j);
  }
  if (node.empty()) return;
  // larger bins where a far atom would make too many: at most about eight bins per node
  const double cap = 8.0 * (double) node.size() + 64.0;
  while (((hi[0] - lo[0]) / side + 1.0) * ((hi[1] - lo[1]) / side + 1.0) *
             ((hi[2] - lo[2]) / side + 1.0) >
         cap)
    side *= 2.0;
  for (int d = 0; d < 3; d++) nb[d] = (int) ((hi[d] - lo[d]) / side) + 1;
  const int nbins = nb[0] * nb[1] * nb[2];
  start.assign(nbins + 1, 0);
  sorted.resize(node.size());
  std::vector<int> where(node.size());
  for (size_t k = 0; k < node.size(); k++) {
    where[k] = bin_at(x[node[k]]);
    start[where[k] + 1]++;
  }
  for (int b = 0; b < nbins; b++) start[b + 1] += start[b];
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (size_t k = 0; k < node.size(); k++) sorted[fill[where[k]]++] = node[k];
}

// a triangle a-b-c as the search sees it: its centre, unit normal and longest edge h
struct TriangleFrame {
  double cen[3], nrm[3], h;
  bool degenerate;    // no direction to face
  TriangleFrame(double **x, int a, int b, int c);
};

TriangleFrame::TriangleFrame(double **x, int a, int b, int c)
{
  double u[3], w[3], v[3];
  for (int d = 0; d < 3; d++) {
    u[d] = x[b][d] - x[a][d];
    w[d] = x[c][d] - x[a][d];
    v[d] = x[c][d] - x[b][d];
    cen[d] = (x[a][d] + x[b][d] + x[c][d]) / 3.0;
  }
  nrm[0] = u[1] * w[2] - u[2] * w[1];
  nrm[1] = u[2] * w[0] - u[0] * w[2];
  nrm[2] = u[0] * w[1] - u[1] * w[0];
  const double len = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
  degenerate = len == 0.0;
  h = 0.0;
  if (degenerate) return;
  for (int d = 0; d < 3; d++) nrm[d] /= len;
  h = std::sqrt(
      MAX(MAX(u[0] * u[0] + u[1] * u[1] + u[2] * u[2], w[0] * w[0] + w[1] * w[1] + w[2] * w[2]),
          v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
}

// whether a wall node of another cell than the central node b's, within D of b, hides the triangle
class HiderSearch {
 public:
  HiderSearch(LAMMPS *lmp, const WallNodeBins &bins, double D) :
      x(lmp->atom->x), molecule(lmp->atom->molecule), bins(bins), D(D)
  {
  }
  bool hidden(int b, const TriangleFrame &t) const;

 private:
  double **x;
  const tagint *molecule;
  const WallNodeBins &bins;
  const double D;
  bool hidden_in(int bin, int b, const TriangleFrame &t) const;
};

bool HiderSearch::hidden_in(int bin, int b, const TriangleFrame &t) const
{
  const double D2 = D * D;
  for (int q = bins.start[bin]; q < bins.start[bin + 1]; q++) {
    const int j = bins.sorted[q];
    if (CellMech::same_cell(molecule, j, b)) continue;
    double r[3], dc[3];
    for (int d = 0; d < 3; d++) {
      r[d] = x[j][d] - x[b][d];
      dc[d] = x[j][d] - t.cen[d];
    }
    if (r[0] * r[0] + r[1] * r[1] + r[2] * r[2] <= D2 && hides_triangle(dc, t.nrm, t.h))
      return true;
  }
  return false;
}

// another cell's wall in front of a triangle is mostly the glued neighbour's, a gap away along the
// normal: its bin first, then every bin within D of the central node
bool HiderSearch::hidden(int b, const TriangleFrame &t) const
{
  const double side = bins.side, half = 0.5 * side, reach = D + std::sqrt(3.0) * half;
  int k0[3], k1[3];
  for (int d = 0; d < 3; d++) {
    double p[3] = {x[b][0], x[b][1], x[b][2]};
    p[d] = x[b][d] - D;
    k0[d] = bins.bin_of(p, d);
    p[d] = x[b][d] + D;
    k1[d] = bins.bin_of(p, d);
  }
  double p[3];
  for (int d = 0; d < 3; d++) p[d] = t.cen[d] + MIN(t.h, D) * t.nrm[d];
  const int first = bins.bin_at(p);
  if (hidden_in(first, b, t)) return true;
  for (int kz = k0[2]; kz <= k1[2]; kz++)
    for (int ky = k0[1]; ky <= k1[1]; ky++)
      for (int kx = k0[0]; kx <= k1[0]; kx++) {
        const int bin = bins.bin_index(kx, ky, kz);
        if (bin == first) continue;
        // a bin wholly behind the triangle's plane or beyond D of its node holds no hider
        const double bc[3] = {bins.lo[0] + (kx + 0.5) * side, bins.lo[1] + (ky + 0.5) * side,
                              bins.lo[2] + (kz + 0.5) * side};
        double sb = 0.0, rb = 0.0;
        for (int d = 0; d < 3; d++) {
          sb += (bc[d] - t.cen[d]) * t.nrm[d];
          rb += (bc[d] - x[b][d]) * (bc[d] - x[b][d]);
        }
        if (sb < -std::sqrt(3.0) * half || rb > reach * reach) continue;
        if (hidden_in(bin, b, t)) return true;
      }
  return false;
}

}    // namespace

namespace CellMech {

void count_glued_nodes(LAMMPS *lmp, std::vector<double> &node_glued)
{
  const tagint *molecule = lmp->atom->molecule;
  node_glued.assign(lmp->atom->nlocal + lmp->atom->nghost, 0.0);
  int **bondlist = lmp->neighbor->bondlist;
  // each bond is in the list once, owned by either node's rank
  for (int k = 0; k < lmp->neighbor->nbondlist; k++) {
    const int i1 = bondlist[k][0], i2 = bondlist[k][1];
    if (bondlist[k][2] <= 0 || same_cell(molecule, i1, i2)) continue;    // debonded or a tether
    node_glued[i1] += 1.0;
    node_glued[i2] += 1.0;
  }
}

void find_open_triangles(LAMMPS *lmp, const PairCellSPH *sph, double depth,
                         const std::vector<double> &node_glued, const std::vector<int> &slot,
                         std::vector<char> &open)
{
  const WallNodeBins bins(lmp, sph, depth);
  if (bins.empty()) return;
  const HiderSearch search(lmp, bins, depth);
  double **x = lmp->atom->x;
  for_each_wall_triangle(
      lmp->neighbor->anglelist, lmp->neighbor->nanglelist, [&](int n, int a, int b, int c) {
        if (slot[n] < 1) return;
        // glued: two or three of its nodes hold lamella bonds (the glued region's rim runs through
        // triangles; the majority splits them about evenly between glued and not)
        if ((node_glued[a] > 0.0) + (node_glued[b] > 0.0) + (node_glued[c] > 0.0) >= 2) {
          open[n] = 0;
          return;
        }
        const TriangleFrame t(x, a, b, c);
        if (t.degenerate) return;
        open[n] = search.hidden(b, t) ? 0 : 1;
      });
}

}    // namespace CellMech
