/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: angle style cell/membrane

   Every wall triangle (an angle a-b-c of the topology, written by cellgen.py
   with b its central node) is a constant-strain element of an incompressible
   thin Neo-Hookean sheet of shear modulus G and thickness t0 (Eq. M1 in
   physics/membrane.h), measured against the triangle's own rest shape: the
   reference positions d2_cellref of its nodes, the same per-atom array the
   tethers take their rest lengths from. The forces are the exact gradient
   of that energy (Eq. M2), so energy, momentum and angular momentum are
   conserved and the virial is exact. Unlike a tether network, whose shear
   modulus is 1.5 times the sheet's, the element has the sheet's response in
   every deformation, not only in equibiaxial stretch.
   Damping: each edge of a triangle carries gamma / 2 along it (Eq. 11), so a
   wall edge, shared by two triangles, is damped as one tether of gamma.
   Failure (lamf): a triangle whose largest principal stretch passes lamf
   leaves the wall; the topology follows on every rank in fix
   CELL_TETHER_BREAK, the same bookkeeping as for broken tethers.
------------------------------------------------------------------------- */

#include "angle_cell_membrane.h"

#include "cell_checks.h"
#include "cell_coeff.h"
#include "cell_compat.h"
#include "cell_fields.h"

#include "atom.h"
#include "bond.h"
#include "cell_restart.h"
#include "comm.h"
#include "error.h"
#include "fix_cell_tether_break.h"
#include "force.h"
#include "math_const.h"
#include "memory.h"
#include "neighbor.h"
#include "physics/damping.h"
#include "physics/membrane.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace CellPhysics;

// smallest area ratio of a triangle to its rest shape before the run stops: the element's energy
// diverges as the area vanishes (the incompressible sheet thickens without bound), so a triangle
// this small is an integration that has already failed, not a state of the wall
static constexpr double MIN_AREA_RATIO = 1.0e-3;

/* ---------------------------------------------------------------------- */

AngleCellMembrane::AngleCellMembrane(LAMMPS *_lmp) :
    Angle(_lmp), G(nullptr), t0(nullptr), gamma(nullptr), lamf(nullptr), wrinkle(nullptr), iref(-1),
    breaker(nullptr)
{
  born_matrix_enable = 0;
  writedata = 1;
}

AngleCellMembrane::~AngleCellMembrane()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(G);
    memory->destroy(t0);
    memory->destroy(gamma);
    memory->destroy(lamf);
    memory->destroy(wrinkle);
  }
}

/* ---------------------------------------------------------------------- */

