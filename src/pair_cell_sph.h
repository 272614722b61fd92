/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: SPH protoplasm (Eqs. 3-7): cubic-spline kernel, Tait equation
   of state with background turgor, symmetric pressure force, Morris
   laminar viscosity and the continuity equation, with per-particle mass.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(cell/sph,PairCellSPH);
// clang-format on
#else

#ifndef LMP_PAIR_CELL_SPH_H
#define LMP_PAIR_CELL_SPH_H

#include "atom.h"
#include "pair.h"
#include "physics/tait.h"

namespace CellMech {
class SPHPairs;
struct SPHTypeData;
}    // namespace CellMech

namespace LAMMPS_NS {

class PairCellSPH : public Pair {
 public:
  PairCellSPH(class LAMMPS *);
  ~PairCellSPH() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  double single(int, int, int, int, double, double, double, double &) override;
  void *extract(const char *, int &) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  // d_drho of local atoms from the current positions and velocities (Eq. 7). Called by fix
  // cell/fluid in pre_force; keeps the fluid pairs it finds for compute() (cell_sph_pairs.h)
  void continuity();

  // equation of state of a fluid type; used by fix cell/fluid and compute cell/props too
  bool is_fluid(int type) const { return fluid[type] != 0; }
  // (inline: the fix calls them once per fluid particle and step)
  double pressure(int type, double rho) const
  {
    return CellPhysics::tait_pressure_kappa(rho, rho0[type], kappa[type], P0[type]);
  }
  double dpressure_drho(int type, double rho) const
  {
    return CellPhysics::tait_dpdrho(rho, rho0[type], c[type]);
  }
  double *rho_array() const { return atom->dvector[irho]; }      // per-atom density d_rho
  double *drho_array() const { return atom->dvector[idrho]; }    // per-atom continuity rate d_drho

 protected:
  void check_fluid_atoms();
  void check_spacing();
  void check_timestep();
  void check_respa_level();
  // the kernel support 2s must span this many fluid spacings (check_spacing)
  static constexpr double MIN_SUPPORT_SPACINGS = 1.25;
  int *fluid;                    // per type: 1 if a fluid type (pair_coeff I I set)
  double *rho0, *c, *P0, *mu;    // per type
  double *kappa;                 // per type: tait_kappa(rho0, c), set by init_style
  double **s;                    // per type pair: smoothing length (cutoff 2s)
  double **sinv, **wrnorm;       // per type pair: 1 / s and kernel_wr_norm(s)
  int irho, idrho;               // indices of d_rho, d_drho in atom->dvector
  // Monaghan's artificial stress (pair_style cell/sph stress eps n dp; eps 0: off, the default):
  // its strength, exponent and particle spacing; per type pair W(dp) and the prefactor of f =
  // W(r) / W(dp) for kernel_w_q, kernel_w_norm(s) / W(dp) (init_one);
  // per local and ghost atom R = eps |P| / rho^2 in tension, else 0 (allocated only when on)
  double stress_eps, stress_dp;
  int stress_n;
  bool tension;    // some local or ghost particle has R > 0 (this step)
  double **wdp, **fnorm;
  double *stress_r;
  // the cohesion (pair_style cell/sph cohesion gamma; 0: off, the default): its surface tension
  // and per type pair the amplitude A of Eq. C2 at r_c = 2s (init_one)
  double coh_gamma;
  double **coh_a;
  int nmax;
  // per local and ghost atom, once per step: P / rho^2, m, 1 / rho, mu
  static constexpr int NQUANT = 4;
  double *quant;
  // the interacting fluid pairs, found by continuity() at this step's positions and reused by
  // compute() (cell_sph_pairs.h)
  CellMech::SPHPairs *pairs;

  void allocate();
  CellMech::SPHTypeData type_data() const;
  void fluid_quantities(int eflag);
  // Eq. 5 over the pairs; with STRESS, the artificial stress as well; with COHESION, Eq. C1
  template <bool STRESS, bool COHESION> void forces();
  double cohesion_pair(double a, double rc, double voli, double volj, double rsq,
                       double &evdwl) const;
  void stress_settings(int narg, char **arg);
};

}    // namespace LAMMPS_NS

#endif
#endif
