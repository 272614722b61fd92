// SPDX-License-Identifier: GPL-2.0-or-later
// The bending hinge (Eqs. B1-B3) of the cell model, checked without LAMMPS (src/physics/bending.h).
#include "physics/bending.h"

#include "common.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace CellPhysics;

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
