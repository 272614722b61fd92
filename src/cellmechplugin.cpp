/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the plugin entry point. All styles of the package register
   here, after a check that the LAMMPS loading us is the one we were built
   against (LAMMPS only warns on version mismatch and does not compare
   integer sizes or MPI, which corrupts memory silently).
------------------------------------------------------------------------- */

#include "lammpsplugin.h"

#include "cell_compat.h"
#include "error.h"
#include "lammps.h"
#include "version.h"

#include "angle_cell_membrane.h"
#include "bond_cell_lamella.h"
#include "bond_cell_tether.h"
#include "compute_cell_contacts.h"
#include "compute_cell_props.h"
#include "compute_cell_shear_atom.h"
#include "dihedral_cell_bending.h"
#include "fix_cell_fluid.h"
#include "fix_cell_lamella_break.h"
#include "fix_cell_plates.h"
#include "fix_cell_tether_break.h"
#include "fix_cell_vtk.h"
#include "pair_cell_lj84.h"
#include "pair_cell_sph.h"
#include "pair_cell_virtual.h"

using namespace LAMMPS_NS;

// LAMMPS stores the object behind a void * and uses it as its style base class: return that base
template <class Base, class T> static void *create(void *lmp)
{
  return static_cast<Base *>(new T((LAMMPS *) lmp));
}

template <class Base, class T> static void *create(void *lmp, int argc, char **argv)
{
  return static_cast<Base *>(new T((LAMMPS *) lmp, argc, argv));
}

extern "C" void lammpsplugin_init(void *ptr, void *handle, void *regfunc)
{
  auto lmp = (LAMMPS *) ptr;
  const auto built = CellMech::compiled_signature();
  const std::string why = CellMech::compat_mismatch(lmp, built);
  if (!why.empty()) {
    // Refuse to register anything: a style compiled for other type sizes would corrupt memory.
    if (lmp->error)
      lmp->error->warning(FLERR,
                          "cellmech plugin NOT loaded: it was built for a different LAMMPS:\n{}"
                          "Rebuild the plugin against this LAMMPS (tools/setup.sh, or cmake "
                          "-DLAMMPS_SOURCE_DIR=... -DLAMMPS_BINARY_DIR=...).",
                          why);
    return;
  }

  lammpsplugin_t plugin;
  auto register_plugin = (lammpsplugin_regfunc) regfunc;
  plugin.version = LAMMPS_VERSION;
  plugin.author = "cellmech developers";
  plugin.handle = handle;

  // pair, bond, angle, dihedral: constructed from LAMMPS alone (v1); fix, compute: with their
  // arguments (v2)
  struct {
    const char *style, *name, *info;
    lammpsplugin_factory1 *v1;
    lammpsplugin_factory2 *v2;
  } styles[] = {
      {"angle", "cell/membrane", "cellmech Neo-Hookean membrane element on each wall triangle",
       &create<Angle, AngleCellMembrane>, nullptr},
      {"dihedral", "cell/bending", "cellmech bending stiffness of the wall: a hinge per wall edge",
       &create<Dihedral, DihedralCellBending>, nullptr},
      {"bond", "cell/tether", "cellmech Neo-Hookean cell wall tether",
       &create<Bond, BondCellTether>, nullptr},
      {"bond", "cell/lamella", "cellmech middle lamella: cohesive bond between cells",
       &create<Bond, BondCellLamella>, nullptr},
      {"pair", "cell/lj84", "cellmech 8-4 excluded-volume repulsion with contact damping",
       &create<Pair, PairCellLJ84>, nullptr},
      {"pair", "cell/sph", "cellmech SPH protoplasm (Tait, Morris viscosity, continuity)",
       &create<Pair, PairCellSPH>, nullptr},
      {"pair", "cell/virtual", "cellmech virtual particles at the wall triangles' barycentres",
       &create<Pair, PairCellVirtual>, nullptr},
      {"fix", "cell/fluid", "cellmech density and osmotic mass integration of the protoplasm",
       nullptr, &create<Fix, FixCellFluid>},
      {"fix", "CELL_TETHER_BREAK", "cellmech bookkeeping of broken tethers (internal)", nullptr,
       &create<Fix, FixCellTetherBreak>},
      {"fix", "CELL_LAMELLA_BREAK", "cellmech bookkeeping of debonded lamella bonds (internal)",
       nullptr, &create<Fix, FixCellLamellaBreak>},
      {"fix", "cell/plates",
       "cellmech plates (fix wall/harmonic whose force under respa is the inner steps' mean)",
       nullptr, &create<Fix, FixCellPlates>},
      {"fix", "cell/vtk", "cellmech cell walls as VTK triangulated surfaces for ParaView", nullptr,
       &create<Fix, FixCellVTK>},
      {"compute", "cell/props",
       "cellmech per-cell volume, area, pressure, stretch, equatorial force, leaks", nullptr,
       &create<Compute, ComputeCellProps>},
      {"compute", "cell/shear/atom", "cellmech per-particle protoplasm shear stress (Eqs. 24-26)",
       nullptr, &create<Compute, ComputeCellShearAtom>},
      {"compute", "cell/contacts",
       "cellmech per-cell-pair lamella bonds, contact force and area of a tissue", nullptr,
       &create<Compute, ComputeCellContacts>},
  };
  for (auto &st : styles) {
    plugin.style = st.style;
    plugin.name = st.name;
    plugin.info = st.info;
    if (st.v1)
      plugin.creator.v1 = st.v1;
    else
      plugin.creator.v2 = st.v2;
    (*register_plugin)(&plugin, lmp);
  }
}
