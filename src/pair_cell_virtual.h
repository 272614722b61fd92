/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: virtual wall particles (paper Sec. II C): one massless particle
   at the barycentre of each wall triangle repels the fluid with the 8-4
   law of pair cell/lj84 (whose coefficients it shares), and optionally
   holds the fluid of its own cell (adhere); its reaction is shared by the
   triangle's three nodes.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(cell/virtual,PairCellVirtual);
// clang-format on
#else

#ifndef LMP_PAIR_CELL_VIRTUAL_H
#define LMP_PAIR_CELL_VIRTUAL_H

#include "cell_near_list.h"
#include "pair_cell_lj84.h"

#include <vector>

namespace LAMMPS_NS {

class PairCellVirtual : public PairCellLJ84 {
 public:
  PairCellVirtual(class LAMMPS *);
  ~PairCellVirtual() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  double memory_usage() override;
  // some fluid type adheres to its own cell's wall (after init)
  bool adheres() const { return adhering; }

 protected:
  double reach;    // bound on |barycentre - central node| of a triangle
  // the adhesion of a fluid type to its own cell's wall type (Eq. A1): strength and range, 0 if
  // none; adhering: some type pair has Fa > 0
  double **fa, **delta;
  bool adhering;
  void allocate() override;
  std::vector<double **> extra_coeffs() override { return {fa, delta}; }
  // types with a cell/virtual coefficient: under pair_style hybrid the neighbour list skips the
  // others, so a central node of such a type has no list to walk
  std::vector<char> listed;
  // r0 must be at least this fraction of the wall's mean triangle edge (check_contact_distance)
  static constexpr double MIN_R0_EDGE = 0.5;
  void check_contact_distance();
  // the fluid near each triangle, found at each neighbour-list build (find_near)
  CellMech::NearList near;
  void find_near();
  void barycentre(int a, int b, int c, double *B) const;
  void repel_fluid(int n, int a, int b, int c, int eflag);
  void hold_fluid(int a, int b, int c, int eflag);
  void tally_contact(int k, int a, int b, int c, const double *del, double fpair, double e,
                     int eflag);
  void check_reach(int a, int b, int c, const double *B);
};

}    // namespace LAMMPS_NS

#endif
#endif
