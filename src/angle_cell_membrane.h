/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the cell wall as an incompressible Neo-Hookean membrane,
   one constant-strain element per wall triangle (Eqs. M1, M2), with
   damping along the triangle's edges (Eq. 11).
------------------------------------------------------------------------- */

#ifdef ANGLE_CLASS
// clang-format off
AngleStyle(cell/membrane,AngleCellMembrane);
// clang-format on
#else

#ifndef LMP_ANGLE_CELL_MEMBRANE_H
#define LMP_ANGLE_CELL_MEMBRANE_H

#include "angle.h"

namespace LAMMPS_NS {

class AngleCellMembrane : public Angle {
 public:
  AngleCellMembrane(class LAMMPS *);
  ~AngleCellMembrane() override;
  void compute(int, int) override;
  void coeff(int, char **) override;
  void init_style() override;
  double equilibrium_angle(int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_data(FILE *) override;
  double single(int, int, int, int) override;
  void *extract(const char *, int &) override;

 protected:
  double *G, *t0, *gamma;
  int iref;    // index of the reference-position array d2_cellref in atom->darray

  void allocate();
  void degenerate(int, int, int, double);
};

}    // namespace LAMMPS_NS

#endif
#endif
