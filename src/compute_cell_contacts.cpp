/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: compute cell/contacts

   compute ID group cell/contacts

   Global array, one row per pair of cells (molecule IDs i < j) that are
   glued (intact middle-lamella bonds), were glued (debonded bonds) or
   touch (wall nodes within the wall-wall contact distance r0 of pair
   cell/lj84), in the order of (i, j):
     1 cell i   2 cell j
     3 intact lamella bonds   4 their area (d_alam, as bond cell/lamella)
     5 debonded lamella bonds   6 their area (fix cell_debonded)
     7 force of the lamella bonds on cell j from cell i, along the line
       of the centres n = (c_j - c_i)/|c_j - c_i|: > 0 pushes the cells
       apart (compression), < 0 holds them together (adhesion)
     8 the same for the wall-wall contacts (8-4 repulsion and damping)
     9 wall-node pairs in contact (not glued)
    10 contact area: wall area of the nodes that touch the other cell,
       glued or in contact, mean of the two sides (a third of each
       node's current triangle areas)
    11 distance between the two cell centres
   Bonds between atoms of two cells are lamella bonds; the contacts are
   the non-bonded wall-node pairs of pair cell/lj84's wall-wall cutoff.
   Only atoms of the group count: a bond or a contact when both of its
   atoms are in it, a node's area when it and the node of the other cell
   that it touches or is glued to are. Debonded bonds are known per cell
   pair only (fix cell_debonded), not per atom: they count when both
   cells have a wall node in the group (group all: every one). The centres (column 11) are those
   of the whole cells.
   The rows are summed over all ranks and are the same on every rank.
------------------------------------------------------------------------- */

#include "compute_cell_contacts.h"

#include "atom.h"
#include "bond.h"
#include "cell_fields.h"
#include "cell_mpi.h"
#include "cell_topology.h"
#include "comm.h"
#include "compute_cell_props.h"
#include "error.h"
#include "fix.h"
#include "fix_cell_lamella_break.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "pair_cell_sph.h"
#include "physics/surface.h"
#include "update.h"

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

using namespace LAMMPS_NS;

ComputeCellContacts::ComputeCellContacts(LAMMPS *_lmp, int narg, char **arg) :
    Compute(_lmp, narg, arg), nmax(0), node_area(nullptr), ialam(-1), nrows_max(0),
    list(nullptr), sph(nullptr), contact(nullptr), contact_r0(nullptr)
{
  if (narg != 3)
    error->all(FLERR,
               "Illegal compute cell/contacts command: expected no arguments after the style, got "
               "{}",
               narg - 3);
  if (!atom->molecule_flag)
    error->all(FLERR,
               "Compute cell/contacts requires molecule IDs (one per cell): atom_style molecular");
  array_flag = 1;
  size_array_cols = NCOL;
  size_array_rows = 0;
  size_array_rows_variable = 1;
  extarray = 0;
  comm_reverse = 1;
}

ComputeCellContacts::~ComputeCellContacts()
{
  memory->destroy(node_area);
  memory->destroy(array);
}

void ComputeCellContacts::init()
{
  sph = dynamic_cast<PairCellSPH *>(force->pair_match("^cell/sph", 0));
  contact = force->pair_match("^cell/lj84", 0);
  if (!contact)
    error->all(FLERR,
               "Compute cell/contacts requires pair style cell/lj84 (the wall-wall contacts)");
  int dim;
  contact_r0 = (double **) contact->extract("r0", dim);
  if (!force->newton_bond)
    error->all(FLERR, "Compute cell/contacts requires newton_bond on (each bond and triangle once)");
  if (!force->angle)
    error->all(FLERR,
               "Compute cell/contacts requires an angle style (angle_style zero nocoeff) so that "
               "LAMMPS lists the wall triangles");
  int flag, cols;
  ialam = atom->find_custom(CellMech::AREA_FIELD, flag, cols);
  if (ialam >= 0 && (flag != 1 || cols != 0)) ialam = -1;
  // built only when invoked; the pair cutoffs cover the wall-wall contact distance
  neighbor->add_request(this, NeighConst::REQ_FULL | NeighConst::REQ_OCCASIONAL);
}

void ComputeCellContacts::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

/* ----------------------------------------------------------------------
   fix ave/time mode vector asks a variable-length array for its row count before it reads
   the rows; the count is known only after the rows are computed
------------------------------------------------------------------------- */

int ComputeCellContacts::lock_length()
{
  if (invoked_array != update->ntimestep) compute_array();
  return size_array_rows;
}

/* ---------------------------------------------------------------------- */

void ComputeCellContacts::compute_array()
{
  invoked_array = update->ntimestep;
  // the failures found so far reach every rank's special lists and the debond table first
  auto *debonded = FixCellFailure::synced(lmp, FixCellLamellaBreak::ID);

  CellMech::CellIndex cells;
  cells.build(lmp);
  std::vector<double> c;
  ComputeCellProps::wall_centres(lmp, cells, sph, c);

  node_areas();
  PairSums local;
  add_lamella_bonds(local);
  add_contacts(local);
  Rows rows;
  std::map<PairSums::Key, std::array<double, 6>> forces;    // lamella, contact vectors
  sum_rows(local, rows, forces);
  if (debonded && debonded->array_flag && debonded->size_array_rows > 0)
    add_debonded(debonded, cells, rows);
  add_normals(cells, c, forces, rows);
  fill_array(rows);
}

// each node's share of its triangles' current area, summed on the owner
void ComputeCellContacts::node_areas()
{
  double **x = atom->x;
  if (atom->nmax > nmax) {
    memory->destroy(node_area);
    nmax = atom->nmax;
    memory->create(node_area, nmax, "cell/contacts:node_area");
  }
  for (int i = 0; i < atom->nlocal + atom->nghost; i++) node_area[i] = 0.0;
  CellMech::for_each_wall_triangle(neighbor->anglelist, neighbor->nanglelist,
                                   [&](int, int a, int b, int cc) {
                                     double u[3], w[3];
                                     for (int d = 0; d < 3; d++) {
                                       u[d] = x[b][d] - x[a][d];
                                       w[d] = x[cc][d] - x[a][d];
                                     }
                                     const double third = CellPhysics::triangle_area(u, w) / 3.0;
                                     node_area[a] += third;
                                     node_area[b] += third;
                                     node_area[cc] += third;
                                   });
  comm->reverse_comm(this);
}

// lamella bonds: bonds between two cells, each once (newton_bond on); force on the higher cell
void ComputeCellContacts::add_lamella_bonds(PairSums &local)
{
  double **x = atom->x;
  const tagint *molecule = atom->molecule;
  const int *mask = atom->mask;
  const double *alam = ialam >= 0 ? atom->dvector[ialam] : nullptr;
  int **bondlist = neighbor->bondlist;
  for (int n = 0; n < neighbor->nbondlist; n++) {
    const int i1 = bondlist[n][0], i2 = bondlist[n][1], btype = bondlist[n][2];
    if (btype <= 0 || CellMech::same_cell(molecule, i1, i2)) continue;
    if (!(mask[i1] & groupbit) || !(mask[i2] & groupbit)) continue;
    PairSums::Row &s = local(molecule[i1], molecule[i2]);
    s[BONDS] += 1.0;
    if (alam) s[BONDS_AREA] += CellMech::lamella_area(alam, i1, i2);
    const double del[3] = {x[i1][0] - x[i2][0], x[i1][1] - x[i2][1], x[i1][2] - x[i2][2]};
    double fbond = 0.0;
    force->bond->single(btype, del[0] * del[0] + del[1] * del[1] + del[2] * del[2], i1, i2, fbond);
    const double sign = molecule[i1] > molecule[i2] ? 1.0 : -1.0;    // force on i1 is del fbond
    for (int d = 0; d < 3; d++) s[BONDS_FORCE + d] += sign * del[d] * fbond;
  }
}

// wall-wall contacts between cells: the full list sees each node pair from both nodes; the force
// is taken on the node of the higher cell, the area on every node that touches
void ComputeCellContacts::add_contacts(PairSums &local)
{
  double **x = atom->x;
  const int *type = atom->type;
  const tagint *molecule = atom->molecule;
  const int *mask = atom->mask;
  neighbor->build_one(list);
  double *special_lj = force->special_lj;
  int **nspecial = atom->nspecial;
  tagint **special = atom->special;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int itype = type[i];
    if (!(mask[i] & groupbit) || nspecial[i][0] == 0 || (sph && sph->is_fluid(itype))) continue;
    std::set<tagint> touched;
    // glued: the other cells among its 1-2 neighbours
    for (int k = 0; k < nspecial[i][0]; k++) {
      const int j = atom->map(special[i][k]);
      if (j >= 0 && !CellMech::same_cell(molecule, i, j) && (mask[j] & groupbit))
        touched.insert(molecule[j]);
    }
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      int j = jlist[jj];
      const double factor_lj = special_lj[sbmask(j)];
      j &= NEIGHMASK;
      const int jtype = type[j];
      if (CellMech::same_cell(molecule, i, j) || !(mask[j] & groupbit) ||
          (sph && sph->is_fluid(jtype)) || nspecial[j][0] == 0)
        continue;
      const int lo = MIN(itype, jtype), hi = MAX(itype, jtype);
      if (!contact->setflag[lo][hi]) continue;
      const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      const double r0 = contact_r0[itype][jtype];
      if (rsq >= r0 * r0 || factor_lj == 0.0) continue;
      touched.insert(molecule[j]);
      if (molecule[i] < molecule[j]) continue;
      double fpair = 0.0;
      contact->single(i, j, itype, jtype, rsq, 0.0, factor_lj, fpair);
      PairSums::Row &s = local(molecule[i], molecule[j]);
      for (int d = 0; d < 3; d++) s[CONTACTS_FORCE + d] += del[d] * fpair;
      s[CONTACTS] += 1.0;
    }
    for (const tagint m : touched) local(molecule[i], m)[CONTACTS_AREA] += node_area[i];
  }
}

