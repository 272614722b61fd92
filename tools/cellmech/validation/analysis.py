# SPDX-License-Identifier: GPL-2.0-or-later
"""Reading the measured quantity out of a run's time series (shared by the validation cases and
the tests)."""
import math

import numpy as np

from ..cellgen.datafile import read_data


def crossing_period(t, r, r0, nper):
    """Period from the crossings of the rest radius r0 (both directions) over the first nper
    periods. A tether network has no bending stiffness: in the compressive half cycle short-wave
    buckling modes grow from round-off and, after a few periods, crumple the wall (the mean
    radius then drifts below r0). The breathing mode is measured before that.
    A sample exactly at r0 (the output has 6 digits) counts as below it, so no crossing is lost."""
    y = r - r0
    above = y > 0
    idx = np.where(above[:-1] != above[1:])[0]
    tc = t[idx] - y[idx] * (t[idx + 1] - t[idx]) / (y[idx + 1] - y[idx])
    if len(tc) < 2 * nper + 1:
        raise RuntimeError(f"fewer than {nper} periods recorded")
    return (tc[2 * nper] - tc[0]) / nper


def strongest_modes(peaks, n):
    """The n strongest spectral peaks [(omega, amplitude)], returned in increasing frequency."""
    return sorted(p[0] for p in sorted(peaks, key=lambda p: -p[1])[:n])


def windowed(x, y, centres, half):
    """Mean of y over |x - centre| < half for each centre (NaN where the window is empty)."""
    out = []
    for c in centres:
        sel = np.abs(x - c) < half
        out.append(float(y[sel].mean()) if sel.any() else float("nan"))
    return np.array(out)


def windowed_curve(x, centres, half, xs, ys):
    """A reference curve (xs, ys) seen through windowed(x, ., centres, half): its values at the
    records x, averaged over the same windows. A window's mean of a curved force is not the force
    at the window's centre (for F ~ eps^n it lies above it by about n (n - 1) / 6 (half / eps)^2:
    +4% at half / eps = 0.2 and n = 3), and the records in a window do not centre on it (their
    mean strain is up to half a record spacing off), so a windowed simulation is compared with
    its reference windowed alike. NaN where a window is empty or reaches past the curve."""
    x = np.asarray(x, dtype=float)
    y = np.interp(x, xs, ys, left=np.nan, right=np.nan)
    return windowed(x, y, centres, half)


def energy_balance(t, ke, e):
    """(largest deviation of the total energy from its start, secular drift = slope of a linear
    fit times the run time), both per the largest kinetic energy."""
    dev = np.abs(e - e[0]).max() / ke.max()
    slope = np.polyfit(t, e, 1)[0]
    drift = abs(slope) * (t[-1] - t[0]) / ke.max()
    return dev, drift


def sheet_membrane_width(path, orient):
    """Reference width W of a cellgen.py sheet for the membrane wall's force per width P W, from
    its data file (positions and triangles). A homogeneous stretch is exact for constant-strain
    elements and in equilibrium with the sheet's borders (a zigzag border's two segments at a node
    have opposite normals: their tractions cancel node by node), so:
     * bonds along X: the free sides are straight rows, every cut across the sheet spans them:
       W = y_max - y_min;
     * bonds along Y: the pulled and held edges are straight columns, the only nodes of their
       groups in in.sheet (column spacing a sqrt3/2 > 0.6 a), so the pull's work F (x_max - x_min)
       d lam is the energy's change A0 G t0 dw: W = A0 / (x_max - x_min), A0 the triangles' area."""
    data = read_data(path)
    pos = {int(w[0]): np.array([float(w[3]), float(w[4])]) for w in data.rows("Atoms")}
    tri = [tuple(int(v) for v in w[2:5]) for w in data.rows("Angles")]
    xy = np.array(list(pos.values()))
    if orient == "x":
        return float(np.ptp(xy[:, 1]))
    area = sum(0.5 * abs((pos[b][0] - pos[a][0]) * (pos[c][1] - pos[a][1]) -
                         (pos[b][1] - pos[a][1]) * (pos[c][0] - pos[a][0])) for a, b, c in tri)
    return float(area / np.ptp(xy[:, 0]))


def read_dump_frames(path):
    """Frames of a LAMMPS `dump custom ... id x y z` sorted by id: [(step, xyz (N x 3))]."""
    frames, lines = [], open(path).read().split("\n")
    i = 0
    while i < len(lines) and lines[i].startswith("ITEM: TIMESTEP"):
        step, n = int(lines[i + 1]), int(lines[i + 3])
        rows = np.array([l.split() for l in lines[i + 9:i + 9 + n]], dtype=float)
        frames.append((step, rows[np.argsort(rows[:, 0]), 1:4]))
        i += 9 + n
    return frames


def degree_spectrum(xyz, lmax):
    """Power per spherical-harmonic degree l = 0..lmax of the radial displacement r - mean(r) of
    nodes spread evenly over a sphere centred at the origin (a geodesic wall: equal quadrature
    weights 4 pi / N, accurate for l well below the mesh's resolution, about sqrt(N)). The fully
    normalised associated Legendre functions come from the standard recurrences in l at fixed m
    (stable, one pass per m)."""
    r = np.linalg.norm(xyz, axis=1)
    f = (r - r.mean()) * (4 * math.pi / len(r))
    x = xyz[:, 2] / r
    sx = np.sqrt(np.maximum(0.0, 1 - x * x))
    ph = np.arctan2(xyz[:, 1], xyz[:, 0])
    out = np.zeros(lmax + 1)
    pmm = np.full_like(x, math.sqrt(1 / (4 * math.pi)))
    for m in range(lmax + 1):
        if m > 0:
            pmm = -math.sqrt((2 * m + 1) / (2 * m)) * sx * pmm
        # real harmonics: sqrt2 cos(m phi), sqrt2 sin(m phi) for m > 0
        parts = [f] if m == 0 else [math.sqrt(2) * f * np.cos(m * ph), math.sqrt(2) * f * np.sin(m * ph)]
        p2, p1 = None, pmm
        for l in range(m, lmax + 1):
            if l == m + 1:
                p2, p1 = p1, math.sqrt(2 * m + 3) * x * p1
            elif l > m + 1:
                a = math.sqrt((4 * l * l - 1) / (l * l - m * m))
                b = math.sqrt(((l - 1) ** 2 - m * m) / (4 * (l - 1) ** 2 - 1))
                p2, p1 = p1, a * (x * p1 - b * p2)
            out[l] += sum(float(np.dot(g, p1)) ** 2 for g in parts)
    return out


def buckle_wavelength(power, R):
    """Wavelength 2 pi R / sqrt(l (l + 1)) of the power-weighted mean degree over l >= 2 (l = 0 is
    the breathing, l = 1 a rigid shift), and that mean degree."""
    l = np.arange(len(power))
    sel = l >= 2
    lbar = float((l[sel] * power[sel]).sum() / power[sel].sum())
    return 2 * math.pi * R / math.sqrt(lbar * (lbar + 1)), lbar
