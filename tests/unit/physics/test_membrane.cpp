// SPDX-License-Identifier: GPL-2.0-or-later
// The membrane element (Eqs. M1-M3) of the cell model, checked without LAMMPS
// (src/physics/membrane.h).
#include "physics/membrane.h"

#include "common.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace CellPhysics;

/* ---------------------------------------------------------------------
   Membrane element (Eqs. M1-M2): one triangle against the closed-form
   incompressible Neo-Hookean sheet, the finite-difference gradient, rigid
   motion and degenerate shapes. The reference triangle is not equilateral
   and sits turned in space, so nothing rests on a special orientation.
------------------------------------------------------------------------ */

namespace {

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

void evaluate(const Tri &t, double &E, double f[3][3], double &area, bool relax = false,
              double residual = 0.0)
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
  E = membrane_energy(G, T0, rest, s, relax, residual);
  membrane_forces(G, T0, rest, s, f[0], f[2], relax, residual);
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
double gradient_error(const Tri &t, bool relax, bool show, double residual = 0.0)
{
  double E, f[3][3], area;
  evaluate(t, E, f, area, relax, residual);
  double worst = 0, fmax = 0;
  for (auto &r : f) for (double v : r) fmax = std::max(fmax, std::fabs(v));
  for (int n = 0; n < 3; n++)
    for (int d = 0; d < 3; d++) {
      const double h = 1e-5;
      Tri p = t, m = t;
      p.x[n][d] += h;
      m.x[n][d] -= h;
      double Ep, Em, fp[3][3], ap;
      evaluate(p, Ep, fp, ap, relax, residual);
      evaluate(m, Em, fp, ap, relax, residual);
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

TEST(MembraneElement, ResidualStiffnessBlendsAndHoldsTrianglesOpen)
{
  // Eq. M4: (1 - r) W_M3 + r W_M1, forces minus its gradient, in a wrinkled and in a slack state
  const double r = 0.01;
  const double Fw[2][2] = {{1.25, 0.15}, {-0.05, 0.7}};
  const double Fs[2][2] = {{0.8, 0.1}, {0.05, 0.6}};
  for (const auto *F2 : {Fw, Fs}) {
    Tri t = make(F2);
    t.x[2][2] += 0.1;
    double E, f[3][3], area, Et, Ef;
    evaluate(t, E, f, area, true, r);
    evaluate(t, Et, f, area, true);
    evaluate(t, Ef, f, area, false);
    const double worst = gradient_error(t, true, false, r);
    std::printf("%s: E %.10g = (1 - r) %.10g + r %.10g; largest difference / largest force %.2e\n",
                F2 == Fw ? "wrinkled" : "slack", E, Et, Ef, worst);
    EXPECT_NEAR(E, (1 - r) * Et + r * Ef, 1e-13 * std::fabs(Ef));
    EXPECT_LT(worst, 1e-8);
  }
  // a slack triangle squeezed towards no area: tension-field theory stores nothing, the residual
  // a growing energy (the 1/J2 term of Eq. M1), and pushes the nodes apart
  double last = 0.0;
  for (double k : {0.5, 0.1, 0.03, 0.01}) {
    const double F2[2][2] = {{0.9, 0.0}, {0.0, k}};
    Tri t = make(F2);
    double E, f[3][3], area, Et;
    evaluate(t, Et, f, area, true);
    evaluate(t, E, f, area, true, r);
    std::printf("area / rest area %.3f: W_M3 %.3g, W_M4 %.6g\n", 0.9 * k, Et, E);
    EXPECT_EQ(Et, 0.0);
    EXPECT_GT(E, last);
    last = E;
  }
}