void AngleCellMembrane::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  // a membrane wall may have no tethers to watch each step for a blow-up (bond style zero)
  if (!force->bond_match("cell/tether"))
    CellMech::check_step_motion(lmp, "Angle style cell/membrane");

  double **f = atom->f;
  int **anglelist = neighbor->anglelist;
  const int nanglelist = neighbor->nanglelist;
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;
  double eangle = 0.0;
  rest_shapes();

  for (int n = 0; n < nanglelist; n++) {
    const int type = anglelist[n][3];
    if (type <= 0) continue;    // triangle of a broken wall
    const int ia = anglelist[n][0], ib = anglelist[n][1], ic = anglelist[n][2];

    double a[3], c[3];
    MembraneRest rest;
    MembraneStrain s;
    if (!cached_shape(n, ia, ib, ic, rest, s, a, c))
      error->one(FLERR,
                 "Angle style cell/membrane: triangle {}-{}-{} has no area in its reference "
                 "shape; are the d2_{} reference positions set and communicated to ghosts "
                 "(ghost yes)?",
                 atom->tag[ia], atom->tag[ib], atom->tag[ic], CellMech::REF_FIELD);
    if (!(s.J2 > MIN_AREA_RATIO * MIN_AREA_RATIO)) degenerate(ia, ib, ic, s.J2);

    if (lamf[type] > 0.0) {
      double lam1, lam2;
      membrane_stretches(s, lam1, lam2);
      // tension only: lam1 >= lam2, so a triangle shortened in every direction never fails. It
      // leaves the angle list now; fix CELL_TETHER_BREAK takes it out of the topology on every
      // rank.
      if (lam1 > lamf[type]) {
        anglelist[n][3] = 0;
        breaker->triangle_failed(atom->tag[ia], atom->tag[ib], atom->tag[ic]);
        continue;
      }
    }

    double fa[3], fc[3];
    const double w =
        membrane_forces(G[type], t0[type], rest, s, fa, fc, wrinkle[type] > 0.0, residual(type));
    if (eflag) eangle = w;

    double fb[3] = {-fa[0] - fc[0], -fa[1] - fc[1], -fa[2] - fc[2]};
    const int node[3] = {ia, ib, ic};
    double *fn[3] = {fa, fb, fc};
    add_damping(type, node, fn);

    if (newton_bond || ia < nlocal)
      for (int d = 0; d < 3; d++) f[ia][d] += fa[d];
    if (newton_bond || ib < nlocal)
      for (int d = 0; d < 3; d++) f[ib][d] += fb[d];
    if (newton_bond || ic < nlocal)
      for (int d = 0; d < 3; d++) f[ic][d] += fc[d];
    if (evflag)
      ev_tally(ia, ib, ic, nlocal, newton_bond, eangle, fa, fc, a[0], a[1], a[2], c[0], c[1], c[2]);
  }
  if (breaker) breaker->computed();
}

/* ----------------------------------------------------------------------
   current and reference shape of triangle ia-ib-ic: edges a, c from the
   central node ib and the strain; false if the reference shape has no area
------------------------------------------------------------------------- */

bool AngleCellMembrane::shape(int ia, int ib, int ic, MembraneRest &rest, MembraneStrain &s,
                              double a[3], double c[3]) const
{
  if (!rest_shape(ia, ib, ic, rest)) return false;
  strain(rest, ia, ib, ic, s, a, c);
  return true;
}

// the rest shape from the nodes' reference positions; false if it has no area
bool AngleCellMembrane::rest_shape(int ia, int ib, int ic, MembraneRest &rest) const
{
  double **ref = atom->darray[iref];
  double A[3], C[3];
  for (int d = 0; d < 3; d++) {
    A[d] = ref[ia][d] - ref[ib][d];
    C[d] = ref[ic][d] - ref[ib][d];
  }
  return membrane_rest(A, C, rest);
}

// the current edges a, c from the central node ib and the strain against the rest shape
void AngleCellMembrane::strain(const MembraneRest &rest, int ia, int ib, int ic, MembraneStrain &s,
                               double a[3], double c[3]) const
{
  double **x = atom->x;
  for (int d = 0; d < 3; d++) {
    a[d] = x[ia][d] - x[ib][d];
    c[d] = x[ic][d] - x[ib][d];
  }
  membrane_strain(rest, a, c, s);
}

void AngleCellMembrane::rest_shapes()
{
  int **anglelist = neighbor->anglelist;
  const int nanglelist = neighbor->nanglelist;
  if (!CellMech::list_rebuilt(lmp, rest_build, rests.size(), nanglelist)) return;
  rests.assign(nanglelist, RestShape{0.0, 0.0, 0.0, 0.0});
  for (int n = 0; n < nanglelist; n++) {
    MembraneRest rest;
    if (rest_shape(anglelist[n][0], anglelist[n][1], anglelist[n][2], rest))
      rests[n] = RestShape{rest.Dinv[0][0], rest.Dinv[0][1], rest.Dinv[1][1], rest.area};
  }
}

// shape() with the rest shape of entry n of the angle list (rest_shapes): the same numbers
bool AngleCellMembrane::cached_shape(int n, int ia, int ib, int ic, MembraneRest &rest,
                                     MembraneStrain &s, double a[3], double c[3]) const
{
  const RestShape &r = rests[n];
  if (!(r.area > 0.0)) return false;
  rest.Dinv[0][0] = r.d00;
  rest.Dinv[0][1] = r.d01;
  rest.Dinv[1][0] = 0.0;
  rest.Dinv[1][1] = r.d11;
  rest.area = r.area;
  strain(rest, ia, ib, ic, s, a, c);
  return true;
}

