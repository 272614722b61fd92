# SPDX-License-Identifier: GPL-2.0-or-later
"""Is a plate compression quasi-static? Pure functions on the record of a plate experiment
(in.compress, in.tissue-compress, in.tissue-impact; issue 29).

A compression measures the cell or the tissue only when the plates' load crosses it in
equilibrium; a fast one measures the inertia of the plate-driven mass as well. Three signs tell
them apart, each over strain windows (default 2% wide: several records each, longer than the
ringing of the wall nodes against the plates, shorter than the features of the curve):

* balance(): the two plates carry the same load. The bottom plate's force less the top one's is
  the rate of change of the momentum of everything between them (docs/Howto_plates.rst), zero in
  equilibrium. Per window: mean F_top, mean F_bottom and (F_top - F_bottom) / their mean.
* energy(): the kinetic energy of all atoms against the work the plates have done. A
  quasi-static plate's work is stored in the wall and the fluid or dissipated; KE / W is the share
  that went into motion. Per window: mean KE / mean W.
* rate_difference(): the curve does not move when the plate speed halves. Per window: the plate
  force (mean of both plates) of the run at v against the run at v/2, relative to the slower one.

verdict() holds them against the tolerances below and says, one line per failing criterion, why a
run is dynamic. check() does all of it on records as {column name: array}: the columns of
in.compress (CELL_COMPRESS here) or in.tissue-compress (cellmech.tissue.tissuedata.COMPRESS), which
share the names strain, F_top_nN, F_bottom_nN, broken_tethers, KE and WORK. report() is the printed
table. tools/plot_main.py and tools/plot_tissue.py print it for every plate experiment;
cellmech.ladder finds the speed at which it passes. Docs: docs/Howto_plates.rst, "Is it
quasi-static?".

Units micro: strain 1, forces nN, energies nN um (= pg um^2/us^2 = 1e-15 J).
"""
import math
from dataclasses import dataclass, field

import numpy as np

# the columns the inputs append for this check (in.compress, in.tissue-compress): compute ke of all
# atoms, and the plates' work, each plate's force times its move summed over the steps (fix
# cell/plates; the grips' by fix ave/time, lammps-inputs/grips-move.lmp)
KE, WORK = "kinetic_energy_nNum", "plate_work_nNum"
# in.compress's record after its step column (in.tissue-compress's: tissuedata.COMPRESS)
CELL_COMPRESS = ["time_us", "strain", "F_top_nN", "F_bottom_nN", "F_equator_nN", "P_mean_kPa",
                 "broken_tethers", "leaked", "volume_um3", "fluid_volume_um3", "pz_pg_um_us", KE, WORK]

WINDOW = 0.02
# issue 29's criterion: both plates agree within 5% over 2%-strain windows
TOL_BALANCE = 0.05
# an oscillation that holds a share KE/W of the work rings with about sqrt(KE/W) of the load
# (spring energy k a^2 / 2 against k d^2 / 2: amplitude over deflection a/d = sqrt(KE/W)); at 1%
# that is 10% peak to mean, which a window spanning several periods averages well within the 5%
TOL_KE = 0.01
# halving the speed may move the curve no more than the plates may disagree: below that the
# balance could not tell the two speeds apart
TOL_RATE = 0.05
# windows in which both plates carry less than this share of the largest window-mean force of the
# range are skipped: before contact the imbalance is 0/0, just after it the ratio of two forces of
# a few wall nodes measures which ring of nodes touches first, not the load path
FLOOR = 0.02
# fewer records than this in a window: its mean is one sample of the ringing, not a mean
MIN_RECORDS = 3


@dataclass
class BalanceRow:
    lo: float
    hi: float
    n: int
    top: float
    bottom: float
    imbalance: float = None     # (top - bottom) / mean(top, bottom); None: skipped
    skipped: str = ""


@dataclass
class EnergyRow:
    lo: float
    hi: float
    n: int
    ke: float
    work: float
    ratio: float = None         # KE / W; None: skipped
    skipped: str = ""


@dataclass
class RateRow:
    lo: float
    hi: float
    fast: float                 # window-mean plate force at v
    slow: float                 # ... at v/2
    difference: float = None    # (fast - slow) / slow; None: skipped
    skipped: str = ""


@dataclass
class Verdict:
    quasistatic: bool
    numbers: dict               # worst value of each criterion and its window
    reasons: list = field(default_factory=list)     # one line per failing criterion
    failed: list = field(default_factory=list)      # their names: balance, ke_over_work, rate

    @property
    def label(self):
        return "quasi-static" if self.quasistatic else "dynamic"


def windows(lo, hi, width=WINDOW):
    """Strain windows (a, b) tiling lo..hi, `width` wide but the last, which takes the rest (between
    half a width and one and a half), so that no window is a sliver of a few records."""
    if hi <= lo:
        return []
    n = max(1, math.floor((hi - lo) / width + 0.5 + 1e-9))
    edges = [round(lo + k * width, 12) for k in range(n)] + [hi]     # (round-off off the edges)
    return list(zip(edges[:-1], edges[1:]))


