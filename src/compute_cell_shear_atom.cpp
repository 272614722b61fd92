/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: compute cell/shear/atom

   SPH estimate of the protoplasm's viscous shear stress (Eqs. 24-26):
     tau_i^ab = mu_i ( sum_j (m_j/rho_j) v_ji^b dW_ij/dx_i^a
                     + sum_j (m_j/rho_j) v_ji^a dW_ij/dx_i^b ),  v_ji = v_j - v_i
     tau_i = sqrt(tau_xy^2 + tau_xz^2 + tau_yz^2)
   Per-atom array: 1 tau, 2 tau_xy, 3 tau_xz, 4 tau_yz (pressure units), zero for non-fluid
   atoms. The sums run over the particles pair cell/sph pairs a particle with: fluid of the same
   cell (CellMech::same_cell), whatever its group. A full neighbour list, built when the compute
   is invoked, keeps each particle's sum local, so no reverse communication is needed; the
   velocities of the ghosts are sent anew, since LAMMPS last sent them after the first half of
   the step's integration (comm_modify vel yes), half a step before the owners' at output. The
   mean over a region (the impact zone) is `compute reduce/region ... ave c_ID[1]`.
------------------------------------------------------------------------- */

#include "compute_cell_shear_atom.h"

#include "atom.h"
#include "cell_topology.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "pair_cell_sph.h"
#include "physics/kernel.h"
#include "physics/observables.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace CellPhysics;

ComputeCellShearAtom::ComputeCellShearAtom(LAMMPS *_lmp, int narg, char **arg) :
    Compute(_lmp, narg, arg), nmax(0), tau(nullptr), list(nullptr), sph(nullptr)
{
  if (narg != 3)
    error->all(FLERR,
               "Illegal compute cell/shear/atom command: expected no arguments after the "
               "style, got {}",
               narg - 3);
  peratom_flag = 1;
  size_peratom_cols = 4;
  comm_forward = 3;
}

ComputeCellShearAtom::~ComputeCellShearAtom()
{
  memory->destroy(tau);
}

void ComputeCellShearAtom::init()
{
  sph = dynamic_cast<PairCellSPH *>(force->pair_match("^cell/sph", 0));
  if (!sph) error->all(FLERR, "Compute cell/shear/atom requires pair style cell/sph");
  if (!atom->rmass_flag) error->all(FLERR, "Compute cell/shear/atom requires per-atom masses");
  // built only when invoked; the pair's cutoffs cover the kernel support 2s
  neighbor->add_request(this, NeighConst::REQ_FULL | NeighConst::REQ_OCCASIONAL);
}

void ComputeCellShearAtom::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

void ComputeCellShearAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(tau);
    nmax = atom->nmax;
    memory->create(tau, nmax, 4, "cell/shear/atom:tau");
    array_atom = tau;
  }
  neighbor->build_one(list);
  comm->forward_comm(this);

  double **x = atom->x;
  double **v = atom->v;
  double *rmass = atom->rmass;
  int *type = atom->type;
  int *mask = atom->mask;
  const tagint *molecule = atom->molecule;
  const double *rho = sph->rho_array();
  int dim;
  auto mu = (double *) sph->extract("mu", dim);
  auto s = (double **) sph->extract("s", dim);

  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < 4; k++) tau[i][k] = 0.0;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int itype = type[i];
    if (!(mask[i] & groupbit) || !sph->is_fluid(itype)) continue;
    double g[3][3] = {{0.0}};    // g[a][b] = sum_j (m_j/rho_j) v_ji^b dW/dx_i^a
    int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const int jtype = type[j];
      if (!sph->is_fluid(jtype) || !CellMech::same_cell(molecule, i, j)) continue;
      const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      const double smooth = s[itype][jtype];
      if (rsq >= 4.0 * smooth * smooth || rsq == 0.0) continue;
      const double r = sqrt(rsq);
      const double w = rmass[j] / rho[j] * kernel_dwdr(r, smooth) / r;
      const double vji[3] = {v[j][0] - v[i][0], v[j][1] - v[i][1], v[j][2] - v[i][2]};
      velocity_gradient_add(g, w, del, vji);
    }
    const double txy = viscous_shear(mu[itype], g, 0, 1);
    const double txz = viscous_shear(mu[itype], g, 0, 2);
    const double tyz = viscous_shear(mu[itype], g, 1, 2);
    tau[i][0] = shear_stress_magnitude(txy, txz, tyz);
    tau[i][1] = txy;
    tau[i][2] = txz;
    tau[i][3] = tyz;
  }
}

/* ----------------------------------------------------------------------
   the owners' velocities to their ghosts; an image across a periodic boundary of a box that
   fix deform remaps takes the box's velocity, as LAMMPS's own ghost velocities do
------------------------------------------------------------------------- */

int ComputeCellShearAtom::pack_forward_comm(int n, int *list, double *buf, int pbc_flag, int *pbc)
{
  double **v = atom->v;
  const int *mask = atom->mask;
  double dv[3] = {0.0, 0.0, 0.0};
  if (pbc_flag && domain->deform_vremap) {
    const double *h_rate = domain->h_rate;
    dv[0] = pbc[0] * h_rate[0] + pbc[5] * h_rate[5] + pbc[4] * h_rate[4];
    dv[1] = pbc[1] * h_rate[1] + pbc[3] * h_rate[3];
    dv[2] = pbc[2] * h_rate[2];
  }
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    const bool remap = pbc_flag && domain->deform_vremap && (mask[j] & domain->deform_groupbit);
    for (int d = 0; d < 3; d++) buf[m++] = remap ? v[j][d] + dv[d] : v[j][d];
  }
  return m;
}

void ComputeCellShearAtom::unpack_forward_comm(int n, int first, double *buf)
{
  double **v = atom->v;
  int m = 0;
  for (int i = first; i < first + n; i++) {
    v[i][0] = buf[m++];
    v[i][1] = buf[m++];
    v[i][2] = buf[m++];
  }
}

double ComputeCellShearAtom::memory_usage()
{
  return 4.0 * nmax * sizeof(double);
}
