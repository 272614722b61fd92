/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: check that the LAMMPS loading this plugin is the one it was
   built against. LAMMPS itself only warns on a version mismatch and does
   not check integer sizes or MPI at all; a mismatch there corrupts memory.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_COMPAT_H
#define CELLMECH_CELL_COMPAT_H

#include "domain.h"

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

// LAMMPS_VERSION_NUMBER (YYYYMMDD) is set by CMakeLists.txt from the LAMMPS tree's version.h.
#ifndef LAMMPS_VERSION_NUMBER
#error "LAMMPS_VERSION_NUMBER must be defined (CMakeLists.txt reads it from version.h)"
#endif

namespace CellMech {

// What this plugin was compiled with.
struct BuildSignature {
  std::string version;             // LAMMPS_VERSION string, e.g. "4 Feb 2025"
  int bigint, tagint, imageint;    // sizeof() of LAMMPS integer types
  std::string mpi_vendor;          // as LAMMPS's platform::mpi_vendor() spells it
  int mpi_major;                   // MPI standard version of the mpi.h used
};

BuildSignature compiled_signature();

// The styles compute forces, pressures and energies without LAMMPS's unit conversion factors, which
// is right only where those are 1 (units micro, nano, si, cgs, lj); any other unit style is an
// error naming the style.
void require_unit_consistency(LAMMPS_NS::LAMMPS *lmp, const std::string &style);

// Domain::minimum_image takes the caller's file and line since LAMMPS 12 Jun 2025 (lammps/lammps
// pull request 4610), for its error message; one call for every release:
// CellMech::minimum_image(domain, FLERR, dx, dy, dz).
inline void minimum_image(const LAMMPS_NS::Domain *domain, const char *file, int line, double &dx,
                          double &dy, double &dz)
{
#if LAMMPS_VERSION_NUMBER >= 20250612
  domain->minimum_image(file, line, dx, dy, dz);
#else
  (void) file;
  (void) line;
  domain->minimum_image(dx, dy, dz);
#endif
}
// Empty string when the running LAMMPS matches; otherwise one line per difference.
std::string compat_mismatch(LAMMPS_NS::LAMMPS *lmp, const BuildSignature &built);

}    // namespace CellMech

#endif
