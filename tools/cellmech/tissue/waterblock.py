# SPDX-License-Identifier: GPL-2.0-or-later
"""The "Water" section's held blocks beyond the 2x2x2 (tools/tissue.sh stages water-dry-hold-27
and water-back-hold): the 27-cell block dried to 20% of its water beside the 8-cell one, and the
dried 8-cell block returned to pure water (rehydration), with CSV files, plots and pictures."""
import os

import numpy as np

from .. import params
from . import tissuedata as T
from . import water as Wt

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FS = (0.9, 0.8, 0.7, 0.6, 0.4, 0.2)
CLASS = {0: "centre", 1: "face", 2: "edge", 3: "corner"}    # by free faces


def shrink_rows(d, fs=FS):
    """{fraction: volume, area, size (each / its first record), turgor, sphericity} of a drying."""
    x = d["water_fraction"]
    L = Wt.mean_edge(d)
    o = np.argsort(x)
    return {str(f): dict(volume=Wt.at(d, f, "volume_um3") / d["volume_um3"][0],
                         area=Wt.at(d, f, "wall_area_um2") / d["wall_area_um2"][0],
                         size=float(np.interp(f, x[o], (L / L[0])[o])), turgor=Wt.at(d, f, "turgor_mean_kPa"),
                         sphericity=Wt.at(d, f, "sphericity"))
            for f in fs if f >= x.min() - 1e-3}


def water_by_class(path):
    """Each cell's water at the end of a drying over its water at the start (compute cell/props
    column MASS), averaged over the cells with 0, 1, 2, 3 free faces (centre, face, edge, corner
    of a cubic block, from the cells' centroids at the start)."""
    rows = T.load_table(path)
    first, last = rows[0][1], rows[-1][1]
    c = first[:, 9:12]                                   # XC, YC, ZC
    lo, hi = c.min(0), c.max(0)
    tol = 0.25 * (hi - lo)
    free = ((np.abs(c - lo) < tol) | (np.abs(c - hi) < tol)).sum(1)
    w = last[:, 3] / first[:, 3]
    return {int(k): float(w[free == k].mean()) for k in np.unique(free)}


def dry_hold_27(rep, S):
    """Experiment 5: the 27-cell block dried as section 4's (stage water-dry-hold-27), beside the
    8-cell block's record at equal water."""
    name = "water-dry-hold-27"
    rep.w("### 5. The 27-cell block dried to 20% of its water", "")
    if not os.path.exists(rep.p(f"{name}/tissue-dry.csv")):
        rep.w("Not run or failed.", "")
        return
    e = params.run_settings(rep.p(name), "in.tissue-dry")
    d = Wt.dry_run(rep, name)
    T.write_csv(rep.fig(f"{name}.csv"), d, list(d),
                f"in.tissue-dry: 3x3x3 coarse block, membrane wall, wrinkle yes, residual {e.get('residual', 0)}, "
                f"Fa {e['Fa']}, sphcoh {e.get('sphcoh', 0)}, share {e.get('share', 'particle')}, Lp {e['Lp']}")
    Wt.dry_figure(rep, d, None, png=f"{name}.png")
    pic = Wt.render(rep, d, {}, name=name, what="the 3x3x3 block")
    q = Wt.dry_measure(d, None)
    q["stop"] = Wt.stop_reason(rep.p(f"{name}/log.lammps"))
    q["bvh_gap"] = Wt.bvh_gap(d)
    q["rows"] = shrink_rows(d)
    sec = Wt.section_rows(rep, name, d)
    q["sections"] = {f"{w:.4f}": v for w, v in sec.items()}
    if os.path.exists(rep.p("water-dry-hold/tissue-dry.csv")):
        eight = Wt.dry_run(rep, "water-dry-hold")
        q["eight"] = {k: v for k, v in shrink_rows(eight).items() if k in q["rows"]}
        q["eight_gap"] = Wt.bvh_gap(eight)
    q["water_by_class"] = water_by_class(rep.p(f"{name}/tissue-dry-cells.dat"))
    S["dry_hold_27"] = q
    rows = []
    for f, r in q["rows"].items():
        o = q.get("eight", {}).get(f)
        rows.append(f"| {float(f):.0%} | {r['volume']:.4f} | {q['bvh_gap'][f]:+.1%} | "
                    + (f"{q['eight_gap'][f]:+.1%} | " if o else "- | ")
                    + f"{r['area']:.4f} | {r['size']:.4f} | " + (f"{o['size']:.4f} | " if o else "- | ")
                    + f"{r['turgor']:.4g} | {r['sphericity']:.4f} |")
    stop = f" The run stopped there: `{q['stop']}`" if q["stop"] else ""
    rep.w(f"Section 4's drying on the 3x3x3 block: its centre cell has no free face and dries only through its "
          f"neighbours (Eq. W4, exposed outside), the same settings (Lp {e['Lp']}, share {e.get('share', 'particle')}, "
          f"the level-3 adhesion, artificial stress, cohesion and residual stiffness). Water {q['water0_pg']:.4g} pg down "
          f"to {q['end_fraction']:.1%} in {q['time_us']:.3g} us.{stop}", "",
          "| water | enclosed volume | vs Boyle-van 't Hoff | 2x2x2: vs Boyle-van 't Hoff | wall area | block size | "
          "2x2x2: block size | mean turgor (kPa) | sphericity |", "|---|---|---|---|---|---|---|---|---|", *rows, "",
          "(volume, area and size / their values at full turgor; the 2x2x2 columns: section 4's block at the same "
          "water)", "", f"![drying, 27 cells]({rep.link(name + '.png')})", "",
          *([f"![walls, 27 cells]({rep.link(pic)})", ""] if pic else []),
          *Wt.section_text(sec),
          "*What the model gives.* The 27 cells shrink with their water as the 8 do: the enclosed volume stays "
          + Wt.bvh_words(q["bvh_gap"]) + f"; the block's size at {q['end_fraction']:.0%} water is "
          f"{list(q['rows'].values())[-1]['size']:.3f} of its turgid size. The block dries from outside in: at the end "
          + ", ".join(f"the {CLASS[k]} cells hold {v:.0%} of their water" for k, v in q["water_by_class"].items())
          + " (water crosses to the outside only through the exposed walls, Eq. W4, and between cells through their "
          "glued walls, Eqs. W2-W3), and the drier outer cells, pressed on the wetter inner ones, flatten (elongation "
          "in the sections). Coarse cells (level 3), one drying rate "
          "(section 4's rate check holds for the 8-cell block).", "",
          f"Data: [{name}.csv]({rep.link(name + '.csv')}).", "")


