# SPDX-License-Identifier: GPL-2.0-or-later
"""Analysis of the experiment outputs of tools/experiments.sh (and of the short forms in
tests/test_experiments.py): relaxation times, impact-zone shear stresses, rate independence,
turgor slopes, failure strain, crack origin and escaping fluid.

Every function takes the numbers from the files the LAMMPS inputs write; nothing here knows the
paper's values (report.py sets them beside ours).
"""
import math
import os

import numpy as np


def load(path):
    """Numeric table of a fix ave/time file (comment lines '#')."""
    return np.loadtxt(path, comments="#", ndmin=2)


# ---------------------------------------------------------------- columns of the inputs' tables
# in.impact / in.failure: step tt eps Ftop Fbot Feq P tauzone nzone tauall lammax nbroken
IMP = dict(t=1, eps=2, ftop=3, fbot=4, feq=5, p=6, tau=7, nzone=8, tauall=9, lammax=10, nbroken=11)
# in.compress: step tt eps Ftop Fbot Feq P [broken leak]
CMP = dict(t=1, eps=2, ftop=3, fbot=4, feq=5, p=6)
# in.relax (release stage): step tt Feq Feqz P H W ke
REL = dict(t=1, feq=2, feqz=3, p=4, h=5, w=6, ke=7)


# ---------------------------------------------------------------- relaxation
def smooth(y, n):
    """Moving average over n samples (odd), the ends over what is there."""
    if n <= 1:
        return np.asarray(y, float)
    k = np.ones(n)
    return np.convolve(y, k, "same") / np.convolve(np.ones(len(y)), k, "same")


