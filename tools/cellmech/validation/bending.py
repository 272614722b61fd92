# SPDX-License-Identifier: GPL-2.0-or-later
"""Breathing and buckling of the bending wall (issue 11): the settings and the reading of the
records, shared by validation case 8 and tests/test_breathing_bending.py.

The wall is the bending one (membrane + hinges, -var wall bending) with node masses by area
(cellgen --wall-mass-by-area): equal node masses make the geodesic wall's surface density vary by
-23..+20% in an icosahedral pattern that does not shrink with refinement, and the breathing mode
drives that pattern out of round (degrees 6, 10, 12, 18, ...), which swamps both a clean
breathing record and the buckles.

Below the critical stress: released from an isotropic stretch 1 + BELOW eps_c (Eq. S2), the
compressive half-swing reaches BELOW sigma_c. Above it: released from 1 - ABOVE eps_c, the wall
starts at ABOVE sigma_c in compression with a random seed of imperfections, and the buckles that
grow are read from the spherical-harmonic spectrum of the node radii."""
import math

import numpy as np

from . import analysis
from . import references as ref
from .common import M_WALL, R0, STIFF, resolution
from .entry import Entry, pyplot, save_plot

BELOW = 0.5          # compressive half-swing of the breathing run / the critical strain
ABOVE = 2.0          # initial compression of the buckling run / the critical strain
PERIODS = 20         # breathing periods measured
THICK = 4.0          # the buckling runs' wall: THICK times Table I's stiff t0 (lambda_c resolved)
BUCKLE_TIME = 0.4    # us, about 4.4 breathing periods of the thick wall
BUCKLE_DT = {3: 0.001, 4: 0.0005, 5: 0.00025}   # us: the thick wall's hinges are 64x stiffer
FRAMES = 32          # dumps of the node positions over BUCKLE_TIME
LMAX = 40            # spectrum up to this degree (level 4 resolves about sqrt(2562) = 50)
ONSET = 0.1          # the buckles count from an rms of the node radii of this times the swing


def seed(level):
    """Largest random displacement of a node (um): 2 nm at level 4, scaled with sqrt(nodes) so that
    every spherical harmonic gets the same seed amplitude at every level (white noise of per-node
    size s puts s^2 4 pi / N into each harmonic's coefficient)."""
    return 0.002 * 2.0 ** (level - 4)


def breathing_record(a, R, omega5, periods=PERIODS):
    """A breathing record (in.breathing: step t rmean rrms) read per period of Eq. A5: omega from
    the crossings of R over `periods` periods, the swing (half the range of the mean radius) and
    the largest rms of the node radii in the first and last period and in all (omega None when
    the mean radius stops crossing R, as a crumpled wall's does)."""
    t, r, s = a[:, 1], a[:, 2], a[:, 3]
    try:
        w = 2 * math.pi / analysis.crossing_period(t, r, R, periods)
    except RuntimeError:      # a crumpled wall's mean radius stays below R: no omega
        w = None
    T = 2 * math.pi / omega5
    k = np.floor(t / T).astype(int)
    swing = [0.5 * np.ptp(r[k == i]) for i in range(periods)]
    spread = [s[k == i].max() for i in range(periods)]
    return dict(omega=w, swing_first=swing[0], swing_last=swing[-1], rms_first=spread[0],
                rms_last=spread[-1], rms_max=max(spread), drift=float(r[k == periods - 1].mean() - R))


