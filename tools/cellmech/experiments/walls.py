# SPDX-License-Identifier: GPL-2.0-or-later
"""The paper's experiments with two walls side by side: the tether network (the paper's, the
committed report docs/experiments.md) and the Neo-Hookean membrane (WALL=membrane
tools/experiments.sh), for relaxation, impact and failure, each beside the paper's result and the
reason for each difference.

  python3 -m cellmech.experiments.report --membrane RUNDIR --report REPORTDIR

writes the section "## Membrane wall" into REPORTDIR/experiments.md (in place of an existing one,
else before "## Plots and pictures"); the rest of the report stays as it is. The tether column
is read from that report's own tables, so the tether runs (an hour of one core) need not be
there; the membrane column is measured from RUNDIR with the same functions (analyse.py).
"""
import math
import os
import re

import numpy as np

from .. import params
from .. import reporting as rp
from . import analyse as A

TITLE = "## Membrane wall"
WALLS = ("membrane", "bending")     # the walls that get a section beside the tether report
# where the section goes in a report that has none yet
BEFORE = "## Plots and pictures"
LAMF = 1.04
NAN = float("nan")


# ---------------------------------------------------------------- numbers of the committed report
def num(s):
    """The first number in s (nan when there is none, e.g. 'n/a')."""
    m = re.search(r"[-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?", s or "")
    return float(m.group(0)) if m else NAN


def md_tables(text):
    """Tables of a markdown report, keyed by the bold title before each (the first words of a
    '**Title** ...' line) or, for the summary table, by '## <heading>': list of dicts per row."""
    out, key, lines = {}, None, text.split("\n")
    k = 0
    while k < len(lines):
        ln = lines[k]
        if ln.startswith("**"):
            key = ln[2:].split("**")[0]
        elif ln.startswith("## "):
            key = ln
        elif ln.startswith("|") and key is not None and key not in out:
            head = [c.strip() for c in ln.strip().strip("|").split("|")]
            rows = []
            k += 2    # the |---| line
            while k < len(lines) and lines[k].startswith("|"):
                cells = [c.strip() for c in lines[k].strip().strip("|").split("|")]
                rows.append(dict(zip(head, cells)))
                k += 1
            out[key] = rows
            continue
        k += 1
    return out


def _relax_row(r):
    return dict(t_first=num(r["t_first (us)"]), tau_e=num(r["tau_e (us)"]), tau_fit=num(r["tau_fit (us)"]),
                period=num(r["period (us)"]), crossings=int(num(r["sign changes"])), regime=r["regime"])


def tether_numbers(text):
    """The numbers of a report written by report.py main() (the tether wall), in the form of
    measure()."""
    T = md_tables(text)
    N = dict(relax={}, shear={}, transmitted={}, failure={})
    for cell in ("stiff", "soft"):
        for r in T.get(f"Relaxation, {cell} cell", []):
            N["relax"][(cell, r["case"].split()[0])] = _relax_row(r)
    shear = next((v for k, v in T.items() if k.startswith("Impact-zone shear stress")), [])
    for r in shear:
        for m in (1, 10, 100, 1000):
            v = r.get(f"{m} mPa s 4% / 10%", "n/a").split("/")
            if len(v) == 2 and math.isfinite(num(v[0])):
                N["shear"][(r["cell"], m)] = (num(v[0]), num(v[1]))
    for r in T.get("Failure", []):
        lat = re.findall(r"[-+]?\d+(?:\.\d*)?", r.get("first broken nodes: mean latitude (range)", ""))
        span = re.findall(r"[-+]?\d+(?:\.\d*)?", r.get("span after 0.2 us, speed of its ends", ""))
        jet = r.get("escaping fluid median / 90th pct speed", "").split(" / ")
        N["failure"][r["run"]] = dict(
            eps_f=num(r["eps_f"]) / 100, lat=float(lat[0]) if lat else NAN,
            lat_range=(float(lat[1]), float(lat[2])) if len(lat) >= 3 else None,
            span=(float(span[0]), float(span[1])) if len(span) >= 3 else None,
            speed=float(span[2]) if len(span) >= 3 else NAN,
            n_final=num(r.get("broken tethers at end")), t_90=num(r.get("90% of them after")),
            jet=(num(jet[0]), num(jet[1])) if len(jet) == 2 else (NAN, NAN))
    summary = next((v for k, v in T.items() if k == "## Paper against ours"), [])
    for r in summary:
        g = re.search(r"membrane theory .*?([\d.]+) uN \(Neo-Hookean\), ([\d.]+) uN \(tether-network law\)",
                      r.get("ours", ""))
        if r.get("experiment", "").startswith("compression: force at eps") and g:
            N["theory"] = dict(neohookean=float(g.group(1)), network=float(g.group(2)))
            N["f19"] = num(r["ours"]) * 1e3
        m = re.match(r"impact (stiff|soft): transmitted force", r.get("experiment", ""))
        if m:
            s = r["ours"]
            g = re.search(r"reaches ([\d.e+-]+) nN .*?([-+][\d.]+)% strain later.*?eps = (\d+)\+-1%: "
                          r"impact ([\d.e+-]+) nN, quasistatic ([\d.e+-]+) nN", s)
            if g:
                N["transmitted"][m.group(1)] = dict(level=float(g.group(1)), lag=float(g.group(2)) / 100,
                                                    eps=float(g.group(3)) / 100, f_imp=float(g.group(4)),
                                                    f_qs=float(g.group(5)))
    return N


