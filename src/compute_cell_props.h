/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: per-cell observables (one row per molecule ID): volume, wall
   area, fluid pressure and mass, tether stretch, equatorial force (Eq. 23),
   fluid count and fluid outside its own wall (leaks), broken tethers, and
   in a tissue its middle lamella: bonds and area glued and debonded.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(cell/props,ComputeCellProps);
// clang-format on
#else

#ifndef LMP_COMPUTE_CELL_PROPS_H
#define LMP_COMPUTE_CELL_PROPS_H

#include "cell_index.h"
#include "cell_sums.h"
#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeCellProps : public Compute {
 public:
  enum {
    VOLUME,
    AREA,
    PRESSURE,
    MASS,
    NFLUID,
    LAM_MEAN,
    LAM_MAX,
    FEQ,
    NLEAK,
    XC,
    YC,
    ZC,
    NBROKEN,
    NLAMELLA,
    GLUED_AREA,
    NDEBONDED,
    DEBONDED_AREA,
    MOLECULE,
    NCOL
  };

  ComputeCellProps(class LAMMPS *, int, char **);
  ~ComputeCellProps() override;
  void init() override;
  void compute_array() override;
  int lock_length() override;

  // centre of the cell in each slot 1..N of cells (mean of its unwrapped wall nodes) into
  // c[3m..3m+2], the same on every rank; shared with compute cell/contacts
  static void wall_centres(class LAMMPS *, const CellMech::CellIndex &cells,
                           const class PairCellSPH *, std::vector<double> &c);

 protected:
  double normal[3];
  int leaks;    // 1: count fluid outside its wall (O(N_fluid x N_triangles) per call)
  int ncells;
  CellMech::CellIndex cells;    // row m is the cell in slot m (ascending molecule IDs)
  class PairCellSPH *sph;
  class BondCellTether *tether;
  class AngleCellMembrane *membrane;    // the wall's membrane elements, if they carry its forces
  int ialam;                            // per-atom lamella area d_alam (tissue), -1 without one
  int iref;                             // per-atom reference positions d2_cellref (rest lengths)

  CellMech::CellSums sums;    // this call's, per slot

  void allocate(int);
  void relative(int i, int m, const std::vector<double> &c, double *out) const;
  void add_triangles(const std::vector<double> &c);
  void add_bonds(const std::vector<double> &c, std::vector<double> &lmax);
  void fill_row(int m, const CellMech::CellSum &, double lmax, const std::vector<double> &c);
  void add_debonded(class Fix *);
  void count_leaks(const std::vector<double> &);
};

}    // namespace LAMMPS_NS

#endif
#endif
