# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 11: in-vacuo breathing of the bending wall (membrane + hinges) below the classical
buckling stress of a spherical shell, and its buckling above it (Eqs. S1-S5 of physics/shell.h;
settings and analysis in cellmech.validation.bending, shared with validation case 8).

1. Stiff wall of Table I (t0 = 0.126 um, R = 30 um): sigma_c = E t/(R sqrt(3(1 - nu^2))) = 6.72 MPa,
   eps_c = t/(3R) = 1.4e-3. Released from 1 + 0.5 eps_c, level 4, node masses by area, 20 periods:
   omega within 0.5% of Eq. A5 (the wall's own uniform mode is A5 times sqrt(sum A0 / 4 pi R^2) =
   0.9994, printed), the swing in the last period at least 95% of the first (the energy stays in
   the breathing mode), the rms of the node radii at most a quarter of the swing (the mesh's own
   non-uniform response is 2% of it; a crumpled wall's exceeds the swing) and the mean radius of
   the last period within 2% of the swing from R. The tether wall at the same amplitude crumples
   (rms of the node radii above the swing), which shows the bending is what holds the wall.
2. Above: lambda_c = 7.05 um is 3.1 edges at level 4, and the buckles that grow fastest at twice
   sigma_c are lambda_c / sqrt2 = 5.0 um = 2.2 edges, not resolved; the wall 4 times thicker
   (t0 = 0.504 um: eps_c = 5.6e-3, lambda_c = 14.1 um, 6.2 edges at level 4, 12.5 at 5) is.
   Released from 1 - 2 eps_c with a random seed (equal per harmonic at both levels): the rms of
   the node radii grows more than 20-fold in 0.4 us at levels 4 and 5, and less than 3-fold from
   1 - 0.5 eps_c (the control below sigma_c). The wavelength (power-weighted mean degree of the
   radii's spherical-harmonic spectrum over one period from the onset) lies between the fastest-
   growing at the peak stress, lambda_c / sqrt2 = 9.97 um (Eq. S5, 5% below allowed for the
   discrete spectrum), and lambda_c (the stress swings below its peak while they grow); levels
   4 and 5 agree within 10%. Measured when this test was written: 10.77 and 10.19 um, level 4
   one degree (l 17 vs 18, 5.5% of the wavelength) longer for each of four seeds (10.76-10.85
   against 10.18-10.32 um), level 6 (40962 nodes, once by hand) 10.19 um again: the level-4
   offset is its discretisation at 4.4 edges per wavelength, and 10% allows it about twice.
"""
import math

import pytest

import lmptest as T

from cellmech.validation import analysis, bending as B
from cellmech.validation import references as ref

R, M = T.CELL["R"], T.CELL["M_wall"]
G, T0 = T.STIFF["G"], T.STIFF["t0"]


def breathe(d, wall, data, lam, out, dt=0.001):
    w5 = ref.omega_a5(G, T0, R, M)
    steps = int(math.ceil((B.PERIODS + 0.5) * 2 * math.pi / w5 / dt))
    T.lmp(T.INPUTS + "/in.breathing", cwd=d, log=f"log.{out}", variables=dict(
        data=data, wall=wall, G=G, t0=T0, dt=dt, nsteps=steps, lam=lam, out=out, dir=T.INPUTS))
    return B.breathing_record(T.load(f"{d}/{out}"), R, w5)


def buckle(d, level, lam, tag):
    t0 = B.THICK * T0
    dt = B.BUCKLE_DT[level]
    steps = int(round(B.BUCKLE_TIME / dt))
    every = steps // B.FRAMES
    T.lmp(T.INPUTS + "/in.breathing", cwd=d, log=f"log.{tag}", variables=dict(
        data=f"wall{level}.data", wall="bending", G=G, t0=t0, dt=dt, nsteps=steps, lam=lam,
        out=f"{tag}.dat", noise=B.seed(level), dump=every, dumpfile=f"{tag}.xyz", dir=T.INPUTS))
    frames = analysis.read_dump_frames(f"{d}/{tag}.xyz")
    swing = abs(1 - lam) * R
    return B.buckles(frames, dt, R, swing, 2 * math.pi / ref.omega_a5(G, t0, R, M))


@pytest.fixture(scope="module")
def walls(rundir):
    """The bending walls of levels 4 and 5 (cellgen --bending, wall mass by area)."""
    for level in (4, 5):
        T.cellgen("cell", "-o", f"wall{level}.data", "--level", level, "--radius", R, "--nfluid", 0,
                  "--wall-mass", M, "--bending", "--wall-mass-by-area", cwd=rundir)
    E = 3 * G
    print(f"stiff wall: sigma_c {ref.shell_critical_stress(E, T0, R) / 1e3:.4g} MPa, "
          f"eps_c {ref.shell_critical_strain(T0, R):.4g}, lambda_c {ref.shell_buckle_wavelength(T0, R):.4g} um = "
          f"{ref.shell_buckle_wavelength(T0, R) / B.edge_length(4, R):.2f} edges at level 4")
    return rundir


def test_breathing_below_critical_stress(walls):
    """Breathing below sigma_c, 20 periods: the bending wall keeps its mode, the tether wall crumples."""
    d = walls
    ec = ref.shell_critical_strain(T0, R)
    lam = 1 + B.BELOW * ec
    w5 = ref.omega_a5(G, T0, R, M)
    mesh = ref.membrane_mesh_factor(4)
    print(f"\nreleased from {lam:.6f} (compressive half-swing {B.BELOW} eps_c), {B.PERIODS} periods")
    print(f"{'wall':8s} {'omega':>10s} {'vs A5':>9s} {'vs A5 x mesh':>12s} {'swing 1st':>9s} "
          f"{'last':>9s} {'rms 1st':>9s} {'rms max':>9s} {'drift':>9s}")
    rec = {}
    for wall in ("bending", "tether"):
        b = rec[wall] = breathe(d, wall, "wall4.data", lam, f"below-{wall}.dat")
        # a crumpled wall's mean radius stops crossing R: no omega
        om = (f"{b['omega']:10.6g} {b['omega'] / w5 - 1:+9.2e} {b['omega'] / (w5 * mesh) - 1:+12.2e}"
              if b["omega"] else f"{'none':>10s} {'':9s} {'':12s}")
        print(f"{wall:8s} {om} "
              f"{b['swing_first']:9.4g} {b['swing_last']:9.4g} {b['rms_first']:9.3g} "
              f"{b['rms_max']:9.3g} {b['drift']:+9.2e}")
    b = rec["bending"]
    T.check("bending wall: omega over 20 periods within 0.5% of Eq. A5",
            b["omega"] is not None and abs(b["omega"] / w5 - 1) < 0.005,
            f"{(b['omega'] or math.nan) / w5 - 1:+.3%} (mesh factor {mesh:.5f})")
    T.check("bending wall: the swing stays in the breathing mode (last >= 95% of first)",
            b["swing_last"] >= 0.95 * b["swing_first"], f"{b['swing_last'] / b['swing_first']:.4f}")
    T.check("bending wall: no crumpling (rms of node radii <= swing / 4 in every period)",
            b["rms_max"] <= 0.25 * b["swing_first"], f"{b['rms_max'] / b['swing_first']:.3f} of the swing")
    T.check("bending wall: mean radius of the last period within 2% of the swing from R",
            abs(b["drift"]) <= 0.02 * b["swing_first"], f"{b['drift'] / b['swing_first']:+.4f}")
    t = rec["tether"]
    T.check("tether wall at the same amplitude crumples (rms of node radii > swing)",
            t["rms_max"] > t["swing_first"], f"{t['rms_max'] / t['swing_first']:.2f} of the swing")


def test_buckling_above_critical_stress(walls):
    """Buckling above sigma_c, thick wall, levels 4 and 5: the wavelength of the shell theory,
    independent of the mesh; no buckling below."""
    d = walls
    t0 = B.THICK * T0
    ec = ref.shell_critical_strain(t0, R)
    lc, lf = ref.shell_buckle_wavelength(t0, R), ref.shell_fastest_wavelength(t0, R, B.ABOVE)
    print(f"\nthick wall t0 {t0:g} um: eps_c {ec:.4g}, lambda_c {lc:.4g} um, fastest at {B.ABOVE:g} "
          f"sigma_c {lf:.4g} um; edges {B.edge_length(4, R):.3f} (level 4), {B.edge_length(5, R):.3f} um (5)")
    print(f"{'run':12s} {'rms seed':>9s} {'rms end':>9s} {'growth':>8s} {'onset us':>9s} {'mean l':>7s} "
          f"{'peak l':>6s} {'lambda um':>9s}")
    got = {}
    for tag, level, a in (("above-L4", 4, B.ABOVE), ("above-L5", 5, B.ABOVE), ("control-L4", 4, B.BELOW)):
        k = buckle(d, level, 1 - a * ec, tag)
        got[tag] = k
        g = k["rms_end"] / k["rms0"]
        extra = (f"{k['onset']:9.4f} {k['degree']:7.2f} {k['peak']:6d} {k['wavelength']:9.4g}"
                 if k["onset"] is not None else f"{'-':>9s}")
        print(f"{tag:12s} {k['rms0']:9.3g} {k['rms_end']:9.3g} {g:8.1f} {extra}")
    for tag in ("above-L4", "above-L5"):
        k = got[tag]
        T.check(f"{tag}: buckles above sigma_c (rms grows > 20-fold)", k["rms_end"] > 20 * k["rms0"] and
                k["onset"] is not None, f"{k['rms_end'] / k['rms0']:.1f}-fold")
        if k["onset"] is not None:
            T.check(f"{tag}: wavelength between lambda_c/sqrt2 (-5%) and lambda_c",
                    0.95 * lf <= k["wavelength"] <= lc, f"{k['wavelength']:.4g} um in [{0.95 * lf:.4g}, {lc:.4g}]")
    k = got["control-L4"]
    T.check("control at 0.5 sigma_c: no buckling (rms grows < 3-fold)", k["rms_end"] < 3 * k["rms0"],
            f"{k['rms_end'] / k['rms0']:.2f}-fold")
    l4, l5 = got["above-L4"].get("wavelength"), got["above-L5"].get("wavelength")
    if l4 and l5:
        T.check("buckle wavelength does not depend on the mesh (levels 4 and 5 within 10%)",
                abs(l5 / l4 - 1) < 0.10, f"{l4:.4g} vs {l5:.4g} um ({l5 / l4 - 1:+.2%})")