# ---------------------------------------------------------------- numbers of a run folder
def _ok(run, stage):
    p = os.path.join(run, "times.txt")
    if not os.path.exists(p):
        return False
    return any(ln.split()[:1] == [stage] and ln.split()[-1] == "ok" for ln in open(p))


def shape_relaxation(a):
    """The relaxation (analyse.relaxation) of the cell's shape anisotropy, height minus width H - W
    (in.relax's columns): zero for the free cell by its symmetry, so it needs no reference value
    from another run, and it swings through zero each time the cell goes from oblate to prolate."""
    t, d = a[:, A.REL["t"]], a[:, A.REL["h"]] - a[:, A.REL["w"]]
    r = A.relaxation(t, d, 0.0)
    r["regime"] = "oscillating" if r["crossings"] >= 2 else "overdamped"
    # the first overshoot x (the largest excursion past zero, relative to the start, smoothed as
    # relaxation() does) gives the damping ratio of a damped oscillator, ln(1/x) / sqrt(pi^2 + ln^2 x)
    n = max(1, int(round(0.02 * (t[-1] - t[0]) / (t[1] - t[0]))) | 1)
    ds = A.smooth(d, n)
    past = np.nonzero(np.sign(ds) != np.sign(ds[0]))[0]
    r["overshoot"] = float(np.max(np.abs(ds[past[0]:][np.sign(ds[past[0]:]) != np.sign(ds[0])])) / abs(ds[0])) \
        if len(past) else 0.0
    x = r["overshoot"]
    r["zeta"] = math.log(1 / x) / math.sqrt(math.pi ** 2 + math.log(x) ** 2) if 0 < x < 1 else NAN
    # the swing after the overshoot, relative to it (a linear oscillator keeps x of each swing in the
    # next); open: the record ends inside that swing, so the ratio is a lower bound
    sg = np.sign(ds)
    flips = np.nonzero(sg[1:] != sg[:-1])[0] + 1
    r["swing2"], r["swing2_open"] = NAN, False
    if len(flips) >= 2 and x > 0:
        first = np.max(np.abs(ds[flips[0]:flips[1]]))
        end = flips[2] if len(flips) >= 3 else len(ds)
        r["swing2"] = float(np.max(np.abs(ds[flips[1]:end])) / first)
        r["swing2_open"] = len(flips) < 3
    return r


def measure(run, r0=1.6, dt=0.001):
    """The same numbers as tether_numbers() from the files of a run folder of tools/experiments.sh
    (stages that did not finish are left out)."""
    N = dict(relax={}, shear={}, transmitted={}, failure={})
    for cell, cases in (("stiff", ("1", "10", "100", "1000", "zeta")), ("soft", ("1", "10", "100"))):
        load = os.path.join(run, f"{cell}-compressed.restart.load.dat")
        f_inf = float(np.mean(A.load(load)[:5, A.CMP["feq"]])) if os.path.exists(load) else NAN
        for lab in cases:
            if not _ok(run, f"relax-{cell}-{lab}"):
                continue
            a = A.load(os.path.join(run, f"relax-{cell}-{lab}.dat"))
            r = A.relaxation(a[:, A.REL["t"]], a[:, A.REL["feq"]], f_inf)
            r["regime"] = "oscillating" if r["crossings"] >= 2 else "overdamped"
            r["shape"] = shape_relaxation(a)
            r["t_end"] = float(a[-1, A.REL["t"]] - a[0, A.REL["t"]])
            N["relax"][(cell, lab)] = r
    if _ok(run, "compress-0.5"):
        # as report.py: the mean of both plates over eps = 18-20%
        c = A.load(os.path.join(run, "compress-0.5.dat"))
        N["f19"] = A.window_mean(c[:, A.CMP["eps"]], 0.5 * (c[:, A.CMP["ftop"]] + c[:, A.CMP["fbot"]]),
                                 0.19, 0.01)[0]
    for cell, qs in (("stiff", "compress-0.5"), ("soft", "compress-soft")):
        for m in (1, 10, 100, 1000):
            p = os.path.join(run, f"impact-{cell}-{m}.dat")
            if not (os.path.exists(p) and _ok(run, f"impact-{cell}-{m}")):
                continue
            a = A.load(p)
            N["shear"][(cell, m)] = (1e3 * A.impact_shear(a, 0.04)[0], 1e3 * A.impact_shear(a, 0.10)[0])
            if m == 1 and _ok(run, qs):
                N["transmitted"][cell] = A.transmitted(a, A.load(os.path.join(run, qs + ".dat")))
            elif m == 1:
                # no quasistatic run: the impact's own force at 19%
                e = a[:, A.IMP["eps"]]
                N["transmitted"][cell] = dict(level=NAN, lag=NAN, eps=0.19, f_qs=NAN,
                                              f_imp=A.window_mean(e, a[:, A.IMP["fbot"]], 0.19, 0.01)[0])
    for lab in ("qs", "impact-1", "impact-1000"):
        p = os.path.join(run, f"failure-{lab}.dat")
        if not (os.path.exists(p) and _ok(run, f"failure-{lab}")):
            continue
        # the run's own time step and r0 where tools/experiments.sh recorded them (settings.json)
        s = params.recorded_settings(run, f"log.failure-{lab}") or dict(r0=r0, dt=dt)
        f = A.failure(p, p[:-4] + ".dump", float(s["dt"]), float(s["r0"]))
        N["failure"][lab] = dict(
            eps_f=f["eps_f"], lat=f.get("lat_first_mean", NAN), lat_range=f.get("lat_first_range"),
            span=f.get("span_02"), speed=f.get("crack_speed", NAN), n_final=f.get("n_final", NAN),
            t_90=f.get("t_90", NAN), jet=(f.get("jet_median", NAN), f.get("jet_p90", NAN)))
        a = A.load(p)
        N["failure"][lab].update(after_burst(a), series=(a[:, A.IMP["eps"]], a[:, A.IMP["nbroken"]]))
    return N