def buckles(frames, dt, R, swing, T):
    """The buckles of a buckling run's dumped frames: onset = first frame whose rms of the node
    radii passes ONSET times the swing; the spectra of the frames over one breathing period T
    from there summed (the buckles' amplitude breathes with the wall), their power-weighted mean
    degree (l >= 2) and its wavelength 2 pi R / sqrt(l (l + 1))."""
    rms = np.array([np.linalg.norm(x, axis=1).std() for _, x in frames])
    times = np.array([step * dt for step, _ in frames])
    hit = np.where(rms > ONSET * swing)[0]
    if not len(hit):
        return dict(onset=None, rms0=float(rms[0]), rms_end=float(rms[-1]))
    t0 = times[hit[0]]
    power = sum(analysis.degree_spectrum(x, LMAX) for (step, x), t in zip(frames, times)
                if t0 <= t < t0 + T)
    lam, lbar = analysis.buckle_wavelength(power, R)
    return dict(onset=float(t0), rms0=float(rms[0]), rms_end=float(rms[-1]), degree=lbar,
                wavelength=lam, peak=int(np.argmax(power[2:]) + 2))


def edge_length(level, R):
    """Mean edge of the level's geodesic wall of radius R."""
    from .. import cellgen
    nodes, _, edges = cellgen.icosphere(level)
    return float(R * np.linalg.norm(nodes[edges[:, 0]] - nodes[edges[:, 1]], axis=1).mean())



# ---- validation case 8 ----------------------------------------------------------------------------

def case_bending_shell(run, level, ctx):
    """Breathing below and buckling above the classical buckling stress of a spherical shell, with
    the bending wall whatever WALL is (the tethers beside it at the same amplitude)."""
    G, t0 = STIFF["G"], STIFF["t0"]
    # the breathing runs at level 4 or finer: at level 3 lambda_c of the stiff wall is 1.6 edges,
    # and the wall loses its swing to mesh-scale folds within 20 periods even below sigma_c
    bl = max(level, 4)
    e = Entry("8-bending-shell", "Breathing and buckling of the bending wall (Eqs. A5, S1-S5)",
              "no bending in the paper; a tether wall crumples after about two periods at lam = 1.01",
              resolution(bl, fluid=False))
    ec = ref.shell_critical_strain(t0, R0)
    w5 = ref.omega_a5(G, t0, R0, M_WALL)
    lam = 1 + BELOW * ec
    plt = pyplot()
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.6))
    recs = shell_breathing(run, bl, lam, w5, ax[0])
    mesh = ref.membrane_mesh_factor(bl)
    breathing_rows(e, recs, w5, mesh)
    # buckling: the thick wall at two or three levels
    tt = THICK * t0
    lc, lf = ref.shell_buckle_wavelength(tt, R0), ref.shell_fastest_wavelength(tt, R0, ABOVE)
    levels = (3, 4, 5) if level >= 4 else (3, 4)
    wavelengths = {}
    for lv in levels:
        k = shell_buckling(run, e, lv, lc, lf, ax[1])
        if k is not None:
            wavelengths[lv] = k
    top = max(wavelengths) if wavelengths else None
    if top and top - 1 in wavelengths:
        # level 3 has 2.2 edges per lambda_S5: unresolved, compared but not judged
        e.add(f"wavelength level {top} vs level {top - 1}", wavelengths[top], wavelengths[top - 1], "um",
              tol=0.10 if top - 1 >= 4 else None)
    ax[1].axvline(R0 * 2 * math.pi / lc, color="k", ls=":", label="l of lambda_c")
    ax[1].axvline(R0 * 2 * math.pi / lf, color="k", ls="--", label="l of Eq. S5")
    ax[1].set_xlabel("spherical-harmonic degree l")
    ax[1].set_ylabel("share of the radii's power")
    ax[1].legend(fontsize=8)
    save_plot(fig, ctx, "bending-shell.png", e)
    bending_notes(e, bl, lam, mesh)
    return e


