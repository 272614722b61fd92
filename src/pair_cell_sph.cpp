/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: pair style cell/sph

   Weakly compressible SPH for the protoplasm (Van Liedekerke et al. 2010):
     dv_i/dt = - sum_j m_j (P_i/rho_i^2 + P_j/rho_j^2) grad_i W_ij
               + sum_j m_j (mu_i + mu_j) / (rho_i rho_j) v_ij (1/r) dW/dr     (Eq. 5)
     P = P0 + rho0 c^2/7 [(rho/rho0)^7 - 1]                                   (Eq. 6)
     drho_i/dt (continuity part) = sum_j m_j v_ij . grad_i W_ij               (Eq. 7)
   Particles of different molecule IDs (cells) do not interact.
   Per-particle mass is atom->rmass (osmosis changes it, fix cell/fluid);
   density and its rate live in fix property/atom as d_rho and d_drho.
   fix cell/fluid advances density and mass before the forces (using
   continuity() below), so both are forward-communicated to ghosts at the
   start of compute(); the rate is reverse-communicated in continuity().
   The pair energy is the fluid's internal energy sum_i m_i e(rho_i) with
   de/drho = P/rho^2, so that kinetic + potential energy is the conserved
   total of the inviscid equations.
   pair_style cell/sph stress adds Monaghan's artificial stress (not the paper's) to the pressure
   term where a particle is in tension (physics/sph.h; its pair energy joins the energy).
   pair_style cell/sph cohesion gives the fluid of a cell a surface tension (Eqs. C1-C2, not the
   paper's), so that a void inside it costs energy and a drying protoplasm stays one body.
------------------------------------------------------------------------- */

#include "pair_cell_sph.h"

#include "cell_checks.h"
#include "cell_coeff.h"
#include "cell_compat.h"
#include "cell_fields.h"
#include "cell_sph_pairs.h"

#include "atom.h"
#include "cell_topology.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "physics/kernel.h"
#include "physics/sph.h"
#include "physics/tait.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace CellPhysics;

/* ---------------------------------------------------------------------- */

PairCellSPH::PairCellSPH(LAMMPS *_lmp) :
    Pair(_lmp), fluid(nullptr), rho0(nullptr), c(nullptr), P0(nullptr), mu(nullptr), kappa(nullptr),
    s(nullptr), sinv(nullptr), wrnorm(nullptr), irho(-1), idrho(-1), stress_eps(0.0),
    stress_dp(0.0), stress_n(0), tension(false), wdp(nullptr), fnorm(nullptr), stress_r(nullptr),
    coh_gamma(0.0), coh_a(nullptr), nmax(0), quant(nullptr), pairs(new CellMech::SPHPairs(_lmp))
{
  comm_forward = 2;
  comm_reverse = 1;
  // the viscous force is not along r_ij; the virial is tallied per pair with its full vector
  no_virial_fdotr_compute = 0;
}

PairCellSPH::~PairCellSPH()
{
  memory->destroy(quant);
  memory->destroy(stress_r);
  delete pairs;
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(fluid);
    memory->destroy(rho0);
    memory->destroy(c);
    memory->destroy(P0);
    memory->destroy(mu);
    memory->destroy(kappa);
    memory->destroy(s);
    memory->destroy(sinv);
    memory->destroy(wrnorm);
    memory->destroy(wdp);
    memory->destroy(fnorm);
    memory->destroy(coh_a);
  }
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (update->setupflag) check_respa_level();

  // fix cell/fluid advanced density and mass in pre_force: refresh the ghosts
  comm->forward_comm(this);
  fluid_quantities(eflag);
  // the pairs of fix cell/fluid's continuity pass at these positions, or a search of our own
  pairs->find_for_forces(list, type_data());

  // the artificial stress only where a local or ghost particle is in tension (fluid_quantities)
  const bool stress = stress_eps > 0.0 && tension;
  if (coh_gamma > 0.0)
    stress ? forces<true, true>() : forces<false, true>();
  else
    stress ? forces<true, false>() : forces<false, false>();

  if (vflag_fdotr) virial_fdotr_compute();
}

