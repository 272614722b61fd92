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
   the pressure (osmotic_mass_step in physics/osmosis.h), stable for the large
   Lp that inflate a cell. Under run_style respa they advance on the
   outermost level, with the SPH forces, by its step; with only the wall's
   elements on the inner levels (they act on wall nodes), the fluid's
   velocity there is still the half step of the outer level.

   Options for tissues (not in the paper, which has one cell in pure water;
   docs/fix_cell_fluid.rst): Pi and Lp per cell; solutes kept in their cell,
   Pi W = Pi0 W0 (Eq. W1); water exchanged between glued cells through
   their shared wall, k (psi_a - psi_b) with psi = P + Pi (Eqs. W2-W3),
   one mass per pair added to one cell and taken from the other so that
   the exchange conserves mass to round-off; and the outside reached only
   through the exposed wall (Eq. W4: neither glued nor facing another
   cell's wall within a distance, or, as an explicit choice, not glued),
   at a water potential psi_ext or at a set flux. Each cell's share is
   spread evenly over its fluid particles, as Eq. 10's A_c / N_f does.
------------------------------------------------------------------------- */

#include "fix_cell_fluid.h"

#include "cell_compat.h"

#include "cell_fields.h"

#include "atom.h"
#include "cell_checks.h"
#include "cell_exposed.h"
#include "comm.h"
#include "error.h"
#include "fix_cell_tether_break.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "pair_cell_sph.h"
#include "pair_cell_virtual.h"
#include "physics/sph.h"
#include "respa.h"
#include "update.h"

#include <algorithm>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace CellPhysics;

namespace {
constexpr int NCOLS = 7;    // compute_array columns
}    // namespace

/* ----------------------------------------------------------------------
   fix ID group cell/fluid Pi value Lp value [keyword args ...]
     cell M Pi value Lp value | cells file | solute yes/no | exchange yes/no
     | external psi value | external flux value
------------------------------------------------------------------------- */

FixCellFluid::FixCellFluid(LAMMPS *_lmp, int narg, char **arg) :
    Fix(_lmp, narg, arg), settings(_lmp), water(settings, sums, books.water0), ncells(0), dt(0.0),
    ilevel_respa(0), sph(nullptr), iref(-1), ialam(-1)
{
  parse_command(narg, arg);
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
  array_flag = 1;
  size_array_cols = NCOLS;
  size_array_rows = 0;
  extarray = 0;
  comm_forward = comm_reverse = 1;    // node_glued, at a neighbour-list build
  // fix ave/time (mode vector) takes the number of rows when it is defined, usually before the
  // first run: the cells present now size the vector and array (zero rows otherwise, all run long)
  index_cells();
}

void FixCellFluid::parse_command(int narg, char **arg)
{
  if (narg < 7)
    error->all(FLERR,
               "Illegal fix cell/fluid command: expected 'fix ID group cell/fluid Pi value Lp "
               "value [keyword args ...]', got {} arguments after the group",
               narg - 3);
  // both keywords, in either order, each once
  if (strcmp(arg[3], arg[5]) == 0)
    error->all(FLERR,
               "Illegal fix cell/fluid command: keyword '{}' given twice; expected 'Pi value Lp "
               "value' (in either order)",
               arg[3]);
  if ((strcmp(arg[3], "Pi") != 0 && strcmp(arg[3], "Lp") != 0) ||
      (strcmp(arg[5], "Pi") != 0 && strcmp(arg[5], "Lp") != 0))
    error->all(FLERR,
               "Illegal fix cell/fluid command: expected 'Pi value Lp value' (in either order) "
               "first, got '{} {} {} {}'",
               arg[3], arg[4], arg[5], arg[6]);
  settings.parse_keyword(2, &arg[3]);
  settings.parse_keyword(2, &arg[5]);
  for (int iarg = 7; iarg < narg;) iarg += settings.parse_keyword(narg - iarg, &arg[iarg]);
  settings.end_command();
}

int FixCellFluid::setmask()
{
  return PRE_FORCE | PRE_FORCE_RESPA;
}

/* ----------------------------------------------------------------------
   fix_modify ID keyword args: the fix's keywords, between runs (inflation
   with a large Lp first, then a drying series of external psi values)
------------------------------------------------------------------------- */

int FixCellFluid::modify_param(int narg, char **arg)
{
  // one keyword per call: LAMMPS's fix_modify passes what it does not know itself
  return settings.parse_keyword(narg, arg);
}

/* ---------------------------------------------------------------------- */

void FixCellFluid::init()
{
  CellMech::require_unit_consistency(lmp, "Fix cell/fluid");
  find_styles();
  warn_unheld_protoplasm();
  warn_uneven_share();
  check_respa();
  // exposed outside looks for other cells' walls up to its distance from a triangle
  if (settings.exposed_outside() && settings.active()) widen_ghost_cutoff();
  const int published = size_array_rows;
  index_cells();
  if (ncells != published && comm->me == 0 && !modify->get_fix_by_style("^ave/time").empty())
    error->warning(FLERR,
                   "Fix cell/fluid {}: the number of cells changed from {} to {} since the fix "
                   "was defined or last ran; a fix ave/time defined before now keeps the old "
                   "number of rows of f_{}",
                   id, published, ncells, id);
}

void FixCellFluid::find_styles()
{
  sph = dynamic_cast<PairCellSPH *>(force->pair_match("^cell/sph", 0));
  if (!sph) error->all(FLERR, "Fix cell/fluid requires pair style cell/sph (alone or in hybrid)");
  check_group();
  if (!atom->rmass_flag)
    error->all(FLERR, "Fix cell/fluid requires per-atom masses (rmass in fix property/atom)");
  if (!force->newton_bond)
    error->all(FLERR,
               "Fix cell/fluid requires newton_bond on: each wall triangle must be counted once");
  if (settings.active() && (!atom->nangles || !force->angle))
    error->all(FLERR,
               "Fix cell/fluid with Lp > 0 or an external flux needs the wall triangles as angles "
               "and an angle style (angle_style zero nocoeff) to measure the cell area");
  int flag, cols;
  iref = atom->find_custom(CellMech::REF_FIELD, flag, cols);
  if (iref >= 0 && (flag != 1 || cols != 3)) iref = -1;
  ialam = atom->find_custom(CellMech::AREA_FIELD, flag, cols);
  if (ialam >= 0 && (flag != 1 || cols != 0)) ialam = -1;
  // the shared wall is the lamella's area (d_alam) on the rest shape (d2_cellref) of the walls
  if (settings.exchange && (iref < 0 || ialam < 0))
    error->all(FLERR,
               "Fix cell/fluid {} exchange yes needs the per-atom fields d2_cellref (rest shape of "
               "the walls) and d_alam (lamella area) of fix property/atom, as cellgen.py tissue "
               "writes them; missing: {}",
               id, iref < 0 ? (ialam < 0 ? "both" : "d2_cellref") : "d_alam");
}

// Below its osmotic potential a cell loses its turgor and dries on. Held by nothing, its SPH
// protoplasm (no membrane, no cohesion) tears from the wall into vacuum and clumps: a picture of
// neither air drying (the protoplast pulls its wall in, cytorrhysis) nor plasmolysis (not
// modelled, keyword medium). Only a warning: runs that show what the adhesion changes need it off.
void FixCellFluid::warn_unheld_protoplasm()
{
  if (warned_unheld || comm->me != 0) return;
  if (settings.external != CellMech::WaterSettings::EXT_PSI || !settings.active()) return;
  const double Pi0 = settings.highest_pi0();
  if (settings.ext_value >= Pi0) return;
  auto wall = dynamic_cast<PairCellVirtual *>(force->pair_match("^cell/virtual", 0));
  if (wall && wall->adheres()) return;
  warned_unheld = true;
  error->warning(FLERR,
                 "Fix cell/fluid {}: external psi {} is below the osmotic potential {} of a cell: "
                 "it loses its turgor and dries on, and with no adhesion of its fluid to its wall "
                 "(pair_coeff ... cell/virtual ... adhere Fa delta) the protoplasm leaves the wall "
                 "into vacuum and clumps (docs/Howto_tissue.rst, drying)",
                 id, settings.ext_value, Pi0);
}

// With share particle (Eq. 10 as written) every particle of a cell takes the same mass, so where
// their masses differ (an inflation spreads them 88-1031 pg in a coarse block) a continuous loss
// to the outside dries the light ones first: they go into a tension that the wall contact holds,
// which no cell of one pressure would have (docs/studies/drying-cell.md). Collective.
void FixCellFluid::warn_uneven_share()
{
  // the outside draws water: a set flux, or air below pure water's potential
  const bool drying = settings.external_flux() ||
      (settings.external == CellMech::WaterSettings::EXT_PSI && settings.ext_value < 0.0 &&
       settings.active());
  if (warned_share || settings.share_volume() || !drying) return;
  double lo = std::numeric_limits<double>::max(), hi = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || !sph->is_fluid(atom->type[i])) continue;
    lo = std::min(lo, atom->rmass[i]);
    hi = std::max(hi, atom->rmass[i]);
  }
  double glo, ghi;
  MPI_Allreduce(&lo, &glo, 1, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(&hi, &ghi, 1, MPI_DOUBLE, MPI_MAX, world);
  warned_share = true;
  if (comm->me != 0 || !(ghi > 2.0 * glo)) return;
  error->warning(
      FLERR,
      "Fix cell/fluid {}: the fluid particles' masses differ by a factor {:.3g}, and with "
      "share particle (the default) each takes the same share of its cell's water flux "
      "to the outside, so the light ones dry first and hold a tension; share volume "
      "spreads it by volume and keeps one pressure per cell (docs/fix_cell_fluid.rst)",
      id, ghi / glo);
}

