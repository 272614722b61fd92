# SPDX-License-Identifier: GPL-2.0-or-later
"""Section 3 of the tissue report (cellmech.tissue.report): the rate study, tools/tissue.sh's block
compressed to failure at its fast plate speed (2 m/s for RES=coarse) at each turgor with each
named lamella (in.tissue-compress). The quasi-static checks (cellmech.quasistatic) call these runs
dynamic, so they feed neither the trends nor the summary's numbers (section 2, convblock.py, has
the converged ones). Load, measure, check, figures, text; every number goes into the summary
(rep.S["block_rate_study"])."""
import os
import re
import sys

import numpy as np

from .. import params, reporting
from .. import quasistatic as Q
from . import converged as C
from . import tissuedata as T
from .tissuedata import fmt, pct

plt = reporting.pyplot()

PIS = (-364, -100)                  # the turgid and the flaccid block, kPa (folder names)
LAMS = tuple(params.lamellae())     # the named lamellae: strong, weak
EPS_FIT = (0.01, 0.03)              # strain range of the apparent modulus
COLOURS = {(-364, "strong"): "C3", (-364, "weak"): "C1", (-100, "strong"): "C0", (-100, "weak"): "C9"}
MODE_RULE = ("rupture if broken tethers / all tethers >= debonded area / glued area, "
             "debonding otherwise, none if both 0")


def settings(rep):
    """{lamella: the settings of its first block compression} (where none ran: the input's
    defaults with the named lamella)."""
    out = {}
    for lam in LAMS:
        names = [f"compress{Pi}-{lam}" for Pi in PIS if os.path.exists(rep.p(f"compress{Pi}-{lam}/tissue-compress.dat"))]
        out[lam] = (rep.settings(names[0], "in.tissue-compress", lam) if names else
                    dict(params.defaults(os.path.join(params.INPUTS, "in.tissue-compress")), **params.lamellae()[lam]))
    return out


def speed(rep, names):
    """The plate speed (m/s) of the runs: from their settings.json; for runs older than it, the
    vcompress= of run-info.txt (tools/tissue.sh passes it as -var vplate); None where neither says."""
    have = [n for n in names if os.path.exists(rep.p(f"{n}/{params.SETTINGS}"))]
    if have:
        return sorted({rep.settings(n, "in.tissue-compress")["vplate"] for n in have})[-1]
    m = re.search(r"vcompress=([0-9.eE+-]+)", rep.info)
    return float(m.group(1)) if m else None


def quasistatic(R, d):
    """The quasi-static checks of one run into R (no run at half the speed: balance and KE/W), from
    the compression's check start (converged.KINDS) to the first rupture."""
    k = C.KINDS["compress"]
    _, _, _, v = Q.check(d, k.start, float(d["strain"].max()), width=k.width)
    R["quasistatic"] = v.quasistatic
    R["qs_balance_worst"], R["qs_ke_over_work_worst"] = v.numbers["balance"], v.numbers["ke_over_work"]
    R["qs_reasons"] = v.reasons
    R["qs_range"] = [k.start, Q.intact_range(d, k.start, float(d["strain"].max()))[1]]


def measure_curve(R, d, sm):
    """The stress curve's numbers into R: modulus, peak, first rupture and debond, start state."""
    eps = d["strain"]
    m = (eps >= EPS_FIT[0]) & (eps <= EPS_FIT[1])
    R["modulus_kPa"] = float(np.polyfit(eps[m], sm[m], 1)[0]) if m.sum() >= 3 else None
    kpk = int(np.argmax(sm))
    R["peak_stress_kPa"], R["strain_at_peak"] = float(sm[kpk]), float(eps[kpk])
    R["peak_is_end"] = bool(eps[kpk] >= eps[-1] - 0.01)
    R["first_rupture_strain"], _ = T.first_rise(eps, d["broken_tethers"])
    R["first_debond_strain"], _ = T.first_rise(eps, d["debonded_bonds"])
    ev = [x for x in (R["first_rupture_strain"], R["first_debond_strain"]) if x is not None]
    R["first_event_strain"] = min(ev) if ev else None
    R["P_start_kPa"] = T.start_pressure(d)
    R["glued_start_um2"] = float(d["glued_area_um2"][0])
    R["debarea_start_um2"] = float(d["debonded_area_um2"][0])
    R["glued_initial_um2"] = R["glued_start_um2"] + R["debarea_start_um2"]


