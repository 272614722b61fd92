/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the cell wall as an incompressible Neo-Hookean membrane,
   one constant-strain element per wall triangle (Eqs. M1, M2), with
   damping along the triangle's edges (Eq. 11) and optional failure above
   a critical principal stretch.
------------------------------------------------------------------------- */

#ifdef ANGLE_CLASS
// clang-format off
AngleStyle(cell/membrane,AngleCellMembrane);
// clang-format on
#else

#ifndef LMP_ANGLE_CELL_MEMBRANE_H
#define LMP_ANGLE_CELL_MEMBRANE_H

#include "angle.h"

#include <array>
#include <vector>

namespace CellPhysics {
struct MembraneRest;
struct MembraneStrain;
}    // namespace CellPhysics

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

  // forces of the element of triangle ia-ib-ic (local or ghost atoms) on its three nodes, the
  // elastic ones (Eq. M2) and the edge damping, as compute() applies them (for observables such
  // as the equatorial force of compute cell/props); false if the triangle has no rest area
  bool triangle_forces(int type, int ia, int ib, int ic, double f[3][3]);

 protected:
  double *G, *t0, *gamma, *lamf;
  double *wrinkle;    // 0: full sheet (Eq. M1); 1 + r: tension-field theory (M3, M4: residual r)
  double residual(int type) const { return wrinkle[type] > 0.0 ? wrinkle[type] - 1.0 : 0.0; }
  int iref;    // index of the reference-position array d2_cellref in atom->darray
  // the bookkeeping of failures (fix CELL_TETHER_BREAK) when some angle type has a critical
  // stretch lamf, else null
  class FixCellTetherBreak *breaker;

  bool shape(int ia, int ib, int ic, CellPhysics::MembraneRest &, CellPhysics::MembraneStrain &,
             double a[3], double c[3]) const;
  bool rest_shape(int ia, int ib, int ic, CellPhysics::MembraneRest &) const;
  void strain(const CellPhysics::MembraneRest &, int ia, int ib, int ic,
              CellPhysics::MembraneStrain &, double a[3], double c[3]) const;
  // per entry of neighbor->anglelist since its last build (rest_build, its timestep): the rest
  // shape of its triangle, D^-1 (upper triangular) and area; area 0: none. The reference
  // positions do not change, so it is found once per build, not each step (membrane_rest costs
  // three square roots and three divisions: 12% of the full cell's step)
  struct RestShape {
    double d00, d01, d11, area;
  };
  bigint rest_build = -1;
  std::vector<RestShape> rests;
  void rest_shapes();
  bool cached_shape(int n, int ia, int ib, int ic, CellPhysics::MembraneRest &,
                    CellPhysics::MembraneStrain &, double a[3], double c[3]) const;
  void add_damping(int type, const int node[3], double *fn[3]);
  void allocate();
  void degenerate(int, int, int, double);
};

}    // namespace LAMMPS_NS

#endif
#endif
