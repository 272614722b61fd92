/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: dihedral style cell/bending

   Bending stiffness of the cell wall. Every pair of wall triangles sharing
   an edge is a LAMMPS dihedral i-j-k-l with j-k the shared edge (written by
   cellgen.py --bending), a hinge of the discrete-shells energy (Eq. B2 in
   physics/bending.h) with the plate bending stiffness D = G t0^3 / 3 of the
   wall (Eq. B1: E = 3G, nu = 1/2). The hinge bends against its own rest
   dihedral angle, from the reference positions d2_cellref of its nodes (the
   same per-atom array the tethers and membrane elements take their rest
   shape from), so a wall at rest stores no bending energy whatever its
   curvature. The forces are the exact gradient of the energy (Eq. B3):
   energy, momentum and angular momentum are conserved and the virial is
   exact. A tether network or membrane element alone has no bending
   stiffness: its wall crumples under compression of its own plane.
------------------------------------------------------------------------- */

#include "dihedral_cell_bending.h"

#include "cell_checks.h"
#include "cell_compat.h"
#include "cell_fields.h"

#include "atom.h"
#include "cell_restart.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"
#include "physics/bending.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace CellPhysics;

/* ---------------------------------------------------------------------- */

DihedralCellBending::DihedralCellBending(LAMMPS *_lmp) :
    Dihedral(_lmp), G(nullptr), t0(nullptr), iref(-1)
{
  born_matrix_enable = 0;
  writedata = 1;
}

DihedralCellBending::~DihedralCellBending()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(G);
    memory->destroy(t0);
  }
}

/* ---------------------------------------------------------------------- */

void DihedralCellBending::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  // a wall of hinges alone (bond style zero, angle style zero) has nothing else watching each
  // step for a blow-up
  if (!force->bond_match("cell/tether") && !force->angle_match("cell/membrane"))
    CellMech::check_step_motion(lmp, "Dihedral style cell/bending");

  double **x = atom->x;
  double **f = atom->f;
  double **ref = atom->darray[iref];
  int **dihedrallist = neighbor->dihedrallist;
  const int ndihedrallist = neighbor->ndihedrallist;
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;
  double edihedral = 0.0;

  for (int n = 0; n < ndihedrallist; n++) {
    const int type = dihedrallist[n][4];
    if (type <= 0) continue;
    const int node[4] = {dihedrallist[n][0], dihedrallist[n][1], dihedrallist[n][2],
                         dihedrallist[n][3]};

    // LAMMPS's edge vectors vb1 = x1 - x2, vb2 = x3 - x2, vb3 = x4 - x3 (ev_tally takes them)
    double vb1[3], vb2[3], vb3[3], B1[3], B2[3], B3[3];
    for (int d = 0; d < 3; d++) {
      vb1[d] = x[node[0]][d] - x[node[1]][d];
      vb2[d] = x[node[2]][d] - x[node[1]][d];
      vb3[d] = x[node[3]][d] - x[node[2]][d];
      B1[d] = ref[node[0]][d] - ref[node[1]][d];
      B2[d] = ref[node[2]][d] - ref[node[1]][d];
      B3[d] = ref[node[3]][d] - ref[node[2]][d];
    }
    HingeRest rest;
    if (!hinge_rest(B1, B2, B3, rest))
      error->one(FLERR,
                 "Dihedral style cell/bending: hinge {}-{}-{}-{} has a triangle without area in "
                 "its reference shape; are the d2_{} reference positions set and communicated to "
                 "ghosts (ghost yes), and do the two triangles share the edge {}-{}?",
                 atom->tag[node[0]], atom->tag[node[1]], atom->tag[node[2]], atom->tag[node[3]],
                 CellMech::REF_FIELD, atom->tag[node[1]], atom->tag[node[2]]);
    double phi, grad[4][3];
    if (!hinge_angle(vb1, vb2, vb3, phi, grad))
      error->one(FLERR,
                 "Dihedral style cell/bending: hinge {}-{}-{}-{} has collapsed (a triangle with "
                 "its nodes on a line, where the bending angle is undefined); the wall has been "
                 "crushed or tangled -- most likely the time step is too large for the wall "
                 "stiffness, or a node was placed on top of another",
                 atom->tag[node[0]], atom->tag[node[1]], atom->tag[node[2]], atom->tag[node[3]]);

    const double D = bending_stiffness(G[type], t0[type]);
    double fh[4][3];
    hinge_forces(D, rest, phi, grad, fh);
    if (eflag) edihedral = hinge_energy(D, rest, phi);

    for (int a = 0; a < 4; a++)
      if (newton_bond || node[a] < nlocal)
        for (int d = 0; d < 3; d++) f[node[a]][d] += fh[a][d];
    if (evflag)
      ev_tally(node[0], node[1], node[2], node[3], nlocal, newton_bond, edihedral, fh[0], fh[2],
               fh[3], vb1[0], vb1[1], vb1[2], vb2[0], vb2[1], vb2[2], vb3[0], vb3[1], vb3[2]);
  }
}