// half of Eq. 11 on each edge of the triangle with nodes node[], added to their forces fn[]: a
// wall edge belongs to two triangles
void AngleCellMembrane::add_damping(int type, const int node[3], double *fn[3])
{
  if (!(gamma[type] > 0.0)) return;
  double **x = atom->x;
  double **v = atom->v;
  for (int e = 0; e < 3; e++) {
    const int i = node[e], j = node[(e + 1) % 3];
    double dx[3], dv[3];
    for (int d = 0; d < 3; d++) {
      dx[d] = x[i][d] - x[j][d];
      dv[d] = v[i][d] - v[j][d];
    }
    const double rsq = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
    const double rdotv = dx[0] * dv[0] + dx[1] * dv[1] + dx[2] * dv[2];
    const double fdamp = damping_fpair(0.5 * gamma[type], rdotv, rsq);
    for (int d = 0; d < 3; d++) {
      fn[e][d] += fdamp * dx[d];
      fn[(e + 1) % 3][d] -= fdamp * dx[d];
    }
  }
}

bool AngleCellMembrane::triangle_forces(int type, int ia, int ib, int ic, double f[3][3])
{
  double a[3], c[3];
  MembraneRest rest;
  MembraneStrain s;
  if (!shape(ia, ib, ic, rest, s, a, c) || !(s.J2 > 0.0)) return false;
  membrane_forces(G[type], t0[type], rest, s, f[0], f[2], wrinkle[type] > 0.0, residual(type));
  for (int d = 0; d < 3; d++) f[1][d] = -f[0][d] - f[2][d];
  const int node[3] = {ia, ib, ic};
  double *fn[3] = {f[0], f[1], f[2]};
  add_damping(type, node, fn);
  return true;
}

/* ---------------------------------------------------------------------- */

void AngleCellMembrane::degenerate(int ia, int ib, int ic, double J2)
{
  error->one(FLERR,
             "Angle style cell/membrane: triangle {}-{}-{} has shrunk to {:.3g} of its rest area "
             "(the element cannot go below {:.0e}); the wall has been crushed or tangled in one "
             "step -- most likely the time step is too large for the wall stiffness, or a node "
             "was placed on top of another",
             atom->tag[ia], atom->tag[ib], atom->tag[ic], std::sqrt(std::max(J2, 0.0)),
             MIN_AREA_RATIO);
}

/* ---------------------------------------------------------------------- */

void AngleCellMembrane::allocate()
{
  allocated = 1;
  const int n = atom->nangletypes;
  memory->create(G, n + 1, "angle:G");
  memory->create(t0, n + 1, "angle:t0");
  memory->create(gamma, n + 1, "angle:gamma");
  memory->create(lamf, n + 1, "angle:lamf");
  memory->create(wrinkle, n + 1, "angle:wrinkle");
  memory->create(setflag, n + 1, "angle:setflag");
  for (int i = 1; i <= n; i++) setflag[i] = 0;
}

/* ----------------------------------------------------------------------
   angle_coeff N G t0 [gamma] [lamf value] [wrinkle yes|no] [residual r]
------------------------------------------------------------------------- */

