/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the vector algebra of the laws in src/physics/ (dot and cross
   products of 3-vectors given as pointers, arrays or std::array), each
   product in the one order of its terms that the laws were written with.
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_VEC3_H
#define CELLMECH_PHYSICS_VEC3_H

#include <array>

namespace CellPhysics {

// u . w, summed from the first component
template <class U, class W> inline double dot(const U &u, const W &w)
{
  return u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
}

// u x w
template <class U, class W> inline std::array<double, 3> cross(const U &u, const W &w)
{
  return {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
}

}    // namespace CellPhysics

#endif