def measure_damage(rep, R, name, d):
    """The damage at the end into R: from the last complete per-cell table (ruptured cells,
    debonded area), the record's end, and the failure mode by the share of each material failed."""
    ncell = int(rep.block["cells"])
    tab = [(s, a) for s, a in T.load_table(rep.p(f"{name}/tissue-compress-cells.dat")) if len(a) == ncell]
    if tab:
        step, a = tab[-1]
        R["table_step"] = step
        R["table_strain"] = float(np.interp(step, d["step"], d["strain"]))
        R["ruptured_cells"] = int(np.sum(a[:, 12] >= 1))
        R["broken_tethers_table"] = int(np.sum(a[:, 12]))
        R["debonded_area_um2"] = float(np.sum(a[:, 16]) / 2)
    else:
        R["table_step"], R["table_strain"], R["ruptured_cells"] = None, None, None
        R["debonded_area_um2"] = float(d["debonded_area_um2"][-1])
    R["debonded_area_dat_end_um2"] = float(d["debonded_area_um2"][-1])
    R["broken_tethers_end"] = int(d["broken_tethers"][-1])
    R["debonded_bonds_end"] = int(d["debonded_bonds"][-1])
    A0 = R["glued_initial_um2"]
    R["debonded_fraction"] = R["debonded_area_um2"] / A0 if A0 > 0 else None
    # like with like: the share of each failing material that has failed (a cell with one broken
    # tether of 1920 is not a burst cell)
    fr = R.get("broken_tethers_table", R["broken_tethers_end"]) / rep.tethers_total()
    fd = R["debonded_fraction"] or 0.0
    R["ruptured_fraction"] = fr
    R["mode"] = "none" if fr == 0 and fd == 0 else ("rupture" if fr >= fd else "debonding")
    lk = rep.p(f"{name}/tissue-compress.dat.leaks")
    if os.path.exists(lk):
        R["leaked_particles_end"] = int(T.load(lk, T.LEAKS)["leaked_particles"][-1])


def compress_run(rep, name, Pi, lam, window_us):
    """One compression: (its numbers R, its record d, the smoothed stress); its CSV written."""
    d = T.load(rep.p(f"{name}/tissue-compress.dat"), T.COMPRESS)
    cs = rep.settings(name, "in.tissue-compress", lam)
    n = max(1, int(round(window_us / float(np.median(np.diff(d["time_us"]))))))
    sm = T.smooth(d["stress_kPa"], n)
    R = {"name": name, "Pi_kPa": Pi, "lamella": lam, "sigl_kPa": cs["sigl"], "Gl": cs["Gl"],
         "window_samples": n, "strain_end": float(d["strain"][-1])}
    measure_curve(R, d, sm)
    measure_damage(rep, R, name, d)
    quasistatic(R, d)
    T.write_csv(rep.fig(f"{name}.csv"), {**d, "stress_smoothed_kPa": sm},
                ["time_us", "strain", "stress_kPa", "stress_smoothed_kPa"] + T.COMPRESS[3:],
                f"in.tissue-compress Pi {Pi} kPa, lamella {lam} (sigl {cs['sigl']:g} kPa, Gl {cs['Gl']:g}); "
                f"smoothed: centred moving average over {n} samples ({window_us:g} us)")
    return R, d, sm


def load(rep, window_us):
    """{(Pi, lamella): compress_run(...)} of the compressions that finished."""
    runs = {}
    for Pi in PIS:
        for lam in LAMS:
            name = f"compress{Pi}-{lam}"
            if os.path.exists(rep.p(f"{name}/tissue-compress.dat")):
                try:
                    runs[(Pi, lam)] = compress_run(rep, name, Pi, lam, window_us)
                except Exception as e:  # a broken run should not stop the report
                    print(f"report: {name}: {e}", file=sys.stderr)
    return runs