def after_burst(a):
    """What the wall does once the cell has burst (in.failure's table): the largest edge (tether)
    stretch in the sample before the first failure (lam_edge_f), and, from the first sample whose
    pressure is below a tenth of that before the failure on, the elements that still fail per 1%
    of strain (rate_after) and the largest edge stretch meanwhile (lam_edge_after)."""
    nb, i = a[:, A.IMP["nbroken"]], np.nonzero(a[:, A.IMP["nbroken"]] > 0)[0]
    out = dict(lam_edge_f=NAN, rate_after=NAN, lam_edge_after=NAN)
    if not len(i) or i[0] == 0:
        return out
    out["lam_edge_f"] = float(a[i[0] - 1, A.IMP["lammax"]])
    p_f = a[i[0] - 1, A.IMP["p"]]
    j = np.nonzero((np.arange(len(a)) > i[0]) & (a[:, A.IMP["p"]] < 0.1 * p_f))[0]
    if len(j) and a[-1, A.IMP["eps"]] > a[j[0], A.IMP["eps"]]:
        e = a[:, A.IMP["eps"]]
        out["rate_after"] = float((nb[-1] - nb[j[0]]) / (100 * (e[-1] - e[j[0]])))
        out["lam_edge_after"] = float(a[j[0]:, A.IMP["lammax"]].max())
    return out


# ---------------------------------------------------------------- the continuum reference
def continuum_stretch(eps_list, material="neohookean"):
    """Where a continuous wall of the same law is stretched most: the inflated Neo-Hookean (or
    tether-network) membrane of the stiff cell between frictionless plates (tools/cellmech/
    membrane.py), at each strain the largest principal stretch, which of the two it is, its
    latitude (current, seen from the centre, as analyse.failure measures it) and that of the
    contact edge; and the strain at which that stretch reaches LAMF."""
    from .. import membrane as M
    p = params.stiff()
    c = M.Curve(p["G"] * p["t0"], params.CELL["R"], p["P"], bulk_modulus=7.0e4, material=material)
    out, lam_prev, e_prev, eps_lamf = [], None, None, NAN
    for eps in sorted(set(eps_list) | set(np.arange(0.10, 0.241, 0.01).round(3))):
        c.advance(eps)
        _, slack, sol = c.state
        thc = sol.p[1]
        tau = np.linspace(0.0, 1.0, 4001)
        Y = sol.sol(tau)
        th = thc + (M.HALF_PI - thc) * tau     # the free meridian (the disc is stretched less)
        l2, l1, z = Y[2], Y[3], Y[5]
        i = int(np.argmax(np.maximum(l1, l2)))
        lam = float(max(l1[i], l2[i]))
        lat = lambda k: math.degrees(math.atan2(z[k], math.sin(th[k]) * l2[k]))
        if eps in eps_list:
            out.append(dict(eps=eps, lam=lam, kind="hoop" if l2[i] >= l1[i] else "meridional",
                            lat=lat(i), lat_edge=lat(0), lam_eq=float(max(l1[-1], l2[-1]))))
        if lam_prev is not None and lam_prev < LAMF <= lam and not math.isfinite(eps_lamf):
            eps_lamf = e_prev + (LAMF - lam_prev) / (lam - lam_prev) * (eps - e_prev)
        lam_prev, e_prev = lam, eps
    return out, eps_lamf


# ---------------------------------------------------------------- the side-by-side table
def f3(x, unit=""):
    s = rp.fmt(x)
    return s if s == "n/a" else s + unit


def swing(r):
    """The next swing relative to the overshoot, '>= x' when the record ends inside it."""
    if not math.isfinite(r.get("swing2", NAN)):
        return "n/a"
    return f"{'>= ' if r['swing2_open'] else ''}{100 * r['swing2']:.0f}%"


