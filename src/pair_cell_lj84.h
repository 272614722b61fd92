/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: 8-4 excluded-volume repulsion (Eq. 12) with contact damping,
   between fluid and wall and between non-bonded wall particles.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(cell/lj84,PairCellLJ84);
// clang-format on
#else

#ifndef LMP_PAIR_CELL_LJ84_H
#define LMP_PAIR_CELL_LJ84_H

#include "pair.h"

#include <vector>

namespace LAMMPS_NS {

class PairCellLJ84 : public Pair {
 public:
  PairCellLJ84(class LAMMPS *, const char *name = "cell/lj84");
  ~PairCellLJ84() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_data(FILE *) override;
  void write_data_all(FILE *) override;
  double single(int, int, int, int, double, double, double, double &) override;
  void *extract(const char *, int &) override;

 protected:
  const char *style_name;    // for messages: cell/virtual shares the coefficients and their checks
  const char *coeff_args;    // the coefficients after 'pair_coeff I J', for messages
  double **f0, **r0, **gamma;

  virtual void allocate();
  // per-type-pair coefficients a derived style keeps beyond f0, r0 and gamma (cell/virtual's
  // adhesion), all zero where unused: in the restart file they follow gamma in a record marked 2
  // instead of setflag's 1, only where one of them is not zero, so that the files without them
  // (every cell/lj84 file, and those written before they existed) keep their layout
  virtual std::vector<double **> extra_coeffs() { return {}; }
  void require_ghost_velocities();    // if any contact is damped
};

}    // namespace LAMMPS_NS

#endif
#endif
