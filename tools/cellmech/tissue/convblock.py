# SPDX-License-Identifier: GPL-2.0-or-later
"""Section 2 of the tissue report (cellmech.tissue.report): the blocks compressed and pulled apart
at converged rates, read from tools/tissue-converged.sh's run folders (report.py --converged DIR
...). Every condition is measured and judged by cellmech.tissue.converged (one source: its
modulus, failure, checks and verdicts); this module only lays them out per block size and
experiment, says where a number has not converged, and holds the published trends against the
converged numbers. Every number goes into the summary (rep.S["block_converged"],
rep.S["block_trends"])."""
import os
from dataclasses import dataclass

import numpy as np

from . import converged as C
from .tissuedata import and_list, fmt, gen_stats, pct

TITLE = "## 2. Blocks at converged rates: compression and tension to failure"
# the published trends the section checks, with their sources (converged.LITERATURE's rows)
STIFFER = ("Higher turgor stiffens the tissue: measured moduli rise with turgor "
           f"({C.LITERATURE[0][2]}).")
EARLIER = "Higher turgor makes the tissue fail earlier (at a smaller strain)."
MODE = (f"Weak adhesion turns rupture into debonding: {C.LITERATURE[2][1]} ({C.LITERATURE[2][2]}).")


@dataclass
class Campaign:
    """One run folder's conditions of one experiment (converged.KINDS), measured by converged.py."""
    runs: str
    gen: dict
    kind: C.Kind
    rows: dict          # {(pi, lam): converged.conditions' row}
    lams: dict          # {lam: the settings its runs were given}
    page: str           # the dedicated report's name (NAME of NAME.md in runs), or None

    @property
    def cells(self):
        return int(self.gen["cells"])

    @property
    def held_whole(self):
        """A tension whose grips held the end cells whole (in.tissue-tension -var jaws cells)."""
        return self.kind.stage == "tension" and C.jaws_cells(self.lams)

    @property
    def tag(self):
        return f"{self.kind.stage}_{self.cells}" + ("_jaws" if self.held_whole else "")

    def heading(self):
        shape = self.gen["seeds"].split(",")[0].replace("lattice sc ", "")
        return (f"{shape} block of {self.cells} cells, {'compression' if self.kind.stage == 'compress' else 'tension'}"
                + (", its end layers held whole" if self.held_whole else ""))


def page_name(kind, runs):
    """The converged report tools/tissue-converged.sh wrote for this kind into RUNS: the NAME.md
    whose title is the kind's (None where there is none)."""
    for name in sorted(os.listdir(runs)):
        if name.endswith(".md"):
            with open(os.path.join(runs, name)) as f:
                if f.readline().strip() == f"# {kind.title}":
                    return name[:-3]
    return None


def campaigns(dirs):
    """[Campaign] of every experiment with conditions in each run folder, by block size, compression
    first."""
    out = []
    for runs in dirs:
        gen = gen_stats(os.path.join(runs, "gen", "block.json"))
        for kind in C.KINDS.values():
            data, rows = C.conditions(kind, runs)
            if rows:
                out.append(Campaign(runs, gen, kind, rows, C.lamella_settings(kind, runs, data),
                                    page_name(kind, runs)))
    order = list(C.KINDS)
    return sorted(out, key=lambda c: (c.cells, order.index(c.kind.stage)))


def first_fast(m):
    """The first failure event of the run at 2v (None: none)."""
    f = m["fail_fast"]["first"]
    return min(f.values()) if f else None


def mode_cell(m):
    if m["burst"]:
        return "burst before loading"
    mode, fast = m["fail"]["mode"], m["fail_fast"]["mode"]
    return (mode + ("" if fast == mode else f" (2v: {fast})")
            + ("" if m["first_converged"] else " (not converged)")
            + (" (stopped early, below)" if m.get("notes") else ""))


