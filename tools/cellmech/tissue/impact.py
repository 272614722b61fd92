# SPDX-License-Identifier: GPL-2.0-or-later
"""Section 4 of the tissue report (cellmech.tissue.report): the turgid block hit by the top plate
at each speed (in.tissue-impact), its bruise against the impact energy. Load, measure, figures,
text; every number goes into the summary (rep.S["impact"])."""
import os

import numpy as np

from .. import reporting
from . import tissuedata as T
from .tissuedata import fmt, pct

plt = reporting.pyplot()

SPEEDS = (5, 10, 20)    # impact speeds, m/s (folder names impact-V)


def load(rep):
    """[(V, record)] of the impacts that ran."""
    return [(v, T.load(rep.p(f"impact-{v}/tissue-impact.dat"), T.COMPRESS)) for v in SPEEDS
            if os.path.exists(rep.p(f"impact-{v}/tissue-impact.dat"))]


def measure(rep, v, d):
    """One impact's numbers: the plate's work while it drives in (the impact energy), and the
    bruise at the end of the hold (ruptured cells, debonded area, fluid lost)."""
    name = f"impact-{v}"
    ncell = int(rep.block["cells"])
    t, eps = d["time_us"], d["strain"]
    # the plate moves at v until tpress: the strain stops growing there
    kp = int(np.nonzero(eps >= eps.max() - 1e-9)[0][0])
    W = T.integral(d["F_top_nN"][:kp + 1] * v, t[:kp + 1])
    R = {"vplate_m_s": v, "tpress_us": float(t[kp]), "strain_max": float(eps.max()),
         "energy_nNum": W, "energy_pJ": W / 1e3, "t_end_us": float(t[-1])}
    tab = [(s, a) for s, a in T.load_table(rep.p(f"{name}/tissue-impact-cells.dat")) if len(a) == ncell]
    if tab:
        step, a = tab[-1]
        R["table_time_us"] = float(np.interp(step, d["step"], t))
        R["ruptured_cells"] = int(np.sum(a[:, 12] >= 1))
        R["debonded_area_um2"] = float(np.sum(a[:, 16]) / 2)
    else:
        R["ruptured_cells"], R["debonded_area_um2"] = None, float(d["debonded_area_um2"][-1])
    A0 = float(d["glued_area_um2"][0] + d["debonded_area_um2"][0])
    R["debonded_fraction"] = R["debonded_area_um2"] / A0 if A0 > 0 else None
    R["broken_tethers_end"] = int(d["broken_tethers"][-1])
    lk = rep.p(f"{name}/tissue-impact.dat.leaks")
    if os.path.exists(lk):
        R["leaked_particles"] = int(T.load(lk, T.LEAKS)["leaked_particles"][-1])
        R["fluid_lost_pg"] = R["leaked_particles"] * float(rep.block["fluid_mass"])
        R["fluid_lost_fraction"] = R["fluid_lost_pg"] / float(d["fluid_mass_pg"][0])
    R["fluid_mass_change_pg"] = float(d["fluid_mass_pg"][-1] - d["fluid_mass_pg"][0])
    T.write_csv(rep.fig(f"{name}.csv"), d, T.COMPRESS, f"in.tissue-impact at {v} m/s")
    return R, kp


def bruise_axes(ax, rows, ncell):
    """The bruise against the impact energy: ruptured cells, debonded area, fluid lost."""
    E = [r["energy_pJ"] for r in rows]
    ax.plot(E, [r["ruptured_cells"] or 0 for r in rows], "o-", label="ruptured cells")
    ax.set_xlabel("impact energy = plate work (pJ)")
    ax.set_ylabel(f"ruptured cells (of {ncell})")
    a2 = ax.twinx()
    a2.plot(E, [100 * (r["debonded_fraction"] or 0) for r in rows], "s--", color="C1",
            label="debonded area (% of glued)")
    a2.plot(E, [100 * r.get("fluid_lost_fraction", 0) for r in rows], "^:", color="C2",
            label="fluid lost (% of fluid mass)")
    a2.set_ylabel("%")
    for r in rows:
        ax.annotate(f"{r['vplate_m_s']} m/s\n{r['broken_tethers_end']} broken tethers",
                    (r["energy_pJ"], r["ruptured_cells"] or 0), fontsize=7,
                    textcoords="offset points", xytext=(-20, -28))
    ax.set_ylim(-0.5, ncell + 1.5)
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = a2.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, fontsize=8)
    ax.set_title("bruise against impact energy", fontsize=9)