def regimes(N, cell, cases):
    osc = [m for m in cases if (cell, m) in N["relax"] and N["relax"][(cell, m)]["regime"] == "oscillating"]
    od = [m for m in cases if (cell, m) in N["relax"] and N["relax"][(cell, m)]["regime"] == "overdamped"]
    if not osc and not od:
        return "n/a"
    return "; ".join(f"{what} at {', '.join(ms)} mPa s" for what, ms in (("oscillating", osc), ("overdamped", od))
                     if ms)


def compare_rows(T, M, cont=None, label="membrane"):
    """Rows (quantity, tether, membrane, paper, why) from the numbers of both walls (tether_numbers,
    measure) and, for failure, the continuum reference (continuum_stretch at each failure strain).
    Each 'why' is worked out from the numbers it stands beside."""
    return (relax_stiff_rows(T, M, label) + relax_soft_rows(T, M, label) + compression_rows(T, M, label)
            + transmitted_rows(T, M, label) + shear_rows(T, M, label) + failure_rows(T, M, cont, label))


def relax_stiff_rows(T, M, label):
    """The stiff cell's relaxation: its period at 1 mPa s, and its damping regime."""
    rows = []
    rT, rM = T["relax"], M["relax"]
    k = ("stiff", "1")
    if k in rT and k in rM:
        pt, pm = rT[k]["period"], rM[k]["period"]
        ratio = pm / pt if pt > 0 else NAN
        # the mode's stiffness k = k_area + k_shear: the area stiffness is the same in both walls
        # (equibiaxial law), the tether net's shear stiffness 1.5x the sheet's; so the stiffness
        # ratio tether/membrane q = (period ratio)^2 gives the shear part 2 (q - 1) of the sheet's k
        q = ratio ** 2
        why = (f"period {label}/tether {ratio:.2f}: the tether wall's mode is {q:.2f}x stiffer; with the "
               "same area stiffness and the tether net's 1.5x shear modulus, the shear part of the "
               f"mode's stiffness is 2 (q - 1) = {200 * (q - 1):.0f}% of the {label}'s")
        if math.isfinite(ratio):
            why += ("; so the prolate-oblate mode is set by the wall's shear stiffness"
                    if abs(ratio - math.sqrt(1.5)) < 0.05 else
                    f" (shear alone would give sqrt(1.5) = {math.sqrt(1.5):.2f}): the mode also stretches "
                    "the wall's area")
            why += ("; the softer sheet lengthens the period, so the paper's shorter one (< 1 us) is not "
                    "the wall law" if ratio > 1 else "")
        rows.append(("relaxation stiff, 1 mPa s: period, tau_e (us)",
                     f"{f3(pt)}, {f3(rT[k]['tau_e'])}", f"{f3(pm)}, {f3(rM[k]['tau_e'])}",
                     "relaxes in ~1 us, then oscillates, period < 1 us", why))
    cs = ["1", "10", "100", "1000"]
    if any(("stiff", m) in rM for m in cs):
        ran = [m for m in cs if ("stiff", m) in rM]
        same = all(rT.get(("stiff", m), {}).get("regime") == rM[("stiff", m)]["regime"] for m in ran)
        rows.append(("relaxation stiff: damping regime", regimes(T, "stiff", cs), regimes(M, "stiff", cs),
                     "oscillates at 1 mPa s, overdamped above ~0.5 Pa s",
                     ("the same regime at every viscosity run with both walls" if same else
                      "the regimes differ at " + ", ".join(m for m in ran if rT.get(("stiff", m), {}).get("regime")
                                                             != rM[("stiff", m)]["regime"]) + " mPa s")
                     + f" ({label} run at {', '.join(ran)} mPa s)"))
    return rows


