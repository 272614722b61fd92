# SPDX-License-Identifier: GPL-2.0-or-later
"""Readers and analysis helpers for the tissue experiments (tools/tissue.sh, tools/cellmech/tissue/report.py).

Units are LAMMPS units micro: um, us, pg, nN, kPa; energy nN um = 1e-15 J (fJ); Gc in pg/us^2
(1000 pg/us^2 = 1 J/m^2), so Gc x area (um^2) is in nN um as well.
"""
import json
import os

import numpy as np

from .. import reporting
from ..launch import stage_times
from ..quasistatic import KE, WORK


def fmt(x, nd=3):
    """A number of the tissue reports: nd significant digits, integers whole, "-" where missing."""
    return reporting.fmt(x, nd, missing="-", exact_ints=True)


def pct(x, nd=3):
    """A fraction as a percentage of the tissue reports ("-" where missing)."""
    return reporting.percent(x, nd)


def span(xs, unit=""):
    """'lo-hi' of the numbers (one value where they print alike), with the unit."""
    lo, hi = fmt(min(xs)), fmt(max(xs))
    return (lo if lo == hi else f"{lo}-{hi}") + unit


def and_list(words):
    """'a', 'a and b', 'a, b and c'."""
    words = list(words)
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]

# fix ave/time files of the inputs (after the step column); COMPRESS ends with the kinetic energy and
# the plate's work of the quasi-static check (cellmech.quasistatic; records older than issue 29
# lack them and load() reads them as zeros)
COMPRESS = ["time_us", "strain", "stress_kPa", "F_top_nN", "F_bottom_nN", "P_mean_kPa", "P_min_kPa",
            "P_max_kPa", "fluid_mass_pg", "broken_tethers", "debonded_bonds", "debonded_area_um2",
            "glued_area_um2", KE, WORK]
# in.tissue-tension writes the same layout: the grips take the plates' columns (stress and forces
# positive in tension, the top grip's work as the plate's), so the quasi-static check reads both
TENSION = COMPRESS
LEAKS = ["time_us", "strain", "leaked_particles"]
INFLATE = ["time_us", "volume_um3", "fluid_mass_pg", "P_mean_kPa", "P_min_kPa", "P_max_kPa",
           "stretch_mean", "lamella_bonds", "glued_area_um2", "broken_tethers", "debonded_bonds"]
PRESS = ["time_us", "strain", "F_top_nN", "F_bottom_nN", "P1_kPa", "P2_kPa", "contact_area_um2",
         "glued_area_um2", "F_interface_nN", "debonded_bonds", "debonded_area_um2"]
PULL = ["separation_um", "F_pull_nN", "F_hold_nN", "P1_kPa", "P2_kPa", "contact_area_um2",
        "glued_area_um2", "F_interface_nN", "lamella_bonds", "debonded_bonds", "debonded_area_um2"]
# compute cell/props (17) and cell/contacts (11) columns
PROPS = ["volume", "wall_area", "pressure", "fluid_mass", "fluid_count", "stretch_mean", "stretch_max",
         "F_equator", "leaked", "cx", "cy", "cz", "broken_tethers", "lamella_bonds", "glued_area",
         "debonded_bonds", "debonded_area"]
PAIRS = ["i", "j", "lamella_bonds", "glued_area", "debonded_bonds", "debonded_area", "F_lamella",
         "F_contact", "contacts", "contact_area", "distance"]


def load(path, cols):
    """A fix ave/time scalar file as {name: column}, with 'step'."""
    a = np.loadtxt(path, comments="#", ndmin=2)
    d = {"step": a[:, 0]}
    for k, name in enumerate(cols):
        d[name] = a[:, k + 1] if a.shape[1] > k + 1 else np.zeros(len(a))
    return d


def load_table(path):
    """A fix ave/time mode vector file: list of (step, rows array without the row index)."""
    out = []
    with open(path) as f:
        lines = [ln for ln in f if not ln.startswith("#")]
    i = 0
    while i < len(lines):
        w = lines[i].split()
        i += 1
        if len(w) != 2:
            continue
        step, n = int(float(w[0])), int(w[1])
        rows = [list(map(float, lines[i + k].split()[1:])) for k in range(n)]
        i += n
        out.append((step, np.array(rows) if rows else np.zeros((0, 1))))
    return out


