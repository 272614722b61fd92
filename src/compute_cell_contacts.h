/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: per-cell-pair observables of a tissue: middle-lamella bonds
   and area (intact and debonded), the force the lamella and the wall-wall
   contacts carry between the two cells, and their contact area.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(cell/contacts,ComputeCellContacts);
// clang-format on
#else

#ifndef LMP_COMPUTE_CELL_CONTACTS_H
#define LMP_COMPUTE_CELL_CONTACTS_H

#include "cell_mpi.h"
#include "compute.h"

#include <array>
#include <map>
#include <vector>

namespace CellMech {
class CellIndex;
}

namespace LAMMPS_NS {

class ComputeCellContacts : public Compute {
 public:
  enum {
    CELL_I,
    CELL_J,
    NBONDS,
    GLUED_AREA,
    NDEBONDED,
    DEBONDED_AREA,
    F_LAMELLA,
    F_CONTACT,
    NCONTACTS,
    CONTACT_AREA,
    DISTANCE,
    NCOL
  };

  ComputeCellContacts(class LAMMPS *, int, char **);
  ~ComputeCellContacts() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void compute_array() override;
  int lock_length() override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

 private:
  // per-pair sums before the reduction: lamella bonds, their area and force on the higher cell
  // (3), contact force (3), contacts, contact area (both sides)
  enum {
    BONDS,
    BONDS_AREA,
    BONDS_FORCE,
    CONTACTS_FORCE = BONDS_FORCE + 3,
    CONTACTS = CONTACTS_FORCE + 3,
    CONTACTS_AREA,
    NSUM
  };
  using PairSums = CellMech::PairSums<NSUM>;
  using Rows = std::map<PairSums::Key, std::array<double, NCOL>>;

  void node_areas();
  void add_lamella_bonds(PairSums &);
  void add_contacts(PairSums &);
  void sum_rows(const PairSums &, Rows &, std::map<PairSums::Key, std::array<double, 6>> &forces);
  static std::array<double, NCOL> &row(Rows &, tagint m1, tagint m2);
  void add_debonded(class Fix *, const CellMech::CellIndex &, Rows &);
  void add_normals(const CellMech::CellIndex &, const std::vector<double> &centres,
                   const std::map<PairSums::Key, std::array<double, 6>> &forces, Rows &);
  void fill_array(const Rows &);

  int nmax;
  double *node_area;    // per atom: a third of the current area of its triangles
  int ialam;            // per-atom lamella area d_alam, -1 without one
  int nrows_max;
  class NeighList *list;
  class PairCellSPH *sph;
  class Pair *contact;    // pair cell/lj84: the wall-wall contacts
  double **contact_r0;
};

}    // namespace LAMMPS_NS

#endif
#endif
