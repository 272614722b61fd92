# SPDX-License-Identifier: GPL-2.0-or-later
"""Section 1 of the tissue report (cellmech.tissue.report): two glued cells pressed and pulled
apart (in.tissue-pair), beside a single cell of the same size pressed alone. Load, measure,
figures, text; every number goes into the summary (rep.S["pair"])."""
import os
import types

import numpy as np

from .. import params, reporting
from .. import quasistatic as Q
from . import converged as C
from . import tissuedata as T

plt = reporting.pyplot()

TITLE = "## 1. Two glued cells: press and pull"
TRAVEL_UM = (1.0, 2.0, 3.0, 4.0)    # plate travels at which the pair and the single cell are compared
STRAINS = (0.01, 0.02, 0.03, 0.05)  # ... and strains (the pair is twice as tall: twice the travel)


def load(rep):
    """(press of the pair, press of the single cell, pull of the pair or None, the pair's settings),
    or None when either press is missing. The approach (plate travel from first contact) is added
    to both presses."""
    if not (os.path.exists(rep.p("pair/pair-press.dat")) and os.path.exists(rep.p("single/pair-press.dat"))):
        return None
    pr = T.load(rep.p("pair/pair-press.dat"), T.PRESS)
    sg = T.load(rep.p("single/pair-press.dat"), T.PRESS)
    pl = T.load(rep.p("pair/pair-pull.dat"), T.PULL) if os.path.exists(rep.p("pair/pair-pull.dat")) else None
    ps = rep.settings("pair", "in.tissue-pair")
    for d in (pr, sg):
        d["approach_um"] = ps["vplate"] * d["time_us"] - 2 * ps["gap"]
    T.write_csv(rep.fig("pair-press.csv"), pr, ["time_us", "strain", "approach_um"] + T.PRESS[2:],
                "in.tissue-pair, two glued cells stacked along z: press (P1, P2 the two cells)")
    T.write_csv(rep.fig("single-press.csv"), sg, ["time_us", "strain", "approach_um", "F_top_nN",
                "F_bottom_nN", "P1_kPa"], "in.tissue-pair -var ncell 1: the single cell pressed")
    return pr, sg, pl, ps


def measure_press(pr, sg, window_us):
    """The press's numbers (summary keys) and the smoothing window n (samples): forces smoothed by
    a centred moving average over window_us of plate time."""
    n = max(1, int(round(window_us / np.median(np.diff(pr["time_us"])))))
    fp, fs = T.smooth(pr["F_top_nN"], n), T.smooth(sg["F_top_nN"], n)
    S = {}
    # forces at the end of the press (mean of the last window)
    S["press_end_strain_pair"] = float(pr["strain"][-1])
    S["press_end_force_pair_nN"] = float(fp[-1])
    S["press_end_strain_single"] = float(sg["strain"][-1])
    S["press_end_force_single_nN"] = float(fs[-1])
    # force at the same strain: 5% (both reach it)
    e5 = 0.05
    S["force_at_5pct_pair_nN"] = float(np.interp(e5, pr["strain"], fp))
    S["force_at_5pct_single_nN"] = float(np.interp(e5, sg["strain"], fs))
    S["glued_area_start_um2"] = float(pr["glued_area_um2"][0])
    S["contact_area_start_um2"] = float(pr["contact_area_um2"][0])
    S["glued_area_end_press_um2"] = float(pr["glued_area_um2"][-1])
    S["contact_area_end_press_um2"] = float(pr["contact_area_um2"][-1])
    S["P_start_kPa"] = [float(pr["P1_kPa"][0]), float(pr["P2_kPa"][0])]
    S["P_end_press_kPa"] = [float(np.mean(pr["P1_kPa"][-n:])), float(np.mean(pr["P2_kPa"][-n:]))]
    S["P_single_start_kPa"] = float(sg["P1_kPa"][0])
    S["P_single_end_press_kPa"] = float(np.mean(sg["P1_kPa"][-n:]))
    S["press_work_pair_nNum"] = T.integral(pr["F_top_nN"][pr["approach_um"] > 0],
                                           pr["approach_um"][pr["approach_um"] > 0])
    S["window_samples"] = n
    S["by_travel"] = [{"travel_um": x, "pair_nN": float(np.interp(x, pr["approach_um"], fp)),
                       "single_nN": float(np.interp(x, sg["approach_um"], fs))}
                      for x in TRAVEL_UM if x <= min(pr["approach_um"].max(), sg["approach_um"].max())]
    S["by_strain"] = [{"strain": e, "pair_nN": float(np.interp(e, pr["strain"], fp)),
                       "single_nN": float(np.interp(e, sg["strain"], fs))} for e in STRAINS]
    S["quasistatic"] = {"pair": balance_check(pr), "single": balance_check(sg)}
    return S, n