/* ---------------------------------------------------------------------- */

void DihedralCellBending::allocate()
{
  allocated = 1;
  const int n = atom->ndihedraltypes;
  memory->create(G, n + 1, "dihedral:G");
  memory->create(t0, n + 1, "dihedral:t0");
  memory->create(setflag, n + 1, "dihedral:setflag");
  for (int i = 1; i <= n; i++) setflag[i] = 0;
}

/* ----------------------------------------------------------------------
   dihedral_coeff N G t0
------------------------------------------------------------------------- */

void DihedralCellBending::coeff(int narg, char **arg)
{
  if (narg != 3)
    error->all(FLERR,
               "Dihedral_coeff cell/bending: expected 'dihedral_coeff N G t0' (shear modulus and "
               "thickness of the wall), got {} arguments",
               narg);
  if (atom->ndihedraltypes == 0)
    error->all(FLERR,
               "Dihedral_coeff cell/bending: the system has no dihedral types, so no hinges to "
               "bend: write the data file with them (cellgen.py ... --bending)");
  if (!allocated) allocate();

  int ilo, ihi;
  utils::bounds(FLERR, arg[0], 1, atom->ndihedraltypes, ilo, ihi, error);
  const double G_one = utils::numeric(FLERR, arg[1], false, lmp);
  const double t0_one = utils::numeric(FLERR, arg[2], false, lmp);
  if (!(G_one > 0.0) || !std::isfinite(G_one))
    error->all(FLERR, "Dihedral_coeff cell/bending: shear modulus G must be > 0, got {}", arg[1]);
  if (!(t0_one > 0.0) || !std::isfinite(t0_one))
    error->all(FLERR, "Dihedral_coeff cell/bending: wall thickness t0 must be > 0, got {}", arg[2]);
  CellMech::require_magnitude(lmp, "Dihedral_coeff cell/bending", "G", G_one);
  CellMech::require_magnitude(lmp, "Dihedral_coeff cell/bending", "t0", t0_one);

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    G[i] = G_one;
    t0[i] = t0_one;
    setflag[i] = 1;
    count++;
  }
  if (count == 0) error->all(FLERR, "Incorrect args for dihedral coefficients");
}

/* ---------------------------------------------------------------------- */

void DihedralCellBending::init_style()
{
  CellMech::require_unit_consistency(lmp, "Dihedral style cell/bending");
  int flag, cols;
  iref = atom->find_custom(CellMech::REF_FIELD, flag, cols);
  if (iref < 0 || flag != 1 || cols != 3)
    error->all(FLERR,
               "Dihedral style cell/bending requires the wall reference positions as a per-atom "
               "array: 'fix cell all property/atom rmass d_rho d_drho d2_{} 3 ghost yes' before "
               "read_data, filled from the data file (read_data ... fix ID NULL cell)",
               CellMech::REF_FIELD);
}

/* ---------------------------------------------------------------------- */

void DihedralCellBending::write_restart(FILE *fp)
{
  CellMech::write_type_arrays(fp, atom->ndihedraltypes, {G, t0});
}

void DihedralCellBending::read_restart(FILE *fp)
{
  allocate();
  const int n = atom->ndihedraltypes;
  CellMech::read_type_arrays(fp, n, {G, t0}, comm->me, world, error);
  for (int i = 1; i <= n; i++) setflag[i] = 1;
}

void DihedralCellBending::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ndihedraltypes; i++) fprintf(fp, "%d %.15g %.15g\n", i, G[i], t0[i]);
}

/* ---------------------------------------------------------------------- */

double DihedralCellBending::single(int type, int i1, int i2, int i3, int i4)
{
  double **x = atom->x;
  double **ref = atom->darray[iref];
  double vb1[3], vb2[3], vb3[3], B1[3], B2[3], B3[3];
  for (int d = 0; d < 3; d++) {
    vb1[d] = x[i1][d] - x[i2][d];
    vb2[d] = x[i3][d] - x[i2][d];
    vb3[d] = x[i4][d] - x[i3][d];
    B1[d] = ref[i1][d] - ref[i2][d];
    B2[d] = ref[i3][d] - ref[i2][d];
    B3[d] = ref[i4][d] - ref[i3][d];
  }
  HingeRest rest;
  double phi;
  if (!hinge_rest(B1, B2, B3, rest) || !hinge_angle(vb1, vb2, vb3, phi)) return 0.0;
  return hinge_energy(bending_stiffness(G[type], t0[type]), rest, phi);
}

/* ---------------------------------------------------------------------- */

void *DihedralCellBending::extract(const char *str, int &dim)
{
  dim = 1;
  if (strcmp(str, "G") == 0) return (void *) G;
  if (strcmp(str, "t0") == 0) return (void *) t0;
  return nullptr;
}