def table(c):
    k = c.kind
    head = (f"| Pi (kPa) | lamella | v (m/s) | P at start (kPa) | modulus {k.window[0]:.0%}-{k.window[1]:.0%} (kPa) | "
            f"failure stress (kPa) | strain at peak | first failure (v; 2v) | failure mode | judged | "
            f"{k.ends} (worst) | KE/W (worst) | vs 2v (worst) | converged from |")
    lines = [head, "|" + "---|" * 14]
    for (pi, lam), m in c.rows.items():
        peak, at = C.failure_cells(m)
        lines.append(f"| {pi} | {lam} | {m['v']:g} | {m['P0']:.0f} | {C.modulus_cell(m)} | {peak} | {at} | "
                     f"{C.pct(m['first_event'])}; {C.pct(first_fast(m))} | {mode_cell(m)} | {C.judged(m)} | "
                     f"{C.pct(m['balance'])} | {C.pct(m['ke'])} | {C.pct(m['rate'])} | "
                     f"{'-' if m['start'] is None else C.strain_pct(m['start'])} |")
    return lines


def link(rep, c):
    """Where the campaign's own report is, from the tissue report's folder."""
    if c.page is None:
        return None
    here = os.path.join(rep.report, f"{c.page}.md")
    return f"{c.page}.md" if os.path.exists(here) else os.path.relpath(os.path.join(c.runs, f"{c.page}.md"), rep.report)


def text_campaign(rep, n, c):
    k = c.kind
    ln = link(rep, c)
    rep.w(f"### 2.{n} The {c.heading()}", "",
          f"Run folder `{c.runs}` ({C.run_info(k, c.runs)}); each condition at v and, as its rate evidence, at 2v "
          "(the two slowest speeds of the ladder that differ by 2)"
          + (f"; its own report, with the stress-strain curves at both speeds: [{c.page}.md]({ln})." if ln else "."), "")
    if ln:
        rep.w(f"![{c.page}]({ln[:-3]}.png)", "")
    rep.w(*table(c))
    notes = C.stopped_text(c.rows) + C.where_text(c.rows)
    if notes:
        rep.w(*notes.rstrip("\n").split("\n"))
    rep.w("")


def jsonable(m):
    """A condition's numbers for the summary file (nan as None)."""
    def num(x):
        return None if x is None or not np.isfinite(x) else float(x)
    f = m["fail"]
    return {"v_m_s": m["v"], "P_start_kPa": m["P0"], "modulus_kPa": num(m["E"]), "modulus_converged": m["converged"],
            "failure_stress_kPa": None if m["burst"] else f["peak_kPa"],
            "strain_at_peak": None if m["burst"] else f["strain_at_peak"], "still_rising": m["rising"],
            "failure_converged": m["failure_converged"],
            "failure_stress_2v_kPa": None if m["burst"] else m["fail_fast"]["peak_kPa"],
            "strain_at_peak_2v": None if m["burst"] else m["fail_fast"]["strain_at_peak"],
            "peak_agrees_2v": m["peak_agrees"],
            "stopped_by_error_after_peak": [{"run": which, "strain": at} for which, at in m["stopped"]],
            "first_event_strain": m["first_event"],
            "first_event_strain_2v": first_fast(m), "first_event_converged": m["first_converged"],
            "mode": "burst before loading" if m["burst"] else f["mode"], "mode_2v": m["fail_fast"]["mode"],
            "burst_before_loading": m["burst"], "judged_strain": list(m["judged"]), "balance_worst": num(m["balance"]),
            "ke_over_work_worst": num(m["ke"]), "vs_2v_worst": num(m["rate"]), "converged_from": m["start"],
            "check_at_v": m["verdict"], "notes": m.get("notes", [])}


# ------------------------------------------------------------------ trends
def turgor_stiffer(c, lam):
    """(verdict or None, words): do the converged moduli rise with turgor (converged.turgor_points)?"""
    pts, rises = C.turgor_points(c.rows, lam)
    left = [f"Pi {pi}: " + ("burst before loading" if m["burst"] else "failed before the window ends"
                            if not np.isfinite(m["E"]) else "not converged")
            for pi in C.PIS if (pi, lam) in c.rows and not (m := c.rows[pi, lam])["converged"]]
    words = ", ".join(f"{fmt(e)} kPa at Pi {pi}" for pi, e in pts) or "none"
    return rises, words + (f" ({'; '.join(left)})" if left else "")


