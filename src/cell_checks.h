/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: checks shared by the styles that turn silent NaN and
   misleading errors into messages that name the cause.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_CHECKS_H
#define CELLMECH_CELL_CHECKS_H

#include <string>

namespace LAMMPS_NS {
class Atom;
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
  int index = -1;    // the atom's local (or ghost) index
  double dist = 0.0, speed = 0.0;
};
StepMotion fastest_step(LAMMPS_NS::LAMMPS *lmp, const int *atoms = nullptr, int natoms = -1);
std::string blow_up_advice(LAMMPS_NS::LAMMPS *lmp, const StepMotion &m);

// Appended to the messages about per-atom fields that hold nonsense (zero rest length, density or
// area): after read_restart, fix property/atom gets its values back in the order of its new
// definition, so fields listed in another order than in the run that wrote the restart swap
// their values silently.
constexpr const char *RESTART_FIELDS_HINT =
    "; after read_restart: is fix property/atom defined with the same fields in the same order as "
    "in the run that wrote the restart file (rmass d_rho d_drho d2_cellref 3 [d_alam])? Its "
    "values come back in the order of the new definition, whatever their names";

// Once per step (bond style cell/tether): an atom that moved farther than the neighbor skin in
// one step has passed pairs it should have met, and within a few steps LAMMPS stops with an
// error that points elsewhere (a stretched triangle, "Bond atoms missing"). Stops the run at the
// first such step with the cause (error->one on the rank that sees it: no communication).
void check_step_motion(LAMMPS_NS::LAMMPS *lmp, const std::string &style);

// Whether the run being set up will move atoms: the time-step checks below concern the dynamics
// only, not a run 0, a run without an integrator, a minimisation, or the init of a command that
// needs one (delete_bonds, write_data, ...), which may come before the input sets its time step.
bool will_step(LAMMPS_NS::LAMMPS *lmp);

// The time step the bond styles are integrated with: under run_style respa that of the bonds'
// level (the wall's inner step, lammps-inputs/respa.lmp), not the outer update->dt.
double bond_step(LAMMPS_NS::LAMMPS *lmp);

// the mass of atom i: its per-atom rmass where the system has one, else its type's
double atom_mass(const LAMMPS_NS::Atom *atom, int i);

// fix viscous adds f = -gamma v once per step: explicit, so each step multiplies a velocity by
// about 1 - gamma dt / m, which overshoots and grows once gamma dt > 2 m. Stops the run at its
// start (error->all, collective) naming the fix, the atom and the largest drag that is stable.
void check_drag(LAMMPS_NS::LAMMPS *lmp);

// The stability bound of the time step, far exceeded: a time step this many times the limit of
// the stiffest element (the fluid's acoustic limit 0.25 s/c, a tether's 2/omega) moves atoms
// across the domain within a step or two, and LAMMPS stops with an error that points elsewhere
// ("Bond atoms missing"); the usual cause is a forgotten 'timestep' (units micro: 2 us). Runs a
// few times over the limit are left to blow up and be explained by blow_up_advice.
constexpr double FAR_ABOVE_LIMIT = 10.0;
// the closing hint of those messages: the level table's time steps and the units' default
std::string timestep_hint(LAMMPS_NS::LAMMPS *lmp);

}    // namespace CellMech

#endif
