// SPDX-License-Identifier: GPL-2.0-or-later
// cellmech styles inside an in-process LAMMPS: forces against the formulas, bad input gives a
// LAMMPS error that names the command and what was expected, and the plugin guard.
#include "atom.h"
#include "bond.h"
#include "cell_mpi.h"
#include "cell_topology.h"
#include "compute.h"
#include "exceptions.h"
#include "fix.h"
#include "force.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "variable.h"

#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <regex>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {

class Lmp : public ::testing::Test {
 protected:
  LAMMPS *lmp = nullptr;
  void SetUp() override { lmp = make(); }
  void TearDown() override { delete lmp; }

  static LAMMPS *make()
  {
    const char *args[] = {"lmp", "-log", "none", "-echo", "none", "-screen", "none", nullptr};
    auto *l = new LAMMPS(7, (char **) args, MPI_COMM_WORLD);
    l->input->one(std::string("plugin load ") + CELLMECH_PLUGIN);
    return l;
  }
  void cmd(const std::string &line) { lmp->input->one(line); }
  void cmds(const std::vector<std::string> &lines)
  {
    for (auto &l : lines) cmd(l);
  }
  // run a command and return the LAMMPS error message it raised ("" if none)
  std::string error_of(const std::string &line)
  {
    try {
      cmd(line);
    } catch (LAMMPSException &e) {
      return e.what();
    }
    return "";
  }
  double f(int tag, int d) { return lmp->atom->f[lmp->atom->map(tag)][d]; }

  // two wall nodes joined by one tether, reference (rest) distance l0 along x, stretched to l
  void two_nodes(double l0, double l, const std::string &coeff = "1 8e5 0.126 0.0")
  {
    cmds({"units micro", "atom_style molecular", "atom_modify map array",
          "region box block -10 10 -10 10 -10 10",
          "create_box 1 box bond/types 1 extra/bond/per/atom 1 extra/special/per/atom 2",
          "fix ref all property/atom d2_cellref 3 ghost yes", "mass 1 5.0",
          "create_atoms 1 single 0 0 0", "create_atoms 1 single " + std::to_string(l) + " 0 0",
          "set atom 2 d2_cellref[1] " + std::to_string(l0), "create_bonds single/bond 1 1 2",
          "bond_style cell/tether", "bond_coeff " + coeff, "pair_style zero 1.0",
          "pair_coeff * *"});
  }
};

TEST_F(Lmp, TetherForceInLammpsIsEq19)
{
  const double G = 8e5, t0 = 0.126, l0 = 2.5;
  for (double lam : {0.9, 1.01, 1.2}) {
    delete lmp;
    lmp = make();
    two_nodes(l0, lam * l0);
    cmd("run 0");
    const double expect = G * l0 * t0 / std::sqrt(3.0) * (lam - std::pow(lam, -5));
    // atom 1 at the origin is pulled toward atom 2 (+x) when stretched
    const double got = f(1, 0);
    std::printf("lam %.2f  LAMMPS force %.10g  Eq.19 %.10g\n", lam, got, expect);
    EXPECT_NEAR(got, expect, 1e-10 * std::fabs(expect));
    EXPECT_NEAR(f(2, 0), -expect, 1e-10 * std::fabs(expect));
  }
}

TEST_F(Lmp, TetherDampingAlongBond)
{
  const double gamma = 0.1;
  two_nodes(2.5, 2.5, "1 8e5 0.126 0.1");
  cmds({"comm_modify vel yes", "velocity all set 0 0 0", "set atom 2 vx 3.0 vy 7.0", "run 0"});
  // at rest length only damping acts, along x only: -gamma (v12 . e) e on atom 1, v12 = -3 x
  EXPECT_NEAR(f(1, 0), gamma * 3.0, 1e-12);
  EXPECT_NEAR(f(1, 1), 0.0, 1e-12);
}

TEST_F(Lmp, TetherBreaksAboveCriticalStretch)
{
  two_nodes(2.5, 2.5 * 1.05, "1 8e5 0.126 0.0 lamf 1.04");
  // a broken tether's nodes become an ordinary pair: only consistent with 1-3/1-4 weights 1
  EXPECT_TRUE(std::regex_search(error_of("run 0"),
                                std::regex("cell/tether.*lamf requires 'special_bonds lj 0 1 1'")));
  cmd("special_bonds lj 0 1 1");
  cmd("run 0");
  EXPECT_EQ(f(1, 0), 0.0);
  delete lmp;
  lmp = make();
  two_nodes(2.5, 2.5 * 1.03, "1 8e5 0.126 0.0 lamf 1.04");
  cmds({"special_bonds lj 0 1 1", "run 0"});
  EXPECT_GT(f(1, 0), 0.0);
}

