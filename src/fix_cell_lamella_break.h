/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: internal fix CELL_LAMELLA_BREAK, the bookkeeping of debonded
   middle-lamella bonds between cells. Created by bond style cell/lamella
   with the ID cell_debonded; kept apart from tether rupture (cell_broken).
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(CELL_LAMELLA_BREAK,FixCellLamellaBreak);
// clang-format on
#else

#ifndef LMP_FIX_CELL_LAMELLA_BREAK_H
#define LMP_FIX_CELL_LAMELLA_BREAK_H

#include "fix_cell_failure.h"

#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class FixCellLamellaBreak : public FixCellFailure {
 public:
  static constexpr const char *ID = "cell_debonded";

  // one debonded lamella bond: its atoms and their cells (molecule IDs), its area, when
  struct Event {
    tagint tag1, tag2, mol1, mol2;
    double area;
    bigint step;
    double time;
  };
  // the debonds between one pair of cells
  struct Debond {
    int count;        // bonds debonded
    double area;      // their total area
    double tfirst;    // time of the first and the last debond
    double tlast;
  };

  FixCellLamellaBreak(class LAMMPS *, int, char **);
  ~FixCellLamellaBreak() override;
  double compute_scalar() override;
  double compute_array(int, int) override;

  // a lamella bond (tag1 < tag2, in cells mol1 and mol2, of area A) debonded on this rank; it
  // has left the bond list and the bond arrays of the atom(s) storing it here
  void debonded(tagint tag1, tagint tag2, tagint mol1, tagint mol2, double area);
  // event log (rank 0 appends one line per debond); empty: none
  void set_log(const std::string &file);

  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  std::vector<Event> pending;    // found on this rank since the last sync (FixCellFailure)
  std::map<std::pair<tagint, tagint>, Debond> table;
  std::vector<std::vector<double>> rows;    // the table as compute_array() gives it
  bigint ntotal;                            // debonded bonds, the sum of the table's counts
  std::string logname;
  FILE *logfp;

  void update_rows();
  bool flush() override;
  // every rank calls this with the same list: the bonds debonded, without duplicates
  void apply(const std::vector<Event> &events);
};

}    // namespace LAMMPS_NS

#endif
#endif
