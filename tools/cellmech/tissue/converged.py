# SPDX-License-Identifier: GPL-2.0-or-later
"""The report of tools/tissue-converged.sh (issue 29): tissue compression, or tension, at converged
plate (grip) speeds, side by side with parenchyma measurements.

  python3 -m cellmech.tissue.converged RUNS REPORT [NAME [KIND]]

KIND: compress (default) or tension (KINDS below says what differs). RUNS holds the generated
block's statistics (gen/block.json), KIND{PI}-{LAM}-{SPEED}/tissue-KIND.dat and the run settings
(run-info.txt);
each condition is judged on the two slowest speeds it has that differ by a factor of 2 (the
ladder's last rungs: v against 2v). REPORT gets NAME.md and NAME.png (NAME: tissue-quasistatic).
Per condition: the
quasi-static check (cellmech.quasistatic) of the slow run from 2% strain to its first wall rupture,
the slow curve against the fast one over the same range (rate evidence), the modulus (slope of a
straight line through the stress over its window, KINDS), the failure stress (peak of the stress over
1% strain windows), the strain there, the first rupture and debond, and the failure mode
(tissuedata.failure: which kind of event begins first). Each number comes from the slow run.
A window has converged when it passes the checks of CHECKS (the balance and the rate, each per
window, as the speed ladder, cellmech.tissue.ladder, judges it); the kinetic energy against the
plates' work (KE/W) is printed beside them but not judged: in the coarse fluid it holds 3-10% of the
work at any plate speed (the fluid's rearrangement under load, docs/Howto_plates.rst), so no
slower speed removes it and it cannot tell a converged curve from one that is not; the modulus when every window from its window on has (the strain
`converged from`, and the verdict, say the same); the failure stress when failure_rule holds (the
first failure and the peak, stress and strain, agree at v and 2v, the peak is no record's end and
no blow-up of either run). A number that has not converged is shown as such (modulus_cell,
failure_cells).
"""
import os
import re
import sys
from dataclasses import dataclass, replace

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .. import params  # noqa: E402
from .. import quasistatic as Q  # noqa: E402
from . import tissuedata as T  # noqa: E402
from .tissuedata import COMPRESS, TENSION, and_list, failure, fmt, gen_stats, load, span  # noqa: E402

PIS = (-100, -364, -600)
LAMELLAE = tuple(params.lamellae())   # the named lamellae: strong, weak


@dataclass(frozen=True)
class Kind:
    """What differs between the experiments the report judges."""
    stage: str          # run folders STAGE{PI}-{LAM}-{SPEED}/ with tissue-STAGE.dat, in.tissue-STAGE
    window: tuple       # the modulus window (strain)
    start: float        # the checks start here (strain)
    width: float        # the checks' strain windows
    to_peak: bool       # the checks end at the peak stress: past it the lamella lets go faster than
                        # any grip moves, so only the rise to the failure can be quasi-static; and
                        # the modulus is only of an intact lamella, which a pull loads directly
    title: str
    did: str            # what was done to the block, for the summary
    ends: str           # the plates or the grips, in the tables' words
    protocol: str       # the input and its start, for the summary
    versus: str         # this loading against the measurements' (mostly tension)


KINDS = {
    # past the plates' first contacts with the block's domed faces (at Pi -100 kPa the 2-4% window is
    # still dynamic at 0.25 m/s: the flaccid block carries little load there), before any cell fails
    "compress": Kind("compress", (0.04, 0.06), 0.02, Q.WINDOW, False, "Tissue compression at converged plate speeds",
                     "compressed to failure", "plates",
                     "the quasi-static protocol of `in.tissue-compress` (docs/Howto_plates.rst, \"A protocol that "
                     "reaches quasi-static\"): at rest first, both plates closing after a smooth start",
                     "a compression here, mostly tension there"),
    # the grips hold the block from the start; their smooth start takes the first 1% of strain, and
    # the weak lamella's peak comes at about 3% (docs/Howto_tissue.rst "Tension"), so the windows
    # are 1% wide and the modulus is read over 1-2%
    "tension": Kind("tension", (0.01, 0.02), 0.005, 0.01, True, "Tissue tension at converged grip speeds",
                    "pulled apart to failure", "grips",
                    "`in.tissue-tension` (docs/Howto_tissue.rst, \"Tension\"): the wall nodes near its bottom "
                    "and top gripped, at rest in the grips first, both grips moving apart after a smooth start",
                    "a tension here and there"),
}

