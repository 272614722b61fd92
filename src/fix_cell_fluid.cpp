/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: fix cell/fluid

     drho_i/dt = drho^c_i/dt + (rho_i / m_i) dm_i/dt                        (Eq. 9)
     dm_i/dt   = -(A_c L_p rho_i / N_f)(P_i + Pi)                           (Eq. 10)
   drho^c_i/dt is the continuity rate of pair cell/sph (Eq. 7). A_c is the
   current area of the wall of the particle's cell, summed over the wall's
   triangles (the angles of the topology), and N_f the cell's current
   number of fluid particles in the fix group.
   Density and mass leapfrog the velocities, as in the paper: in pre_force,
   once the positions and half-step velocities of the new step are known
   and before the forces, rho(n+1) = rho(n) + dt [drho^c/dt + (rho/m) dm/dt]
   with the continuity rate of the half-step velocities, so the pressure
   force of step n+1 sees the density of step n+1. Advancing the density by
   velocity-Verlet half steps instead (with the rate of the previous force
   call) lets the pressure lag the motion and pumps energy into the
   acoustic modes at a rate ~ (c k)^2 dt: unstable at the wall's time steps.
   The osmotic uptake of a step is Eq. 10 linearised in its own effect on
   the pressure (osmotic_mass_step in cell_physics.h), stable for the large
   Lp that inflate a cell. Under run_style respa they advance on the
   outermost level, with the SPH forces.
------------------------------------------------------------------------- */

#include "fix_cell_fluid.h"

#include "cell_compat.h"

#include "atom.h"
#include "cell_checks.h"
#include "cell_physics.h"
#include "comm.h"
#include "error.h"
#include "fix_cell_tether_break.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "pair_cell_sph.h"
#include "respa.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace CellPhysics;

/* ----------------------------------------------------------------------
   fix ID group cell/fluid Pi value Lp value
------------------------------------------------------------------------- */

FixCellFluid::FixCellFluid(LAMMPS *_lmp, int narg, char **arg) :
    Fix(_lmp, narg, arg), Pi(0.0), Lp(0.0), dt(0.0), ilevel_respa(0), ncells(0), area(nullptr),
    nfluid(nullptr), nbroken(nullptr), flux_local(nullptr), flux_all(nullptr), flux_stale(1),
    sph(nullptr)
{
  if (narg != 7)
    error->all(FLERR,
               "Illegal fix cell/fluid command: expected 'fix ID group cell/fluid Pi value Lp "
               "value', got {} arguments after the group",
               narg - 3);
  // both keywords, in either order, each once
  if (strcmp(arg[3], arg[5]) == 0)
    error->all(FLERR,
               "Illegal fix cell/fluid command: keyword '{}' given twice; expected 'Pi value Lp "
               "value' (in either order)",
               arg[3]);
  modify_param(2, &arg[3]);
  modify_param(2, &arg[5]);
  if (!atom->molecule_flag)
    error->all(FLERR,
               "Fix cell/fluid requires molecule IDs (one per cell): use atom_style molecular");
  // positions are left to fix nve & co.; this fix advances density and mass only
  time_integrate = 0;
  vector_flag = 1;
  extvector = 1;
  global_freq = 1;
  restart_global = 1;
  size_vector = 0;
}

FixCellFluid::~FixCellFluid()
{
  memory->destroy(area);
  memory->destroy(nfluid);
  memory->destroy(nbroken);
  memory->destroy(flux_local);
  memory->destroy(flux_all);
}

int FixCellFluid::setmask()
{
  return PRE_FORCE | PRE_FORCE_RESPA;
}

/* ----------------------------------------------------------------------
   fix_modify ID Pi value Lp value: change the osmotic potential or the
   hydraulic conductivity between runs (inflation with a large Lp first)
------------------------------------------------------------------------- */

int FixCellFluid::modify_param(int narg, char **arg)
{
  // one keyword-value pair per call: LAMMPS's fix_modify passes what it does not know itself
  if (narg < 2) error->all(FLERR, "fix cell/fluid: keyword '{}' needs a value", arg[0]);
  if (strcmp(arg[0], "Pi") == 0) {
    Pi = utils::numeric(FLERR, arg[1], false, lmp);
    if (Pi > 0.0)
      error->all(FLERR,
                 "fix cell/fluid: osmotic potential Pi must be <= 0 (water potential), got {}", Pi);
    CellMech::require_magnitude(lmp, "fix cell/fluid", "osmotic potential Pi", Pi);
  } else if (strcmp(arg[0], "Lp") == 0) {
    Lp = utils::numeric(FLERR, arg[1], false, lmp);
    if (Lp < 0.0)
      error->all(FLERR, "fix cell/fluid: hydraulic conductivity Lp must be >= 0, got {}", Lp);
    CellMech::require_magnitude(lmp, "fix cell/fluid", "hydraulic conductivity Lp", Lp);
  } else
    error->all(FLERR, "Unknown keyword '{}' for fix cell/fluid: expected 'Pi' or 'Lp'", arg[0]);
  return 2;
}

