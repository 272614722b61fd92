/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: checks shared by the styles (see cell_checks.h)
------------------------------------------------------------------------- */

#include "cell_checks.h"

#include "bond_cell_lamella.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "fix_viscous.h"
#include "force.h"
#include "lammps.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "respa.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;

namespace CellMech {

void require_magnitude(LAMMPS *lmp, const std::string &command, const char *name, double value)
{
  const double a = std::fabs(value);
  if (value == 0.0 || (a >= 1.0 / MAX_MAGNITUDE && a <= MAX_MAGNITUDE)) return;
  lmp->error->all(FLERR,
                  "{}: {} = {} is outside what the model's arithmetic can carry: a non-zero "
                  "parameter must have a magnitude between {:g} and {:g} (the model squares and "
                  "raises to the 7th power, so beyond that a run overflows double precision to "
                  "NaN)",
                  command, name, value, 1.0 / MAX_MAGNITUDE, MAX_MAGNITUDE);
}

StepMotion fastest_step(LAMMPS *lmp, const int *atoms, int natoms)
{
  const Atom *atom = lmp->atom;
  const int n = atoms ? natoms : atom->nlocal;
  double vmax2 = 0.0;
  int imax = -1;
  for (int k = 0; k < n; k++) {
    const int i = atoms ? atoms[k] : k;
    const double *v = atom->v[i];
    const double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    // !(v2 <= vmax2) also catches a NaN velocity
    if (!(v2 <= vmax2)) {
      vmax2 = v2;
      imax = i;
    }
  }
  StepMotion m;
  if (imax < 0) return m;
  m.tag = (long) atom->tag[imax];
  m.index = imax;
  m.speed = std::sqrt(vmax2);
  m.dist = m.speed * lmp->update->dt;
  return m;
}

namespace {

  // fix viscous keeps its per-type drag protected and offers no extract(): a member pointer named
  // through a derived class reads it (the fix is never copied or changed)
  struct ViscousGamma : FixViscous {
    static const double *of(FixViscous *fix) { return fix->*(&ViscousGamma::gamma); }
  };

  // the largest gamma dt / (2 m) of the viscous fixes that act on atom i (ghost or local), with the
  // fix and its gamma; 0 if none acts on it
  struct Drag {
    double ratio = 0.0, gamma = 0.0;
    const char *fix = "";
  };

  Drag drag_on(LAMMPS *lmp, int i)
  {
    Drag d;
    const Atom *atom = lmp->atom;
    for (Fix *f : lmp->modify->get_fix_by_style("^viscous$")) {
      auto *fv = dynamic_cast<FixViscous *>(f);
      if (!fv || !(atom->mask[i] & fv->groupbit)) continue;
      const double g = ViscousGamma::of(fv)[atom->type[i]];
      const double r = g * lmp->update->dt / (2.0 * atom_mass(atom, i));
      if (!(r <= d.ratio)) {
        d.ratio = r;
        d.gamma = g;
        d.fix = fv->id;
      }
    }
    return d;
  }

  // the fluid's acoustic limit 0.25 s/c (the smallest over the fluid types of pair cell/sph), or 0
  // without a fluid
  struct Acoustic {
    double limit = 0.0, s = 0.0, c = 0.0;
  };