def figure_stress_strain(rep, runs, window_us):
    """block-stress-strain.png: stress against strain with the first events, and the event counts."""
    fig, ax = plt.subplots(1, 2, figsize=(14, 5))
    for key, (R, d, sm) in runs.items():
        c = COLOURS[key]
        lab = f"Pi {key[0]}, {key[1]}"
        ax[0].plot(d["strain"], d["stress_kPa"], color=c, alpha=0.15, lw=0.6)
        ax[0].plot(d["strain"], sm, color=c, label=lab, ls="-" if key[1] == "strong" else "--")
        for x, mk in ((R["first_rupture_strain"], "x"), (R["first_debond_strain"], "o")):
            if x is not None:
                ax[0].plot(x, np.interp(x, d["strain"], sm), mk, color=c, ms=9, mfc="none", mew=2)
        ax[1].plot(d["strain"], d["broken_tethers"], color=c, label=f"{lab}: broken tethers")
        ax[1].plot(d["strain"], d["debonded_bonds"], color=c, ls=":", label=f"{lab}: debonded bonds")
    ax[0].plot([], [], "kx", label="first broken tether")
    ax[0].plot([], [], "ko", mfc="none", label="first debond")
    ax[0].set_xlabel("strain")
    ax[0].set_ylabel("stress = F_top / A0 (kPa)")
    ax[0].set_xlim(left=-0.005)
    ax[0].set_ylim(bottom=min(0, min(np.min(r[2]) for r in runs.values())))
    ax[0].legend(fontsize=8, loc="upper right")
    v = speed(rep, [R["name"] for R, _, _ in runs.values()])
    ax[0].set_title(f"rate study (dynamic): block compression at {'the plate speed of run-info.txt' if v is None else f'{v:g} m/s'}; "
                    f"smoothed {window_us:g} us", fontsize=9)
    ax[1].set_xlabel("strain")
    ax[1].set_ylabel("count")
    ax[1].set_yscale("symlog", linthresh=10)
    ax[1].legend(fontsize=7)
    ax[1].set_title("failure events: wall rupture (solid) and debonding (dotted)", fontsize=9)
    reporting.save_figure(rep.fig("block-stress-strain.png"), fig, tight=True)


def figure_mode(rep, runs):
    """block-failure-mode.png: ruptured against debonded fraction, one point per run."""
    fig, ax = plt.subplots(figsize=(6, 4.6))
    for key, (R, d, sm) in runs.items():
        ax.plot(100 * (R["debonded_fraction"] or 0), 100 * R["ruptured_fraction"],
                "o" if key[1] == "strong" else "s", color=COLOURS[key], ms=10,
                label=f"Pi {key[0]}, {key[1]}: {R['mode']}")
    xm = 100 * max([max(R["debonded_fraction"] or 0, R["ruptured_fraction"]) for R, _, _ in runs.values()]
                   + [0.05]) * 1.15
    ax.plot([0, xm], [0, xm], "k:", lw=0.8, label="ruptured fraction = debonded fraction")
    ax.set_xlim(-0.02 * xm, xm)
    ax.set_ylim(-0.02 * xm, xm)
    ax.set_xlabel("debonded fraction of the glued area (%)")
    ax.set_ylabel("ruptured fraction of the wall tethers (%)")
    ax.legend(fontsize=8)
    ax.set_title("failure mode at the end of the compression", fontsize=9)
    reporting.save_figure(rep.fig("block-failure-mode.png"), fig, tight=True)


