/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the tether sweep of bond style cell/tether (cell_tether_sweep.h)
------------------------------------------------------------------------- */

#include "cell_tether_sweep.h"

#include "cell_checks.h"
#include "cell_fields.h"
#include "cell_simd.h"

#include "atom.h"
#include "error.h"
#include "neighbor.h"
#include "physics/damping.h"
#include "physics/tether.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace CellPhysics;

namespace CellMech {

/* ----------------------------------------------------------------------
   Stretch lam = l / l0 and force factor fbond (the force on atom 1 is fbond (x1 - x2)) of n
   tethers from their squared lengths, r . v, rest lengths, tension factors (Eq. 19) and
   damping coefficients: the tension of tether_tension_scaled and damping_fpair where the
   coefficient is > 0. Compiled for the baseline and for AVX2 (cell_simd.h), with the bits of one
   tether at a time.
------------------------------------------------------------------------- */

CELLMECH_SIMD_CLONES static void
tether_sweep(int n, const double *__restrict rsq, const double *__restrict rdv,
             const double *__restrict rest, const double *__restrict scale,
             const double *__restrict damp, double *__restrict lam, double *__restrict fbond)
{
  for (int k = 0; k < n; k++) {
    const double r = std::sqrt(rsq[k]);
    const double l = r / rest[k];
    const double fb = -tether_tension_scaled(scale[k], l) / r;
    lam[k] = l;
    fbond[k] = damp[k] > 0.0 ? fb + damping_fpair(damp[k], rdv[k], rsq[k]) : fb;
  }
}

/* ----------------------------------------------------------------------
   Each tether's rest length, tension factor and damping coefficient change only with the bond
   list (a build or a setup): computed then, they spare every step a square root and a
   division, which the divider of the CPU, the loop's bottleneck, would otherwise run for every
   tether.
------------------------------------------------------------------------- */

void TetherSweep::rest_lengths(const TetherTypeData &coeff)
{
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;
  if (!list_rebuilt(lmp, rest_build, rest.size(), nbondlist)) return;
  rest.assign(nbondlist, 1.0);
  scale.assign(nbondlist, 0.0);
  damp.assign(nbondlist, 0.0);
  for (int n = 0; n < nbondlist; n++) {
    const int i1 = bondlist[n][0];
    const int i2 = bondlist[n][1];
    const int type = bondlist[n][2];
    if (type <= 0) continue;
    const double l0 = rest_length(atom->darray[coeff.iref], i1, i2);
    if (!(l0 > 0.0))
      error->one(FLERR,
                 "Bond style cell/tether: tether {}-{} has zero rest length; are the "
                 "d2_cellref reference positions set and communicated to ghosts (ghost yes)?{}",
                 atom->tag[i1], atom->tag[i2], RESTART_FIELDS_HINT);
    rest[n] = l0;
    scale[n] = tether_tension_scale(coeff.G[type], coeff.t0[type], l0);
    damp[n] = coeff.gamma[type];
  }
}

/* ----------------------------------------------------------------------
   Two passes: the separations (gathers), then the stretch and force factor of every tether
   (tether_sweep, whose square roots and divisions run in SIMD lanes); the style applies them in
   the bond list's order, so that every force adds up as before, bit for bit.
------------------------------------------------------------------------- */

TetherStep TetherSweep::sweep(const TetherTypeData &coeff)
{
  rest_lengths(coeff);
  double **x = atom->x;
  double **v = atom->v;
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;
  if ((int) fields.size() < SWEEP_FIELDS * nbondlist) fields.resize(SWEEP_FIELDS * nbondlist);
  double *const dx = fields.data(), *const dy = dx + nbondlist, *const dz = dy + nbondlist;
  double *const rsq = dz + nbondlist, *const rdv = rsq + nbondlist;
  double *const lam = rdv + nbondlist, *const fbond = lam + nbondlist;
  for (int n = 0; n < nbondlist; n++) {
    const int i1 = bondlist[n][0];
    const int i2 = bondlist[n][1];
    dx[n] = x[i1][0] - x[i2][0];
    dy[n] = x[i1][1] - x[i2][1];
    dz[n] = x[i1][2] - x[i2][2];
    rsq[n] = dx[n] * dx[n] + dy[n] * dy[n] + dz[n] * dz[n];
    rdv[n] = dx[n] * (v[i1][0] - v[i2][0]) + dy[n] * (v[i1][1] - v[i2][1]) +
        dz[n] * (v[i1][2] - v[i2][2]);
  }
  tether_sweep(nbondlist, rsq, rdv, rest.data(), scale.data(), damp.data(), lam, fbond);
  return {dx, dy, dz, lam, fbond, rest.data()};
}

}    // namespace CellMech
