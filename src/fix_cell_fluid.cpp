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
#include "cell_mpi.h"
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
#include <fstream>
#include <sstream>

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace CellPhysics;

namespace {
enum { EXT_PSI, EXT_FLUX };
enum { EXPOSE_OUTSIDE, EXPOSE_UNGLUED };
// default of exposed outside, in Angstrom (10 um): wider than the voids at the rounded edges and
// corners of a cellgen.py tissue (8 um would do at rest, unglued), so that a cell with no free face
// has no exposed wall (docs/fix_cell_fluid.rst, *The outside*)
constexpr double EXPOSE_DEPTH_ANGSTROM = 1.0e5;
constexpr int NCOLS = 7;    // compute_array columns
// restart tag of the format (tag, ncells, then ID, uptake, W0 per cell): not an integer, so it
// cannot be mistaken for the cell count that opens the two earlier formats
constexpr double RESTART_TAG = -0.5;
}    // namespace

/* ----------------------------------------------------------------------
   fix ID group cell/fluid Pi value Lp value [keyword args ...]
     cell M Pi value Lp value | cells file | solute yes/no | exchange yes/no
     | external psi value | external flux value
------------------------------------------------------------------------- */

FixCellFluid::FixCellFluid(LAMMPS *_lmp, int narg, char **arg) :
    Fix(_lmp, narg, arg), Pi(0.0), Lp(0.0), solute(0), exchange(0), external(EXT_PSI),
    ext_value(0.0), expose(EXPOSE_OUTSIDE), expose_depth(EXPOSE_DEPTH_ANGSTROM * force->angstrom),
    dt(0.0), ilevel_respa(0), ncells(0), area(nullptr), nfluid(nullptr), nbroken(nullptr),
    flux_local(nullptr), flux_all(nullptr), flux_stale(1), sph(nullptr), iref(-1), ialam(-1)
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
  parse_keyword(2, &arg[3]);
  parse_keyword(2, &arg[5]);
  for (int iarg = 7; iarg < narg;) iarg += parse_keyword(narg - iarg, &arg[iarg]);
  in_command = false;
  given.clear();
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
   fix_modify ID keyword args: the fix's keywords, between runs (inflation
   with a large Lp first, then a drying series of external psi values)
------------------------------------------------------------------------- */

int FixCellFluid::modify_param(int narg, char **arg)
{
  // one keyword per call: LAMMPS's fix_modify passes what it does not know itself
  return parse_keyword(narg, arg);
}

namespace {
// utils::numeric's own error would not say which keyword, file or line the text came from
void require_number(LAMMPS *lmp, const char *text, const std::string &name)
{
  if (!utils::is_double(text))
    lmp->error->all(FLERR, "fix cell/fluid: {} must be a number, got '{}'", name, text);
}

double osmotic_value(LAMMPS *lmp, const char *text, const std::string &what)
{
  require_number(lmp, text, "osmotic potential Pi" + what);
  const double Pi = utils::numeric(FLERR, text, false, lmp);
  if (Pi > 0.0)
    lmp->error->all(FLERR,
                    "fix cell/fluid: osmotic potential Pi{} must be <= 0 (water potential), got {}",
                    what, Pi);
  CellMech::require_magnitude(lmp, "fix cell/fluid", "osmotic potential Pi", Pi);
  return Pi;
}

double conductivity_value(LAMMPS *lmp, const char *text, const std::string &what)
{
  require_number(lmp, text, "hydraulic conductivity Lp" + what);
  const double Lp = utils::numeric(FLERR, text, false, lmp);
  if (Lp < 0.0)
    lmp->error->all(FLERR, "fix cell/fluid: hydraulic conductivity Lp{} must be >= 0, got {}", what,
                    Lp);
  CellMech::require_magnitude(lmp, "fix cell/fluid", "hydraulic conductivity Lp", Lp);
  return Lp;
}

tagint cell_id(LAMMPS *lmp, const char *text, const std::string &where)
{
  if (!utils::is_integer(text))
    lmp->error->all(FLERR,
                    "fix cell/fluid {}: the cell (molecule ID) must be an integer >= 1, got '{}'",
                    where, text);
  const tagint m = utils::tnumeric(FLERR, text, false, lmp);
  if (m < 1)
    lmp->error->all(FLERR, "fix cell/fluid {}: the cell (molecule ID) must be >= 1, got {}", where,
                    text);
  return m;
}
}    // namespace

