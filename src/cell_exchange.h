/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: water exchanged between glued cells through their shared
   wall for fix cell/fluid (exchange yes): k (psi_a - psi_b) with
   psi = P + Pi (Eqs. W2-W3), one mass per pair added to one cell and taken
   from the other, so that the exchange conserves mass to round-off.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_EXCHANGE_H
#define CELLMECH_CELL_EXCHANGE_H

#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace CellMech {

class CellIndex;
class CellSums;
class CellWater;

// two cells glued by intact lamella bonds: their slots a < b and the bonds' rest area
struct GluedPair {
  int a, b;
  double area;
};

class CellExchange {
 public:
  // Collective: this step's glued pairs from the bond list of every rank, in ascending order of
  // (a, b), the same list on every rank, so that every rank computes the same exchange.
  // alam: the per-atom lamella area d_alam.
  void find_pairs(LAMMPS_NS::LAMMPS *, const CellIndex &, const double *alam);
  void clear() { glued.clear(); }
  const std::vector<GluedPair> &pairs() const { return glued; }
  // adds to uptake[m] the mass each cell m takes from its neighbours in a step dt
  void add_uptake(const CellSums &, const CellWater &, double dt,
                  std::vector<double> &uptake) const;

 private:
  std::vector<GluedPair> glued;
};

}    // namespace CellMech

#endif
