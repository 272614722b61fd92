/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the water potentials of each cell for fix cell/fluid, from
   its settings (cell_water_settings.h) and this step's sums
   (cell_sums.h): the osmotic potential with the solutes kept (Eq. W1),
   the water potential psi = mean P + Pi (W2), the glued and the exposed
   wall area, and the water a fluid particle takes up from the outside
   through the exposed wall (Eq. 10, W4).
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_WATER_H
#define CELLMECH_CELL_WATER_H

#include <vector>

namespace LAMMPS_NS {
class PairCellSPH;
}

namespace CellMech {

class CellIndex;
class CellSums;
class WaterSettings;
struct GluedPair;

class CellWater {
 public:
  // water0: W0 of Eq. W1 per slot (cell_uptake.h)
  CellWater(const WaterSettings &settings, const CellSums &sums,
            const std::vector<double> &water0) :
      settings(settings),
      sums(sums), water0(water0)
  {
  }
  // zeroed values for the slots 0..ncells
  void resize(int ncells);
  // this step's values of every cell, the same on every rank
  void update(const CellIndex &, const std::vector<GluedPair> &pairs);
  // dpsi/dM of cell m, for the linearised exchange step
  double potential_stiffness(int m) const;
  // the pressure of cell m that its water potential holds (share particle: the particles' mean;
  // share volume: their volume-weighted mean)
  double pressure(int m) const;
  // cell m's water flux over the share its fluid particle of this mass and density takes: N_f
  // (share particle), or V_f / V_i (share volume)
  double shares(int m, double mass, double rho) const;
  // mass a fluid particle of cell m (of a type, density and mass, its shares() n) takes up from
  // the outside in a step dt
  double outside_mass_step(int m, const LAMMPS_NS::PairCellSPH *, int type, double rho, double mass,
                           double n, double dt) const;

  // per cell (slots), the same on every rank: Pi0 and Lp of the cell, and this step's osmotic
  // and water potentials, exposed and glued area
  std::vector<double> pi0, lp, pinow, psi, exposed, glued;

 private:
  const WaterSettings &settings;
  const CellSums &sums;
  const std::vector<double> &water0;
};

}    // namespace CellMech

#endif
