/* -*- c++ -*- ----------------------------------------------------------
   cellmech: the per-atom fields of fix property/atom that several styles
   read (names without the d_ / d2_ prefix), and what is derived from them.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_FIELDS_H
#define CELLMECH_CELL_FIELDS_H

#include <cmath>

namespace CellMech {

constexpr char REF_FIELD[] = "cellref";    // d2_cellref: rest (reference) position of a wall node
constexpr char AREA_FIELD[] = "alam";      // d_alam: a node's area share of its lamella bonds

// Rest length of the bond i-j (tether or lamella): the distance of the nodes' reference positions.
inline double rest_length(double *const *ref, int i, int j)
{
  const double dx = ref[i][0] - ref[j][0];
  const double dy = ref[i][1] - ref[j][1];
  const double dz = ref[i][2] - ref[j][2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// Area a lamella bond i-j stands for: the mean of its two nodes' shares (cellgen.py tissue).
inline double lamella_area(const double *alam, int i, int j)
{
  return 0.5 * (alam[i] + alam[j]);
}

}    // namespace CellMech

#endif