# Parenchyma measurements (orders of magnitude, as the sources report them)
LITERATURE = [
    ("modulus of apple and potato parenchyma, tension and compression, across turgor states",
     "about 1-20 MPa, rising with turgor",
     "Lin and Pitt 1986; Oey et al. 2007; Scanlon et al. 1996"),
    ("failure stress of apple flesh", "about 0.3 MPa", "Oey et al. 2007; Lin and Pitt 1986"),
    ("failure mode", "turgid tissue: cells rupture; flaccid or weakly bonded tissue: cells debond "
     "(separate along the middle lamella)", "Lin and Pitt 1986; Oey et al. 2007"),
]
REFERENCES = """* Lin, T.-T. and Pitt, R. E. (1986). Rheology of apple and potato tissue as affected by cell turgor
  pressure. *Journal of Texture Studies* 17, 291-313.
* Oey, M. L., Vanstreels, E., De Baerdemaeker, J., Tijskens, E., Ramon, H., Hertog, M. L. A. T. M. and
  Nicolai, B. (2007). Effect of turgor on micromechanical and structural properties of apple tissue: a
  quantitative analysis. *Postharvest Biology and Technology* 44, 240-247.
* Scanlon, M. G., Pang, C. H. and Biliaderis, C. G. (1996). The effect of osmotic adjustment on the
  mechanical properties of potato parenchyma. *Food Research International* 29, 481-488."""


def modulus(d, lo, hi):
    """Slope (kPa) of the least-squares line through the stress over strain lo-hi."""
    k = (d["strain"] >= lo) & (d["strain"] <= hi)
    return float(np.polyfit(d["strain"][k], d["stress_kPa"][k], 1)[0]) if k.sum() > 2 else float("nan")


# two runs' failures agree within this much strain (the first rupture or debond, the strain at the
# peak) and an error stop this close after a peak may have made it: the resolution of the peak,
# whose stress failure() smooths over 1% windows of strain
TOL_STRAIN = 0.01
# the checks of cellmech.quasistatic a window must pass, in its names: (name, row field, tolerance);
# KE/W is printed, not judged (module docstring)
CHECKS = (("balance", "imbalance", Q.TOL_BALANCE), ("rate", "difference", Q.TOL_RATE))


def window_failures(bal, rate):
    """{window start: [the CHECKS the window fails]} over the balance and rate rows of the
    same windows; a check the window skipped counts as failed (nothing shows it holds)."""
    out = {}
    for (name, attr, tol), rows in zip(CHECKS, (bal, rate)):
        for r in rows:
            x = getattr(r, attr)
            out.setdefault(r.lo, [])
            if x is None or abs(x) > tol:
                out[r.lo].append(name)
    return out


def converged_from(fails):
    """The start of the first window from which every later window passes all CHECKS (fails:
    window_failures; None: the last window fails)."""
    start = None
    for lo in sorted(fails, reverse=True):
        if fails[lo]:
            break
        start = lo
    return start


def verdict_words(fails, start):
    """The judgement of a condition's windows in words, as converged_from reads them."""
    if not fails:
        return "not converged: no window to judge"
    if start is None:
        return "not converged: the last window fails " + ", ".join(fails[max(fails)])
    before = list(dict.fromkeys(n for lo in sorted(fails) if lo < start for n in fails[lo]))
    return (f"converged from {strain_pct(start)} (before it: {', '.join(before)})" if before else
            "converged: every window passes " + ", ".join(n for n, *_ in CHECKS))


def error_stops(runs, fails, errors):
    """[(which, strain)]: the runs (v, 2v) that an error stopped within TOL_STRAIN strain after
    their peak (runs: their records, fails: their failure(), errors: stopped() of each)."""
    return [(which, float(r["strain"].max())) for which, r, g, err in zip(("v", "2v"), runs, fails, errors)
            if err and float(r["strain"].max()) - g["strain_at_peak"] <= TOL_STRAIN]


def peaks_agree(f, ff):
    """Do the peaks at v and at 2v agree: the stress within TOL_RATE, its strain within TOL_STRAIN?"""
    return (abs(ff["peak_kPa"] - f["peak_kPa"]) <= Q.TOL_RATE * abs(f["peak_kPa"])
            and abs(ff["strain_at_peak"] - f["strain_at_peak"]) <= TOL_STRAIN)


