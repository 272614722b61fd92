// SPDX-License-Identifier: GPL-2.0-or-later
// What several of the physics tests share: the stiff cell's wall, the lattice sums of the SPH
// checks and the rotation that turns the wall elements' test shapes in space.
#ifndef CELLMECH_TEST_PHYSICS_COMMON_H
#define CELLMECH_TEST_PHYSICS_COMMON_H

#include <cmath>

// Stiff cell of Table I in LAMMPS units micro: G = E/3 = 800 MPa = 8e5 kPa, t0 = 0.126 um.
static constexpr double G = 8.0e5, T0 = 0.126, L0 = 2.5;

inline double dot3(const double *a, const double *b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// sum over a cubic lattice of spacing h (s/h = 2: the lattice sums of the kernel moments agree
// with the integrals to 5e-5; at the paper's h = s they are 2% off) around the origin of f(del)
// for every lattice point j != 0 within the support, del = x_0 - x_j
template <class F> void lattice_sum(double s, double h, F &&f)
{
  const int n = (int) std::ceil(2.0 * s / h);
  for (int a = -n; a <= n; a++)
    for (int b = -n; b <= n; b++)
      for (int k = -n; k <= n; k++) {
        if (!a && !b && !k) continue;
        const double xj[3] = {a * h, b * h, k * h};
        const double r = std::sqrt(dot3(xj, xj));
        if (r >= 2.0 * s) continue;
        const double del[3] = {-xj[0], -xj[1], -xj[2]};
        f(xj, del, r);
      }
}

// a general rotation (axis (1,2,3)/|.|, 0.7 rad) so that no test sits in a coordinate plane
inline void rotate(const double in[3], double out[3])
{
  double k[3] = {1, 2, 3};
  const double kn = std::sqrt(14.0);
  for (double &e : k) e /= kn;
  const double th = 0.7, c = std::cos(th), s = std::sin(th);
  const double kd = k[0] * in[0] + k[1] * in[1] + k[2] * in[2];
  const double kx[3] = {k[1] * in[2] - k[2] * in[1], k[2] * in[0] - k[0] * in[2],
                        k[0] * in[1] - k[1] * in[0]};
  for (int d = 0; d < 3; d++) out[d] = in[d] * c + kx[d] * s + k[d] * kd * (1 - c);
}

#endif
