/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: water exchanged between glued cells for fix cell/fluid
   (cell_exchange.h)
------------------------------------------------------------------------- */

#include "cell_exchange.h"

#include "atom.h"
#include "cell_fields.h"
#include "cell_index.h"
#include "cell_mpi.h"
#include "cell_sums.h"
#include "cell_topology.h"
#include "cell_water.h"
#include "lammps.h"
#include "neighbor.h"
#include "physics/water.h"

using namespace LAMMPS_NS;
using namespace CellPhysics;

namespace CellMech {

void CellExchange::find_pairs(LAMMPS *lmp, const CellIndex &cells, const double *alam)
{
  PairSums<1> local;    // keyed by slots
  const tagint *molecule = lmp->atom->molecule;
  int **bondlist = lmp->neighbor->bondlist;
  for (int n = 0; n < lmp->neighbor->nbondlist; n++) {
    const int i1 = bondlist[n][0], i2 = bondlist[n][1];
    if (bondlist[n][2] <= 0 || same_cell(molecule, i1, i2)) continue;    // debonded or a tether
    const int a = cells.slot(molecule[i1]), b = cells.slot(molecule[i2]);
    if (a < 1 || b < 1) continue;
    local(a, b)[0] += lamella_area(alam, i1, i2);
  }
  const PairSums<1> all = local.summed(lmp->world);
  glued.clear();
  for (const auto &kv : all.all())
    glued.push_back({(int) kv.first.first, (int) kv.first.second, kv.second[0]});
}

void CellExchange::add_uptake(const CellSums &sums, const CellWater &water, double dt,
                              std::vector<double> &uptake) const
{
  for (const GluedPair &p : glued) {
    const CellSum &a = sums[p.a], &b = sums[p.b];
    // a wall without triangles has no area to share (and no stretch to scale it by)
    if (a.nfluid == 0 || b.nfluid == 0 || a.broken > 0.0 || b.broken > 0.0 || a.rest_area <= 0.0 ||
        b.rest_area <= 0.0)
      continue;
    const double Lab = series_conductivity(water.lp[p.a], water.lp[p.b]);
    if (Lab == 0.0) continue;
    // the glued rest area at the walls' mean areal stretch; the mean density of the two
    const double Aab = p.area * 0.5 * (a.area / a.rest_area + b.area / b.rest_area);
    const double rho = 0.5 * (a.density / a.nfluid + b.density / b.nfluid);
    const double dM =
        exchange_mass_step(Aab * Lab * rho, dt, water.psi[p.a], water.psi[p.b],
                           water.potential_stiffness(p.a), water.potential_stiffness(p.b));
    uptake[p.a] -= dM;
    uptake[p.b] += dM;
  }
}

}    // namespace CellMech
