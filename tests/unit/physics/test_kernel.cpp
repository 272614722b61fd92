// SPDX-License-Identifier: GPL-2.0-or-later
// The SPH kernel (Eqs. 3-4) of the cell model, checked without LAMMPS (src/physics/kernel.h).
#include "physics/kernel.h"

#include "physics/sph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace CellPhysics;

// Composite Simpson over [a, b] with n (even) panels of the radial integrand 4 pi r^2 f(r).
template <class F> static double radial_simpson(F f, double a, double b, int n)
{
  const double h = (b - a) / n;
  double sum = 0.0;
  for (int k = 0; k <= n; k++) {
    const double r = a + k * h;
    const double w = (k == 0 || k == n) ? 1.0 : ((k % 2) ? 4.0 : 2.0);
    sum += w * 4.0 * M_PI * r * r * f(r);
  }
  return sum * h / 3.0;
}

TEST(Kernel, IntegratesToOneIn3D)
{
  // Eq. 3: int W dV = 1. The integrand 4 pi r^2 W is a quintic polynomial on [0, s] and on
  // [s, 2s] (W is only C2 at q = 1), so Simpson is run on each piece separately: its error is
  // (b-a) h^4 max|f''''| / 180, about 1e-13 with 2000 panels per piece here; the tolerance 1e-10
  // leaves room for round-off of the 4000 terms (~1e-13) and nothing else.
  for (double s : {0.5, 1.2, 3.2}) {
    auto W = [s](double r) {
      return kernel_w(r, s);
    };
    const double I = radial_simpson(W, 0.0, s, 2000) + radial_simpson(W, s, 2.0 * s, 2000);
    std::printf("s %.2f  int 4 pi r^2 W dr = %.15f  error %.2e\n", s, I, std::fabs(I - 1.0));
    EXPECT_LT(std::fabs(I - 1.0), 1e-10);
  }
}

TEST(Kernel, PaperPrefactorWouldIntegrateToFourNinths)
{
  // docs/model.md sec. 5: the bracket of Eq. 4 with the printed prefactor 2/(3 pi s^3) integrates
  // to (2/3)/(3/2) = 4/9, not one; the unit integral of Eq. 3 requires 3/(2 pi s^3). The paper's
  // kernel is the implemented one rescaled by the ratio of the two prefactors.
  const double s = 3.2;
  const double ratio = (2.0 / (3.0 * M_PI * s * s * s)) / (3.0 / (2.0 * M_PI * s * s * s));
  auto Wpaper = [s, ratio](double r) {
    return ratio * kernel_w(r, s);
  };
  const double I = radial_simpson(Wpaper, 0.0, s, 2000) + radial_simpson(Wpaper, s, 2.0 * s, 2000);
  std::printf("printed prefactor 2/(3 pi s^3): integral %.15f  (4/9 = %.15f, error %.2e)\n", I,
              4.0 / 9.0, std::fabs(I - 4.0 / 9.0));
  EXPECT_LT(std::fabs(I - 4.0 / 9.0), 1e-10);
  // and the implemented prefactor, read off the kernel at r = 0: W(0) = (2/3) 3/(2 pi s^3)
  EXPECT_NEAR(kernel_w(0.0, s), 1.0 / (M_PI * s * s * s), 1e-15 / (s * s * s));
}

TEST(Kernel, DerivativeIsFiniteDifferenceOfKernel)
{
  // Central difference of a function with bounded third derivative:
  //   |(W(r+h) - W(r-h))/2h - W'(r)| <= h^2 max|W'''| / 6 + round-off eps max|W| / h.
  // The cubic spline has |d3W/dr3| = 3 norm/s^3 on q < 1 and norm/s^3 on 1 < q < 2 (norm =
  // 3/(2 pi s^3)), so the bound is computed, not chosen; the check is that no point exceeds it.
  // The relative error printed is against max|W'| = (2/3) norm/s (at q = 2/3).
  for (double s : {1.2, 3.2}) {
    const double norm = 3.0 / (2.0 * M_PI * s * s * s);
    const double h = 1e-4 * s;
    const double bound = h * h * 3.0 * norm / (s * s * s) / 6.0 +
        4.0 * 2.220446049250313e-16 * kernel_w(0.0, s) / h;    // 4 eps max|W| / h
    const double dwmax = 2.0 / 3.0 * norm / s;
    double maxerr = 0.0, maxrel = 0.0;
    for (int k = 1; k < 2000; k++) {
      const double r = k * 2.0 * s / 2000.0;
      const double fd = (kernel_w(r + h, s) - kernel_w(r - h, s)) / (2.0 * h);
      const double err = std::fabs(fd - kernel_dwdr(r, s));
      maxerr = std::max(maxerr, err);
      if (std::fabs(kernel_dwdr(r, s)) > 1e-3 * dwmax)
        maxrel = std::max(maxrel, err / std::fabs(kernel_dwdr(r, s)));
      EXPECT_LE(err, bound) << "r/s = " << r / s;
    }
    std::printf("s %.2f  max |FD - dW/dr| = %.2e  (bound %.2e; %.2e of max|dW/dr|; max pointwise "
                "rel.err %.2e where |dW/dr| > 1e-3 max)\n",
                s, maxerr, bound, maxerr / dwmax, maxrel);
    // dW/dr < 0 inside the support: the pressure force between two particles is repulsive
    for (double q : {0.01, 0.5, 1.0, 1.5, 1.999}) EXPECT_LT(kernel_dwdr(q * s, s), 0.0);
    EXPECT_EQ(kernel_dwdr(0.0, s), 0.0);
  }
}

