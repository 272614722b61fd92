#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""membrane: an inflated thin Neo-Hookean membrane squeezed between two rigid plates.

Independent reference for the quasistatic compression of the cell (Feng and Yang 1973 style,
docs/model.md section 4). Axisymmetric membrane, no bending stiffness; the contents are a fixed volume
(optionally a liquid of bulk modulus K); the plates are flat, rigid and frictionless. A membrane
carries no compression, so where the classical solution would compress the centre of the contact
disc the solver uses tension-field theory: a slack (wrinkled) disc inside a taut ring.
The equations and their derivation are in docs/membrane.rst.

material="network" replaces the Neo-Hookean sheet by the affine, orientation-averaged energy of
the model's tether network (Eq. 19 bonds): same equibiaxial law, 1.5x the shear modulus.

Nondimensional internally: lengths / R0, tensions / (G t0), pressure p R0 / (G t0).

Usage:
  membrane.py --G 8e5 --t0 0.126 --R0 30 --P 364 --eps-max 0.2 --n 21 [--K 7e4]
              [--material neohookean|network] -o curve.csv
As a module:
  membrane.compress_curve(G_t0, R0, P_turgor, strains, bulk_modulus=None,
                          material="neohookean") -> list of dicts
"""
import argparse
import math
import sys

import numpy as np
from scipy.integrate import solve_bvp
from scipy.optimize import brentq

HALF_PI = 0.5 * math.pi
# classical (no slack) branch: the pole condition l1 = l2 is applied at theta = POLE * theta_c,
# off the coordinate singularity; the singular mode it lets in decays like 1/theta, so its trace
# at the contact edge is ~POLE^3 (checked against POLE = 1e-3 in the tests' convergence study).
POLE = 1e-4
TOL = 1e-7              # solve_bvp residual tolerance (relative, on O(1) nondimensional states)
MAX_NODES = 30000       # a converging step needs hundreds to a few thousand; beyond: a bad guess
GUESS_NODES = 400       # the previous state is resampled on about this many nodes
STEP = 0.0025           # largest continuation step in strain


# ------------------------------------------------------------------------------- material law

def tensions(l1, l2):
    """True (Cauchy) tensions T1, T2 per G t0 of the incompressible Neo-Hookean sheet,
    W = (G t0 / 2)(l1^2 + l2^2 + (l1 l2)^-2 - 3), T_i = (dW/dl_i) / l_j."""
    j3 = (l1 * l2) ** -3
    return l1 / l2 - j3, l2 / l1 - j3


def dtension1(l1, l2):
    """dT1/dl1 and dT1/dl2 (per G t0)."""
    j3 = (l1 * l2) ** -3
    return 1.0 / l2 + 3.0 * j3 / l1, -l1 / l2 ** 2 + 3.0 * j3 / l2


def energy_density(l1, l2):
    """Strain energy per reference area per G t0 of the Neo-Hookean sheet."""
    return 0.5 * (l1 * l1 + l2 * l2 + (l1 * l2) ** -2 - 3.0)


# The tether network (src/physics/tether.h tether_energy, Eq. 19): a bond of rest length l0 at
# stretch lam stores U = (G t0 l0^2 / sqrt3) u(lam), u = lam^2/2 - 3/4 + lam^-4/4, so that
# dU/dl = (G t0 l0 / sqrt3)(lam - lam^-5). A triangulated net has 3 bonds per node and
# sqrt3/2 l0^2 of area per node: W = 3 U / (sqrt3/2 l0^2) = 2 G t0 <u>. Affine deformation
# with bonds in all directions (the geodesic net): lam(phi)^2 = l1^2 cos^2 phi + l2^2 sin^2 phi,
# averaged uniformly over phi, <lam^2> = (l1^2 + l2^2)/2 and
# <lam^-4> = (l1^2 + l2^2) / (2 l1^3 l2^3)
# [the mean of 1/(a cos^2 + b sin^2)^2 over phi is (a + b)/(2 (ab)^1.5)].
# W / (G t0) = (l1^2 + l2^2)/2 - 3/2 + (l1^2 + l2^2)/(4 (l1 l2)^3): equibiaxially
# l^2 - 3/2 + l^-4/2, exactly the Neo-Hookean sheet's; in shear 1.5 G t0 against G t0.

def network_energy_density(l1, l2):
    """Strain energy per reference area per G t0 of the orientation-averaged tether network."""
    s = l1 * l1 + l2 * l2
    return 0.5 * s - 1.5 + 0.25 * s * (l1 * l2) ** -3


def network_tensions(l1, l2):
    """True tensions T1, T2 per G t0 of the tether network, T_i = (dW/dl_i) / l_j."""
    a, b = l1 * l1, l2 * l2
    ab = a * b
    return (l1 / l2 - (0.25 / b + 0.75 / a) / ab,
            l2 / l1 - (0.25 / a + 0.75 / b) / ab)


def network_dtension1(l1, l2):
    """dT1/dl1 and dT1/dl2 of the tether network (per G t0)."""
    a, b = l1 * l1, l2 * l2
    return (1.0 / l2 + (0.5 / b + 3.0 / a) / (l1 * a * b),
            -l1 / b + (1.0 / b + 1.5 / a) / (l2 * a * b))


# (T1, T2), (dT1/dl1, dT1/dl2), W: all per G t0. Both vanish only at l1 = l2 = 1 (W >= 0, a mean
# of bond energies u >= 0 that are zero only at lam = 1), which the slack edge relies on.
MATERIALS = {"neohookean": (tensions, dtension1, energy_density),
             "network": (network_tensions, network_dtension1, network_energy_density)}


def young_laplace_stretch(p_hat):
    """Stretch lam of the free inflated sphere: p R / 2 = G t0 (1 - lam^-6), R = lam R0, with
    p_hat = p R0 / (G t0). The pressure peaks at lam = 7^(1/7) (inflation instability).
    The same law for both materials: their equibiaxial energies are identical."""
    lam_max = 7.0 ** (1.0 / 7.0)
    if p_hat <= 0.0:
        return 1.0
    if p_hat > 2.0 * (1.0 - lam_max ** -6) / lam_max:
        raise ValueError("turgor above the Neo-Hookean sphere's limit pressure")
    # in x = ln(lam) with expm1: at low turgor lam - 1 ~ 1e-5 and 1 - lam^-6 would cancel
    x = brentq(lambda x: 0.5 * p_hat * math.exp(x) + math.expm1(-6.0 * x), 0.0, math.log(lam_max),
               xtol=1e-300, rtol=4.0 * sys.float_info.epsilon)
    return math.exp(x)


# ---------------------------------------------------------------------------------- equations
# Reference sphere: material colatitude theta (pole 0, equator pi/2), reference arc R0 theta.
# Deformed: radius r = R0 l2 sin(theta), meridian slope angle psi (0 on the plate, pi/2 at the
# equator), meridional stretch l1 = (ds/dtheta) / R0. Equilibrium (membrane, normal pressure p):
#   d(r T1)/ds = T2 cos(psi)                       (meridional)
#   T1 dpsi/ds + T2 sin(psi) / r = p               (normal; on the plate the plate takes p)


def meridian_slopes(theta, l2, l1, cpsi, law=MATERIALS["neohookean"]):
    """d l2/dtheta and d l1/dtheta from the geometry of r = l2 sin(theta) and the meridional
    equilibrium d(r T1)/dtheta = T2 dr/dtheta written for l1 (chain rule through T1(l1, l2))."""
    s, c = np.sin(theta), np.cos(theta)
    r = s * l2
    drdth = l1 * cpsi
    T1, T2 = law[0](l1, l2)
    a11, a12 = law[1](l1, l2)
    dl2 = (drdth - l2 * c) / s
    dl1 = ((T2 - T1) * drdth / r - a12 * dl2) / a11
    return dl2, dl1


def normal_slope(theta, l2, l1, psi, p, law=MATERIALS["neohookean"]):
    """d psi/dtheta of the free (unsupported) meridian: curvature from the normal balance."""
    r = np.sin(theta) * l2
    T1, T2 = law[0](l1, l2)
    return l1 * (p - T2 * np.sin(psi) / r) / T1


class Problem:
    """Two regions on one mapped coordinate tau in [0, 1]:
    A: the taut part of the contact disc, theta from theta_s to theta_c (psi = 0 on the plate);
    B: the free meridian, theta from theta_c to the equator.
    States y = [l2A, l1A, l2B, l1B, psiB, zB, VB] (VB: volume of the upper half, z: height above
    the equator). Parameters k = [p, theta_c] (+ theta_s when the disc has a slack centre).
    classical: taut to the pole (l1 = l2 there); slack: theta_s is a free boundary where the
    sheet is unstretched (l1 = l2 = 1), see docs/membrane.rst for the corner condition."""

    def __init__(self, lam, h, p0, K_hat, slack, material="neohookean"):
        self.lam, self.h, self.p0, self.K, self.slack = lam, h, p0, K_hat, slack
        self.material, self.law = material, MATERIALS[material]
        self.V0 = 4.0 / 3.0 * math.pi * lam ** 3

    def inner(self, k):
        return k[2] if self.slack else POLE * k[1]

    def target_volume(self, p):
        return self.V0 if self.K is None else self.V0 * (1.0 - (p - self.p0) / self.K)

    def fun(self, tau, y, k):
        p, thc = k[0], k[1]
        ths = self.inner(k)
        thA = ths + (thc - ths) * tau
        thB = thc + (HALF_PI - thc) * tau
        dl2A, dl1A = meridian_slopes(thA, y[0], y[1], 1.0, self.law)
        psi = y[4]
        dl2B, dl1B = meridian_slopes(thB, y[2], y[3], np.cos(psi), self.law)
        dpsi = normal_slope(thB, y[2], y[3], psi, p, self.law)
        rB = np.sin(thB) * y[2]
        dz = -y[3] * np.sin(psi)
        dV = -math.pi * rB ** 2 * dz
        LA, LB = thc - ths, HALF_PI - thc
        return np.vstack([LA * dl2A, LA * dl1A, LB * dl2B, LB * dl1B, LB * dpsi, LB * dz, LB * dV])

    def bc(self, ya, yb, k):
        p = k[0]
        inner = [ya[0] - 1.0, ya[1] - 1.0] if self.slack else [ya[1] - ya[0]]
        return np.array(inner + [
            yb[0] - ya[2], yb[1] - ya[3],                 # l2, l1 (i.e. r, T1) continuous at the edge
            ya[4], yb[4] - HALF_PI,                       # tangent to the plate; vertical at equator
            ya[5] - self.h, yb[5],                        # plate height; equator at z = 0
            ya[6], yb[6] - 0.5 * self.target_volume(p)])  # enclosed volume


def first_guess(lam, eps, n=201):
    """Young-Laplace sphere with a flattened cap: the start of the continuation in strain."""
    tau = np.linspace(0.0, 1.0, n)
    h = lam * (1.0 - eps)
    thc = math.asin(math.sqrt(1.0 - (1.0 - eps) ** 2))
    psi = HALF_PI * tau
    y = np.vstack([np.full(n, lam), np.full(n, lam), np.full(n, lam), np.full(n, lam), psi,
                   h * np.cos(psi), (2.0 / 3.0) * math.pi * lam ** 3 * tau])
    return tau, y, np.array([0.0, thc])


def thinned_mesh(x, n=GUESS_NODES):
    """Every k-th node of mesh x (keeping its clustering) merged with a uniform grid."""
    stride = max(1, len(x) // n)
    return np.union1d(x[::stride], np.r_[np.linspace(0.0, 1.0, n // 2 + 1), x[-1]])


def solve(prob, tau, y, k, tol=TOL):
    """Collocation solve; None when it does not converge (a bad guess overflows on the way:
    those warnings are the failed attempt's, not the answer's)."""
    with np.errstate(all="ignore"):
        sol = solve_bvp(prob.fun, prob.bc, tau, y, p=k, tol=tol, bc_tol=tol * 1e-2,
                        max_nodes=MAX_NODES)
    return sol if sol.status == 0 and np.all(np.isfinite(sol.y)) else None


def strain_energy(prob, sol, refine=8):
    """Strain energy of the whole wall (both halves), per G t0 R0^2; the slack disc stores none.
    Simpson on the collocation mesh refined `refine` times (the interpolant is C1 cubic)."""
    from scipy.integrate import simpson
    thc, ths = sol.p[1], prob.inner(sol.p)
    x = sol.x
    tau = np.union1d(x, (x[:-1, None] + np.diff(x)[:, None] * np.arange(1, refine) / refine).ravel())
    Y = sol.sol(tau)
    thA = ths + (thc - ths) * tau
    thB = thc + (HALF_PI - thc) * tau
    W = prob.law[2]
    UA = simpson(W(Y[1], Y[0]) * np.sin(thA), x=thA)
    UB = simpson(W(Y[3], Y[2]) * np.sin(thB), x=thB)
    # classical branch: the tiny cap inside POLE * theta_c is at the pole's stretch
    U0 = 0.0 if prob.slack else W(Y[1, 0], Y[0, 0]) * (1.0 - math.cos(ths))
    return 2.0 * 2.0 * math.pi * (UA + UB + U0)


def describe(prob, sol, neval=4001):
    """Nondimensional outputs and check quantities of one converged state."""
    p, thc = sol.p[0], sol.p[1]
    ths = prob.inner(sol.p)
    y0, y1 = sol.sol(0.0), sol.sol(1.0)
    a = math.sin(thc) * y0[2]
    r_eq = y1[2]
    tens = prob.law[0]
    T1_eq = tens(y1[3], y1[2])[0]
    tau = np.linspace(0.0, 1.0, neval)
    Y = sol.sol(tau)
    TA = tens(Y[1], Y[0])
    TB = tens(Y[3], Y[2])
    return dict(p=p, a=a, a_slack=math.sin(ths) * y0[0] if prob.slack else 0.0, r_eq=r_eq,
                V=2.0 * y1[6], V_target=prob.target_volume(p), F=p * math.pi * a * a,
                F_eq=p * math.pi * r_eq ** 2 - 2.0 * math.pi * r_eq * T1_eq, T1_eq=T1_eq,
                lam_inner=y0[1], theta_c=thc, theta_s=ths if prob.slack else 0.0,
                min_T_disc=float(min(TA[0].min(), TA[1].min())),
                min_T_free=float(min(TB[0].min(), TB[1].min())),
                h=prob.h, nodes=len(sol.x), slack=prob.slack, U=strain_energy(prob, sol))


class Curve:
    """Continuation in strain from the Young-Laplace state; switches to the slack-centre branch
    where the classical solution's pole stretch would fall below 1 (compression).
    advance(eps) returns the nondimensional state, dimensional(eps, state) the caller's units."""

    def __init__(self, G_t0, R0, P_turgor, bulk_modulus=None, tol=TOL, step=STEP,
                 tension_field=True, material="neohookean"):
        if material not in MATERIALS:
            raise ValueError(f"material must be one of {', '.join(MATERIALS)}")
        self.Gt, self.R0, self.tol, self.step = G_t0, R0, tol, step
        self.material = material
        # tension_field=False keeps the classical branch with its compressed pole (for
        # comparison only: a membrane cannot carry that compression)
        self.tension_field = tension_field
        self.p0 = P_turgor * R0 / G_t0
        self.K = None if bulk_modulus is None else bulk_modulus * R0 / G_t0
        self.lam = young_laplace_stretch(self.p0)
        self.R_infl = self.lam * R0
        self.state = None          # (eps, slack, sol)
        self.eps_slack = None      # strain at which the slack centre appears (None: not yet)

    def problem(self, eps, slack):
        return Problem(self.lam, self.lam * (1.0 - eps), self.p0, self.K, slack, self.material)

    def _attempt(self, eps, slack, guess):
        prob = self.problem(eps, slack)
        sol = solve(prob, *guess, tol=self.tol)
        if sol is None:
            return None
        ok_inner = slack or not self.tension_field or sol.sol(0.0)[1] >= 1.0
        return prob, sol, ok_inner

    def _guess(self, slack):
        """Previous state as the next guess, on a thinned mesh: solve_bvp only ever adds nodes,
        so reusing its mesh lets the node count grow along the continuation."""
        eps, was_slack, sol = self.state
        k = sol.p
        if slack and not was_slack:
            k = np.array([k[0], k[1], 0.2 * k[1]])
        tau = thinned_mesh(sol.x)
        return tau, sol.sol(tau), k

    def _find_onset(self, eps_lo, eps_hi):
        """Strain where the classical pole stretch reaches 1 (pole tension zero)."""
        keep = self.state

        def f(e):
            self.state = keep
            r = self._attempt(e, False, self._guess(False))
            if r is None:
                raise RuntimeError("classical branch lost near the slack onset")
            return r[1].sol(0.0)[1] - 1.0
        eps_star = brentq(f, eps_lo, eps_hi, xtol=1e-7)
        self.state = keep
        return eps_star

    def advance(self, eps_target):
        """Move the continuation to eps_target (> current strain) in steps <= self.step,
        halving the step where the collocation does not converge."""
        if self.state is not None and eps_target < self.state[0] - 1e-12:
            raise ValueError("the continuation only moves to larger strains")
        if self.state is None:
            # the flattened-sphere guess holds for a cap whose strain is well below the
            # prestretch lam - 1 (found by trial: 1e-3 at 364 kPa, 3e-5 at 3 kPa)
            ladder = [e for e in (1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6)
                      if e <= 0.5 * (self.lam - 1.0)] or [1e-6]
            for e0 in ladder:
                e0 = min(eps_target, e0)
                sol = solve(self.problem(e0, False), *first_guess(self.lam, e0), tol=self.tol)
                if sol is not None and sol.sol(0.0)[1] >= 1.0:
                    break
            else:
                raise RuntimeError("no converged start near first contact")
            self.state = (e0, False, sol)
        while self.state[0] < eps_target - 1e-12:
            eps, slack, _ = self.state
            h = min(self.step, eps_target - eps, eps)   # geometric steps near first contact
            while True:
                e = eps + h
                r = self._attempt(e, slack, self._guess(slack))
                if r is not None and not r[2]:
                    # the classical solution compresses the pole: the slack centre starts here
                    self.eps_slack = self._find_onset(eps, e)
                    # start the slack branch just past its onset, where the slack disc is still
                    # small and the last classical state is a close guess
                    es = min(e, self.eps_slack + 0.25 * (e - self.eps_slack) + 1e-6)
                    r = None
                    for frac in (1.0, 0.5, 0.25, 0.1):
                        tau, yg, k = self._guess(False)
                        rs = self._attempt(es, True, (tau, yg, np.r_[k, frac * 0.1 * k[1]]))
                        if rs is not None and rs[1].p[2] > 0.0:
                            r = rs
                            break
                    if r is None:
                        raise RuntimeError(f"slack branch did not start at eps {es:.5f}")
                    e, slack = es, True
                if r is not None:
                    self.state = (e, slack, r[1])
                    break
                h *= 0.5
                if h < 1e-7:
                    raise RuntimeError(f"continuation stalled at eps {eps:.6f}")
        return describe(self.problem(self.state[0], self.state[1]), self.state[2])

    def dimensional(self, eps, d):
        """Outputs in the caller's units (force G_t0 R0, pressure G_t0 / R0, length R0)."""
        L, Tn = self.R0, self.Gt
        out = dict(eps=eps, F=d["F"] * Tn * L, p=d["p"] * Tn / L, a=d["a"] * L,
                   a_slack=d["a_slack"] * L, r_eq=d["r_eq"] * L, V=d["V"] * L ** 3,
                   V_target=d["V_target"] * L ** 3, F_eq=d["F_eq"] * Tn * L,
                   T1_eq=d["T1_eq"] * Tn, min_T_disc=d["min_T_disc"] * Tn,
                   min_T_free=d["min_T_free"] * Tn, lam_inner=d["lam_inner"],
                   theta_c=d["theta_c"], theta_s=d["theta_s"], nodes=d["nodes"],
                   slack=d["slack"], R_inflated=self.R_infl, U=d["U"] * Tn * L * L)
        return out

    def zero_load(self):
        """The Young-Laplace sphere (eps = 0, no contact), in the caller's units."""
        L, Tn = self.R0, self.Gt
        R = self.R_infl
        T0 = self.p0 * self.lam / 2.0 * Tn
        return dict(eps=0.0, F=0.0, p=self.p0 * Tn / L, a=0.0, a_slack=0.0, r_eq=R,
                    V=4.0 / 3.0 * math.pi * R ** 3, V_target=4.0 / 3.0 * math.pi * R ** 3,
                    F_eq=0.0, T1_eq=T0, min_T_disc=T0, min_T_free=T0, lam_inner=self.lam,
                    theta_c=0.0, theta_s=0.0, nodes=0, slack=False, R_inflated=R,
                    U=4.0 * math.pi * MATERIALS[self.material][2](self.lam, self.lam) * Tn * L * L)


