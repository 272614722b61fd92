/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_water.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: water in a tissue: solutes, exchange between cells and the exposed wall (Eqs. W1-W4;
   not in the paper).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_WATER_H
#define CELLMECH_PHYSICS_WATER_H

#include "vec3.h"

namespace CellPhysics {

/* ---------------------------------------------------------------------
   Water in a tissue (fix cell/fluid options solute, exchange, external;
   not in the paper, which has one cell in pure water: docs/fix_cell_fluid.rst)
------------------------------------------------------------------------ */

// Solutes kept in their cell (Eq. W1, Boyle-van 't Hoff): the osmotic potential is proportional to
// the solute concentration, so Pi W = Pi0 W0 with W the cell's water (fluid) mass.
inline double solute_osmotic_potential(double Pi0, double W0, double W)
{
  return Pi0 * W0 / W;
}

// Conductivity of the wall two cells share (Eq. W2): water crosses both cells' walls in series,
// 1/Lp = 1/Lp_a + 1/Lp_b; zero when either wall is closed to water.
inline double series_conductivity(double Lp_a, double Lp_b)
{
  return (Lp_a > 0.0 && Lp_b > 0.0) ? Lp_a * Lp_b / (Lp_a + Lp_b) : 0.0;
}

// Share of a cell's water flux that its fluid particle of mass m and density rho takes (Eq. W5):
// its volume m / rho over the cell's fluid volume Vf = sum m_j / rho_j. A cell's mass change dM
// then changes every particle's density by the same (rho / m) dm = dM / Vf (Eq. 9 at fixed
// volume), so a cell of one pressure keeps one, whatever its particles' masses.
inline double volume_share(double m, double rho, double Vf)
{
  return m / rho / Vf;
}

// Mass that cell a gives cell b in one step dt (Eq. W3): dM_b/dt = -dM_a/dt = k (psi_a - psi_b),
// k = A_ab Lp_ab rho, psi = P + Pi the water potentials, linearised in the step's own effect on
// them as osmotic_mass_step is (dpsi/dM of each cell, > 0: a cell's potential rises as it gains
// water), so that a large k dt brings the two potentials together without overshoot.
inline double exchange_mass_step(double k, double dt, double psi_a, double psi_b, double dpsi_dM_a,
                                 double dpsi_dM_b)
{
  return k * dt * (psi_a - psi_b) / (1.0 + k * dt * (dpsi_dM_a + dpsi_dM_b));
}

// Wall area of a cell open to the outside by Eq. W4's 'exposed unglued' (every space between cells
// counts as outside): the current area A less the glued part, whose rest area A_glued_ref (the
// lamella areas d_alam) is scaled by the wall's areal stretch A / A_ref (A_ref the rest area of its
// triangles); never below zero.
inline double exposed_area(double A, double A_ref, double A_glued_ref)
{
  if (A_ref <= 0.0) return A;
  const double open = 1.0 - A_glued_ref / A_ref;
  return open > 0.0 ? A * open : 0.0;
}

// Whether a point at offset d from the centroid of a wall triangle (unit outward normal n, longest
// edge h) lies in front of it, so that a wall through that point hides the triangle from the
// outside (Eq. W4, exposed outside): on its outer side (d.n > 0) within 45 degrees of the normal,
// or, close to the wall, within h of the normal line. The cone alone would miss a facing wall
// nearer than its node spacing (the glued walls are 2.56 um apart, the coarse nodes 3.3-5.5 um):
// the normal line crosses that wall inside one of its triangles, within h/sqrt(3) of a node.
inline bool hides_triangle(const double *d, const double *n, double h)
{
  const double s = dot(d, n);
  if (s <= 0.0) return false;
  const double lateral2 = dot(d, d) - s * s;
  const double r = s > h ? s : h;
  return lateral2 <= r * r;
}

}    // namespace CellPhysics

#endif
