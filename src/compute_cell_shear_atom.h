/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: per-particle protoplasm shear stress (paper Eqs. 24-26).
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(cell/shear/atom,ComputeCellShearAtom);
// clang-format on
#else

#ifndef LMP_COMPUTE_CELL_SHEAR_ATOM_H
#define LMP_COMPUTE_CELL_SHEAR_ATOM_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeCellShearAtom : public Compute {
 public:
  ComputeCellShearAtom(class LAMMPS *, int, char **);
  ~ComputeCellShearAtom() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void compute_peratom() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

 private:
  int nmax;
  double **tau;    // per atom: |tau|, tau_xy, tau_xz, tau_yz
  class NeighList *list;
  class PairCellSPH *sph;
};

}    // namespace LAMMPS_NS

#endif
#endif