def compress_curve(G_t0, R0, P_turgor, strains, bulk_modulus=None, tol=TOL, step=STEP,
                   material="neohookean"):
    """Plate force-strain curve of the inflated membrane.

    G_t0: wall shear modulus times thickness; R0: unstressed radius; P_turgor: pressure at zero
    load (the contents' volume is then fixed, or follows V = V0 (1 - (p - P_turgor)/K) with
    K = bulk_modulus); strains: increasing eps = DeltaX / (2 R_inflated) >= 0; material:
    "neohookean" (the sheet) or "network" (the orientation-averaged tether network).
    Returns one dict per strain with 'eps','F','p','a','a_slack','r_eq','V' (units of the inputs:
    kPa, um, kPa*um -> nN, um^3) plus check quantities ('F_eq' = p pi r_eq^2 - 2 pi r_eq T1_eq,
    'V_target', 'min_T_disc', 'min_T_free', 'lam_inner', 'slack', 'eps_slack', ...)."""
    c = Curve(G_t0, R0, P_turgor, bulk_modulus, tol, step, material=material)
    out = []
    for eps in strains:
        if eps < 0.0:
            raise ValueError("strains must be >= 0")
        d = c.zero_load() if eps == 0.0 else c.dimensional(eps, c.advance(eps))
        d["eps_slack"] = c.eps_slack
        out.append(d)
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--G", type=float, required=True, help="wall shear modulus (kPa)")
    ap.add_argument("--t0", type=float, required=True, help="wall thickness (um)")
    ap.add_argument("--R0", type=float, required=True, help="unstressed radius (um)")
    ap.add_argument("--P", type=float, required=True, help="turgor at zero load (kPa)")
    ap.add_argument("--eps-max", type=float, default=0.2)
    ap.add_argument("--n", type=int, default=21, help="strains 0..eps-max")
    ap.add_argument("--K", type=float, default=None, help="bulk modulus of the contents (kPa)")
    ap.add_argument("--tol", type=float, default=TOL)
    ap.add_argument("--material", choices=sorted(MATERIALS), default="neohookean",
                    help="wall law: Neo-Hookean sheet or orientation-averaged tether network")
    ap.add_argument("-o", "--output", default="-")
    a = ap.parse_args(argv)
    strains = np.linspace(0.0, a.eps_max, a.n)
    rows = compress_curve(a.G * a.t0, a.R0, a.P, strains, a.K, tol=a.tol, material=a.material)
    es = rows[-1]["eps_slack"]
    print(f"membrane.py ({a.material}): G {a.G:g} t0 {a.t0:g} R0 {a.R0:g} P {a.P:g} K {a.K}: "
          f"R_inflated "
          f"{rows[0]['R_inflated']:.6f}, slack centre from eps "
          f"{'(none up to eps-max)' if es is None else f'{es:.5f}'}", file=sys.stderr)
    f = sys.stdout if a.output == "-" else open(a.output, "w")
    f.write("eps,F_nN,p_kPa,a_um,a_slack_um,r_eq_um,V_um3\n")
    for r in rows:
        f.write(f"{r['eps']:.6g},{r['F']:.9g},{r['p']:.9g},{r['a']:.9g},{r['a_slack']:.9g},"
                f"{r['r_eq']:.9g},{r['V']:.10g}\n")
    if f is not sys.stdout:
        f.close()


if __name__ == "__main__":
    main()
