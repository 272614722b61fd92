// SPDX-License-Identifier: GPL-2.0-or-later
// The cohesive law of the middle lamella (Eqs. L1-L5) of the cell model, checked without LAMMPS
// (src/physics/lamella.h).
#include "physics/lamella.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace CellPhysics;

// Middle lamella (Xu & Needleman cohesive law), units micro: sigma_c = 300 kPa, Gc = 0.05 J/m^2
// = 50 pg/us^2, so delta_c = 0.0613 um.
static constexpr double SIGC = 300.0, GC = 50.0;

TEST(Lamella, LengthMakesBreakWorkEqualGc)
{
  const double dc = cohesive_length(SIGC, GC);
  const double expect = GC / (SIGC * std::exp(1.0) * (1.0 - 11.0 * std::exp(-10.0)));
  const double at_break = cohesive_energy(SIGC, dc, cohesive_break_opening(dc));
  std::printf("delta_c %.10g um (Eq. L3 %.10g); energy per area at the break %.15g, Gc %.15g, "
              "rel.err %.2e\n",
              dc, expect, at_break, GC, std::fabs(at_break / GC - 1.0));
  EXPECT_NEAR(dc, expect, 1e-15 * expect);
  EXPECT_EQ(cohesive_break_opening(dc), 10.0 * dc);
  EXPECT_NEAR(at_break, GC, 1e-14 * GC);
}

TEST(Lamella, TractionIsEnergyDerivative)
{
  // five-point difference, h = 1e-4 delta_c: truncation h^4 T^(4)/30 ~ 1e-17 sigma_c; round-off
  // 1.5 eps E / h, largest near the break (E ~ Gc, T = 1.4e-3 sigma_c): 1.4e-9 sigma_c, 3e-9 of
  // T there. The traction, zero at delta = 0, is compared with 1e-3 sigma_c at least.
  const double dc = cohesive_length(SIGC, GC);
  double worst = 0.0;
  for (double x : {-2.0, -0.3, -1e-3, 1e-3, 0.2, 0.4999, 0.5, 0.5001, 1.0, 2.5, 6.0, 9.9}) {
    const double d = x * dc, h = 1e-4 * dc;
    double E[5];
    for (int k = 0; k < 5; k++) E[k] = cohesive_energy(SIGC, dc, d + (k - 2) * h);
    const double dE = (E[0] - 8 * E[1] + 8 * E[3] - E[4]) / (12 * h);
    const double T = cohesive_traction(SIGC, dc, d);
    const double err = std::fabs(dE - T) / std::max(std::fabs(T), 1e-3 * SIGC);
    worst = std::max(worst, err);
    std::printf("delta/dc %+8.4f  T %+.10g  dE/ddelta %+.10g  rel.err %.2e\n", x, T, dE, err);
    EXPECT_LT(err, 1e-8);
  }
  std::printf("traction vs finite-difference energy derivative: worst rel.err %.2e\n", worst);
}

TEST(Lamella, PeakAtDeltaC)
{
  const double dc = cohesive_length(SIGC, GC);
  EXPECT_NEAR(cohesive_traction(SIGC, dc, dc), SIGC, 1e-13 * SIGC);
  const double h = 1e-5 * dc;
  const double slope =
      (cohesive_traction(SIGC, dc, dc + h) - cohesive_traction(SIGC, dc, dc - h)) / (2 * h);
  std::printf("peak traction %.15g (sigma_c %.1f), slope there %.2e sigma_c/delta_c\n",
              cohesive_traction(SIGC, dc, dc), SIGC, slope * dc / SIGC);
  EXPECT_LT(std::fabs(slope * dc / SIGC), 1e-9);
  for (double x : {0.5, 0.9, 1.1, 2.0})
    EXPECT_LT(cohesive_traction(SIGC, dc, x * dc), SIGC) << "x = " << x;
}

TEST(Lamella, CompressiveBranchContinuesInitialStiffness)
{
  const double dc = cohesive_length(SIGC, GC);
  const double k0 = SIGC * std::exp(1.0) / dc;
  for (double x : {-0.5, -0.1, -1e-6}) {
    const double d = x * dc;
    EXPECT_NEAR(cohesive_traction(SIGC, dc, d), k0 * d, 1e-14 * std::fabs(k0 * d));
    EXPECT_NEAR(cohesive_energy(SIGC, dc, d), 0.5 * k0 * d * d, 1e-14 * 0.5 * k0 * d * d);
    EXPECT_LT(cohesive_traction(SIGC, dc, d), 0.0);
  }
  // same stiffness on both sides of zero; energy and traction vanish there, continuously
  const double e = 1e-9 * dc;
  const double k_plus = cohesive_traction(SIGC, dc, e) / e;
  const double k_minus = cohesive_traction(SIGC, dc, -e) / -e;
  std::printf("stiffness at zero opening: tension %.12g, compression %.12g, sigma_c e/dc %.12g\n",
              k_plus, k_minus, k0);
  EXPECT_NEAR(k_plus / k0, 1.0, 1e-8);
  EXPECT_NEAR(k_minus / k0, 1.0, 1e-14);
  EXPECT_EQ(cohesive_energy(SIGC, dc, 0.0), 0.0);
  EXPECT_EQ(cohesive_traction(SIGC, dc, 0.0), 0.0);
  EXPECT_NEAR(cohesive_energy(SIGC, dc, e), cohesive_energy(SIGC, dc, -e),
              1e-8 * cohesive_energy(SIGC, dc, e));
}

TEST(Lamella, SmallOpeningEnergyHasNoCancellation)
{
  // 1 - (1 + x) e^-x = x^2/2 - x^3/3 + x^4/8 - ...: the energy keeps full precision as x -> 0
  const double dc = cohesive_length(SIGC, GC);
  const double scale = SIGC * std::exp(1.0) * dc;
  for (double x : {1e-8, 1e-4, 1e-3}) {
    const double series = x * x / 2 - x * x * x / 3 + x * x * x * x / 8 - std::pow(x, 5) / 30;
    const double got = cohesive_energy(SIGC, dc, x * dc) / scale;
    EXPECT_NEAR(got / series, 1.0, 1e-13) << "x = " << x;
  }
  // the series and the closed form agree where they meet
  const double lo = cohesive_energy(SIGC, dc, 0.5 * dc * (1 - 1e-15));
  const double hi = cohesive_energy(SIGC, dc, 0.5 * dc);
  EXPECT_NEAR(lo / hi, 1.0, 1e-13);
}