def write_csv(path, d, cols, header=""):
    a = np.column_stack([d[c] for c in cols])
    np.savetxt(path, a, delimiter=",", header=(header + "\n" if header else "") + ",".join(cols),
               comments="# " if header else "", fmt="%.8g")


def smooth(y, n):
    """Centred moving average over n samples (edges padded with the end values)."""
    n = int(n)
    if n < 2 or len(y) < n:
        return np.asarray(y, float).copy()
    pad = np.pad(y, (n // 2, n - 1 - n // 2), mode="edge")
    return np.convolve(pad, np.ones(n) / n, mode="valid")


def first_rise(x, count):
    """x at the first record where a cumulative count exceeds its starting value (None if never)."""
    k = np.nonzero(count > count[0] + 0.5)[0]
    return (float(x[k[0]]), int(k[0])) if len(k) else (None, None)


# the turgor "at the start" of a loading: over its first half percent of strain, the first half of
# the smooth start (the block hardly loaded: its turgor rises by 2 kPa over the first 2% of a
# compression)
START_STRAIN = 0.005


def start_pressure(d, upto=START_STRAIN):
    """The block's mean turgor as its loading begins: the median of P_mean_kPa over the records up
    to `upto` of strain past the first. The first record alone is no measure: under respa it reads
    several percent low (336 kPa against 361-364 kPa in the next five records of a block at Pi -364
    kPa, respa 5), single level it agrees with the next."""
    e = np.asarray(d["strain"], float)
    return float(np.median(np.asarray(d["P_mean_kPa"], float)[np.abs(e - e[0]) <= upto]))


def gen_stats(path):
    with open(path) as f:
        return json.load(f)


times = stage_times


def integral(y, x):
    y, x = np.asarray(y, float), np.asarray(x, float)
    if len(x) < 2:
        return 0.0
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(x)))