def relaxation(t, f, f_inf, smooth_time=None):
    """Relaxation of a signal f(t) towards f_inf after a release at t[0].

    The signal is first smoothed over smooth_time (default 2% of the record), which removes the
    wall's and the fluid's fast vibrations (tens of ns) but not the cell's relaxation.
    d = f - f_inf; the envelope env(t) = max |d(t')| over t' >= t (what is still left to relax).
    tau_e: the first time env drops below |d|max / e (a settling time: for an oscillation
    decaying as exp(-t/tau), and for an overdamped exp(-t/tau), tau_e = tau).
    tau_fit: from a straight-line fit of log env(t) where env lies between 0.8 and 0.1 of
    its start (or over what is available when the record ends earlier: then 'extrapolated').
    t_first: the first time |d| drops below |d|max / e (the fast initial relaxation, before any
    overshoot or oscillation).
    Oscillation: sign changes of d - centre, centre the mean of d over the second half of the
    record (the cell may still swing about a state a little off its free one), between excursions
    larger than 10% of the start; period = twice the mean spacing of those sign changes.
    Overdamped: fewer than two.
    """
    t = np.asarray(t, float) - t[0]
    if smooth_time is None:
        smooth_time = 0.02 * t[-1]
    dt = t[1] - t[0] if len(t) > 1 else 1.0
    n = max(1, int(round(smooth_time / dt)) | 1)
    d = smooth(f, n) - f_inf
    env = np.maximum.accumulate(np.abs(d)[::-1])[::-1]
    d0 = env[0]
    res = dict(d0=d0, tau_e=float("nan"), tau_fit=float("nan"), period=float("nan"),
               crossings=0, extrapolated=False, t_first=float("nan"), centre=float("nan"))
    if not d0 > 0:
        return res
    first = np.nonzero(np.abs(d) < d0 / math.e)[0]
    if len(first):
        res["t_first"] = float(t[first[0]])
    below = np.nonzero(env < d0 / math.e)[0]
    if len(below):
        res["tau_e"] = float(t[below[0]])
    sel = (env <= 0.8 * d0) & (env >= 0.1 * d0)
    if sel.sum() < 5 or env[-1] > 0.1 * d0:   # the record ends before the decay gets that far
        sel = env <= 0.8 * d0
        res["extrapolated"] = bool(env[-1] > 0.1 * d0)
    if sel.sum() >= 5:
        slope = np.polyfit(t[sel], np.log(env[sel]), 1)[0]
        if slope < 0:
            res["tau_fit"] = float(-1.0 / slope)
    centre = float(np.mean(d[len(d) // 2:]))
    res["centre"] = centre
    dc = d - centre
    idx = np.nonzero(np.abs(dc) > 0.1 * d0)[0]
    sgn = np.sign(dc[idx])
    cross = [0.5 * (t[idx[k]] + t[idx[k + 1]]) for k in range(len(idx) - 1) if sgn[k] != sgn[k + 1]]
    res["crossings"] = len(cross)
    if len(cross) >= 2:
        res["period"] = float(2.0 * np.mean(np.diff(cross)))
    return res


# ---------------------------------------------------------------- plate experiments
def contact_curve(a, cols=CMP, which="fbot"):
    """Strain and plate force from the first contact of the bottom plate on (eps re-zeroed there is
    not done: eps counts from the plate's first position, the paper's Delta X / 2R)."""
    eps, f = a[:, cols["eps"]], a[:, cols[which]]
    return eps, f


def window_mean(x, y, x0, half):
    sel = np.abs(x - x0) <= half
    return (float(np.mean(y[sel])), int(sel.sum())) if sel.any() else (float("nan"), 0)


def impact_shear(a, eps0, half=0.005):
    """Mean impact-zone shear stress (kPa) over the samples with |eps - eps0| <= half."""
    return window_mean(a[:, IMP["eps"]], a[:, IMP["tau"]], eps0, half)


def rate_difference(a1, a2, windows=(0.06, 0.10, 0.14, 0.18), half=0.02):
    """Largest and rms relative difference, over strain windows, of the plate force (mean of both
    plates) between two compression rates, relative to the second run. The windows are 4% wide
    (tests/test_compress.py): the discrete wall meets the plates ring by ring, which puts steps of
    2-3% strain into the curve, and each window spans at least one step."""
    def win(a):
        e = a[:, CMP["eps"]]
        f = 0.5 * (a[:, CMP["ftop"]] + a[:, CMP["fbot"]])
        return np.array([window_mean(e, f, w, half)[0] for w in windows])
    f1, f2 = win(a1), win(a2)
    rel = np.abs(f1 - f2) / np.abs(f2)
    return float(np.nanmax(rel)), float(np.sqrt(np.nanmean(rel ** 2)))


def slope(a, lo, hi, cols=CMP, which="fbot"):
    """Least-squares slope dF/deps (nN per unit strain) of the plate force over lo <= eps <= hi."""
    e, f = a[:, cols["eps"]], a[:, cols[which]]
    sel = (e >= lo) & (e <= hi)
    if sel.sum() < 3:
        return float("nan")
    return float(np.polyfit(e[sel], f[sel], 1)[0])


def contact_strain(a, cols=CMP, which="fbot", frac=0.02):
    """Strain where the plate force first exceeds frac of its largest value."""
    e, f = a[:, cols["eps"]], a[:, cols[which]]
    i = np.nonzero(f > frac * np.max(f))[0]
    return float(e[i[0]]) if len(i) else float("nan")


def lag(a_imp, a_qs, level):
    """Strain at which the transmitted force first reaches `level` (nN), impact minus quasistatic;
    +inf when the impact run ends before its force gets there (and the quasistatic one does),
    nan when neither gets there."""
    def first(a, cols):
        e, f = a[:, cols["eps"]], a[:, cols["fbot"]]
        i = np.nonzero(f >= level)[0]
        return float(e[i[0]]) if len(i) else float("inf")
    qs = first(a_qs, CMP)
    if not math.isfinite(qs):
        return float("nan")
    return first(a_imp, IMP) - qs


def transmitted(a_imp, a_qs, frac=0.2):
    """The transmitted (bottom-plate) force of an impact beside the quasistatic curve: the level frac
    of the largest quasistatic force (nN), the lag of the impact in reaching it (lag()), and the mean
    force of both over eps +- 1% at the largest strain both reach less 1% (eps, f_imp, f_qs)."""
    level = frac * float(np.max(a_qs[:, CMP["fbot"]]))
    e_hi = min(float(a_imp[-1, IMP["eps"]]), float(a_qs[-1, CMP["eps"]])) - 0.01
    return dict(level=level, lag=lag(a_imp, a_qs, level), eps=e_hi,
                f_imp=window_mean(a_imp[:, IMP["eps"]], a_imp[:, IMP["fbot"]], e_hi, 0.01)[0],
                f_qs=window_mean(a_qs[:, CMP["eps"]], a_qs[:, CMP["fbot"]], e_hi, 0.01)[0])


# ---------------------------------------------------------------- failure
def read_dump(path):
    """Frames of a LAMMPS dump custom file: list of (step, column names, array)."""
    frames = []
    with open(path) as f:
        lines = f.readlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            cols = lines[i + 8].split()[2:]
            data = np.array([l.split() for l in lines[i + 9:i + 9 + n]], float).reshape(n, len(cols))
            frames.append((step, cols, data))
            i += 9 + n
        else:
            i += 1
    return frames


def _outside(wall, fluid, centre, margin):
    """Fluid particles beyond the wall: farther from the centre than the wall node nearest to their
    direction, by more than margin."""
    rw = wall - centre
    nw = np.linalg.norm(rw, axis=1)
    uw = rw / nw[:, None]
    rf = fluid - centre
    nf = np.linalg.norm(rf, axis=1)
    uf = rf / np.maximum(nf, 1e-12)[:, None]
    nearest = np.argmax(uf @ uw.T, axis=1)
    return nf > nw[nearest] + margin


def failure(dat, dumpfile, dt, margin):
    """Failure strain, crack origin and course, and the speed of the fluid that escapes.

    dat: the in.failure table; dumpfile: its dump (frames from the first broken tether on);
    dt: time step; margin: how far beyond the wall a fluid particle must be to count as escaped
    (the fluid-wall contact distance r0: fluid inside sits about r0 inside the wall nodes).
    Polar angle: latitude of a broken node seen from the wall centre, 0 at the equator (the plane
    through the centre normal to the compression axis z), 90 degrees at the plates.
    """
    res = failure_onset(load(dat))
    if "n_final" not in res or not os.path.exists(dumpfile):
        return res
    frames = read_dump(dumpfile)
    if not frames:
        return res
    # the dense dump (in.failure: every bdense steps while the crack grows) gives the origin and
    # the course; the sparse one the escaping fluid
    dense = read_dump(dumpfile + ".dense") if os.path.exists(dumpfile + ".dense") else []
    res["dense"] = bool(dense)
    step0 = (dense or frames)[0][0]
    first_lat, course = crack_course(dense, frames, dt, step0)
    speeds = escapes(frames, dt, step0, margin)
    if first_lat is not None:
        res["lat_first_mean"] = float(np.mean(first_lat))
        res["lat_first_absmean"] = float(np.mean(np.abs(first_lat)))
        res["lat_first_range"] = (float(first_lat.min()), float(first_lat.max()))
        res["n_first"] = int(len(first_lat))
    res["course"] = course
    res["escape"] = speeds
    if course:
        # the crack's run: the latitude span of the broken nodes 0.2 us after the first break, and
        # the mean speed at which its ends moved apart along a meridian of the undeformed cell (R0)
        c = np.array(course)
        k = np.nonzero(c[:, 0] <= 0.2 + 1e-9)[0][-1]
        res["span_02"] = (float(c[k, 2]), float(c[k, 3]))
        grow = (c[k, 3] - c[k, 2]) - (c[0, 3] - c[0, 2])
        res["crack_speed"] = float(np.radians(grow) * 30.0 / c[k, 0]) if c[k, 0] > 0 else float("nan")
    if speeds:
        # the jet: the largest median speed of the escaped fluid over the frames with at least 5 out
        ok = [s for s in speeds if s[1] >= 5]
        if ok:
            best = max(ok, key=lambda s: s[2])
            res["jet_median"] = best[2]
            res["jet_p90"] = best[3]
            res["jet_time"] = best[0]
    return res


def failure_onset(a):
    """From the in.failure table a: the strain and time of the first broken tether, the broken
    count at the end and the time it takes to reach 90% of it (nan strain and time: none broke)."""
    nb = a[:, IMP["nbroken"]]
    res = dict(eps_f=float("nan"), t_f=float("nan"))
    i = np.nonzero(nb > 0)[0]
    if not len(i):
        return res
    res["eps_f"] = float(a[i[0], IMP["eps"]])
    res["t_f"] = float(a[i[0], IMP["t"]])
    res["n_final"] = int(nb[-1])
    # time for the broken count to reach 90% of its final value
    j = np.nonzero(nb >= 0.9 * nb[-1])[0][0]
    res["t_90"] = float(a[j, IMP["t"]] - a[i[0], IMP["t"]])
    return res


def _frame(cols, d):
    """Of one dump frame: column index, wall mask, positions, the wall's centre, each particle's
    latitude about it, and the mask of wall nodes with a broken element."""
    c = {n: k for k, n in enumerate(cols)}
    w = d[:, c["type"]] == 1
    pos = d[:, [c["x"], c["y"], c["z"]]]
    centre = pos[w].mean(axis=0)
    r = pos - centre
    lat = np.degrees(np.arcsin(np.clip(r[:, 2] / np.linalg.norm(r, axis=1), -1, 1)))
    return c, w, pos, centre, lat, w & (d[:, c["nbroken"]] > 0)


def crack_course(dense, frames, dt, step0):
    """The latitudes of the first broken nodes and the crack's course, (time after step0, broken
    nodes, lowest latitude, highest latitude) per frame with a break: from the dense frames when
    there are any (the sparse ones then only extend it past their end), else the sparse ones."""
    course = []
    first_lat = None
    for step, cols, d in dense:
        _, _, _, _, lat, br = _frame(cols, d)
        if br.any():
            if first_lat is None:
                first_lat = lat[br]
            course.append(((step - step0) * dt, int(br.sum()), float(lat[br].min()), float(lat[br].max())))
    for step, cols, d in frames:
        _, _, _, _, lat, br = _frame(cols, d)
        if br.any() and not dense:
            if first_lat is None:
                first_lat = lat[br]
            course.append(((step - step0) * dt, int(br.sum()), float(lat[br].min()), float(lat[br].max())))
        elif br.any() and (not course or (step - step0) * dt > course[-1][0]):
            course.append(((step - step0) * dt, int(br.sum()), float(lat[br].min()), float(lat[br].max())))
    return first_lat, course


def escapes(frames, dt, step0, margin):
    """Per frame with fluid outside the wall: (time after step0, particles outside, their median
    speed, its 90th percentile)."""
    speeds = []
    for step, cols, d in frames:
        c, w, pos, centre, _, _ = _frame(cols, d)
        fl = d[:, c["type"]] == 2
        out = _outside(pos[w], pos[fl], centre, margin)
        v = d[:, [c["vx"], c["vy"], c["vz"]]][fl][out]
        if len(v):
            speeds.append(((step - step0) * dt, int(out.sum()), float(np.median(np.linalg.norm(v, axis=1))),
                           float(np.percentile(np.linalg.norm(v, axis=1), 90))))
    return speeds
