/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the coefficients' shared checks (cell_coeff.h)
------------------------------------------------------------------------- */

#include "cell_coeff.h"

#include "cell_checks.h"
#include "cell_fields.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "lammps.h"
#include "utils.h"

using namespace LAMMPS_NS;

namespace CellMech {

double coefficient(LAMMPS *lmp, const std::string &command, const char *name, const char *arg,
                   Sign sign)
{
  const double value = utils::numeric(FLERR, arg, false, lmp);
  if (sign == Sign::POSITIVE && value <= 0.0)
    lmp->error->all(FLERR, "{}: {} must be > 0, got {}", command, name, value);
  if (sign == Sign::NON_NEGATIVE && value < 0.0)
    lmp->error->all(FLERR, "{}: {} must be >= 0, got {}", command, name, value);
  require_magnitude(lmp, command, name, value);
  return value;
}

WallCoefficients wall_coefficients(LAMMPS *lmp, const std::string &command, char **arg,
                                   bool with_gamma)
{
  WallCoefficients w;
  w.G = coefficient(lmp, command, "shear modulus G", arg[0], Sign::POSITIVE);
  w.t0 = coefficient(lmp, command, "wall thickness t0", arg[1], Sign::POSITIVE);
  w.gamma = with_gamma ? coefficient(lmp, command, "damping gamma", arg[2], Sign::NON_NEGATIVE)
                       : 0.0;
  return w;
}

int set_types(int ilo, int ihi, int *setflag,
              std::initializer_list<std::pair<double *, double>> values)
{
  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (const auto &v : values) v.first[i] = v.second;
    setflag[i] = 1;
    count++;
  }
  return count;
}

bool any_positive(const int *setflag, const double *values, int n)
{
  for (int i = 1; i <= n; i++)
    if (setflag[i] && values[i] > 0.0) return true;
  return false;
}

int reference_positions(LAMMPS *lmp, const std::string &style)
{
  int flag, cols;
  const int iref = lmp->atom->find_custom(REF_FIELD, flag, cols);
  if (iref < 0 || flag != 1 || cols != 3)
    lmp->error->all(FLERR,
                    "{} requires the wall reference positions as a per-atom array: 'fix cell all "
                    "property/atom rmass d_rho d_drho d2_{} 3 ghost yes' before read_data, filled "
                    "from the data file (read_data ... fix ID NULL cell)",
                    style, REF_FIELD);
  return iref;
}

void require_ghost_velocities(LAMMPS *lmp, const std::string &what)
{
  if (!lmp->comm->ghost_velocity)
    lmp->error->all(FLERR, "{} requires 'comm_modify vel yes' (ghost velocities)", what);
}

void require_special_lj_011(LAMMPS *lmp, const std::string &what, const char *why)
{
  const double *lj = lmp->force->special_lj;
  if (lj[2] != 1.0 || lj[3] != 1.0)
    lmp->error->all(FLERR, "{} requires 'special_bonds lj 0 1 1' (got lj {} {} {}): {}", what,
                    lj[1], lj[2], lj[3], why);
}

}    // namespace CellMech