void AngleCellMembrane::coeff(int narg, char **arg)
{
  static const char *usage = "expected 'angle_coeff N G t0 [gamma] [lamf value] [wrinkle yes|no] "
                             "[residual r]' (shear modulus, wall thickness, edge damping, critical "
                             "stretch, tension-field theory and its residual stiffness)";
  if (narg < 3) error->all(FLERR, "Angle_coeff cell/membrane: {}, got {} arguments", usage, narg);
  // the optional gamma is the one positional argument after t0 that is not a keyword
  int iarg = 3;
  const auto keyword = [&](int i) {
    return strcmp(arg[i], "lamf") == 0 || strcmp(arg[i], "wrinkle") == 0 ||
        strcmp(arg[i], "residual") == 0;
  };
  if (iarg < narg && !keyword(iarg)) iarg++;
  const int ngamma = iarg - 3;
  double lamf_one = 0.0, wrinkle_one = 0.0, residual_one = 0.0;
  for (; iarg < narg; iarg += 2) {
    if (!keyword(iarg))
      error->all(FLERR,
                 "Angle_coeff cell/membrane: unknown keyword '{}', expected 'lamf', 'wrinkle' "
                 "or 'residual'",
                 arg[iarg]);
    if (iarg + 1 >= narg)
      error->all(FLERR, "Angle_coeff cell/membrane: keyword '{}' needs a value; {}", arg[iarg],
                 usage);
    if (strcmp(arg[iarg], "lamf") == 0) {
      lamf_one = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(lamf_one > 1.0) || !std::isfinite(lamf_one))
        error->all(FLERR,
                   "Angle_coeff cell/membrane: critical stretch lamf must be > 1 (a triangle fails "
                   "when its largest principal stretch passes lamf), got {}",
                   arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "residual") == 0) {
      residual_one = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(residual_one > 0.0 && residual_one < 1.0))
        error->all(FLERR,
                   "Angle_coeff cell/membrane: residual must be > 0 and < 1 (the fraction of the "
                   "full sheet's stiffness a wrinkled triangle keeps, Eq. M4), got {}",
                   arg[iarg + 1]);
    } else {
      const std::string v = arg[iarg + 1];
      if (v != "yes" && v != "no")
        error->all(FLERR,
                   "Angle_coeff cell/membrane: wrinkle must be 'yes' (tension-field theory, Eq. "
                   "M3) or 'no' (the full sheet, Eq. M1), got '{}'",
                   v);
      wrinkle_one = v == "yes" ? 1.0 : 0.0;
    }
  }
  if (residual_one > 0.0 && wrinkle_one == 0.0)
    error->all(FLERR,
               "Angle_coeff cell/membrane: residual {} needs wrinkle yes: it is the stiffness a "
               "wrinkled triangle keeps (Eq. M4)",
               residual_one);
  // one per-type array for both, so that restart files keep their layout: 0 for the full sheet,
  // 1 + r for tension-field theory with the residual r
  if (wrinkle_one > 0.0) wrinkle_one += residual_one;
  if (atom->nangletypes == 0)
    error->all(FLERR,
               "Angle_coeff cell/membrane: the system has no angle types, so no wall triangles "
               "to give coefficients to (a data file of cellgen.py has them)");
  if (!allocated) allocate();

  int ilo, ihi;
  utils::bounds(FLERR, arg[0], 1, atom->nangletypes, ilo, ihi, error);
  const char *cmd = "Angle_coeff cell/membrane";
  const CellMech::WallCoefficients wall = CellMech::wall_coefficients(lmp, cmd, arg + 1, ngamma);
  CellMech::require_magnitude(lmp, cmd, "critical stretch lamf", lamf_one);
  if (CellMech::set_types(ilo, ihi, setflag,
                          {{G, wall.G},
                           {t0, wall.t0},
                           {gamma, wall.gamma},
                           {lamf, lamf_one},
                           {wrinkle, wrinkle_one}}) == 0)
    error->all(FLERR, "Incorrect args for angle coefficients");
  // created now, so that its count (f_cell_broken) can be used in thermo and variables at once
  if (lamf_one > 0.0) FixCellTetherBreak::ensure(lmp);
}

/* ---------------------------------------------------------------------- */

