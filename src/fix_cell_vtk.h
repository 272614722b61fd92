/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the cell walls as triangulated surfaces for ParaView (legacy
   VTK PolyData), one file every N steps.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(cell/vtk,FixCellVTK);
// clang-format on
#else

#ifndef LMP_FIX_CELL_VTK_H
#define LMP_FIX_CELL_VTK_H

#include "fix.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixCellVTK : public Fix {
 public:
  FixCellVTK(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;

 private:
  std::string prefix;
  int iref;    // reference positions d2_cellref

  void write();
  std::vector<double> local_points();
  std::vector<double> local_triangles();
};

}    // namespace LAMMPS_NS

#endif
#endif