def shell_breathing(run, bl, lam, w5, ax):
    """The breathing records below sigma_c at level bl: the bending wall with node masses by area,
    the tethers beside it and the bending wall with equal masses ({tag: breathing_record}), drawn
    into ax."""
    G, t0 = STIFF["G"], STIFF["t0"]
    steps = int(math.ceil((PERIODS + 0.5) * 2 * math.pi / w5 / 0.001))
    recs = {}
    for tag, wall, extra in (("bending", "bending", ["--wall-mass-by-area"]),
                             ("tether", "tether", ["--wall-mass-by-area"]),
                             ("bending, equal masses", "bending", [])):
        data = f"wall{bl}-bending{'-area' if extra else ''}.data"
        run.cellgen(data, "cell", "--level", bl, "--nfluid", 0, "--wall-mass", M_WALL, "--bending", *extra)
        out = f"shell-breathing-{wall}{'-area' if extra else ''}-L{bl}.dat"
        run.lmp("in.breathing", f"log.{out[:-4]}", outputs=(out,), wall=wall, data=data, G=G, t0=t0,
                dt=0.001, nsteps=steps, lam=lam, out=out)
        a = np.loadtxt(run.path(out), ndmin=2)
        ax.plot(a[:, 1] * w5 / (2 * math.pi), a[:, 3] / ((lam - 1) * R0), label=tag, lw=0.8)
        recs[tag] = breathing_record(a, R0, w5)
    ax.set_xlabel("t / (2 pi / omega_A5)")
    ax.set_ylabel("rms of node radii / swing")
    ax.set_yscale("log")
    ax.legend(fontsize=8)
    return recs


def breathing_rows(e, recs, w5, mesh):
    """The bending wall's breathing judged against Eq. A5; the tethers and equal masses beside it."""
    b = recs["bending"]
    e.add(f"breathing {PERIODS} periods at {BELOW:g} sigma_c: omega vs Eq. A5", b["omega"], w5, "rad/us", tol=0.005)
    e.add("  omega vs Eq. A5 x membrane mesh factor", b["omega"], w5 * mesh, "rad/us")
    e.add("  swing in the last period / first", b["swing_last"] / b["swing_first"], 1.0, "", tol=0.05)
    e.add("  largest rms of node radii / swing", b["rms_max"] / b["swing_first"], None)
    e.add("  first period's rms of node radii / swing (the mesh's own)", b["rms_first"] / b["swing_first"], None)
    e.add("  mean radius of the last period - R, per swing", b["drift"] / b["swing_first"], None)
    for tag in ("tether", "bending, equal masses"):
        r = recs[tag]
        e.add(f"  {tag}: omega vs Eq. A5 (blank: mean radius no longer crosses R)", r["omega"], w5, "rad/us")
        e.add(f"  {tag}: largest rms of node radii / swing", r["rms_max"] / r["swing_first"], None)
        e.add(f"  {tag}: swing in the last period / first", r["swing_last"] / r["swing_first"], 1.0)
        e.add(f"  {tag}: mean radius of the last period - R, per swing", r["drift"] / r["swing_first"], None)


