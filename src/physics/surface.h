/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_surface.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: triangulated closed surfaces: triangle areas, enclosed volumes, solid angles,
   distances.
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_SURFACE_H
#define CELLMECH_PHYSICS_SURFACE_H

#include "vec3.h"

#include <array>
#include <cmath>

namespace CellPhysics {

/* ---------------------------------------------------------------------
   Triangulated closed surfaces
------------------------------------------------------------------------ */

// Area of the triangle spanned by edge vectors u and w from one vertex.
inline double triangle_area(const double *u, const double *w)
{
  const std::array<double, 3> c = cross(u, w);
  return 0.5 * std::sqrt(dot(c, c));
}

// Signed volume of the cone from the origin over the triangle (a, a + u, a + w): a . (u x w) / 6.
// Summed over a closed mesh whose triangles are in right-hand order seen from outside (outward
// normals, the contract of cell_fields.h) it is the enclosed volume (divergence theorem).
inline double cone_volume(const double *a, const double *u, const double *w)
{
  return dot(a, cross(u, w)) / 6.0;
}

// Signed solid angle of triangle (a, b, c) seen from the origin (van Oosterom & Strackee 1983).
// Summed over a closed outward-oriented mesh it is 4 pi for a point inside, 0 outside.
inline double solid_angle(const double *a, const double *b, const double *c)
{
  const double la = std::sqrt(dot(a, a));
  const double lb = std::sqrt(dot(b, b));
  const double lc = std::sqrt(dot(c, c));
  const double num = dot(a, cross(b, c));
  const double ab = dot(a, b);
  const double ac = dot(a, c);
  const double bc = dot(b, c);
  const double den = la * lb * lc + ab * lc + ac * lb + bc * la;
  return 2.0 * std::atan2(num, den);
}

// Squared distance from the origin to triangle (a, b, c): the closest point by Voronoi regions of
// the vertices, edges and face (Ericson, Real-Time Collision Detection, 5.1.5).
inline double origin_triangle_dist_sq(const double *a, const double *b, const double *c)
{
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double ap[3] = {-a[0], -a[1], -a[2]};
  const double bp[3] = {-b[0], -b[1], -b[2]};
  const double cp[3] = {-c[0], -c[1], -c[2]};
  double q[3];
  auto at = [&](double u, double v) {    // a + u ab + v ac
    for (int d = 0; d < 3; d++) q[d] = a[d] + u * ab[d] + v * ac[d];
    return dot(q, q);
  };
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return dot(a, a);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return dot(b, b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return at(d1 / (d1 - d3), 0.0);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return dot(c, c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return at(0.0, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return at(1.0 - w, w);
  }
  const double den = 1.0 / (va + vb + vc);
  return at(vb * den, vc * den);
}

}    // namespace CellPhysics

#endif
