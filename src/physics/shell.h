/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_shell.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: a thin spherical shell: its breathing mode in vacuo (Eq. A5) and its classical
   buckling (Eqs. S1-S5).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_SHELL_H
#define CELLMECH_PHYSICS_SHELL_H

#include <cmath>

namespace CellPhysics {

/* ---------------------------------------------------------------------
   Thin spherical shell, breathing mode in vacuo (Eq. A5):
     omega = (1/R) sqrt(4 E / rho_s),  rho_s = M_wall / (4 pi R^2 t0).
------------------------------------------------------------------------ */

inline double breathing_omega_vacuo(double E, double R, double wall_mass, double t0)
{
  const double rho_s = wall_mass / (4.0 * M_PI * R * R * t0);
  return std::sqrt(4.0 * E / rho_s) / R;
}

/* ----------------------------------------------------------------------
   Classical buckling of a spherical shell (Eqs. S1-S5): Zoelly (1915), Timoshenko & Gere,
   Theory of Elastic Stability (1961) sec. 11.3, Hutchinson, J. Appl. Mech. 34, 49 (1967).
   A shell of radius R, thickness t, modulus E, Poisson ratio nu under an equibiaxial membrane
   stress sigma (compression positive). A shallow dimple w ~ cos(k x) with k R >> 1 is in
   equilibrium (the shallow-shell equation) when
     sigma t k^2 = D k^4 + E t / R^2,     D = E t^3 / (12 (1 - nu^2))  (Eq. B1)
   the bending resisting at short waves, the hoop stretching of the curved shell at long ones.
   The least stress for which some k balances (d/dk = 0: k_c^4 = E t / (D R^2)) is (Eq. S1)
     sigma_c = E t / (R sqrt(3 (1 - nu^2))),
   the buckle's wavelength is (Eq. S4)  lambda_c = 2 pi / k_c = 2 pi sqrt(R t) / (12 (1 - nu^2))^(1/4),
   the equibiaxial strain of sigma_c (Hooke, plane stress) is (Eq. S2)
     eps_c = (1 - nu) sigma_c / E          (t / (3 R) for nu = 1/2),
   and the external pressure that makes it (Laplace, sigma = p R / (2 t)) is (Eq. S3)
     p_c = 2 E t^2 / (R^2 sqrt(3 (1 - nu^2))).
   Above sigma_c a band of k grows; in time a mode of wall density rho grows at the rate
   rho t s^2 = sigma t k^2 - D k^4 - E t / R^2, fastest at k^2 = sigma t / (2 D), so a shell held
   (or swung) to sigma = a sigma_c buckles first at (Eq. S5)  lambda = lambda_c / sqrt(a).
   The hinges of Eqs. B2-B3 have D in the mean-curvature term, the only one that enters here (the
   Gaussian term integrates to the boundary of a dimple), so the wall meets S1-S5 with E = 3G,
   nu = 1/2 (the incompressible membrane).
------------------------------------------------------------------------- */

// Critical equibiaxial membrane stress of a spherical shell (Eq. S1).
inline double shell_critical_stress(double E, double t, double R, double nu)
{
  return E * t / (R * std::sqrt(3.0 * (1.0 - nu * nu)));
}

// Equibiaxial compressive strain at the critical stress (Eq. S2).
inline double shell_critical_strain(double E, double t, double R, double nu)
{
  return (1.0 - nu) * shell_critical_stress(E, t, R, nu) / E;
}

// Classical buckling pressure of a spherical shell (Eq. S3).
inline double shell_critical_pressure(double E, double t, double R, double nu)
{
  return 2.0 * t * shell_critical_stress(E, t, R, nu) / R;
}

// Wavelength of the classical buckle (Eq. S4).
inline double shell_buckle_wavelength(double t, double R, double nu)
{
  constexpr double PI = 3.14159265358979323846;
  return 2.0 * PI * std::sqrt(R * t) / std::pow(12.0 * (1.0 - nu * nu), 0.25);
}

// Fastest-growing wavelength at a compressive stress a times the critical one, a >= 1 (Eq. S5).
inline double shell_fastest_wavelength(double t, double R, double nu, double a)
{
  return shell_buckle_wavelength(t, R, nu) / std::sqrt(a);
}

}    // namespace CellPhysics

#endif