def text_intro(rep, window_us):
    """The section's heading, what ran and the definitions."""
    ncell = int(rep.block["cells"])
    st, wk = (settings(rep)[lam] for lam in ("strong", "weak"))
    v = speed(rep, [f"compress{Pi}-{lam}" for Pi in PIS for lam in LAMS])
    at = f"at {v:g} m/s" if v is not None else "at the plate speed of run-info.txt"
    rep.w(f"## 3. Rate study: block of {ncell} cells compressed {at} (dynamic)", "",
          f"**A rate study, not the tissue's response.** By the quasi-static checks (cellmech.quasistatic: the "
          f"plates balance within {Q.TOL_BALANCE:.0%} and KE/W stays below {Q.TOL_KE:.0%} in every "
          f"{C.strain_pct(C.KINDS['compress'].width)} window from {C.strain_pct(C.KINDS['compress'].start)} "
          "strain to the first rupture; no run at half the speed) every run below is dynamic (the *quasi-static "
          "check* column): the plate "
          "drives inertia as well as the tissue, and these runs predate the quasi-static protocol (their "
          "inflation left the cells' fluid still moving, and the top plate alone moves). Their numbers feed "
          "neither the trends nor the summary; section 2 has the converged ones. They stay to show what a fast "
          "compression gives, with the pictures and per-cell tables of a run to 30% strain.", "",
          f"`cellgen.py tissue --lattice sc` ({ncell} cells, {rep.block['lamella_bonds']} lamella bonds, glued "
          f"area {sum(p['glued_area'] for p in rep.block['pairs']):.6g} um^2 over {len(rep.block['pairs'])} "
          f"cell pairs), inflated twice with `in.tissue-inflate` (Pi {' and '.join(map(str, PIS))} kPa), each "
          f"compressed with `in.tissue-compress -var lamf {st['lamf']:g}` (tethers break at {st['lamf'] - 1:.0%} "
          f"stretch, the paper's) with a strong (sigl {st['sigl']:g} kPa, Gl {st['Gl']:g} pg/us^2 = "
          f"{st['Gl'] / 1000:g} J/m^2) and a weak lamella ({wk['sigl']:g} kPa, {wk['Gl']:g} pg/us^2), {at}. "
          "Stress = top-plate force / initial cross-section of the block; strain = plate travel from first "
          f"contact / initial height. Stress smoothed by a centred moving average over {window_us:g} us of plate "
          "time (faint: raw); the plate force rings with the walls.", "",
          "Definitions: **apparent modulus** = slope of a straight-line fit of the smoothed stress over strain "
          f"{EPS_FIT[0]:.0%}-{EPS_FIT[1]:.0%}; **strain at peak** = strain of the largest smoothed stress (if that "
          "is at the end of the run, the block has not softened yet: marked 'end'); **first rupture** = strain "
          "of the first record with a broken tether; **first debond** = first record with a debonded lamella "
          "bond (beyond those at the start); **ruptured cells** = cells with >= 1 broken tether (compute "
          "cell/props column 13) in the last per-cell table; **ruptured fraction** = broken tethers in that table "
          "over all the block's tethers (3 n - 6 per closed wall of n nodes); **debonded fraction** = column 17 summed / 2 (each "
          "bond counts in both cells) in that table, over the glued area at the start of the compression plus "
          "any debonded during inflation (= the area glued by the generator); **failure mode**: *rupture* if "
          "the ruptured fraction of the walls >= the debonded fraction of the glued area, *debonding* otherwise, "
          "*none* if both are 0: the share of each failing material that has failed.", "")


def qs_cell(R):
    """The quasi-static check's verdict of a run, with its worst numbers and range."""
    lo, hi = R["qs_range"]
    return (f"{'quasi-static' if R['quasistatic'] else 'dynamic'} ({pct(R['qs_balance_worst'])}; "
            f"{pct(R['qs_ke_over_work_worst'])}; {C.strain_pct(lo)}-{pct(hi)})")