def balance_check(d):
    """The press's quasi-static check (cellmech.quasistatic) from the compression's check start to
    its end: the plates' balance only (the pair's record has no kinetic energy or plate work)."""
    k = C.KINDS["compress"]
    bal = Q.balance(d["strain"], d["F_top_nN"], d["F_bottom_nN"], k.start, float(d["strain"].max()), k.width)
    v = Q.verdict(bal, [])
    return {"balance_worst": v.numbers["balance"], "balance_window": v.numbers["balance_window"],
            "dynamic": "balance" in v.failed, "range": [k.start, float(d["strain"].max())],
            "bottom_first_load_strain": T.first_rise(d["strain"], np.asarray(d["F_bottom_nN"], float))[0],
            "reason": next((r for r in v.reasons if r.startswith("balance")), "")}


def ratio(a, b):
    return a / b if b else float("nan")


def measure_pull(pl, ps, window_us):
    """The pull's curves and numbers: the grip force smoothed over one period of its ringing, the
    work of separation up to the last debond against Gl x glued area. Returns a namespace u with
    the arrays the figure draws and u.S, the summary keys."""
    u = types.SimpleNamespace(sep=pl["separation_um"], Fraw=pl["F_pull_nN"], vpull=ps["vpull"])
    # the grip force rings (the pair's shape oscillation against the rigidly moved grips): smoothed
    # over one period of that ringing (its strongest Fourier component) before the F > 0 cut,
    # which would otherwise keep half of every oscillation
    u.dsep = float(np.median(np.diff(u.sep)))
    per = T.dominant_period(u.Fraw, u.dsep)
    u.npl = max(1, int(round((per if per else window_us * 0.5) / u.dsep)))
    u.F = T.smooth(u.Fraw, u.npl)
    pl["F_pull_smoothed_nN"] = u.F
    deb = pl["debonded_bonds"]
    kd = np.nonzero(np.diff(deb) > 0)[0]
    u.k_last = int(kd[-1] + 1) if len(kd) else len(u.sep) - 1
    u.separated = bool(pl["glued_area_um2"][-1] <= 0 or pl["lamella_bonds"][-1] <= 0)
    u.sl = slice(0, u.k_last + 1)
    u.Fp = np.where(u.F[u.sl] > 0, u.F[u.sl], 0.0)
    u.W = T.integral(u.Fp, u.sep[u.sl])
    u.A0 = A0 = float(pl["glued_area_um2"][0])
    u.kmax = int(np.argmax(u.F))
    u.Gl, sigl = ps["Gl"], ps["sigl"]
    u.S = dict(pull_ringing_period_um=per, pull_window_samples=u.npl,
               pull_force_max_raw_nN=float(np.max(u.Fraw)),
               work_signed_raw_nNum=T.integral(u.Fraw[u.sl], u.sep[u.sl]),
               interface_adhesion_max_nN=float(-np.min(pl["F_interface_nN"])))
    u.S.update(pull_force_max_nN=float(u.F[u.kmax]), pull_force_max_sep_um=float(u.sep[u.kmax]),
               pull_glued_area_start_um2=A0, pull_last_debond_sep_um=float(u.sep[u.k_last]),
               pull_separated=u.separated, pull_glued_area_end_um2=float(pl["glued_area_um2"][-1]),
               pull_debonded_bonds_end=int(deb[-1]), pull_lamella_bonds_end=int(pl["lamella_bonds"][-1]),
               work_separation_nNum=u.W, Gc=u.Gl, sigl_kPa=sigl,
               GcA_nNum=u.Gl * A0, W_over_GcA=u.W / (u.Gl * A0) if A0 > 0 else None,
               sigmaA_nN=sigl * A0,
               pull_P_end_kPa=[float(pl["P1_kPa"][-1]), float(pl["P2_kPa"][-1])],
               pull_F_end_nN=float(u.F[-1]))
    return u