/* ---------------------------------------------------------------------- */

void FixCellFluid::init()
{
  CellMech::require_unit_consistency(lmp, "Fix cell/fluid");
  sph = dynamic_cast<PairCellSPH *>(force->pair_match("^cell/sph", 0));
  if (!sph) error->all(FLERR, "Fix cell/fluid requires pair style cell/sph (alone or in hybrid)");
  check_group();
  if (!atom->rmass_flag)
    error->all(FLERR, "Fix cell/fluid requires per-atom masses (rmass in fix property/atom)");
  if (!force->newton_bond)
    error->all(FLERR,
               "Fix cell/fluid requires newton_bond on: each wall triangle must be counted once");
  if (Lp > 0.0 && (!atom->nangles || !force->angle))
    error->all(FLERR,
               "Fix cell/fluid with Lp > 0 needs the wall triangles as angles and an angle "
               "style (angle_style zero nocoeff) to measure the cell area");
  dt = update->dt;
  ilevel_respa = 0;
  if (utils::strmatch(update->integrate_style, "^respa")) {
    auto respa = dynamic_cast<Respa *>(update->integrate);
    ilevel_respa = respa->nlevels - 1;
    dt = respa->step[ilevel_respa];
    // density must advance where the SPH forces and the continuity rate are computed
    if (respa->level_pair != ilevel_respa)
      error->all(FLERR,
                 "Fix cell/fluid with run_style respa requires the pair styles on the outermost "
                 "level (e.g. run_style respa 2 2 bond 1 angle 1 pair 2)");
  }
  index_cells();
}

/* ----------------------------------------------------------------------
   the fix advances the density and mass of the fluid (cell/sph types) in its group: a group with
   none would silently do nothing, and two fixes sharing atoms would advance them twice per step
------------------------------------------------------------------------- */

void FixCellFluid::check_group()
{
  int *mask = atom->mask, *type = atom->type;
  bigint fluid_local = 0, fluid = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((mask[i] & groupbit) && sph->setflag[type[i]][type[i]]) fluid_local++;
  MPI_Allreduce(&fluid_local, &fluid, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (fluid == 0)
    error->all(FLERR,
               "Fix cell/fluid {}: group {} holds no fluid particles (atoms of a type with "
               "pair_coeff T T cell/sph); the fix would do nothing",
               id, group->names[igroup]);
  for (auto *other : modify->get_fix_by_style("^cell/fluid$")) {
    if (other == this) continue;
    bigint shared_local = 0, shared = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((mask[i] & groupbit) && (mask[i] & other->groupbit)) shared_local++;
    MPI_Allreduce(&shared_local, &shared, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    if (shared)
      error->all(FLERR,
                 "Fix cell/fluid {} and fix cell/fluid {} both act on {} atoms (groups {} and {}): "
                 "each would advance their density and mass; use one fix per fluid",
                 id, other->id, shared, group->names[igroup], group->names[other->igroup]);
  }
}

/* ----------------------------------------------------------------------
   the cells present and their slots; each rank's uptake totals follow their cells' molecule IDs
   when the slots change (a cell appears or disappears) and take up a restart file's totals
------------------------------------------------------------------------- */

void FixCellFluid::index_cells()
{
  const std::vector<tagint> old = cells.molecule_ids();
  cells.build(lmp);
  if (cells.molecule_ids() == old && flux_restart.empty() && flux_local) return;
  const int n = cells.size();
  std::vector<double> flux(n + 1, 0.0);
  for (int k = 1; k <= (int) old.size(); k++) flux[cells.slot(old[k - 1])] += flux_local[k];
  // the restart's totals were kept on rank 0 only, so they are summed once
  if (comm->me == 0)
    for (const auto &kv : flux_restart) flux[cells.slot(kv.first)] += kv.second;
  flux_restart.clear();
  flux[0] = 0.0;    // slot 0: IDs that left
  ncells = n;
  for (double **a : {&area, &nfluid, &nbroken, &flux_local, &flux_all}) {
    memory->destroy(*a);
    memory->create(*a, ncells + 1, "cell/fluid:percell");
  }
  for (int m = 0; m <= ncells; m++) flux_local[m] = flux[m];
  size_vector = ncells;
  flux_stale = 1;
}

/* ----------------------------------------------------------------------
   wall area (triangles = angles, counted once with newton_bond on) and
   fluid count of each cell
------------------------------------------------------------------------- */

void FixCellFluid::cell_geometry()
{
  double **x = atom->x;
  tagint *molecule = atom->molecule;
  int *mask = atom->mask;
  const int n1 = ncells + 1;
  std::vector<double> local(3 * n1, 0.0), all(3 * n1);

  int **anglelist = neighbor->anglelist;
  for (int n = 0; n < neighbor->nanglelist; n++) {
    if (anglelist[n][3] <= 0) continue;    // triangle of a broken wall
    const int a = anglelist[n][0], b = anglelist[n][1], c = anglelist[n][2];
    double u[3], w[3];
    for (int d = 0; d < 3; d++) {
      u[d] = x[b][d] - x[a][d];
      w[d] = x[c][d] - x[a][d];
    }
    // the cell of the central node (contract: cell_fields.h)
    const int m = cells.slot(molecule[b]);
    if (m >= 1) local[m] += triangle_area(u, w);
  }
  for (int i = 0; i < atom->nlocal; i++) {
    const int m = cells.slot(molecule[i]);
    if ((mask[i] & groupbit) && sph->is_fluid(atom->type[i]) && m >= 1) local[n1 + m] += 1.0;
  }
  // broken tethers, each counted at both of its nodes by fix CELL_TETHER_BREAK
  auto *broken = modify->get_fix_by_id(FixCellTetherBreak::ID);
  if (broken)
    for (int i = 0; i < atom->nlocal; i++) {
      const int m = cells.slot(molecule[i]);
      if (m >= 1) local[2 * n1 + m] += broken->vector_atom[i];
    }
  MPI_Allreduce(local.data(), all.data(), 3 * n1, MPI_DOUBLE, MPI_SUM, world);
  for (int m = 0; m <= ncells; m++) {
    area[m] = all[m];
    nfluid[m] = all[n1 + m];
    nbroken[m] = all[2 * n1 + m];
  }
}

/* ---------------------------------------------------------------------- */

// at the start of a run the state is as given: nothing to advance, only cells to count
void FixCellFluid::setup_pre_force(int /*vflag*/)
{
  index_cells();
}

void FixCellFluid::pre_force(int /*vflag*/)
{
  // atoms change ranks or leave only when LAMMPS re-neighbors
  if (neighbor->ago == 0) index_cells();
  sph->continuity();
  const bool osmosis = (Lp > 0.0);
  if (osmosis) cell_geometry();

  double *rho = sph->rho_array();
  double *drho = sph->drho_array();
  double *rmass = atom->rmass;
  int *type = atom->type;
  int *mask = atom->mask;
  tagint *molecule = atom->molecule;
  const int nlocal = atom->nlocal;

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit) || !sph->is_fluid(type[i])) continue;
    double rate = drho[i];
    const int m = cells.slot(molecule[i]);
    double dm = 0.0;
    // Eq. 10 needs the membrane that holds the solutes in: a wall with a broken tether has a
    // hole (its triangles and their virtual particles are gone), its protoplast has burst, and
    // its fluid, inside or escaped, no longer exchanges water osmotically
    if (osmosis && m >= 1 && nfluid[m] > 0 && nbroken[m] == 0.0) {
      const double P = sph->pressure(type[i], rho[i]);
      const double k = osmotic_coefficient(area[m], Lp, rho[i], nfluid[m]);
      dm = osmotic_mass_step(k, dt, P, Pi, sph->dpressure_drho(type[i], rho[i]), rho[i], rmass[i]);
      flux_local[m] += dm;
      flux_stale = 1;
    }
    rho[i] += density_increment(rho[i], rmass[i], rate, dt, dm);
    rmass[i] += dm;
  }
}