def _select(strain, a, b, last):
    """Records with a <= strain < b (<= b in the last window)."""
    return (strain >= a) & ((strain <= b) if last else (strain < b))


def window_means(strain, ys, wins):
    """For each window (a, b): (records in it, [mean of each y over them])."""
    strain = np.asarray(strain, float)
    out = []
    for k, (a, b) in enumerate(wins):
        m = _select(strain, a, b, k == len(wins) - 1)
        out.append((int(m.sum()), [float(np.mean(np.asarray(y, float)[m])) if m.any() else 0.0
                                   for y in ys]))
    return out


def balance(strain, top, bottom, lo, hi, width=WINDOW, floor=FLOOR):
    """The plates' force balance per strain window of lo..hi: BalanceRow's. Windows where both
    plates carry less than floor x the largest window-mean force of the range, or with fewer than
    MIN_RECORDS records, are kept with the reason they were skipped."""
    wins = windows(lo, hi, width)
    means = window_means(strain, (top, bottom), wins)
    big = max([max(abs(t), abs(b)) for n, (t, b) in means if n] or [0.0])
    rows = []
    for (a, b), (n, (ft, fb)) in zip(wins, means):
        row = BalanceRow(a, b, n, ft, fb)
        if n < MIN_RECORDS:
            row.skipped = f"{n} record(s)"
        elif big <= 0 or max(abs(ft), abs(fb)) < floor * big:
            row.skipped = f"both plates below {floor:.0%} of the largest load ({floor * big:.4g} nN)"
        else:
            row.imbalance = (ft - fb) / (0.5 * (ft + fb))
        rows.append(row)
    return rows


def energy(strain, ke, work, lo, hi, width=WINDOW, floor=FLOOR):
    """Kinetic energy against the plates' work per strain window: EnergyRow's. Windows where the
    plates have done less than floor x the range's largest window-mean work are skipped (before
    contact the ratio is motion over nothing), as are those with fewer than MIN_RECORDS records.
    The kinetic energy is all of it, the inflation's leftover motion included: a cell still
    ringing from its inflation loads the plates with that ringing as well."""
    wins = windows(lo, hi, width)
    means = window_means(strain, (ke, work), wins)
    big = max([w for n, (k, w) in means if n] or [0.0])
    rows = []
    for (a, b), (n, (k, w)) in zip(wins, means):
        row = EnergyRow(a, b, n, k, w)
        if n < MIN_RECORDS:
            row.skipped = f"{n} record(s)"
        elif big <= 0 or w < floor * big:
            row.skipped = "no plate work recorded" if big <= 0 else \
                f"plate work below {floor:.0%} of the range's largest"
        else:
            row.ratio = k / w
        rows.append(row)
    return rows


def plate_force(rec):
    """The load a record's plates carry: the mean of both (their difference is the inertia of what
    lies between them, which the mean leaves out to first order)."""
    return 0.5 * (np.asarray(rec["F_top_nN"], float) + np.asarray(rec["F_bottom_nN"], float))


def rate_difference(fast, slow, lo, hi, width=WINDOW, floor=FLOOR):
    """Two records of one experiment at speeds v (fast) and v/2 (slow): per strain window, the
    window-mean plate force of each and their relative difference against the slower run:
    RateRow's. Windows below floor x the slower run's largest window force, or with fewer than
    MIN_RECORDS records in either run, are skipped."""
    wins = windows(lo, hi, width)
    mf = window_means(fast["strain"], (plate_force(fast),), wins)
    ms = window_means(slow["strain"], (plate_force(slow),), wins)
    big = max([abs(f[0]) for n, f in ms if n] or [0.0])
    rows = []
    for (a, b), (nf, (ff,)), (ns, (fs,)) in zip(wins, mf, ms):
        row = RateRow(a, b, ff, fs)
        if min(nf, ns) < MIN_RECORDS:
            row.skipped = f"{nf} and {ns} record(s)"
        elif big <= 0 or abs(fs) < floor * big:
            row.skipped = f"load below {floor:.0%} of the largest"
        else:
            row.difference = (ff - fs) / fs
        rows.append(row)
    return rows


def _worst(rows, attr):
    """(largest |value|, its row) over the rows not skipped; (None, None) when all were."""
    kept = [r for r in rows if getattr(r, attr) is not None]
    if not kept:
        return None, None
    r = max(kept, key=lambda r: abs(getattr(r, attr)))
    return abs(getattr(r, attr)), r


def _span(r):
    return f"{100 * r.lo:.3g}-{100 * r.hi:.3g}% strain"