def write_pull_csv(rep, pl, u):
    T.write_csv(rep.fig("pair-pull.csv"), pl, T.PULL[:2] + ["F_pull_smoothed_nN"] + T.PULL[2:],
                f"in.tissue-pair, pull: top grip moves up at {u.vpull:g} m/s; F_pull > 0 in tension; smoothed: "
                f"centred moving average over {u.npl} samples ({u.npl * u.dsep:.3g} um of separation)")


def press_force_axes(a0, a3, pr, sg, n, window_us):
    """The force panels of the press figure: against strain (a0) and against approach (a3)."""
    fp, fs = T.smooth(pr["F_top_nN"], n), T.smooth(sg["F_top_nN"], n)
    a3.plot(pr["approach_um"], fp / 1e3, color="C0", label="glued pair")
    a3.plot(sg["approach_um"], fs / 1e3, color="C1", label="single cell")
    a3.set_xlabel("approach = plate travel from first contact (um)")
    a3.set_ylabel("top plate force (uN, smoothed)")
    a3.set_xlim(left=-0.5)
    a3.legend(fontsize=8)
    a3.set_title("press: force vs approach", fontsize=9)
    a0.plot(pr["strain"], pr["F_top_nN"] / 1e3, color="C0", alpha=0.25, lw=0.7)
    a0.plot(sg["strain"], sg["F_top_nN"] / 1e3, color="C1", alpha=0.25, lw=0.7)
    a0.plot(pr["strain"], fp / 1e3, color="C0", label="glued pair (two cells in series)")
    a0.plot(sg["strain"], fs / 1e3, color="C1", label="single cell")
    a0.set_xlabel("strain (plate travel / initial height)")
    a0.set_ylabel("top plate force (uN)")
    a0.set_xlim(left=-0.01)
    ax0b = a0.secondary_xaxis("top")
    ax0b.set_xlabel("(pair height ~ 2x single: same strain = twice the approach)", fontsize=8)
    ax0b.set_xticks([])
    a0.legend(fontsize=8)
    a0.set_title(f"press (smoothed: {window_us:g} us window; faint: raw)", fontsize=9)


def figure_press(rep, pr, sg, n, window_us, pulled):
    """pair-press.png: force against strain and approach, the interface's areas, the pressures."""
    fig, ax = plt.subplots(1, 4, figsize=(20, 4.6))
    press_force_axes(ax[0], ax[3], pr, sg, n, window_us)
    ax[1].plot(pr["strain"], pr["contact_area_um2"], label="contact area (glued or touching)")
    ax[1].plot(pr["strain"], pr["glued_area_um2"], label="glued area (intact lamella)")
    ax[1].set_xlabel("strain")
    ax[1].set_ylabel("area (um^2)")
    ax[1].set_xlim(left=-0.01)
    ax[1].legend(fontsize=8)
    ax[1].set_title("cell-cell interface of the pair", fontsize=9)
    ax[2].plot(pr["strain"], T.smooth(pr["P1_kPa"], n), label="pair: cell 1 (bottom)")
    ax[2].plot(pr["strain"], T.smooth(pr["P2_kPa"], n), label="pair: cell 2 (top)")
    ax[2].plot(sg["strain"], T.smooth(sg["P1_kPa"], n), label="single cell", ls="--")
    if pulled:
        ax[2].plot([], [])
    ax[2].set_xlabel("strain")
    ax[2].set_ylabel("mean fluid pressure (kPa)")
    ax[2].set_xlim(left=-0.01)
    ax[2].legend(fontsize=8)
    ax[2].set_title("pressures during the press", fontsize=9)
    reporting.save_figure(rep.fig("pair-press.png"), fig, tight=True)