def falls(pts):
    """Do the values fall with rising turgor (pts in order of rising turgor; None: too few)?"""
    return all(b[1] < a[1] for a, b in zip(pts, pts[1:])) if len(pts) > 1 else None


def turgor_earlier(c, lam):
    """(first event earlier with turgor, words; peak earlier with turgor, words): the first failure
    event where it converged (a block burst before loading failed before any strain) and the strain
    at peak where the failure converged."""
    rows = [(pi, c.rows[pi, lam]) for pi in sorted((p for p, l_ in c.rows if l_ == lam), key=lambda p: -p)]
    # a block that did not fail within its record gives no strain to compare
    ev = [(pi, -np.inf if m["burst"] else m["first_event"]) for pi, m in rows
          if m["burst"] or (m["first_converged"] and m["first_event"] is not None)]
    pk = [(pi, m["fail"]["strain_at_peak"]) for pi, m in rows if m["failure_converged"]]
    ev_w = ", ".join(f"{'burst before loading' if x == -np.inf else pct(x)} at Pi {pi}" for pi, x in ev) or "none converged"
    pk_w = ", ".join(f"{pct(x)} at Pi {pi}" for pi, x in pk) or "none converged"
    return falls(ev), ev_w, falls(pk), pk_w


def mode_turn(c, pi):
    """(does the weak lamella turn the strong one's wall rupture into debonding at this turgor, or
    None where either's first failure has not converged, burst, or changes kind at 2v; words)."""
    a, b = c.rows.get((pi, "strong")), c.rows.get((pi, "weak"))
    if not (a and b):
        return None, None
    burst = a["burst"] or b["burst"]
    why = [f"{lam}: {w}" for lam, m in (("strong", a), ("weak", b)) if not m["burst"]
           for w in (["no failure within its record"] if not m["fail"]["first"] else
                     ([] if m["first_converged"] else ["first failure not converged"])
                     + ([] if m["fail"]["mode"] == m["fail_fast"]["mode"] else ["another kind at 2v"]))]
    words = f"strong lamella: {mode_cell(a)}, weak: {mode_cell(b)}" + (f" ({'; '.join(why)})" if why else "")
    if why or burst:
        return None, words
    return a["fail"]["mode"] == "wall rupture" and b["fail"]["mode"] == "lamella debonding", words


def verdict_word(v):
    return "**yes**" if v else ("**no**" if v is not None else "**cannot tell**")


def trends(cs):
    """({key: True, False or None (not enough converged numbers)}, the lines saying them)."""
    T_, lines = {}, []
    for c in cs:
        lines += [f"*{c.heading()[0].upper() + c.heading()[1:]}* ({c.runs}):", ""]
        for lam in C.LAMELLAE:
            s, sw = turgor_stiffer(c, lam)
            e, ew, p, pw = turgor_earlier(c, lam)
            T_[f"{c.tag}_turgor_stiffer_{lam}"] = s
            T_[f"{c.tag}_turgor_fails_earlier_{lam}"] = e
            T_[f"{c.tag}_turgor_peak_earlier_{lam}"] = p
            lines.append(f"* {lam} lamella: converged modulus {sw} -> higher turgor stiffer: {verdict_word(s)}; "
                         f"first failure (converged) {ew} -> fails earlier: {verdict_word(e)}; strain at peak "
                         f"(converged) {pw} -> peak earlier: {verdict_word(p)}.")
        for pi in C.PIS:
            t, tw = mode_turn(c, pi)
            if tw is None:
                continue
            T_[f"{c.tag}_weak_turns_rupture_into_debonding_Pi{pi}"] = t
            lines.append(f"* Pi {pi}: {tw} -> weak adhesion turns rupture into debonding: {verdict_word(t)}.")
        lines.append("")
    return T_, lines


