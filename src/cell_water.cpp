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
    psi[m] = pressure(m) + pinow[m];
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

// the cell's pressure: the mean of its particles', or with share volume their volume-weighted
// mean, which the volume-shared flux keeps uniform
double CellWater::pressure(int m) const
{
  const CellSum &s = sums[m];
  if (s.nfluid == 0) return 0.0;
  if (settings.share_volume()) return s.volume_pressure / s.fluid_volume;
  return s.pressure / s.nfluid;
}

// the cell's flux over the share fluid particle (mass, rho) takes: N_f (Eq. 10), or V_f / V_i
// (Eq. W5). A divisor, so that share particle computes what Eq. 10 did before share volume, to
// the bit.
double CellWater::shares(int m, double mass, double rho) const
{
  const CellSum &s = sums[m];
  return settings.share_volume() ? 1.0 / volume_share(mass, rho, s.fluid_volume) : s.nfluid;
}

// its pressure and, with the solutes kept, its osmotic potential (dPi/dW = -Pi/W by Eq. W1), as
// the cell's water changes by dM spread by shares()
double CellWater::potential_stiffness(int m) const
{
  const CellSum &s = sums[m];
  // share volume: dm_i = dM V_i / V raises P_i by dP/drho dM / V (Eq. 9 at fixed V_i); their
  // volume-weighted mean by sum(dP_i/drho V_i) / V^2
  double k = settings.share_volume() ? s.volume_stiffness / (s.fluid_volume * s.fluid_volume)
                                     : s.stiffness / (s.nfluid * s.nfluid);
  if (settings.solute && s.mass > 0.0) k -= pinow[m] / s.mass;
  return k;
}

// the whole wall unless exchange yes: its exposed part (Eq. W4); Eq. 10 linearised in the step's
// own effect on the pressure (osmotic_mass_step), or a set flux spread evenly
double CellWater::outside_mass_step(int m, const PairCellSPH *sph, int type, double rho,
                                    double mass, double n, double dt) const
{
  const CellSum &s = sums[m];
  if (settings.external == WaterSettings::EXT_FLUX)
    return -settings.ext_value * exposed[m] * dt / n;
  if (!(lp[m] > 0.0)) return 0.0;
  const double P = sph->pressure(type, rho);
  // A_c L_p rho / N_f (Eq. 10), or A_c L_p rho V_i / V_f (Eq. W5)
  const double k = osmotic_coefficient(exposed[m], lp[m], rho, n);
  double dPdrho = sph->dpressure_drho(type, rho);
  // kept solutes: the step's uptake dm = dW / n also raises Pi by -Pi n dm / W (Eq. W1), a
  // stiffness that adds to the pressure's
  if (settings.solute && s.mass > 0.0) dPdrho -= pinow[m] * n / s.mass * mass / rho;
  return osmotic_mass_step(k, dt, P, pinow[m] - settings.ext_value, dPdrho, rho, mass);
}

}    // namespace CellMech
