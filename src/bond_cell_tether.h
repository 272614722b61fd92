/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: Neo-Hookean tether of the DEM cell wall (Eq. 19) with
   damping along the bond (Eq. 11) and optional critical-stretch failure.
------------------------------------------------------------------------- */

#ifdef BOND_CLASS
// clang-format off
BondStyle(cell/tether,BondCellTether);
// clang-format on
#else

#ifndef LMP_BOND_CELL_TETHER_H
#define LMP_BOND_CELL_TETHER_H

#include "bond.h"

namespace CellMech {
class TetherSweep;
}

namespace LAMMPS_NS {

class BondCellTether : public Bond {
 public:
  BondCellTether(class LAMMPS *);
  ~BondCellTether() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double equilibrium_distance(int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_data(FILE *) override;
  double single(int, double, int, int, double &) override;
  void *extract(const char *, int &) override;

 protected:
  double *G, *t0, *gamma, *lamf;
  int iref;       // index of the reference-position array d2_cellref in atom->darray
  double lmax;    // largest rest length, for the bond-extent check of LAMMPS
  int checked;    // reference positions checked for plausibility in this run
  // the bookkeeping of failures (fix CELL_TETHER_BREAK) when some bond type has a critical
  // stretch lamf, else null
  class FixCellTetherBreak *breaker;
  // the stretch and force factor of every tether in one sweep (cell_tether_sweep.h)
  CellMech::TetherSweep *tethers;

  void add_break_fix();

  void allocate();
  void check_timestep();
  void wrong_reference(int i1, int i2, double lam);
  void break_tether(int n);
};

}    // namespace LAMMPS_NS

#endif
#endif
