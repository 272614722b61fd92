/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: internal fix CELL_LAMELLA_BREAK

   When a middle-lamella bond debonds, bond style cell/lamella removes it
   from the bond list and the bond arrays of the atom that stores it and
   hands it to debonded(). When every rank has the debonds (FixCellFailure:
   at the neighbor build of the next step, or earlier for an output), each
   rank
   - takes the two nodes out of each other's 1-2 special list (the same
     code as for a broken tether, CellMech::remove_special12);
     after that build the nodes of the two cells are an ordinary contact
     pair that the 8-4 repulsion keeps apart: a debonded interface still
     resists interpenetration, it only lost its tensile strength. A lamella
     bond is no triangle edge: no angles change;
   - counts the debond at its nodes that it owns (per-atom vector; travels
     with the atoms and is written to restart files);
   - adds it to the table of debonds per pair of cells, with the step and
     time it debonded. All ranks see the same events in the same order, so
     the table is identical everywhere without communication; it is written
     to restart files by rank 0 and restored on all ranks.
   Tether rupture has its own fix (cell_broken): a crack through a wall and
   a cell separating from its neighbour are different failure modes.
------------------------------------------------------------------------- */

#include "fix_cell_lamella_break.h"

#include "atom.h"
#include "cell_mpi.h"
#include "cell_topology.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "update.h"

#include <algorithm>

using namespace LAMMPS_NS;
using namespace FixConst;

static constexpr int NCOLS = 6;    // cell i, cell j, count, area, t_first, t_last

/* ---------------------------------------------------------------------- */

FixCellLamellaBreak::FixCellLamellaBreak(LAMMPS *_lmp, int narg, char **arg) :
    FixCellFailure(_lmp, narg, arg), ntotal(0), logfp(nullptr)
{
  if (narg != 3)
    error->all(FLERR, "Illegal fix CELL_LAMELLA_BREAK command: expected no arguments, got {}",
               narg - 3);
  restart_global = 1;
  scalar_flag = 1;
  extscalar = 0;
  array_flag = 1;
  size_array_cols = NCOLS;
  size_array_rows = 0;
  size_array_rows_variable = 1;
  extarray = 0;
  global_freq = 1;
  add_counts();    // count: the lamella bonds debonded at each node
}

FixCellLamellaBreak::~FixCellLamellaBreak()
{
  if (logfp) fclose(logfp);
}

/* ---------------------------------------------------------------------- */

double FixCellLamellaBreak::compute_scalar()
{
  sync();
  return (double) ntotal;
}

double FixCellLamellaBreak::compute_array(int i, int j)
{
  // no sync() here: LAMMPS reads size_array_rows before asking for the elements, and a sync would
  // change the rows under it. The table is current at output steps and after compute_scalar.
  if (i < 0 || i >= (int) rows.size() || j < 0 || j >= NCOLS) return 0.0;
  return rows[i][j];
}

void FixCellLamellaBreak::update_rows()
{
  rows.clear();
  ntotal = 0;
  for (const auto &kv : table) {
    const Debond &d = kv.second;
    rows.push_back({(double) kv.first.first, (double) kv.first.second, (double) d.count, d.area,
                    d.tfirst, d.tlast});
    ntotal += d.count;
  }
  size_array_rows = (int) rows.size();
}

/* ----------------------------------------------------------------------
   the log is appended to, so that a run continued from a restart file
   extends the record of the run that wrote it
------------------------------------------------------------------------- */

void FixCellLamellaBreak::set_log(const std::string &file)
{
  if (file == logname) return;
  if (logfp) fclose(logfp);
  logfp = nullptr;
  logname = file;
  if (comm->me != 0 || logname.empty()) return;
  logfp = fopen(logname.c_str(), "a");
  if (!logfp)
    error->one(FLERR, "Bond style cell/lamella: cannot open the debond log file {}: {}", logname,
               utils::getsyserror());
  if (ftell(logfp) == 0) {
    utils::print(logfp, "# lamella debonds: step time tag_i tag_j cell_i cell_j area\n");
    fflush(logfp);
  }
}

/* ---------------------------------------------------------------------- */

void FixCellLamellaBreak::debonded(tagint tag1, tagint tag2, tagint mol1, tagint mol2, double area)
{
  const double time = update->atime + (update->ntimestep - update->atimestep) * update->dt;
  pending.push_back({tag1, tag2, mol1, mol2, area, update->ntimestep, time});
  failed();
}