// Two wall triangles 1-2-3 and 2-4-3 share the tether 2-3; the square is sheared so that 2-3 is
// stretched 1.06x and the outer tethers about 1.03x. With lamf 1.05 only 2-3 may break, and then
// the topology must follow: bond gone, both triangles gone, 2 and 3 out of each other's special
// list and in the neighbor list (they repel), counts kept through a restart.
class Patch : public Lmp {
 protected:
  void build(const std::string &coeff)
  {
    const double L = 2.0, d = 0.03 * L;
    auto at = [](double x, double y) {
      return "create_atoms 1 single " + std::to_string(x) + " " + std::to_string(y) + " 0";
    };
    cmds({"units micro",
          "atom_style molecular",
          "atom_modify map array",
          "boundary f f f",
          "region box block -10 10 -10 10 -10 10",
          "create_box 1 box bond/types 1 angle/types 1 extra/bond/per/atom 3 "
          "extra/angle/per/atom 2 extra/special/per/atom 8",
          "fix ref all property/atom d2_cellref 3 ghost yes",
          "mass 1 5.0",
          at(0, 0),
          at(L + d, -d),
          at(-d, L + d),
          at(L, L),
          "set atom 2 d2_cellref[1] 2.0",
          "set atom 3 d2_cellref[2] 2.0",
          "set atom 4 d2_cellref[1] 2.0",
          "set atom 4 d2_cellref[2] 2.0",
          "special_bonds lj 0 1 1",
          "create_bonds single/bond 1 1 2 special no",
          "create_bonds single/bond 1 1 3 special no",
          "create_bonds single/bond 1 2 4 special no",
          "create_bonds single/bond 1 3 4 special no",
          "create_bonds single/bond 1 2 3 special no",
          "create_bonds single/angle 1 1 2 3 special no",
          "create_bonds single/angle 1 2 4 3 special yes",
          "bond_style cell/tether",
          "bond_coeff " + coeff,
          "angle_style zero nocoeff",
          "angle_coeff *",
          "pair_style cell/lj84",
          "pair_coeff 1 1 10.0 3.5",
          "comm_modify cutoff 6.0",
          "compute pl all pair/local dist",
          "thermo_style custom step bonds"});
  }
  // is other a 1-2 neighbour of tag? (1-3 and 1-4 weigh 1: an ordinary pair)
  bool special_has(int tag, int other)
  {
    const int i = lmp->atom->map(tag);
    for (int m = 0; m < lmp->atom->nspecial[i][0]; m++)
      if (lmp->atom->special[i][m] == other) return true;
    return false;
  }
  int angle_types_on(int tag)
  {
    const int i = lmp->atom->map(tag);
    int on = 0;
    for (int m = 0; m < lmp->atom->num_angle[i]; m++) on += lmp->atom->angle_type[i][m] > 0;
    return on;
  }
  // does the pair list (compute pair/local) hold the pair 2-3?
  bool pair23_listed()
  {
    auto *c = lmp->modify->get_compute_by_id("pl");
    c->compute_local();
    return has_dist(c, diag());
  }
  double diag()
  {
    double **x = lmp->atom->x;
    const int i = lmp->atom->map(2), j = lmp->atom->map(3);
    return std::sqrt(std::pow(x[i][0] - x[j][0], 2) + std::pow(x[i][1] - x[j][1], 2));
  }
  // the state after tether 2-3 broke: it is gone with both triangles, 2 and 3 are no longer 1-2
  // neighbours (2 and 1 still are), one broken tether counted, at both of its nodes
  void expect_23_broken()
  {
    EXPECT_EQ(lmp->atom->nbonds, 4);
    EXPECT_EQ(lmp->atom->nangles, 0);
    EXPECT_FALSE(special_has(2, 3));
    EXPECT_FALSE(special_has(3, 2));
    EXPECT_TRUE(special_has(2, 1));
    EXPECT_EQ(angle_types_on(1) + angle_types_on(2) + angle_types_on(3) + angle_types_on(4), 0);
    auto *fix = lmp->modify->get_fix_by_id("cell_broken");
    ASSERT_NE(fix, nullptr);
    EXPECT_EQ(fix->compute_scalar(), 1.0);
    EXPECT_EQ(fix->vector_atom[lmp->atom->map(2)], 1.0);
    EXPECT_EQ(fix->vector_atom[lmp->atom->map(3)], 1.0);
    EXPECT_EQ(fix->vector_atom[lmp->atom->map(1)], 0.0);
  }
  static bool has_dist(LAMMPS_NS::Compute *c, double r)
  {
    for (int n = 0; n < c->size_local_rows; n++)
      if (std::fabs(c->vector_local[n] - r) < 1e-9) return true;
    return false;
  }
};

TEST_F(Patch, BrokenTetherUpdatesTopology)
{
  build("1 8e5 0.126 0.0 lamf 1.05");
  cmd("run 0");
  // broken in the setup force call: bond removed, triangles gone, special lists updated
  expect_23_broken();
  // the next step re-neighbors: 2 and 3 are now an ordinary pair within the 8-4 cutoff
  cmd("run 1");
  EXPECT_TRUE(pair23_listed()) << "broken pair 2-3 missing from the neighbor list";
  EXPECT_EQ(lmp->atom->nbonds, 4);
  // the restart keeps all of it; the special list rebuilt from the bonds agrees
  cmd("write_restart patch.restart");
  delete lmp;
  lmp = make();
  cmds({"read_restart patch.restart", "fix ref all property/atom d2_cellref 3 ghost yes",
        "special_bonds lj 0 1 1", "pair_style cell/lj84", "pair_coeff 1 1 10.0 3.5",
        "angle_coeff *", "compute pl all pair/local dist", "run 0"});
  expect_23_broken();
  EXPECT_TRUE(pair23_listed());
  std::remove("patch.restart");
}

TEST_F(Patch, NoBreakBelowCriticalStretch)
{
  build("1 8e5 0.126 0.0 lamf 1.07");
  cmd("run 1");
  EXPECT_EQ(lmp->atom->nbonds, 5);
  EXPECT_EQ(lmp->atom->nangles, 2);
  EXPECT_TRUE(special_has(2, 3));
  EXPECT_EQ(angle_types_on(2) + angle_types_on(4), 2);
  EXPECT_FALSE(pair23_listed());
  EXPECT_EQ(lmp->modify->get_fix_by_id("cell_broken")->compute_scalar(), 0.0);
}

TEST_F(Lmp, TetherBreaksWithoutAngles)
{
  // atom_style bond has no angle arrays: a break must not touch them
  cmds({"units micro", "atom_style bond", "atom_modify map array",
        "region box block -10 10 -10 10 -10 10",
        "create_box 1 box bond/types 1 extra/bond/per/atom 1 extra/special/per/atom 2",
        "fix ref all property/atom d2_cellref 3 ghost yes", "mass 1 5.0",
        "create_atoms 1 single 0 0 0", "create_atoms 1 single 2.7 0 0",
        "set atom 2 d2_cellref[1] 2.5", "create_bonds single/bond 1 1 2", "special_bonds lj 0 1 1",
        "bond_style cell/tether", "bond_coeff 1 8e5 0.126 0.0 lamf 1.04", "pair_style zero 1.0",
        "pair_coeff * *", "run 0"});
  EXPECT_EQ(lmp->atom->nbonds, 0);
  EXPECT_EQ(lmp->modify->get_fix_by_id("cell_broken")->compute_scalar(), 1.0);
}

TEST_F(Lmp, Repulsion84InLammps)
{
  const double f0 = 3.0, r0 = 2.0, r = 1.7;
  cmds({"units micro", "atom_style atomic", "atom_modify map array",
        "region box block -10 10 -10 10 -10 10", "create_box 2 box", "mass * 1.0",
        "create_atoms 1 single 0 0 0", "create_atoms 2 single 0 " + std::to_string(r) + " 0",
        "pair_style cell/lj84", "pair_coeff * * " + std::to_string(f0) + " " + std::to_string(r0),
        "run 0"});
  const double expect = f0 * (std::pow(r0 / r, 8) - std::pow(r0 / r, 4)) / r;
  std::printf("8-4 repulsion at r %.2f: LAMMPS %.10g  Eq.12 %.10g\n", r, -f(1, 1), expect);
  EXPECT_NEAR(-f(1, 1), expect, 1e-10 * expect);
  EXPECT_NEAR(f(2, 1), expect, 1e-10 * expect);
}