/* ----------------------------------------------------------------------
   the pair forces of Eq. 5 over this step's fluid pairs; with STRESS (pair_style cell/sph stress)
   the artificial stress joins the central part. Without it the loop is the same code as before
   the option existed, so that runs without it keep their bits.
------------------------------------------------------------------------- */

template <bool STRESS, bool COHESION> void PairCellSPH::forces()
{
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const int *const pair_first = pairs->first();
  const int *const pair_j = pairs->neighbour();
  const double *const pair_wr = pairs->wr();
  const double *const x = atom->x ? atom->x[0] : nullptr;
  const double *const vf = atom->v ? atom->v[0] : nullptr;
  double *const ff = atom->f ? atom->f[0] : nullptr;
  const int *const type = atom->type;
  const int *const ilist = list->ilist;
  const int inum = list->inum;
  for (int ii = 0; ii < inum; ii++) {
    const int kend = pair_first[ii + 1];
    if (pair_first[ii] == kend) continue;
    const int i = ilist[ii];
    const double xi = x[3 * i], yi = x[3 * i + 1], zi = x[3 * i + 2];
    const double vxi = vf[3 * i], vyi = vf[3 * i + 1], vzi = vf[3 * i + 2];
    const double *const qi = quant + NQUANT * i;
    const double prho2i = qi[0], mi = qi[1], irhoi = qi[2], mui = qi[3];
    const double *const sinvi = STRESS ? sinv[type[i]] : nullptr;
    const double *const wdpi = STRESS ? wdp[type[i]] : nullptr;
    const double *const fnormi = STRESS ? fnorm[type[i]] : nullptr;
    const double ri = STRESS ? stress_r[i] : 0.0;
    const double *const si = COHESION ? s[type[i]] : nullptr;
    const double *const cohai = COHESION ? coh_a[type[i]] : nullptr;
    const double voli = mi * irhoi;
    // as drho[i] in SPHPairs::find_pairs: the same additions in the same order, in registers
    double fxi = ff[3 * i], fyi = ff[3 * i + 1], fzi = ff[3 * i + 2];
    for (int k = pair_first[ii]; k < kend; k++) {
      const int j = pair_j[k];
      const double wr = pair_wr[k];
      const double *const qj = quant + NQUANT * j;
      const double mj = qj[1];
      // the same differences as in the search, so the same bits
      const double delx = xi - x[3 * j];
      const double dely = yi - x[3 * j + 1];
      const double delz = zi - x[3 * j + 2];
      const double dvx = vxi - vf[3 * j];
      const double dvy = vyi - vf[3 * j + 1];
      const double dvz = vzi - vf[3 * j + 2];

      // Eq. 5: pressure (central) and Morris viscosity (along v_ij), both antisymmetric in i, j
      double fp = sph_pressure_fpair(mi, mj, prho2i, qj[0], wr);
      double evdwl = 0.0;
      // the artificial stress where either particle is in tension (R > 0)
      if (STRESS && ri + stress_r[j] > 0.0) {
        const int jt = type[j];
        const double q = std::sqrt(delx * delx + dely * dely + delz * delz) * sinvi[jt];
        const double f = kernel_w_q(q, fnormi[jt]);
        const double fn = sph_stress_fn(f, stress_n);
        fp += sph_stress_fpair(mi, mj, ri, stress_r[j], fn, wr);
        if (eflag_either)
          evdwl = sph_stress_energy(mi, mj, ri, stress_r[j], fn * f, wdpi[jt], stress_n);
      }
      if (COHESION)
        fp += cohesion_pair(cohai[type[j]], 2.0 * si[type[j]], voli, mj * qj[2],
                            delx * delx + dely * dely + delz * delz, evdwl);
      const double fv = sph_viscous_fvel(mi, mj, mui, qj[3], irhoi, qj[2], wr);
      const double fx = fp * delx + fv * dvx;
      const double fy = fp * dely + fv * dvy;
      const double fz = fp * delz + fv * dvz;

      fxi += fx;
      fyi += fy;
      fzi += fz;
      if (newton_pair || j < nlocal) {
        ff[3 * j] -= fx;
        ff[3 * j + 1] -= fy;
        ff[3 * j + 2] -= fz;
      }
      if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, evdwl, 0.0, fx, fy, fz, delx, dely, delz);
    }
    ff[3 * i] = fxi;
    ff[3 * i + 1] = fyi;
    ff[3 * i + 2] = fzi;
  }
}