def back_figure(rep, dry, back, png):
    """PNG: enclosed volume and turgor against the water content, drying and rehydration."""
    fig, ax = plt.subplots(1, 3, figsize=(13, 4))
    V0, A0 = dry["volume_um3"][0], dry["wall_area_um2"][0]
    for d, lab in ((dry, "drying"), (back, "rehydration")):
        x = d["water_fraction"]
        ax[0].plot(x, d["volume_um3"] / V0, label=lab)
        ax[1].plot(x, d["turgor_mean_kPa"], label=lab)
        ax[2].plot(x, d["wall_area_um2"] / A0, label=lab)
    ax[0].set_ylabel("enclosed volume / turgid")
    ax[1].set_ylabel("mean turgor (kPa)")
    ax[2].set_ylabel("wall area / turgid")
    for a in ax:
        a.set_xlabel("water content (fraction of the turgid block's)")
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(rep.fig(png), dpi=90)
    plt.close(fig)


BACK = (("water-back-hold", "water-dry-hold-fast", "2x2x2"), ("water-back-hold-27", "water-dry-hold-27", "3x3x3"))


def back_measure(rep, name, src):
    """The rehydration (stage NAME) of the block dried by stage SRC: its record, SRC's, the end
    state against the turgid one, and the two paths at equal water."""
    dry, back = Wt.read_csv(rep.p(f"{src}/tissue-dry.csv")), Wt.read_csv(rep.p(f"{name}/tissue-dry.csv"))
    V0, A0 = dry["volume_um3"][0], dry["wall_area_um2"][0]
    xb = back["water_fraction"]
    paths = {str(f): dict(volume_back=Wt.at(back, f, "volume_um3") / V0, volume_dry=Wt.at(dry, f, "volume_um3") / V0,
                          turgor_back=Wt.at(back, f, "turgor_mean_kPa"), turgor_dry=Wt.at(dry, f, "turgor_mean_kPa"),
                          area_back=Wt.at(back, f, "wall_area_um2") / A0, area_dry=Wt.at(dry, f, "wall_area_um2") / A0)
             for f in (0.3, 0.5, 0.7, 0.9) if xb.min() <= f <= xb.max()}
    Pi0 = params.run_settings(rep.p(name), "in.tissue-dry")["Pi"]
    q = dict(start_fraction=float(xb[0]), end_fraction=float(xb[-1]), time_us=float(back["time_us"][-1]),
             # the cells' water potential at the end, P + Pi0 W0 / W (Eq. W1): 0 once back in equilibrium
             psi_end_kPa=float(back["turgor_mean_kPa"][-1] + Pi0 / xb[-1]), Pi0_kPa=Pi0,
             # the water at the rest density (rho0 = 1) over the enclosed volume, turgid and at the end
             fill0=float(dry["water_pg"][0] / dry["volume_um3"][0]),
             fill_end=float(back["water_pg"][-1] / back["volume_um3"][-1]),
             volume=float(back["volume_um3"][-1] / V0), area=float(back["wall_area_um2"][-1] / A0),
             turgor_kPa=float(back["turgor_mean_kPa"][-1]), turgor0_kPa=float(dry["turgor_mean_kPa"][0]),
             size=float(Wt.mean_edge(back)[-1] / Wt.mean_edge(dry)[0]), broken=int(back["broken"][-1]),
             debonded=int(back["debonded"][-1]), debonded_dry=int(dry["debonded"][-1]), paths=paths,
             stop=Wt.stop_reason(rep.p(f"{name}/log.lammps")))
    return dry, back, q


