// SPDX-License-Identifier: GPL-2.0-or-later
// The osmotic uptake of a fluid particle (Eq. 10) of the cell model, checked without LAMMPS
// (src/physics/osmosis.h).
#include "physics/osmosis.h"

#include "physics/tait.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace CellPhysics;

TEST(Osmosis, LinearisedStepIsEq10AndStable)
{
  // stiff cell numbers, units micro: rho 1, c 264.6, particle mass 27.3, Pi = -364 kPa
  const double rho0 = 1.0, c = 264.6, m = 27.3, Pi = -364.0, dt = 0.001;
  const double P = 100.0, rho = 1.0014;
  const double k_small = 11300.0 * 1e-9 * rho / 3500.0;    // physical Lp: A Lp rho / N_f
  const double dpdrho = tait_dpdrho(rho, rho0, c);
  // small k dt: the step is dt times Eq. 10
  const double step = osmotic_mass_step(k_small, dt, P, Pi, dpdrho, rho, m);
  const double euler = dt * osmotic_mass_rate(11300.0, 1e-9, rho, 3500, P, Pi) / rho * rho;
  // they differ by the linearisation's relative correction k dt dP/drho rho/m (8e-9 here)
  const double corr = k_small * dt * dpdrho * rho / m;
  std::printf("physical Lp: step %.6e, dt * Eq.10 %.6e, expected relative difference %.2e\n", step,
              euler, corr);
  EXPECT_NEAR(step / euler, 1.0 / (1.0 + corr), 1e-14);
  // huge k dt (inflation with Lp = 100): a particle at fixed volume is driven to P = -Pi by
  // Newton steps; the error must contract every step, quadratically once close (factor >= 10)
  double mm = m, r = rho0, p = 0.0, err = -Pi;
  for (int n = 0; n < 50; n++) {
    const double dm =
        osmotic_mass_step(100.0 * 11300.0 * r / 3500.0, dt, p, Pi, tait_dpdrho(r, rho0, c), r, mm);
    r += r / mm * dm;    // Eq. 9 at fixed volume
    mm += dm;
    p = tait_pressure(r, rho0, c, 0.0);
    const double e = std::fabs(p + Pi);
    if (n == 0) std::printf("first step from 0: P = %.4f kPa (target %.1f)\n", p, -Pi);
    if (e > 1e-9) EXPECT_LT(e, (n == 0 ? 0.05 : 0.1) * err) << "step " << n;
    err = std::max(e, 1e-12);
  }
  std::printf("Lp = 100: pressure after 50 steps %.6f kPa (target %.1f)\n", p, -Pi);
  EXPECT_NEAR(p / -Pi, 1.0, 1e-6);
}

TEST(Osmosis, CoefficientIsEq10)
{
  // Eq. 10 for a stiff cell of Table I in units micro: A_c = 4 pi R^2 (R = 30 um), Lp = 1e-12
  // m/(Pa s) = 1e-9 um/(kPa us), N_f = 3500, rho = 1 pg/um^3, at P = 0 and Pi = -364 kPa
  const double A = 4.0 * M_PI * 30.0 * 30.0, Lp = 1e-9, rho = 1.0, Pi = -364.0;
  const double k = osmotic_coefficient(A, Lp, rho, 3500);
  const double rate = osmotic_mass_rate(A, Lp, rho, 3500, 0.0, Pi);
  std::printf("k = A Lp rho / N = %.10g pg/(kPa us)  dm/dt at P = 0: %.10g pg/us per particle\n", k,
              rate);
  EXPECT_NEAR(k, A * Lp * rho / 3500.0, 1e-16 * k);
  EXPECT_EQ(rate, -k * (0.0 + Pi));
  EXPECT_GT(rate, 0.0);    // water flows in below turgor
  EXPECT_EQ(osmotic_mass_rate(A, Lp, rho, 3500, -Pi, Pi), 0.0);
}