def relax_soft_rows(T, M, label):
    """The soft cell's relaxation: its first return at 1 mPa s, and its damping regime
    (F_eq and the shape H - W)."""
    rows = []
    rT, rM = T["relax"], M["relax"]
    k = ("soft", "1")
    if k in rT and k in rM:
        rows.append(("relaxation soft, 1 mPa s: t_first, tau_e (us)",
                     f"{f3(rT[k]['t_first'])}, {f3(rT[k]['tau_e'])}", f"{f3(rM[k]['t_first'])}, {f3(rM[k]['tau_e'])}",
                     "30 us", f"t_first {label}/tether {rM[k]['t_first'] / rT[k]['t_first']:.2f}"
                     + (", where the stiff cell's period differs by "
                        f"{rM[('stiff', '1')]['period'] / rT[('stiff', '1')]['period']:.2f}"
                        if ("stiff", "1") in rM and ("stiff", "1") in rT else "")
                     + (": the soft cell's first swing back does not follow the wall law" if
                        abs(rM[k]["t_first"] / rT[k]["t_first"] - 1) < 0.05 else "")))
    sc = ["1", "10", "100"]
    if any(("soft", m) in rM for m in sc):
        both_od = all(r["regime"] == "overdamped" for (c, m), r in list(rT.items()) + list(rM.items())
                      if c == "soft" and m in sc)
        shp = {m: rM[("soft", m)]["shape"] for m in sc if ("soft", m) in rM and "shape" in rM[("soft", m)]}
        shape_txt = "; ".join(f"{m} mPa s {r['regime']}" + (
            f" (period {f3(r['period'])} us, {r['crossings']} sign changes, first overshoot "
            f"{100 * r['overshoot']:.0f}% of the start, the next swing {swing(r)} of it)" if r["crossings"] >= 2
            else f" (overshoot {100 * r['overshoot']:.0f}%)") for m, r in shp.items())
        why = ("F_eq overdamped already at 1 mPa s with either wall: the wall law does not set it" if both_od
               else "the walls differ in F_eq")
        osc = [m for m, r in shp.items() if r["regime"] == "oscillating"]
        if osc and both_od:
            p = shp[osc[0]]["period"]
            trelax = float(M["relax"][("soft", osc[0])].get("t_end", NAN))
            why += (f". But the shape, H - W, swings through zero at {', '.join(osc)} mPa s: the soft cell's "
                    f"shape mode has a period of {f3(p)} us and the {f3(trelax)} us record holds "
                    f"{trelax / p:.1f} of them, so F_eq, measured against the free cell's value from another "
                    "run, shows fewer than the two sign changes the test needs: the 'overdamped at 1 mPa s' "
                    "is the record's length, not the damping"
                    + (f"; at {', '.join(m for m, r in shp.items() if r['regime'] == 'overdamped')} mPa s the "
                       "shape creeps back without crossing, as the paper's 'overdamped near 10 mPa s'"
                       if any(r["regime"] == "overdamped" for r in shp.values()) else "")
                    + ". The tether cell's F_eq relaxes as the "
                    f"membrane's (t_first {f3(rT.get(('soft', '1'), {}).get('t_first'))} and "
                    f"{f3(rM.get(('soft', '1'), {}).get('t_first'))} us), so likely the same there; its "
                    "H - W is not in the committed report")
        rows.append(("relaxation soft: damping regime", "F_eq: " + regimes(T, "soft", sc),
                     "F_eq: " + regimes(M, "soft", sc) + (f"; shape H - W: {shape_txt}" if shp else ""),
                     "overdamped near 10 mPa s", why))
    return rows


def compression_rows(T, M, label):
    """Quasistatic compression: each wall against the continuous membrane of its own law."""
    rows = []
    if "f19" in T and "f19" in M and "theory" in T:
        th = T["theory"]
        rows.append(("quasistatic compression, 0.5 m/s: force at eps = 19% (uN)",
                     f"{T['f19'] / 1e3:.0f} ({100 * (T['f19'] / 1e3 / th['network'] - 1):+.0f}% vs its law's "
                     f"membrane, {th['network']:.0f})",
                     f"{M['f19'] / 1e3:.0f} ({100 * (M['f19'] / 1e3 / th['neohookean'] - 1):+.0f}% vs its law's "
                     f"membrane, {th['neohookean']:.0f})",
                     "follows the analytical membrane model",
                     f"{label}/tether {M['f19'] / T['f19']:.2f}, the continuous membranes of the two laws "
                     f"{th['neohookean'] / th['network']:.2f}: the force at large strain follows the wall's "
                     "shear modulus (the tether net's is 1.5x the sheet's); each wall is near the continuous "
                     "membrane of its own law"))
    return rows


def transmitted_rows(T, M, label):
    """Impact: the force passed to the bottom plate, each cell."""
    rows = []
    for cell in ("stiff", "soft"):
        t, m = T["transmitted"].get(cell), M["transmitted"].get(cell)
        if t and m:
            def tr(x):
                s = f"{f3(x['f_imp'] / 1e3)} uN at eps = {100 * x['eps']:.0f}%"
                if math.isfinite(x["f_qs"]):
                    s += f" (quasistatic {f3(x['f_qs'] / 1e3)}), lag {100 * x['lag']:+.1f}%"
                return s
            mq = m["f_qs"] if math.isfinite(m["f_qs"]) else t["f_qs"]
            if not (t["f_imp"] > 0.1 * t["f_qs"] and m["f_imp"] > 0.1 * mq):
                rows.append((f"impact {cell}, 1 mPa s: transmitted force", tr(t), tr(m),
                             "lags, then exceeds the quasistatic force",
                             "in both walls the cell spreads sideways under the impacting plate and hardly "
                             "loads the bottom plate (below a tenth of the quasistatic force at that strain)"))
                continue
            ratio = m["f_imp"] / t["f_imp"]
            rows.append((f"impact {cell}, 1 mPa s: transmitted force", tr(t), tr(m),
                         "lags, then exceeds the quasistatic force",
                         f"{label}/tether {ratio:.2f}" + (
                             f"; quasistatic {m['f_qs'] / t['f_qs']:.2f}" if math.isfinite(m["f_qs"])
                             and math.isfinite(t["f_qs"]) else "") + (
                             "; the continuous membranes of both laws (tools/membrane.py, compression "
                             f"row above) {T['theory']['neohookean'] / T['theory']['network']:.2f}: the "
                             "two laws differ only in shear (the sheet 1.5x softer), so the plates load the wall in "
                             "shear"
                             if cell == "stiff" and "theory" in T else "")))
    return rows