def figure_pull(rep, pl, u):
    """pair-pull.png: the pull force with the work of separation shaded, the areas and pressures."""
    sep = u.sep
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.4))
    ax[0].plot(sep, u.Fraw / 1e3, lw=0.5, color="C0", alpha=0.25, label="raw")
    ax[0].plot(sep, u.F / 1e3, lw=1.2, color="C0", label=f"pull force on the top grip (window {u.npl * u.dsep:.3g} um)")
    ax[0].plot(sep, -pl["F_interface_nN"] / 1e3, lw=0.8, color="C4",
               label="adhesion across the interface (-lamella - contact force)")
    ax[0].fill_between(sep[u.sl], 0, u.Fp / 1e3, color="C0", alpha=0.2,
                       label=f"W = {u.W / 1e3:.3g} pJ (F > 0, to the last debond)")
    ax[0].axvline(sep[u.k_last], color="k", ls=":", lw=0.8, label="last debond")
    ax[0].plot(sep[u.kmax], u.F[u.kmax] / 1e3, "rv", label=f"pull-off force {u.F[u.kmax] / 1e3:.3g} uN")
    ax[0].axhline(0, color="grey", lw=0.5)
    ax[0].set_xlabel("grip separation (um)")
    ax[0].set_ylabel("pull force (uN)")
    ax[0].legend(fontsize=8)
    ax[0].set_title(f"pull at {u.vpull:g} m/s; Gc A0 = {u.Gl * u.A0 / 1e3:.3g} pJ", fontsize=9)
    ax[1].plot(sep, pl["glued_area_um2"], label="glued area")
    ax[1].plot(sep, pl["contact_area_um2"], label="contact area")
    ax[1].set_xlabel("grip separation (um)")
    ax[1].set_ylabel("area (um^2)")
    a2 = ax[1].twinx()
    a2.plot(sep, pl["P1_kPa"], "C2--", lw=0.8, label="P cell 1")
    a2.plot(sep, pl["P2_kPa"], "C3--", lw=0.8, label="P cell 2")
    a2.set_ylabel("pressure (kPa)")
    h1, l1 = ax[1].get_legend_handles_labels()
    h2, l2 = a2.get_legend_handles_labels()
    ax[1].legend(h1 + h2, l1 + l2, fontsize=8)
    reporting.save_figure(rep.fig("pair-pull.png"), fig, tight=True)


def text_press(rep, S, ps, n, window_us):
    """The section's heading, what ran, and the press table."""
    fmt, pct = T.fmt, T.pct
    sigl, Gl = ps["sigl"], ps["Gl"]
    inflate = rep.settings("inflate-pair", "in.tissue-inflate")
    rep.w(TITLE, "",
          "`cellgen.py tissue --lattice sc --n 1 1 2` (two cells stacked along z, glued across one face) and "
          f"`--n 1 1 1` (one cell of the same equivalent radius, {params.CELL['R']:g} um), each inflated with "
          f"`in.tissue-inflate` (Pi {ps['Pi']:g} kPa, Lp {inflate['Lp']:g}, the steps of run-info.txt), then "
          "`in.tissue-pair`: the plates press at "
          f"{ps['vplate']:g} m/s to {ps['press']:.0%} "
          "strain (strain = plate travel from first contact / initial height; the pair is twice as high, so at one "
          f"strain it is pressed twice as far); the pair is then gripped (wall nodes within {ps['grip']:g} um of a "
          f"plate) and the top grip pulled up at {ps['vpull']:g} m/s. Walls do not rupture (lamf {ps['lamf']:g}); lamella: "
          f"strength sigl {sigl:g} kPa, fracture energy Gc {Gl:g} pg/us^2 = {Gl / 1000:g} J/m^2 "
          "(tissue-model.lmp defaults). Force curves are smoothed by a centred moving average over "
          f"{window_us:g} us ({n} samples) of plate time; the raw force rings at the walls' frequencies.", "",
          f"![press]({rep.link('pair-press.png')})", "",
          "| quantity | definition | value |", "|---|---|---|",
          f"| force at 5% strain, pair | smoothed top-plate force | {fmt(S['force_at_5pct_pair_nN'] / 1e3)} uN |",
          f"| force at 5% strain, single cell | same | {fmt(S['force_at_5pct_single_nN'] / 1e3)} uN |",
          f"| force at the end of the press, pair | smoothed, at strain {pct(S['press_end_strain_pair'])} | "
          f"{fmt(S['press_end_force_pair_nN'] / 1e3)} uN |",
          f"| force at the end of the press, single | smoothed, at strain {pct(S['press_end_strain_single'])} | "
          f"{fmt(S['press_end_force_single_nN'] / 1e3)} uN |",
          f"| glued area, start / end of press | intact lamella bonds' area (cell/contacts col. 4) | "
          f"{fmt(S['glued_area_start_um2'])} / {fmt(S['glued_area_end_press_um2'])} um^2 |",
          f"| contact area, start / end of press | wall area touching the other cell (col. 10) | "
          f"{fmt(S['contact_area_start_um2'])} / {fmt(S['contact_area_end_press_um2'])} um^2 |",
          f"| pressures before the press | cells 1, 2 of the pair; single | {fmt(S['P_start_kPa'][0])}, "
          f"{fmt(S['P_start_kPa'][1])}; {fmt(S['P_single_start_kPa'])} kPa |",
          f"| pressures at the end of the press | mean of the last window | {fmt(S['P_end_press_kPa'][0])}, "
          f"{fmt(S['P_end_press_kPa'][1])}; {fmt(S['P_single_end_press_kPa'])} kPa |", "")
    text_compare(rep, S, ps)


