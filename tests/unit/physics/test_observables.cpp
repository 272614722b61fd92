// SPDX-License-Identifier: GPL-2.0-or-later
// The paper's observables: equatorial force and shear stress (Eqs. 23-26) of the cell model,
// checked without LAMMPS (src/physics/observables.h).
#include "physics/observables.h"

#include "physics/kernel.h"

#include "common.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace CellPhysics;

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
