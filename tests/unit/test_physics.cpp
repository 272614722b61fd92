// Physics of the cell model, checked without LAMMPS (cell_physics.h).
#include "cell_physics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace CellPhysics;

// Stiff cell of Table I in LAMMPS units micro: G = E/3 = 800 MPa = 8e5 kPa, t0 = 0.126 um.
static constexpr double G = 8.0e5, T0 = 0.126, L0 = 2.5;

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
    const double dU = (tether_energy(G, T0, L0, (l + h) / L0) -
                       tether_energy(G, T0, L0, (l - h) / L0)) /
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
  const double k_fd = (tether_tension(G, T0, L0, 1.0 + h) - tether_tension(G, T0, L0, 1.0 - h)) /
      (2.0 * h * L0);
  const double k = 6.0 * G * T0 / std::sqrt(3.0);
  std::printf("stiffness: finite difference %.10g  6 G t0/sqrt3 %.10g  (%.6g N/m)\n", k_fd, k,
              k * 1e-3);
  EXPECT_NEAR(k_fd / k, 1.0, 1e-8);
  EXPECT_DOUBLE_EQ(tether_stiffness(G, T0), k);
  // MODEL.md section 3: the stiff wall's tether stiffness is 349 N/m (1e-3 N/m per micro unit)
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

TEST(Breathing, PaperFrequenciesFromTableI)
{
  // MODEL.md: a wall mass near 1.3e-11 kg reproduces the paper's 3.451e7 and 5.943e5 rad/s
  const double R = 30e-6, M = 1.276e-11;
  const double ws = breathing_omega_vacuo(2.4e9, R, M, 126e-9);
  const double wsoft = breathing_omega_vacuo(20e6, R, 1.423e-11, 5e-9);
  std::printf("omega stiff %.4e (paper 3.451e7), soft %.4e (paper 5.943e5)\n", ws, wsoft);
  EXPECT_NEAR(ws / 3.451e7, 1.0, 2e-3);
  EXPECT_NEAR(wsoft / 5.943e5, 1.0, 2e-3);
}
