// SPDX-License-Identifier: GPL-2.0-or-later
// The Tait equation of state (Eq. 6) of the cell model, checked without LAMMPS
// (src/physics/tait.h).
#include "physics/tait.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace CellPhysics;

TEST(Tait, ReferencePressureAndSoundSpeed)
{
  // Eq. 6: P(rho0) = P0 exactly ((rho0/rho0)^7 = 1), and dP/drho at rho0 = 7 kappa/rho0 = c^2
  // (kappa = rho0 c^2/7), so c is the sound speed of the linearised fluid. Central difference with
  // h = 1e-6 rho0: truncation h^2 P'''/6 = 5 (h/rho0)^2 c^2 = 5e-12 c^2, round-off
  // eps P / h ~ 2e-10 P0 / rho0; against c^2 >= 1e4 both are below 1e-9 relative.
  struct Case {
    double rho0, c, P0;
  };
  for (const Case &k : {Case{1.0, 264.6, 364.0}, Case{1.0, 20.0, 100.0}, Case{1000.0, 264.6, 0.0},
                        Case{1.0, 1500.0, -50.0}}) {
    EXPECT_EQ(tait_pressure(k.rho0, k.rho0, k.c, k.P0), k.P0);
    const double h = 1e-6 * k.rho0;
    const double dP = (tait_pressure(k.rho0 + h, k.rho0, k.c, k.P0) -
                       tait_pressure(k.rho0 - h, k.rho0, k.c, k.P0)) /
        (2.0 * h);
    const double err = std::fabs(dP / (k.c * k.c) - 1.0);
    std::printf("rho0 %g c %g P0 %g: P(rho0) = %.17g  dP/drho = %.12g  c^2 = %.12g  rel.err %.2e\n",
                k.rho0, k.c, k.P0, tait_pressure(k.rho0, k.rho0, k.c, k.P0), dP, k.c * k.c, err);
    EXPECT_LT(err, 1e-9);
    // the law itself at a compressed and an expanded state
    for (double x : {0.97, 1.03}) {
      const double expect = k.P0 + k.rho0 * k.c * k.c / 7.0 * (std::pow(x, 7) - 1.0);
      EXPECT_NEAR(tait_pressure(x * k.rho0, k.rho0, k.c, k.P0), expect,
                  1e-13 * (std::fabs(expect) + std::fabs(k.P0)));
    }
  }
}

TEST(Tait, InternalEnergyDerivativeIsPOverRho2)
{
  // de/drho = P / rho^2 (central difference, h = 1e-6 rho0: truncation ~ (h/rho0)^2 c^2 ~ 1e-7
  // kPa um^3/pg against P/rho^2 ~ 364, round-off eps e / h ~ 1e-8), e(rho0) = 0
  const double rho0 = 1.0, c = 264.6, P0 = 364.0;
  EXPECT_EQ(tait_internal_energy(rho0, rho0, c, P0), 0.0);
  for (double x : {0.98, 0.999, 1.0, 1.001, 1.02}) {
    const double rho = x * rho0, h = 1e-6 * rho0;
    const double fd =
        (tait_internal_energy(rho + h, rho0, c, P0) - tait_internal_energy(rho - h, rho0, c, P0)) /
        (2.0 * h);
    const double expect = tait_pressure(rho, rho0, c, P0) / (rho * rho);
    std::printf("rho/rho0 %.3f: de/drho %.10g  P/rho^2 %.10g  rel.err %.2e\n", x, fd, expect,
                std::fabs(fd / expect - 1.0));
    EXPECT_NEAR(fd / expect, 1.0, 1e-7);
  }
}