TEST(Kernel, PairFactorIsdWdrOverR)
{
  // kernel_wr(r^2, 1/s, norm/s) is (dW/dr) / r rearranged so that q < 1 needs no division: the
  // same function to round-off. Its q = sqrt(r^2) (1/s) differs from r / s by at most 2.5 ulp
  // (three roundings against one), i.e. by 5 eps absolute for q < 2; in the outer bracket
  // u = 2 - q carries that as a relative error 5 eps / u, doubled in u^2, plus a few roundings of
  // 0.5 eps each in both forms: |rel. err.| <= 12 eps (1 + 1/u) covers it (u = 1 inside q < 1).
  const double eps = 2.220446049250313e-16;
  for (double s : {0.5, 1.2, 3.2, 6.4}) {
    const double inv_s = 1.0 / s, wn = kernel_wr_norm(s);
    double worst = 0.0;    // largest error in units of the bound
    for (int k = 1; k <= 4000; k++) {
      const double r = std::nextafter(k * 2.0 * s / 4000.0, 0.0);
      const double ref = kernel_dwdr(r, s) / r;
      const double got = kernel_wr(r * r, inv_s, wn);
      const double u = r / s < 1.0 ? 1.0 : 2.0 - r / s;
      const double bound = 12.0 * eps * (1.0 + 1.0 / u) * std::fabs(ref);
      EXPECT_LE(std::fabs(got - ref), bound) << "s = " << s << ", r/s = " << r / s;
      if (bound > 0.0) worst = std::max(worst, std::fabs(got - ref) / bound);
    }
    std::printf("s %.2f  max |kernel_wr - dW/dr / r| = %.2f of the bound 12 eps (1 + 1/u)\n", s,
                worst);
    // zero at and beyond the support, like dW/dr
    for (double r : {2.0 * s, std::nextafter(2.0 * s, 10.0 * s), 3.0 * s})
      EXPECT_EQ(kernel_wr(r * r, inv_s, wn), 0.0) << "r/s = " << r / s;
  }
  // the Morris viscosity from inverse densities is the quotient law of Eq. 5 (a few roundings apart)
  const double fv = 2.0 * 3.0 * (1.0e-3 + 2.0e-3) / (1.1 * 0.9) * -0.7;
  const double fvi = sph_viscous_fvel(2.0, 3.0, 1.0e-3, 2.0e-3, 1.0 / 1.1, 1.0 / 0.9, -0.7);
  EXPECT_LE(std::fabs(fvi - fv), 8.0 * eps * std::fabs(fv));
}

TEST(Kernel, ExactlyZeroOutsideSupport)
{
  // compact support 2s: the pair cutoff is 2s, so W and dW/dr must vanish exactly there and beyond
  for (double s : {0.5, 1.2, 3.2}) {
    for (double r :
         {2.0 * s, std::nextafter(2.0 * s, 10.0 * s), 2.0001 * s, 2.5 * s, 10.0 * s, 1e6 * s}) {
      EXPECT_EQ(kernel_w(r, s), 0.0) << "r/s = " << r / s;
      EXPECT_EQ(kernel_dwdr(r, s), 0.0) << "r/s = " << r / s;
    }
    // and both approach zero continuously from inside (W ~ u^3, dW/dr ~ u^2, u = 2 - r/s)
    const double r = std::nextafter(2.0 * s, 0.0);
    EXPECT_LT(kernel_w(r, s), 1e-40);
    EXPECT_LT(std::fabs(kernel_dwdr(r, s)), 1e-25);
    std::printf("s %.2f  W(2s) = %g  dW/dr(2s) = %g  W(2s-ulp) = %.3g  dW/dr(2s-ulp) = %.3g\n", s,
                kernel_w(2.0 * s, s), kernel_dwdr(2.0 * s, s), kernel_w(r, s), kernel_dwdr(r, s));
  }
}
