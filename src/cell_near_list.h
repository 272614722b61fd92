/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: a list inside LAMMPS's neighbour list. For each entry of
   neighbor->anglelist (a wall triangle), the atoms of a neighbour list
   that lay within a contact range plus the neighbour skin of it when the
   lists were built. Between builds no atom moves more than half the skin
   (neigh_modify check yes, as for LAMMPS's own lists), so a point made
   of atoms (a triangle's barycentre) and any atom close in by at most
   the skin: an atom outside range + skin at the build stays outside the
   range until the next one. The per-step search of a contact then walks
   these few atoms, in the order of the neighbour list, instead of the
   whole list of the triangle's central node, whose cutoff also spans
   the triangle's reach.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_NEAR_LIST_H
#define CELLMECH_CELL_NEAR_LIST_H

#include "lmptype.h"

#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace CellMech {

class NearList {
 public:
  // whether the lists were built (or a run is being set up) since the last search, or the atom
  // or triangle count changed: the search must be made again
  bool stale(LAMMPS_NS::LAMMPS *);
  // a search: start(), then for each entry n of the angle list in order open(n) and add(k) for
  // each of its atoms, then close()
  void start(int nentries);
  void open(int n) { first[n] = (int) atoms.size(); }
  void add(int k) { atoms.push_back(k); }
  void close() { first[first.size() - 1] = (int) atoms.size(); }
  // the atoms of entry n: begin(n) .. end(n) - 1
  const int *begin(int n) const { return atoms.data() + first[n]; }
  const int *end(int n) const { return atoms.data() + first[n + 1]; }
  double memory_usage() const;

 private:
  LAMMPS_NS::bigint build = -1;    // the timestep of the build they were found for
  int nall = -1;                   // local and ghost atoms then
  std::vector<int> first, atoms;
};

}    // namespace CellMech

#endif