/* ----------------------------------------------------------------------
   one pair's cohesion (Eq. C1) at distance^2 rsq: its central force factor, its energy added to
   evdwl when energy is tallied
------------------------------------------------------------------------- */

double PairCellSPH::cohesion_pair(double a, double rc, double voli, double volj, double rsq,
                                  double &evdwl) const
{
  const double r = std::sqrt(rsq);
  if (eflag_either) evdwl += cohesion_energy(a, voli, volj, r, rc);
  return cohesion_fpair(a, voli, volj, r, rc);
}

/* ----------------------------------------------------------------------
   quantities of one particle only: once per particle, not per pair, side by side for the pair
   loop's gathers: P / rho^2, m, 1 / rho, mu; and the internal energy of the local particles
------------------------------------------------------------------------- */

void PairCellSPH::fluid_quantities(int eflag)
{
  double *rmass = atom->rmass;
  int *type = atom->type;
  double *rho = atom->dvector[irho];
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(quant);
    memory->create(quant, NQUANT * nmax, "pair:quant");
    memory->destroy(stress_r);
  }
  if (stress_eps > 0.0 && !stress_r) memory->create(stress_r, nmax, "pair:stress_r");
  tension = false;
  for (int i = 0; i < nall; i++) {
    const int t = type[i];
    double *const q = quant + NQUANT * i;
    if (fluid[t]) {
      const double inv_rho = 1.0 / rho[i];
      q[0] = pressure(t, rho[i]) * inv_rho * inv_rho;
      q[1] = rmass[i];
      q[2] = inv_rho;
      q[3] = mu[t];
      if (stress_eps > 0.0) {
        stress_r[i] = sph_stress_r(pressure(t, rho[i]), inv_rho, stress_eps);
        tension = tension || stress_r[i] > 0.0;
      }
      if (i < nlocal && eflag) {
        const double ei = rmass[i] * tait_internal_energy(rho[i], rho0[t], c[t], P0[t]);
        if (eflag_global) eng_vdwl += ei;
        if (eflag_atom) eatom[i] += ei;
      }
    } else {
      q[0] = q[1] = q[2] = q[3] = 0.0;
      if (stress_eps > 0.0) stress_r[i] = 0.0;
    }
  }
}

CellMech::SPHTypeData PairCellSPH::type_data() const
{
  return {fluid, cutsq, sinv, wrnorm};
}

/* ----------------------------------------------------------------------
   continuity rate drho_i/dt = sum_j m_j v_ij . grad_i W_ij (Eq. 7) into d_drho
   of local atoms. Called by fix cell/fluid before the forces, with the
   velocities of the half step, so that the density leapfrogs the velocity.
------------------------------------------------------------------------- */

