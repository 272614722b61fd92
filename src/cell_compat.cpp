/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: plugin/LAMMPS compatibility check (see cell_compat.h)
------------------------------------------------------------------------- */

#include "cell_compat.h"

#include "error.h"
#include "force.h"
#include "lammps.h"
#include "update.h"
#include "library.h"
#include "lmptype.h"
#include "platform.h"
#include "version.h"

#include <mpi.h>

using namespace LAMMPS_NS;

namespace CellMech {

// Same macro chain as platform::mpi_vendor(), but evaluated with the mpi.h of this plugin.
static const char *compiled_mpi_vendor()
{
#if defined(MPI_STUBS)
  return "MPI STUBS";
#elif defined(OPEN_MPI)
  return "Open MPI";
#elif defined(MPICH_NAME)
  return "MPICH";
#elif defined(I_MPI_VERSION)
  return "Intel MPI";
#else
  return "Unknown MPI implementation";
#endif
}

BuildSignature compiled_signature()
{
#ifdef CELLMECH_FAKE_LAMMPS_VERSION
  // only for the test that proves the guard refuses a foreign LAMMPS
  const char *version = CELLMECH_FAKE_LAMMPS_VERSION;
#else
  const char *version = LAMMPS_VERSION;
#endif
  return {version,
          (int) sizeof(bigint),
          (int) sizeof(tagint),
          (int) sizeof(imageint),
          compiled_mpi_vendor(),
          MPI_VERSION};
}

std::string compat_mismatch(LAMMPS *lmp, const BuildSignature &built)
{
  std::string why;
  if (built.version != lmp->version)
    why += "  LAMMPS version: plugin built for '" + built.version + "', running '" + lmp->version +
        "'\n";
  struct {
    const char *name;
    int built;
  } sizes[] = {{"bigint", built.bigint}, {"tagint", built.tagint}, {"imageint", built.imageint}};
  for (auto &s : sizes) {
    int running = lammps_extract_setting(lmp, s.name);
    if (running != s.built)
      why += "  integer size of " + std::string(s.name) + ": plugin " + std::to_string(s.built) +
          " bytes, LAMMPS " + std::to_string(running) +
          " bytes (LAMMPS_SIZES smallsmall/smallbig/bigbig differ)\n";
  }
  if (!lammps_config_has_mpi_support())
    why += "  MPI: plugin built with " + built.mpi_vendor + ", LAMMPS built without MPI (STUBS)\n";
  else if (platform::mpi_vendor() != built.mpi_vendor)
    why += "  MPI: plugin built with " + built.mpi_vendor + ", LAMMPS built with " +
        platform::mpi_vendor() + "\n";
  int major = 0, minor = 0;
  platform::mpi_info(major, minor);
  if (major != built.mpi_major)
    why += "  MPI standard: plugin " + std::to_string(built.mpi_major) + ", LAMMPS " +
        std::to_string(major) + "\n";
  return why;
}

void require_unit_consistency(LAMMPS *lmp, const std::string &style)
{
  const Force *force = lmp->force;
  if (force->ftm2v != 1.0 || force->nktv2p != 1.0 || force->mvv2e != 1.0)
    lmp->error->all(FLERR,
                    "{} does not support units {}: the cell model applies no unit conversion "
                    "(ftm2v {:.6g}, nktv2p {:.6g}, mvv2e {:.6g}, all must be 1); use units micro "
                    "(the model's parameters are given in it), or nano, si, cgs",
                    style, lmp->update->unit_style, force->ftm2v, force->nktv2p, force->mvv2e);
}

}    // namespace CellMech
