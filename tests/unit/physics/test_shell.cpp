// SPDX-License-Identifier: GPL-2.0-or-later
// The thin spherical shell: breathing in vacuo (Eq. A5) and buckling (Eqs. S1-S5) of the cell
// model, checked without LAMMPS (src/physics/shell.h).
#include "physics/shell.h"

#include "physics/bending.h"
#include "physics/tether.h"

#include "common.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace CellPhysics;

TEST(Breathing, PaperFrequenciesFromTableI)
{
  // docs/model.md section 5: a wall mass near 1.3e-11 kg reproduces the paper's 3.451e7 and
  // 5.943e5 rad/s
  const double R = 30e-6, M = 1.276e-11;
  const double ws = breathing_omega_vacuo(2.4e9, R, M, 126e-9);
  const double wsoft = breathing_omega_vacuo(20e6, R, 1.423e-11, 5e-9);
  std::printf("omega stiff %.4e (paper 3.451e7), soft %.4e (paper 5.943e5)\n", ws, wsoft);
  EXPECT_NEAR(ws / 3.451e7, 1.0, 2e-3);
  EXPECT_NEAR(wsoft / 5.943e5, 1.0, 2e-3);
}

// Eqs. S1 and S4 against the shallow-shell balance they come from, minimised numerically: the
// stress sigma(k) = D k^2 / t + E / (R^2 k^2) that a dimple of wavenumber k needs, with D from
// bending_stiffness (Eq. B1) for nu = 1/2 and the plate formula for another nu
TEST(ShellBuckling, CriticalStressIsTheLeastBalancingStress)
{
  constexpr double PI = 3.14159265358979323846;
  const double R = 30.0;
  for (double t : {0.126, 0.504}) {
    for (double nu : {0.5, 0.3}) {
      const double E = 3.0 * G;
      const double D = nu == 0.5 ? bending_stiffness(G, t)
                                 : E * t * t * t / (12.0 * (1.0 - nu * nu));
      // golden-section search of sigma(k) over k R in [1, 1000]
      double a = 1.0 / R, b = 1000.0 / R;
      const double g = 0.5 * (std::sqrt(5.0) - 1.0);
      auto sigma = [&](double k) {
        return D * k * k / t + E / (R * R * k * k);
      };
      for (int it = 0; it < 200; it++) {
        const double c = b - g * (b - a), d = a + g * (b - a);
        if (sigma(c) < sigma(d))
          b = d;
        else
          a = c;
      }
      const double kmin = 0.5 * (a + b), smin = sigma(kmin);
      const double sc = shell_critical_stress(E, t, R, nu), lc = shell_buckle_wavelength(t, R, nu);
      std::printf("t %.3f nu %.1f: sigma_c %.10g (search %.10g), lambda_c %.10g (search %.10g) um, "
                  "eps_c %.6g, p_c %.6g kPa\n",
                  t, nu, sc, smin, lc, 2.0 * PI / kmin, shell_critical_strain(E, t, R, nu),
                  shell_critical_pressure(E, t, R, nu));
      EXPECT_NEAR(sc / smin, 1.0, 1e-12);
      EXPECT_NEAR(lc * kmin / (2.0 * PI), 1.0, 1e-7);    // k at a flat minimum: sqrt(tolerance)
    }
  }
}

// Eq. S2 against the wall's own material: the incompressible Neo-Hookean sheet compressed
// equibiaxially by eps_c carries a membrane force equibiaxial_tension (Eq. 15) of -sigma_c t to
// first order in eps_c. Eq. S3: the classical coefficient p_c = 1.21 E (t/R)^2 of nu = 0.3
// (Timoshenko & Gere) and the Laplace balance p_c R = 2 sigma_c t for a sphere.
TEST(ShellBuckling, CriticalStrainAndPressure)
{
  const double E = 3.0 * G, R = 30.0, t = T0;
  const double sc = shell_critical_stress(E, t, R, 0.5), ec = shell_critical_strain(E, t, R, 0.5);
  const double T = equibiaxial_tension(G, t, 1.0 - ec);
  std::printf("eps_c %.6g = t/(3R) %.6g; Neo-Hookean force at 1 - eps_c %.8g, -sigma_c t %.8g\n",
              ec, t / (3.0 * R), T, -sc * t);
  EXPECT_NEAR(ec * 3.0 * R / t, 1.0, 1e-14);
  EXPECT_NEAR(T / (-sc * t), 1.0, 5.0 * ec);    // the Neo-Hookean law is linear to O(eps)
  const double pc03 = shell_critical_pressure(E, t, R, 0.3) / (E * t * t / (R * R));
  std::printf("p_c / (E (t/R)^2) at nu 0.3: %.6g (Timoshenko & Gere: 1.21)\n", pc03);
  EXPECT_NEAR(pc03, 1.21, 0.005);
  EXPECT_NEAR(shell_critical_pressure(E, t, R, 0.5) * R / (2.0 * sc * t), 1.0, 1e-15);
}

// Eq. S5: the growth rate rho t s^2 = sigma t k^2 - D k^4 - E t / R^2 at sigma = a sigma_c is
// largest at lambda_c / sqrt(a) (a numerical maximum), and no k grows below sigma_c
TEST(ShellBuckling, FastestGrowingWavelength)
{
  constexpr double PI = 3.14159265358979323846;
  const double E = 3.0 * G, R = 30.0, t = 0.504, D = bending_stiffness(G, t);
  for (double a : {0.9, 1.0, 2.0, 4.0}) {
    const double sigma = a * shell_critical_stress(E, t, R, 0.5);
    double best = -1e300, kbest = 0.0;
    for (int i = 1; i <= 200000; i++) {
      const double k = i * 1e-5 * 10.0;
      const double s2 = sigma * t * k * k - D * k * k * k * k - E * t / (R * R);
      if (s2 > best) {
        best = s2;
        kbest = k;
      }
    }
    std::printf("a %.1f: largest rho t s^2 %.6g at lambda %.6g um, Eq. S5 %.6g um\n", a, best,
                2.0 * PI / kbest, shell_fastest_wavelength(t, R, 0.5, a));
    if (a < 1.0)
      EXPECT_LT(best, 0.0);
    else
      EXPECT_NEAR(2.0 * PI / kbest / shell_fastest_wavelength(t, R, 0.5, a), 1.0, 2e-3);
  }
}
