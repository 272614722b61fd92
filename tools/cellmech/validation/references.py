# SPDX-License-Identifier: GPL-2.0-or-later
"""Reference values of the validation cases, computed from the paper's formulas (units micro:
um, pg, us, kPa, nN). Nothing here is a stored number: every reference follows from the model
parameters the caller passes."""
import math

import numpy as np
from scipy.optimize import brentq


def omega_a5(G, t0, R, M):
    """In-vacuo breathing, Eq. A5: omega = (1/R) sqrt(4E/rho_s), E = 3G, rho_s = M/(4 pi R^2 t0)."""
    rho_s = M / (4 * math.pi * R * R * t0)
    return math.sqrt(4 * 3.0 * G / rho_s) / R


def mesh_factor(level):
    """omega_network / omega_A5 of a geodesic tether network in its uniform radial mode. The
    network's tether energy is sum(l0^2) G t0/sqrt3 u(lam) where the continuum shell has
    2 sqrt3 4 pi R^2 G t0/sqrt3 u(lam), so the ratio is sqrt(sum l0^2 / (2 sqrt3 4 pi R^2))
    (1.0049 at level 4)."""
    from .. import cellgen
    nodes, _, edges = cellgen.icosphere(level)
    l = np.linalg.norm(nodes[edges[:, 0]] - nodes[edges[:, 1]], axis=1)
    return math.sqrt((l ** 2).sum() / (2 * math.sqrt(3) * 4 * math.pi))


def a4_roots(Et, R, M, rho, c, n=3):
    """First n roots of Eq. A4 as angular frequencies (rad/us):
    j0(q)/j1(q) - q rho_s t/(rho R) + 4 E t/(q rho c^2 R) = 0, q = omega R / c,
    with rho_s t = M / (4 pi R^2) the wall's own mass per area."""
    rhost = M / (4 * math.pi * R * R)

    def f(q):
        j0 = math.sin(q) / q
        j1 = math.sin(q) / q ** 2 - math.cos(q) / q
        return j0 / j1 - q * rhost / (rho * R) + 4 * Et / (q * rho * c * c * R)

    qs = np.linspace(0.05, 20, 20000)
    v = np.array([f(q) for q in qs])
    out = []
    for a, b, va, vb in zip(qs[:-1], qs[1:], v[:-1], v[1:]):
        # sign changes through zero, not the poles of j0/j1
        if np.sign(va) != np.sign(vb) and abs(va) < 50 and abs(vb) < 50:
            out.append(brentq(f, a, b) * c / R)
    return out[:n]


def tait_density(P, rho0, c, P0=0.0):
    """Density of the fluid at pressure P from the equation of state (Eq. 6),
    P = P0 + kappa[(rho/rho0)^7 - 1], kappa = rho0 c^2 / 7."""
    kappa = rho0 * c * c / 7.0
    return rho0 * (1.0 + (P - P0) / kappa) ** (1.0 / 7.0)


def tait_sound_speed(rho, rho0, c):
    """Local sound speed sqrt(dP/drho) = c (rho/rho0)^3 of the same equation of state."""
    return c * (rho / rho0) ** 3


def young_laplace_stretch_at(P, R, G, t0):
    """Stretch of a Neo-Hookean wall of tension P R / 2 = G t0 (1 - lam^-6) at radius R."""
    return (1 - P * R / 2 / (G * t0)) ** (-1 / 6)


def young_laplace_stretch(P, R0, G, t0):
    """Self-consistent inflated stretch: P lam R0 / 2 = G t0 (1 - lam^-6), on the stable branch:
    the pressure the membrane holds, 2 G t0 (1 - lam^-6) / (lam R0), peaks at lam = 7^(1/6)."""
    return brentq(lambda l: P * l * R0 / 2 - G * t0 * (1 - l ** -6), 1.0, 7 ** (1 / 6))


def sheet_a1(lam):
    """Paper Eq. A1: uniaxial stretch, other sides free, force per G t0 W."""
    return lam ** 2 - lam ** -2


def sheet_a2(lam):
    """Paper Eq. A2: uniaxial stretch, other sides fixed, force per G t0 W."""
    return (lam ** 2 - 1 / lam) * np.sqrt(lam)


def sheet_neo_hookean(lam, sides):
    """Exact incompressible Neo-Hookean sheet: free lam - lam^-2, fixed (plane strain) lam - lam^-3."""
    return lam - lam ** -2 if sides == "free" else lam - lam ** -3


def sheet_network_modulus(sides):
    """Small-strain modulus of the linear triangular spring network (k = 6 G t0 / sqrt3), per G t0:
    2k/sqrt3 = 4 (free), 2k/sqrt3 / (1 - 1/9) = 4.5 (plane strain, Poisson ratio 1/3)."""
    return 4.0 if sides == "free" else 4.5


def observed_order(f1, f2, f3, ratio=2.0):
    """Observed convergence order from three levels refined by `ratio` and the Richardson
    extrapolate; (None, None) when the differences do not shrink monotonically."""
    d1, d2 = f1 - f2, f2 - f3
    if d2 == 0 or d1 / d2 <= 0 or abs(d1) <= abs(d2) * 1.0000001:
        return None, None
    p = math.log(abs(d1 / d2)) / math.log(ratio)
    return p, f3 + (f3 - f2) / (ratio ** p - 1)
