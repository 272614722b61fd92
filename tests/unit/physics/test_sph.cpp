// SPDX-License-Identifier: GPL-2.0-or-later
// The SPH pair force, continuity and density update (Eqs. 5, 7-9) of the cell model, checked
// without LAMMPS (src/physics/sph.h).
#include "physics/sph.h"

#include "physics/kernel.h"
#include "physics/tait.h"

#include "common.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace CellPhysics;

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

// Monaghan's artificial stress (sph_stress_*, pair_style cell/sph stress): Table I's fluid at the
// coarse level's smoothing length, two particles in tension, Monaghan's eps = 0.2 and n = 4, the
// particle spacing dp = s / 1.12 (the coarse cell's s / dx).
struct StressPair {
  double s = 6.4, dp = 6.4 / 1.12, eps = 0.2, rho0 = 1.0, c = 264.6;
  double m[2] = {180.0, 190.0}, rho[2] = {0.9971, 0.9985};
  int n = 4;
  double R(int k) const
  {
    return sph_stress_r(tait_pressure(rho[k], rho0, c, 0.0), 1.0 / rho[k], eps);
  }
  double U(double r) const
  {
    // f from W itself, the definition
    const double wdp = kernel_w(dp, s);
    return sph_stress_energy(m[0], m[1], R(0), R(1), sph_stress_fn(kernel_w(r, s) / wdp, n + 1),
                             wdp, n);
  }
  // the radial force on 0 from 1, F_ij . r_ij / r = fs r
  double Fr(double r) const
  {
    // f as pair cell/sph computes it: the bracket at q = r (1/s) times kernel_w_norm(s) / W(dp)
    const double f = kernel_w_q(r * (1.0 / s), kernel_w_norm(s) / kernel_w(dp, s));
    const double fn = sph_stress_fn(f, n);
    return sph_stress_fpair(m[0], m[1], R(0), R(1), fn, kernel_dwdr(r, s) / r) * r;
  }
};

TEST(SPH, ArtificialStressIsMinusGradientOfItsEnergy)
{
  // at fixed R_i + R_j the pair force is -dU/dr of U = m_i m_j (R_i + R_j) W(dp) f^(n+1) / (n+1):
  // central differences of U at distances across both branches of the kernel, n = 1 to 6. Near the
  // support U ~ (2 - q)^(3(n+1)) is steep: the truncation h^2 U''' / (6 U') ~ (3(n+1))^2 h^2 /
  // (6 (2s - r)^2) is 3e-7 at q = 1.9 with h = 1e-5 s, so h = 1e-6 s (3e-9; round-off eps U / (h U')
  // at most 1e-8 of the force, at q = 0.15)
  StressPair p;
  double worst = 0.0;
  for (int n = 1; n <= 6; n++) {
    p.n = n;
    for (double q : {0.15, 0.5, 0.93, 1.07, 1.5, 1.9}) {
      const double r = q * p.s, h = 1e-6 * p.s;
      const double dUdr = (p.U(r + h) - p.U(r - h)) / (2.0 * h);
      const double err = std::fabs(p.Fr(r) + dUdr) / std::fabs(dUdr);
      worst = std::max(worst, err);
      if (n == 4)
        std::printf("n 4 r/s %.2f: F_r %.10g  -dU/dr %.10g  rel.err %.1e\n", q, p.Fr(r), -dUdr,
                    err);
    }
  }
  EXPECT_LT(worst, 1e-7);
}

TEST(SPH, ArtificialStressLimits)
{
  StressPair p;
  // R = eps |P| / rho^2 in tension; no stress at or above zero pressure
  const double P = tait_pressure(p.rho[0], p.rho0, p.c, 0.0);
  EXPECT_LT(P, 0.0);
  EXPECT_DOUBLE_EQ(p.R(0), -p.eps * P / (p.rho[0] * p.rho[0]));
  EXPECT_EQ(sph_stress_r(0.0, 1.0, p.eps), 0.0);
  EXPECT_EQ(sph_stress_r(364.0, 1.0, p.eps), 0.0);
  EXPECT_EQ(sph_stress_fpair(p.m[0], p.m[1], 0.0, 0.0, 0.7, -0.1), 0.0);
  // f = 1 at the particle spacing: F_r = -m_i m_j (R_i + R_j) dW/dr(dp), U = m_i m_j R W(dp)/(n+1)
  const double Rs = p.R(0) + p.R(1);
  EXPECT_NEAR(p.Fr(p.dp), -p.m[0] * p.m[1] * Rs * kernel_dwdr(p.dp, p.s),
              1e-14 * std::fabs(p.Fr(p.dp)));
  EXPECT_NEAR(p.U(p.dp), p.m[0] * p.m[1] * Rs * kernel_w(p.dp, p.s) / 5.0, 1e-14 * p.U(p.dp));
  // a repulsion inside the support, growing as the pair closes in (down to r = 0.6 s, below the
  // kernel's steepest point 2s/3: f^n keeps rising there), nothing beyond it
  double last = 0.0;
  for (double q = 1.95; q > 0.6; q -= 0.05) {
    EXPECT_GT(p.Fr(q * p.s), last) << "r/s " << q;
    last = p.Fr(q * p.s);
  }
  EXPECT_EQ(p.Fr(2.0 * p.s), 0.0);
  EXPECT_EQ(p.U(2.0 * p.s), 0.0);
  // symmetric in i, j: the pair's forces cancel (momentum)
  EXPECT_EQ(sph_stress_fpair(p.m[0], p.m[1], p.R(0), p.R(1), 0.3, -0.2),
            sph_stress_fpair(p.m[1], p.m[0], p.R(1), p.R(0), 0.3, -0.2));
}