void FixCellFluid::check_respa()
{
  dt = update->dt;
  ilevel_respa = 0;
  if (!utils::strmatch(update->integrate_style, "^respa")) return;
  auto respa = dynamic_cast<Respa *>(update->integrate);
  ilevel_respa = respa->nlevels - 1;
  dt = respa->step[ilevel_respa];
  // density must advance with the SPH forces, where the pairs of the continuity pass are reused;
  // with respa's 'hybrid' keyword pair cell/sph checks its own level in the run's setup
  const int level = respa->level_pair;
  if (respa->nhybrid_styles == 0 && level != ilevel_respa)
    error->all(FLERR,
               "Fix cell/fluid {} with run_style respa needs the pair styles (cell/sph) on the "
               "outermost level: expected 'run_style respa {} ... pair {}', got {}",
               id, respa->nlevels, ilevel_respa + 1,
               level < 0 ? std::string("pair inner/middle/outer")
                         : fmt::format("pair {}", level + 1));
}

// the other cells' walls within the distance of exposed outside must be here as ghosts on every
// rank, as pair styles raise the cutoff for what they need (tip4p)
void FixCellFluid::widen_ghost_cutoff()
{
  // the default is a length in um; reduced units have no um to convert it from
  if (!settings.depth_given && force->angstrom == 1.0 && strcmp(update->unit_style, "lj") == 0)
    error->all(FLERR,
               "Fix cell/fluid {} exposed outside: units lj has no length for the default "
               "distance (10 um); give it, 'exposed outside D', or use exposed unglued",
               id);
  if (comm->mode != Comm::SINGLE)
    error->all(FLERR,
               "Fix cell/fluid {} exposed outside needs one ghost cutoff for all atoms "
               "(comm_modify mode single), or use exposed unglued",
               id);
  const double have =
      MAX(comm->cutghostuser, force->pair ? force->pair->cutforce + neighbor->skin : 0.0);
  if (have < settings.expose_depth) {
    if (comm->me == 0)
      utils::logmesg(lmp,
                     "Fix cell/fluid {}: communication cutoff raised from {:.8} to {:.8}, the "
                     "distance of 'exposed outside'\n",
                     id, have, settings.expose_depth);
    comm->cutghostuser = settings.expose_depth;
  }
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
   the cells present and their slots; the books follow the cells' molecule IDs when the slots
   change (a cell appears or disappears) and take up a restart file's record
------------------------------------------------------------------------- */

void FixCellFluid::index_cells()
{
  const std::vector<tagint> old = cells.molecule_ids();
  cells.build(lmp);
  if (!books.reindex(old, cells, comm->me)) return;
  ncells = cells.size();
  water.resize(ncells);
  sums.clear(ncells);
  size_vector = ncells;
  size_array_rows = ncells;
}

/* ----------------------------------------------------------------------
   this step's sums of each cell: wall area (triangles = angles, counted
   once with newton_bond on), fluid and broken tethers
------------------------------------------------------------------------- */

void FixCellFluid::measure_cells()
{
  sums.clear(ncells);
  if (triangles.stale(lmp)) {
    triangles.index(lmp, cells, iref >= 0 ? atom->darray[iref] : nullptr);
    if (settings.exposed_outside()) find_open_triangles();
  }
  triangles.add_areas(lmp, iref >= 0, sums);
  sums.add_fluid(lmp, sph, cells, groupbit);
  // a wall with a broken tether is open (advance_fluid); called at the neighbor stage and after,
  // where the counts of the last build are the present ones
  sums.add_broken_tethers(lmp, cells, FixCellFailure::built_counts(lmp, FixCellTetherBreak::ID));
  sums.reduce(world);
}

// found where the ghosts are fresh, at the build: the nodes glued to another cell, counted at both
// nodes of their bonds, are summed onto their owners, then sent to the ghosts
void FixCellFluid::find_open_triangles()
{
  CellMech::count_glued_nodes(lmp, node_glued);
  comm->reverse_comm(this);
  comm->forward_comm(this);
  triangles.find_open(lmp, sph, settings.expose_depth, node_glued);
}

// this step's glued pairs (exchange yes) and every cell's potentials
void FixCellFluid::update_potentials()
{
  if (settings.exchange)
    exchange.find_pairs(lmp, cells, atom->dvector[ialam]);
  else
    exchange.clear();
  water.update(cells, exchange.pairs());
}

/* ---------------------------------------------------------------------- */

// at the start of a run the state is as given: nothing to advance, only cells to count
void FixCellFluid::setup_pre_force(int /*vflag*/)
{
  index_cells();
  measure_cells();
  update_potentials();
  // W0 of Eq. W1: the water of each cell when the fix first ran (or from the restart file)
  for (int m = 1; m <= ncells; m++)
    if (books.water0[m] == 0.0) books.water0[m] = sums[m].mass;
  update_potentials();
  check_cell_settings();
  check_walls();
}

// a setting for a cell that is not there is a typo, which would otherwise be silent
void FixCellFluid::check_cell_settings()
{
  for (const auto &kv : settings.percell) {
    const int m = cells.slot(kv.first);
    if (m < 1 || sums[m].nfluid == 0)
      error->all(FLERR,
                 "Fix cell/fluid {}: a per-cell setting names cell (molecule ID) {}, which holds "
                 "no fluid particles of group {}",
                 id, kv.first, group->names[igroup]);
  }
}

// fluid of a molecule without wall triangles would have a wall area of 0 and take up or lose no
// water through it, without a word
void FixCellFluid::check_walls()
{
  const bool flux = settings.external_flux();
  for (int m = 1; m <= ncells; m++) {
    const CellMech::CellSum &s = sums[m];
    if (s.nfluid > 0 && s.area <= 0.0 && s.broken == 0.0 && (water.lp[m] > 0.0 || flux))
      error->all(FLERR,
                 "Fix cell/fluid {}: cell (molecule ID) {} holds {} fluid particle(s) of group {} "
                 "but no wall triangles (angles whose central node has that molecule ID), so its "
                 "wall area is 0 and no water would cross it; give the fluid the molecule ID of "
                 "its cell's wall (or, without an external flux, 'cell {} Lp 0' to keep it closed)",
                 id, cells.id(m), (bigint) s.nfluid, group->names[igroup], cells.id(m));
  }
}

void FixCellFluid::pre_force(int /*vflag*/)
{
  // atoms change ranks or leave only when LAMMPS re-neighbors
  if (neighbor->ago == 0) index_cells();
  sph->continuity();
  const bool osmosis = settings.active();
  std::vector<double> uptake(ncells + 1, 0.0);    // per cell: from its neighbours, this step
  if (osmosis) {
    measure_cells();
    update_potentials();
    exchange.add_uptake(sums, water, dt, uptake);
  }
  advance_fluid(osmosis, uptake);
}

// Eq. 9 with the mass step of Eq. 10 (the outside and the neighbours)
void FixCellFluid::advance_fluid(bool osmosis, const std::vector<double> &uptake)
{
  double *rho = sph->rho_array();
  double *drho = sph->drho_array();
  double *rmass = atom->rmass;
  int *type = atom->type;
  int *mask = atom->mask;
  tagint *molecule = atom->molecule;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || !sph->is_fluid(type[i])) continue;
    const int m = cells.slot(molecule[i]);
    double dm = 0.0;
    // Eq. 10 needs the membrane that holds the solutes in: a wall with a broken tether has a
    // hole (its triangles and their virtual particles are gone), its protoplast has burst, and
    // its fluid, inside or escaped, no longer exchanges water osmotically
    if (osmosis && m >= 1 && sums[m].nfluid > 0 && sums[m].broken == 0.0) {
      // the particle's part of the cell's flux, from the outside and from its neighbours
      const double n = water.shares(m, rmass[i], rho[i]);
      dm = water.outside_mass_step(m, sph, type[i], rho[i], rmass[i], n, dt);
      dm += uptake[m] / n;
      if (rmass[i] + dm <= 0.0)
        error->one(FLERR,
                   "Fix cell/fluid {}: fluid particle {} of cell {} would lose all its mass "
                   "({} + {}) this step: the cell has dried out (external flux or potential too "
                   "strong for its water)",
                   id, atom->tag[i], molecule[i], rmass[i], dm);
      books.add(m, dm);
    }
    rho[i] += density_increment(rho[i], rmass[i], drho[i], dt, dm);
    rmass[i] += dm;
  }
}

