/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: fix cell/plates

   The plates of Eq. 21 are a harmonic wall (docs/Howto_plates.rst), and
   under Verlet this fix is LAMMPS's fix wall/harmonic, bit for bit. Under
   run_style respa the plates may need the wall's short step (the contact
   spring k_p on a wall node is as stiff as a tether), so they go on an
   inner level (fix_modify ID respa 1). fix wall/harmonic then reports the
   force of the last inner step only, while the fluid's impulse, applied
   once per outer step, makes the contact force swing over the inner steps
   (read that way, the force of a compression came out 22-68% low). This
   fix reports the mean over the inner steps of the outer step: the
   impulse the plates gave, divided by the outer step, which is the force
   a single-level run reads.

   And a cost: fix wall/harmonic, when a plate moves (its coordinate an
   equal-style variable), asks every compute for the next step so that the
   variable may use one, and the potential energy is such a compute: every
   pair, bond and angle style then tallied its energy every step, a tenth
   of a compression's time. This fix evaluates the coordinates itself and
   leaves the energy to the steps that output it.

   The work of the moving walls (f_ID[nwall + m], m = 1 .. nwall): a
   quasi-static test compares the kinetic energy with it (issue 29). Summed
   in an input by fix ave/time at every step, it asked every compute for
   every step, the same cost again (21% of a compression); this fix sums it
   per rank in each call and adds the ranks up only when it is output, so
   it also costs no reduction per step.
------------------------------------------------------------------------- */

#include "fix_cell_plates.h"

#include "input.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

using namespace LAMMPS_NS;

FixCellPlates::FixCellPlates(LAMMPS *_lmp, int narg, char **arg) :
    FixWallHarmonic(_lmp, narg, arg), nsum(0)
{
  for (double &e : esum) e = 0.0;
  for (int m = 0; m < 6; m++) work[m] = lastcoord[m] = 0.0;
  size_vector = 2 * nwall;
}

/* ----------------------------------------------------------------------
   fix wall/harmonic's force, with the moving walls' coordinates evaluated here and handed to it
   as constants for this call (variable epsilon or sigma: its own way, unchanged). A coordinate
   variable may still use a compute that can be evaluated at any step (LAMMPS invokes it); one
   that needs the energy or virial of the step stops with LAMMPS's error.
------------------------------------------------------------------------- */

void FixCellPlates::post_force(int vflag)
{
  bool coords_only = varflag != 0;
  for (int m = 0; m < nwall; m++) coords_only = coords_only && wstyle[m] != VARIABLE;
  if (!coords_only) {
    FixWallHarmonic::post_force(vflag);
    return;
  }
  modify->clearstep_compute();
  int moving[6] = {0, 0, 0, 0, 0, 0};
  double fixed[6];
  for (int m = 0; m < nwall; m++) {
    if (xstyle[m] != VARIABLE) continue;
    // as fix wall scales a variable coordinate (units lattice)
    const double scale = wallwhich[m] < YLO ? xscale : (wallwhich[m] < ZLO ? yscale : zscale);
    moving[m] = 1;
    fixed[m] = coord0[m];
    coord0[m] = input->variable->compute_equal(xindex[m]) * scale;
    xstyle[m] = CONSTANT;
  }
  varflag = 0;
  FixWallHarmonic::post_force(vflag);
  varflag = 1;
  for (int m = 0; m < nwall; m++)
    if (moving[m]) {
      add_work(m, coord0[m]);
      coord0[m] = fixed[m];
      xstyle[m] = VARIABLE;
    }
}

/* ----------------------------------------------------------------------
   The work wall m has done on this rank's atoms in the step that brought it to coord: the force
   of its atoms on it (ewall, fix wall's sign: the reaction) against its move, at the end of the
   step, as a sum of F v dt. A setup moves nothing: it only takes the coordinate a run starts from
   (every run starts with one, so the first coordinate is always a setup's).
------------------------------------------------------------------------- */

void FixCellPlates::add_work(int m, double coord)
{
  if (!update->setupflag) work[m] -= ewall[m + 1] * (coord - lastcoord[m]);
  lastcoord[m] = coord;
}

/* ----------------------------------------------------------------------
   1 .. nwall: fix wall's force on each wall; nwall + 1 .. 2 nwall: the work each has done since
   the fix was defined (zero for a wall that does not move, and for every wall when epsilon or
   sigma is a variable: post_force then leaves the walls to fix wall/harmonic)
------------------------------------------------------------------------- */

double FixCellPlates::compute_vector(int n)
{
  if (n < nwall) return FixWallHarmonic::compute_vector(n);
  double all[6];
  MPI_Allreduce(work, all, nwall, MPI_DOUBLE, MPI_SUM, world);
  return all[n - nwall];
}

/* ----------------------------------------------------------------------
   iloop counts the steps of this level within one step of the level above
   (0 first); the setup calls it once with 0
------------------------------------------------------------------------- */

void FixCellPlates::post_force_respa(int vflag, int ilevel, int iloop)
{
  if (ilevel != ilevel_respa) return;
  post_force(vflag);
  if (iloop == 0) {
    nsum = 0;
    for (int m = 0; m <= nwall; m++) esum[m] = 0.0;
  }
  nsum++;
  for (int m = 0; m <= nwall; m++) {
    esum[m] += ewall[m];
    ewall[m] = esum[m] / nsum;
  }
}