def measure(kind, slow, fast, errors=(None, None)):
    """One condition's numbers from its slow run, its checks from both, judged as a kind (Kind);
    errors: the error that stopped each run (stopped()), or None. The checks end at the first wall
    rupture of either run: past it the curves part by the timing of the events."""
    f, ff = failure(slow), failure(fast)
    end = float(slow["strain"].max())
    hi = min(f["first"].get("wall rupture", end), ff["first"].get("wall rupture", end))
    if kind.to_peak:
        hi = min(hi, f["strain_at_peak"])
    bal, en, _, v = Q.check(slow, kind.start, hi, half=None, width=kind.width)
    rate = Q.rate_difference(fast, slow, kind.start, hi, width=kind.width)
    worst = max((abs(r.difference) for r in rate if r.difference is not None), default=float("nan"))
    fails = window_failures(bal, rate)
    start = converged_from(fails)
    # a modulus only of the intact block: its window ends before the first rupture (and in a
    # tension before the first debond)
    intact = kind.window[1] <= min(hi, f["first"].get("lamella debonding", end) if kind.to_peak else hi)
    # a wall that ruptured before kind.start burst under its own turgor (at the inflation or the
    # plates' first touch): that is no compression failure, and its peak no failure stress
    first = [min(g["first"].values()) if g["first"] else end for g in (f, ff)]
    burst = f["first"].get("wall rupture", end) < kind.start
    # the first failure event (its strain and kind) has converged when both speeds begin to fail
    # within TOL_STRAIN of each other, the walls intact at kind.start
    first_converged = not burst and abs(first[0] - first[1]) <= TOL_STRAIN
    # a peak in the record's last TOL_STRAIN may be no peak: the stress was still rising at its end
    rising = f["strain_at_peak"] >= end - TOL_STRAIN
    # the failure stress has converged when, besides, the peak at 2v is the peak at v and no blow-up
    # came right after either peak (it may have made it)
    agree = peaks_agree(f, ff)
    stops = error_stops((slow, fast), (f, ff), errors)
    return dict(P0=T.start_pressure(slow), E=modulus(slow, *kind.window) if intact else float("nan"),
                fail=f, fail_fast=ff, failure_converged=first_converged and not rising and agree and not stops,
                first_converged=first_converged, first_event=first[0] if f["first"] else None,
                burst=burst, rising=rising, peak_agrees=agree, stopped=stops,
                balance=v.numbers.get("balance"), ke=v.numbers.get("ke_over_work"), rate=worst,
                start=start, judged=(kind.start, hi),
                converged=intact and start is not None and start <= kind.window[0],
                verdict=verdict_words(fails, start))


def stopped(folder):
    """The error that stopped a run early (its log's first ERROR line, cut short), or None: a run
    that blew up past its first rupture keeps its record up to there, and the report says so. Only
    an error inside a run counts: after the setup of the log's last run (LAMMPS's "Per MPI rank
    memory" line) and before its end ("Loop time"); one after the last run ended stopped nothing."""
    try:
        with open(f"{folder}/log.lammps") as f:
            lines = f.read().splitlines()
    except OSError:
        return None
    err = next((line.strip() for line in lines if line.startswith("ERROR")), None)
    last = {key: max((k for k, line in enumerate(lines) if line.startswith(key)), default=-1)
            for key in ("Per MPI rank memory", "Loop time of")}
    if err is None or last["Loop time of"] > last["Per MPI rank memory"]:
        return None
    return err[:90] + "..." if len(err) > 90 else err


def load_runs(kind, runs):
    """{(pi, lam): (v, slow record, fast record, errors)} for the two slowest speeds v and 2v of each
    condition of the kind (Kind) found in RUNS; errors: the error that stopped each run early
    (stopped()), or None."""
    out = {}
    for pi in PIS:
        for lam in LAMELLAE:
            tag = f"{kind.stage}{pi}-{lam}-"
            rec = f"tissue-{kind.stage}.dat"
            speeds = sorted(float(n[len(tag):]) for n in os.listdir(runs)
                            if n.startswith(tag) and os.path.exists(f"{runs}/{n}/{rec}"))
            pairs = [(a, b) for a in speeds for b in speeds if abs(b - 2 * a) < 1e-9]
            if pairs:
                a, b = pairs[0]
                recs = [load(f"{runs}/{tag}{s:g}/{rec}", COMPRESS if kind.stage == "compress" else TENSION)
                        for s in (a, b)]
                out[pi, lam] = (a, *recs, tuple(stopped(f"{runs}/{tag}{s:g}") for s in (a, b)))
    return out


def stop_notes(v, slow, fast, errors):
    """The runs an error stopped early (errors as load_runs gives them), where and why, in words."""
    return [f"the run at {s:g} m/s stopped at {rec['strain'].max():.1%} strain: {err}"
            for s, rec, err in zip((v, 2 * v), (slow, fast), errors) if err]


def run_settings(kind, runs, pi, lam, v):
    """The effective settings of the run of condition (pi, lam) at speed v (its settings.json; for
    a run older than it, the input's defaults with the named lamella)."""
    return params.run_settings(f"{runs}/{kind.stage}{pi}-{lam}-{v:g}", f"in.tissue-{kind.stage}",
                               params.lamellae()[lam])


def lamella_settings(kind, runs, data):
    """{lam: the settings of the first slow run with that lamella}: its sigl, Gl, lamf as run."""
    out = {}
    for (pi, lam), (v, *_) in data.items():
        out.setdefault(lam, run_settings(kind, runs, pi, lam, v))
    return out


