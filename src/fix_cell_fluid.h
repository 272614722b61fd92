/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: integrates the density and mass of the protoplasm particles:
   continuity (from pair cell/sph) plus osmotic exchange through the cell
   wall (Eqs. 9-10), per cell (molecule ID).

   The fix is the integrator; its equations live in parts of their own,
   each with one job:
     cell_water_settings.h  its keywords: Pi, Lp, per cell, solutes, outside
     cell_sums.h            the sums per cell (shared with compute cell/props)
     cell_water.h           the potentials per cell (Eqs. W1-W2) and the
                            outside through the exposed wall (Eqs. 10, W4)
     cell_wall_triangles.h  the wall triangles: cell, rest area, outside
     cell_exposed.h         the triangles that face the outside (W4)
     cell_exchange.h        water between glued cells (Eqs. W2-W3)
     cell_uptake.h          each cell's uptake and W0, across runs and
                            restart files

   Separate fixes (solutes, exchange, outside) registering with a
   coordinator, as in LAMMPS's RHEO package (fix rheo/pressure,
   rheo/viscosity and rheo/thermal find fix rheo in init, flag themselves
   to it in setup_pre_force and then each runs its own pre_force, in the
   order of the input script; fix rheo refuses to come after them): not
   recommended now. They would buy nothing users ask for -- the keywords
   already switch each part on and off, and fix_modify changes them
   between runs -- and would cost what one fix gives for free: every part
   reads the same per-cell sums and potentials of one step and adds to one
   mass step per particle, outside then exchange, and conservation of mass
   to round-off and the bit-identical results depend on that order. If a
   need appears (another outside boundary, a solute model to swap), this
   fix should stay the coordinator and call the registered parts itself,
   each adding its per-cell uptake through one call as
   CellExchange::add_uptake does now, rather than let each part run its
   own pre_force as RHEO's do: then the coordinator, not the order of the
   input script, fixes the order of the terms, and it keeps the sums, the
   step and the restart record in one place.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(cell/fluid,FixCellFluid);
// clang-format on
#else

#ifndef LMP_FIX_CELL_FLUID_H
#define LMP_FIX_CELL_FLUID_H

#include "cell_exchange.h"
#include "cell_index.h"
#include "cell_sums.h"
#include "cell_uptake.h"
#include "cell_wall_triangles.h"
#include "cell_water.h"
#include "cell_water_settings.h"
#include "fix.h"

#include <vector>

namespace LAMMPS_NS {

class FixCellFluid : public Fix {
 public:
  FixCellFluid(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void setup_pre_force_respa(int, int) override;
  void pre_force(int) override;
  void pre_force_respa(int, int, int) override;
  int modify_param(int, char **) override;
  double compute_vector(int) override;
  double compute_array(int, int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;

 protected:
  CellMech::WaterSettings settings;
  CellMech::UptakeBooks books;
  CellMech::CellIndex cells;    // slots 1..ncells
  CellMech::CellSums sums;      // this step's, per slot
  CellMech::CellWater water;    // this step's potentials, per slot
  CellMech::CellExchange exchange;
  CellMech::WallTriangles triangles;
  int ncells;
  double dt;    // step of the level where the SPH forces are
  int ilevel_respa;
  class PairCellSPH *sph;
  int iref, ialam;                   // d2_cellref and d_alam
  std::vector<double> node_glued;    // per local and ghost atom: its intact lamella bonds
  bool warned_unheld = false;        // warn_unheld_protoplasm said it (once per fix)
  bool warned_share = false;         // warn_uneven_share said it (once per fix)

  void parse_command(int, char **);
  void find_styles();
  void warn_unheld_protoplasm();
  void warn_uneven_share();
  void check_respa();
  void widen_ghost_cutoff();
  void check_group();
  void check_walls();
  void check_cell_settings();
  void index_cells();
  void measure_cells();
  void find_open_triangles();
  void update_potentials();
  void advance_fluid(bool osmosis, const std::vector<double> &uptake);
};

}    // namespace LAMMPS_NS

#endif
#endif
