# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 2, check 3: in-vacuo breathing of the wall (Eq. A5) for the stiff and soft walls of
Table I. The wall is stretched isotropically by lam and released with no fluid; the period of the
mean radius must match omega = (1/R) sqrt(4E/rho_s), rho_s = M_wall/(4 pi R^2 t0), within 1%.

The discrete network differs from the continuum shell by its mesh: for a uniform radial mode the
tether energy is sum(l0^2) G t0/sqrt3 u(lam), so omega_net/omega = sqrt(sum l0^2/(2 sqrt3 4 pi R^2))
= 1.0049 at level 4, printed below. The amplitude is kept small (lam = 1.002) so that the
Neo-Hookean nonlinearity (a shift of order (lam-1)) stays well below the 1% tolerance; lam = 1.01,
the stiff cell's turgor stretch, is run as well and reported.
"""
import math

import lmptest as T

from cellmech.validation.analysis import crossing_period as period  # shared with tools/validate.sh
from cellmech.validation.references import mesh_factor, omega_a5

R, M, LEVEL = T.CELL["R"], T.CELL["M_wall"], 4
CASES = {  # name: G (kPa), t0 (um), dt (us), steps
    "stiff": (T.STIFF["G"], T.STIFF["t0"], 0.001, 600),
    "soft": (T.SOFT["G"], T.SOFT["t0"], 0.02, 1500),
}


def test_wall_breathing_period(rundir):
    d = rundir
    T.cellgen("cell", "-o", "wall.data", "--level", LEVEL, "--radius", R, "--nfluid", 0,
              "--wall-mass", M, cwd=d)
    mesh = mesh_factor(LEVEL)
    print(f"mesh factor sqrt(sum l0^2 / (2 sqrt3 4 pi R^2)) = {mesh:.5f}")
    print(f"{'wall':6s} {'lam':>6s} {'omega sim':>12s} {'omega A5':>12s} {'rel.err':>9s} periods")
    for name, (G, t0, dt, steps) in CASES.items():
        omega = omega_a5(G, t0, R, M)            # rad/us
        for lam in (1.002, 1.01):
            out = f"{name}-{lam}.dat"
            T.lmp(T.INPUTS + "/in.breathing", cwd=d, variables=dict(
                data="wall.data", G=G, t0=t0, dt=dt, nsteps=steps, lam=lam, out=out, dir=T.INPUTS))
            data = T.load(f"{d}/{out}")
            n = 2 if lam == 1.002 else 1
            w = 2 * math.pi / period(data[:, 1], data[:, 2], R, n)
            err = w / omega - 1
            print(f"{name:6s} {lam:6.3f} {w * 1e6:12.5e} {omega * 1e6:12.5e} {err:+9.2e} {n}")
            if lam == 1.002:
                T.check(f"{name} breathing frequency within 1% of Eq. A5", abs(err) < 0.01,
                        f"err {err:+.2%}")
    # the same stiff wall in SI units (m, kg, s; cellgen --units si): the conversions a user makes.
    # Positions, masses and moduli scale exactly, so the period must come out 1e-6 times the
    # micro one, to the round-off of a different floating-point path (1e-9).
    T.cellgen("cell", "-o", "wall-si.data", "--level", LEVEL, "--radius", R * 1e-6, "--nfluid", 0,
              "--wall-mass", M * 1e-15, "--units", "si", cwd=d)
    G, t0, dt, steps = CASES["stiff"]
    periods = {}
    for units, data, scale in (("micro", "wall.data", 1.0), ("si", "wall-si.data", 1e-6)):
        out = f"units-{units}.dat"
        # micro: G kPa, t0 um, dt us, f0 nN um = 1e-15 J, r0 um; si: Pa, m, s, J, m
        T.lmp(T.INPUTS + "/in.breathing", cwd=d, variables=dict(
            data=data, units=units, G=G * (1e3 if units == "si" else 1), t0=t0 * scale, dt=dt * scale,
            nsteps=steps, lam=1.002, out=out, f0=2.0e5 * (1e-15 if units == "si" else 1),
            r0=1.5 * scale, cut=6.0 * scale, skin=0.1 * scale, dir=T.INPUTS))
        a = T.load(f"{d}/{out}")
        periods[units] = period(a[:, 1], a[:, 2], R * scale, 2)
    ratio = periods["si"] / (periods["micro"] * 1e-6)
    print(f"period: micro {periods['micro']:.10g} us, si {periods['si']:.10g} s, ratio {ratio:.12f}")
    T.check("units si gives the micro period times 1e-6", abs(ratio - 1) < 1e-9, f"{ratio - 1:+.1e}")
