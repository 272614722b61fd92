# SPDX-License-Identifier: GPL-2.0-or-later
"""Reading the measured quantity out of a run's time series (shared by the validation cases and
the tests)."""
import numpy as np


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


def energy_balance(t, ke, e):
    """(largest deviation of the total energy from its start, secular drift = slope of a linear
    fit times the run time), both per the largest kinetic energy."""
    dev = np.abs(e - e[0]).max() / ke.max()
    slope = np.polyfit(t, e, 1)[0]
    drift = abs(slope) * (t[-1] - t[0]) / ke.max()
    return dev, drift
