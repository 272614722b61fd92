/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the sums per cell shared by fix cell/fluid and compute
   cell/props (cell_sums.h)
------------------------------------------------------------------------- */

#include "cell_sums.h"

#include "atom.h"
#include "cell_index.h"
#include "pair_cell_sph.h"

using namespace LAMMPS_NS;

namespace CellMech {

void CellSums::add_fluid(LAMMPS *lmp, const PairCellSPH *sph, const CellIndex &cells, int groupbit)
{
  Atom *atom = lmp->atom;
  const double *rho = sph->rho_array();
  const double *rmass = atom->rmass;
  const int *type = atom->type;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    const int m = cells.slot(atom->molecule[i]);
    if (m < 1 || !sph->is_fluid(type[i]) || !(mask[i] & groupbit)) continue;
    CellSum &s = sums[m];
    s.nfluid += 1.0;
    s.mass += rmass[i];
    const double P = sph->pressure(type[i], rho[i]);
    const double dPdrho = sph->dpressure_drho(type[i], rho[i]);
    s.pressure += P;
    // dP_i/dM of the cell when a mass dM is spread evenly (N dm_i = dM, Eq. 9 at fixed volume)
    s.stiffness += dPdrho * rho[i] / rmass[i];
    s.density += rho[i];
    const double V = rmass[i] / rho[i];
    s.fluid_volume += V;
    s.volume_pressure += P * V;
    s.volume_stiffness += dPdrho * V;
  }
}

void CellSums::add_broken_tethers(LAMMPS *lmp, const CellIndex &cells, const double *nbroken)
{
  if (!nbroken) return;
  // each broken tether is counted at both of its nodes
  for (int i = 0; i < lmp->atom->nlocal; i++) {
    const int m = cells.slot(lmp->atom->molecule[i]);
    if (m >= 1) sums[m].broken += 0.5 * nbroken[i];
  }
}

void CellSums::reduce(MPI_Comm world)
{
  const int count = (int) (sums.size() * sizeof(CellSum) / sizeof(double));
  MPI_Allreduce(MPI_IN_PLACE, sums.data(), count, MPI_DOUBLE, MPI_SUM, world);
}

}    // namespace CellMech
