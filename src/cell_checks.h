/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: checks shared by the styles that turn silent NaN and
   misleading errors into messages that name the cause.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_CHECKS_H
#define CELLMECH_CELL_CHECKS_H

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace CellMech {

// Largest magnitude of a model parameter, and smallest of a non-zero one. The model squares sound
// speeds, raises density ratios to the 7th power (Eq. 6) and multiplies moduli, areas and
// conductivities, so a parameter beyond 1e+-100 overflows or underflows double precision
// (1e+-308) somewhere and the run ends in NaN; the physical values of every supported unit
// style lie well inside (1e-21 to 1e12).
constexpr double MAX_MAGNITUDE = 1.0e100;

// error->all naming the command and the parameter unless value is 0 or its magnitude lies in
// [1/MAX_MAGNITUDE, MAX_MAGNITUDE] (NaN and inf fail too)
void require_magnitude(LAMMPS_NS::LAMMPS *lmp, const std::string &command, const char *name,
                       double value);

// The fastest local atom's move in the last step, |v| dt (velocity Verlet drifts every atom by
// its half-step velocity): its tag and distance, and a sentence naming the likely cause of a
// blow-up with the numbers (distance against the neighbor skin, speed, time step).
struct StepMotion {
  long tag = 0;
  double dist = 0.0, speed = 0.0;
};
StepMotion fastest_step(LAMMPS_NS::LAMMPS *lmp, const int *atoms = nullptr, int natoms = -1);
std::string blow_up_advice(LAMMPS_NS::LAMMPS *lmp, const StepMotion &m);

// Once per step (bond style cell/tether): an atom that moved farther than the neighbor skin in
// one step has passed pairs it should have met, and within a few steps LAMMPS stops with an
// error that points elsewhere (a stretched triangle, "Bond atoms missing"). Stops the run at the
// first such step with the cause (error->one on the rank that sees it: no communication).
void check_step_motion(LAMMPS_NS::LAMMPS *lmp, const std::string &style);

}    // namespace CellMech

#endif