def shear_rows(T, M, label):
    """Impact: the shear stress of the fluid under the plate at 1 mPa s, each cell."""
    rows = []
    for cell in ("stiff", "soft"):
        t, m = T["shear"].get((cell, 1)), M["shear"].get((cell, 1))
        if t and m:
            rows.append((f"impact {cell}, 1 mPa s: shear stress at eps = 4% (10%) (Pa)",
                         f"{t[0]:.0f} ({t[1]:.0f})", f"{m[0]:.0f} ({m[1]:.0f})",
                         "250" if cell == "stiff" else "same range as the stiff cell",
                         f"{label}/tether {m[0] / t[0]:.2f} at 4%" + (
                             ": the fluid's shear under the plate is set by the plate's speed and the viscosity, "
                             "not by the wall" if abs(m[0] / t[0] - 1) < 0.15 else
                             ": the wall changes the flow under the plate")))
    return rows


def failure_rows(T, M, cont, label):
    """Failure: strain and origin of each run, and the quasistatic crack's course,
    broken elements and jet."""
    rows = []
    fT, fM = T["failure"], M["failure"]
    paper_f = {"qs": ("~14%, near the equator, runs to the poles in < 0.5 us"),
               "impact-1": "~7%, near the plate", "impact-1000": "~10%, near the plate"}
    for lab in ("qs", "impact-1", "impact-1000"):
        t, m = fT.get(lab), fM.get(lab)
        if not (t and m):
            continue
        c = (cont or {}).get(lab)
        rows.append((f"failure {lab}: eps_f; first broken nodes' latitude (deg)",
                     f"{100 * t['eps_f']:.1f}%; {f3(t['lat'])}", f"{100 * m['eps_f']:.1f}%; {f3(m['lat'])}",
                     paper_f[lab], failure_why(t, m, c, label)))
        if lab == "qs":
            rows += crack_rows(t, m, label)
    return rows


def failure_why(t, m, c, label):
    """Why the walls' failure strains and origins differ: the two criteria at the onset, the
    continuum's most stretched place (c, quasistatic only), the broken count at the other's strain."""
    d = 100 * (m["eps_f"] - t["eps_f"])
    why = f"{label} {d:+.1f}% strain" + (
        ", the same latitude next to the other plate (the cell is symmetric)" if
        abs(abs(m["lat"]) - abs(t["lat"])) < 3 and m["lat"] * t["lat"] < 0 else
        f", {abs(m['lat']) - abs(t['lat']):+.0f} deg of latitude")
    why += (f". A triangle fails when its largest principal stretch passes lamf, a tether when its own "
            f"length does (an edge at 30 deg to the principal direction sees only sqrt(0.75 lam1^2 + "
            f"0.25 lam2^2)); here the largest edge stretch in the {label} wall just before its first "
            f"failure was {m.get('lam_edge_f', NAN):.4f}, within "
            f"{100 * (LAMF - m.get('lam_edge_f', NAN)) / LAMF:.1f}% "
            "of lamf (and of the largest principal stretch, which lies between them): at the onset "
            "the two criteria differ little")
    if c:
        why += (f". Continuum ({label} law, frictionless plates) at eps = {100 * c['eps']:.1f}%: the "
                f"largest stretch {c['lam']:.4f} is the {c['kind']} one at latitude {c['lat']:.0f} deg, "
                f"{c['lat_edge'] - c['lat']:.0f} deg below the contact edge ({c['lat_edge']:.0f} deg); "
                f"at the equator {c['lam_eq']:.4f}; it reaches lamf at eps = "
                f"{100 * c['eps_lamf']:.1f}%: the discrete wall, bent ring by ring over the plate "
                "edge, gets there earlier")
        if c["lat"] > 20 and c["lam"] > c["lam_eq"]:
            why += (". Between plates a membrane is stretched most just below the contact edge, where "
                    "the plates have pushed the wall out most relative to its radius, not at the "
                    "equator" + (": that is where both walls' cracks start" if abs(abs(m["lat"]) - c["lat"])
                                 < 5 and abs(abs(t["lat"]) - c["lat"]) < 5 else ""))
    if "series" in m and math.isfinite(t["eps_f"]):
        e, nb = m["series"]
        k = np.nonzero(e >= t["eps_f"])[0]
        if len(k) and nb[k[0]] > 0:
            why += (f". At the tether wall's failure strain the {label} wall has {nb[k[0]]:.0f} broken edges "
                    f"already (at the end {nb[-1]:.0f}): the counts of two runs taken at one strain compare "
                    "their onsets, not their cracks")
    return why


