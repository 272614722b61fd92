/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: internal fix CELL_TETHER_BREAK, the bookkeeping of broken
   wall tethers. Created by bond style cell/tether when a bond type has a
   critical stretch (bond_coeff ... lamf v), with the ID cell_broken.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(CELL_TETHER_BREAK,FixCellTetherBreak);
// clang-format on
#else

#ifndef LMP_FIX_CELL_TETHER_BREAK_H
#define LMP_FIX_CELL_TETHER_BREAK_H

#include "fix.h"

#include <utility>
#include <vector>

namespace LAMMPS_NS {

class FixCellTetherBreak : public Fix {
 public:
  static constexpr const char *ID = "cell_broken";

  FixCellTetherBreak(class LAMMPS *, int, char **);
  ~FixCellTetherBreak() override;
  int setmask() override;
  double compute_scalar() override;

  // every rank calls this with the same list: the tag pairs of the tethers broken this step
  void apply(const std::vector<std::pair<tagint, tagint>> &pairs);

  // drop the atom with tag other from the 1-2 special list of local atom i (also used for
  // debonded lamella bonds, fix CELL_LAMELLA_BREAK); false when it is not a 1-2 neighbour
  static bool remove_special12(class Atom *atom, int i, tagint other);
  // drop the bond to partner from atom i's bond arrays (the last bond takes its slot)
  static void remove_bond(class Atom *atom, int i, tagint partner);

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int maxsize_restart() override;
  int size_restart(int) override;

 protected:
  double *nbroken;    // per atom: broken tethers that ended at this node
};

}    // namespace LAMMPS_NS

#endif
#endif
