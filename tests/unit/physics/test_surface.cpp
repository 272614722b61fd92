// SPDX-License-Identifier: GPL-2.0-or-later
// Triangulated closed surfaces of the cell model, checked without LAMMPS (src/physics/surface.h).
#include "physics/surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace CellPhysics;

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