def text_compare(rep, S, ps):
    """The pair against the single cell by plate travel and by strain, and the press's check."""
    fmt, pct = T.fmt, T.pct
    q = S["quasistatic"]
    study = os.path.relpath(os.path.join(params.ROOT, "docs", "studies", "tissue-pair-stiffness.md"), rep.report)
    rep.w(f"**The pair against one cell: by plate travel, not by strain** ([the pair's stiffness study]({study})). "
          "Two cells glued across a flat face are not two springs in series: the glued face is pressed equally "
          "from both sides and takes almost none of the travel, which goes into the two caps that touch the "
          "plates, as for the single cell. At one strain the pair, twice as tall, is pressed twice as far, so "
          "by strain it looks stiffer; by plate travel it carries about the single cell's force at first. The "
          "smoothed top-plate force:", "",
          "| plate travel (um) | pair (uN) | single (uN) | pair / single |", "|---|---|---|---|",
          *[f"| {r['travel_um']:g} | {fmt(r['pair_nN'] / 1e3)} | {fmt(r['single_nN'] / 1e3)} | "
            f"{fmt(ratio(r['pair_nN'], r['single_nN']))} |" for r in S["by_travel"]], "",
          "| strain | pair (uN) | single (uN) | pair / single |", "|---|---|---|---|",
          *[f"| {pct(r['strain'])} | {fmt(r['pair_nN'] / 1e3)} | {fmt(r['single_nN'] / 1e3)} | "
            f"{fmt(ratio(r['pair_nN'], r['single_nN']))} |" for r in S["by_strain"]], "")
    words = {k: ("dynamic" if c["dynamic"] else "balanced") + f" (worst {pct(c['balance_worst'])}, "
             f"{C.strain_pct(c['range'][0])}-{pct(c['range'][1])} strain; the bottom plate first loaded at "
             f"{pct(c['bottom_first_load_strain'])} strain)" for k, c in q.items()}
    dyn = [k for k, c in q.items() if c["dynamic"]]
    rep.w(f"Quasi-static check of the presses (cellmech.quasistatic, the plates' balance over "
          f"{C.strain_pct(C.KINDS['compress'].width)} windows, tolerance {Q.TOL_BALANCE:.0%}; their records have no kinetic "
          f"energy or plate work): pair {words['pair']}, single cell {words['single']}. "
          + (f"At {ps['vplate']:g} m/s with the top plate alone these presses are dynamic: the force rings with the "
             "driven cells (the tables above sample that ringing), so neither comparison is a stiffness here; both "
             "are a rate study. At converged speeds (0.25 and 0.125 m/s, both plates, at rest first) the study "
             "finds the pair about as stiff as one cell by plate travel and 2.3-3x stiffer by strain from 1 to 3%, "
             "up to about 3 um of travel, where the stacked pair starts to tip between the frictionless plates "
             "(an unstable two-cell column, not a tissue property)." if dyn else
             "Both presses balance: the comparison above holds at this speed."), "")


def verdict(S):
    """What W / (Gl A0) says about the pull's energy balance."""
    r = S["W_over_GcA"]
    if r is None:
        return ""
    if abs(r - 1) <= 0.15:
        return (f"Here W / (Gc A0) = {r:.2f}: within 15% of 1, the cohesive law's energy balance holds "
                "at this pull speed, but it is a balance of the terms above, not a direct measure of "
                "Gc (the signed work, which lets the negative half-cycles of the ringing cancel, is "
                f"{S['work_signed_raw_nNum'] / 1e3:.3g} pJ).")
    if r > 1:
        return (f"Here W / (Gc A0) = {r:.2f} > 1: the grip does more work than the glue absorbs; the "
                "rest goes into viscous and contact damping and into the cells' elastic energy that "
                "is still stored when the last bond lets go (then released as oscillation).")
    return (f"Here W / (Gc A0) = {r:.2f} < 1: the stored elastic energy of the cells (and of the "
            "compressed interface after the press) drives part of the debonding, so the grip "
            "does less than Gc A0 of work.")


