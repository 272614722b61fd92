/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: middle lamella between the walls of neighbouring cells, a
   cohesive traction-separation bond (Xu & Needleman exponential law) that
   debonds irreversibly at 10 delta_c.
------------------------------------------------------------------------- */

#ifdef BOND_CLASS
// clang-format off
BondStyle(cell/lamella,BondCellLamella);
// clang-format on
#else

#ifndef LMP_BOND_CELL_LAMELLA_H
#define LMP_BOND_CELL_LAMELLA_H

#include "bond.h"
#include "fix_cell_lamella_break.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class BondCellLamella : public Bond {
 public:
  BondCellLamella(class LAMMPS *);
  ~BondCellLamella() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double equilibrium_distance(int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void write_data(FILE *) override;
  double single(int, double, int, int, double &) override;
  void *extract(const char *, int &) override;

  // The stiffest bond of the last setup against the time step: its type, critical opening and
  // omega dt (velocity Verlet integrates a spring only while omega dt < 2), for the blow-up advice
  struct Stiffest {
    int type = 0;
    double delta_c = 0.0, omega_dt = 0.0;
  };
  Stiffest stiffest() const { return stiff; }

 protected:
  double *sigma, *Gc, *gamma;    // strength (pressure), fracture energy (energy/area), damping
  double *dc;                    // characteristic opening of each type, from sigma and Gc
  int iref;                      // index of the reference positions d2_cellref in atom->darray
  int ialam;                     // index of the per-bond area share d_alam in atom->dvector
  double lmax;                   // largest rest length, for the bond-extent check of LAMMPS
  std::string logfile;           // debond event log (bond_style cell/lamella log FILE)
  FixCellLamellaBreak *breaker;    // the bookkeeping of debonds (fix CELL_LAMELLA_BREAK)
  Stiffest stiff;

  void update_dc();
  void check_stiffness();
  FixCellLamellaBreak *break_fix();
  void add_break_fix();

  void allocate();
};

}    // namespace LAMMPS_NS

#endif
#endif