def figure(kind, data, lams, path):
    # a panel per lamella that ran: an empty one would read as a condition that failed
    ran = [lam for lam in LAMELLAE if any(key[1] == lam for key in data)]
    fig, axes = plt.subplots(1, len(ran), figsize=(5 * len(ran), 4), sharey=True, squeeze=False)
    axes = axes[0]
    for ax, lam in zip(axes, ran):
        for n, pi in enumerate(PIS):
            if (pi, lam) not in data:
                continue
            v, slow, fast, _ = data[pi, lam]
            c = f"C{n}"
            ax.plot(slow["strain"], slow["stress_kPa"], color=c, lw=1.2, label=f"Pi {pi} kPa, {v:g} m/s")
            ax.plot(fast["strain"], fast["stress_kPa"], color=c, lw=0.8, ls="--", label=f"Pi {pi} kPa, {2 * v:g} m/s")
        if lam in lams:
            ax.set_title(f"{lam} lamella (sigl {lams[lam]['sigl']:g} kPa, Gc {lams[lam]['Gl'] / 1000:g} J/m^2)", fontsize=10)
        ax.set_xlabel(strain_label(kind, lams))
        ax.legend(fontsize=7)
    axes[0].set_ylabel(f"stress (top {kind.ends[:-1]} force / initial cross-section, kPa)")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def pct(x):
    return "-" if x is None or not np.isfinite(x) else f"{x:.1%}"


def strain_pct(x):
    """A strain as a percentage with no needless decimal: 2%, 0.5%."""
    return f"{x:.0%}" if abs(x * 100 - round(x * 100)) < 1e-9 else f"{x:.1%}"


def judged(m):
    lo, hi = m["judged"]
    return f"{strain_pct(lo)}-{hi:.1%}" if hi > lo else "-"


def modulus_cell(m):
    """The modulus as the tables give it: a number only where it has converged."""
    if m["converged"]:
        return fmt(m["E"])
    if m["burst"]:
        return "burst before loading"
    if not np.isfinite(m["E"]):
        return "- (failed before the window ends)"
    return f"not converged ({fmt(m['E'])} at v)"


def failure_cells(m):
    """(failure stress, strain at peak) as the tables give them: a number only where the failure
    has converged; else why not, with both speeds' values where they differ."""
    f, ff = m["fail"], m["fail_fast"]
    if m["burst"]:
        return "burst before loading", "-"
    if m["stopped"]:
        return ("; ".join(f"run{'' if which == 'v' else ' at 2v'} stopped at {pct(at)} (error)" for which, at in m["stopped"]),
                f"({pct(f['strain_at_peak'])} at v)")
    if m["rising"]:
        return f"> {fmt(f['peak_kPa'])} (still rising)", f"> {pct(f['strain_at_peak'])}"
    if m["failure_converged"]:
        return fmt(f["peak_kPa"]), pct(f["strain_at_peak"])
    return (f"not converged ({fmt(f['peak_kPa'])} at v; {fmt(ff['peak_kPa'])} at 2v)",
            f"({pct(f['strain_at_peak'])} at v; {pct(ff['strain_at_peak'])} at 2v)")


def table(kind, rows):
    head = (f"| Pi (kPa) | lamella | speed v (m/s) | P at start (kPa) | modulus {kind.window[0]:.0%}-"
            f"{kind.window[1]:.0%} (kPa) | failure stress (kPa) | strain at peak | first rupture (v; 2v) | "
            f"first debond (v; 2v) | failure mode | judged | {kind.ends} (worst) | KE/W (worst) | vs 2v (worst) | "
            "converged from |\n|" + "---|" * 15)
    lines = [head]
    for (pi, lam), m in rows.items():
        f, ff = m["fail"], m["fail_fast"]
        peak, at = failure_cells(m)
        lines.append(
            f"| {pi} | {lam} | {m['v']:g} | {m['P0']:.0f} | {modulus_cell(m)} | {peak} | {at} | "
            f"{pct(f['first'].get('wall rupture'))}; {pct(ff['first'].get('wall rupture'))} | "
            f"{pct(f['first'].get('lamella debonding'))}; {pct(ff['first'].get('lamella debonding'))} | "
            f"{'burst before loading' if m.get('burst') else f['mode']}"
            f"{' (stopped early, below)' if m.get('notes') else ''} | "
            f"{judged(m)} | {pct(m['balance'])} | {pct(m['ke'])} | {pct(m['rate'])} | "
            f"{'-' if m['start'] is None else strain_pct(m['start'])} |")
    return "\n".join(lines)