def crack_rows(t, m, label):
    """The quasistatic crack of both walls: its run, the broken elements at the end, the jet."""
    rows = []
    def run_(x):
        return (f"{x['span'][0]:.0f} to {x['span'][1]:.0f} deg, {f3(x['speed'])} m/s; 90% after "
                f"{f3(x['t_90'])} us" if x["span"] else "n/a")
    rows.append(("failure qs: crack after 0.2 us (span, speed of its ends)", run_(t), run_(m),
                 "runs to the poles in < 0.5 us",
                 f"speed of the ends {label}/tether {m['speed'] / t['speed']:.2f}"
                 + (": the crack runs about as fast in either wall" if 0.75 < m["speed"] / t["speed"] < 1.33
                    else "") + f"; the 90% time is {m['t_90'] / t['t_90']:.0f}x the tether's"
                 + (f" because the {label} keeps failing after the burst (next row)"
                    if math.isfinite(m.get("rate_after", NAN)) and m["t_90"] > 2 * t["t_90"] else "")))
    rows.append(("failure qs: broken elements at the end", f"{f3(t['n_final'])} tethers",
                 f"{f3(m['n_final'])} edges", "not given",
                 "not the same count: a broken tether is one open edge, while an edge next to "
                 "a failed triangle counts from that triangle on, so every failed triangle "
                 "adds its rim edges too"
                 + (f". After the burst (pressure below a tenth) the {label} wall still loses "
                    f"{m['rate_after']:.0f} edges per 1% of plate travel with its largest edge "
                    f"stretch at most {m['lam_edge_after']:.4f}"
                    # the claim that no edge passes lamf only where the run shows it
                    + (" < lamf: the triangles that fail then are stretched beyond lamf along "
                       "none of their edges, i.e. sheared" if m["lam_edge_after"] < LAMF else
                       f", about lamf = {LAMF:g}: a triangle fails on its largest principal "
                       "stretch, which shear raises above its edges'")
                    + " (the empty wall squeezed by the plates; a simple shear of 0.08 along one "
                    "edge of a triangle gives a principal stretch of 1.04 with its edges at most "
                    "1.036), which no tether senses" if math.isfinite(m.get("rate_after", NAN)) else "")))
    rows.append(("failure qs: escaping fluid, median / 90th pct (m/s)",
                 f"{f3(t['jet'][0])} / {f3(t['jet'][1])}", f"{f3(m['jet'][0])} / {f3(m['jet'][1])}",
                 "~3", f"{label}/tether {m['jet'][0] / t['jet'][0]:.2f}: the turgor before the burst "
                 "drives the jet through the opening (the Bernoulli speed at that pressure bounds it, "
                 "tables above)"))
    return rows

# releases of the soft cell that tell what damps it (run by hand beside the stages, see
# soft_damping_note): file suffix -> what differs from relax-soft-1
DIAG = {"mu0.01": "fluid viscosity 0.01 mPa s (100x less)", "gc0": "1 mPa s, no fluid-wall contact damping (gc 0)"}


def soft_damping_note(run):
    """Lines on what damps the soft cell, from the releases relax-soft-SUFFIX.dat (DIAG) in the run
    folder beside relax-soft-1; [] when there are none."""
    load = os.path.join(run, "soft-compressed.restart.load.dat")
    def finished(k):
        # a stage of tools/experiments.sh, or a release run by hand that got to its end
        if k == "1":
            return _ok(run, "relax-soft-1")
        log = os.path.join(run, f"log.relax-soft-{k}")
        return os.path.exists(log) and "Total wall time" in open(log).read()
    got = [(k, os.path.join(run, f"relax-soft-{k}.dat")) for k in ["1"] + list(DIAG)]
    got = [(k, p) for k, p in got if os.path.exists(p) and finished(k)]
    if len(got) < 2 or not os.path.exists(load):
        return []
    f_inf = float(np.mean(A.load(load)[:5, A.CMP["feq"]]))
    L = ["**What damps the soft cell** (the same compressed state released with one setting changed; "
         "F_eq as in the relaxation tables, and the shape H - W with its first overshoot, the damping "
         "ratio of a linear oscillator with that overshoot, and the next swing relative to the overshoot, "
         "which such an oscillator would shrink by the same factor):", "",
         "| release | F_eq: t_first (us), sign changes, regime | H - W: period (us), sign changes, overshoot, "
         "damping ratio, next swing / overshoot, regime |", "|---|---|---|"]
    reg = {}
    for k, p in got:
        a = A.load(p)
        r = A.relaxation(a[:, A.REL["t"]], a[:, A.REL["feq"]], f_inf)
        reg[k] = "oscillating" if r["crossings"] >= 2 else "overdamped"
        sh = shape_relaxation(a)
        L.append(f"| {'1 mPa s (relax-soft-1)' if k == '1' else DIAG[k]} | {f3(r['t_first'])}, {r['crossings']}, "
                 f"{reg[k]} | {f3(sh['period'])}, {sh['crossings']}, {100 * sh['overshoot']:.0f}%, "
                 f"{f3(sh['zeta'])}, {swing(sh)}, {sh['regime']} |")
        reg[k + "-shape"] = sh
    said = []
    z1 = reg["1-shape"]["zeta"]
    for k, what, most in (("mu0.01", "100x less viscosity", "the fluid's viscosity"),
                          ("gc0", "no fluid-wall contact damping", "the fluid-wall contact damping (gc)")):
        if k + "-shape" not in reg:
            continue
        zk = reg[k + "-shape"]["zeta"]
        if math.isfinite(z1) and math.isfinite(zk):
            x1, xk = reg["1-shape"]["overshoot"], reg[k + "-shape"]["overshoot"]
            said.append(f"with {what} the shape's first overshoot is {100 * xk:.0f}% against {100 * x1:.0f}% "
                        f"at 1 mPa s (damping ratios {zk:.2f} and {z1:.2f}): "
                        + (f"{most} takes most of what the first swing loses" if zk < 0.5 * z1 else
                           f"{most} takes little of what the first swing loses"))
        elif reg["1-shape"]["regime"] != reg[k + "-shape"]["regime"]:
            said.append(f"with {what} the shape is {reg[k + '-shape']['regime']}, at 1 mPa s "
                        f"{reg['1-shape']['regime']}: {most} sets the regime")
    s2 = reg["1-shape"].get("swing2", NAN)
    if math.isfinite(s2) and s2 > 0.8:
        said.append(f"after the first swing the mode hardly decays at 1 mPa s (the next swing "
                    f"{swing(reg['1-shape'])} of the overshoot): the loss is in the first, largest swing")
    text = "; ".join(said)
    return L + ([""] + [text[:1].upper() + text[1:] + "."] if said else []) + [""]


