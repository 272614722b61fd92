/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: what the styles share about the atoms of a cell: the per-atom
   fields of fix property/atom that several styles read (names without the
   d_ / d2_ prefix) and what is derived from them, the wall triangles'
   contract with the data files, and which atoms are wall nodes.

   Wall triangles. A triangle of a cell wall is a LAMMPS angle (a, b, c) of
   angle type 1, written by cellgen.py (tools/; every generator of walls):
     - orientation: (x_b - x_a) x (x_c - x_a) points OUT of the cell (right-hand
       order seen from outside), so that summed cone volumes are the cell
       volume (compute cell/props), solid angles are 4 pi inside (leaks) and
       VTK normals point out (fix cell/vtk);
     - ownership: b, the angle's middle atom, is the central node. With
       newton_bond on (required) LAMMPS stores the angle with atom b, so the
       rank that owns b owns the triangle; the triangle belongs to the cell
       molecule[b] (wall area per cell in fix cell/fluid and compute
       cell/props), and pair cell/virtual finds the fluid near the triangle's
       virtual particle in b's neighbour list, within reach of x_b;
     - a triangle whose angle type is <= 0 has been taken out of the wall by
       a broken tether (bond style cell/tether) or has failed (angle style
       cell/membrane) and counts nowhere (CellMech::for_each_wall_triangle,
       cell_topology.h, the one loop over the triangles, skips it).
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_FIELDS_H
#define CELLMECH_CELL_FIELDS_H

#include "atom.h"
#include "fix_cell_lamella_break.h"
#include "fix_cell_tether_break.h"
#include "lammps.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>

namespace CellMech {

constexpr char REF_FIELD[] = "cellref";    // d2_cellref: rest (reference) position of a wall node
constexpr char AREA_FIELD[] = "alam";      // d_alam: a node's area share of its lamella bonds
constexpr char RHO_FIELD[] = "rho";        // d_rho: density of a fluid particle (pair cell/sph)
constexpr char DRHO_FIELD[] = "drho";      // d_drho: its continuity rate (Eq. 7)

/* ----------------------------------------------------------------------
   Wall nodes, the one definition for compute cell/props (cell centres) and
   fix cell/vtk (points): the atoms with 1-2 neighbours now (tethers or
   lamella bonds), or that have had them, so that a node whose bonds have all
   broken is still part of its wall and the broken and debonded counts
   (fix cell_broken, cell_debonded) of every node are seen. Fluid never has
   bonds: pair cell/sph refuses a bonded atom of a fluid type. Valid for
   local atoms (the per-atom counts of the fixes are). Collective: the
   counts are read synced (FixCellFailure::synced_counts).
------------------------------------------------------------------------- */

class WallNodes {
 public:
  explicit WallNodes(LAMMPS_NS::LAMMPS *lmp) :
      nspecial(lmp->atom->nspecial),
      nbroken(LAMMPS_NS::FixCellFailure::synced_counts(lmp, LAMMPS_NS::FixCellTetherBreak::ID)),
      ndebonded(LAMMPS_NS::FixCellFailure::synced_counts(lmp, LAMMPS_NS::FixCellLamellaBreak::ID))
  {
  }
  bool operator()(int i) const
  {
    return nspecial[i][0] > 0 || (nbroken && nbroken[i] > 0.0) || (ndebonded && ndebonded[i] > 0.0);
  }

 private:
  int **nspecial;
  const double *nbroken, *ndebonded;
};

// Rest length of the bond i-j (tether or lamella): the distance of the nodes' reference positions.
inline double rest_length(double *const *ref, int i, int j)
{
  const double dx = ref[i][0] - ref[j][0];
  const double dy = ref[i][1] - ref[j][1];
  const double dz = ref[i][2] - ref[j][2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// Data a style keeps per entry of LAMMPS's bond or angle list (rest lengths, rest areas) hold
// until the list is built again: at a neighbour-list build (its timestep, neighbor->lastcall) or
// at a setup (which builds at the timestep it starts from). True when they must be found again
// (kept entries, list entries); stamp then takes the build's timestep.
inline bool list_rebuilt(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::bigint &stamp, size_t kept, int n)
{
  if (!lmp->update->setupflag && lmp->neighbor->lastcall == stamp && kept == (size_t) n)
    return false;
  stamp = lmp->neighbor->lastcall;
  return true;
}

// Area a lamella bond i-j stands for: the mean of its two nodes' shares (cellgen.py tissue).
inline double lamella_area(const double *alam, int i, int j)
{
  return 0.5 * (alam[i] + alam[j]);
}

}    // namespace CellMech

#endif