void FixCellFluid::pre_force_respa(int vflag, int ilevel, int /*iloop*/)
{
  if (ilevel == ilevel_respa) pre_force(vflag);
}

/* ----------------------------------------------------------------------
   vector element m: mass taken up by the cell in slot m+1 (ascending
   molecule IDs) through its wall since the fix was defined (negative: lost)
------------------------------------------------------------------------- */

double FixCellFluid::compute_vector(int m)
{
  if (flux_stale) {
    MPI_Allreduce(flux_local, flux_all, ncells + 1, MPI_DOUBLE, MPI_SUM, world);
    flux_stale = 0;
  }
  return flux_all[m + 1];
}

/* ----------------------------------------------------------------------
   restart: -ncells, then (molecule ID, uptake) of each cell. Files of the
   earlier format (ncells, then the uptake of molecules 1..ncells) still read.
------------------------------------------------------------------------- */

void FixCellFluid::write_restart(FILE *fp)
{
  std::vector<double> sum(ncells + 1), list(1 + 2 * ncells);
  MPI_Allreduce(flux_local, sum.data(), ncells + 1, MPI_DOUBLE, MPI_SUM, world);
  list[0] = -ncells;
  for (int m = 1; m <= ncells; m++) {
    list[2 * m - 1] = (double) cells.id(m);
    list[2 * m] = sum[m];
  }
  if (comm->me == 0) {
    int size = list.size() * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list.data(), sizeof(double), list.size(), fp);
  }
}

void FixCellFluid::restart(char *buf)
{
  auto list = (double *) buf;
  flux_restart.clear();
  if (list[0] < 0) {
    const int n = (int) -list[0];
    for (int m = 1; m <= n; m++) flux_restart[(tagint) list[2 * m - 1]] += list[2 * m];
  } else {
    const int n = (int) list[0];
    for (int m = 1; m <= n; m++) flux_restart[m] += list[m];
  }
}
