/* ----------------------------------------------------------------------
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

#include "bond_cell_tether.h"
#include "compute_cell_props.h"
#include "compute_cell_shear_atom.h"
#include "fix_cell_fluid.h"
#include "fix_cell_vtk.h"
#include "pair_cell_lj84.h"
#include "pair_cell_sph.h"
#include "pair_cell_virtual.h"

using namespace LAMMPS_NS;

static Bond *bond_cell_tether_creator(LAMMPS *lmp)
{
  return new BondCellTether(lmp);
}

static Pair *pair_cell_lj84_creator(LAMMPS *lmp)
{
  return new PairCellLJ84(lmp);
}

static Pair *pair_cell_sph_creator(LAMMPS *lmp)
{
  return new PairCellSPH(lmp);
}

static Pair *pair_cell_virtual_creator(LAMMPS *lmp)
{
  return new PairCellVirtual(lmp);
}

static Fix *fix_cell_fluid_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixCellFluid(lmp, argc, argv);
}

static Fix *fix_cell_vtk_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixCellVTK(lmp, argc, argv);
}

static Compute *compute_cell_props_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new ComputeCellProps(lmp, argc, argv);
}

static Compute *compute_cell_shear_atom_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new ComputeCellShearAtom(lmp, argc, argv);
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

  plugin.style = "bond";
  plugin.name = "cell/tether";
  plugin.info = "cellmech Neo-Hookean cell wall tether";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &bond_cell_tether_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "pair";
  plugin.name = "cell/lj84";
  plugin.info = "cellmech 8-4 excluded-volume repulsion with contact damping";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &pair_cell_lj84_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "cell/sph";
  plugin.info = "cellmech SPH protoplasm (Tait, Morris viscosity, continuity)";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &pair_cell_sph_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "cell/virtual";
  plugin.info = "cellmech virtual particles at the wall triangles' barycentres";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &pair_cell_virtual_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "cell/fluid";
  plugin.info = "cellmech density and osmotic mass integration of the protoplasm";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_cell_fluid_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "cell/vtk";
  plugin.info = "cellmech cell walls as VTK triangulated surfaces for ParaView";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_cell_vtk_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "compute";
  plugin.name = "cell/props";
  plugin.info = "cellmech per-cell volume, area, pressure, stretch, equatorial force, leaks";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &compute_cell_props_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "cell/shear/atom";
  plugin.info = "cellmech per-particle protoplasm shear stress (Eqs. 24-26)";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &compute_cell_shear_atom_creator;
  (*register_plugin)(&plugin, lmp);
}
