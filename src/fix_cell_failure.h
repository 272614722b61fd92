/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the common part of the internal fixes that keep the books of
   wall and lamella failure (CELL_TETHER_BREAK, CELL_LAMELLA_BREAK): when
   a failure found on one rank reaches the others, and the per-atom count
   of the failures at each node (kept through migration and restarts).
   Not a style itself.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CELL_FAILURE_H
#define LMP_FIX_CELL_FAILURE_H

#include "fix.h"

namespace LAMMPS_NS {

class FixCellFailure : public Fix {
 public:
  FixCellFailure(class LAMMPS *, int, char **);
  ~FixCellFailure() override;

  int setmask() override;
  void init() override;
  void setup(int) override;
  void min_setup(int) override;
  void pre_exchange() override;
  void end_of_step() override;
  void post_run() override;

  // the per-atom counts (count below) through atom sorting, migration and restarts
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int maxsize_restart() override;
  int size_restart(int) override;

  // A style that can fail calls failed() for each failure it finds on this rank (after keeping
  // it in the derived fix's pending list) and computed() at the end of every force computation,
  // on every rank alike.
  void failed();
  void computed();
  // Bring every rank's topology and counts up to date with the failures found so far. Collective:
  // every rank calls it at the same point (the consumers of the counts -- compute_scalar, compute
  // cell/props, fix cell/vtk -- are called so); without a force computation since the last
  // call it returns at once.
  void sync();
  // the failure fix with this ID after a sync(), or null if there is none; collective
  static FixCellFailure *synced(class LAMMPS *lmp, const char *id);
  // The one way to read the per-atom failure counts (local atoms) of the fix with this ID; null
  // when there is none. synced_counts syncs first (collective): right at any point, as outputs
  // need. built_counts does not: they are as of the last neighbor build, which is the present
  // from the neighbor stage of a step to its force computation (a failure forces the build of
  // the next step, which applies it), so a per-step reader there (fix cell/fluid's pre_force)
  // needs no collective call in the steps without failure.
  static const double *synced_counts(class LAMMPS *lmp, const char *id);
  static const double *built_counts(class LAMMPS *lmp, const char *id);

 protected:
  // per atom: the failures that ended at this node (broken tethers, debonded lamella bonds), the
  // fix's vector_atom; null until the derived constructor, its arguments checked, calls add_counts
  double *count;
  void add_counts();
  // gather the pending failures of all ranks and apply them on every rank; true if there were any
  // anywhere. Collective.
  virtual bool flush() = 0;

 private:
  int deferred;          // failures wait for the next neighbor build (see the .cpp)
  int stale;             // a force computation since the last sync() (alike on every rank)
  int since_build;       // a sync() since the last neighbor build found failures
  bigint forgiven_at;    // step whose build this fix took out of the dangerous-build count
  void forgive_build();
};

}    // namespace LAMMPS_NS

#endif
