/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the sums per cell (slot of a CellIndex) over its wall
   triangles, fluid particles and bonds, taken on each rank and summed
   over all ranks in one reduction. Shared by fix cell/fluid (Eqs. 9-10,
   W1-W4) and compute cell/props (its table): each fills the fields it
   needs and leaves the others 0, so that one reduction serves either.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_SUMS_H
#define CELLMECH_CELL_SUMS_H

#include <mpi.h>

#include <type_traits>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
class PairCellSPH;
}    // namespace LAMMPS_NS

namespace CellMech {

class CellIndex;

struct CellSum {
  // the wall triangles
  double volume = 0.0;       // cones from the cell centre over the triangles (divergence theorem)
  double area = 0.0;         // current wall area A_c (Eq. 10)
  double rest_area = 0.0;    // the same triangles on the rest shape d2_cellref
  double open_area = 0.0;    // of the triangles that face the outside (Eq. W4, exposed outside)
  double feq = 0.0;          // equatorial force across the cell's plane (Eq. 23)
  // the fluid particles of a group
  double nfluid = 0.0;              // N_f
  double mass = 0.0;                // the cell's water W (Eq. W1)
  double pressure = 0.0;            // sum of P_i
  double stiffness = 0.0;           // sum of dP_i/drho rho_i / m_i (see add_fluid)
  double density = 0.0;             // sum of rho_i
  double fluid_volume = 0.0;        // sum of V_i = m_i / rho_i
  double volume_pressure = 0.0;     // sum of P_i V_i
  double volume_stiffness = 0.0;    // sum of dP_i/drho V_i
  // the bonds
  double stretch = 0.0;       // sum of l/l0 over the wall's intact tethers
  double ntethers = 0.0;      // those tethers
  double broken = 0.0;        // broken tethers (wall rupture)
  double nlamella = 0.0;      // intact middle-lamella bonds to other cells
  double glued_area = 0.0;    // their area
};
// reduce() sums them as an array of doubles
static_assert(std::is_standard_layout<CellSum>::value && sizeof(CellSum) == 18 * sizeof(double),
              "CellSum must hold doubles only");

class CellSums {
 public:
  // zeroed sums for the slots 0..ncells; slot 0 collects nothing (atoms of no cell)
  void clear(int ncells) { sums.assign(ncells + 1, CellSum()); }
  int size() const { return (int) sums.size(); }
  CellSum &operator[](int slot) { return sums[slot]; }
  const CellSum &operator[](int slot) const { return sums[slot]; }

  // the fluid particles (types pair cell/sph treats as fluid) of the group among the local atoms
  void add_fluid(LAMMPS_NS::LAMMPS *, const LAMMPS_NS::PairCellSPH *, const CellIndex &,
                 int groupbit);
  // broken tethers from the per-node counts of fix CELL_TETHER_BREAK (FixCellFailure's
  // synced_counts or built_counts; null: none broken)
  void add_broken_tethers(LAMMPS_NS::LAMMPS *, const CellIndex &, const double *nbroken);
  // collective: every rank's sums, the same on every rank
  void reduce(MPI_Comm world);

 private:
  std::vector<CellSum> sums;
};

}    // namespace CellMech

#endif
