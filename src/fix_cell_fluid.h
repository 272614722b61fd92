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
#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixCellFluid : public Fix {
 public:
  FixCellFluid(class LAMMPS *, int, char **);
  ~FixCellFluid() override;
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
  double Pi, Lp;    // of every cell without a per-cell setting
  std::map<LAMMPS_NS::tagint, std::pair<double, double>> percell;    // molecule ID -> (Pi, Lp)
  int solute;          // 1: Pi W of each cell stays Pi0 W0 (Eq. W1)
  int exchange;        // 1: water crosses the glued walls between cells (Eq. W3)
  int external;        // EXT_PSI: exposed walls exchange with psi_ext; EXT_FLUX: lose a set flux
  double ext_value;    // psi_ext or the flux per area
  int expose;          // with exchange: EXPOSE_OUTSIDE (neither glued nor faced) or EXPOSE_UNGLUED
  double expose_depth;    // EXPOSE_OUTSIDE: how far in front another cell's wall hides a triangle
  double dt;              // step of the level where the SPH forces are
  int ilevel_respa;
  int ncells;    // number of cells, in slots 1..ncells of cells
  CellMech::CellIndex cells;
  double *area, *nfluid;            // per cell, current wall area and fluid count
  double *nbroken;                  // per cell, broken tethers: its wall is open
  double *flux_local, *flux_all;    // per cell, mass added by osmosis since the fix was defined
  std::map<LAMMPS_NS::tagint, double> flux_restart;    // by molecule ID, from a restart file
  int flux_stale;
  class PairCellSPH *sph;
  // per cell (slots), the same on every rank: Pi0 and Lp of the cell, the water W0 when the fix
  // started (Eq. W1), and this step's water, osmotic and water potentials, exposed and glued area
  std::vector<double> pi0, lp, water0, water, pinow, psi, exposed, glued;
  std::vector<double> open_area;    // per cell (slots): area of its triangles that face the outside
  std::vector<double> aref, sump, sumstiff, sumrho;    // rest wall area, sums over the fluid
  // per entry of neighbor->anglelist since the last build: the cell slot of the triangle and its
  // rest area (cell_geometry); the timestep of the build they were found for
  bigint tri_build = -1;
  std::vector<int> tri_slot;
  std::vector<double> tri_aref;
  std::vector<char> tri_open;        // EXPOSE_OUTSIDE: the triangle faces the outside
  std::vector<double> node_glued;    // per local and ghost atom: its intact lamella bonds
  std::map<LAMMPS_NS::tagint, double> water0_restart;
  int iref, ialam;    // d2_cellref and d_alam

  int parse_keyword(int, char **);
  int parse_one(int, char **);
  void index_cells();
  void check_group();
  void cell_geometry();
  void find_open_triangles();
  void check_walls();
  void cell_water();
  void glued_pairs(std::vector<double> &);
  double potential_stiffness(int) const;
  bool active() const;
  std::vector<double> pairs;    // this step's glued pairs: slot a, slot b, glued rest area
  std::map<std::string, std::string> given;    // fix command: keyword -> its words, once each
  bool in_command = true;                      // parsing the fix command (not fix_modify)
  bool depth_given = false;                    // exposed outside D given (no default in units lj)
};

}    // namespace LAMMPS_NS

#endif
#endif