void PairCellSPH::continuity()
{
  double *drho = atom->dvector[idrho];
  const int newton_pair = force->newton_pair;
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < (newton_pair ? nall : atom->nlocal); i++) drho[i] = 0.0;
  pairs->find_with_continuity(list, type_data(), drho);
  if (newton_pair) comm->reverse_comm(this);
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::allocate()
{
  allocated = 1;
  const int np1 = atom->ntypes + 1;
  memory->create(setflag, np1, np1, "pair:setflag");
  memory->create(cutsq, np1, np1, "pair:cutsq");
  memory->create(s, np1, np1, "pair:s");
  memory->create(sinv, np1, np1, "pair:sinv");
  memory->create(wrnorm, np1, np1, "pair:wrnorm");
  memory->create(wdp, np1, np1, "pair:wdp");
  memory->create(fnorm, np1, np1, "pair:fnorm");
  memory->create(coh_a, np1, np1, "pair:coh_a");
  memory->create(fluid, np1, "pair:fluid");
  memory->create(rho0, np1, "pair:rho0");
  memory->create(c, np1, "pair:c");
  memory->create(P0, np1, "pair:P0");
  memory->create(mu, np1, "pair:mu");
  memory->create(kappa, np1, "pair:kappa");
  for (int i = 1; i < np1; i++) {
    fluid[i] = 0;
    rho0[i] = c[i] = P0[i] = mu[i] = kappa[i] = 0.0;
    for (int j = i; j < np1; j++) setflag[i][j] = 0;
  }
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::init_style()
{
  CellMech::require_unit_consistency(lmp, "Pair style cell/sph");
  if (!atom->rmass_flag)
    error->all(FLERR,
               "Pair style cell/sph requires per-atom masses: add rmass to the fix property/atom "
               "(fix ID all property/atom rmass d_rho d_drho ...)");
  int flag, cols;
  irho = atom->find_custom(CellMech::RHO_FIELD, flag, cols);
  if (irho < 0 || flag != 1 || cols != 0)
    error->all(FLERR,
               "Pair style cell/sph requires the per-atom density d_rho of fix property/atom");
  idrho = atom->find_custom(CellMech::DRHO_FIELD, flag, cols);
  if (idrho < 0 || flag != 1 || cols != 0)
    error->all(
        FLERR,
        "Pair style cell/sph requires the per-atom density rate d_drho of fix property/atom");
  if (!comm->ghost_velocity)
    error->all(FLERR,
               "Pair style cell/sph requires 'comm_modify vel yes' (viscosity and continuity use "
               "ghost velocities)");
  check_fluid_atoms();
  check_spacing();
  check_timestep();
  CellMech::check_drag(lmp);
  // without fix cell/fluid the continuity equation is never integrated: a frozen density is
  // legal (a fixed boundary of SPH particles) but rarely meant for a whole system
  if (modify->get_fix_by_style("^cell/fluid").empty() && comm->me == 0)
    error->warning(FLERR, "Pair style cell/sph without fix cell/fluid: densities stay constant");
  neighbor->add_request(this);
}

double PairCellSPH::init_one(int i, int j)
{
  if (!fluid[i] || !fluid[j])
    error->all(FLERR, "Pair style cell/sph: types {} and {} are not both fluid types", i, j);
  if (setflag[i][j] == 0) s[i][j] = 0.5 * (s[i][i] + s[j][j]);
  s[j][i] = s[i][j];
  sinv[i][j] = sinv[j][i] = 1.0 / s[i][j];
  wrnorm[i][j] = wrnorm[j][i] = kernel_wr_norm(s[i][j]);
  if (stress_eps > 0.0) {
    if (stress_dp >= 2.0 * s[i][j])
      error->all(FLERR,
                 "pair_style cell/sph stress: particle spacing dp {} must lie inside the kernel's "
                 "support 2s = {} of types {} and {}",
                 stress_dp, 2.0 * s[i][j], i, j);
    wdp[i][j] = wdp[j][i] = kernel_w(stress_dp, s[i][j]);
    fnorm[i][j] = fnorm[j][i] = kernel_w_norm(s[i][j]) / wdp[i][j];
  }
  coh_a[i][j] = coh_a[j][i] = cohesion_amplitude(coh_gamma, 2.0 * s[i][j]);
  return 2.0 * s[i][j];
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::write_restart(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++) {
    fwrite(&fluid[i], sizeof(int), 1, fp);
    for (double *a : {rho0, c, P0, mu}) fwrite(&a[i], sizeof(double), 1, fp);
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      fwrite(&s[i][j], sizeof(double), 1, fp);
    }
  }
}

void PairCellSPH::read_restart(FILE *fp)
{
  allocate();
  // one value, in the order write_restart wrote them: read by rank 0, sent to every rank
  auto get = [&](auto &value) {
    if (comm->me == 0) utils::sfread(FLERR, &value, sizeof(value), 1, fp, nullptr, error);
    MPI_Bcast(&value, sizeof(value), MPI_BYTE, 0, world);
  };
  for (int i = 1; i <= atom->ntypes; i++) {
    get(fluid[i]);
    for (double *a : {rho0, c, P0, mu}) get(a[i]);
    kappa[i] = tait_kappa(rho0[i], c[i]);
    for (int j = i; j <= atom->ntypes; j++) {
      get(setflag[i][j]);
      get(s[i][j]);
    }
  }
}