// one keyword and its arguments; returns how many words it took. In the fix command a keyword
// other than cell and cells (which add up, cell by cell) may come once: a second one would
// silently replace the first (external psi, then external flux, ran with the flux only).
// fix_modify changes them between runs, so there the last one counts.
int FixCellFluid::parse_keyword(int narg, char **arg)
{
  const int n = parse_one(narg, arg);
  const std::string key = arg[0];
  if (in_command && key != "cell" && key != "cells") {
    std::string words = key;
    for (int k = 1; k < n; k++) words += std::string(" ") + arg[k];
    auto it = given.find(key);
    if (it != given.end())
      error->all(FLERR,
                 "fix cell/fluid: keyword '{}' given twice, '{}' and '{}': give it once "
                 "(fix_modify changes it between runs)",
                 key, it->second, words);
    given[key] = words;
  }
  return n;
}

int FixCellFluid::parse_one(int narg, char **arg)
{
  const std::string key = arg[0];
  auto need = [&](int n, const char *form) {
    if (narg < n)
      error->all(FLERR, "fix cell/fluid: keyword '{}' needs {} argument(s): '{}', got {}", key,
                 n - 1, form, narg - 1);
  };
  if (key == "Pi") {
    need(2, "Pi value");
    Pi = osmotic_value(lmp, arg[1], "");
    return 2;
  }
  if (key == "Lp") {
    need(2, "Lp value");
    Lp = conductivity_value(lmp, arg[1], "");
    return 2;
  }
  if (key == "cell") {
    // cell M followed by Pi value and/or Lp value: unset ones stay the fix's own
    need(4, "cell M Pi value Lp value");
    const tagint m = cell_id(lmp, arg[1], "cell");
    const std::string what = fmt::format(" of cell {}", m);
    auto it = percell.find(m);
    std::pair<double, double> v = it == percell.end() ? std::make_pair(double(NAN), double(NAN))
                                                      : it->second;
    int n = 2;
    while (n + 1 < narg && (strcmp(arg[n], "Pi") == 0 || strcmp(arg[n], "Lp") == 0)) {
      if (arg[n][0] == 'P')
        v.first = osmotic_value(lmp, arg[n + 1], what);
      else
        v.second = conductivity_value(lmp, arg[n + 1], what);
      n += 2;
    }
    if (n == 2)
      error->all(FLERR,
                 "fix cell/fluid: keyword 'cell {}' expects 'Pi value' and/or 'Lp value', got '{}'",
                 arg[1], arg[2]);
    percell[m] = v;
    return n;
  }
  if (key == "cells") {
    // a file of lines 'M Pi Lp' (molecule ID, osmotic potential, conductivity); # starts a comment
    need(2, "cells file");
    std::ifstream in(arg[1]);
    if (!in)
      error->all(FLERR, "fix cell/fluid cells: cannot open file '{}': {}", arg[1],
                 utils::getsyserror());
    std::string line;
    int lineno = 0, entries = 0;
    while (std::getline(in, line)) {
      lineno++;
      line = utils::trim_comment(line);
      auto words = utils::split_words(line);
      if (words.empty()) continue;
      const std::string where = fmt::format("cells file '{}' line {}", arg[1], lineno);
      if (words.size() != 3)
        error->all(FLERR, "fix cell/fluid {}: expected 'M Pi Lp' (3 numbers), got '{}'", where,
                   line);
      const std::string what = fmt::format(" in {}", where);
      const tagint m = cell_id(lmp, words[0].c_str(), where);
      percell[m] = {osmotic_value(lmp, words[1].c_str(), what),
                    conductivity_value(lmp, words[2].c_str(), what)};
      entries++;
    }
    // an empty file (the wrong one, or a generator that wrote nothing) would leave every cell at
    // the fix's Pi and Lp without a word
    if (entries == 0)
      error->all(FLERR,
                 "fix cell/fluid cells: file '{}' has no 'M Pi Lp' line ({} lines, all blank or "
                 "comments); give the cells' values or leave out the keyword",
                 arg[1], lineno);
    return 2;
  }
  if (key == "solute" || key == "exchange") {
    need(2, (key + " yes/no").c_str());
    (key == "solute" ? solute : exchange) = utils::logical(FLERR, arg[1], false, lmp);
    return 2;
  }
  if (key == "external") {
    need(3, "external psi value' or 'external flux value");
    if (strcmp(arg[1], "psi") == 0)
      external = EXT_PSI;
    else if (strcmp(arg[1], "flux") == 0)
      external = EXT_FLUX;
    else
      error->all(FLERR, "fix cell/fluid: keyword 'external' expects 'psi' or 'flux', got '{}'",
                 arg[1]);
    require_number(lmp, arg[2], fmt::format("the value of 'external {}'", arg[1]));
    ext_value = utils::numeric(FLERR, arg[2], false, lmp);
    if (ext_value != 0.0)
      CellMech::require_magnitude(lmp, "fix cell/fluid", "external value", ext_value);
    return 3;
  }
  if (key == "exposed") {
    need(2, "exposed outside D' or 'exposed unglued");
    if (strcmp(arg[1], "unglued") == 0) {
      expose = EXPOSE_UNGLUED;
      return 2;
    }
    if (strcmp(arg[1], "outside") != 0)
      error->all(FLERR,
                 "fix cell/fluid: keyword 'exposed' expects 'outside D' or 'unglued', got '{}'",
                 arg[1]);
    need(3, "exposed outside D");
    require_number(lmp, arg[2], "the distance D of 'exposed outside'");
    const double D = utils::numeric(FLERR, arg[2], false, lmp);
    if (D <= 0.0)
      error->all(FLERR, "fix cell/fluid: the distance D of 'exposed outside' must be > 0, got {}",
                 arg[2]);
    CellMech::require_magnitude(lmp, "fix cell/fluid", "exposed distance", D);
    expose = EXPOSE_OUTSIDE;
    expose_depth = D;
    depth_given = true;
    return 3;
  }
  error->all(FLERR,
             "Unknown keyword '{}' for fix cell/fluid: expected Pi, Lp, cell, cells, solute, "
             "exchange, external or exposed",
             key);
  return 0;
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
  if (active() && (!atom->nangles || !force->angle))
    error->all(FLERR,
               "Fix cell/fluid with Lp > 0 or an external flux needs the wall triangles as angles "
               "and an angle style (angle_style zero nocoeff) to measure the cell area");
  int flag, cols;
  iref = atom->find_custom(CellMech::REF_FIELD, flag, cols);
  if (iref >= 0 && (flag != 1 || cols != 3)) iref = -1;
  ialam = atom->find_custom(CellMech::AREA_FIELD, flag, cols);
  if (ialam >= 0 && (flag != 1 || cols != 0)) ialam = -1;
  // the shared wall is the lamella's area (d_alam) on the rest shape (d2_cellref) of the walls
  if (exchange && (iref < 0 || ialam < 0))
    error->all(FLERR,
               "Fix cell/fluid {} exchange yes needs the per-atom fields d2_cellref (rest shape of "
               "the walls) and d_alam (lamella area) of fix property/atom, as cellgen.py tissue "
               "writes them; missing: {}",
               id, iref < 0 ? (ialam < 0 ? "both" : "d2_cellref") : "d_alam");
  dt = update->dt;
  ilevel_respa = 0;
  if (utils::strmatch(update->integrate_style, "^respa")) {
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
  // exposed outside looks for other cells' walls up to expose_depth from a triangle: they must be
  // here as ghosts on every rank, as pair styles raise the cutoff for what they need (tip4p)
  if (exchange && expose == EXPOSE_OUTSIDE && active()) {
    // the default is a length in um; reduced units have no um to convert it from
    if (!depth_given && force->angstrom == 1.0 && strcmp(update->unit_style, "lj") == 0)
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
    if (have < expose_depth) {
      if (comm->me == 0)
        utils::logmesg(lmp,
                       "Fix cell/fluid {}: communication cutoff raised from {:.8} to {:.8}, the "
                       "distance of 'exposed outside'\n",
                       id, have, expose_depth);
      comm->cutghostuser = expose_depth;
    }
  }
  const int published = size_array_rows;
  index_cells();
  if (ncells != published && comm->me == 0 && !modify->get_fix_by_style("^ave/time").empty())
    error->warning(FLERR,
                   "Fix cell/fluid {}: the number of cells changed from {} to {} since the fix "
                   "was defined or last ran; a fix ave/time defined before now keeps the old "
                   "number of rows of f_{}",
                   id, published, ncells, id);
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
  if (cells.molecule_ids() == old && flux_restart.empty() && water0_restart.empty() && flux_local)
    return;
  const int n = cells.size();
  std::vector<double> flux(n + 1, 0.0), w0(n + 1, 0.0);
  for (int k = 1; k <= (int) old.size(); k++) {
    flux[cells.slot(old[k - 1])] += flux_local[k];
    w0[cells.slot(old[k - 1])] = water0[k];
  }
  // the restart's totals were kept on rank 0 only, so they are summed once
  if (comm->me == 0)
    for (const auto &kv : flux_restart) flux[cells.slot(kv.first)] += kv.second;
  for (const auto &kv : water0_restart) w0[cells.slot(kv.first)] = kv.second;
  flux_restart.clear();
  water0_restart.clear();
  flux[0] = 0.0;    // slot 0: IDs that left
  w0[0] = 0.0;
  water0 = w0;
  for (auto *v : {&pi0, &lp, &water, &pinow, &psi, &exposed, &glued, &open_area, &aref, &sump,
                  &sumstiff, &sumrho})
    v->assign(n + 1, 0.0);
  ncells = n;
  for (double **a : {&area, &nfluid, &nbroken, &flux_local, &flux_all}) {
    memory->destroy(*a);
    memory->create(*a, ncells + 1, "cell/fluid:percell");
  }
  for (int m = 0; m <= ncells; m++) flux_local[m] = flux[m];
  size_vector = ncells;
  size_array_rows = ncells;
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
  constexpr int NF = 9;
  std::vector<double> local(NF * n1, 0.0), all(NF * n1);
  double **ref = iref >= 0 ? atom->darray[iref] : nullptr;

  int **anglelist = neighbor->anglelist;
  const int nangle = neighbor->nanglelist;
  // a triangle's cell (that of its central node, contract: cell_fields.h) and rest area change
  // only with the angle list and the cell index (a build or a setup): found then, not each step
  if (CellMech::list_rebuilt(lmp, tri_build, tri_slot.size(), nangle)) {
    tri_slot.assign(nangle, 0);
    tri_aref.assign(nangle, 0.0);
    for (int n = 0; n < nangle; n++) {
      const int a = anglelist[n][0], b = anglelist[n][1], c = anglelist[n][2];
      tri_slot[n] = cells.slot(molecule[b]);
      if (!ref) continue;
      double u[3], w[3];
      for (int d = 0; d < 3; d++) {
        u[d] = ref[b][d] - ref[a][d];
        w[d] = ref[c][d] - ref[a][d];
      }
      tri_aref[n] = triangle_area(u, w);
    }
    // the triangles that face the outside, found where the ghosts are fresh: at the build
    tri_open.assign(nangle, 1);
    if (exchange && expose == EXPOSE_OUTSIDE) find_open_triangles();
  }
  for (int n = 0; n < nangle; n++) {
    if (anglelist[n][3] <= 0) continue;    // triangle of a broken wall
    const int m = tri_slot[n];
    if (m < 1) continue;
    const int a = anglelist[n][0], b = anglelist[n][1], c = anglelist[n][2];
    double u[3], w[3];
    for (int d = 0; d < 3; d++) {
      u[d] = x[b][d] - x[a][d];
      w[d] = x[c][d] - x[a][d];
    }
    const double A = triangle_area(u, w);
    local[m] += A;
    if (ref) local[3 * n1 + m] += tri_aref[n];
    if (tri_open[n]) local[8 * n1 + m] += A;
  }
  double *rho = sph->rho_array();
  double *rmass = atom->rmass;
  int *type = atom->type;
  for (int i = 0; i < atom->nlocal; i++) {
    const int m = cells.slot(molecule[i]);
    if (!(mask[i] & groupbit) || !sph->is_fluid(type[i]) || m < 1) continue;
    local[n1 + m] += 1.0;
    local[4 * n1 + m] += rmass[i];
    local[5 * n1 + m] += sph->pressure(type[i], rho[i]);
    // dP_i/dM of the cell when a mass dM is spread evenly (N dm_i = dM, Eq. 9 at fixed volume)
    local[6 * n1 + m] += sph->dpressure_drho(type[i], rho[i]) * rho[i] / rmass[i];
    local[7 * n1 + m] += rho[i];
  }
  // broken tethers, each counted at both of its nodes by fix CELL_TETHER_BREAK
  auto *broken = modify->get_fix_by_id(FixCellTetherBreak::ID);
  if (broken)
    for (int i = 0; i < atom->nlocal; i++) {
      const int m = cells.slot(molecule[i]);
      if (m >= 1) local[2 * n1 + m] += broken->vector_atom[i];
    }
  MPI_Allreduce(local.data(), all.data(), NF * n1, MPI_DOUBLE, MPI_SUM, world);
  for (int m = 0; m <= ncells; m++) {
    area[m] = all[m];
    nfluid[m] = all[n1 + m];
    nbroken[m] = all[2 * n1 + m];
    aref[m] = all[3 * n1 + m];
    water[m] = all[4 * n1 + m];
    sump[m] = all[5 * n1 + m];
    sumstiff[m] = all[6 * n1 + m];
    sumrho[m] = all[7 * n1 + m];
    open_area[m] = all[8 * n1 + m];
  }
}

/* ----------------------------------------------------------------------
   exposed outside (Eq. W4): a wall triangle faces the outside unless it is
   glued (two of its nodes hold intact lamella bonds: the cells' turgor
   peels glued faces up to the lamella's critical opening, 12 um in the
   coarse block, and they are no less glued) or a wall node of another
   cell lies in front of it (hides_triangle) within expose_depth of its
   central node (walls that touch or face each other across a narrow
   space, glued or not). The central node is owned (the rank that owns it
   lists the triangle) and, at a neighbour-list build, inside this rank's
   subdomain, so every node within expose_depth <= the ghost cutoff (init
   raises it) is here as an owned atom or a ghost: the same answer on any
   number of ranks. Evaluated at each build, with the ghosts just
   communicated; between builds the walls move less than the skin.
------------------------------------------------------------------------- */

void FixCellFluid::find_open_triangles()
{
  double **x = atom->x;
  tagint *molecule = atom->molecule;
  int *type = atom->type;
  const int nall = atom->nlocal + atom->nghost;
  const double D = expose_depth, D2 = D * D;

  // the nodes glued to another cell: their intact lamella bonds (in the bond list once, owned by
  // either node's rank), counted at both nodes and summed onto their owners, then sent to ghosts
  node_glued.assign(nall, 0.0);
  int **bondlist = neighbor->bondlist;
  for (int k = 0; k < neighbor->nbondlist; k++) {
    const int i1 = bondlist[k][0], i2 = bondlist[k][1];
    if (bondlist[k][2] <= 0 || molecule[i1] == molecule[i2]) continue;    // debonded or a tether
    node_glued[i1] += 1.0;
    node_glued[i2] += 1.0;
  }
  comm->reverse_comm(this);
  comm->forward_comm(this);

  // the wall nodes of all cells (a cell's atoms that are not fluid), binned in cubes of side D
  // (smaller bins, fewer nodes to test, cost more in bins visited: 2x the time at D/2)
  std::vector<int> node;
  double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {0.0, 0.0, 0.0};
  for (int j = 0; j < nall; j++) {
    if (molecule[j] < 1 || sph->is_fluid(type[j])) continue;
    for (int d = 0; d < 3; d++) {
      lo[d] = node.empty() ? x[j][d] : MIN(lo[d], x[j][d]);
      hi[d] = node.empty() ? x[j][d] : MAX(hi[d], x[j][d]);
    }
    node.push_back(j);
  }
  if (node.empty()) return;
  // larger bins where a far atom would make too many: at most about eight bins per node
  double side = D;
  const double cap = 8.0 * (double) node.size() + 64.0;
  while (((hi[0] - lo[0]) / side + 1.0) * ((hi[1] - lo[1]) / side + 1.0) *
             ((hi[2] - lo[2]) / side + 1.0) >
         cap)
    side *= 2.0;
  int nb[3];
  for (int d = 0; d < 3; d++) nb[d] = (int) ((hi[d] - lo[d]) / side) + 1;
  auto bin_of = [&](const double *p, int d) {
    const int k = (int) ((p[d] - lo[d]) / side);
    return k < 0 ? 0 : (k >= nb[d] ? nb[d] - 1 : k);
  };
  const int nbins = nb[0] * nb[1] * nb[2];
  std::vector<int> start(nbins + 1, 0), sorted(node.size());
  std::vector<int> where(node.size());
  for (size_t k = 0; k < node.size(); k++) {
    const double *p = x[node[k]];
    where[k] = (bin_of(p, 2) * nb[1] + bin_of(p, 1)) * nb[0] + bin_of(p, 0);
    start[where[k] + 1]++;
  }
  for (int b = 0; b < nbins; b++) start[b + 1] += start[b];
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (size_t k = 0; k < node.size(); k++) sorted[fill[where[k]]++] = node[k];
  }

  int **anglelist = neighbor->anglelist;
  const int nangle = neighbor->nanglelist;
  for (int n = 0; n < nangle; n++) {
    if (anglelist[n][3] <= 0 || tri_slot[n] < 1) continue;
    const int a = anglelist[n][0], b = anglelist[n][1], c = anglelist[n][2];
    // glued: two or three of its nodes hold lamella bonds (the glued region's rim runs through
    // triangles; the majority splits them about evenly between glued and not)
    if ((node_glued[a] > 0.0) + (node_glued[b] > 0.0) + (node_glued[c] > 0.0) >= 2) {
      tri_open[n] = 0;
      continue;
    }
    double u[3], w[3], v[3], nrm[3], cen[3];
    for (int d = 0; d < 3; d++) {
      u[d] = x[b][d] - x[a][d];
      w[d] = x[c][d] - x[a][d];
      v[d] = x[c][d] - x[b][d];
      cen[d] = (x[a][d] + x[b][d] + x[c][d]) / 3.0;
    }
    nrm[0] = u[1] * w[2] - u[2] * w[1];
    nrm[1] = u[2] * w[0] - u[0] * w[2];
    nrm[2] = u[0] * w[1] - u[1] * w[0];
    const double len = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (len == 0.0) continue;    // degenerate: no direction to face
    for (int d = 0; d < 3; d++) nrm[d] /= len;
    const double h = std::sqrt(
        MAX(MAX(u[0] * u[0] + u[1] * u[1] + u[2] * u[2], w[0] * w[0] + w[1] * w[1] + w[2] * w[2]),
            v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    const tagint own = molecule[b];
    int k0[3], k1[3];
    for (int d = 0; d < 3; d++) {
      double p[3] = {x[b][0], x[b][1], x[b][2]};
      p[d] = x[b][d] - D;
      k0[d] = bin_of(p, d);
      p[d] = x[b][d] + D;
      k1[d] = bin_of(p, d);
    }
    // another cell's wall in front of a triangle is mostly the glued neighbour's, a gap away
    // along the normal: its bin first, then every bin within D of the central node
    const double half = 0.5 * side, reach = D + std::sqrt(3.0) * half;
    auto hidden_in = [&](int bin) {
      for (int q = start[bin]; q < start[bin + 1]; q++) {
        const int j = sorted[q];
        if (molecule[j] == own) continue;
        double r[3], dc[3];
        for (int d = 0; d < 3; d++) {
          r[d] = x[j][d] - x[b][d];
          dc[d] = x[j][d] - cen[d];
        }
        if (r[0] * r[0] + r[1] * r[1] + r[2] * r[2] <= D2 && hides_triangle(dc, nrm, h))
          return true;
      }
      return false;
    };
    double p[3];
    for (int d = 0; d < 3; d++) p[d] = cen[d] + MIN(h, D) * nrm[d];
    const int first = (bin_of(p, 2) * nb[1] + bin_of(p, 1)) * nb[0] + bin_of(p, 0);
    bool hidden = hidden_in(first);
    for (int kz = k0[2]; kz <= k1[2] && !hidden; kz++)
      for (int ky = k0[1]; ky <= k1[1] && !hidden; ky++)
        for (int kx = k0[0]; kx <= k1[0] && !hidden; kx++) {
          const int bin = (kz * nb[1] + ky) * nb[0] + kx;
          if (bin == first) continue;
          // a bin wholly behind the triangle's plane or beyond D of its node holds no hider
          const double bc[3] = {lo[0] + (kx + 0.5) * side, lo[1] + (ky + 0.5) * side,
                                lo[2] + (kz + 0.5) * side};
          double sb = 0.0, rb = 0.0;
          for (int d = 0; d < 3; d++) {
            sb += (bc[d] - cen[d]) * nrm[d];
            rb += (bc[d] - x[b][d]) * (bc[d] - x[b][d]);
          }
          if (sb < -std::sqrt(3.0) * half || rb > reach * reach) continue;
          hidden = hidden_in(bin);
        }
    tri_open[n] = hidden ? 0 : 1;
  }
}

/* ----------------------------------------------------------------------
   the rest area of the intact lamella bonds between each pair of cells
   (slots a < b), summed over all ranks: the same list, in the same order,
   on every rank, so that every rank computes the same exchange
------------------------------------------------------------------------- */

void FixCellFluid::glued_pairs(std::vector<double> &pairs)
{
  std::map<std::pair<int, int>, double> local;
  const double *alam = atom->dvector[ialam];
  tagint *molecule = atom->molecule;
  int **bondlist = neighbor->bondlist;
  for (int n = 0; n < neighbor->nbondlist; n++) {
    const int i1 = bondlist[n][0], i2 = bondlist[n][1];
    if (bondlist[n][2] <= 0 || molecule[i1] == molecule[i2]) continue;    // debonded or a tether
    const int a = cells.slot(molecule[i1]), b = cells.slot(molecule[i2]);
    if (a < 1 || b < 1) continue;
    local[std::make_pair(MIN(a, b), MAX(a, b))] += CellMech::lamella_area(alam, i1, i2);
  }
  std::vector<double> mine;
  for (const auto &kv : local) {
    mine.push_back(kv.first.first);
    mine.push_back(kv.first.second);
    mine.push_back(kv.second);
  }
  const std::vector<double> gathered = CellMech::allgather_list(mine, MPI_DOUBLE, world);
  const int total = gathered.size();
  // summed in rank order into an ordered map: the same sums on every rank
  std::map<std::pair<int, int>, double> all;
  for (int k = 0; k < total; k += 3)
    all[std::make_pair((int) gathered[k], (int) gathered[k + 1])] += gathered[k + 2];
  pairs.clear();
  for (const auto &kv : all) {
    pairs.push_back(kv.first.first);
    pairs.push_back(kv.first.second);
    pairs.push_back(kv.second);
  }
}

/* ----------------------------------------------------------------------
   per cell: Pi0 and Lp (the fix's or the cell's own), then this step's
   osmotic potential (Eq. W1), water potential, glued and exposed area
------------------------------------------------------------------------- */

void FixCellFluid::cell_water()
{
  for (int m = 1; m <= ncells; m++) {
    auto it = percell.find(cells.id(m));
    pi0[m] = Pi;
    lp[m] = Lp;
    if (it != percell.end()) {
      if (!std::isnan(it->second.first)) pi0[m] = it->second.first;
      if (!std::isnan(it->second.second)) lp[m] = it->second.second;
    }
    pinow[m] = (solute && water0[m] > 0.0 && water[m] > 0.0)
        ? solute_osmotic_potential(pi0[m], water0[m], water[m])
        : pi0[m];
    psi[m] = nfluid[m] > 0 ? sump[m] / nfluid[m] + pinow[m] : pinow[m];
    glued[m] = 0.0;
  }
  pairs.clear();
  if (exchange) glued_pairs(pairs);
  for (size_t k = 0; k < pairs.size(); k += 3) {
    glued[(int) pairs[k]] += pairs[k + 2];
    glued[(int) pairs[k + 1]] += pairs[k + 2];
  }
  // without exchange every wall meets the outside whole, as the single cell of the paper
  for (int m = 1; m <= ncells; m++)
    exposed[m] = (exchange && expose == EXPOSE_OUTSIDE) ? open_area[m]
                                                        : exposed_area(area[m], aref[m], glued[m]);
}

// water moves through some wall: a conductivity > 0 or a set flux
bool FixCellFluid::active() const
{
  bool any = Lp > 0.0 || (external == EXT_FLUX && ext_value != 0.0);
  for (const auto &kv : percell) any = any || kv.second.second > 0.0;
  return any;
}

// dpsi/dM of cell m, for the linearised exchange step: its pressure and, with the solutes kept,
// its osmotic potential (dPi/dW = -Pi/W by Eq. W1)
double FixCellFluid::potential_stiffness(int m) const
{
  double s = sumstiff[m] / (nfluid[m] * nfluid[m]);
  if (solute && water[m] > 0.0) s -= pinow[m] / water[m];
  return s;
}

/* ---------------------------------------------------------------------- */

// at the start of a run the state is as given: nothing to advance, only cells to count
void FixCellFluid::setup_pre_force(int /*vflag*/)
{
  index_cells();
  cell_geometry();
  cell_water();
  // W0 of Eq. W1: the water of each cell when the fix first ran (or from the restart file)
  for (int m = 1; m <= ncells; m++)
    if (water0[m] == 0.0) water0[m] = water[m];
  cell_water();
  for (const auto &kv : percell) {
    const int m = cells.slot(kv.first);
    if (m < 1 || nfluid[m] == 0)
      error->all(FLERR,
                 "Fix cell/fluid {}: a per-cell setting names cell (molecule ID) {}, which holds "
                 "no fluid particles of group {}",
                 id, kv.first, group->names[igroup]);
  }
  check_walls();
}

// fluid of a molecule without wall triangles would have a wall area of 0 and take up or lose no
// water through it, without a word
void FixCellFluid::check_walls()
{
  const bool flux = external == EXT_FLUX && ext_value != 0.0;
  for (int m = 1; m <= ncells; m++)
    if (nfluid[m] > 0 && area[m] <= 0.0 && nbroken[m] == 0.0 && (lp[m] > 0.0 || flux))
      error->all(FLERR,
                 "Fix cell/fluid {}: cell (molecule ID) {} holds {} fluid particle(s) of group {} "
                 "but no wall triangles (angles whose central node has that molecule ID), so its "
                 "wall area is 0 and no water would cross it; give the fluid the molecule ID of "
                 "its cell's wall (or, without an external flux, 'cell {} Lp 0' to keep it closed)",
                 id, cells.id(m), (bigint) nfluid[m], group->names[igroup], cells.id(m));
}

void FixCellFluid::pre_force(int /*vflag*/)
{
  // atoms change ranks or leave only when LAMMPS re-neighbors
  if (neighbor->ago == 0) index_cells();
  sph->continuity();
  const bool osmosis = active();
  std::vector<double> uptake(ncells + 1, 0.0);    // per cell: from its neighbours, this step
  if (osmosis) {
    cell_geometry();
    cell_water();
    for (size_t k = 0; k < pairs.size(); k += 3) {
      const int a = (int) pairs[k], b = (int) pairs[k + 1];
      // a wall without triangles has no area to share (and no stretch to scale it by)
      if (nfluid[a] == 0 || nfluid[b] == 0 || nbroken[a] > 0.0 || nbroken[b] > 0.0 ||
          aref[a] <= 0.0 || aref[b] <= 0.0)
        continue;
      const double Lab = series_conductivity(lp[a], lp[b]);
      if (Lab == 0.0) continue;
      // the glued rest area at the walls' mean areal stretch; the mean density of the two
      const double Aab = pairs[k + 2] * 0.5 * (area[a] / aref[a] + area[b] / aref[b]);
      const double rho = 0.5 * (sumrho[a] / nfluid[a] + sumrho[b] / nfluid[b]);
      const double dM = exchange_mass_step(Aab * Lab * rho, dt, psi[a], psi[b],
                                           potential_stiffness(a), potential_stiffness(b));
      uptake[a] -= dM;
      uptake[b] += dM;
    }
  }

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
      // the outside through the exposed wall (the whole wall unless exchange yes)
      if (external == EXT_FLUX) {
        dm = -ext_value * exposed[m] * dt / nfluid[m];
      } else if (lp[m] > 0.0) {
        const double P = sph->pressure(type[i], rho[i]);
        const double k = osmotic_coefficient(exposed[m], lp[m], rho[i], nfluid[m]);
        double dPdrho = sph->dpressure_drho(type[i], rho[i]);
        // kept solutes: the step's uptake dm on each of the N_f particles also raises Pi by
        // -Pi N_f dm / W (Eq. W1), a stiffness that adds to the pressure's
        if (solute && water[m] > 0.0) dPdrho -= pinow[m] * nfluid[m] / water[m] * rmass[i] / rho[i];
        dm = osmotic_mass_step(k, dt, P, pinow[m] - ext_value, dPdrho, rho[i], rmass[i]);
      }
      dm += uptake[m] / nfluid[m];
      if (rmass[i] + dm <= 0.0)
        error->one(FLERR,
                   "Fix cell/fluid {}: fluid particle {} of cell {} would lose all its mass "
                   "({} + {}) this step: the cell has dried out (external flux or potential too "
                   "strong for its water)",
                   id, atom->tag[i], molecule[i], rmass[i], dm);
      flux_local[m] += dm;
      flux_stale = 1;
    }
    rho[i] += density_increment(rho[i], rmass[i], rate, dt, dm);
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
  if (flux_stale) {
    MPI_Allreduce(flux_local, flux_all, ncells + 1, MPI_DOUBLE, MPI_SUM, world);
    flux_stale = 0;
  }
  return flux_all[m + 1];
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
  if (m < 1 || m > ncells || (int) water.size() <= m) return 0.0;
  switch (col) {
    case 0:
      return (double) cells.id(m);
    case 1:
      return water[m];
    case 2:
      return pinow[m];
    case 3:
      return psi[m];
    case 4:
      return exposed[m];
    case 5:
      return area[m] - exposed[m];
    case 6:
      return water0[m];
  }
  return 0.0;
}

/* ----------------------------------------------------------------------
   restart: RESTART_TAG, ncells, then (molecule ID, uptake, W0) of each
   cell. Files of the earlier formats (-ncells, then (molecule ID, uptake);
   ncells, then the uptake of molecules 1..ncells) still read, their W0
   taken at the next run's start.
------------------------------------------------------------------------- */

void FixCellFluid::write_restart(FILE *fp)
{
  std::vector<double> sum(ncells + 1), list(2 + 3 * ncells);
  MPI_Allreduce(flux_local, sum.data(), ncells + 1, MPI_DOUBLE, MPI_SUM, world);
  list[0] = RESTART_TAG;
  list[1] = ncells;
  for (int m = 1; m <= ncells; m++) {
    list[3 * m - 1] = (double) cells.id(m);
    list[3 * m] = sum[m];
    list[3 * m + 1] = water0[m];
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
  water0_restart.clear();
  if (list[0] == RESTART_TAG) {
    const int n = (int) list[1];
    for (int m = 1; m <= n; m++) {
      flux_restart[(tagint) list[3 * m - 1]] += list[3 * m];
      water0_restart[(tagint) list[3 * m - 1]] = list[3 * m + 1];
    }
  } else if (list[0] < 0) {
    const int n = (int) -list[0];
    for (int m = 1; m <= n; m++) flux_restart[(tagint) list[2 * m - 1]] += list[2 * m];
  } else {
    const int n = (int) list[0];
    for (int m = 1; m <= n; m++) flux_restart[m] += list[m];
  }
}
