/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the water potentials of each cell for fix cell/fluid
   (cell_water.h)
------------------------------------------------------------------------- */

#include "cell_water.h"

#include "cell_exchange.h"
#include "cell_index.h"
#include "cell_sums.h"
#include "cell_water_settings.h"
#include "pair_cell_sph.h"
#include "physics/osmosis.h"
#include "physics/water.h"

using namespace LAMMPS_NS;
using namespace CellPhysics;

namespace CellMech {

void CellWater::resize(int ncells)
{
  for (auto *v : {&pi0, &lp, &pinow, &psi, &exposed, &glued}) v->assign(ncells + 1, 0.0);
}

void CellWater::update(const CellIndex &cells, const std::vector<GluedPair> &pairs)
{
  const int ncells = cells.size();
  for (int m = 1; m <= ncells; m++) {
    const CellSum &s = sums[m];
    pi0[m] = settings.pi0_of(cells.id(m));
    lp[m] = settings.lp_of(cells.id(m));
    pinow[m] = (settings.solute && water0[m] > 0.0 && s.mass > 0.0)
        ? solute_osmotic_potential(pi0[m], water0[m], s.mass)
        : pi0[m];
    psi[m] = s.nfluid > 0 ? s.pressure / s.nfluid + pinow[m] : pinow[m];
    glued[m] = 0.0;
  }
  for (const GluedPair &p : pairs) {
    glued[p.a] += p.area;
    glued[p.b] += p.area;
  }
  // without exchange every wall meets the outside whole, as the single cell of the paper
  for (int m = 1; m <= ncells; m++)
    exposed[m] = settings.exposed_outside()
        ? sums[m].open_area
        : exposed_area(sums[m].area, sums[m].rest_area, glued[m]);
}

// its pressure and, with the solutes kept, its osmotic potential (dPi/dW = -Pi/W by Eq. W1)
double CellWater::potential_stiffness(int m) const
{
  const CellSum &s = sums[m];
  double k = s.stiffness / (s.nfluid * s.nfluid);
  if (settings.solute && s.mass > 0.0) k -= pinow[m] / s.mass;
  return k;
}

// the whole wall unless exchange yes: its exposed part (Eq. W4); Eq. 10 linearised in the step's
// own effect on the pressure (osmotic_mass_step), or a set flux spread evenly
double CellWater::outside_mass_step(int m, const PairCellSPH *sph, int type, double rho,
                                    double mass, double dt) const
{
  const CellSum &s = sums[m];
  if (settings.external == WaterSettings::EXT_FLUX)
    return -settings.ext_value * exposed[m] * dt / s.nfluid;
  if (!(lp[m] > 0.0)) return 0.0;
  const double P = sph->pressure(type, rho);
  const double k = osmotic_coefficient(exposed[m], lp[m], rho, s.nfluid);
  double dPdrho = sph->dpressure_drho(type, rho);
  // kept solutes: the step's uptake dm on each of the N_f particles also raises Pi by
  // -Pi N_f dm / W (Eq. W1), a stiffness that adds to the pressure's
  if (settings.solute && s.mass > 0.0) dPdrho -= pinow[m] * s.nfluid / s.mass * mass / rho;
  return osmotic_mass_step(k, dt, P, pinow[m] - settings.ext_value, dPdrho, rho, mass);
}

}    // namespace CellMech
