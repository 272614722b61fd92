/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the topology surgery of a failure (cell_topology.h)
------------------------------------------------------------------------- */

#include "cell_topology.h"

#include "atom.h"
#include "atom_vec.h"
#include "force.h"
#include "lammps.h"

using namespace LAMMPS_NS;

namespace CellMech {

void release_edges(LAMMPS *lmp, const std::vector<Edge> &edges, bool bonds)
{
  Atom *atom = lmp->atom;
  const int nlocal = atom->nlocal;
  const int newton_bond = lmp->force->newton_bond;
  bigint removed_local = 0, removed = 0;
  for (const auto &e : edges)
    for (int side = 0; side < 2; side++) {
      const tagint me = side ? e.second : e.first;
      const tagint other = side ? e.first : e.second;
      const int i = atom->map(me);
      if (i < 0 || i >= nlocal) continue;
      remove_special12(atom, i, other);
      // with newton_bond off both nodes store the bond; count it once
      if (bonds && atom->avec->bonds_allow && remove_bond(atom, i, other) &&
          (newton_bond || me < other))
        removed_local++;
    }
  if (!bonds) return;
  MPI_Allreduce(&removed_local, &removed, 1, MPI_LMP_BIGINT, MPI_SUM, lmp->world);
  atom->nbonds -= removed;
}

/* ---------------------------------------------------------------------- */

void remove_triangles(LAMMPS *lmp, const TrianglePredicate &is_gone)
{
  Atom *atom = lmp->atom;
  const int nlocal = atom->nlocal;
  tagint *tag = atom->tag;
  // Triangles leave the angle arrays (for later neighbor builds, restarts and data files) and the
  // global angle count
  bigint removed_local = 0, removed = 0;
  const int newton_bond = lmp->force->newton_bond;
  // (an atom style without angles, e.g. bond, has no triangles to update)
  for (int i = 0; i < nlocal && atom->avec->angles_allow; i++) {
    int m = 0;
    while (m < atom->num_angle[i]) {
      if (!is_gone(atom->angle_atom1[i][m], atom->angle_atom2[i][m], atom->angle_atom3[i][m])) {
        m++;
        continue;
      }
      // with newton_bond off all three atoms store it; count it once, at its central atom
      if (newton_bond || tag[i] == atom->angle_atom2[i][m]) removed_local++;
      const int last = atom->num_angle[i] - 1;
      atom->angle_type[i][m] = atom->angle_type[i][last];
      atom->angle_atom1[i][m] = atom->angle_atom1[i][last];
      atom->angle_atom2[i][m] = atom->angle_atom2[i][last];
      atom->angle_atom3[i][m] = atom->angle_atom3[i][last];
      atom->num_angle[i]--;
    }
  }
  MPI_Allreduce(&removed_local, &removed, 1, MPI_LMP_BIGINT, MPI_SUM, lmp->world);
  atom->nangles -= removed;

  // A hinge (dihedral style cell/bending: 1-2-3 and 2-3-4 the two triangles, 2-3 the shared
  // edge) bends the wall between two triangles; with either gone there is no wall left to bend
  // there, and kept it would pull the torn nodes back to their rest angle, so it leaves the
  // dihedral arrays and the global count in the same way.
  if (!atom->avec->dihedrals_allow) return;
  auto hinge_gone = [&](tagint t1, tagint t2, tagint t3, tagint t4) {
    return is_gone(t1, t2, t3) || is_gone(t2, t3, t4);
  };
  removed_local = 0;
  for (int i = 0; i < nlocal; i++) {
    int m = 0;
    while (m < atom->num_dihedral[i]) {
      if (!hinge_gone(atom->dihedral_atom1[i][m], atom->dihedral_atom2[i][m],
                      atom->dihedral_atom3[i][m], atom->dihedral_atom4[i][m])) {
        m++;
        continue;
      }
      // with newton_bond off all four atoms store it; count it once, at its second atom
      if (newton_bond || tag[i] == atom->dihedral_atom2[i][m]) removed_local++;
      const int last = atom->num_dihedral[i] - 1;
      atom->dihedral_type[i][m] = atom->dihedral_type[i][last];
      atom->dihedral_atom1[i][m] = atom->dihedral_atom1[i][last];
      atom->dihedral_atom2[i][m] = atom->dihedral_atom2[i][last];
      atom->dihedral_atom3[i][m] = atom->dihedral_atom3[i][last];
      atom->dihedral_atom4[i][m] = atom->dihedral_atom4[i][last];
      atom->num_dihedral[i]--;
    }
  }
  removed = 0;
  MPI_Allreduce(&removed_local, &removed, 1, MPI_LMP_BIGINT, MPI_SUM, lmp->world);
  atom->ndihedrals -= removed;
}

/* ---------------------------------------------------------------------- */

bool remove_bond(Atom *atom, int i, tagint partner)
{
  int *num_bond = atom->num_bond;
  for (int m = 0; m < num_bond[i]; m++)
    if (atom->bond_atom[i][m] == partner) {
      const int last = num_bond[i] - 1;
      atom->bond_atom[i][m] = atom->bond_atom[i][last];
      atom->bond_type[i][m] = atom->bond_type[i][last];
      num_bond[i]--;
      return true;
    }
  return false;
}

bool remove_special12(Atom *atom, int i, tagint other)
{
  int **nspecial = atom->nspecial;
  tagint **special = atom->special;
  // the 1-2 neighbours come first in the special list; drop the partner, shift the rest
  const int n12 = nspecial[i][0];
  int m = 0;
  while (m < n12 && special[i][m] != other) m++;
  if (m == n12) return false;    // not a 1-2 pair (e.g. a second bond between them broke)
  for (int k = m; k < nspecial[i][2] - 1; k++) special[i][k] = special[i][k + 1];
  nspecial[i][0]--;
  nspecial[i][1]--;
  nspecial[i][2]--;
  return true;
}

}    // namespace CellMech
