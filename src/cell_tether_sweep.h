/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the stretch and force factor of every tether of bond style
   cell/tether in one sweep, with what changes only with the bond list
   (rest length, tension factor, damping coefficient) kept between its
   builds. A helper the style owns, as pair cell/sph owns its pair search
   (cell_sph_pairs.h, which says why not LAMMPS's OPT convention); the
   style keeps the physics it applies: start check, failure, forces.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_TETHER_SWEEP_H
#define CELLMECH_CELL_TETHER_SWEEP_H

#include "lmptype.h"
#include "pointers.h"

#include <vector>

namespace CellMech {

// per entry n of neighbor->bondlist, this step: separation x1 - x2, stretch l / l0, force factor
// (the force on atom 1 is fbond (x1 - x2)), and the rest length
struct TetherStep {
  const double *dx, *dy, *dz, *lam, *fbond, *rest;
};

// the bond style's per-type coefficients (its arrays, not copies) and the reference positions
struct TetherTypeData {
  const double *G, *t0, *gamma;
  int iref;    // index of d2_cellref in atom->darray
};

class TetherSweep : protected LAMMPS_NS::Pointers {
 public:
  TetherSweep(LAMMPS_NS::LAMMPS *_lmp) : Pointers(_lmp) {}
  // every entry of the bond list: its separation, stretch and force factor at this step (Eq. 19
  // with the damping of Eq. 11)
  TetherStep sweep(const TetherTypeData &);

 private:
  // per entry of neighbor->bondlist since its last build: rest length, tether_tension_scale,
  // damping coefficient; the timestep of that build
  LAMMPS_NS::bigint rest_build = -1;
  std::vector<double> rest, scale, damp;
  // per entry, this step: separation (3), r^2, r . v, stretch, force factor
  static constexpr int SWEEP_FIELDS = 7;
  std::vector<double> fields;

  void rest_lengths(const TetherTypeData &);
};

}    // namespace CellMech

#endif