def where_text(rows, thirds=False):
    """Where each condition failed at v (failure_where), as a list under the table: a failure only in
    the bottom or top layer, which the plates or grips hold, is the fixture's, not the tissue's; so
    is a debonding only at the interfaces with end layers held whole (jaws cells), as far as the
    held cells' rigid walls load their lamella otherwise than a free cell's would. thirds: the
    block has no layers (a random block): its thirds by centroid are not what the fixture holds,
    so neither remark is made."""
    notes = []
    for (pi, lam), m in rows.items():
        w = (m.get("where") or {}).get("kinds")
        if not w:
            continue
        words = "; ".join(f"{kind} in " + ", ".join(f"{n} {layer}" for layer, n in by.items()) + " cell(s)"
                          for kind, by in w.items())
        # with two layers every cell is held: the remark needs a middle layer
        three = m["where"]["layers"] >= 3 and not thirds
        held = three and all(set(by) <= {"bottom", "top"} for by in w.values())
        faces = m["where"].get("interfaces") or {}
        if faces:
            words += "; the debonded bonds by interface: " + ", ".join(f"{k} {n}" for k, n in faces.items())
        by_grips = m["where"].get("held_interfaces")
        if by_grips:
            words += ("; by whether the grips hold the cells whole: "
                      + ", ".join(f"{k} {n}" for k, n in by_grips.items()))
        at_jaws = (three and m["where"].get("held_whole") and faces and "wall rupture" not in w
                   and all("bottom" in k or "top" in k for k in faces))
        notes.append(f"* Pi {pi}, {lam} lamella: {words}"
                     + (" (only in the layers the plates or grips hold)" if held else "")
                     + (" (only at the interfaces with the end layers the grips hold whole)" if at_jaws else ""))
    by = ("thirds of the cells by their centroids along the loading axis at the start; the plates or "
          "grips touch cells of the bottom and top thirds, not all of them" if thirds else
          "the cells' layer along the loading axis at the start")
    return (f"\nWhere the blocks failed (at v, by {by}):\n\n" + "\n".join(notes) + "\n") if notes else ""


def stopped_text(rows):
    """The runs an error stopped before their final strain, as a list under the table."""
    notes = [f"* Pi {pi}, {lam} lamella: {n}" for (pi, lam), m in rows.items() for n in m.get("notes", [])]
    return ("\nStopped early (their records end there; the checks and numbers above use what they hold):\n\n"
            + "\n".join(notes) + "\n") if notes else ""


def compare(kind, rows):
    """The converged rows against the measured orders (LITERATURE): modulus 1-20 MPa, failure
    stress 0.3 MPa; only what has converged is compared."""
    E = [m["E"] for m in rows.values() if m["converged"]]
    peak = [m["fail"]["peak_kPa"] for m in rows.values() if m["failure_converged"]]
    if not E and not peak:
        return "Neither a modulus nor a failure stress has converged here: nothing to set beside the measurements."
    if E:
        # the measured range's low end against the stiffest row, its top against the softest
        low, top = 1e3 / max(E), 2e4 / min(E)
        where = (f"lies {fmt(low, 2)}-{fmt(top, 2)} times below the measured 1-20 MPa" if low > 1 else
                 f"reaches the low end of the measured 1-20 MPa and lies up to {fmt(top, 2)} times below its top")
        modulus_words = f"the model's modulus, {span(E)} kPa, {where}"
    below = f"{span([300 / p for p in peak])} times below apple's 0.3 MPa" if peak else ""
    if E and peak:
        out = f"{modulus_words}, and its failure stress, {span(peak)} kPa, {below} ({kind.versus})."
    elif E:
        out = f"{modulus_words} ({kind.versus}); no failure stress has converged here."
    else:
        out = f"no modulus has converged here; the model's failure stress, {span(peak)} kPa, lies {below} ({kind.versus})."
    return out[0].upper() + out[1:]


def turgor_points(rows, lam):
    """([(pi, modulus)] of the converged moduli of a lamella in order of rising turgor, whether
    they rise with it); the rise is None with fewer than two converged moduli."""
    pts = sorted(((pi, rows[pi, lam]["E"]) for pi in PIS if (pi, lam) in rows and rows[pi, lam]["converged"]),
                 key=lambda p: -p[0])
    return pts, (all(b[1] > a[1] for a, b in zip(pts, pts[1:])) if len(pts) > 1 else None)


def turgor_trend(rows):
    """The converged moduli against turgor, per lamella."""
    out = []
    for lam in LAMELLAE:
        pts, rises = turgor_points(rows, lam)
        if len(pts) > 1:
            out.append(f"{lam.capitalize()} lamella: " + ", ".join(f"{fmt(e)} kPa at Pi {pi}" for pi, e in pts)
                       + (" (rises with turgor)." if rises else " (does not rise with turgor)."))
    return " ".join(out) or "Too few converged moduli to tell a trend."


def mode_trend(rows):
    return "Model: " + "; ".join(f"Pi {pi} {lam}: {'burst before loading' if m.get('burst') else m['fail']['mode']}"
                                 for (pi, lam), m in rows.items()) + "."


def fluid_per_cell(gen):
    return float(np.mean([c["fluid"] for c in gen["cell"]]))


def cell_size(gen):
    """The edge of a cube of the mean cell volume, um."""
    return gen["volume_mean"] ** (1 / 3)


def random_block(gen):
    """Whether the generator placed the seeds at random (a Laguerre block, not a lattice)."""
    return gen["seeds"].startswith("random")


