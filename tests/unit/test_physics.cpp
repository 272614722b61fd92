// SPDX-License-Identifier: GPL-2.0-or-later
// Physics of the cell model, checked without LAMMPS (cell_physics.h).
#include "cell_physics.h"

#include <gtest/gtest.h>

#include <algorithm>
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
  // docs/model.md section 5: a wall mass near 1.3e-11 kg reproduces the paper's 3.451e7 and
  // 5.943e5 rad/s
  const double R = 30e-6, M = 1.276e-11;
  const double ws = breathing_omega_vacuo(2.4e9, R, M, 126e-9);
  const double wsoft = breathing_omega_vacuo(20e6, R, 1.423e-11, 5e-9);
  std::printf("omega stiff %.4e (paper 3.451e7), soft %.4e (paper 5.943e5)\n", ws, wsoft);
  EXPECT_NEAR(ws / 3.451e7, 1.0, 2e-3);
  EXPECT_NEAR(wsoft / 5.943e5, 1.0, 2e-3);
}

/* ---------------------------------------------------------------------
   SPH kernel (Eqs. 3-4) and equation of state (Eq. 6)
------------------------------------------------------------------------ */

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

TEST(Geometry, OriginTriangleDistance)
{
  // triangle in the plane z = 2 around the z axis: the face is closest
  const double a[3] = {-1, -1, 2}, b[3] = {2, -1, 2}, c[3] = {-1, 2, 2};
  EXPECT_NEAR(origin_triangle_dist_sq(a, b, c), 4.0, 1e-14);
  // shifted so that the origin's foot is beyond edge bc (x + y = 1 line at z = 2)
  const double a2[3] = {1, 1, 2}, b2[3] = {4, 1, 2}, c2[3] = {1, 4, 2};
  EXPECT_NEAR(origin_triangle_dist_sq(a2, b2, c2), 1 + 1 + 4, 1e-14);    // vertex a2
  const double a3[3] = {-3, 1, 0}, b3[3] = {3, 1, 0}, c3[3] = {0, 5, 0};
  EXPECT_NEAR(origin_triangle_dist_sq(a3, b3, c3), 1.0, 1e-14);    // edge ab
  // brute force against a dense sampling of random triangles
  unsigned seed = 12345;
  auto rnd = [&]() {
    seed = seed * 1103515245u + 12345u;
    return ((seed >> 8) & 0xffff) / 32768.0 - 1.0;
  };
  double worst = 0.0;
  for (int trial = 0; trial < 200; trial++) {
    double p[9];
    for (double &v : p) v = 3.0 * rnd();
    double best = 1e300;
    const int n = 200;
    for (int i = 0; i <= n; i++)
      for (int j = 0; i + j <= n; j++) {
        const double u = (double) i / n, v = (double) j / n;
        double q[3], d2 = 0.0;
        for (int d = 0; d < 3; d++) {
          q[d] = p[d] + u * (p[3 + d] - p[d]) + v * (p[6 + d] - p[d]);
          d2 += q[d] * q[d];
        }
        best = std::min(best, d2);
      }
    const double exact = origin_triangle_dist_sq(p, p + 3, p + 6);
    EXPECT_LE(exact, best + 1e-12);    // never farther than any sampled point
    worst = std::max(worst, std::sqrt(best) - std::sqrt(exact));
  }
  std::printf("closest-point distance vs sampling: sampled points at most %.2e farther\n", worst);
  EXPECT_LT(worst, 0.05);    // grid spacing 3*sqrt(2)*2/200 bounds how far sampling can miss
}

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

/* ---------------------------------------------------------------------
   The equations the drivers apply (pair cell/sph, fix cell/fluid, the damping of the bond and
   contact styles, compute cell/props and cell/shear/atom), each through its one function.
------------------------------------------------------------------------ */

