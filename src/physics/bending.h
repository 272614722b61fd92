/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_bending.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: the bending of the wall, discrete-shells hinges (Eqs. B1-B3).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_BENDING_H
#define CELLMECH_PHYSICS_BENDING_H

#include "vec3.h"

#include <array>
#include <cmath>

namespace CellPhysics {

/* ---------------------------------------------------------------------
   Bending of the wall (dihedral style cell/bending), the package's own
   Eqs. B1-B3 (docs/dihedral_cell_bending.rst). A hinge is a LAMMPS dihedral
   i-j-k-l: two wall triangles (i, j, k) and (j, k, l) sharing the edge j-k.
   The wall is a plate of bending stiffness
     D = E t0^3 / (12 (1 - nu^2)) = G t0^3 / 3,  E = 3G, nu = 1/2     (Eq. B1)
   and each hinge stores the discrete-shells energy (Grinspun et al. 2003)
     W = (D / 2) (phi - phi0)^2 |e0|^2 / A0                            (Eq. B2)
   with phi the dihedral angle, phi0 its rest value from the reference
   positions, |e0| the rest length of the shared edge and A0 the rest area
   of both triangles together. The forces are its exact gradient,
     f_a = -D (phi - phi0) |e0|^2 / A0  dphi/dx_a                     (Eq. B3)
   with the dihedral-angle derivatives of Blondel & Karplus (J. Comput.
   Chem. 17, 1132 (1996)).
   Why the prefactor is D / 2: on a mesh of equilateral triangles of side h
   whose nodes move onto a smooth surface, a hinge's angle changes by
     phi - phi0 = h (3 kn - kt) / (2 sqrt3)
   (its four nodes on the quadratic surface; kn, kt the changes of normal
   curvature across and along its edge), |e0|^2 / A0 = 2 / sqrt3, and there
   are 2 sqrt3 / h^2 edges per area in three directions 60 degrees apart.
   Averaged over them, the energy k (phi - phi0)^2 |e0|^2 / A0 tends to the density
     k [(k1 + k2)^2 - (8/3) k1 k2]       (k1, k2 principal changes)
   (3 |e|^2 / A on a sphere gives the Willmore density (k1 + k2)^2, as
   Wardetzky et al. 2007 state), against the plate's (D / 2) [(k1 + k2)^2 -
   2 (1 - nu) k1 k2]. k = D / 2 makes the two equal for every bending
   without Gaussian curvature (a plate bent onto a cylinder of radius R
   stores D / (2 R^2) per area, whatever the mesh orientation) and in the
   mean-curvature term of any bending. The Gaussian term is that of nu =
   -1/3, not 1/2; no single hinge constant matches both: an equal change of
   both curvatures (a sphere's) stores 4/9 of the nu = 1/2 plate's energy.
------------------------------------------------------------------------ */

// Bending stiffness of the wall (Eq. B1).
inline double bending_stiffness(double G, double t0)
{
  return G * t0 * t0 * t0 / 3.0;
}

// Dihedral angle phi in (-pi, pi] of the hinge with edge vectors b1 = x_i - x_j, b2 = x_k - x_j
// (the shared edge) and b3 = x_l - x_k (LAMMPS's vb1, vb2, vb3), pi for a flat hinge; with grad
// non-null also dphi/dx for the four nodes i, j, k, l. Returns false for a hinge whose triangles
// have no area (collinear nodes): the angle is then undefined and its derivative infinite.
inline bool hinge_angle(const double b1[3], const double b2[3], const double b3[3], double &phi,
                        double grad[4][3] = nullptr)
{
  // F = x_i - x_j, G = x_j - x_k, H = x_l - x_k; A = F x G, B = H x G the triangles' normals
  const double g[3] = {-b2[0], -b2[1], -b2[2]};
  const std::array<double, 3> A = cross(b1, g), B = cross(b3, g);
  const double a2 = dot(A, A);
  const double b2n = dot(B, B);
  const double g2 = dot(g, g);
  const double f2 = dot(b1, b1);
  const double h2 = dot(b3, b3);
  // relative to the edge lengths, so that the test does not depend on the units
  if (!(g2 > 0.0) || !(a2 > 1e-24 * f2 * g2) || !(b2n > 1e-24 * h2 * g2)) return false;
  const double gn = std::sqrt(g2);
  const double y = dot(cross(B, A), g) / gn;
  const double x = dot(A, B);
  phi = std::atan2(y, x);
  if (grad) {
    const double fg = dot(b1, g) / (a2 * gn);
    const double hg = dot(b3, g) / (b2n * gn);
    for (int d = 0; d < 3; d++) {
      grad[0][d] = -gn / a2 * A[d];
      grad[3][d] = gn / b2n * B[d];
      grad[1][d] = gn / a2 * A[d] + fg * A[d] - hg * B[d];
      grad[2][d] = -(grad[0][d] + grad[1][d] + grad[3][d]);
    }
  }
  return true;
}

// Rest state of a hinge: its rest dihedral angle and the weight |e0|^2 / A0 of Eq. B2, from the
// reference edge vectors (as hinge_angle). Returns false for a reference hinge without area.
struct HingeRest {
  double phi0;
  double weight;
};

inline bool hinge_rest(const double B1[3], const double B2[3], const double B3[3], HingeRest &rest)
{
  if (!hinge_angle(B1, B2, B3, rest.phi0)) return false;
  // the triangles' areas: |B1 x B2| / 2 and |B2 x B3| / 2
  const std::array<double, 3> n1 = cross(B1, B2), n2 = cross(B2, B3);
  const double area = 0.5 * (std::sqrt(dot(n1, n1)) + std::sqrt(dot(n2, n2)));
  rest.weight = dot(B2, B2) / area;
  return true;
}

// phi - phi0 wrapped into (-pi, pi]: a hinge passing through its fully folded state (phi = 0 for
// a flat rest shape) keeps an energy continuous in the positions.
inline double hinge_deviation(double phi, double phi0)
{
  constexpr double PI = 3.14159265358979323846;
  double dphi = phi - phi0;
  if (dphi > PI)
    dphi -= 2.0 * PI;
  else if (dphi <= -PI)
    dphi += 2.0 * PI;
  return dphi;
}

// Energy of a hinge (Eq. B2) with bending stiffness D (Eq. B1).
inline double hinge_energy(double D, const HingeRest &rest, double phi)
{
  const double dphi = hinge_deviation(phi, rest.phi0);
  return 0.5 * D * rest.weight * dphi * dphi;
}

// Forces on the hinge's nodes i, j, k, l (Eq. B3) from the angle's gradient (hinge_angle).
inline void hinge_forces(double D, const HingeRest &rest, double phi, const double grad[4][3],
                         double f[4][3])
{
  const double c = -D * rest.weight * hinge_deviation(phi, rest.phi0);
  for (int a = 0; a < 4; a++)
    for (int d = 0; d < 3; d++) f[a][d] = c * grad[a][d];
}

}    // namespace CellPhysics

#endif