// the same rows on every rank: every rank's sums added up, in the columns of the array
void ComputeCellContacts::sum_rows(const PairSums &local, Rows &rows,
                                   std::map<PairSums::Key, std::array<double, 6>> &forces)
{
  const PairSums total = local.summed(world);
  for (const auto &kv : total.all()) {
    const PairSums::Row &s = kv.second;
    auto &r = row(rows, kv.first.first, kv.first.second);
    r[NBONDS] = s[BONDS];
    r[GLUED_AREA] = s[BONDS_AREA];
    r[NCONTACTS] = s[CONTACTS];
    r[CONTACT_AREA] = 0.5 * s[CONTACTS_AREA];    // both sides
    auto &f = forces[kv.first];
    for (int d = 0; d < 3; d++) {
      f[d] = s[BONDS_FORCE + d];
      f[3 + d] = s[CONTACTS_FORCE + d];
    }
  }
}

// the row of cells m1, m2 (either order), with its cell columns set when new
std::array<double, ComputeCellContacts::NCOL> &ComputeCellContacts::row(Rows &rows, tagint m1,
                                                                        tagint m2)
{
  const PairSums::Key key(MIN(m1, m2), MAX(m1, m2));
  auto it = rows.find(key);
  if (it == rows.end()) {
    std::array<double, NCOL> r{};
    r[CELL_I] = key.first;
    r[CELL_J] = key.second;
    it = rows.emplace(key, r).first;
  }
  return it->second;
}