void FixCellFluid::setup_pre_force_respa(int vflag, int ilevel)
{
  if (ilevel == ilevel_respa) setup_pre_force(vflag);
}

void FixCellFluid::pre_force_respa(int vflag, int ilevel, int /*iloop*/)
{
  if (ilevel != ilevel_respa) return;
  // the inner levels' last half kick changed the owned velocities after the last forward
  // communication: the ghosts take them again, so that the continuity rate (and the outer pair
  // forces) see the same velocities on both sides of a rank boundary, as under Verlet
  if (ilevel > 0) comm->forward_comm();
  pre_force(vflag);
}

/* ----------------------------------------------------------------------
   node_glued of ghosts: summed onto the owners, then copied back
------------------------------------------------------------------------- */

int FixCellFluid::pack_reverse_comm(int n, int first, double *buf)
{
  for (int i = 0; i < n; i++) buf[i] = node_glued[first + i];
  return n;
}

void FixCellFluid::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int i = 0; i < n; i++) node_glued[list[i]] += buf[i];
}

int FixCellFluid::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  for (int i = 0; i < n; i++) buf[i] = node_glued[list[i]];
  return n;
}

void FixCellFluid::unpack_forward_comm(int n, int first, double *buf)
{
  for (int i = 0; i < n; i++) node_glued[first + i] = buf[i];
}

