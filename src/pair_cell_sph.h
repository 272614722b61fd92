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
  // cell/fluid in pre_force; keeps the fluid pairs it finds for compute() (pairs_of_continuity)
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
  int nmax;
  // per local and ghost atom, once per step: P / rho^2, m, 1 / rho, mu
  static constexpr int NQUANT = 4;
  double *quant;
  // the interacting fluid pairs of the neighbour list (within 2s, same cell) as a compact list:
  // those of ilist[ii] are pair_j[k], pair_wr[k] (grad_i W = wr r_ij) for k in
  // pair_first[ii] .. pair_first[ii + 1] - 1. Found by continuity() at this step's positions and
  // reused by compute(): the step, and the neighbour-list build and atom count they were found with
  bigint pairs_step, pairs_build;
  int pairs_nall;
  int *pair_first, *pair_j;
  double *pair_wr;
  int maxfirst, maxpair;
  // the candidates: the fluid pairs of one cell in the neighbour list (any distance), those of
  // ilist[ii] cand_j[k] for k in cand_first[ii] .. cand_first[ii + 1] - 1, found once per
  // neighbour-list build (the build count and atom count they were found with; every setup)
  bigint cand_build;
  int cand_nall;
  int *cand_first, *cand_j;
  int maxcand_first, maxcand;
  // one smoothing length for every pair of fluid types (the usual one fluid type): it and its
  // 1 / s and kernel_wr_norm(s), for the kernel sweep of all of an atom's pairs at once
  bool s_uniform;
  double sinv_uniform, wrnorm_uniform;
  // the distance test of find_pairs, with a branch or without (search_kind): the kind in use,
  // the searches since it was chosen, the searches of the plan still to make, and the shortest
  // time of each kind in the plan (s)
  enum { SEARCH_BRANCH = 0, SEARCH_BRANCHLESS = 1, SEARCH_AUTO = 2 };
  int search_choice = SEARCH_AUTO;    // pair_style search: auto (planned) or one kind
  static constexpr int SEARCH_TIMED = 6, SEARCH_PLAN = 10, SEARCH_REPLAN = 1000;
  int search_mode = SEARCH_BRANCHLESS, search_count = 0, search_trials = 0;
  double search_time[2] = {0.0, 0.0};

  void allocate();
  bool pairs_of_continuity();
  void find_candidates();
  int search_kind();
  void search_took(int kind, double seconds);

  // the one neighbour-list search both passes share: fills the pair list and, with CONTINUITY,
  // adds each pair's continuity terms (Eq. 7) to d_drho
  template <bool CONTINUITY> void find_pairs();
};

}    // namespace LAMMPS_NS

#endif
#endif
