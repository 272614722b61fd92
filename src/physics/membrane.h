/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_membrane.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: the membrane wall, the constant-strain Neo-Hookean triangle (Eqs. M1-M3).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_MEMBRANE_H
#define CELLMECH_PHYSICS_MEMBRANE_H

#include "vec3.h"

#include <array>
#include <cmath>

namespace CellPhysics {

/* ---------------------------------------------------------------------
   Membrane wall (angle style cell/membrane): the incompressible thin
   Neo-Hookean sheet that the paper's tethers stand for (Eq. 15), on each
   wall triangle as a constant-strain element. Eqs. M1-M2 are the package's
   own numbering (docs/angle_cell_membrane.rst). The triangle a-b-c has reference edges A = X_a - X_b,
   C = X_c - X_b and current edges a = x_a - x_b, c = x_c - x_b. In an
   orthonormal frame (e1, e2) of the reference plane the reference edges are
   the columns of the 2x2 matrix D; the 3x2 deformation gradient is
   F = [a c] D^-1 and C2 = F^T F its in-plane right Cauchy-Green tensor.
   Incompressibility gives the thickness stretch lam3^2 = 1 / det C2, so
     W = (G t0 A0 / 2) (tr C2 + 1 / det C2 - 3)                    (Eq. M1)
   per triangle of reference area A0 (G the shear modulus, E = 3G).
   Its exact gradient with respect to the current edges is
     dW/d[a c] = G t0 A0 F (I - C2^-1 / det C2) D^-T                 (Eq. M2)
   so that the forces are f_a = -dW/da, f_c = -dW/dc, f_b = -(f_a + f_c):
   they sum to zero, and W depends on F only through C2, so rigid motion
   costs nothing and angular momentum is conserved.
------------------------------------------------------------------------ */

// Reference shape of a triangle: D^-1 (row-major 2x2) and the area A0. Returns false for a
// reference triangle without area (collinear or coincident nodes).
struct MembraneRest {
  double e1[3], e2[3];    // orthonormal frame of the reference plane (diagnostics)
  double Dinv[2][2];
  double area;
};

inline bool membrane_rest(const double A[3], const double C[3], MembraneRest &rest)
{
  const double la = std::sqrt(dot(A, A));
  const std::array<double, 3> n = cross(A, C);
  const double ln = std::sqrt(dot(n, n));
  // relative to the edge lengths, so that the test does not depend on the units
  const double lc = std::sqrt(dot(C, C));
  if (!(la > 0.0) || !(ln > 1e-12 * la * lc)) return false;
  for (int d = 0; d < 3; d++) rest.e1[d] = A[d] / la;
  // e2 = (n / |n|) x e1
  rest.e2[0] = (n[1] * rest.e1[2] - n[2] * rest.e1[1]) / ln;
  rest.e2[1] = (n[2] * rest.e1[0] - n[0] * rest.e1[2]) / ln;
  rest.e2[2] = (n[0] * rest.e1[1] - n[1] * rest.e1[0]) / ln;
  // D = [[A.e1, C.e1], [0, C.e2]] is upper triangular
  const double d11 = la, d12 = dot(C, rest.e1);
  const double d22 = dot(C, rest.e2);
  rest.Dinv[0][0] = 1.0 / d11;
  rest.Dinv[0][1] = -d12 / (d11 * d22);
  rest.Dinv[1][0] = 0.0;
  rest.Dinv[1][1] = 1.0 / d22;
  rest.area = 0.5 * ln;
  return true;
}

// In-plane invariants of the current edges a, c against the rest shape: C2 = F^T F.
struct MembraneStrain {
  double F[3][2];     // deformation gradient (current 3D vectors per reference direction)
  double C2[2][2];    // right Cauchy-Green tensor, in the reference frame
  double J2;          // det C2 = (current area / reference area)^2
};

inline void membrane_strain(const MembraneRest &rest, const double a[3], const double c[3],
                            MembraneStrain &s)
{
  for (int d = 0; d < 3; d++) {
    s.F[d][0] = a[d] * rest.Dinv[0][0] + c[d] * rest.Dinv[1][0];
    s.F[d][1] = a[d] * rest.Dinv[0][1] + c[d] * rest.Dinv[1][1];
  }
  for (int p = 0; p < 2; p++)
    for (int q = 0; q < 2; q++)
      s.C2[p][q] = s.F[0][p] * s.F[0][q] + s.F[1][p] * s.F[1][q] + s.F[2][p] * s.F[2][q];
  s.J2 = s.C2[0][0] * s.C2[1][1] - s.C2[0][1] * s.C2[1][0];
}

/* Tension-field theory (Eq. M3): a wall much thinner than a triangle wrinkles at a scale below the
   mesh rather than carry compression, so with `wrinkle yes` the element stores Pipkin's relaxed
   energy (Pipkin, IMA J. Appl. Math. 36, 85 (1986)) of the sheet, with principal stretches
   lam1 >= lam2:
     taut      lam2 >= lam1^-1/2:          W of Eq. M1
     wrinkled  lam1 > 1, lam2 < lam1^-1/2: W = (G t0 A0 / 2) (lam1^2 + 2 / lam1 - 3)   (Eq. M3)
     slack     lam1 <= 1:                  W = 0
   The wrinkled energy is the sheet's in uniaxial tension with free sides, where the minor tension
   vanishes (lam2 = lam1^-1/2), so the stress is continuous across every boundary: a tension field
   along the major direction v only. This is the membrane that the quasistatic reference
   (tools/membrane.py) solves, whose contact disc lies slack on the plate. */

// The response of the triangle as P = G t0 A0 F K (first Piola stress times volume, K a symmetric
// 2x2 in the reference frame) and W = G t0 A0 dev / 2. Without relax, K = I - C2^-1 / det C2
// (Eq. M2) and dev = I1 - 3 (Eq. M1), formed from the deviations so that it keeps its digits near
// rest; with relax, Eq. M3.
// The larger eigenvalue of C2, lam1^2 (the principal stretches: membrane_stretches).
inline double membrane_major(const MembraneStrain &s)
{
  const double tr = s.C2[0][0] + s.C2[1][1];
  const double dif = s.C2[0][0] - s.C2[1][1];
  const double root = std::sqrt(0.25 * dif * dif + s.C2[0][1] * s.C2[1][0]);
  return 0.5 * tr + root;
}

inline void membrane_response(const MembraneStrain &s, bool relax, double K[2][2], double &dev)
{
  if (relax) {
    const double off = s.C2[0][1];
    const double e1 = membrane_major(s);    // lam1^2
    const double lam1 = std::sqrt(e1);
    if (!(lam1 > 1.0)) {    // slack
      K[0][0] = K[0][1] = K[1][0] = K[1][1] = 0.0;
      dev = 0.0;
      return;
    }
    // lam2^2 lam1 < 1 (with lam2^2 = J2 / e1): wrinkled
    if (s.J2 < lam1) {
      // unit eigenvector of C2 for e1; of the two equivalent forms the longer one keeps its digits
      double v0 = off, v1 = e1 - s.C2[0][0];
      const double w0 = e1 - s.C2[1][1], w1 = off;
      if (w0 * w0 + w1 * w1 > v0 * v0 + v1 * v1) {
        v0 = w0;
        v1 = w1;
      }
      const double vn = std::sqrt(v0 * v0 + v1 * v1);
      if (vn > 0.0) {
        v0 /= vn;
        v1 /= vn;
      } else {    // e1 = e2 cannot be wrinkled (lam1 > 1 >= lam2); kept for safety
        v0 = 1.0;
        v1 = 0.0;
      }
      // dW/dC2 = (G t0 A0 / 2) (1 - lam1^-3) v v^T, and P = 2 F dW/dC2
      const double k = 1.0 - 1.0 / (e1 * lam1);
      K[0][0] = k * v0 * v0;
      K[0][1] = K[1][0] = k * v0 * v1;
      K[1][1] = k * v1 * v1;
      dev = (e1 - 1.0) + 2.0 * (1.0 - lam1) / lam1;
      return;
    }
  }
  // C2^-1 / det C2 = adj(C2) / J2^2
  const double inv = 1.0 / (s.J2 * s.J2);
  K[0][0] = 1.0 - s.C2[1][1] * inv;
  K[0][1] = s.C2[0][1] * inv;
  K[1][0] = s.C2[1][0] * inv;
  K[1][1] = 1.0 - s.C2[0][0] * inv;
  dev = (s.C2[0][0] - 1.0) + (s.C2[1][1] - 1.0) + (1.0 - s.J2) / s.J2;
}

// Tension-field theory with a residual stiffness (Eq. M4): with relax and residual r > 0 the
// triangle stores (1 - r) W_M3 + r W_M1, so that a wrinkled or slack triangle keeps the fraction r
// of the full sheet's response. Eq. M3 alone lets a triangle shrink in its plane to nothing (its
// slack energy is zero), which a real wall does not: it folds out of its plane, and the bending
// that folding costs resists the compression. The full sheet's W_M1 grows without bound as the
// triangle's area goes to zero (the 1/J2 term), so a small r keeps every triangle open while the
// wall as a whole shrinks nearly free. Energy and response blend alike: the forces stay minus
// the gradient of the energy.
inline void membrane_response(const MembraneStrain &s, bool relax, double residual, double K[2][2],
                              double &dev)
{
  membrane_response(s, relax, K, dev);
  if (!relax || residual <= 0.0) return;
  double Kf[2][2], devf;
  membrane_response(s, false, Kf, devf);
  for (int p = 0; p < 2; p++)
    for (int q = 0; q < 2; q++) K[p][q] = (1.0 - residual) * K[p][q] + residual * Kf[p][q];
  dev = (1.0 - residual) * dev + residual * devf;
}

// Energy of the triangle (Eq. M1, or Eq. M3 with relax, Eq. M4 with a residual).
inline double membrane_energy(double G, double t0, const MembraneRest &rest,
                              const MembraneStrain &s, bool relax = false, double residual = 0.0)
{
  double K[2][2], dev;
  membrane_response(s, relax, residual, K, dev);
  return 0.5 * G * t0 * rest.area * dev;
}

// Forces on the two outer nodes of the triangle (Eq. M2, or the gradient of Eq. M3 with relax):
// fa = -dW/da, fc = -dW/dc; the central node takes -(fa + fc). Needs J2 > 0 (a triangle with
// area). Returns the energy W, which the response gives at no extra cost.
inline double membrane_forces(double G, double t0, const MembraneRest &rest,
                              const MembraneStrain &s, double fa[3], double fc[3],
                              bool relax = false, double residual = 0.0)
{
  double K[2][2], dev;
  membrane_response(s, relax, residual, K, dev);
  const double k = G * t0 * rest.area;
  for (int d = 0; d < 3; d++) {
    // P = k F K (first Piola stress times volume), then dW/d[a c] = P D^-T
    const double P0 = k * (s.F[d][0] * K[0][0] + s.F[d][1] * K[1][0]);
    const double P1 = k * (s.F[d][0] * K[0][1] + s.F[d][1] * K[1][1]);
    fa[d] = -(P0 * rest.Dinv[0][0] + P1 * rest.Dinv[0][1]);
    fc[d] = -(P0 * rest.Dinv[1][0] + P1 * rest.Dinv[1][1]);
  }
  return 0.5 * G * t0 * rest.area * dev;    // as membrane_energy, to the bit
}

// Principal in-plane stretches (lam1 >= lam2) of the triangle: square roots of the eigenvalues
// of C2 (for failure by the largest stretch and for diagnostics).
inline void membrane_stretches(const MembraneStrain &s, double &lam1, double &lam2)
{
  const double e1 = membrane_major(s);
  lam1 = std::sqrt(e1);
  lam2 = std::sqrt(s.J2 / e1);
}

}    // namespace CellPhysics

#endif
