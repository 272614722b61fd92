// SPDX-License-Identifier: GPL-2.0-or-later
// The damping of bonds and contacts (Eq. 11) of the cell model, checked without LAMMPS
// (src/physics/damping.h).
#include "physics/damping.h"

#include "common.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace CellPhysics;

TEST(Damping, Eq11AlongLineOfCentresDissipates)
{
  // F_i = damping_fpair r_ij must be -gamma (v_ij . e) e: along r_ij, blind to the perpendicular
  // velocity, equal and opposite on j (r_ji = -r_ij and v_ji = -v_ij give the same factor), and
  // its power F_i . v_ij = -gamma (v_ij . e)^2 <= 0
  const double gamma = 1e-7;
  const double r[3] = {0.3, -1.2, 2.1};
  const double rsq = dot3(r, r), rl = std::sqrt(rsq);
  const double e[3] = {r[0] / rl, r[1] / rl, r[2] / rl};
  for (const double vpar : {-3.0, 0.0, 0.7}) {
    const double vperp[3] = {1.2, 0.3, 0.0};    // perpendicular to r: r . vperp = 0.36 - 0.36 = 0
    double v[3];
    for (int d = 0; d < 3; d++) v[d] = vpar * e[d] + vperp[d];
    const double fpair = damping_fpair(gamma, dot3(r, v), rsq);
    double F[3], expect[3], err = 0.0;
    for (int d = 0; d < 3; d++) {
      F[d] = fpair * r[d];
      expect[d] = -gamma * dot3(v, e) * e[d];
      err = std::max(err, std::fabs(F[d] - expect[d]));
    }
    const double mr[3] = {-r[0], -r[1], -r[2]}, mv[3] = {-v[0], -v[1], -v[2]};
    const double fpair_ji = damping_fpair(gamma, dot3(mr, mv), rsq);
    const double power = dot3(F, v);
    std::printf("v.e %5.2f: F = (%.6g %.6g %.6g)  -gamma(v.e)e err %.2e  F.v %.6g = -gamma(v.e)^2 "
                "%.6g\n",
                vpar, F[0], F[1], F[2], err, power, -gamma * vpar * vpar);
    EXPECT_LT(err, 1e-15 * gamma * (std::fabs(vpar) + 1.0));
    EXPECT_EQ(fpair_ji, fpair);
    EXPECT_LE(power, 0.0);
    EXPECT_NEAR(power, -gamma * vpar * vpar, 1e-14 * gamma * (vpar * vpar + 1.0));
  }
}
