/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: LAMMPS plugin for the micromechanics of biological cells.
   The laws of the SPH-DEM plant cell model (Van Liedekerke et al., Phys. Rev. E 81, 061906
   (2010)) as pure functions free of LAMMPS, so that tests can call them: one header per
   topic in src/physics/, checked by tests/unit/physics/test_kernel.cpp.
   Equation numbers refer to that paper; docs/model.md describes the model.
   This header: the cubic-spline SPH kernel and its derivatives (Eqs. 3-4).
------------------------------------------------------------------------- */

#ifndef CELLMECH_PHYSICS_KERNEL_H
#define CELLMECH_PHYSICS_KERNEL_H

#include <cmath>

namespace CellPhysics {

// Cubic-spline kernel of smoothing length s, support 2s. Eq. 3 (unit integral) fixes the
// prefactor at 3 / (2 pi s^3) for this bracket; the 2 / (3 pi s^3) printed in Eq. 4 does not
// integrate to one (docs/model.md, section 5).
// kernel_w_q: the bracket at q = r / s times a prefactor that a pair loop computes once per type
// pair (kernel_w_norm(s), or that over W(r_ref) for the ratio W(r) / W(r_ref)), so that no
// division is left per pair.
inline double kernel_w_norm(double s)
{
  return 3.0 / (2.0 * M_PI * s * s * s);
}

inline double kernel_w_q(double q, double norm)
{
  if (q < 1.0) return norm * (2.0 / 3.0 - q * q + 0.5 * q * q * q);
  if (q < 2.0) {
    const double u = 2.0 - q;
    return norm * u * u * u / 6.0;
  }
  return 0.0;
}

inline double kernel_w(double r, double s)
{
  return kernel_w_q(r / s, kernel_w_norm(s));
}

// dW/dr; the gradient is dW/dr times the unit vector r_ij / r. Its prefactor depends on s only: a
// pair loop computes it once per type pair (kernel_dwdr_norm) and passes it, with the same bits.
inline double kernel_dwdr_norm(double s)
{
  return 3.0 / (2.0 * M_PI * s * s * s * s);
}

inline double kernel_dwdr(double r, double s, double norm)
{
  const double q = r / s;
  if (q < 1.0) return norm * (-2.0 * q + 1.5 * q * q);
  if (q < 2.0) {
    const double u = 2.0 - q;
    return -norm * 0.5 * u * u;
  }
  return 0.0;
}

inline double kernel_dwdr(double r, double s)
{
  return kernel_dwdr(r, s, kernel_dwdr_norm(s));
}

// (dW/dr) / r from r^2: the factor wr of grad_i W_ij = wr r_ij (Eq. 5, Eq. 7) that the pair loops
// use, with 1/s and kernel_wr_norm(s) = kernel_dwdr_norm(s) / s of the type pair computed once.
// Inside q < 1 the 1/r cancels, so no division is left there; both brackets are evaluated and one
// is selected, with no branch, so that a loop over pairs calling it runs in SIMD lanes. It equals
// kernel_dwdr(r, s) / r to a few ulp, not bit for bit (tests/unit: Kernel.PairFactorIsdWdrOverR).
inline double kernel_wr_norm(double s)
{
  return kernel_dwdr_norm(s) / s;
}

inline double kernel_wr(double rsq, double inv_s, double wr_norm)
{
  const double q = std::sqrt(rsq) * inv_s;
  const double u = 2.0 - q;
  const double inner = wr_norm * (-2.0 + 1.5 * q);
  const double outer = -wr_norm * 0.5 * u * u / q;
  return q < 1.0 ? inner : (q < 2.0 ? outer : 0.0);
}

}    // namespace CellPhysics

#endif