static bool tag_order(const FixCellLamellaBreak::Event &a, const FixCellLamellaBreak::Event &b)
{
  return std::make_pair(a.tag1, a.tag2) < std::make_pair(b.tag1, b.tag2);
}

static bool same_bond(const FixCellLamellaBreak::Event &a, const FixCellLamellaBreak::Event &b)
{
  return a.tag1 == b.tag1 && a.tag2 == b.tag2;
}

/* ----------------------------------------------------------------------
   all ranks' debonds on all ranks, in rank order, then sorted by tags: the
   same table and log on any number of ranks. With newton_bond off both
   owners of a bond saw it debond. Tags and cells travel as tagints, the
   rest as doubles, so that bigbig tags stay exact.
------------------------------------------------------------------------- */

bool FixCellLamellaBreak::flush()
{
  std::vector<tagint> tags;
  std::vector<double> values;
  for (const auto &e : pending) {
    tags.insert(tags.end(), {e.tag1, e.tag2, e.mol1, e.mol2});
    values.insert(values.end(), {e.area, (double) e.step, e.time});
  }
  pending.clear();
  // the one collective of a build without debonds
  if (!CellMech::any_rank_has((int) tags.size(), world)) return false;
  tags = CellMech::allgather_list(tags, MPI_LMP_TAGINT, world);
  values = CellMech::allgather_list(values, MPI_DOUBLE, world);

  const int nall = (int) tags.size() / 4;
  std::vector<Event> events;
  for (int k = 0; k < nall; k++)
    events.push_back({tags[4 * k], tags[4 * k + 1], tags[4 * k + 2], tags[4 * k + 3], values[3 * k],
                      (bigint) values[3 * k + 1], values[3 * k + 2]});
  // stable: a bond seen by two ranks debonded in one step, so either copy will do
  std::stable_sort(events.begin(), events.end(), tag_order);
  events.erase(std::unique(events.begin(), events.end(), same_bond), events.end());

  atom->nbonds -= (bigint) events.size();
  apply(events);
  return true;
}

/* ---------------------------------------------------------------------- */

void FixCellLamellaBreak::apply(const std::vector<Event> &events)
{
  if (events.empty()) return;
  const int nlocal = atom->nlocal;

  for (const auto &e : events) {
    for (int side = 0; side < 2; side++) {
      const int i = atom->map(side ? e.tag2 : e.tag1);
      if (i < 0 || i >= nlocal) continue;
      count[i] += 1.0;
      CellMech::remove_special12(atom, i, side ? e.tag1 : e.tag2);
    }
    const auto key = std::make_pair(std::min(e.mol1, e.mol2), std::max(e.mol1, e.mol2));
    auto it = table.find(key);
    if (it == table.end()) it = table.emplace(key, Debond{0, 0.0, e.time, e.time}).first;
    it->second.count++;
    it->second.area += e.area;
    it->second.tfirst = std::min(it->second.tfirst, e.time);
    it->second.tlast = std::max(it->second.tlast, e.time);
    if (logfp)
      utils::print(logfp, "{} {:.10g} {} {} {} {} {:.10g}\n", e.step, e.time, e.tag1, e.tag2,
                   key.first, key.second, e.area);
  }
  if (logfp) fflush(logfp);
  update_rows();
}

/* ----------------------------------------------------------------------
   global restart: the per-pair table, as doubles (cell IDs below 2^53)
------------------------------------------------------------------------- */

void FixCellLamellaBreak::write_restart(FILE *fp)
{
  std::vector<double> list;
  list.push_back((double) rows.size());
  for (const auto &r : rows) list.insert(list.end(), r.begin(), r.end());
  if (comm->me == 0) {
    const int size = (int) (list.size() * sizeof(double));
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list.data(), sizeof(double), list.size(), fp);
  }
}

void FixCellLamellaBreak::restart(char *buf)
{
  const auto *list = (const double *) buf;
  const int n = static_cast<int>(list[0]);
  table.clear();
  for (int k = 0; k < n; k++) {
    const double *r = list + 1 + NCOLS * k;
    const auto key = std::make_pair((tagint) r[0], (tagint) r[1]);
    table[key] = Debond{static_cast<int>(r[2]), r[3], r[4], r[5]};
  }
  update_rows();
}
