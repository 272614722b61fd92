/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_observables.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: the paper's observables: the equatorial force (Eq. 23) and the protoplasm's shear
   stress (Eqs. 24-26).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_OBSERVABLES_H
#define CELLMECH_PHYSICS_OBSERVABLES_H

#include "vec3.h"

#include <cmath>

namespace CellPhysics {

/* ---------------------------------------------------------------------
   Observables of the paper
------------------------------------------------------------------------ */

// Equatorial force (Eq. 23): the internal force that the bonds crossing the plane through the
// cell centre carry from one hemisphere to the other. The hemisphere is the nodes at height
// s = (x - centre) . n > 0, so a node on the plane belongs to exactly one side.
inline bool crosses_equator(double s1, double s2)
{
  return (s1 > 0.0) != (s2 > 0.0);
}

// One bond's share of Eq. 23: the force on the node above the plane from the one below, along
// -n; positive in tension. fpair is the bond's force factor (force on node 1 = fpair (x1 - x2),
// negative in tension), dn = (x1 - x2) . n, s1 and s2 the nodes' heights. Zero if the bond does
// not cross, and the same whichever node is called 1.
inline double equatorial_force_term(double fpair, double dn, double s1, double s2)
{
  if (!crosses_equator(s1, s2)) return 0.0;
  return (s1 > s2) ? -fpair * dn : fpair * dn;
}

// A membrane triangle's share of Eq. 23 (angle style cell/membrane): the force its element
// exerts on its nodes above the plane, along -n; positive in tension. f[k] are the element's
// forces on its three nodes (summing to zero), s[k] the nodes' heights. Zero for a triangle
// wholly on one side; for forces that are pair forces along the edges it is the sum of the
// edges' equatorial_force_term.
inline double equatorial_force_triangle(const double f[3][3], const double s[3], const double n[3])
{
  double share = 0.0;
  for (int k = 0; k < 3; k++)
    if (s[k] > 0.0) share -= dot(f[k], n);
  return share;
}

// Protoplasm shear stress (Eqs. 24-26). Eq. 25 estimates the velocity gradient of particle i as
//   g[a][b] = sum_j (m_j / rho_j) v_ji^b dW_ij/dx_i^a,  v_ji = v_j - v_i,
// with dW_ij/dx_i^a = (dW/dr / r) del^a, del = x_i - x_j; this adds neighbour j's term with
// w = (m_j / rho_j) (dW/dr) / r.
inline void velocity_gradient_add(double g[3][3], double w, const double *del, const double *vji)
{
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) g[a][b] += w * del[a] * vji[b];
}

// Off-diagonal viscous stress tau^ab = mu (dv^b/dx^a + dv^a/dx^b) (Eq. 24) from that gradient.
inline double viscous_shear(double mu, const double g[3][3], int a, int b)
{
  return mu * (g[a][b] + g[b][a]);
}

// Total effective shear stress (Eq. 26).
inline double shear_stress_magnitude(double txy, double txz, double tyz)
{
  return std::sqrt(txy * txy + txz * txz + tyz * tyz);
}

}    // namespace CellPhysics

#endif