static double dot3(const double *a, const double *b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

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

// Two fluid particles of Table I's fluid (units micro) at a distance within the kernel's support.
struct SphPair {
  double x[2][3] = {{0.4, -0.3, 0.2}, {-1.1, 0.9, 1.5}};
  double v[2][3] = {{0.02, -0.01, 0.05}, {-0.03, 0.04, 0.01}};
  double m[2] = {31.0, 35.0}, rho[2] = {1.004, 0.998}, mu[2] = {1.0, 3.0};
  double s = 3.2, rho0 = 1.0, c = 264.6, P0 = 364.0;
  double P(int k) const { return tait_pressure(rho[k], rho0, c, P0); }
  // F on a from b, from the driver's functions (Eq. 5)
  void force(int a, int b, double *F) const
  {
    double del[3], dv[3];
    for (int d = 0; d < 3; d++) {
      del[d] = x[a][d] - x[b][d];
      dv[d] = v[a][d] - v[b][d];
    }
    const double wr = kernel_wr(dot3(del, del), 1.0 / s, kernel_wr_norm(s));
    const double fp =
        sph_pressure_fpair(m[a], m[b], P(a) / (rho[a] * rho[a]), P(b) / (rho[b] * rho[b]), wr);
    const double fv = sph_viscous_fvel(m[a], m[b], mu[a], mu[b], 1.0 / rho[a], 1.0 / rho[b], wr);
    for (int d = 0; d < 3; d++) F[d] = fp * del[d] + fv * dv[d];
  }
};

TEST(SPH, PairForceIsEq5AndConservesMomentum)
{
  // Eq. 5 written out with the kernel's gradient taken by central differences of W itself
  // (kernel_w), so that the force functions and the kernel derivative are checked together:
  //   F_ij = -m_i m_j (P_i/rho_i^2 + P_j/rho_j^2) grad_i W + m_i m_j (mu_i+mu_j)/(rho_i rho_j)
  //          v_ij (1/r) dW/dr
  // h = 1e-5 s: truncation h^2 W'''/6 ~ 1e-11 of W', round-off eps W / h ~ 1e-11 relative.
  const SphPair p;
  double del[3], dv[3];
  for (int d = 0; d < 3; d++) {
    del[d] = p.x[0][d] - p.x[1][d];
    dv[d] = p.v[0][d] - p.v[1][d];
  }
  const double r = std::sqrt(dot3(del, del));
  const double h = 1e-5 * p.s;
  double gradW[3];
  for (int d = 0; d < 3; d++) {
    double xp[3] = {del[0], del[1], del[2]}, xm[3] = {del[0], del[1], del[2]};
    xp[d] += h;
    xm[d] -= h;
    gradW[d] = (kernel_w(std::sqrt(dot3(xp, xp)), p.s) - kernel_w(std::sqrt(dot3(xm, xm)), p.s)) /
        (2.0 * h);
  }
  const double dWdr = (kernel_w(r + h, p.s) - kernel_w(r - h, p.s)) / (2.0 * h);
  const double pr = p.P(0) / (p.rho[0] * p.rho[0]) + p.P(1) / (p.rho[1] * p.rho[1]);
  double F[3], Fji[3], expect[3], err = 0.0, scale = 0.0;
  p.force(0, 1, F);
  p.force(1, 0, Fji);
  for (int d = 0; d < 3; d++) {
    expect[d] = -p.m[0] * p.m[1] * pr * gradW[d] +
        p.m[0] * p.m[1] * (p.mu[0] + p.mu[1]) / (p.rho[0] * p.rho[1]) * dv[d] * dWdr / r;
    err = std::max(err, std::fabs(F[d] - expect[d]));
    scale = std::max(scale, std::fabs(expect[d]));
  }
  std::printf("r/s %.3f  F_ij = (%.10g %.10g %.10g)\n  Eq. 5 with finite-difference kernel = "
              "(%.10g %.10g %.10g)  rel.err %.2e\n  F_ij + F_ji = (%.2g %.2g %.2g)\n",
              r / p.s, F[0], F[1], F[2], expect[0], expect[1], expect[2], err / scale,
              F[0] + Fji[0], F[1] + Fji[1], F[2] + Fji[2]);
  EXPECT_LT(err / scale, 1e-8);
  // momentum: the same pair seen from j is exactly the opposite force
  for (int d = 0; d < 3; d++) EXPECT_EQ(F[d] + Fji[d], 0.0);

  // the pressure part is central (no torque: angular momentum), the viscous part only dissipates
  const double wr = kernel_wr(dot3(del, del), 1.0 / p.s, kernel_wr_norm(p.s));
  const double fp = sph_pressure_fpair(p.m[0], p.m[1], p.P(0) / (p.rho[0] * p.rho[0]),
                                       p.P(1) / (p.rho[1] * p.rho[1]), wr);
  const double fv =
      sph_viscous_fvel(p.m[0], p.m[1], p.mu[0], p.mu[1], 1.0 / p.rho[0], 1.0 / p.rho[1], wr);
  const double Fp[3] = {fp * del[0], fp * del[1], fp * del[2]};
  const double torque[3] = {del[1] * Fp[2] - del[2] * Fp[1], del[2] * Fp[0] - del[0] * Fp[2],
                            del[0] * Fp[1] - del[1] * Fp[0]};
  const double power = fv * dot3(dv, dv);
  std::printf("  pressure torque |r x F_p| %.2e of |r||F_p| %.6g; viscous power %.6g\n",
              std::sqrt(dot3(torque, torque)), r * std::sqrt(dot3(Fp, Fp)), power);
  EXPECT_LT(std::sqrt(dot3(torque, torque)), 1e-15 * r * std::sqrt(dot3(Fp, Fp)));
  EXPECT_LT(power, 0.0);
  EXPECT_GT(fp * 1.0, 0.0);    // turgor pushes the pair apart
}

TEST(SPH, PressureWorkIsInternalEnergyChange)
{
  // Eqs. 5, 6 and 7 together: for the inviscid fluid the power of the pressure forces equals
  // minus the rate of the internal energy sum_i m_i e(rho_i) when the densities follow the
  // continuity equation, d/dt sum m e = sum m_i (P_i/rho_i^2) drho_i/dt. This is the identity
  // that makes the pair energy of pair cell/sph conserved with the kinetic energy; it holds
  // pair by pair, so up to round-off for any positions and velocities.
  const int N = 6;
  const double s = 3.2, rho0 = 1.0, c = 264.6, P0 = 364.0;
  double x[N][3], v[N][3], m[N], rho[N], prho2[N];
  for (int i = 0; i < N; i++) {
    for (int d = 0; d < 3; d++) {
      x[i][d] = 1.7 * std::sin(1.3 * i + 2.1 * d + 0.4);
      v[i][d] = 0.05 * std::cos(0.7 * i - 1.9 * d);
    }
    m[i] = 30.0 + i;
    rho[i] = 1.0 + 0.003 * std::sin(2.0 * i);
    prho2[i] = tait_pressure(rho[i], rho0, c, P0) / (rho[i] * rho[i]);
  }
  double drho[N] = {0.0}, power = 0.0, npairs = 0;
  for (int i = 0; i < N; i++)
    for (int j = i + 1; j < N; j++) {
      double del[3], dv[3];
      for (int d = 0; d < 3; d++) {
        del[d] = x[i][d] - x[j][d];
        dv[d] = v[i][d] - v[j][d];
      }
      const double r = std::sqrt(dot3(del, del));
      if (r >= 2.0 * s) continue;
      npairs++;
      const double wr = kernel_dwdr(r, s) / r;
      const double term = continuity_term(dv[0], dv[1], dv[2], del[0], del[1], del[2], wr);
      drho[i] += m[j] * term;
      drho[j] += m[i] * term;
      const double fp = sph_pressure_fpair(m[i], m[j], prho2[i], prho2[j], wr);
      power += fp * dot3(del, dv);    // F_i . v_i + F_j . v_j = F_ij . v_ij
    }
  double dE = 0.0, scale = 0.0;
  for (int i = 0; i < N; i++) {
    dE += m[i] * prho2[i] * drho[i];
    scale += std::fabs(m[i] * prho2[i] * drho[i]);
  }
  std::printf("%g pairs: pressure power %.12g, internal energy rate %.12g, sum %.2e (of %.6g)\n",
              npairs, power, dE, power + dE, scale);
  EXPECT_GT(npairs, 5);
  EXPECT_LT(std::fabs(power + dE), 1e-13 * scale);
}

// sum over a cubic lattice of spacing h (s/h = 2: the lattice sums of the kernel moments agree
// with the integrals to 5e-5; at the paper's h = s they are 2% off) around the origin of f(del)
// for every lattice point j != 0 within the support, del = x_0 - x_j
template <class F> static void lattice_sum(double s, double h, F &&f)
{
  const int n = (int) std::ceil(2.0 * s / h);
  for (int a = -n; a <= n; a++)
    for (int b = -n; b <= n; b++)
      for (int k = -n; k <= n; k++) {
        if (!a && !b && !k) continue;
        const double xj[3] = {a * h, b * h, k * h};
        const double r = std::sqrt(dot3(xj, xj));
        if (r >= 2.0 * s) continue;
        const double del[3] = {-xj[0], -xj[1], -xj[2]};
        f(xj, del, r);
      }
}

TEST(SPH, ContinuityOfUniformExpansionIsMinusRhoDivV)
{
  // Eq. 7 on a lattice at rest density with v = a x (div v = 3a): drho/dt = -rho div v = -3 a rho.
  // The SPH sum is -a m/h^3 sum_j h^3 r_j^2 W'(r_j)/r_j, the lattice quadrature of the kernel's
  // second moment (-3 exactly as an integral).
  const double s = 3.2, rho = 1.0, a = 0.01;
  for (const double hs : {0.5, 1.0}) {
    const double h = hs * s, m = rho * h * h * h;
    double rate = 0.0;
    lattice_sum(s, h, [&](const double *xj, const double *del, double r) {
      // v_0j = v_0 - v_j = -a x_j
      rate += m *
          continuity_term(-a * xj[0], -a * xj[1], -a * xj[2], del[0], del[1], del[2],
                          kernel_dwdr(r, s) / r);
    });
    const double expect = -3.0 * a * rho;
    std::printf("h/s %.1f: drho/dt %.10g  -rho div v %.10g  rel.err %.2e\n", hs, rate, expect,
                std::fabs(rate / expect - 1.0));
    if (hs == 0.5) EXPECT_NEAR(rate / expect, 1.0, 1e-4);
  }
}

TEST(Density, MassChangeKeepsParticleVolume)
{
  // Eq. 9 over a step: with no deformation (continuity rate 0) the mass taken up raises the density
  // at constant volume V = m / rho (Eq. 8); the continuity part is dt drho/dt.
  double rho = 1.0021, m = 33.3;
  const double V = m / rho;
  double worst = 0.0;
  for (double dm : {0.5, -0.2, 1e-6, 3.0, -1.7}) {
    rho += density_increment(rho, m, 0.0, 1e-3, dm);
    m += dm;
    worst = std::max(worst, std::fabs(m / rho / V - 1.0));
    std::printf("dm %8.2g: m %.10g rho %.12g  V = m/rho %.15g\n", dm, m, rho, m / rho);
  }
  EXPECT_LT(worst, 1e-15);
  EXPECT_EQ(density_increment(rho, m, 2.5, 1e-3, 0.0), 2.5e-3);
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

TEST(Water, SoluteKeepsPiTimesWater)
{
  // Eq. W1: a cell of 86000 pg water at Pi0 = -364 kPa; halving the water doubles |Pi|
  const double Pi0 = -364.0, W0 = 86000.0;
  for (double W : {86000.0, 43000.0, 17200.0, 172000.0}) {
    const double Pi = solute_osmotic_potential(Pi0, W0, W);
    std::printf("W = %8.0f pg: Pi = %9.3f kPa, Pi W / (Pi0 W0) - 1 = %.1e\n", W, Pi,
                Pi * W / (Pi0 * W0) - 1.0);
    EXPECT_NEAR(Pi * W, Pi0 * W0, 1e-15 * std::fabs(Pi0 * W0));
  }
  EXPECT_EQ(solute_osmotic_potential(Pi0, W0, W0), Pi0);
  EXPECT_EQ(solute_osmotic_potential(Pi0, W0, 0.5 * W0), 2.0 * Pi0);
}

TEST(Water, SeriesConductivityOfTwoWalls)
{
  EXPECT_EQ(series_conductivity(2.0, 2.0), 1.0);    // two equal walls: half of one
  EXPECT_NEAR(series_conductivity(1.0, 3.0), 0.75, 1e-15);
  EXPECT_EQ(series_conductivity(1.0, 3.0), series_conductivity(3.0, 1.0));
  EXPECT_EQ(series_conductivity(0.0, 5.0), 0.0);    // a closed wall stops the flow
  EXPECT_EQ(series_conductivity(5.0, 0.0), 0.0);
  // never more than the more closed of the two
  EXPECT_LT(series_conductivity(1e-9, 1e3), 1e-9);
}

TEST(Water, ExchangeStepIsW3AndEqualisesPotentials)
{
  // small k dt: the step is dt k (psi_a - psi_b); antisymmetric in the two cells
  const double k = 1e-6, dt = 1e-3, sa = 0.004, sb = 0.01;
  const double d = exchange_mass_step(k, dt, -100.0, -364.0, sa, sb);
  std::printf("small k dt: step %.10e, dt k dpsi %.10e\n", d, dt * k * 264.0);
  EXPECT_NEAR(d, dt * k * 264.0, 1e-8 * d);
  EXPECT_GT(d, 0.0);    // water moves to the lower potential
  EXPECT_EQ(exchange_mass_step(k, dt, -364.0, -100.0, sb, sa), -d);
  EXPECT_EQ(exchange_mass_step(k, dt, -200.0, -200.0, sa, sb), 0.0);
  // two cells of linear potentials psi = psi0 + s M: any k dt never overshoots and, for a huge one,
  // lands on the common potential in one step (exact for linear potentials)
  for (double kdt : {1e-3, 1.0, 1e3, 1e12}) {
    double Ma = 0.0, Mb = 0.0;
    const double pa0 = -100.0, pb0 = -364.0;
    double gap = pa0 - pb0;
    for (int n = 0; n < 20; n++) {
      const double m = exchange_mass_step(kdt, 1.0, pa0 + sa * Ma, pb0 + sb * Mb, sa, sb);
      Ma -= m;
      Mb += m;
      const double g = (pa0 + sa * Ma) - (pb0 + sb * Mb);
      // round-off of the potentials (1e-13 kPa) once the gap has closed
      EXPECT_GE(g, -1e-12) << "overshoot at k dt " << kdt;
      EXPECT_LE(std::fabs(g), std::fabs(gap) + 1e-12);
      gap = g;
    }
    EXPECT_EQ(Ma + Mb, 0.0);    // what a loses b gains
    std::printf("k dt %.0e: potential gap after 20 steps %.3e kPa (from 264)\n", kdt, gap);
    if (kdt >= 1e3) EXPECT_LT(std::fabs(gap), 1e-9);
  }
}

TEST(Water, ExposedAreaIsWallLessGluedPart)
{
  // a cube-like cell of rest area 600 with 100 glued, stretched to 720 (areal stretch 1.2)
  EXPECT_NEAR(exposed_area(720.0, 600.0, 100.0), 600.0, 1e-12);
  EXPECT_EQ(exposed_area(720.0, 600.0, 0.0), 720.0);    // a free cell: its whole wall
  EXPECT_EQ(exposed_area(720.0, 600.0, 600.0), 0.0);    // fully glued: nothing exposed
  EXPECT_EQ(exposed_area(720.0, 600.0, 650.0), 0.0);    // never negative
  EXPECT_EQ(exposed_area(720.0, 0.0, 0.0), 720.0);      // no rest shape known
}

TEST(Water, HidesTriangleInFrontOnly)
{
  // a triangle of longest edge h = 4 at the origin, facing +z
  const double n[3] = {0.0, 0.0, 1.0}, h = 4.0;
  auto at = [&](double x, double y, double z) {
    const double d[3] = {x, y, z};
    return hides_triangle(d, n, h);
  };
  EXPECT_TRUE(at(0.0, 0.0, 2.56));     // the glued neighbour's node straight ahead
  EXPECT_FALSE(at(0.0, 0.0, -2.56));   // behind: the cell's own side
  EXPECT_FALSE(at(0.0, 0.0, 0.0));     // in its plane
  EXPECT_FALSE(at(5.0, 0.0, 0.0));
  // near the wall, within h of the normal line: a facing wall's nodes 3.3-5.5 apart are not missed
  EXPECT_TRUE(at(3.9, 0.0, 1.0));
  EXPECT_FALSE(at(4.1, 0.0, 1.0));
  // further out, within 45 degrees of the normal
  EXPECT_TRUE(at(6.0, 0.0, 6.0));
  EXPECT_TRUE(at(5.9, 0.0, 6.0));
  EXPECT_FALSE(at(6.1, 0.0, 6.0));
  EXPECT_FALSE(at(0.0, 9.0, 8.0));
  // a normal tilted by 45 degrees
  const double m[3] = {std::sqrt(0.5), 0.0, std::sqrt(0.5)}, d[3] = {10.0, 0.0, 0.0};
  EXPECT_TRUE(hides_triangle(d, m, h));    // exactly on the 45-degree cone
  const double e[3] = {-1.0, 0.0, 10.0};
  EXPECT_FALSE(hides_triangle(e, m, h));    // s = 6.4, off the normal line by 7.8
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

TEST(Geometry, ConeVolumesAndAreasOfAClosedMesh)
{
  // the regular octahedron of vertices +-e_x, +-e_y, +-e_z, triangles in right-hand order seen
  // from outside: volume 4/3, area 8 (sqrt3/2) = 4 sqrt3, whatever the origin of the cones
  const double P[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const int T[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                       {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (const double shift : {0.0, 0.3, -7.0}) {
    double vol = 0.0, area = 0.0;
    for (const auto &t : T) {
      double a[3], u[3], w[3];
      for (int d = 0; d < 3; d++) {
        a[d] = P[t[0]][d] + shift * (d + 1);
        u[d] = P[t[1]][d] - P[t[0]][d];
        w[d] = P[t[2]][d] - P[t[0]][d];
      }
      vol += cone_volume(a, u, w);
      area += triangle_area(u, w);
    }
    std::printf(
        "origin shifted by %4.1f (1,2,3): volume %.15g (4/3)  area %.15g (4 sqrt3 = %.15g)\n",
        shift, vol, area, 4.0 * std::sqrt(3.0));
    EXPECT_NEAR(vol, 4.0 / 3.0, 1e-14);
    EXPECT_NEAR(area, 4.0 * std::sqrt(3.0), 1e-14);
  }
}

TEST(Equator, BondShareIsEq23)
{
  // a bond of tension T (force on node 1 = fpair (x1 - x2), fpair = -T / l) at angle theta to
  // the plane's normal carries T cos(theta) across it, the same whichever node is called 1,
  // positive in tension, and nothing when both nodes are on one side
  const double T = 2.5, l = 1.7;
  for (const double theta : {0.0, 0.4, 1.2}) {
    const double fpair = -T / l, dn = l * std::cos(theta);
    const double s1 = 0.3 * dn, s2 = s1 - dn;    // node 1 above, node 2 below
    const double f12 = equatorial_force_term(fpair, dn, s1, s2);
    const double f21 = equatorial_force_term(fpair, -dn, s2, s1);
    std::printf("theta %.1f: share %.15g  T cos(theta) %.15g  swapped %.15g\n", theta, f12,
                T * std::cos(theta), f21);
    EXPECT_NEAR(f12, T * std::cos(theta), 1e-15 * T);
    EXPECT_EQ(f21, f12);
    EXPECT_EQ(equatorial_force_term(-fpair, dn, s1, s2), -f12);    // compression: negative
    EXPECT_EQ(equatorial_force_term(fpair, dn, s1 + 2.0 * dn, s2 + 2.0 * dn), 0.0);
  }
  // a node exactly on the plane belongs to the lower side (s > 0 is the hemisphere)
  EXPECT_TRUE(crosses_equator(0.5, 0.0));
  EXPECT_FALSE(crosses_equator(0.0, -0.5));
}

TEST(Equator, TriangleShareIsSumOfEdgeShares)
{
  // node forces made of three pair forces along the edges (any in-plane force system of a
  // triangle with zero sum and zero moment is one): the triangle's share of Eq. 23 must be the
  // sum of the three bonds' shares, for every way the plane can cut it, and zero when it does not
  const double x[3][3] = {{0.3, -0.2, 0.9}, {-0.8, 0.5, 0.1}, {0.4, 0.7, -0.6}};
  const double p[3] = {-1.3, 0.4, -2.2};    // pair factors of edges 0-1, 1-2, 2-0
  const double n[3] = {0.36, 0.48, 0.8};
  double f[3][3] = {};
  for (int e = 0; e < 3; e++) {
    const int i = e, j = (e + 1) % 3;
    for (int d = 0; d < 3; d++) {
      f[i][d] += p[e] * (x[i][d] - x[j][d]);
      f[j][d] -= p[e] * (x[i][d] - x[j][d]);
    }
  }
  for (const double h : {-2.0, -0.5, 0.0, 0.2, 0.6, 2.0}) {
    double s[3];
    for (int k = 0; k < 3; k++) s[k] = x[k][0] * n[0] + x[k][1] * n[1] + x[k][2] * n[2] - h;
    double edges = 0.0;
    for (int e = 0; e < 3; e++) {
      const int i = e, j = (e + 1) % 3;
      double dn = 0.0;
      for (int d = 0; d < 3; d++) dn += (x[i][d] - x[j][d]) * n[d];
      edges += equatorial_force_term(p[e], dn, s[i], s[j]);
    }
    const double tri = equatorial_force_triangle(f, s, n);
    std::printf("plane at %4.1f: triangle share %.15g, sum of edge shares %.15g\n", h, tri, edges);
    EXPECT_NEAR(tri, edges, 1e-14);
  }
  const double above[3] = {1.0, 2.0, 3.0}, below[3] = {-1.0, -2.0, -3.0};
  EXPECT_NEAR(equatorial_force_triangle(f, above, n), 0.0, 1e-14);
  EXPECT_EQ(equatorial_force_triangle(f, below, n), 0.0);
}

TEST(Shear, LinearShearFlowGivesMuGammaDot)
{
  // Eqs. 24-26 on a lattice at rest density in the shear flow v = (gd y, 0, 0): tau_xy = mu gd,
  // tau_xz = tau_yz = 0, tau = mu gd. A rigid rotation v = w x x has no shear stress at all.
  const double s = 3.2, rho = 1.0, mu = 1.0, gd = 0.02, h = 0.5 * s, m = rho * h * h * h;
  double g[3][3] = {{0.0}}, grot[3][3] = {{0.0}};
  const double w[3] = {0.01, -0.02, 0.03};
  lattice_sum(s, h, [&](const double *xj, const double *del, double r) {
    const double wj = m / rho * kernel_dwdr(r, s) / r;
    const double vji[3] = {gd * xj[1], 0.0, 0.0};    // v_j - v_0, v_0 = 0
    velocity_gradient_add(g, wj, del, vji);
    const double vrot[3] = {w[1] * xj[2] - w[2] * xj[1], w[2] * xj[0] - w[0] * xj[2],
                            w[0] * xj[1] - w[1] * xj[0]};
    velocity_gradient_add(grot, wj, del, vrot);
  });
  const double txy = viscous_shear(mu, g, 0, 1), txz = viscous_shear(mu, g, 0, 2),
               tyz = viscous_shear(mu, g, 1, 2);
  const double tau = shear_stress_magnitude(txy, txz, tyz);
  std::printf(
      "shear: tau_xy %.10g  mu gd %.10g  rel.err %.2e  tau_xz %.2g tau_yz %.2g  tau %.10g\n", txy,
      mu * gd, std::fabs(txy / (mu * gd) - 1.0), txz, tyz, tau);
  EXPECT_NEAR(txy / (mu * gd), 1.0, 1e-4);    // lattice quadrature at h = s/2, as above
  EXPECT_LT(std::fabs(txz) + std::fabs(tyz), 1e-15 * mu * gd);
  EXPECT_EQ(tau, std::fabs(txy) * std::sqrt(1.0 + (txz * txz + tyz * tyz) / (txy * txy)));
  double rot = 0.0;
  for (int a = 0; a < 3; a++)
    for (int b = a + 1; b < 3; b++) rot = std::max(rot, std::fabs(viscous_shear(mu, grot, a, b)));
  std::printf("rigid rotation: largest |tau_ab| %.2e (mu |w| = %.2e)\n", rot,
              mu * std::sqrt(dot3(w, w)));
  EXPECT_LT(rot, 1e-15);
  EXPECT_EQ(shear_stress_magnitude(3.0, 4.0, 12.0), 13.0);
}

/* ---------------------------------------------------------------------
   Membrane element (Eqs. M1-M2): one triangle against the closed-form
   incompressible Neo-Hookean sheet, the finite-difference gradient, rigid
   motion and degenerate shapes. The reference triangle is not equilateral
   and sits turned in space, so nothing rests on a special orientation.
------------------------------------------------------------------------ */

namespace {

// a general rotation (axis (1,2,3)/|.|, 0.7 rad) so that no test sits in a coordinate plane
void rotate(const double in[3], double out[3])
{
  double k[3] = {1, 2, 3};
  const double kn = std::sqrt(14.0);
  for (double &e : k) e /= kn;
  const double th = 0.7, c = std::cos(th), s = std::sin(th);
  const double kd = k[0] * in[0] + k[1] * in[1] + k[2] * in[2];
  const double kx[3] = {k[1] * in[2] - k[2] * in[1], k[2] * in[0] - k[0] * in[2],
                        k[0] * in[1] - k[1] * in[0]};
  for (int d = 0; d < 3; d++) out[d] = in[d] * c + kx[d] * s + k[d] * kd * (1 - c);
}

struct Tri {
  double X[3][3];    // reference nodes a, b, c
  double x[3][3];    // current nodes
};

// reference triangle in the plane z = 0 (not equilateral), current = rotate(F2 X) + shift
Tri make(const double F2[2][2])
{
  const double P[3][2] = {{2.7, 0.4}, {0.3, -0.2}, {1.1, 2.2}};
  Tri t;
  for (int n = 0; n < 3; n++) {
    const double R[3] = {P[n][0], P[n][1], 0.0};
    rotate(R, t.X[n]);
    const double y[3] = {F2[0][0] * P[n][0] + F2[0][1] * P[n][1],
                         F2[1][0] * P[n][0] + F2[1][1] * P[n][1], 0.0};
    rotate(y, t.x[n]);
    for (int d = 0; d < 3; d++) t.x[n][d] += 5.0 + d;
    // the reference too sits somewhere else and turned another way: only shapes matter
  }
  return t;
}

void evaluate(const Tri &t, double &E, double f[3][3], double &area, bool relax = false)
{
  double A[3], C[3], a[3], c[3];
  for (int d = 0; d < 3; d++) {
    A[d] = t.X[0][d] - t.X[1][d];
    C[d] = t.X[2][d] - t.X[1][d];
    a[d] = t.x[0][d] - t.x[1][d];
    c[d] = t.x[2][d] - t.x[1][d];
  }
  MembraneRest rest;
  ASSERT_TRUE(membrane_rest(A, C, rest));
  MembraneStrain s;
  membrane_strain(rest, a, c, s);
  E = membrane_energy(G, T0, rest, s, relax);
  membrane_forces(G, T0, rest, s, f[0], f[2], relax);
  for (int d = 0; d < 3; d++) f[1][d] = -f[0][d] - f[2][d];
  const double n[3] = {a[1] * c[2] - a[2] * c[1], a[2] * c[0] - a[0] * c[2], a[0] * c[1] - a[1] * c[0]};
  area = 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// membrane tension tensor (force per current length) from the virial: T = -sum x (x) f / area,
// in the rotated frame's in-plane axes
void tension(const Tri &t, const double f[3][3], double area, double T[2][2])
{
  double W[3][3] = {};
  for (int n = 0; n < 3; n++)
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) W[i][j] += t.x[n][i] * f[n][j];
  double ex[3], ey[3];
  const double ux[3] = {1, 0, 0}, uy[3] = {0, 1, 0};
  rotate(ux, ex);
  rotate(uy, ey);
  const double *e[2] = {ex, ey};
  for (int p = 0; p < 2; p++)
    for (int q = 0; q < 2; q++) {
      double s = 0;
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) s += e[p][i] * W[i][j] * e[q][j];
      T[p][q] = -s / area;
    }
}

double A0()
{
  const double P[3][2] = {{2.7, 0.4}, {0.3, -0.2}, {1.1, 2.2}};
  return 0.5 * std::fabs((P[0][0] - P[1][0]) * (P[2][1] - P[1][1]) - (P[0][1] - P[1][1]) * (P[2][0] - P[1][0]));
}

// largest |force + central-difference energy gradient (step 1e-5)| over the nine components of
// triangle t, relative to its largest force; show prints each component
double gradient_error(const Tri &t, bool relax, bool show)
{
  double E, f[3][3], area;
  evaluate(t, E, f, area, relax);
  double worst = 0, fmax = 0;
  for (auto &r : f) for (double v : r) fmax = std::max(fmax, std::fabs(v));
  for (int n = 0; n < 3; n++)
    for (int d = 0; d < 3; d++) {
      const double h = 1e-5;
      Tri p = t, m = t;
      p.x[n][d] += h;
      m.x[n][d] -= h;
      double Ep, Em, fp[3][3], ap;
      evaluate(p, Ep, fp, ap, relax);
      evaluate(m, Em, fp, ap, relax);
      const double fd = -(Ep - Em) / (2 * h);
      worst = std::max(worst, std::fabs(fd - f[n][d]) / fmax);
      if (show) std::printf("node %d dir %d  force %.12g  -dE/dx %.12g\n", n, d, f[n][d], fd);
    }
  return worst;
}

}    // namespace

TEST(MembraneElement, ClosedForms)
{
  const double Gt = G * T0;
  for (double lam : {0.9, 1.0, 1.05, 1.2, 1.5}) {
    struct Case { const char *name; double F2[2][2]; double W, T11, T22, T12; };
    const double l3e = 1.0 / (lam * lam), l3u = 1.0 / std::sqrt(lam), l3f = 1.0 / lam;
    const double g = lam - 1.0;    // shear amount
    Case cases[] = {
      {"equibiaxial", {{lam, 0}, {0, lam}}, 2 * lam * lam + l3e * l3e - 3,
       Gt * (lam * lam - l3e * l3e) * l3e, Gt * (lam * lam - l3e * l3e) * l3e, 0},
      {"uniaxial, sides free", {{lam, 0}, {0, 1 / std::sqrt(lam)}}, lam * lam + 2 / lam - 3,
       Gt * (lam * lam - l3u * l3u) * l3u, 0, 0},
      {"uniaxial, sides fixed", {{lam, 0}, {0, 1}}, lam * lam + 1 + l3f * l3f - 3,
       Gt * (lam * lam - l3f * l3f) * l3f, Gt * (1 - l3f * l3f) * l3f, 0},
      {"simple shear", {{1, g}, {0, 1}}, g * g, Gt * g * g, 0, Gt * g},
    };
    for (auto &k : cases) {
      Tri t = make(k.F2);
      double E, f[3][3], area, T[2][2];
      evaluate(t, E, f, area);
      tension(t, f, area, T);
      const double Wexp = 0.5 * Gt * A0() * k.W;
      const double scale = Gt;    // tension scale for the absolute error of zero components
      const double eW = std::fabs(E - Wexp) / (0.5 * Gt * A0() * std::max(std::fabs(k.W), 1e-300));
      const double e11 = std::fabs(T[0][0] - k.T11) / scale, e22 = std::fabs(T[1][1] - k.T22) / scale;
      const double e12 = std::fabs(T[0][1] - k.T12) / scale, e21 = std::fabs(T[1][0] - k.T12) / scale;
      std::printf("%-22s lam %.2f  W %.10g (closed %.10g)  T11 %.8g (%.8g)  T22 %.8g (%.8g)  T12 %.8g (%.8g)\n",
                  k.name, lam, E, Wexp, T[0][0], k.T11, T[1][1], k.T22, T[0][1], k.T12);
      if (std::fabs(k.W) > 1e-12) EXPECT_LT(eW, 1e-9) << k.name;
      else EXPECT_LT(std::fabs(E), 1e-12 * Gt * A0()) << k.name;
      EXPECT_LT(std::max({e11, e22, e12, e21}), 1e-12) << k.name;
    }
  }
}

TEST(MembraneElement, ForcesAreMinusEnergyGradient)
{
  const double F2[2][2] = {{1.13, 0.21}, {-0.08, 0.91}};
  Tri t = make(F2);
  t.x[2][2] += 0.3;    // and out of the plane
  const double worst = gradient_error(t, false, true);
  std::printf("largest difference / largest force %.2e\n", worst);
  EXPECT_LT(worst, 1e-8);
}

TEST(MembraneElement, RigidMotionIsFree)
{
  const double I2[2][2] = {{1, 0}, {0, 1}};
  Tri t = make(I2);    // reference and current differ by a rotation and a shift only
  double E, f[3][3], area;
  evaluate(t, E, f, area);
  double fm = 0;
  for (auto &r : f) for (double v : r) fm = std::max(fm, std::fabs(v));
  std::printf("rigid motion: energy %.3g, largest force %.3g (scale G t0 = %.3g)\n", E, fm, G * T0);
  EXPECT_LT(std::fabs(E), 1e-12 * G * T0 * A0());
  EXPECT_LT(fm, 1e-12 * G * T0);
}

TEST(MembraneElement, ConservesAngularMomentum)
{
  const double F2[2][2] = {{1.3, 0.4}, {0.1, 0.8}};
  Tri t = make(F2);
  t.x[0][0] += 0.5;
  double E, f[3][3], area, L[3] = {}, fsum[3] = {};
  evaluate(t, E, f, area);
  for (int n = 0; n < 3; n++) {
    L[0] += t.x[n][1] * f[n][2] - t.x[n][2] * f[n][1];
    L[1] += t.x[n][2] * f[n][0] - t.x[n][0] * f[n][2];
    L[2] += t.x[n][0] * f[n][1] - t.x[n][1] * f[n][0];
    for (int d = 0; d < 3; d++) fsum[d] += f[n][d];
  }
  const double Lm = std::max({std::fabs(L[0]), std::fabs(L[1]), std::fabs(L[2])});
  std::printf("torque %.3g, force sum %.3g (forces ~%.3g)\n", Lm, fsum[0], std::fabs(f[0][0]));
  EXPECT_LT(Lm, 1e-9 * G * T0 * 10);
}

TEST(MembraneElement, DegenerateReference)
{
  const double A[3] = {1, 0, 0}, C[3] = {2, 0, 0}, Z[3] = {0, 0, 0};
  MembraneRest rest;
  EXPECT_FALSE(membrane_rest(A, C, rest));
  EXPECT_FALSE(membrane_rest(Z, C, rest));
  const double A2[3] = {1, 0, 0}, C2[3] = {0, 1, 0};
  ASSERT_TRUE(membrane_rest(A2, C2, rest));
  MembraneStrain s;
  const double a[3] = {1, 0, 0}, c[3] = {2, 0, 0};    // collapsed onto a line
  membrane_strain(rest, a, c, s);
  std::printf("collapsed triangle: det C2 = %g\n", s.J2);
  EXPECT_EQ(s.J2, 0.0);
}

TEST(MembraneElement, PrincipalStretches)
{
  const double F2[2][2] = {{1.3, 0}, {0, 0.9}};
  Tri t = make(F2);
  double A[3], C[3], a[3], c[3];
  for (int d = 0; d < 3; d++) {
    A[d] = t.X[0][d] - t.X[1][d]; C[d] = t.X[2][d] - t.X[1][d];
    a[d] = t.x[0][d] - t.x[1][d]; c[d] = t.x[2][d] - t.x[1][d];
  }
  MembraneRest rest; membrane_rest(A, C, rest);
  MembraneStrain s; membrane_strain(rest, a, c, s);
  double l1, l2; membrane_stretches(s, l1, l2);
  std::printf("principal stretches %.15g %.15g\n", l1, l2);
  EXPECT_NEAR(l1, 1.3, 1e-13);
  EXPECT_NEAR(l2, 0.9, 1e-13);
}

/* ---------------------------------------------------------------------
   Tension-field membrane (Eq. M3, angle_coeff ... wrinkle yes): Pipkin's
   relaxed energy. Taut states are those of Eq. M1; a wrinkled one carries
   the uniaxial tension of its major stretch only; a slack one nothing.
------------------------------------------------------------------------ */

TEST(MembraneElement, TensionFieldClosedForms)
{
  const double Gt = G * T0;
  const double g = 0.4, l1s = 0.5 * g + std::sqrt(1.0 + 0.25 * g * g);    // simple shear's lam1
  struct Case { const char *name; double F2[2][2]; double l1, l2; bool wrinkled; };
  const Case cases[] = {
      {"equibiaxial 1.1 (taut)", {{1.1, 0}, {0, 1.1}}, 1.1, 1.1, false},
      {"sides fixed 1.3 (taut)", {{1.3, 0}, {0, 1}}, 1.3, 1.0, false},
      {"stretch 1.3, width 0.8 (wrinkled)", {{1.3, 0}, {0, 0.8}}, 1.3, 0.8, true},
      {"stretch 1.05, width 0.5 (wrinkled)", {{1.05, 0}, {0, 0.5}}, 1.05, 0.5, true},
      {"simple shear 0.4 (wrinkled)", {{1, g}, {0, 1}}, l1s, 1 / l1s, true},
  };
  for (const auto &k : cases) {
    Tri t = make(k.F2);
    double E, f[3][3], area, T[2][2], Ef, ff[3][3];
    evaluate(t, E, f, area, true);
    evaluate(t, Ef, ff, area, false);
    tension(t, f, area, T);
    const double l1 = k.l1, l2 = k.l2;
    double Wexp, Tmaj;    // energy per G t0 A0 / 2, and the tension along the major stretch
    if (k.wrinkled) {
      Wexp = l1 * l1 + 2 / l1 - 3;
      Tmaj = Gt * (l1 - 1 / (l1 * l1)) / l2;    // dW/dlam1 per reference width, per current width
    } else {    // Eq. M1, whose tensions ClosedForms checks
      Wexp = l1 * l1 + l2 * l2 + 1 / (l1 * l1 * l2 * l2) - 3;
      Tmaj = 0;
    }
    // the principal tensions of T (symmetric 2x2)
    const double tr = T[0][0] + T[1][1], dif = T[0][0] - T[1][1];
    const double root = std::sqrt(0.25 * dif * dif + T[0][1] * T[1][0]);
    const double Tmax = 0.5 * tr + root, Tmin = 0.5 * tr - root;
    const double Wc = 0.5 * Gt * A0() * Wexp;
    std::printf("%-36s W %.10g (closed %.10g, full sheet %.10g)  T_major %.8g  T_minor %.3g\n",
                k.name, E, Wc, Ef, Tmax, Tmin);
    EXPECT_LT(std::fabs(E / Wc - 1), 1e-12) << k.name;
    if (k.wrinkled) {
      EXPECT_LT(std::fabs(Tmax / Tmaj - 1), 1e-12) << k.name;
      EXPECT_LT(std::fabs(Tmin), 1e-12 * Gt) << k.name;
      EXPECT_LT(E, Ef) << k.name;    // relaxing never costs: the wrinkled sheet is softer
    } else {
      EXPECT_EQ(E, Ef) << k.name;
      for (int n = 0; n < 3; n++)
        for (int d = 0; d < 3; d++) EXPECT_EQ(f[n][d], ff[n][d]) << k.name;
    }
  }
}

TEST(MembraneElement, TensionFieldSlackAndContinuity)
{
  // slack: shortened in every direction, nothing stored and no force
  const double S[2][2] = {{0.95, 0.02}, {0.0, 0.7}};
  Tri t = make(S);
  double E, f[3][3], area;
  evaluate(t, E, f, area, true);
  double fm = 0;
  for (auto &r : f) for (double v : r) fm = std::max(fm, std::fabs(v));
  std::printf("slack: energy %g, largest force %g\n", E, fm);
  EXPECT_EQ(E, 0.0);
  EXPECT_EQ(fm, 0.0);
  // across the taut/wrinkled boundary lam2 = lam1^-1/2 and the slack one lam1 = 1, energy and
  // forces are continuous: a step of 1e-9 in the stretch changes them by O(1e-9)
  const double h = 1e-9, w = 1 / std::sqrt(1.2);
  const double pairs[2][2][2][2] = {
      {{{1 - h, 0}, {0, 0.9}}, {{1 + h, 0}, {0, 0.9}}},    // slack | wrinkled at lam1 = 1
      {{{1.2, 0}, {0, w - h}}, {{1.2, 0}, {0, w + h}}},    // wrinkled | taut at lam1 = 1.2
  };
  for (const auto &Fab : pairs) {
    const auto &Fa = Fab[0], &Fb = Fab[1];
    const double l1 = Fa[0][0];
    double Ea, fa[3][3], Eb, fb[3][3];
    evaluate(make(Fa), Ea, fa, area, true);
    evaluate(make(Fb), Eb, fb, area, true);
    double df = 0, fs = G * T0 * std::sqrt(A0());
    for (int n = 0; n < 3; n++)
      for (int d = 0; d < 3; d++) df = std::max(df, std::fabs(fa[n][d] - fb[n][d]));
    std::printf("boundary at lam1 = %g: energy jump %.3g, force jump %.3g (scale %.3g)\n", l1,
                std::fabs(Ea - Eb), df, fs);
    EXPECT_LT(std::fabs(Ea - Eb), 1e-8 * G * T0 * A0());
    EXPECT_LT(df, 1e-7 * fs);
  }
}

TEST(MembraneElement, TensionFieldForcesAreMinusEnergyGradient)
{
  // one wrinkled and one taut state, turned and sheared, out of the plane
  const double Fw[2][2] = {{1.25, 0.15}, {-0.05, 0.7}};
  const double Ft[2][2] = {{1.13, 0.05}, {-0.02, 1.08}};
  for (const auto *F2 : {Fw, Ft}) {
    const bool wrinkled = F2 == Fw;
    Tri t = make(F2);
    t.x[2][2] += 0.1;
    double E, f[3][3], area, Efull, ff[3][3];
    evaluate(t, E, f, area, true);
    evaluate(t, Efull, ff, area, false);
    const double worst = gradient_error(t, true, false);
    std::printf("%s state: energy %.10g (full sheet %.10g), largest difference / largest force "
                "%.2e\n", wrinkled ? "wrinkled" : "taut", E, Efull, worst);
    if (wrinkled) EXPECT_LT(E, Efull);
    else EXPECT_EQ(E, Efull);
    EXPECT_LT(worst, 1e-8);
  }
}

/* ---------------------------------------------------------------------
   Bending hinge (Eqs. B1-B3, dihedral style cell/bending)
------------------------------------------------------------------------ */

namespace {

// positions of a hinge's nodes i, j, k, l -> the edge vectors of hinge_angle
void hinge_edges(const double x[4][3], double b1[3], double b2[3], double b3[3])
{
  for (int d = 0; d < 3; d++) {
    b1[d] = x[0][d] - x[1][d];
    b2[d] = x[2][d] - x[1][d];
    b3[d] = x[3][d] - x[2][d];
  }
}

double hinge_W(double D, const double X[4][3], const double x[4][3])
{
  double B1[3], B2[3], B3[3], b1[3], b2[3], b3[3], phi;
  HingeRest rest;
  hinge_edges(X, B1, B2, B3);
  hinge_edges(x, b1, b2, b3);
  if (!hinge_rest(B1, B2, B3, rest) || !hinge_angle(b1, b2, b3, phi)) return NAN;
  return hinge_energy(D, rest, phi);
}

void hinge_F(double D, const double X[4][3], const double x[4][3], double f[4][3])
{
  double B1[3], B2[3], B3[3], b1[3], b2[3], b3[3], phi, grad[4][3];
  HingeRest rest;
  hinge_edges(X, B1, B2, B3);
  hinge_edges(x, b1, b2, b3);
  ASSERT_TRUE(hinge_rest(B1, B2, B3, rest));
  ASSERT_TRUE(hinge_angle(b1, b2, b3, phi, grad));
  hinge_forces(D, rest, phi, grad, f);
}

// a flat rest hinge (edge j-k of length L along x, i and l at distances hi, hl on either side),
// turned to a general orientation; the current one has l rotated about the edge by theta
void flat_hinge(double L, double hi, double hl, double theta, double X[4][3], double x[4][3])
{
  const double P[4][3] = {{0.3 * L, hi, 0}, {0, 0, 0}, {L, 0, 0}, {0.6 * L, -hl, 0}};
  const double Q[4][3] = {{0.3 * L, hi, 0}, {0, 0, 0}, {L, 0, 0},
                          {0.6 * L, -hl * std::cos(theta), hl * std::sin(theta)}};
  for (int n = 0; n < 4; n++) {
    rotate(P[n], X[n]);
    rotate(Q[n], x[n]);
    for (int d = 0; d < 3; d++) x[n][d] += 1.5 - d;
  }
}

}    // namespace

TEST(BendingHinge, StiffnessIsPlateWithNuHalf)
{
  const double E = 3.0 * G, nu = 0.5;
  const double D = E * T0 * T0 * T0 / (12.0 * (1.0 - nu * nu));
  std::printf("D = %.15g (plate), bending_stiffness = %.15g\n", D, bending_stiffness(G, T0));
  EXPECT_NEAR(bending_stiffness(G, T0) / D, 1.0, 1e-15);
}

TEST(BendingHinge, ClosedFormOfOneHinge)
{
  // W = (D / 2) theta^2 L^2 / A0 with A0 = L (hi + hl) / 2 for a flat rest hinge folded by theta
  const double D = bending_stiffness(G, T0), L = 2.5, hi = 2.1, hl = 1.7;
  for (double theta : {-2.5, -0.3, 1e-4, 0.2, 1.0, 3.0}) {
    double X[4][3], x[4][3];
    flat_hinge(L, hi, hl, theta, X, x);
    const double W = hinge_W(D, X, x);
    const double Wexp = 0.5 * D * theta * theta * L * L / (0.5 * L * (hi + hl));
    // the angle is known to a few ulp of pi (the rotated nodes and atan2 near pi), so the angle
    // the energy implies is compared absolutely, the energy itself relatively where theta is large
    const double theta_W = std::sqrt(W * 0.5 * L * (hi + hl) / (0.5 * D * L * L));
    std::printf("theta %6.3g: W %.15g, closed form %.15g, angle from W off by %.2g rad\n", theta,
                W, Wexp, theta_W - std::fabs(theta));
    EXPECT_NEAR(theta_W, std::fabs(theta), 1e-14);
    if (std::fabs(theta) >= 0.2) EXPECT_NEAR(W / Wexp, 1.0, 1e-13);
    // the rest angle of a flat hinge is pi, its current one pi - theta (mod 2 pi)
    double b1[3], b2[3], b3[3], phi;
    hinge_edges(x, b1, b2, b3);
    ASSERT_TRUE(hinge_angle(b1, b2, b3, phi));
    EXPECT_NEAR(std::fabs(hinge_deviation(phi, M_PI)), std::fabs(theta), 1e-12);
  }
}

TEST(BendingHinge, ForcesAreMinusEnergyGradient)
{
  const double D = bending_stiffness(G, T0);
  // a curved rest hinge (as on a sphere) and a current shape bent, stretched and sheared
  const double X[4][3] = {{0.4, 2.0, 0.3}, {0.0, 0.0, 0.0}, {2.4, 0.1, -0.1}, {1.5, -1.9, 0.5}};
  double x[4][3];
  const double dx[4][3] = {{0.1, -0.2, 0.4}, {0.05, 0.1, -0.1}, {-0.2, 0.1, 0.15}, {0.3, 0.2, -0.6}};
  for (int n = 0; n < 4; n++)
    for (int d = 0; d < 3; d++) x[n][d] = X[n][d] + dx[n][d];
  double f[4][3];
  hinge_F(D, X, x, f);
  double fmax = 0.0, err = 0.0;
  const double h = 1e-6;
  for (int n = 0; n < 4; n++)
    for (int d = 0; d < 3; d++) {
      double xp[4][3], xm[4][3];
      std::copy(&x[0][0], &x[0][0] + 12, &xp[0][0]);
      std::copy(&x[0][0], &x[0][0] + 12, &xm[0][0]);
      xp[n][d] += h;
      xm[n][d] -= h;
      const double fd = -(hinge_W(D, X, xp) - hinge_W(D, X, xm)) / (2.0 * h);
      fmax = std::max(fmax, std::fabs(f[n][d]));
      err = std::max(err, std::fabs(f[n][d] - fd));
    }
  std::printf("hinge W %.6g, largest force %.6g, largest |f + dW/dx| %.3g (relative %.3g)\n",
              hinge_W(D, X, x), fmax, err, err / fmax);
  EXPECT_GT(fmax, 0.0);
  EXPECT_LT(err / fmax, 1e-8);
}

TEST(BendingHinge, RigidMotionIsFree)
{
  const double D = bending_stiffness(G, T0);
  // the rest hinge turned and moved: no energy, no force
  double X[4][3], x[4][3];
  flat_hinge(2.5, 2.1, 1.7, 0.0, X, x);
  double f[4][3];
  hinge_F(D, X, x, f);
  double fmax = 0.0;
  for (auto &fn : f)
    for (double c : fn) fmax = std::max(fmax, std::fabs(c));
  const double W = hinge_W(D, X, x);
  std::printf("rigidly moved rest hinge: W %.3g, largest force %.3g (D %.6g)\n", W, fmax, D);
  EXPECT_LT(W, 1e-24 * D);
  EXPECT_LT(fmax, 1e-12 * D);
  // a bent hinge: its forces have no net force and no net torque (angular momentum conserved)
  flat_hinge(2.5, 2.1, 1.7, 0.8, X, x);
  hinge_F(D, X, x, f);
  double F[3] = {0, 0, 0}, M[3] = {0, 0, 0};
  for (int n = 0; n < 4; n++) {
    for (int d = 0; d < 3; d++) F[d] += f[n][d];
    M[0] += x[n][1] * f[n][2] - x[n][2] * f[n][1];
    M[1] += x[n][2] * f[n][0] - x[n][0] * f[n][2];
    M[2] += x[n][0] * f[n][1] - x[n][1] * f[n][0];
  }
  const double scale = std::fabs(f[0][0]) + std::fabs(f[0][1]) + std::fabs(f[0][2]);
  std::printf("bent hinge: net force %.3g %.3g %.3g, net torque %.3g %.3g %.3g (forces ~%.3g)\n",
              F[0], F[1], F[2], M[0], M[1], M[2], scale);
  for (int d = 0; d < 3; d++) {
    EXPECT_LT(std::fabs(F[d]), 1e-13 * scale);
    EXPECT_LT(std::fabs(M[d]), 1e-12 * scale);
  }
}

TEST(BendingHinge, FoldingThroughIsContinuous)
{
  // a flat hinge folded by theta and by theta - 2 pi is the same shape: the same energy
  const double D = bending_stiffness(G, T0);
  double X[4][3], x[4][3], x2[4][3];
  flat_hinge(2.5, 2.1, 1.7, 3.0, X, x);
  flat_hinge(2.5, 2.1, 1.7, 3.0 - 2.0 * M_PI, X, x2);
  std::printf("folded by 3 rad: W %.15g, by 3 - 2 pi: W %.15g\n", hinge_W(D, X, x), hinge_W(D, X, x2));
  EXPECT_NEAR(hinge_W(D, X, x) / hinge_W(D, X, x2), 1.0, 1e-12);
}

TEST(BendingHinge, DegenerateHingeIsRefused)
{
  double phi, grad[4][3];
  HingeRest rest;
  const double b2[3] = {2, 0, 0}, b3[3] = {-1, -1, 0}, Z[3] = {0, 0, 0};
  const double along[3] = {-1, 0, 0};    // i on the line of the edge: triangle i-j-k has no area
  EXPECT_FALSE(hinge_angle(along, b2, b3, phi, grad));
  EXPECT_FALSE(hinge_rest(along, b2, b3, rest));
  const double b1[3] = {1, 1, 0};
  EXPECT_FALSE(hinge_angle(b1, Z, b3, phi, grad));    // j on top of k: no edge
  const double b3along[3] = {3, 0, 0};                // l beyond k on the edge's line
  EXPECT_FALSE(hinge_angle(b1, b2, b3along, phi, grad));
  // a nearly but not exactly degenerate hinge still has finite angle and forces
  const double nearly[3] = {-1, 1e-9, 0};
  ASSERT_TRUE(hinge_angle(nearly, b2, b3, phi, grad));
  std::printf("nearly collinear hinge: phi %.6g, |dphi/dx_i| %.3g\n", phi, std::fabs(grad[0][2]));
  EXPECT_TRUE(std::isfinite(phi) && std::isfinite(grad[0][2]));
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
