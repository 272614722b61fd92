/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: integrates the density and mass of the protoplasm particles:
   continuity (from pair cell/sph) plus osmotic exchange through the cell
   wall (Eqs. 9-10), per cell (molecule ID).
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(cell/fluid,FixCellFluid);
// clang-format on
#else

#ifndef LMP_FIX_CELL_FLUID_H
#define LMP_FIX_CELL_FLUID_H

#include "cell_index.h"
#include "fix.h"

#include <map>

namespace LAMMPS_NS {

class FixCellFluid : public Fix {
 public:
  FixCellFluid(class LAMMPS *, int, char **);
  ~FixCellFluid() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void pre_force_respa(int, int, int) override;
  int modify_param(int, char **) override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  double Pi, Lp;
  double dt;    // step of the level where the SPH forces are
  int ilevel_respa;
  int ncells;                       // number of cells, in slots 1..ncells of cells
  CellMech::CellIndex cells;
  double *area, *nfluid;            // per cell, current wall area and fluid count
  double *nbroken;                  // per cell, broken tethers: its wall is open
  double *flux_local, *flux_all;    // per cell, mass added by osmosis since the fix was defined
  std::map<LAMMPS_NS::tagint, double> flux_restart;    // by molecule ID, from a restart file
  int flux_stale;
  class PairCellSPH *sph;

  void index_cells();
  void check_group();
  void cell_geometry();
};

}    // namespace LAMMPS_NS

#endif
#endif