def figure(rep, loaded, rows, stops):
    """impact-bruise.png: the plate force of each impact, and the bruise against the energy."""
    fig, ax = plt.subplots(1, 2, figsize=(13, 4.6))
    for (v, d), kp in zip(loaded, stops):
        t = d["time_us"]
        ax[0].plot(t, d["F_top_nN"] / 1e3, lw=0.7, label=f"{v} m/s")
        ax[0].axvline(t[kp], color=ax[0].lines[-1].get_color(), ls=":", lw=0.7)
    ax[0].set_xlabel("time (us)")
    ax[0].set_ylabel("top plate force (uN)")
    ax[0].legend(fontsize=8)
    ax[0].set_title("impact: plate force (dotted: plate stops)", fontsize=9)
    if rows:
        bruise_axes(ax[1], rows, int(rep.block["cells"]))
    reporting.save_figure(rep.fig("impact-bruise.png"), fig, tight=True)


def text(rep, rows, im):
    """The section: what ran (from the impacts' settings im), the figure and the table."""
    ncell = int(rep.block["cells"])
    rep.w(f"## 4. Impact on the turgid block (Pi {im['Pi']:g} kPa, strong lamella)", "",
          "**Dynamic by design**: an impact measures the bruise that a blow of given energy leaves, inertia "
          "included, not the tissue's quasi-static response (section 2). "
          f"`in.tissue-impact -var vplate V` (lamf {im['lamf']:g}, sigl {im['sigl']:g} kPa, Gl {im['Gl'] / 1000:g} J/m^2): "
          "the top plate hits at V and drives "
          "in at that constant speed to the strain of run-info.txt, then holds (run-info.txt) while the block settles. "
          "**Impact energy** = the plate's work, the integral of F_top x V dt over the pressing time (until the "
          "strain stops growing), from the force time series (every 50 steps, trapezoids; 1 pJ = 1000 nN um). "
          "**Bruise** at the end of the hold: **ruptured cells** (>= 1 broken tether, per-cell table), **debonded "
          "area** (column 17 summed / 2; fraction of the glued area at the impact), **fluid lost** = fluid "
          "particles outside their own wall (in.tissue-compress's .leaks file, last value) x the fluid particle "
          f"mass {fmt(float(rep.block['fluid_mass']))} pg, and as a fraction of the fluid mass. (The cells' fluid mass itself does not "
          "change: escaped particles still belong to their cell; its change, osmosis at Lp 1e-9, is in the "
          "summary.)", "",
          f"![impact]({rep.link('impact-bruise.png')})", "",
          "| V (m/s) | energy (pJ) | plate stops at strain | ruptured cells | broken tethers | debonded area (um^2) | "
          "debonded fraction | fluid lost (particles) | fluid lost (pg) | fluid lost (% of mass) |", "|" + "---|" * 10)
    for r in rows:
        rep.w(f"| {r['vplate_m_s']} | {fmt(r['energy_pJ'])} | {pct(r['strain_max'])} | {fmt(r['ruptured_cells'])} / {ncell} | "
              f"{r['broken_tethers_end']} | {fmt(r['debonded_area_um2'])} | {pct(r['debonded_fraction'])} | "
              f"{r.get('leaked_particles', '-')} | {fmt(r.get('fluid_lost_pg'))} | {pct(r.get('fluid_lost_fraction'))} |")
    rep.w("")


def section(rep):
    """Section 3 into rep (markdown, rep.S["impact"]) and its figure and CSVs."""
    loaded = load(rep)
    measured = [measure(rep, v, d) for v, d in loaded]
    rows = [R for R, _ in measured]
    figure(rep, loaded, rows, [kp for _, kp in measured])
    im = rep.settings(f"impact-{loaded[0][0] if loaded else SPEEDS[0]}", "in.tissue-impact")
    text(rep, rows, im)
    rep.S["impact"] = rows
