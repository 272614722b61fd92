/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: when a failure found on one rank reaches the others

   A tether, a membrane triangle or a lamella bond fails on the rank that
   computes it. That rank takes the failed element out of its own bond or
   angle list at once (it is not computed again). The rest -- the nodes'
   special lists, the triangles and hinges along a broken edge, the counts
   and the global topology sizes -- is on atoms that other ranks own, and
   every rank must re-neighbor in the same step, or LAMMPS's collective
   neighbor check deadlocks. So every rank must learn of a failure, and
   from a rank it does not otherwise talk to.

   A collective call in every force computation would do it (and did, one
   reduction of an integer per step), in the many steps without failure
   too. Instead the failure asks for a neighbor build in the next step
   through the reduction LAMMPS makes in every step anyway: the distance
   check (Neighbor::check_distance) reduces "has an atom moved more than
   half the skin" over all ranks, and the failing rank makes one of its
   atoms appear to have moved (its entry in the positions kept at the last
   build, Neighbor::get_xhold()). Every rank then re-neighbors in the next
   step, and before the exchange (pre_exchange) all ranks gather the
   failures and update their atoms. The only collective left is one small
   reduction at each neighbor build, which is a collective step anyway.

   That gives the rule, on any number of ranks: the failed element stops
   acting in the step it fails; the topology around it, the special lists
   and the counts change at the neighbor build of the next step (as the
   neighbor lists always did). Outputs see the failures of their own step:
   at every output step (end_of_step), in compute_scalar and in the styles
   that read the counts, every rank syncs first.

   It needs the check in every step: neigh_modify every 1 delay 0 check yes
   (cellmech's inputs and LAMMPS's default) without 'include' or 'once'.
   Other settings, KOKKOS and minimization fall back to a gather after
   every force computation and a forced re-neighboring (Fix::next_reneighbor),
   with the same rule. A build forced so in the step right after another
   is not a dangerous build, and does not count as one.
------------------------------------------------------------------------- */

#include "fix_cell_failure.h"

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "output.h"
#include "update.h"

#include <algorithm>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixCellFailure::FixCellFailure(LAMMPS *_lmp, int narg, char **arg) :
    Fix(_lmp, narg, arg), count(nullptr), deferred(0), stale(0), since_build(0), forgiven_at(-1)
{
  nevery = 1;
  force_reneighbor = 1;
  next_reneighbor = -1;
}

// the per-atom counts, zero, kept by atom->grow (and sort, exchange) and in restarts
void FixCellFailure::add_counts()
{
  restart_peratom = 1;
  peratom_flag = 1;
  size_peratom_cols = 0;
  peratom_freq = 1;
  FixCellFailure::grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) count[i] = 0.0;
}

FixCellFailure::~FixCellFailure()
{
  if (!count) return;    // add_counts not reached: nothing registered
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(count);
}

int FixCellFailure::setmask()
{
  return PRE_EXCHANGE | END_OF_STEP;
}

void FixCellFailure::init()
{
  // whichflag 0: an init of write_data, velocity, ... which a later 'run ... pre no' keeps; KOKKOS
  // keeps the positions of the last build in a neighbor class of its own
  deferred = update->whichflag != 2 && !lmp->kokkos && neighbor->dist_check &&
      neighbor->every == 1 && neighbor->delay == 0 && !neighbor->build_once &&
      !neighbor->includegroup;
  since_build = 0;
}

void FixCellFailure::setup(int /*vflag*/)
{
  sync();
}

void FixCellFailure::min_setup(int /*vflag*/)
{
  sync();
}

void FixCellFailure::pre_exchange()
{
  sync();
  if (deferred && since_build) forgive_build();
  since_build = 0;
}

void FixCellFailure::end_of_step()
{
  if (update->ntimestep == output->next) sync();
}

void FixCellFailure::post_run()
{
  sync();
}

/* ---------------------------------------------------------------------- */

void FixCellFailure::failed()
{
  if (!deferred) return;
  // x - xhold far beyond any skin: this rank reports a move in the next distance check
  // (the rank that found a failure owns the atom that stores the element: nlocal > 0; the check
  // keeps xhold from the build of this step's lists on)
  double **xhold = neighbor->get_xhold();
  if (!xhold || atom->nlocal == 0)
    error->one(FLERR,
               "Fix {}: a failure cannot ask for the next neighbor build (no positions of the last "
               "build kept on this rank); please report this",
               id);
  xhold[0][0] = atom->x[0][0] + 1.0e100;
}

void FixCellFailure::computed()
{
  stale = 1;
  if (!deferred) sync();
}

void FixCellFailure::sync()
{
  if (!stale) return;
  stale = 0;
  if (!flush()) return;
  since_build = 1;
  if (!deferred) next_reneighbor = update->ntimestep + 1;
}

FixCellFailure *FixCellFailure::synced(LAMMPS *lmp, const char *id)
{
  auto *fix = dynamic_cast<FixCellFailure *>(lmp->modify->get_fix_by_id(id));
  if (fix) fix->sync();
  return fix;
}

const double *FixCellFailure::synced_counts(LAMMPS *lmp, const char *id)
{
  const auto *fix = synced(lmp, id);
  return fix ? fix->vector_atom : nullptr;
}

const double *FixCellFailure::built_counts(LAMMPS *lmp, const char *id)
{
  const auto *fix = dynamic_cast<FixCellFailure *>(lmp->modify->get_fix_by_id(id));
  return fix ? fix->vector_atom : nullptr;
}

/* ----------------------------------------------------------------------
   The distance check counted this build as dangerous if it came in the
   first step it could (ago == max(every, delay)). A failure forced it; the
   forced re-neighboring this replaces was never counted. Once per build,
   when both failure fixes forced it.
------------------------------------------------------------------------- */

void FixCellFailure::forgive_build()
{
  // a build forced another way (a restart step, another fix) did not pass the check: ago was not
  // counted up in this step and nothing was added to the count
  if (neighbor->ago != std::max(neighbor->every, neighbor->delay) || neighbor->ndanger <= 0 ||
      update->ntimestep - neighbor->lastcall != neighbor->ago)
    return;
  for (const auto *fix : modify->get_fix_list()) {
    if (fix == this) break;
    const auto *other = dynamic_cast<const FixCellFailure *>(fix);
    if (other && other->forgiven_at == update->ntimestep) return;
  }
  neighbor->ndanger--;
  forgiven_at = update->ntimestep;
}

/* ---------------------------------------------------------------------- */

void FixCellFailure::grow_arrays(int nmax)
{
  memory->grow(count, nmax, "cell_failure:count");
  vector_atom = count;
}

void FixCellFailure::copy_arrays(int i, int j, int /*delflag*/)
{
  count[j] = count[i];
}

int FixCellFailure::pack_exchange(int i, double *buf)
{
  buf[0] = count[i];
  return 1;
}

int FixCellFailure::unpack_exchange(int nlocal, double *buf)
{
  count[nlocal] = buf[0];
  return 1;
}

int FixCellFailure::pack_restart(int i, double *buf)
{
  buf[0] = 2;    // values for this atom, including this count (LAMMPS convention)
  buf[1] = count[i];
  return 2;
}

void FixCellFailure::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  count[nlocal] = extra[nlocal][m + 1];
}

int FixCellFailure::maxsize_restart()
{
  return 2;
}

int FixCellFailure::size_restart(int /*nlocal*/)
{
  return 2;
}