/* ----------------------------------------------------------------------
   vector element m: mass taken up by the cell in slot m+1 (ascending
   molecule IDs) through its wall since the fix was defined (negative: lost)
------------------------------------------------------------------------- */

double FixCellFluid::compute_vector(int m)
{
  return books.total(m + 1, world);
}

/* ----------------------------------------------------------------------
   array row m: the cell in slot m+1, as of the last step's exchange:
   1 molecule ID, 2 water (fluid mass) W, 3 osmotic potential Pi,
   4 water potential psi = mean P + Pi, 5 exposed wall area, 6 glued wall
   area (current), 7 W0 of Eq. W1
------------------------------------------------------------------------- */

double FixCellFluid::compute_array(int row, int col)
{
  const int m = row + 1;
  if (m < 1 || m > ncells || sums.size() <= m) return 0.0;
  switch (col) {
    case 0:
      return (double) cells.id(m);
    case 1:
      return sums[m].mass;
    case 2:
      return water.pinow[m];
    case 3:
      return water.psi[m];
    case 4:
      return water.exposed[m];
    case 5:
      return sums[m].area - water.exposed[m];
    case 6:
      return books.water0[m];
  }
  return 0.0;
}

/* ----------------------------------------------------------------------
   restart: the books (cell_uptake.h)
------------------------------------------------------------------------- */

void FixCellFluid::write_restart(FILE *fp)
{
  books.write(fp, cells, comm->me, world);
}

void FixCellFluid::restart(char *buf)
{
  // no release wrote another format: those of development versions are not read
  if (!books.read((double *) buf))
    error->all(FLERR,
               "Fix cell/fluid {}: the restart file holds this fix's uptake totals in an older "
               "format that is no longer read; continue from a restart file written by this "
               "version, or define the fix with another ID to start the totals from zero",
               id);
}