def block_words(gen):
    """The block as the generator made it (gen/block.json), read from the run. A random block
    also gives its seed, the faces of its inner cells (a random block's outer cells are cut by
    its box), the diagram's faces left without a lamella bond and its porosity."""
    n = gen["cells"]
    cells = (f"{gen['wall_nodes_per_cell']} wall nodes and about {fluid_per_cell(gen):.0f} fluid particles per "
             f"cell, cells of about {cell_size(gen):.0f} um")
    faces = f"{gen['faces_mean']:.3g} faces and {gen['neighbours_mean']:.3g} glued neighbours per cell on average"
    if not random_block(gen):
        shape = gen["seeds"].split(",")[0].replace("lattice sc ", "")
        return f"The coarse {shape} block of {n} cells ({cells}, {faces})"
    seed = re.search(r"seed (\d+)", gen["seeds"]).group(1)
    inner = [c["faces"] for c in gen["cell"] if c.get("free_faces", 1) == 0]
    unglued = gen.get("unglued_faces", [])
    return (f"The coarse random Laguerre block of {n} cells (random seeds, seed {seed}; {cells}, volumes "
            f"spread {100 * gen['volume_rel_spread']:.0f}%, {faces}"
            + (f", {np.mean(inner):.3g} faces for its {len(inner)} inner cell{'s' if len(inner) != 1 else ''}"
               if inner else "")
            + f"; {len(unglued)} faces of the diagram, {sum(u['face_area'] for u in unglued):.0f} um^2, "
              f"without a lamella bond; porosity {gen['porosity']:.2f})")


def lamella_words(lams):
    """'a strong (sigl 300 kPa, Gl 1 J/m^2) and a weak lamella (30 kPa, 0.1 J/m^2)', as run."""
    last = len(lams) - 1
    return and_list(f"a {lam}{' lamella' if k == last else ''} ({'sigl ' if k == 0 else ''}{s['sigl']:g} kPa, "
                     f"{'Gl ' if k == 0 else ''}{s['Gl'] / 1000:g} J/m^2)" for k, (lam, s) in enumerate(lams.items()))


def modes_words(rows):
    """How the blocks failed first, counted: 'walls ruptured first in 3, ... of 6 conditions'."""
    kinds = ["burst before loading" if m.get("burst") else m["fail"]["mode"] for m in rows.values()]
    counts = {k: kinds.count(k) for k in dict.fromkeys(kinds)}
    return ", ".join(f"{k} in {n}" for k, n in counts.items()) + f" of {len(rows)} conditions"


def window_rule(kind):
    """What a converged window is (CHECKS), in words."""
    return (f"the {kind.ends} balance within {Q.TOL_BALANCE:.0%} and the curve stays within {Q.TOL_RATE:.0%} of "
            f"that at twice the speed (KE/W printed, not judged: in the coarse fluid it holds 3-10% of the "
            f"work at any speed, docs/Howto_plates.rst)")


def modulus_rule(kind):
    """When a modulus has converged (measure's `converged`), in words."""
    return (f"{window_rule(kind)}, in every {strain_pct(kind.width)} window from the modulus window "
            f"{'to the peak' if kind.to_peak else 'on'}, the block still intact")


def failure_rule(kind):
    """When a failure has converged (measure's `failure_converged`), in words."""
    return (f"the first rupture or debond at both speeds within {TOL_STRAIN:.0%} strain, the walls intact at "
            f"{strain_pct(kind.start)}, a peak before the record's last {TOL_STRAIN:.0%} strain, the peak stress "
            f"at 2v within {Q.TOL_RATE:.0%} of that at v and its strain within {TOL_STRAIN:.0%}, and neither run "
            f"stopped by an error within {TOL_STRAIN:.0%} strain after its peak")


def jaws_cells(lams):
    """Whether the grips held the end cells whole (in.tissue-tension -var jaws cells): the strain
    is then over the gauge between them. Runs older than the setting held nodes."""
    return any(st.get("jaws", "nodes") == "cells" for st in lams.values())


def held_kind(kind, lams):
    """The kind as the runs loaded it, with what the grips held (jaws cells: the end cells held
    whole): a compression by them has grips, not plates; a pull says what its grips held."""
    if not jaws_cells(lams):
        return kind
    grip = next(iter(lams.values())).get("grip")
    if kind.stage == "tension":
        return replace(kind, protocol=kind.protocol.replace(
            "the wall nodes near its bottom and top gripped",
            f"the whole walls of the cells at its bottom and top held by the grips (`-var jaws cells`, every cell "
            f"with a wall node within {grip:g} um of an end: the ends glued in, so the held cells cannot rupture; "
            "strain = the grips' travel over the gauge, the gap between the held walls)"))
    return replace(kind, ends="grips", protocol=(
        "the quasi-static protocol of `in.tissue-compress -var jaws cells`: no plates, the whole walls of "
        f"the cells at its bottom and top held and pressed together (every cell with a wall node within {grip:g} "
        "um of an end: the ends glued to the platens, so that the held cells cannot rupture and no plate "
        "flattens a domed outer cell; strain = the held cells' travel over the gauge, the gap between the "
        "held walls), at rest first, both grips closing after a smooth start"))