def verdict(bal, en, rate=None, tol_balance=TOL_BALANCE, tol_ke=TOL_KE, tol_rate=TOL_RATE):
    """Quasi-static when every window's imbalance is within tol_balance, every window's KE/W is
    below tol_ke and (when the rows of a half-speed run are given) no window moved by more than
    tol_rate; a criterion with no window left to judge fails (nothing shows it holds)."""
    checks = [("balance", bal, "imbalance", tol_balance,
               "the plates differ by {v:.1%} at {span} (tolerance {tol:.0%}); {k} of {n} windows beyond"),
              ("ke_over_work", en, "ratio", tol_ke,
               "kinetic energy is {v:.2%} of the plates' work at {span} (tolerance {tol:.0%}); "
               "{k} of {n} windows beyond")]
    if rate is not None:
        checks.append(("rate", rate, "difference", tol_rate,
                       "halving the speed moves the curve by {v:.1%} at {span} (tolerance {tol:.0%}); "
                       "{k} of {n} windows beyond"))
    numbers, reasons, failed = {}, [], []
    for name, rows, attr, tol, text in checks:
        v, r = _worst(rows, attr)
        numbers[name] = v
        numbers[name + "_window"] = (r.lo, r.hi) if r else None
        numbers[name + "_tolerance"] = tol
        if v is None:
            why = "; ".join(sorted({x.skipped for x in rows})) or "no window in the strain range"
            reasons.append(f"{name}: no window to judge ({why})")
            failed.append(name)
        elif v > tol:
            kept = [x for x in rows if getattr(x, attr) is not None]
            beyond = sum(abs(getattr(x, attr)) > tol for x in kept)
            reasons.append(f"{name}: " + text.format(v=v, span=_span(r), tol=tol, k=beyond, n=len(kept)))
            failed.append(name)
    return Verdict(not reasons, numbers, reasons, failed)


def intact_range(rec, lo, hi):
    """lo..hi cut at the record's end and at the first wall rupture (the first record whose
    broken-tether count exceeds its start): after it the plates load a failing wall, and its
    fluid escapes at a speed no plate sets."""
    strain = np.asarray(rec["strain"], float)
    end = min(hi, float(strain.max())) if len(strain) else lo
    broken = np.asarray(rec.get("broken_tethers", np.zeros(len(strain))), float)
    k = np.nonzero(broken > broken[0] + 0.5)[0] if len(broken) else []
    if len(k):
        end = min(end, float(strain[k[0]]))
    return lo, end


def check(rec, lo, hi, half=None, width=WINDOW, floor=FLOOR, tol_balance=TOL_BALANCE, tol_ke=TOL_KE,
          tol_rate=TOL_RATE):
    """All three on records ({column: array}, names as CELL_COMPRESS): rec at v over lo..hi (cut
    at its first rupture, intact_range), half (optional) the same experiment at v/2.
    Returns (balance rows, energy rows, rate rows or None, Verdict)."""
    lo, hi = intact_range(rec, lo, hi)
    s = rec["strain"]
    bal = balance(s, rec["F_top_nN"], rec["F_bottom_nN"], lo, hi, width, floor)
    en = energy(s, rec[KE], rec[WORK], lo, hi, width, floor)
    rate = rate_difference(rec, half, lo, hi, width, floor) if half is not None else None
    return bal, en, rate, verdict(bal, en, rate, tol_balance, tol_ke, tol_rate)


def _pct(x, fmt="+.1%"):
    return format(x, fmt) if x is not None else "-"


def report(bal, en, rate, v, title="plate compression"):
    """The printed summary: one line per window (forces, imbalance, KE/W), the rate rows when
    given, skipped windows with their reason, and the verdict with its reasons."""
    span = f"{100 * bal[0].lo:.3g}-{100 * bal[-1].hi:.3g}%" if bal else "empty"
    tols = (f"tolerances: balance {v.numbers['balance_tolerance']:.0%}, KE/W "
            f"{v.numbers['ke_over_work_tolerance']:.0%}")
    if rate is not None:
        tols += f", half speed {v.numbers['rate_tolerance']:.0%}"
    out = [f"{title}: quasi-static check over strain {span} ({tols})",
           f"  {'strain (%)':>12} {'F_top (uN)':>11} {'F_bot (uN)':>11} {'(Ft-Fb)/F':>10} {'KE/W':>8}"]
    for b, e in zip(bal, en):
        note = "; ".join(x for x in (b.skipped and f"balance skipped: {b.skipped}",
                                     e.skipped and f"KE/W skipped: {e.skipped}") if x)
        out.append(f"  {100 * b.lo:5.2f}-{100 * b.hi:5.2f} {b.top * 1e-3:11.4g} {b.bottom * 1e-3:11.4g} "
                   f"{_pct(b.imbalance):>10} {_pct(e.ratio, '.2%'):>8}" + (f"  ({note})" if note else ""))
    if rate is not None:
        out.append(f"  {'strain (%)':>12} {'F(v) (uN)':>11} {'F(v/2) (uN)':>11} {'change':>10}")
        for r in rate:
            out.append(f"  {100 * r.lo:5.2f}-{100 * r.hi:5.2f} {r.fast * 1e-3:11.4g} {r.slow * 1e-3:11.4g} "
                       f"{_pct(r.difference):>10}" + (f"  (skipped: {r.skipped})" if r.skipped else ""))
    out.append(f"verdict: {v.label}")
    out += [f"  - {r}" for r in v.reasons]
    return "\n".join(out)