  Acoustic acoustic_limit(LAMMPS *lmp)
  {
    Acoustic a;
    Pair *sph = lmp->force->pair_match("cell/sph", 1);
    if (!sph) return a;
    int dim = 0;
    auto *c = (double *) sph->extract("c", dim);
    auto **s = (double **) sph->extract("s", dim);
    if (!c || !s) return a;
    for (int i = 1; i <= lmp->atom->ntypes; i++) {
      if (!(c[i] > 0.0) || !sph->setflag[i][i]) continue;    // not a fluid type
      const double lim = 0.25 * s[i][i] / c[i];
      if (a.limit == 0.0 || lim < a.limit) a = {lim, s[i][i], c[i]};
    }
    return a;
  }

}    // namespace

double atom_mass(const Atom *atom, int i)
{
  return atom->rmass ? atom->rmass[i] : atom->mass[atom->type[i]];
}

std::string timestep_hint(LAMMPS *lmp)
{
  std::string hint =
      "the cell inputs use the time step of the wall's level (tools/cellmech/params.py LEVELS: "
      "0.001 us at levels 3 and 4, 0.0005 us at level 5)";
  if (lmp->update->dt_default)
    hint +=
        fmt::format("; this run has the default time step of units {} ({:g}): did the input forget "
                    "'timestep'?",
                    lmp->update->unit_style, lmp->update->dt);
  return hint;
}

std::string blow_up_advice(LAMMPS *lmp, const StepMotion &m)
{
  if (!std::isfinite(m.speed))
    return fmt::format(
        "atom {} has a velocity that is not finite ({}): the run has gone to NaN or inf. The "
        "likely cause is a blow-up from a time step too large (the example inputs use 0.001 us) "
        "or a value set by hand that is not finite (a per-atom property, a velocity)",
        m.tag, m.speed);
  const double dt = lmp->update->dt;
  auto text = fmt::format("atom {} moved {:.4g} distance units in one step (speed {:.4g} x time "
                          "step {:g}), against a neighbor skin of {:g}: the run has blown up. ",
                          m.tag, m.dist, m.speed, dt, lmp->neighbor->skin);

  // the causes this package can tell apart, each against its own stability bound: the drag on
  // the atom that ran away, the stiffest lamella bond, the fluid's acoustic limit
  const Drag drag = m.index >= 0 ? drag_on(lmp, m.index) : Drag();
  if (drag.ratio >= 1.0) {
    const double mass = atom_mass(lmp->atom, m.index);
    return text +
        fmt::format("The likely cause is the drag of fix viscous {} on it: gamma dt = {:.4g} "
                    "against 2 x its mass = {:.4g}, so each step's drag overshoots and the "
                    "velocity grows; lower the drag below 2 m / dt = {:.4g} (the inputs' -var "
                    "drag) or the time step",
                    drag.fix, drag.gamma * dt, 2.0 * mass, 2.0 * mass / dt);
  }
  auto *lamella = dynamic_cast<BondCellLamella *>(lmp->force->bond_match("cell/lamella"));
  if (lamella && lamella->stiffest().omega_dt >= 1.0) {
    const auto st = lamella->stiffest();
    return text +
        fmt::format(
               "The likely cause is the middle lamella: its stiffest bond (type {}, "
               "critical opening delta_c = {:.4g}) has omega dt = {:.3g} at this time step, "
               "where velocity Verlet needs omega dt < 2 (less beside the tethers); raise its "
               "fracture energy Gc or lower its strength sigma_c (delta_c = Gc / (e sigma_c)), "
               "or the time step",
               st.type, st.delta_c, st.omega_dt);
  }
  const Acoustic ac = acoustic_limit(lmp);
  if (ac.limit > 0.0 && dt > ac.limit)
    return text +
        fmt::format("The likely cause is a time step {:.3g} times the fluid's acoustic limit "
                    "0.25 s/c = {:.4g} (s {:g}, c {:g}); {}; reduce the time step",
                    dt / ac.limit, ac.limit, ac.s, ac.c, timestep_hint(lmp));
  return text +
      "The likely cause is a time step too large for the stiffest part of the model (the "
      "fluid's acoustic limit 0.25 s/c, the tethers' period; the example inputs use 0.001 us), "
      "or particles that overlapped at the start; reduce the time step";
}

double bond_step(LAMMPS *lmp)
{
  auto *respa = dynamic_cast<Respa *>(lmp->update->integrate);
  if (!respa || !utils::strmatch(lmp->update->integrate_style, "^respa")) return lmp->update->dt;
  return respa->step[respa->level_bond];
}

bool will_step(LAMMPS *lmp)
{
  if (lmp->update->whichflag != 1 || lmp->update->nsteps == 0) return false;
  // without an integrator (a test of topology or forces alone) nothing moves
  for (const Fix *f : lmp->modify->get_fix_list())
    if (f->time_integrate) return true;
  return false;
}

void check_drag(LAMMPS *lmp)
{
  if (!will_step(lmp)) return;
  const Atom *atom = lmp->atom;
  MPI_Comm world = lmp->world;
  for (Fix *f : lmp->modify->get_fix_by_style("^viscous$")) {
    auto *fv = dynamic_cast<FixViscous *>(f);
    if (!fv) continue;
    const double *gamma = ViscousGamma::of(fv);
    struct {
      double ratio;
      int rank;
    } mine = {0.0, lmp->comm->me}, worst;
    int imax = -1;
    for (int i = 0; i < atom->nlocal; i++) {
      if (!(atom->mask[i] & fv->groupbit)) continue;
      const double r = gamma[atom->type[i]] * lmp->update->dt / (2.0 * atom_mass(atom, i));
      if (!(r <= mine.ratio)) {
        mine.ratio = r;
        imax = i;
      }
    }
    MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
    if (worst.ratio < 1.0) continue;
    // the atom, its gamma and mass from the rank that has it
    double info[3] = {0.0, 0.0, 0.0};
    if (worst.rank == lmp->comm->me && imax >= 0)
      info[0] = (double) atom->tag[imax], info[1] = gamma[atom->type[imax]],
      info[2] = atom_mass(atom, imax);
    MPI_Bcast(info, 3, MPI_DOUBLE, worst.rank, world);
    const double dt = lmp->update->dt;
    lmp->error->all(FLERR,
                    "Fix viscous {}: the drag gamma = {:g} on atom {} (mass {:.4g}) is more than "
                    "the time step {:g} can integrate: gamma dt = {:.4g} >= 2 x mass = {:.4g}, so "
                    "each step's drag overshoots and the velocities grow until the run blows up. "
                    "Use gamma < 2 m / dt = {:.4g} (the inputs' -var drag) or a smaller time step",
                    fv->id, info[1], (long) info[0], info[2], dt, info[1] * dt, 2.0 * info[2],
                    2.0 * info[2] / dt);
  }
}

void check_step_motion(LAMMPS *lmp, const std::string &style)
{
  // the setup of a run has made no step: its velocities may be anything (e.g. set by hand)
  const double skin = lmp->neighbor->skin;
  if (lmp->update->setupflag || !(skin > 0.0)) return;
  const StepMotion m = fastest_step(lmp);
  if (!(m.dist <= skin)) lmp->error->one(FLERR, "{}: {}", style, blow_up_advice(lmp, m));
}

}    // namespace CellMech
