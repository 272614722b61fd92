/* -*- c++ -*- ----------------------------------------------------------
   cellmech: per-cell observables (one row per molecule ID): volume, wall
   area, fluid pressure and mass, tether stretch, equatorial force (Eq. 23),
   fluid count and fluid outside its own wall (leaks).
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(cell/props,ComputeCellProps);
// clang-format on
#else

#ifndef LMP_COMPUTE_CELL_PROPS_H
#define LMP_COMPUTE_CELL_PROPS_H

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
    NCOL
  };

  ComputeCellProps(class LAMMPS *, int, char **);
  ~ComputeCellProps() override;
  void init() override;
  void compute_array() override;

 protected:
  double normal[3];
  int leaks;    // 1: count fluid outside its wall (O(N_fluid x N_triangles) per call)
  int ncells;
  class PairCellSPH *sph;
  class BondCellTether *tether;

  void allocate(int);
  void centres(std::vector<double> &);
  void count_leaks(const std::vector<double> &);
};

}    // namespace LAMMPS_NS

#endif
#endif