// debonded bonds: the per-cell-pair table of fix cell_debonded (cell i, cell j, bonds, area)
void ComputeCellContacts::add_debonded(Fix *debonded, const CellMech::CellIndex &cells, Rows &rows)
{
  // per slot: the cell has a wall node in the group (slot 0: none, or a cell no longer there).
  // The table is the same on every rank, so every rank makes this reduction or none does; group
  // all takes every row, as a cell whose atoms have all been deleted has none left to be in it
  const bool all = (igroup == 0);
  const tagint *molecule = atom->molecule;
  const int *mask = atom->mask;
  std::vector<int> mine_in(cells.size() + 1, 0), in_group(cells.size() + 1, 0);
  if (!all) {
    const CellMech::WallNodes wall_node(lmp);
    for (int i = 0; i < atom->nlocal; i++) {
      const int m = cells.slot(molecule[i]);
      if (m >= 1 && (mask[i] & groupbit) && wall_node(i)) mine_in[m] = 1;
    }
    MPI_Allreduce(mine_in.data(), in_group.data(), (int) in_group.size(), MPI_INT, MPI_MAX, world);
  }
  for (int r = 0; r < debonded->size_array_rows; r++) {
    const auto m1 = (tagint) debonded->compute_array(r, 0);
    const auto m2 = (tagint) debonded->compute_array(r, 1);
    if (!all && (!in_group[cells.slot(m1)] || !in_group[cells.slot(m2)])) continue;
    auto &g = row(rows, m1, m2);
    g[NDEBONDED] += debonded->compute_array(r, 2);
    g[DEBONDED_AREA] += debonded->compute_array(r, 3);
  }
}

// normal components along the line of the centres, from the lower cell to the higher one
void ComputeCellContacts::add_normals(const CellMech::CellIndex &cells,
                                      const std::vector<double> &c,
                                      const std::map<PairSums::Key, std::array<double, 6>> &forces,
                                      Rows &rows)
{
  for (auto &kv : rows) {
    auto &r = kv.second;
    double n[3], len = 0.0;
    const int s1 = cells.slot(kv.first.first), s2 = cells.slot(kv.first.second);
    if (s1 >= 1 && s2 >= 1)
      for (int d = 0; d < 3; d++) {
        n[d] = c[3 * s2 + d] - c[3 * s1 + d];
        len += n[d] * n[d];
      }
    len = sqrt(len);
    r[DISTANCE] = len;
    auto f = forces.find(kv.first);
    if (len > 0.0 && f != forces.end()) {
      double fl = 0.0, fc = 0.0;
      for (int d = 0; d < 3; d++) {
        fl += f->second[d] * n[d] / len;
        fc += f->second[3 + d] * n[d] / len;
      }
      r[F_LAMELLA] = fl;
      r[F_CONTACT] = fc;
    }
  }
}

void ComputeCellContacts::fill_array(const Rows &rows)
{
  const int nrows = rows.size();
  if (nrows > nrows_max || !array) {
    memory->destroy(array);
    nrows_max = MAX(nrows, 1);
    memory->create(array, nrows_max, NCOL, "cell/contacts:array");
  }
  size_array_rows = nrows;
  int k = 0;
  for (const auto &kv : rows) {
    for (int col = 0; col < NCOL; col++) array[k][col] = kv.second[col];
    k++;
  }
}

/* ---------------------------------------------------------------------- */

int ComputeCellContacts::pack_reverse_comm(int n, int first, double *buf)
{
  for (int i = 0; i < n; i++) buf[i] = node_area[first + i];
  return n;
}

void ComputeCellContacts::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int i = 0; i < n; i++) node_area[list[i]] += buf[i];
}

double ComputeCellContacts::memory_usage()
{
  return (double) nmax * sizeof(double) + (double) nrows_max * NCOL * sizeof(double);
}
