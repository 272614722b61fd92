// SPDX-License-Identifier: GPL-2.0-or-later
// The 8-4 repulsion of contacts (Eq. 12) of the cell model, checked without LAMMPS
// (src/physics/lj84.h).
#include "physics/lj84.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace CellPhysics;

TEST(Repulsion84, ForceAndEnergy)
{
  const double f0 = 2.0, r0 = 1.5;
  // zero at and beyond the cutoff, continuous energy there, repulsive inside
  EXPECT_EQ(repulsion84_fpair(f0, r0, r0 * r0), 0.0);
  EXPECT_EQ(repulsion84_energy(f0, r0, 4.0 * r0 * r0), 0.0);
  EXPECT_NEAR(repulsion84_energy(f0, r0, r0 * r0 * (1 - 1e-12)), 0.0, 1e-10);
  for (double r : {0.8, 1.0, 1.2, 1.4, 1.49}) {
    const double expect = f0 * (std::pow(r0 / r, 8) - std::pow(r0 / r, 4)) / (r * r);
    const double got = repulsion84_fpair(f0, r0, r * r);
    EXPECT_NEAR(got, expect, 1e-13 * std::fabs(expect));
    EXPECT_GT(got, 0.0);
    const double h = 1e-6;
    const double dE = (repulsion84_energy(f0, r0, (r + h) * (r + h)) -
                       repulsion84_energy(f0, r0, (r - h) * (r - h))) /
        (2 * h);
    const double err = std::fabs(-dE - got * r) / (got * r);
    std::printf("r %.2f  F %.10g  -dE/dr %.10g  rel.err %.2e\n", r, got * r, -dE, err);
    EXPECT_LT(err, 1e-8);
  }
}