def text_table(rep, runs):
    """The figures and the table of the compressions, with the per-cell table's step."""
    ncell = int(rep.block["cells"])
    rep.w(f"![stress-strain]({rep.link('block-stress-strain.png')})", "",
          f"![failure mode]({rep.link('block-failure-mode.png')})", "",
          "| Pi (kPa) | lamella | P at start (kPa) | modulus (kPa) | peak stress (kPa) | strain at peak | first rupture | "
          "first debond | ruptured cells | broken tethers | ruptured fraction | debonded area (um^2) | debonded "
          "fraction | leaked fluid particles | mode | quasi-static check (worst plates; KE/W) |", "|" + "---|" * 16)
    for key, (R, d, sm) in sorted(runs.items(), key=lambda kv: (kv[0][0], kv[0][1])):
        rep.w(f"| {key[0]} | {key[1]} | {fmt(R['P_start_kPa'])} | {fmt(R['modulus_kPa'])} | {fmt(R['peak_stress_kPa'])} | "
              f"{pct(R['strain_at_peak'])}{' (end)' if R['peak_is_end'] else ''} | {pct(R['first_rupture_strain'])} | "
              f"{pct(R['first_debond_strain'])} | {fmt(R['ruptured_cells'])} / {ncell} | {R['broken_tethers_end']} | "
              f"{pct(R['ruptured_fraction'])} | {fmt(R['debonded_area_um2'])} | {pct(R['debonded_fraction'])} | "
              f"{R.get('leaked_particles_end', '-')} | {R['mode']} | {qs_cell(R)} |")
    some = next(iter(runs.values()))[0]
    rep.w("", f"Per-cell table: the last one written, at strain {pct(some['table_strain'])} (step {some['table_step']}; "
          "tables every `tabevery` steps, see run-info.txt). Glued area at the start of the compression: "
          + ", ".join(f"Pi {k[0]} {k[1]} {fmt(R['glued_start_um2'])} um^2 (debonded in inflation "
                      f"{fmt(R['debarea_start_um2'])})" for k, (R, _, _) in sorted(runs.items())) + ".", "")


def text_pairs(rep):
    """The cell pairs with the most debonded area of the turgid block's compressions."""
    for key in ((PIS[0], "weak"), (PIS[0], "strong")):
        name = f"compress{key[0]}-{key[1]}"
        path = rep.p(f"{name}/tissue-compress-pairs.dat")
        if not os.path.exists(path):
            continue
        tab = T.load_table(path)
        if not tab or not len(tab[-1][1]):
            continue
        step, a = tab[-1]
        k = np.argsort(-a[:, 5], kind="stable")[:8]
        rep.w(f"Per cell pair (`compute cell/contacts`, {name}/tissue-compress-pairs.dat, last table, step {step}): "
              f"the {len(k)} pairs with the most debonded area of {len(a)} rows "
              f"(glued {fmt(np.sum(a[:, 3]))} um^2, debonded {fmt(np.sum(a[:, 5]))} um^2 in all).", "",
              "| cells i, j | lamella bonds | glued area (um^2) | debonded bonds | debonded area (um^2) | "
              "lamella force (nN) | contact force (nN) | contact area (um^2) | distance (um) |", "|" + "---|" * 9)
        for r in a[k]:
            rep.w(f"| {int(r[0])}, {int(r[1])} | {int(r[2])} | {fmt(r[3])} | {int(r[4])} | {fmt(r[5])} | {fmt(r[6])} | "
                  f"{fmt(r[7])} | {fmt(r[9])} | {fmt(r[10])} |")
        rep.w("")


def section(rep, window_us):
    """Section 2 into rep (markdown, rep.S, rep.runs for the pictures) and the figures and CSVs."""
    runs = load(rep, window_us)
    text_intro(rep, window_us)
    if not runs:
        rep.w("No block compression finished.", "")
        rep.S["block_rate_study"] = None
        return
    figure_stress_strain(rep, runs, window_us)
    figure_mode(rep, runs)
    text_table(rep, runs)
    rep.S["block_rate_study"] = {f"{k[0]}_{k[1]}": R for k, (R, _, _) in runs.items()}
    rep.S["block_rate_study_definitions"] = {"window_us": window_us, "modulus_strain_range": list(EPS_FIT),
                                             "mode_rule": MODE_RULE, "vplate_m_s": speed(
                                                 rep, [R["name"] for R, _, _ in runs.values()])}
    rep.runs = runs
    text_pairs(rep)
