/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: bending stiffness of the cell wall, one discrete-shells hinge
   per pair of wall triangles sharing an edge (Eqs. B1-B3).
------------------------------------------------------------------------- */

#ifdef DIHEDRAL_CLASS
// clang-format off
DihedralStyle(cell/bending,DihedralCellBending);
// clang-format on
#else

#ifndef LMP_DIHEDRAL_CELL_BENDING_H
#define LMP_DIHEDRAL_CELL_BENDING_H

#include "dihedral.h"

namespace LAMMPS_NS {

class DihedralCellBending : public Dihedral {
 public:
  DihedralCellBending(class LAMMPS *);
  ~DihedralCellBending() override;
  void compute(int, int) override;
  void coeff(int, char **) override;
  void init_style() override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_data(FILE *) override;
  // LAMMPS's Dihedral has no single(); this one gives one hinge's energy (Eq. B2) by local indices
  double single(int type, int i1, int i2, int i3, int i4);
  // no 'override': Dihedral::extract() is virtual in LAMMPS 4 Jul 2026 (this overrides it) but
  // absent in 4 Feb 2025 (a plain member there)
  void *extract(const char *, int &);

 protected:
  double *G, *t0;
  int iref;    // index of the reference-position array d2_cellref in atom->darray

  void allocate();
};

}    // namespace LAMMPS_NS

#endif
#endif