def shell_buckling(run, e, lv, lc, lf, ax):
    """The thick wall released above sigma_c at level lv (and, at level 4, the control below it):
    rows of its growth and buckle wavelength, its spectrum drawn into ax. Returns the wavelength
    (None when no buckle grew)."""
    G, tt = STIFF["G"], THICK * STIFF["t0"]
    ect = ref.shell_critical_strain(tt, R0)
    data = f"wall{lv}-bending-area.data"
    run.cellgen(data, "cell", "--level", lv, "--nfluid", 0, "--wall-mass", M_WALL, "--bending",
                "--wall-mass-by-area")
    wavelength = None
    for a_, kind in ((ABOVE, "above"), (BELOW, "control")):
        if kind == "control" and lv != 4:
            continue
        dt = BUCKLE_DT[lv]
        n = int(round(BUCKLE_TIME / dt))
        tag = f"shell-buckle-{kind}-L{lv}"
        lam_b = 1 - a_ * ect
        run.lmp("in.breathing", f"log.{tag}", outputs=(f"{tag}.dat", f"{tag}.xyz"), wall="bending",
                data=data, G=G, t0=tt, dt=dt, nsteps=n, lam=lam_b, out=f"{tag}.dat",
                noise=seed(lv), dump=n // FRAMES, dumpfile=f"{tag}.xyz")
        frames = analysis.read_dump_frames(run.path(f"{tag}.xyz"))
        k = buckles(frames, dt, R0, abs(1 - lam_b) * R0, 2 * math.pi / ref.omega_a5(G, tt, R0, M_WALL))
        g = k["rms_end"] / k["rms0"]
        if kind == "control":
            e.add(f"buckling control at {BELOW:g} sigma_c, level {lv}: rms growth in {BUCKLE_TIME:g} us", g, None)
            continue
        e.add(f"buckling at {ABOVE:g} sigma_c, level {lv}: rms growth in {BUCKLE_TIME:g} us", g, None,
              group="buckle")
        if k["onset"] is None:
            continue
        wavelength = k["wavelength"]
        e.add(f"  level {lv} ({lf / edge_length(lv, R0):.1f} edges per lambda_S5): wavelength vs Eq. S5",
              k["wavelength"], lf, "um", group="buckle")
        e.add(f"  level {lv}: wavelength vs lambda_c (Eq. S4)", k["wavelength"], lc, "um", group="buckle")
        e.add(f"  level {lv}: mean degree l (peak {k['peak']})", k["degree"], None, group="buckle")
        pw = sum(analysis.degree_spectrum(x, LMAX) for s, x in frames if k["onset"] <= s * dt < k["onset"] + 0.1)
        ax.plot(np.arange(2, LMAX + 1), pw[2:] / pw[2:].sum(), marker=".", label=f"level {lv}")
    return wavelength


def bending_notes(e, bl, lam, mesh):
    """The shell's critical values and the runs' settings."""
    G, t0 = STIFF["G"], STIFF["t0"]
    E = 3 * G
    ec = ref.shell_critical_strain(t0, R0)
    tt = THICK * t0
    ect = ref.shell_critical_strain(tt, R0)
    lc, lf = ref.shell_buckle_wavelength(tt, R0), ref.shell_fastest_wavelength(tt, R0, ABOVE)
    e.note(f"Stiff wall of Table I (G {G:g} kPa, t0 {t0:g} um, R {R0:g} um): sigma_c = E t/(R sqrt(3(1 - "
           f"nu^2))) = {ref.shell_critical_stress(E, t0, R0) / 1e3:.3g} MPa (Eq. S1), eps_c = {ec:.3g} "
           f"(S2), p_c = {2 * t0 * ref.shell_critical_stress(E, t0, R0) / R0:.3g} kPa (S3), lambda_c = "
           f"{ref.shell_buckle_wavelength(t0, R0):.3g} um (S4), {ref.shell_buckle_wavelength(t0, R0) / edge_length(4, R0):.1f} "
           f"edges at level 4. Breathing at level {bl}: released from {lam:.5f} ({BELOW:g} eps_c), {PERIODS} periods, node "
           f"masses by area; the membrane mesh factor sqrt(sum A0 / 4 pi R^2) = {mesh:.5f}.")
    e.note(f"Buckling: at twice sigma_c the fastest-growing buckle of the stiff wall, {ref.shell_fastest_wavelength(t0, R0, ABOVE):.3g} um, "
           f"is {ref.shell_fastest_wavelength(t0, R0, ABOVE) / edge_length(4, R0):.1f} edges at level 4: not resolved. The "
           f"wall {THICK:g} times thicker (t0 {tt:g} um: eps_c {ect:.3g}, lambda_c {lc:.3g} um, Eq. S5 at "
           f"{ABOVE:g} sigma_c {lf:.3g} um) is released from {1 - ABOVE * ect:.5f} with a random seed of "
           f"{seed(4) * 1e3:g} nm at level 4 (scaled with sqrt(nodes): equal per harmonic). Wavelength: "
           f"2 pi R / sqrt(l(l + 1)) of the power-weighted mean degree of the node radii's spectrum, summed "
           f"over one breathing period from the first frame with rms > {ONSET:g} x swing.")