void AngleCellMembrane::init_style()
{
  CellMech::require_unit_consistency(lmp, "Angle style cell/membrane");
  iref = CellMech::reference_positions(lmp, "Angle style cell/membrane");
  if (CellMech::any_positive(setflag, gamma, atom->nangletypes))
    CellMech::require_ghost_velocities(lmp, "Angle style cell/membrane with damping gamma > 0");

  // the membrane is the continuum form of the tether net (Eqs. M1-M2 against Eq. 19): with the
  // tethers on as well the wall is counted twice, and a cell holds a higher turgor at the same
  // osmotic potential
  Bond *tethers = force->bond_match("cell/tether");
  bool tethered = false;
  if (tethers && tethers->setflag)
    for (int i = 1; i <= atom->nbondtypes; i++)
      if (tethers->setflag[i]) tethered = true;
  if (tethered)
    error->all(FLERR,
               "Angle style cell/membrane: bond style cell/tether acts on the same wall: the "
               "tethers and the membrane are two models of one wall and together count it twice. "
               "Keep the tethers as topology (bond_style zero, or zero for the wall's type under "
               "bond_style hybrid: cell-wall.lmp -var wall membrane), or the tethers alone "
               "(angle_style zero nocoeff: -var wall tether)");
  CellMech::check_drag(lmp);

  // triangles that can fail need the topology bookkeeping of fix CELL_TETHER_BREAK (made by
  // angle_coeff, or here for coefficients from a restart file, before the fixes are initialised)
  breaker = nullptr;
  if (CellMech::any_positive(setflag, lamf, atom->nangletypes)) {
    // the nodes of an edge whose triangles have all failed become a non-bonded pair, as those of
    // a broken tether (bond style cell/tether)
    CellMech::require_special_lj_011(lmp, "Angle style cell/membrane with a critical stretch lamf",
                                     "an edge without triangles turns its nodes into a non-bonded "
                                     "pair");
    breaker = FixCellTetherBreak::ensure(lmp);
  }
}

/* ---------------------------------------------------------------------- */

double AngleCellMembrane::equilibrium_angle(int /*i*/)
{
  // each triangle has its own rest shape; the equilateral angle is the nominal one
  return MathConst::MY_PI / 3.0;
}

/* ---------------------------------------------------------------------- */

void AngleCellMembrane::write_restart(FILE *fp)
{
  CellMech::write_type_arrays(fp, atom->nangletypes, {G, t0, gamma, lamf, wrinkle});
}

void AngleCellMembrane::read_restart(FILE *fp)
{
  allocate();
  const int n = atom->nangletypes;
  CellMech::read_type_arrays(fp, n, {G, t0, gamma, lamf, wrinkle}, comm->me, world, error);
  for (int i = 1; i <= n; i++) setflag[i] = 1;
}

void AngleCellMembrane::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->nangletypes; i++) {
    fprintf(fp, "%d %.15g %.15g %.15g", i, G[i], t0[i], gamma[i]);
    if (lamf[i] > 0.0) fprintf(fp, " lamf %.15g", lamf[i]);
    if (wrinkle[i] > 0.0) fprintf(fp, " wrinkle yes");
    if (residual(i) > 0.0) fprintf(fp, " residual %g", residual(i));
    fprintf(fp, "\n");
  }
}

/* ---------------------------------------------------------------------- */

double AngleCellMembrane::single(int type, int i1, int i2, int i3)
{
  double a[3], c[3];
  MembraneRest rest;
  MembraneStrain s;
  if (!shape(i1, i2, i3, rest, s, a, c) || !(s.J2 > 0.0)) return 0.0;
  return membrane_energy(G[type], t0[type], rest, s, wrinkle[type] > 0.0, residual(type));
}

/* ---------------------------------------------------------------------- */

void *AngleCellMembrane::extract(const char *str, int &dim)
{
  dim = 1;
  if (strcmp(str, "G") == 0) return (void *) G;
  if (strcmp(str, "t0") == 0) return (void *) t0;
  if (strcmp(str, "gamma") == 0) return (void *) gamma;
  if (strcmp(str, "lamf") == 0) return (void *) lamf;
  if (strcmp(str, "wrinkle") == 0) return (void *) wrinkle;
  return nullptr;
}