/* ---------------------------------------------------------------------- */

double PairCellSPH::single(int i, int j, int itype, int jtype, double rsq, double /*factor_coul*/,
                           double /*factor_lj*/, double &fforce)
{
  // central (pressure) part only; the viscous force is not along r_ij
  if (!CellMech::same_cell(atom->molecule, i, j)) {
    fforce = 0.0;
    return 0.0;
  }
  const double *rho = atom->dvector[irho];
  const double wr = kernel_wr(rsq, sinv[itype][jtype], wrnorm[itype][jtype]);
  const double mi = atom->rmass[i], mj = atom->rmass[j];
  const double Pi = pressure(itype, rho[i]), Pj = pressure(jtype, rho[j]);
  fforce = sph_pressure_fpair(mi, mj, Pi / (rho[i] * rho[i]), Pj / (rho[j] * rho[j]), wr);
  double energy = 0.0;
  if (coh_gamma > 0.0) {
    const double r = std::sqrt(rsq), rc = 2.0 * s[itype][jtype];
    const double vi = mi / rho[i], vj = mj / rho[j];
    fforce += cohesion_fpair(coh_a[itype][jtype], vi, vj, r, rc);
    energy = cohesion_energy(coh_a[itype][jtype], vi, vj, r, rc);
  }
  if (stress_eps <= 0.0) return energy;
  // the artificial stress and its pair energy
  const double ri = sph_stress_r(Pi, 1.0 / rho[i], stress_eps);
  const double rj = sph_stress_r(Pj, 1.0 / rho[j], stress_eps);
  const double f = kernel_w_q(std::sqrt(rsq) * sinv[itype][jtype], fnorm[itype][jtype]);
  const double fn = sph_stress_fn(f, stress_n);
  fforce += sph_stress_fpair(mi, mj, ri, rj, fn, wr);
  return energy + sph_stress_energy(mi, mj, ri, rj, fn * f, wdp[itype][jtype], stress_n);
}

void *PairCellSPH::extract(const char *str, int &dim)
{
  dim = 1;
  if (strcmp(str, "rho0") == 0) return (void *) rho0;
  if (strcmp(str, "c") == 0) return (void *) c;
  if (strcmp(str, "P0") == 0) return (void *) P0;
  if (strcmp(str, "mu") == 0) return (void *) mu;
  dim = 2;
  if (strcmp(str, "s") == 0) return (void *) s;
  return nullptr;
}

/* ---------------------------------------------------------------------- */

int PairCellSPH::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  double *rho = atom->dvector[irho];
  double *rmass = atom->rmass;
  int m = 0;
  for (int k = 0; k < n; k++) {
    buf[m++] = rho[list[k]];
    buf[m++] = rmass[list[k]];
  }
  return m;
}

void PairCellSPH::unpack_forward_comm(int n, int first, double *buf)
{
  double *rho = atom->dvector[irho];
  double *rmass = atom->rmass;
  int m = 0;
  for (int i = first; i < first + n; i++) {
    rho[i] = buf[m++];
    rmass[i] = buf[m++];
  }
}

int PairCellSPH::pack_reverse_comm(int n, int first, double *buf)
{
  double *drho = atom->dvector[idrho];
  int m = 0;
  for (int i = first; i < first + n; i++) buf[m++] = drho[i];
  return m;
}

void PairCellSPH::unpack_reverse_comm(int n, int *list, double *buf)
{
  double *drho = atom->dvector[idrho];
  int m = 0;
  for (int k = 0; k < n; k++) drho[list[k]] += buf[m++];
}

double PairCellSPH::memory_usage()
{
  return Pair::memory_usage() + (double) NQUANT * nmax * sizeof(double) + pairs->memory_usage();
}
