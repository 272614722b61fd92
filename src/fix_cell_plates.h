/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the plates of the compression experiments (Eq. 21): LAMMPS's
   fix wall/harmonic, whose force and energy read under run_style respa on
   an inner level are the mean over the inner steps of one outer step, and
   which sums the work each moving wall has done.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(cell/plates,FixCellPlates);
// clang-format on
#else

#ifndef LMP_FIX_CELL_PLATES_H
#define LMP_FIX_CELL_PLATES_H

#include "fix_wall_harmonic.h"

namespace LAMMPS_NS {

class FixCellPlates : public FixWallHarmonic {
 public:
  FixCellPlates(class LAMMPS *, int, char **);
  void post_force(int) override;
  void post_force_respa(int, int, int) override;
  double compute_vector(int) override;

 protected:
  double esum[7];    // energy and force on each wall, summed over this outer step's inner steps
  int nsum;          // inner steps summed
  // the work each wall has done on this rank's atoms since the fix was defined, and the
  // coordinate of its last step
  double work[6], lastcoord[6];
  void add_work(int m, double coord);
};

}    // namespace LAMMPS_NS

#endif
#endif