def protocol(kind, lams):
    """How the block was loaded, in words: the kind's protocol, with what the grips held."""
    return held_kind(kind, lams).protocol


def strain_label(kind, lams):
    if kind.stage == "compress":
        return ("strain (closing of the grips / gauge between the held cells)" if jaws_cells(lams)
                else "strain (closing of the plates / initial height)")
    return ("strain (opening of the grips / gauge between the held cells)" if jaws_cells(lams)
            else "strain (opening of the grips / initial height)")


def summary(kind, rows, gen, lams, lamf):
    """The plain-language summary at the top: what ran, the main numbers, what passed."""
    conv = [m for m in rows.values() if m["converged"]]
    fconv = [m for m in rows.values() if m["failure_converged"]]
    Es = [m["E"] for m in conv]
    peaks = [m["fail"]["peak_kPa"] for m in fconv]
    pis = sorted({pi for pi, _ in rows}, reverse=True)
    speeds = sorted({m["v"] for m in rows.values()})
    ran = (f"{block_words(gen)}, glued by the middle lamella, was inflated at Pi "
           f"{and_list(map(str, pis))} kPa with {lamella_words(lams)}, then {kind.did} "
           + (f"(walls rupture at the paper's critical stretch {lamf:g}) " if lamf
              else "(walls that never rupture: lamf 0) ")
           + f"with {protocol(kind, lams)}, "
           f"at v = {and_list(f'{v:g}' for v in speeds)} m/s (the "
           "speed column) and, as the rate evidence, at 2v (the ladder's last two rungs).")
    passed = (f"The modulus converged in {len(conv)} of {len(rows)} conditions ({modulus_rule(kind)})"
              + (f": {span(Es)} kPa." if conv else ".")
              + f" The failure converged in {len(fconv)} ({failure_rule(kind)})"
              + (f": failure stress {span(peaks)} kPa." if fconv else "."))
    return " ".join(x for x in (ran, passed, f"First failure: {modes_words(rows)}.", compare(kind, rows),
                                "Every number is from the run at v; a condition that has not converged is a rate "
                                "study, and its row says so.") if x)


def text(kind, rows, info, gen, name, lams):
    lamf = next(iter(lams.values()))["lamf"]
    lit = "\n".join(f"| {a} | {b} | {c} |" for a, b, c in LITERATURE)
    return f"""# {kind.title}

*Generated by `tools/tissue-converged.sh` ({info}); do not edit by hand.*

**Summary.** {summary(kind, rows, gen, lams, lamf)}

![stress-strain]({name}.png)

{table(kind, rows)}
{stopped_text(rows)}{where_text(rows, random_block(gen))}
*Modulus*: slope of a straight line through the stress over {kind.window[0]:.0%}-{kind.window[1]:.0%}
strain, given where it has converged (*converged from*, below), else *not converged (X at v)*.
*Failure stress*: the peak of the stress over 1% strain windows, with its strain, given where the
failure has converged: {failure_rule(kind)}; else *not converged (X at v; Y at 2v)*, both speeds'
peaks (and strains), or *run stopped at X% (error)* where an error stopped the run at v (or at 2v)
within {TOL_STRAIN:.0%} strain after its peak, which may then be the blow-up's. *First
rupture*: at both speeds; where they differ, the failure strain has not converged with the speed
(the checks end at the earlier one: past it the two curves part by the timing of the events).
*First debond*: likewise, the first lamella bond to let go.
*Failure mode*: which kind of failure begins first, wall rupture (a tether breaks) or lamella
debonding (a lamella bond lets go); *burst before loading*: a wall ruptured before {strain_pct(kind.start)} strain,
under the cell's own turgor (the inflated wall's stretch near the critical 1.04), so the block had
failed before the {kind.ends} loaded it, and its row gives no failure stress; *> X*: the stress was still
rising at the record's end, so X bounds the failure stress from below and the row's failure has not
converged. *Judged*: from {strain_pct(kind.start)} strain to the first rupture of either run{' or the peak stress of the run at v, whichever comes first' if kind.to_peak else ''}.
*{kind.ends.capitalize()}*: the largest (F_top - F_bottom) / mean over {strain_pct(kind.width)} windows there; *KE/W*: the largest kinetic
energy against the {kind.ends}' work over those windows (cellmech.quasistatic's, per window: the window-mean
kinetic energy of all atoms over the window-mean work the {kind.ends} have done since the record's start);
*vs 2v*: the largest difference of the window-mean {kind.ends[:-1]} force between the two speeds. *Converged
from*: the strain from which every {strain_pct(kind.width)} window passes the checks of cellmech.quasistatic that decide:
{window_rule(kind)}. A condition's modulus counts as converged when that is at or below the modulus window
(no modulus where the block has ruptured before the window ends{', or its lamella has begun to let go: a pull loads it directly' if kind.to_peak else ''}).

## Side by side with parenchyma

| quantity | measured in parenchyma | source |
|---|---|---|
{lit}

What the model gives, and why it differs:

* **Modulus and failure stress.** {compare(kind, rows)} The wall is the paper's stiff single cell's
  (Table I: G = 800 MPa, thickness 0.126 um, G t0 = 100 N/m) on cells of about {cell_size(gen):.0f} um, not a wall fitted to
  apple or potato; a block of {gen['cells']} cells with free faces all round is not a bulk tissue
  ({surface(gen)}); and the coarse wall ({gen['wall_nodes_per_cell']} nodes) and fluid (about {fluid_per_cell(gen):.0f} particles)
  bound the curve's resolution. These are the model's numbers at this resolution: nothing was tuned
  towards the measurements.
* **Turgor.** Measured moduli rise with turgor. {turgor_trend(rows)}
* **Failure mode.** Measured: turgid tissue breaks by cell rupture, flaccid or weakly bonded tissue
  by cells coming apart. {mode_trend(rows)}
* **Bruise volume per impact energy** is not here: the impacts are dynamic by nature and stay in
  docs/tissue.md (in.tissue-impact), labelled as such.

The compression reports are docs/tissue-quasistatic.md (the 2x2x2 block) and
docs/tissue-quasistatic-27.md (the 27-cell block), the tension reports docs/tissue-tension-quasistatic.md
(the 2x2x2 block), docs/tissue-tension-quasistatic-27.md (the 27-cell block held by rings of nodes) and
docs/tissue-tension-jaws-27.md (held by its end layers) (`tools/tissue-converged.sh` says how each is
made). Not yet held (issue 29, item 4): a random Laguerre block at converged rates.

## References

{REFERENCES}
"""