def rehydrate(rep, S):
    """Experiment 6: the dried blocks (the 8-cell block of stage water-dry-hold-fast, the 27-cell
    block of water-dry-hold-27) back in pure water: what comes back, against the drying at equal
    water."""
    rep.w("### 6. Rehydration: the dried blocks back in pure water", "")
    done = [b for b in BACK if os.path.exists(rep.p(f"{b[0]}/tissue-dry.csv"))
            and os.path.exists(rep.p(f"{b[1]}/tissue-dry.csv"))]
    if not done:
        rep.w("Not run or failed.", "")
        return
    e = params.run_settings(rep.p(done[0][0]), "in.tissue-dry")
    rep.w("Each dried block continued by `in.tissue-dry -var back 1 -var psi "
          f"{e['psi']:g}` (pure water outside the exposed walls, Lp {e['Lp']}, everything else as it dried) until it "
          "holds 98% of its turgid water or the run's steps end.", "")
    S["rehydrate"] = {}
    for name, src, what in done:
        dry, back, q = back_measure(rep, name, src)
        S["rehydrate"][what] = q
        T.write_csv(rep.fig(f"{name}.csv"), back, list(back),
                    f"in.tissue-dry -var back 1: the dried {what} block in pure water, water as a fraction of the "
                    "turgid block's")
        back_figure(rep, dry, back, f"{name}.png")
        stop = f" The run stopped on an error: `{q['stop']}`." if q["stop"] else ""
        status = rep.times.get(name, (None, "ok"))[1]
        if status != "ok" and not q["stop"]:
            stop += f" The run was stopped before its steps ended (tools/tissue.sh: {status})."
        rep.w(f"*The {what} block* (dried by stage {src} to {q['start_fraction']:.0%} of its water): "
              f"{q['end_fraction']:.1%} of its water after {q['time_us']:.3g} us.{stop}", "",
              "| water | enclosed volume, back | enclosed volume, dried | turgor back (kPa) | turgor dried (kPa) | "
              "wall area, back | wall area, dried |", "|---|---|---|---|---|---|---|",
              *[f"| {float(f):.0%} | {r['volume_back']:.4f} | {r['volume_dry']:.4f} | {r['turgor_back']:.4g} | "
                f"{r['turgor_dry']:.4g} | {r['area_back']:.4f} | {r['area_dry']:.4f} |" for f, r in q["paths"].items()],
              "", "(volume and area / their values at full turgor before the drying)", "",
              f"![rehydration, {what}]({rep.link(name + '.png')})", "",
              f"What comes back: water to {q['end_fraction']:.1%} of the turgid block's, turgor {q['turgor_kPa']:.4g} kPa "
              f"(turgid: {q['turgor0_kPa']:.4g} kPa), enclosed volume {q['volume']:.4f}, wall area {q['area']:.4f} and "
              f"block size {q['size']:.4f} of their turgid values; the cells' water potential P + Pi is "
              f"{q['psi_end_kPa']:.3g} kPa at the end"
              + (" (still drawing water: the run ended before the block was back in equilibrium)"
                 if q["psi_end_kPa"] < -0.05 * abs(q["Pi0_kPa"]) else " (back in equilibrium with pure water, within 5% of Pi0)")
              + f", and its water at the rest density would fill {q['fill_end']:.3f} of the enclosed volume "
              f"({q['fill0']:.3f} turgid)"
              + f". What does not: broken walls {q['broken']}, lamella bonds debonded {q['debonded']} (by the end of "
              f"the drying: {q['debonded_dry']}).", "",
              f"Data: [{name}.csv]({rep.link(name + '.csv')}).", "")
