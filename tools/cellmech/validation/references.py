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


def membrane_mesh_factor(level):
    """omega / omega_A5 of the membrane wall (angle_style cell/membrane) in its uniform radial mode
    with node masses by area (cellgen --wall-mass-by-area): its energy is that of the inscribed
    polyhedron's area, sum A0 W(lam), where the continuum shell has 4 pi R^2 W(lam), so the ratio
    is sqrt(sum A0 / (4 pi R^2)) (0.99940 at level 4). The hinges store nothing in it (uniform
    scaling keeps every dihedral angle)."""
    from .. import cellgen
    nodes, tri, _ = cellgen.icosphere(level)
    a = np.cross(nodes[tri[:, 1]] - nodes[tri[:, 0]], nodes[tri[:, 2]] - nodes[tri[:, 0]])
    return math.sqrt(0.5 * np.linalg.norm(a, axis=1).sum() / (4 * math.pi))


# Classical buckling of a spherical shell, Eqs. S1, S2, S4, S5 of src/physics/shell.h (derived and
# unit-tested there; these are the same formulas for the Python side): radius R, thickness t,
# modulus E, Poisson ratio nu (the wall: E = 3G, nu = 1/2).

def shell_critical_stress(E, t, R, nu=0.5):
    """Eq. S1: sigma_c = E t / (R sqrt(3 (1 - nu^2)))."""
    return E * t / (R * math.sqrt(3 * (1 - nu * nu)))


def shell_critical_strain(t, R, nu=0.5):
    """Eq. S2: the equibiaxial strain of sigma_c, (1 - nu) sigma_c / E (t / (3R) for nu = 1/2)."""
    return (1 - nu) * t / (R * math.sqrt(3 * (1 - nu * nu)))


def shell_buckle_wavelength(t, R, nu=0.5):
    """Eq. S4: lambda_c = 2 pi sqrt(R t) / (12 (1 - nu^2))^(1/4)."""
    return 2 * math.pi * math.sqrt(R * t) / (12 * (1 - nu * nu)) ** 0.25


def shell_fastest_wavelength(t, R, a, nu=0.5):
    """Eq. S5: the fastest-growing buckle at a compressive stress a >= 1 times sigma_c."""
    return shell_buckle_wavelength(t, R, nu) / math.sqrt(a)