def surface(gen):
    """How much of the block is surface: the cells without a free face (the generator's
    free_faces), or for a cubic block without them n^3 cells of which (n - 2)^3 are inner."""
    if all("free_faces" in c for c in gen["cell"]):
        inner = sum(c["free_faces"] == 0 for c in gen["cell"])
    else:
        n = round(gen["cells"] ** (1 / 3))
        inner = max(n - 2, 0) ** 3
    return ("every cell is a surface cell, free to bulge sideways" if inner == 0 else
            f"{gen['cells'] - inner} of its {gen['cells']} cells lie on its surface, free to bulge sideways")


def run_info(kind, runs):
    """What ran, from RUNS/run-info.txt: the driver's lines of this kind (a folder may hold both
    experiments on the same inflated blocks; the tension's lines start with EXP=tension)."""
    if not os.path.exists(f"{runs}/run-info.txt"):
        return runs
    lines = [ln for ln in open(f"{runs}/run-info.txt").read().split("\n") if ln]
    return "; ".join(ln for ln in lines if ln.startswith("EXP=tension") == (kind.stage == "tension"))


def conditions(kind, runs):
    """(load_runs(kind, runs), {(pi, lam): measure(...) with the slow speed v and the notes}): every
    condition of the kind in RUNS, measured and judged."""
    data = load_runs(kind, runs)

    def where(pi, lam, v):
        run = f"{runs}/{kind.stage}{pi}-{lam}-{v:g}/tissue-{kind.stage}"
        return dict(T.failure_where(f"{run}-cells.dat", f"{run}-pairs.dat", T.held_cells(f"{run}-held.txt")),
                    held_whole=jaws_cells({lam: run_settings(kind, runs, pi, lam, v)}))
    return data, {key: dict(measure(kind, slow, fast, errors), v=v, notes=stop_notes(v, slow, fast, errors),
                            where=where(*key, v))
                  for key, (v, slow, fast, errors) in data.items()}


def main(argv=None):
    args = argv or sys.argv[1:]
    runs, report = args[:2]
    name = args[2] if len(args) > 2 else "tissue-quasistatic"
    which = args[3] if len(args) > 3 else "compress"
    if which not in KINDS:
        raise SystemExit(f"converged: KIND {which}: expected one of {', '.join(KINDS)}")
    kind = KINDS[which]
    data, rows = conditions(kind, runs)
    if not data:
        raise SystemExit(f"converged: no condition with runs at v and 2v in {runs}")
    info = run_info(kind, runs)
    gen = gen_stats(f"{runs}/gen/block.json")
    lams = lamella_settings(kind, runs, data)
    kind = held_kind(kind, lams)
    figure(kind, data, lams, f"{report}/{name}.png")
    with open(f"{report}/{name}.md", "w") as f:
        f.write(text(kind, rows, info, gen, name, lams))
    print(table(kind, rows))


if __name__ == "__main__":
    main()
