/* -*- c++ -*- ----------------------------------------------------------
   cellmech: check that the LAMMPS loading this plugin is the one it was
   built against. LAMMPS itself only warns on a version mismatch and does
   not check integer sizes or MPI at all; a mismatch there corrupts memory.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_COMPAT_H
#define CELLMECH_CELL_COMPAT_H

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace CellMech {

// What this plugin was compiled with.
struct BuildSignature {
  std::string version;             // LAMMPS_VERSION string, e.g. "4 Feb 2025"
  int bigint, tagint, imageint;    // sizeof() of LAMMPS integer types
  std::string mpi_vendor;          // as LAMMPS's platform::mpi_vendor() spells it
  int mpi_major;                   // MPI standard version of the mpi.h used
};

BuildSignature compiled_signature();
// Empty string when the running LAMMPS matches; otherwise one line per difference.
std::string compat_mismatch(LAMMPS_NS::LAMMPS *lmp, const BuildSignature &built);

}    // namespace CellMech

#endif