def text_trends(rep, cs):
    T_, lines = trends(cs)
    rep.w("### Do the published trends hold here?", "", "Measured in parenchyma:", "",
          *[f"* {t}" for t in (STIFFER, EARLIER, MODE)], "",
          "Each trend is held against the "
          "converged numbers of each block and experiment above, and only those: a modulus where the condition "
          "converged, a first failure where both speeds begin to fail within 1% strain (a block burst before "
          "loading failed first of all), a strain at peak where the failure converged, a failure mode where the "
          "first failure converged and is of the same kind at 2v, both blocks having failed. *Cannot tell*: fewer "
          "than two converged numbers to compare. The failure mode here is which kind of failure begins first (converged.py), not "
          "the share of each material failed at the end of a run to 30% strain (section 3's rate study): past "
          "the first failure the checks judge nothing.", "", *lines)
    return T_


def section(rep, dirs):
    """Section 2 into rep (markdown, rep.S["block_converged"], rep.S["block_trends"]) from the
    converged campaigns' run folders dirs."""
    rep.w(TITLE, "")
    cs = campaigns(dirs) if dirs else []
    rep.converged = cs
    if not cs:
        rep.w("No converged campaign was given (report.py --converged DIR ...; tools/tissue.sh CONVERGED=...): "
              "this report has no block numbers at converged rates, and section 3's runs are a rate study only.", "")
        rep.S["block_converged"], rep.S["block_trends"] = [], {}
        return
    c0 = cs[0]
    rep.w(f"Blocks made by `tools/tissue-converged.sh` ({and_list(f'{n} cells' for n in sorted({c.cells for c in cs}))}), each "
          f"inflated at Pi {and_list(map(str, sorted({pi for c in cs for pi, _ in c.rows}, reverse=True)))} kPa with "
          f"{C.lamella_words(c0.lams)} and brought to rest, then loaded to failure at two speeds, v and 2v: "
          f"compressed with {C.KINDS['compress'].protocol}; pulled apart with {C.KINDS['tension'].protocol}. "
          "Every number and verdict below is cellmech.tissue.converged's (the campaign's own report says how each "
          "is measured): the modulus is the slope over its window where the condition has converged (a window "
          f"converges when it passes the checks of cellmech.quasistatic that decide: {C.window_rule(C.KINDS['compress'])}"
          " (the grips' in a tension); the modulus when every window from the modulus window on does, to the peak "
          "in a tension, the block intact), else *not converged* with the value at v in brackets; the failure "
          f"stress and strain where the failure has converged ({C.failure_rule(C.KINDS['compress'])}; in a "
          f"tension the walls intact at {C.strain_pct(C.KINDS['tension'].start)}), else *not converged* with "
          "the values at v and at 2v, or *run stopped at X% (error)*; *> X* where the stress still rose at the "
          "record's end; *burst before loading*: a wall ruptured under its own turgor before the loading began. "
          "Evidence: *judged* (the strain range of the checks), the worst plate (grip) balance, the worst KE/W "
          "(per window: the window-mean kinetic energy of all atoms over the window-mean work of the plates or "
          "grips since the record's start), the worst difference to 2v, and the strain from which every window "
          "passes all three (*converged from*).", "")
    for n, c in enumerate(cs, 1):
        text_campaign(rep, n, c)
    rep.S["block_converged"] = [{"cells": c.cells, "experiment": c.kind.stage, "ends_held_whole": c.held_whole,
                                 "runs": c.runs, "page": c.page,
                                 "modulus_window": list(c.kind.window),
                                 "lamellae": {lam: {"sigl_kPa": s["sigl"], "Gl": s["Gl"]} for lam, s in c.lams.items()},
                                 "conditions": {f"{pi}_{lam}": jsonable(m) for (pi, lam), m in c.rows.items()}}
                                for c in cs]
    rep.S["block_trends"] = text_trends(rep, cs)
