// SPDX-License-Identifier: GPL-2.0-or-later
// The Neo-Hookean tether (Eqs. 15, 19-20) of the cell model, checked without LAMMPS
// (src/physics/tether.h).
#include "physics/tether.h"

#include "common.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace CellPhysics;

TEST(Tether, ForceIsEq19)
{
  for (double lam : {0.8, 0.95, 1.0, 1.01, 1.04, 1.2, 1.5}) {
    const double expect = G * L0 * T0 / std::sqrt(3.0) * (lam - std::pow(lam, -5.0));
    const double got = tether_tension(G, T0, L0, lam);
    const double err = std::fabs(got - expect) / std::max(1.0, std::fabs(expect));
    std::printf("lam %.3f  tension %.10g  Eq.19 %.10g  rel.err %.2e\n", lam, got, expect, err);
    EXPECT_LT(err, 1e-14);
  }
}

TEST(Tether, ForceIsMinusEnergyDerivative)
{
  // central difference in l = lam l0: truncation (h/l0)^2 f''/6 = 5 (h/l0)^2 in units of
  // G l0 t0/sqrt3, against f ~ 6 (lam - 1) near rest, gives 1e-10 relative at lam = 1.005 for
  // h = 1e-6 l0; round-off (eps U / h) stays below 1e-12 relative
  for (double lam : {0.7, 0.9, 0.99, 1.005, 1.03, 1.1, 1.3}) {
    const double h = 1e-6 * L0;
    const double l = lam * L0;
    const double dU =
        (tether_energy(G, T0, L0, (l + h) / L0) - tether_energy(G, T0, L0, (l - h) / L0)) /
        (2.0 * h);
    const double f = tether_tension(G, T0, L0, lam);
    const double err = std::fabs(dU - f) / std::fabs(f);
    std::printf("lam %.3f  tension %.10g  dU/dl %.10g  rel.err %.2e\n", lam, f, dU, err);
    EXPECT_LT(err, 1e-8);
  }
  EXPECT_EQ(tether_energy(G, T0, L0, 1.0), 0.0);
}

TEST(Tether, SmallStrainStiffnessIsEq20)
{
  const double h = 1e-6;
  const double k_fd =
      (tether_tension(G, T0, L0, 1.0 + h) - tether_tension(G, T0, L0, 1.0 - h)) / (2.0 * h * L0);
  const double k = 6.0 * G * T0 / std::sqrt(3.0);
  std::printf("stiffness: finite difference %.10g  6 G t0/sqrt3 %.10g  (%.6g N/m)\n", k_fd, k,
              k * 1e-3);
  EXPECT_NEAR(k_fd / k, 1.0, 1e-8);
  EXPECT_DOUBLE_EQ(tether_stiffness(G, T0), k);
  // docs/model.md section 3.2: the stiff wall's tether stiffness is 349 N/m (1e-3 N/m per micro
  // unit)
  EXPECT_NEAR(k * 1e-3, 349.0, 0.5);
}

TEST(Tether, EquilateralNetworkTensionIsNeoHookean)
{
  // sqrt3 f / l of an equilateral network under equibiaxial stretch is the Neo-Hookean tension
  for (double lam : {1.0, 1.01, 1.1}) {
    const double T = std::sqrt(3.0) * tether_tension(G, T0, L0, lam) / (lam * L0);
    EXPECT_NEAR(T, equibiaxial_tension(G, T0, lam), 1e-12 * G * T0);
  }
}
