/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: checks shared by the styles (see cell_checks.h)
------------------------------------------------------------------------- */

#include "cell_checks.h"

#include "atom.h"
#include "error.h"
#include "lammps.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;

namespace CellMech {

void require_magnitude(LAMMPS *lmp, const std::string &command, const char *name, double value)
{
  const double a = std::fabs(value);
  if (value == 0.0 || (a >= 1.0 / MAX_MAGNITUDE && a <= MAX_MAGNITUDE)) return;
  lmp->error->all(FLERR,
                  "{}: {} = {} is outside what the model's arithmetic can carry: a non-zero "
                  "parameter must have a magnitude between {:g} and {:g} (the model squares and "
                  "raises to the 7th power, so beyond that a run overflows double precision to "
                  "NaN)",
                  command, name, value, 1.0 / MAX_MAGNITUDE, MAX_MAGNITUDE);
}

StepMotion fastest_step(LAMMPS *lmp, const int *atoms, int natoms)
{
  const Atom *atom = lmp->atom;
  const int n = atoms ? natoms : atom->nlocal;
  double vmax2 = 0.0;
  int imax = -1;
  for (int k = 0; k < n; k++) {
    const int i = atoms ? atoms[k] : k;
    const double *v = atom->v[i];
    const double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    // !(v2 <= vmax2) also catches a NaN velocity
    if (!(v2 <= vmax2)) {
      vmax2 = v2;
      imax = i;
    }
  }
  StepMotion m;
  if (imax < 0) return m;
  m.tag = (long) atom->tag[imax];
  m.speed = std::sqrt(vmax2);
  m.dist = m.speed * lmp->update->dt;
  return m;
}

std::string blow_up_advice(LAMMPS *lmp, const StepMotion &m)
{
  if (!std::isfinite(m.speed))
    return fmt::format(
        "atom {} has a velocity that is not finite ({}): the run has gone to NaN or inf. The "
        "likely cause is a blow-up from a time step too large (the example inputs use 0.001 us) "
        "or a value set by hand that is not finite (a per-atom property, a velocity)",
        m.tag, m.speed);
  return fmt::format(
      "atom {} moved {:.4g} distance units in one step (speed {:.4g} x time step {:g}), against "
      "a neighbor skin of {:g}: the run has blown up. The likely cause is a time step too large "
      "for the stiffest part of the model (the fluid's acoustic limit 0.25 s/c, the tethers' "
      "period; the example inputs use 0.001 us), or particles that overlapped at the start; "
      "reduce the time step",
      m.tag, m.dist, m.speed, lmp->update->dt, lmp->neighbor->skin);
}

void check_step_motion(LAMMPS *lmp, const std::string &style)
{
  // the setup of a run has made no step: its velocities may be anything (e.g. set by hand)
  const double skin = lmp->neighbor->skin;
  if (lmp->update->setupflag || !(skin > 0.0)) return;
  const StepMotion m = fastest_step(lmp);
  if (!(m.dist <= skin)) lmp->error->one(FLERR, "{}: {}", style, blow_up_advice(lmp, m));
}

}    // namespace CellMech