// The cohesion of Eqs. C1-C2 at the coarse cell's support r_c = 2s = 12.8 um, with particle
// volumes of the coarse fluid (5.71^3 and 6.0^3 um^3) and gamma = 10 nN/um (10 mN/m).
struct CohesionPair {
  double rc = 12.8, gamma = 10.0, vi = 186.3, vj = 216.0;
  double A() const { return cohesion_amplitude(gamma, rc); }
  double Fr(double r) const { return cohesion_fpair(A(), vi, vj, r, rc) * r; }
  double U(double r) const { return cohesion_energy(A(), vi, vj, r, rc); }
};

TEST(SPH, CohesionIsMinusGradientOfItsEnergy)
{
  // U is a quartic in r inside r_c, for which the five-point derivative is exact: only round-off
  // is left, eps U / (h F) ~ 1e-12 of the force with h = 1e-3 r_c away from its roots a, r_c
  CohesionPair p;
  double worst = 0.0;
  for (double q : {0.05, 0.2, 0.45, 0.7, 0.85, 0.97}) {
    const double r = q * p.rc, h = 1e-3 * p.rc;
    const double dUdr = (p.U(r - 2 * h) - 8 * p.U(r - h) + 8 * p.U(r + h) - p.U(r + 2 * h)) / (12 * h);
    const double err = std::fabs(p.Fr(r) + dUdr) / std::fabs(dUdr);
    worst = std::max(worst, err);
    std::printf("r/r_c %.2f: F_r %.10g  -dU/dr %.10g  rel.err %.1e\n", q, p.Fr(r), -dUdr, err);
  }
  EXPECT_LT(worst, 1e-9);
  // repulsive inside a, attractive beyond, nothing at and beyond r_c, U(r_c) = 0
  EXPECT_GT(p.Fr(0.5 * p.rc), 0.0);
  EXPECT_LT(p.Fr(0.7 * p.rc), 0.0);
  EXPECT_EQ(p.Fr(p.rc), 0.0);
  EXPECT_EQ(p.U(p.rc), 0.0);
  EXPECT_EQ(p.Fr(1.2 * p.rc), 0.0);
  EXPECT_EQ(cohesion_fpair(p.A(), p.vi, p.vj, 0.0, p.rc), 0.0);
  EXPECT_EQ(cohesion_fpair(p.A(), p.vi, p.vj, 3.0, p.rc), cohesion_fpair(p.A(), p.vj, p.vi, 3.0, p.rc));
}

TEST(SPH, CohesionAddsNoPressureAndHasItsSurfaceTension)
{
  // a uniform fluid (pair distribution 1, number density n = 1 / V): the law's virial pressure
  // -(2 pi n^2 / 3) int r^3 U' dr vanishes, and Kirkwood-Buff's gamma = (pi n^2 / 8) int r^4 U' dr
  // is the gamma asked for. Simpson's rule on 20000 intervals integrates the polynomial to round-off.
  CohesionPair p;
  p.vi = p.vj = 200.0;
  const double n = 1.0 / p.vi;
  const int N = 20000;
  double m3 = 0.0, m3abs = 0.0, m4 = 0.0;
  for (int k = 0; k <= N; k++) {
    const double r = p.rc * k / N, w = (k == 0 || k == N) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    const double dU = -p.Fr(r);    // U' = -F_r
    m3 += w * r * r * r * dU;
    m3abs += w * std::fabs(r * r * r * dU);
    m4 += w * r * r * r * r * dU;
  }
  const double step = p.rc / N / 3.0;
  m3 *= step;
  m3abs *= step;
  m4 *= step;
  const double gamma = M_PI * n * n / 8.0 * m4;
  std::printf("int r^3 U' dr / int |r^3 U'| dr = %.2e; Kirkwood-Buff gamma %.12g nN/um (asked %g)\n",
              m3 / m3abs, gamma, p.gamma);
  EXPECT_LT(std::fabs(m3 / m3abs), 1e-12);
  EXPECT_NEAR(gamma, p.gamma, 1e-10 * p.gamma);
}