def dominant_period(y, dx, longest=None):
    """Period (in units of dx) of the strongest oscillation of y about its running trend (the trend: a
    moving average over a quarter of the record), periods up to `longest` (default a third of it)."""
    y = np.asarray(y, float)
    n = len(y)
    if n < 16:
        return None
    r = y - smooth(y, max(2, n // 4))
    P = np.abs(np.fft.rfft(r * np.hanning(n))) ** 2
    f = np.fft.rfftfreq(n, dx)
    longest = longest or n * dx / 3
    m = (f > 1.0 / longest)
    if not m.any():
        return None
    return float(1.0 / f[m][np.argmax(P[m])])


def failure(d, window=0.01):
    """The failure of a pull (in.tissue-tension's record, TENSION columns): the stress smoothed over
    `window` of strain (longer than the walls' ringing, shorter than the failure), its peak (the
    failure stress) and the strain there, and the failure mode: which kind of event, broken tethers
    (wall rupture) or debonded lamella bonds (cells coming apart), begins first and how many of
    each there are up to the peak and to the end. Counts are from the record's start (bonds that
    let go before it, in the inflation or a hold, are not the pull's)."""
    ds = np.median(np.diff(d["strain"])) if len(d["strain"]) > 1 else 1.0
    s = smooth(d["stress_kPa"], max(1, int(round(window / ds))))
    k = int(np.argmax(s))
    out = dict(smoothed=s, peak_kPa=float(s[k]), strain_at_peak=float(d["strain"][k]), peak_index=k)
    first = {}
    for kind, col in (("wall rupture", "broken_tethers"), ("lamella debonding", "debonded_bonds")):
        c = np.asarray(d[col], float) - d[col][0]
        out[col + "_to_peak"] = int(round(c[k]))
        out[col] = int(round(c[-1]))
        rise = np.nonzero(c > 0.5)[0]
        if len(rise):
            first[kind] = float(d["strain"][rise[0]])
    out["first"] = first
    # the mode: the kind that begins first; a tie (the same record) goes to the larger count at the peak
    if not first:
        out["mode"] = "none (no wall ruptured, no lamella bond let go)"
    else:
        count = {"wall rupture": out["broken_tethers_to_peak"],
                 "lamella debonding": out["debonded_bonds_to_peak"]}
        out["mode"] = min(first, key=lambda m: (first[m], -count[m]))
    # the stress after the peak: the record's last smoothed value against the peak (a failure drops)
    out["final_kPa"] = float(s[-1])
    return out


# compute cell/props columns (after the row index) of a per-cell table: centroid z, broken tethers,
# debonded lamella bonds
CELL_ZC, CELL_NBROKEN, CELL_NDEBONDED = 11, 12, 15


def failure_where(path, pairs=None, held=None):
    """Where a block failed, from its per-cell table (fix ave/time of compute cell/props): for each
    kind of failure, the cells in which it happened by layer along z (bottom, middle, top thirds of
    the cells' centroids at the start; bottom and top for two layers): {kind: {layer: cells}}, the
    counts from the table's first record, and the number of layers (2 or 3). The bottom and top
    layers are the plates' or the grips'. With the per-pair table (compute cell/contacts), also the
    debonded bonds by interface between layers: {"bottom-middle": bonds, ...}, and with held (the
    cell IDs the jaws hold whole) by whether the grips hold the cells: {"held-free": bonds, ...}."""
    if not os.path.exists(path):    # a run without per-cell tables
        return {}
    rows = load_table(path)
    if len(rows) < 2:
        return {}
    first, last = rows[0][1], rows[-1][1]
    z = first[:, CELL_ZC]
    layers = len(np.unique(np.round((z - z.min()) / max(np.ptp(z), 1e-9) * 2))) if len(z) > 1 else 1
    cut = np.quantile(z, [1 / 3, 2 / 3]) if layers >= 3 else np.array([np.median(z)])
    names = ("bottom", "middle", "top") if layers >= 3 else ("bottom", "top")
    layer = np.digitize(z, cut)
    out = dict(layers=len(names), kinds={})
    for kind, col in (("wall rupture", CELL_NBROKEN), ("lamella debonding", CELL_NDEBONDED)):
        hit = (last[:, col] - first[:, col]) > 0
        if hit.any():
            out["kinds"][kind] = {names[k]: int((hit & (layer == k)).sum()) for k in range(len(names))
                                  if (hit & (layer == k)).any()}
    if pairs and os.path.exists(pairs) and "lamella debonding" in out["kinds"]:
        out["interfaces"] = debond_interfaces(pairs, layer, names)
        if held is not None:
            out["held_interfaces"] = debond_interfaces(
                pairs, [0 if c + 1 in held else 1 for c in range(len(z))], ("held", "free"))
    return out


def held_cells(path):
    """The cells in.tissue-tension's jaws cells hold whole (its write_dump of their wall nodes'
    molecule IDs), or None where the file is not there (jaws nodes, or an older run)."""
    if not os.path.exists(path):
        return None
    return set(np.loadtxt(path, skiprows=9, ndmin=1).astype(int).tolist())


def debond_interfaces(pairs, layer, names):
    """{"bottom-middle": debonded lamella bonds, ...}: the bonds that let go during the run, by the
    layers (layer: one index into names per cell, in cell order) of the two cells they glued, from
    the per-pair table; bottom first."""
    rows = load_table(pairs)
    col, at = PAIRS.index("debonded_bonds"), {}
    for r in rows[0][1]:
        at[int(r[0]), int(r[1])] = r[col]
    out = {}
    for r in rows[-1][1]:
        i, j = int(r[0]), int(r[1])
        n = r[col] - at.get((i, j), 0.0)
        if n > 0:
            key = tuple(sorted((layer[i - 1], layer[j - 1])))
            out[key] = out.get(key, 0) + int(round(n))
    return {f"{names[a]}-{names[b]}": out[a, b] for a, b in sorted(out)}
