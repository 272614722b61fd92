// SPDX-License-Identifier: GPL-2.0-or-later
// Water in a tissue (Eqs. W1-W5) of the cell model, checked without LAMMPS (src/physics/water.h).
#include "physics/water.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace CellPhysics;

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

TEST(Water, VolumeShareChangesEveryDensityAlike)
{
  // Eq. W5: four particles of a cell whose masses differ 10-fold (an inflated cell's spread)
  const double m[4] = {88.0, 250.0, 600.0, 1031.0}, rho[4] = {1.001, 0.999, 1.0, 1.002};
  double Vf = 0.0;
  for (int i = 0; i < 4; i++) Vf += m[i] / rho[i];
  const double dM = -3.7;    // pg: the cell's loss this step
  double sum = 0.0;
  for (int i = 0; i < 4; i++) {
    const double f = volume_share(m[i], rho[i], Vf);
    const double drho = rho[i] / m[i] * f * dM;    // Eq. 9 at fixed volume
    std::printf("m = %6.0f pg: share %.6f, drho = %.15f (dM / Vf = %.15f)\n", m[i], f, drho,
                dM / Vf);
    EXPECT_NEAR(drho, dM / Vf, 1e-15);
    sum += f;
  }
  EXPECT_NEAR(sum, 1.0, 1e-15);    // the cell loses dM, all of it
  // equal particles: the even share of Eq. 10
  EXPECT_NEAR(volume_share(500.0, 1.0, 4 * 500.0), 0.25, 1e-16);
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