// LAMMPS's force-style harness cannot compare cell/sph's single() with its compute()
// (tests/force-styles/README.md): two fluid particles at rest (no viscous force) with different
// densities, at several distances within the kernel's support.
TEST_F(Lmp, SphSingleMatchesCompute)
{
  cmds({"units micro", "atom_style atomic", "atom_modify map array", "comm_modify vel yes",
        "region box block -10 10 -10 10 -10 10", "create_box 1 box",
        "fix cell all property/atom rmass d_rho d_drho ghost yes", "create_atoms 1 single 0 0 0",
        "create_atoms 1 single 1.1 0.4 -0.3", "set atom 1 mass 2.0 d_rho 1.02",
        "set atom 2 mass 3.0 d_rho 0.97", "pair_style cell/sph",
        "pair_coeff 1 1 1.0 264.6 300.0 1.0 3.2"});
  for (double scale : {1.0, 2.5, 4.0}) {
    cmd("set atom 2 x " + std::to_string(1.1 * scale) + " y " + std::to_string(0.4 * scale) +
        " z " + std::to_string(-0.3 * scale));
    cmd("run 0");
    const int i = lmp->atom->map(1), j = lmp->atom->map(2);
    double **x = lmp->atom->x;
    const double del[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
    const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
    double fsingle = 0.0;
    lmp->force->pair->single(i, j, 1, 1, rsq, 1.0, 1.0, fsingle);
    std::printf("cell/sph at r %.3f: compute f1 = (%.10g %.10g %.10g), single -fpair*del = "
                "(%.10g %.10g %.10g)\n",
                std::sqrt(rsq), f(1, 0), f(1, 1), f(1, 2), -fsingle * del[0], -fsingle * del[1],
                -fsingle * del[2]);
    ASSERT_NE(fsingle, 0.0);
    for (int d = 0; d < 3; d++) {
      EXPECT_NEAR(f(1, d), -fsingle * del[d], 1e-12 * std::fabs(fsingle * std::sqrt(rsq)));
      EXPECT_NEAR(f(2, d), fsingle * del[d], 1e-12 * std::fabs(fsingle * std::sqrt(rsq)));
    }
  }
}

// ---------------------------------------------------------------- bad input

#define EXPECT_ERROR(line, pattern)                                                 \
  do {                                                                              \
    std::string msg = error_of(line);                                               \
    std::printf("%s\n  -> %s\n", line, msg.c_str());                                \
    EXPECT_TRUE(std::regex_search(msg, std::regex(pattern))) << "message: " << msg; \
  } while (0)

TEST_F(Lmp, BondBadInput)
{
  two_nodes(2.5, 2.5);
  EXPECT_ERROR("bond_style cell/tether 1.0", "bond_style cell/tether.*expected no arguments");
  EXPECT_ERROR("bond_coeff 1 8e5 0.126", "bond_coeff cell/tether.*expected.*G t0 gamma");
  EXPECT_ERROR("bond_coeff 1 -8e5 0.126 0", "bond_coeff cell/tether: shear modulus G must be > 0");
  EXPECT_ERROR("bond_coeff 1 8e5 0 0", "bond_coeff cell/tether: wall thickness t0 must be > 0");
  EXPECT_ERROR("bond_coeff 1 8e5 0.1 -1", "bond_coeff cell/tether: damping gamma must be >= 0");
  EXPECT_ERROR("bond_coeff 1 8e5 0.1 0 lamx 1.04", "Unknown keyword 'lamx'.*expected 'lamf'");
  EXPECT_ERROR("bond_coeff 1 8e5 0.1 0 lamf 0.9", "lamf must be > 1");
  EXPECT_ERROR("bond_coeff 1 8e5 abc 0", "Expected floating point");
  cmd("bond_coeff 1 8e5 0.126 0.1");
  EXPECT_ERROR("run 0", "cell/tether with damping gamma > 0 requires 'comm_modify vel yes'");
}

TEST_F(Lmp, BondNeedsReferencePositions)
{
  cmds({"units micro", "atom_style molecular", "region box block -10 10 -10 10 -10 10",
        "create_box 1 box bond/types 1 extra/bond/per/atom 1 extra/special/per/atom 2",
        "mass 1 1.0", "create_atoms 1 single 0 0 0", "create_atoms 1 single 2 0 0",
        "create_bonds single/bond 1 1 2", "bond_style cell/tether", "bond_coeff 1 8e5 0.126 0",
        "pair_style zero 1.0", "pair_coeff * *"});
  EXPECT_ERROR("run 0", "cell/tether requires the wall reference positions.*d2_cellref 3");
}

TEST_F(Lmp, BondNeedsBondAtomStyle)
{
  cmds({"units micro", "atom_style atomic", "region box block -10 10 -10 10 -10 10",
        "create_box 1 box"});
  EXPECT_ERROR("bond_style cell/tether", "[Bb]ond_style command when no bonds allowed");
}

TEST_F(Lmp, PairBadInput)
{
  cmds({"units micro", "atom_style atomic", "region box block -10 10 -10 10 -10 10",
        "create_box 2 box", "mass * 1.0", "create_atoms 1 single 0 0 0"});
  EXPECT_ERROR("pair_style cell/lj84 2.0", "pair_style cell/lj84.*expected no arguments");
  cmd("pair_style cell/lj84");
  EXPECT_ERROR("pair_coeff 1 1 1.0", "pair_coeff cell/lj84.*expected.*f0 r0 \\[gamma\\]");
  EXPECT_ERROR("pair_coeff 1 1 1.0 0.0", "contact distance r0 must be > 0");
  EXPECT_ERROR("pair_coeff 1 1 -1.0 1.0", "strength f0 must be >= 0");
  EXPECT_ERROR("pair_coeff 1 1 1.0 1.0 -2", "contact damping gamma must be >= 0");
  EXPECT_ERROR("pair_coeff 1 3 1.0 1.0", "Numeric index 3 is out of bounds");
  cmd("pair_coeff * * 1.0 1.0 0.5");
  EXPECT_ERROR("run 0", "cell/lj84 with contact damping gamma > 0 requires 'comm_modify vel yes'");
}

// ---------------------------------------------------------------- fluid styles: bad input

class Fluid : public Lmp {
 protected:
  void box(bool with_props = true)
  {
    cmds({"units micro", "atom_style molecular", "atom_modify map array"});
    if (with_props) cmd("fix cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes");
    cmds({"region box block -10 10 -10 10 -10 10",
          "create_box 2 box bond/types 1 angle/types 1 extra/bond/per/atom 3 "
          "extra/angle/per/atom 3 extra/special/per/atom 6",
          "create_atoms 2 single 0 0 0", "create_atoms 2 single 1 0 0"});
    if (with_props)
      cmds({"set type 2 mass 1.0", "set type 2 d_rho 1.0"});
    else
      cmd("mass * 1.0");
  }
};

TEST_F(Fluid, SphBadInput)
{
  box();
  EXPECT_ERROR("pair_style cell/sph 1",
               "pair_style cell/sph.*expected keyword 'search', 'stress' or 'cohesion'");
  EXPECT_ERROR("pair_style cell/sph cohesion", "'cohesion' needs gamma");
  EXPECT_ERROR("pair_style cell/sph cohesion -5", "cohesion: surface tension gamma must be > 0");
  EXPECT_ERROR("pair_style cell/sph cohesion 0", "cohesion: surface tension gamma must be > 0");
  EXPECT_ERROR("pair_style cell/sph search", "'search' needs a kind");
  EXPECT_ERROR("pair_style cell/sph stress 0.2 4", "'stress' needs eps n dp, got 2");
  EXPECT_ERROR("pair_style cell/sph stress 0 4 1", "stress: strength eps must be > 0");
  EXPECT_ERROR("pair_style cell/sph stress 0.2 0 1", "stress: exponent n must be an integer >= 1");
  EXPECT_ERROR("pair_style cell/sph stress 0.2 4 -1", "stress: particle spacing dp must be > 0");
  cmds({"pair_style cell/sph stress 0.2 4 6.4", "pair_coeff * * 1 264.6 0 1 3.2",
        "comm_modify vel yes"});
  EXPECT_ERROR("run 0", "stress: particle spacing dp 6.4 must lie inside the kernel's support");
  cmds({"comm_modify vel no", "pair_style cell/sph"});
  EXPECT_ERROR("pair_coeff 2 2 1 264.6 0 1", "pair_coeff cell/sph.*expected.*rho0 c P0 mu s");
  EXPECT_ERROR("pair_coeff 2 2 0 264.6 0 1 3.2", "reference density rho0 must be > 0");
  EXPECT_ERROR("pair_coeff 2 2 1 -1 0 1 3.2", "sound speed c must be > 0");
  EXPECT_ERROR("pair_coeff 2 2 1 264.6 0 -1 3.2", "viscosity mu must be >= 0");
  EXPECT_ERROR("pair_coeff 2 2 1 264.6 0 1 0", "smoothing length s must be > 0");
  EXPECT_ERROR("pair_coeff 1 2 1 264.6 0 1 3.2", "equation of state belongs to one fluid type");
  EXPECT_ERROR("pair_coeff 2 2 3.2", "type 2 needs 'pair_coeff 2 2 rho0 c P0 mu s'");
  cmds({"pair_coeff * * 1 264.6 0 1 3.2"});
  EXPECT_ERROR("run 0", "cell/sph requires 'comm_modify vel yes'");
}

TEST_F(Fluid, SphNeedsPerAtomFields)
{
  box(false);
  cmds({"pair_style cell/sph", "pair_coeff * * 1 264.6 0 1 3.2", "comm_modify vel yes"});
  EXPECT_ERROR("run 0", "cell/sph requires per-atom masses: add rmass");
}

TEST_F(Fluid, VirtualBadInput)
{
  box();
  EXPECT_ERROR("pair_style cell/virtual", "expected 'pair_style cell/virtual reach'");
  EXPECT_ERROR("pair_style cell/virtual -1", "reach .* must be > 0");
  cmd("pair_style cell/virtual 2.0");
  EXPECT_ERROR("pair_coeff 1 2 1.0", "pair_coeff cell/virtual.*expected.*f0 r0 \\[gamma\\]");
  EXPECT_ERROR("pair_coeff 1 2 1.0 0", "contact distance r0 must be > 0");
  cmds({"pair_coeff 1 2 1.0 1.5", "pair_coeff 1 1 0.0 1.0", "pair_coeff 2 2 0.0 1.0"});
  EXPECT_ERROR("run 0", "cell/virtual requires an angle style");
  cmds({"angle_style zero nocoeff", "angle_coeff *", "newton off on"});
  EXPECT_ERROR("run 0", "cell/virtual requires newton_pair on");
}

TEST_F(Fluid, FixFluidBadInput)
{
  box();
  EXPECT_ERROR("fix f all cell/fluid Pi -100",
               "expected 'fix ID group cell/fluid Pi value Lp value \\[keyword args");
  EXPECT_ERROR("fix f all cell/fluid Pi 100 Lp 1", "osmotic potential Pi must be <= 0");
  EXPECT_ERROR("fix f all cell/fluid Pi -100 Lp -1", "hydraulic conductivity Lp must be >= 0");
  EXPECT_ERROR("fix f all cell/fluid Pi -100 Lq 1",
               "expected 'Pi value Lp value' \\(in either order\\) first, got 'Pi -100 Lq 1'");
  EXPECT_ERROR("fix f all cell/fluid Pi -100 Pi -1", "expected 'Pi value Lp value'");
  cmds({"fix f all cell/fluid Pi -100 Lp 0", "pair_style zero 3.0", "pair_coeff * *"});
  EXPECT_ERROR("run 0", "Fix cell/fluid requires pair style cell/sph");
  EXPECT_ERROR("fix_modify f Pi 5", "osmotic potential Pi must be <= 0");
  EXPECT_ERROR("fix_modify f Pj 5", "Unknown keyword 'Pj' for fix cell/fluid");
}

TEST_F(Fluid, ComputePropsBadInput)
{
  box();
  EXPECT_ERROR("compute p all cell/props normal 0 0", "'normal' expects three components");
  EXPECT_ERROR("compute p all cell/props normal 0 0 0",
               "'normal' must be a finite non-zero vector");
  EXPECT_ERROR("compute p all cell/props tilt 1", "Unknown keyword 'tilt' for compute cell/props");
  cmds({"compute p all cell/props", "pair_style zero 3.0", "pair_coeff * *",
        "variable v equal c_p[1][1]", "thermo_style custom step v_v"});
  EXPECT_ERROR("run 0", "Compute cell/props requires a cell wall: bond style cell/tether or angle "
                        "style cell/membrane");
}

// ---------------------------------------------------------------- middle lamella

// Lamella bonds between wall nodes of different cells (molecules), units micro: sigma_c = 300
// kPa, Gc = 0.05 J/m^2 = 50 pg/us^2. The law is written out here again (Xu & Needleman), so that
// the style is checked against the formulas, not against its own functions.
class Lamella : public Lmp {
 protected:
  static constexpr double SIGC = 300.0, GC = 50.0;
  static double dc() { return GC / (SIGC * std::exp(1.0) * (1.0 - 11.0 * std::exp(-10.0))); }
  static double traction(double d)
  {
    const double x = d / dc();
    return x < 0 ? SIGC * std::exp(1.0) * x : SIGC * x * std::exp(1.0 - x);
  }
  static std::string num(double v)
  {
    char buf[64];
    std::snprintf(buf, sizeof(buf), "%.17g", v);
    return buf;
  }
  // create_box and the per-atom fields of a tissue (reference positions and lamella area share)
  void tissue_box(int nbondtypes, const std::string &fix = "d2_cellref 3 d_alam ghost yes")
  {
    cmds({"units micro", "atom_style molecular", "atom_modify map array", "boundary f f f",
          "region box block -10 10 -10 10 -10 10",
          "create_box 1 box bond/types " + std::to_string(nbondtypes) +
              " extra/bond/per/atom 4 extra/special/per/atom 8",
          "fix cell all property/atom " + fix, "mass 1 5.0", "special_bonds lj 0 1 1",
          "timestep 0.001"});
  }
  // a node of cell mol at (x, y, z), its reference position there too, with area share alam
  void node(int tag, int mol, double x, double y, double z, double alam)
  {
    const std::string t = std::to_string(tag);
    cmds({"create_atoms 1 single " + num(x) + " " + num(y) + " " + num(z),
          "set atom " + t + " mol " + std::to_string(mol),
          "set atom " + t + " d2_cellref[1] " + num(x),
          "set atom " + t + " d2_cellref[2] " + num(y),
          "set atom " + t + " d2_cellref[3] " + num(z), "set atom " + t + " d_alam " + num(alam)});
  }
  // value of an equal-style formula, as thermo output and variables see it
  double eval(const std::string &formula) { return lmp->input->variable->compute_equal(formula); }
  Fix *debonded() { return lmp->modify->get_fix_by_id("cell_debonded"); }
  double count_at(int tag) { return debonded()->vector_atom[lmp->atom->map(tag)]; }
  bool special_has(int tag, int other)
  {
    const int i = lmp->atom->map(tag);
    for (int m = 0; m < lmp->atom->nspecial[i][0]; m++)
      if (lmp->atom->special[i][m] == other) return true;
    return false;
  }
  // one lamella bond 1-2 along x of rest length r0 (areas 0.4 and 0.6: A = 0.5), opened to r
  void one_bond(double r0, double r, const std::string &coeff = "1 300 50")
  {
    tissue_box(1);
    node(1, 1, 0, 0, 0, 0.4);
    node(2, 2, r0, 0, 0, 0.6);
    cmds({"set atom 2 x " + num(r), "create_bonds single/bond 1 1 2", "bond_style cell/lamella",
          "bond_coeff " + coeff, "pair_style zero 1.0", "pair_coeff * *", "compute eb all pe bond",
          "thermo_style custom step c_eb"});
  }
};

TEST_F(Lamella, ForceIsMinusEnergyDerivative)
{
  // central difference of the bond energy of LAMMPS (compute pe bond) in the position of atom 2,
  // h = 1e-6 um = 1.6e-5 delta_c: truncation (h/dc)^2 A T''/6 ~ 1e-10 A sigma_c, round-off of
  // energies ~10 nN um over h ~ 1e-9 nN; 1e-7 relative to the force (or 1e-7 A sigma_c near its
  // zero) bounds both with a margin
  const double r0 = 1.0, A = 0.5, h = 1e-6;
  double worst = 0.0;
  for (double x : {-0.5, -0.05, 0.3, 1.0, 2.5, 6.0, 9.5}) {
    const double r = r0 + x * dc();
    double e[2];
    for (int s = 0; s < 2; s++) {
      delete lmp;
      lmp = make();
      one_bond(r0, r + (s ? h : -h));
      cmd("run 0");
      e[s] = lmp->modify->get_compute_by_id("eb")->compute_scalar();
    }
    delete lmp;
    lmp = make();
    one_bond(r0, r);
    cmd("run 0");
    const double fd = -(e[1] - e[0]) / (2 * h);
    const double law = -A * traction(x * dc());
    const double err = std::fabs(f(2, 0) - fd) / std::max(std::fabs(law), 1e-3 * A * SIGC);
    worst = std::max(worst, err);
    std::printf("opening %+6.2f dc: force on 2 %+.10g nN, -dE/dx %+.10g, -A T %+.10g, "
                "FD rel.err %.2e\n",
                x, f(2, 0), fd, law, err);
    EXPECT_LT(err, 1e-7);
    EXPECT_NEAR(f(2, 0), law, 1e-12 * A * SIGC);
    EXPECT_NEAR(f(1, 0), -law, 1e-12 * A * SIGC);
    EXPECT_EQ(lmp->atom->nbonds, 1);
  }
  std::printf("lamella force vs finite-difference energy derivative: worst rel.err %.2e\n", worst);
}

TEST_F(Lamella, DampingAlongBond)
{
  one_bond(1.0, 1.0, "1 300 50 2.0");
  EXPECT_TRUE(std::regex_search(error_of("run 0"),
                                std::regex("cell/lamella with damping.*'comm_modify vel yes'")));
  // at rest length only damping acts: -A gamma (v12 . e) e on atom 1, v12 = -3 x, A = 0.5
  cmds({"comm_modify vel yes", "velocity all set 0 0 0", "set atom 2 vx 3.0 vy 7.0", "run 0"});
  EXPECT_NEAR(f(1, 0), 0.5 * 2.0 * 3.0, 1e-12);
  EXPECT_NEAR(f(1, 1), 0.0, 1e-12);
}

TEST_F(Lamella, WorkToSeparateIsGcTimesArea)
{
  // four vertical bonds of different rest lengths and areas between cell 1 (z = 0) and cell 2
  // above; cell 2 is lifted rigidly in steps h = dc/100.25 to 12 dc, the pull force integrated by
  // the trapezoid rule. Its error is -(h^2/12) [F'(10 dc) - F'(0)] = -(h/dc)^2/12 Gc A (1 + 1e-3)
  // from the curvature, plus at most (h/2) F(10 dc) = 5 e^-10 (h/dc) Gc A from the step in which
  // the bonds let go: 8.3e-6 + 2.3e-6 relative. (The break, 1002.5 steps out, falls mid-step,
  // where the second part nearly cancels; on a step boundary it reaches its bound.)
  tissue_box(1);
  const double L = 1.5;
  const double r0[4] = {0.8, 1.0, 1.2, 0.9}, alam1[4] = {0.3, 0.5, 0.7, 1.0},
               alam2[4] = {0.6, 0.4, 0.9, 0.2};
  double A = 0.0;
  for (int k = 0; k < 4; k++) node(k + 1, 1, (k % 2) * L, (k / 2) * L, 0, alam1[k]);
  for (int k = 0; k < 4; k++) {
    node(k + 5, 2, (k % 2) * L, (k / 2) * L, r0[k], alam2[k]);
    cmd("create_bonds single/bond 1 " + std::to_string(k + 1) + " " + std::to_string(k + 5));
    A += 0.5 * (alam1[k] + alam2[k]);
  }
  cmds({"bond_style cell/lamella", "bond_coeff 1 300 50", "pair_style zero 1.0", "pair_coeff * *",
        "group top molecule 2", "thermo_style custom step bonds"});
  auto pull = [this]() {
    double F = 0.0;
    for (int t = 5; t <= 8; t++) F -= f(t, 2);
    return F;
  };
  const double h = dc() / 100.25;
  cmd("run 0");
  double W = 0.0, Fprev = pull(), Fmax = Fprev;
  int nsteps = 0;
  for (; nsteps < 1200; nsteps++) {
    cmds({"displace_atoms top move 0 0 " + num(h), "run 0"});
    const double F = pull();
    W += 0.5 * h * (F + Fprev);
    Fprev = F;
    Fmax = std::max(Fmax, F);
  }
  const double rel = W / (GC * A) - 1.0;
  const double tol = (h / dc()) * (h / dc()) / 12.0 * 1.01 + 5.0 * std::exp(-10.0) * (h / dc());
  std::printf("work to separate %d bonds (area %.4g um^2): %.10g nN um, Gc A %.10g, rel.err %.2e "
              "(trapezoid bound %.2e); peak pull %.6g nN = %.6f sigma_c A\n",
              4, A, W, GC * A, rel, tol, Fmax, Fmax / (SIGC * A));
  EXPECT_LT(std::fabs(rel), tol);
  EXPECT_NEAR(Fmax / (SIGC * A), 1.0, 1e-3);    // the peak traction sigma_c, sampled to h
  EXPECT_EQ(lmp->atom->nbonds, 0);
  EXPECT_EQ(debonded()->compute_scalar(), 4.0);
  EXPECT_EQ(Fprev, 0.0);
}

// Three cells: cell 1 (nodes 1, 2, tether 1-2), cell 2 above (3, 4, tether 3-4), cell 3 below
// node 2 (5). Lamella bonds (type 2) 1-3 and 2-4 join cells 1 and 2, 2-5 cells 1 and 3; the
// tethers can break (lamf) but are not stretched that far. Areas: A13 = 0.5, A24 = 0.375,
// A25 = 0.325.
class Tissue : public Lamella {
 protected:
  void build()
  {
    tissue_box(2);
    node(1, 1, 0, 0, 0, 0.5);
    node(2, 1, 1, 0, 0, 0.25);
    node(3, 2, 0, 0, 1, 0.5);
    node(4, 2, 1, 0, 1, 0.5);
    node(5, 3, 1, 0, -1, 0.4);
    cmds({"create_bonds single/bond 1 1 2", "create_bonds single/bond 1 3 4",
          "create_bonds single/bond 2 1 3", "create_bonds single/bond 2 2 4",
          "create_bonds single/bond 2 2 5"});
    std::remove("lamella.log");
    cmds({"bond_style hybrid cell/tether cell/lamella log lamella.log"});
    coeffs();
  }
  void coeffs()
  {
    cmds({"bond_coeff 1 cell/tether 8e5 0.126 0.0 lamf 1.5", "bond_coeff 2 cell/lamella 300 50",
          "pair_style zero 2.5", "pair_coeff * *", "compute pl all pair/local dist",
          "thermo_style custom step bonds f_cell_debonded f_cell_broken"});
  }
  // the table row of cells (i, j), or -1
  int row(int ci, int cj)
  {
    for (int r = 0; r < debonded()->size_array_rows; r++)
      if (debonded()->compute_array(r, 0) == ci && debonded()->compute_array(r, 1) == cj) return r;
    return -1;
  }
  void print_table()
  {
    for (int r = 0; r < debonded()->size_array_rows; r++) {
      std::printf("  cells %g-%g: %g bonds, area %g um^2, first %g us, last %g us\n",
                  debonded()->compute_array(r, 0), debonded()->compute_array(r, 1),
                  debonded()->compute_array(r, 2), debonded()->compute_array(r, 3),
                  debonded()->compute_array(r, 4), debonded()->compute_array(r, 5));
    }
  }
  // state after 1-3 (step 5, t = 0.005 us) and 2-4 (step 20) debonded; tethers and 2-5 intact
  void expect_12_debonded()
  {
    print_table();
    EXPECT_EQ(lmp->atom->nbonds, 3);
    EXPECT_FALSE(special_has(1, 3));
    EXPECT_FALSE(special_has(3, 1));
    EXPECT_FALSE(special_has(2, 4));
    EXPECT_TRUE(special_has(1, 2));
    EXPECT_TRUE(special_has(3, 4));
    EXPECT_TRUE(special_has(2, 5));
    EXPECT_EQ(debonded()->compute_scalar(), 2.0);
    EXPECT_EQ(eval("f_cell_debonded"), 2.0);
    for (int t : {1, 2, 3, 4}) EXPECT_EQ(count_at(t), 1.0) << "atom " << t;
    EXPECT_EQ(count_at(5), 0.0);
    const int r = row(1, 2);
    ASSERT_GE(r, 0);
    EXPECT_EQ(debonded()->compute_array(r, 2), 2.0);
    EXPECT_NEAR(debonded()->compute_array(r, 3), 0.5 + 0.375, 1e-15);
    EXPECT_NEAR(eval("f_cell_debonded[1][4]"), 0.875, 1e-15);
    EXPECT_NEAR(debonded()->compute_array(r, 4), 0.005, 1e-15);
    EXPECT_NEAR(debonded()->compute_array(r, 5), 0.02, 1e-15);
    EXPECT_EQ(row(1, 3), -1);
    // tether rupture is a different record, untouched
    auto *broken = lmp->modify->get_fix_by_id("cell_broken");
    ASSERT_NE(broken, nullptr);
    EXPECT_EQ(broken->compute_scalar(), 0.0);
    for (int t = 1; t <= 5; t++) EXPECT_EQ(broken->vector_atom[lmp->atom->map(t)], 0.0);
  }
  bool pair_listed(int a, int b)
  {
    double **x = lmp->atom->x;
    const int i = lmp->atom->map(a), j = lmp->atom->map(b);
    const double r = std::sqrt(std::pow(x[i][0] - x[j][0], 2) + std::pow(x[i][1] - x[j][1], 2) +
                               std::pow(x[i][2] - x[j][2], 2));
    auto *c = lmp->modify->get_compute_by_id("pl");
    c->compute_local();
    for (int n = 0; n < c->size_local_rows; n++)
      if (std::fabs(c->vector_local[n] - r) < 1e-9) return true;
    return false;
  }
  static std::vector<std::string> log_lines()
  {
    std::vector<std::string> lines;
    FILE *fp = std::fopen("lamella.log", "r");
    if (!fp) return lines;
    char buf[256];
    while (std::fgets(buf, sizeof(buf), fp)) lines.emplace_back(buf);
    std::fclose(fp);
    return lines;
  }
};

TEST_F(Tissue, DebondingKeepsItsOwnRecord)
{
  build();
  cmd("run 0");
  EXPECT_EQ(lmp->atom->nbonds, 5);
  EXPECT_TRUE(special_has(1, 3));
  EXPECT_EQ(debonded()->compute_scalar(), 0.0);
  EXPECT_EQ(debonded()->size_array_rows, 0);
  // node 3 is driven up at 1 um/us from an opening of 9.93 dc: it debonds during the run, at
  // step 5 (10.01 dc); the neighbor lists are rebuilt at step 6, with 1-3 an ordinary pair
  cmds({"set atom 3 z " + num(1.0 + 9.93 * dc()), "group n3 id 3", "fix mv n3 move linear 0 0 1.0",
        "run 20", "unfix mv"});
  EXPECT_EQ(lmp->atom->nbonds, 4);
  EXPECT_FALSE(special_has(1, 3));
  EXPECT_EQ(count_at(1), 1.0);
  std::printf("last neighbor list build at step %ld (debond at step 5)\n",
              (long) lmp->neighbor->lastcall);
  EXPECT_EQ(lmp->neighbor->lastcall, 6);
  EXPECT_TRUE(pair_listed(1, 3)) << "debonded pair 1-3 missing from the neighbor list";
  // node 4 past the break (tether 3-4 stretched to 1.2 < lamf)
  cmds({"set atom 4 z " + num(1.0 + 11.0 * dc()), "run 0"});
  expect_12_debonded();

  auto lines = log_lines();
  for (auto &l : lines) std::printf("  log: %s", l.c_str());
  ASSERT_EQ(lines.size(), 3U);
  EXPECT_EQ(lines[0].rfind("# ", 0), 0U);
  EXPECT_EQ(lines[1], "5 0.005 1 3 1 2 0.5\n");
  EXPECT_EQ(lines[2], "20 0.02 2 4 1 2 0.375\n");

  // the restart keeps the table, the counts and the log file's name; bond_style hybrid keeps
  // no coefficients, so they come again, and with them the fixes pick up their restart data
  cmd("write_restart tissue.restart");
  delete lmp;
  lmp = make();
  cmds({"read_restart tissue.restart", "fix cell all property/atom d2_cellref 3 d_alam ghost yes"});
  coeffs();
  cmd("run 0");
  std::printf("after the restart:\n");
  expect_12_debonded();
  // and later debonds add to it
  cmds({"set atom 5 z " + num(-1.0 - 11.0 * dc()), "run 0"});
  print_table();
  EXPECT_EQ(debonded()->compute_scalar(), 3.0);
  EXPECT_EQ(lmp->atom->nbonds, 2);
  EXPECT_EQ(count_at(2), 2.0);
  EXPECT_EQ(count_at(5), 1.0);
  const int r = row(1, 3);
  ASSERT_GE(r, 0);
  EXPECT_EQ(debonded()->compute_array(r, 2), 1.0);
  EXPECT_NEAR(debonded()->compute_array(r, 3), 0.325, 1e-15);
  EXPECT_NEAR(debonded()->compute_array(r, 4), 0.02, 1e-15);
  lines = log_lines();
  ASSERT_EQ(lines.size(), 4U);
  EXPECT_EQ(lines[3], "20 0.02 2 5 1 3 0.325\n");
  std::remove("tissue.restart");
  std::remove("lamella.log");
}

TEST_F(Lamella, PlainStyleRestartsItsCoefficients)
{
  // without hybrid, bond_coeff comes from the restart file and the fix is made by init_style
  one_bond(1.0, 1.0 + 11.0 * dc());
  cmds({"run 0", "write_restart one.restart"});
  EXPECT_EQ(lmp->atom->nbonds, 0);
  delete lmp;
  lmp = make();
  cmds({"read_restart one.restart", "fix cell all property/atom d2_cellref 3 d_alam ghost yes",
        "run 0"});
  ASSERT_NE(debonded(), nullptr);
  EXPECT_EQ(debonded()->compute_scalar(), 1.0);
  EXPECT_EQ(count_at(1), 1.0);
  EXPECT_EQ(count_at(2), 1.0);
  int dim;
  auto *sigma = (double *) lmp->force->bond->extract("sigma", dim);
  auto *Gc = (double *) lmp->force->bond->extract("Gc", dim);
  ASSERT_NE(sigma, nullptr);
  EXPECT_EQ(sigma[1], 300.0);
  EXPECT_EQ(Gc[1], 50.0);
  std::remove("one.restart");
}

TEST_F(Lamella, BadInput)
{
  one_bond(1.0, 1.0);
  EXPECT_ERROR("bond_style cell/lamella 1.0", "bond_style cell/lamella.*expected.*\\[log FILE\\]");
  EXPECT_ERROR("bond_style cell/lamella log", "bond_style cell/lamella.*expected.*\\[log FILE\\]");
  EXPECT_ERROR("bond_coeff 1 300", "bond_coeff cell/lamella.*expected.*sigma_c Gc \\[gamma\\]");
  EXPECT_ERROR("bond_coeff 1 300 50 0 1", "bond_coeff cell/lamella.*expected.*sigma_c Gc");
  EXPECT_ERROR("bond_coeff 1 0 50", "bond_coeff cell/lamella: strength sigma_c must be > 0");
  EXPECT_ERROR("bond_coeff 1 300 -5", "bond_coeff cell/lamella: fracture energy Gc must be > 0");
  EXPECT_ERROR("bond_coeff 1 300 50 -1", "bond_coeff cell/lamella: damping gamma must be >= 0");
  EXPECT_ERROR("bond_coeff 1 300 abc", "Expected floating point");
  cmds({"bond_coeff 1 300 50", "special_bonds lj 0 0 0"});
  EXPECT_ERROR("run 0", "cell/lamella requires 'special_bonds lj 0 1 1'");
}

TEST_F(Lamella, SameCellIsAnError)
{
  one_bond(1.0, 1.0);
  cmd("set atom 2 mol 1");
  EXPECT_ERROR("run 0", "bond 1-2 joins two nodes of the same cell \\(molecule 1\\)");
}

TEST_F(Lamella, NeedsAreaAndReference)
{
  one_bond(1.0, 1.0);
  cmd("set atom 2 d_alam 0.0");
  EXPECT_ERROR("run 0", "bond 1-2 has no area \\(d_alam 0.4 and 0\\)");
  delete lmp;
  lmp = make();
  tissue_box(1, "d2_cellref 3 ghost yes");
  cmds({"create_atoms 1 single 0 0 0", "create_atoms 1 single 1 0 0", "set atom 2 mol 2",
        "create_bonds single/bond 1 1 2", "bond_style cell/lamella", "bond_coeff 1 300 50",
        "pair_style zero 1.0", "pair_coeff * *"});
  EXPECT_ERROR("run 0", "cell/lamella requires the area share.*d_alam ghost yes");
}

// ---------------------------------------------------------------- plugin guard

// Run alone (tests/CMakeLists.txt: ctest's plugin_guard): no other plugin may be loaded first.
TEST(PluginGuard, RefusesForeignLammps)
{
  const char *args[] = {"lmp", "-log", "none", "-echo", "none", nullptr};
  testing::internal::CaptureStdout();
  auto *l = new LAMMPS(5, (char **) args, MPI_COMM_WORLD);
  l->input->one(std::string("plugin load ") + CELLMECH_FOREIGN_PLUGIN);
  std::string out = testing::internal::GetCapturedStdout();
  std::printf("%s\n", out.c_str());
  EXPECT_NE(out.find("cellmech plugin NOT loaded"), std::string::npos);
  EXPECT_NE(out.find("plugin built for '1 Jan 2000'"), std::string::npos);
  l->input->one("units micro");
  l->input->one("atom_style molecular");
  l->input->one("region box block 0 1 0 1 0 1");
  l->input->one("create_box 1 box bond/types 1");
  try {
    l->input->one("bond_style cell/tether");
    ADD_FAILURE() << "a refused plugin must not register its styles";
  } catch (LAMMPSException &e) {
    EXPECT_NE(std::string(e.what()).find("Unrecognized bond style"), std::string::npos);
  }
  delete l;
}

// the cell-topology module (cell_topology.h, cell_mpi.h): header code, no LAMMPS instance
TEST(Topology, SameCellByMoleculeId)
{
  const tagint molecule[3] = {7, 7, 9};
  EXPECT_TRUE(CellMech::same_cell(molecule, 0, 1));
  EXPECT_FALSE(CellMech::same_cell(molecule, 1, 2));
  // without molecule IDs all particles are one body of fluid
  EXPECT_TRUE(CellMech::same_cell(nullptr, 1, 2));
}

TEST(Topology, WallTrianglesSkipTheRemovedOnes)
{
  int rows[3][4] = {{0, 1, 2, 1}, {1, 2, 3, 0}, {2, 3, 4, -1}};
  int row3[4] = {3, 4, 5, 2};
  int *anglelist[4] = {rows[0], rows[1], rows[2], row3};
  std::vector<std::vector<int>> seen;
  CellMech::for_each_wall_triangle(anglelist, 4, [&](int n, int a, int b, int c) {
    seen.push_back({n, a, b, c});
  });
  EXPECT_EQ(seen, (std::vector<std::vector<int>>{{0, 0, 1, 2}, {3, 3, 4, 5}}));
}

TEST(Topology, PairSumsKeepTheIdsAndAddUp)
{
  // the largest IDs a tagint holds come back exactly (they were cast to int, or sent as doubles)
  const tagint big = std::numeric_limits<tagint>::max(), other = big - 1;
  CellMech::PairSums<2> sums;
  sums(big, other)[0] += 1.0;
  sums(other, big)[1] += 0.5;    // the same pair, either order
  sums(3, 2)[0] += 2.0;
  const auto all = sums.summed(MPI_COMM_WORLD).all();
  int nprocs;
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  ASSERT_EQ(all.size(), 2u);
  auto it = all.begin();
  EXPECT_EQ(it->first, CellMech::PairSums<2>::Key(2, 3));
  EXPECT_EQ(it->second[0], 2.0 * nprocs);
  ++it;
  EXPECT_EQ(it->first, CellMech::PairSums<2>::Key(other, big));
  EXPECT_EQ(it->second[0], 1.0 * nprocs);
  EXPECT_EQ(it->second[1], 0.5 * nprocs);
}

}    // namespace

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  int rv = RUN_ALL_TESTS();
  MPI_Finalize();
  return rv;
}
