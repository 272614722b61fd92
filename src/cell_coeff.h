/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: what the force styles of the wall, the lamella, the fluid
   and the contacts (bond cell/tether, cell/lamella, angle cell/membrane,
   pair cell/sph, cell/lj84) do alike with their coefficients: read one
   with its sign and magnitude checked, set it for a range of types, and
   the init_style checks they share.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_COEFF_H
#define CELLMECH_CELL_COEFF_H

#include <initializer_list>
#include <string>
#include <utility>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace CellMech {

// the sign a coefficient must have
enum class Sign { POSITIVE, NON_NEGATIVE, ANY };

// The coefficient name ("sound speed c") of command ("pair_coeff cell/sph") from its argument
// (utils::numeric): error->all "COMMAND: NAME must be > 0, got ARG" (or >= 0) unless its sign is
// right, then require_magnitude (cell_checks.h).
double coefficient(LAMMPS_NS::LAMMPS *lmp, const std::string &command, const char *name,
                   const char *arg, Sign sign);

// The wall's coefficients, alike in its two models (bond cell/tether, angle cell/membrane):
// shear modulus G and thickness t0 from arg[0], arg[1], the damping gamma from arg[2] where
// with_gamma (else 0), each checked as by coefficient()
struct WallCoefficients {
  double G, t0, gamma;
};
WallCoefficients wall_coefficients(LAMMPS_NS::LAMMPS *lmp, const std::string &command, char **arg,
                                   bool with_gamma);

// values[k].first[i] = values[k].second and setflag[i] = 1 for the types ilo..ihi of a bonded
// style; the count of types set
int set_types(int ilo, int ihi, int *setflag,
              std::initializer_list<std::pair<double *, double>> values);

// whether any type 1..n with setflag has a value > 0 (a damping, a critical stretch)
bool any_positive(const int *setflag, const double *values, int n);

// The index of the wall's reference positions d2_cellref in atom->darray; error->all naming
// style ("Bond style cell/tether") and the fix property/atom it needs if there is none.
int reference_positions(LAMMPS_NS::LAMMPS *lmp, const std::string &style);

// error->all unless ghost atoms carry velocities: what ("Bond style cell/tether with damping
// gamma > 0") needs them
void require_ghost_velocities(LAMMPS_NS::LAMMPS *lmp, const std::string &what);

// error->all unless 'special_bonds lj 0 1 1': what ("Bond style cell/lamella") turns a bonded
// pair into a non-bonded one (why) when it breaks, and the special list's 1-3 and 1-4 weights
// would then weigh it
void require_special_lj_011(LAMMPS_NS::LAMMPS *lmp, const std::string &what, const char *why);

// (x_i - x_j) . (v_i - v_j), the rate r dr/dt of the damping of Eq. 11 between atoms i and j
inline double radial_rate(double **x, double **v, int i, int j)
{
  double dot = 0.0;
  for (int d = 0; d < 3; d++) dot += (x[i][d] - x[j][d]) * (v[i][d] - v[j][d]);
  return dot;
}

}    // namespace CellMech

#endif