def table(rows, label="membrane"):
    L = [f"| quantity | tether | {label} | paper | why |", "|---|---|---|---|---|"]
    for r in rows:
        L.append("| " + " | ".join(str(x).replace("|", "/") for x in r) + " |")
    return L


def splice(path, lines, title=TITLE, before=BEFORE):
    """Put `lines` (a section starting with `title`) in place of that section of the markdown file
    `path`, or before the heading `before` (at the end when there is none); the rest stays."""
    rp.splice(path, lines, title, before)


def title_of(label):
    return f"## {label.capitalize()} wall"


def section_of(path, title=TITLE):
    """The lines of section `title` of the markdown file `path` ([] when it has none)."""
    return rp.section_of(path, title)


def section(run, report, label="membrane", continuum=True):
    """The section's lines: the side-by-side table from the committed report REPORT/experiments.md
    (tether) and the run folder RUN (membrane), and plots of the membrane's relaxation and crack."""
    T = tether_numbers(open(os.path.join(report, "experiments.md")).read())
    info, settings = rp.run_info(run)
    r0 = float(settings.get("r0", 1.6))
    M = measure(run, r0=r0)
    cont = {}
    # the quasistatic failure beside the continuous membrane of the same law (an impact is not
    # quasistatic: no continuum reference)
    if continuum and math.isfinite(M["failure"].get("qs", {}).get("eps_f", NAN)):
        got, eps_lamf = continuum_stretch([round(M["failure"]["qs"]["eps_f"], 4)], "neohookean")
        cont["qs"] = dict(got[0], eps_lamf=eps_lamf)
    rows = compare_rows(T, M, cont, label)
    L = [title_of(label), "",
         f"The same experiments with `WALL={label}` (lammps-inputs/cell-wall.lmp: angle_style cell/membrane, "
         "the Neo-Hookean sheet on the wall triangles, failure when a triangle's largest principal stretch "
         f"passes lamf = {LAMF}) beside the tether wall of the tables above and the paper. Generated by "
         f"`WALL={label} RES=paper bash tools/experiments.sh` (report.py --membrane); run settings: "
         f"`{info.strip()}`.", ""]
    L += table(rows, label)
    L += [""] + soft_damping_note(run)
    figs = plots(M, run, os.path.join(report, "experiments"), label)
    L.append("")
    for title, name in figs:
        L.append(f"**{title}**\n\n![{title}](experiments/{name})\n")
    L.append(f"**{label.capitalize()} wall, runs** (wall time, s): " + ", ".join(
        " ".join(ln.split()[:3]) for ln in open(os.path.join(run, "times.txt"))) + "\n"
        if os.path.exists(os.path.join(run, "times.txt")) else "")
    return L, T, M, cont


def plots(M, run, figdir, label):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(figdir, exist_ok=True)
    figs = []
    for cell in ("stiff", "soft"):
        cases = [k for k in M["relax"] if k[0] == cell]
        if not cases:
            continue
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 3.8))
        for _, lab in cases:
            a = A.load(os.path.join(run, f"relax-{cell}-{lab}.dat"))
            ax1.plot(a[:, A.REL["t"]], a[:, A.REL["feq"]] / 1e3, label=f"{lab} mPa s")
            ax2.plot(a[:, A.REL["t"]], a[:, A.REL["h"]] - a[:, A.REL["w"]], label=f"{lab} mPa s")
        load = os.path.join(run, f"{cell}-compressed.restart.load.dat")
        if os.path.exists(load):
            ax1.axhline(float(np.mean(A.load(load)[:5, A.CMP["feq"]])) / 1e3, color="k", lw=0.6, ls=":",
                        label="free cell")
        ax2.axhline(0.0, color="k", lw=0.6, ls=":", label="free cell (sphere)")
        for ax, yl in ((ax1, "equatorial force (uN)"), (ax2, "height - width (um)")):
            ax.set_xlabel("time after release (us)")
            ax.set_ylabel(yl)
            ax.legend(fontsize=8)
        fig.suptitle(f"Relaxation, {cell} cell, {label} wall")
        name = f"{label}-relax-{cell}.png"
        rp.save_figure(os.path.join(figdir, name), fig, bbox_tight=True)
        figs.append((f"{label.capitalize()} wall: relaxation of the {cell} cell", name))
    return figs
