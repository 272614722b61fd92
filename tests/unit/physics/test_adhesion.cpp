// SPDX-License-Identifier: GPL-2.0-or-later
// The adhesion well of the protoplasm at its own wall (Eq. A1, src/physics/adhesion.h), checked
// without LAMMPS.
#include "physics/adhesion.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>

using namespace CellPhysics;

namespace {
constexpr double FA = 3.0, R0 = 1.5, DELTA = 0.4;

// the radial force F(r) = fpair r
double force(double fa, double r)
{
  return adhesion_fpair(fa, R0, DELTA, r * r) * r;
}

double energy(double fa, double r)
{
  return adhesion_energy(fa, R0, DELTA, r * r);
}
}    // namespace

TEST(Adhesion, ForceIsMinusEnergyGradient)
{
  // central difference: truncation h^2 |E'''| / 6 with |E'''| = 8 Fa / delta^2 in the well (0
  // elsewhere), round-off about eps |E| / h with |E| <= the depth 2/3 Fa delta
  const double h = 1e-6, depth = 2.0 / 3.0 * FA * DELTA;
  const double tol = h * h * 8.0 * FA / (DELTA * DELTA) / 6.0 + 4.0 * DBL_EPSILON * depth / h;
  double worst = 0.0;
  int n = 0;
  // inside r0, across the well (its ends kept 10 h away from the stencils), beyond it
  for (double r = 1.0; r < 2.5; r += 0.0123) {
    if (std::fabs(r - R0) < 10 * h || std::fabs(r - R0 - DELTA) < 10 * h) continue;
    const double dE = (energy(FA, r + h) - energy(FA, r - h)) / (2 * h);
    const double err = std::fabs(force(FA, r) + dE);
    worst = std::fmax(worst, err);
    EXPECT_LT(err, tol) << "r = " << r;
    n++;
  }
  std::printf("%d radii: |F + dE/dr| <= %.2e (bound %.2e, Fa %g)\n", n, worst, tol, FA);
}

TEST(Adhesion, ZeroForceAtBothEndsAndAttractiveBetween)
{
  EXPECT_EQ(adhesion_fpair(FA, R0, DELTA, R0 * R0), 0.0);
  EXPECT_EQ(adhesion_fpair(FA, R0, DELTA, (R0 + DELTA) * (R0 + DELTA)), 0.0);
  EXPECT_EQ(force(FA, 0.9 * R0), 0.0);
  EXPECT_EQ(force(FA, R0 + 1.5 * DELTA), 0.0);
  // continuous: 1e-9 of delta inside either end, the force is 4 Fa 1e-9
  const double e = 1e-9 * DELTA;
  EXPECT_LT(std::fabs(force(FA, R0 + e)), 4.0 * FA * 1e-9 * (1 + 1e-6));
  EXPECT_LT(std::fabs(force(FA, R0 + DELTA - e)), 4.0 * FA * 1e-9 * (1 + 1e-6));
  for (double xi = 0.05; xi < 1.0; xi += 0.05) EXPECT_LT(force(FA, R0 + xi * DELTA), 0.0);
}

TEST(Adhesion, PeakFaAtTheMidpoint)
{
  const double mid = force(FA, R0 + 0.5 * DELTA);
  EXPECT_NEAR(mid, -FA, 4 * DBL_EPSILON * FA);
  double strongest = 0.0;
  for (double xi = 0.0; xi <= 1.0; xi += 1e-4)
    strongest = std::fmax(strongest, -force(FA, R0 + xi * DELTA));
  std::printf("pull at r0 + delta/2: %.17g (Fa %g); strongest on a grid of 1e-4 delta: %.17g\n",
              -mid, FA, strongest);
  EXPECT_LE(strongest, FA * (1 + 4 * DBL_EPSILON));
}

TEST(Adhesion, EnergyContinuousAndDepth)
{
  const double depth = 2.0 / 3.0 * FA * DELTA;
  EXPECT_EQ(energy(FA, 0.5 * R0), -depth);
  EXPECT_EQ(energy(FA, R0), -depth);
  EXPECT_EQ(energy(FA, R0 + DELTA), 0.0);
  EXPECT_EQ(energy(FA, 3.0 * R0), 0.0);
  // the energy changes by at most |F| e over a step e: F is 0 at both ends and 4 Fa e/delta next
  // to them, so a step of 1e-9 delta across an end changes E by 4 Fa (1e-9)^2 delta, below
  // round-off of the depth
  const double e = 1e-9 * DELTA, tol = 8 * DBL_EPSILON * depth;
  EXPECT_NEAR(energy(FA, R0 - e), energy(FA, R0 + e), tol);
  EXPECT_NEAR(energy(FA, R0 + DELTA - e), energy(FA, R0 + DELTA + e), tol);
  // midway the well holds half its depth (1 - 3/4 + 1/4 = 1/2)
  EXPECT_NEAR(energy(FA, R0 + 0.5 * DELTA), -0.5 * depth, 4 * DBL_EPSILON * depth);
}

TEST(Adhesion, NoAdhesionWithoutStrength)
{
  for (double r = 0.5; r < 2.5; r += 0.01) {
    EXPECT_EQ(force(0.0, r), 0.0);
    EXPECT_EQ(energy(0.0, r), 0.0);
  }
}