def text_pull(rep, S, u):
    """The pull's figure, table and why W need not equal Gl A0."""
    fmt = T.fmt
    rep.w(f"![pull]({rep.link('pair-pull.png')})", "",
          "| quantity | definition | value |", "|---|---|---|",
          f"| pull-off force | largest smoothed force on the top grip (tension > 0; centred moving average over "
          f"{u.npl * u.dsep:.3g} um of separation = {u.npl * u.dsep / u.vpull:.3g} us, one period of the ringing) | "
          f"{fmt(S['pull_force_max_nN'] / 1e3)} uN at {fmt(S['pull_force_max_sep_um'])} um (raw largest: "
          f"{fmt(S['pull_force_max_raw_nN'] / 1e3)} uN) |",
          f"| largest adhesion across the interface | -(lamella + contact force), cell/contacts col. 7 + 8 | "
          f"{fmt(S['interface_adhesion_max_nN'] / 1e3)} uN |",
          f"| glued area at the start of the pull, A0 | intact lamella area | {fmt(u.A0)} um^2 |",
          f"| strength x area | sigl A0 (the force the whole interface could carry at once) | "
          f"{fmt(S['sigmaA_nN'] / 1e3)} uN |",
          f"| work of separation W | integral of F_pull d(sep) where F_pull > 0, up to the last debond "
          f"(at {fmt(S['pull_last_debond_sep_um'])} um), of the smoothed force | {fmt(u.W / 1e3)} pJ |",
          f"| signed work to the last debond | integral of the raw F_pull d(sep), negative parts included | "
          f"{fmt(S['work_signed_raw_nNum'] / 1e3)} pJ |",
          f"| Gc A0 | fracture energy x glued area | {fmt(S['GcA_nNum'] / 1e3)} pJ |",
          f"| W / (Gc A0) | | **{fmt(S['W_over_GcA'])}** |",
          f"| separated at the end? | glued area 0 | {'yes' if u.separated else 'no'} "
          f"({fmt(S['pull_glued_area_end_um2'])} um^2 left, {S['pull_debonded_bonds_end']} bonds debonded, "
          f"{S['pull_lamella_bonds_end']} intact) |",
          f"| work of the press | integral of F_top d(approach) | {fmt(S['press_work_pair_nNum'] / 1e3)} pJ |", "")
    rep.w("Why W need not equal Gc A0: the grips pull on the walls, not on the interface. (i) The grip force "
          "works on the cells' walls and fluid too: elastic energy stored in the stretched cells is released "
          "when the last bonds go (and can drive debonding the grip does not pay for); (ii) the fluid viscosity "
          f"and the contact damping dissipate work at {u.vpull:g} m/s; the pair rings at its shape mode (period "
          f"{fmt(S.get('pull_ringing_period_um'))} um of separation here), and clipping F > 0 on that signal "
          "counts half-cycles that give energy back, so the force is smoothed over one period first; "
          "(iii) the interface peels from its rim: only part of the bonds carries load at a time, so the "
          "pull-off force stays below sigl A0 and the bonds opened last may let go elastically; (iv) the press "
          "before the pull leaves the interface in compression, and the pull first unloads it (F_pull <= 0, "
          "not counted). " + verdict(S), "")


def section(rep, window_us):
    """Section 1 into rep (its markdown lines, rep.S["pair"]) and the figures and CSVs."""
    loaded = load(rep)
    if loaded is None:
        rep.w(TITLE, "", "Not run or failed (see times.txt).", "")
        rep.S["pair"] = None
        return
    pr, sg, pl, ps = loaded
    S, n = measure_press(pr, sg, window_us)
    figure_press(rep, pr, sg, n, window_us, pl is not None)
    u = None
    if pl is not None:
        u = measure_pull(pl, ps, window_us)
        S.update(u.S)
        write_pull_csv(rep, pl, u)
        figure_pull(rep, pl, u)
    rep.S["pair"] = S
    text_press(rep, S, ps, n, window_us)
    if u is not None:
        text_pull(rep, S, u)
    rep.w("CSV of the raw curves: "
          f"[pair-press.csv]({rep.link('pair-press.csv')}), [single-press.csv]({rep.link('single-press.csv')})"
          + (f", [pair-pull.csv]({rep.link('pair-pull.csv')})" if pl is not None else "") + ".", "")
