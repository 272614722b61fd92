# SPDX-License-Identifier: GPL-2.0-or-later
"""The tissue modulus and failure at two wall resolutions (docs/studies/tissue-resolution.md): the
coarse 2x2x2 lattice block made at level 3 (642 wall nodes a cell) and at the paper's level 4 (2562), each
inflated at Pi -364 kPa with the strong lamella and compressed between plates at v and 2v by
tools/tissue-converged.sh, one run folder a level:
  for L in 3 4; do LEVEL=$L OUT=RUNS/L$L BLOCK="2 2 2" STRAIN=0.12 SPEEDS="0.25 0.125" PIS=-364 \\
    ONLY="gen inflate-364-strong compress-364-strong-0.25 compress-364-strong-0.125" \\
    bash tools/tissue-converged.sh; done
  python3 docs/studies/tissue-resolution.py RUNS [PNG]
Each level is measured and judged by cellmech.tissue.converged (the modulus over its window, the
plates' balance and the curve against twice the speed, the first rupture and the failure stress);
this prints the tables of the study and draws both levels' curves."""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools"))
from cellmech.tissue import converged as C  # noqa: E402
from cellmech.tissue import tissuedata as T  # noqa: E402

KIND = C.KINDS["compress"]
CONDITION = (-364, "strong")


def level_row(folder):
    """One level's numbers: its generator's statistics, the inflated state and the compression's."""
    gen = T.gen_stats(f"{folder}/gen/block.json")
    infl = T.load(f"{folder}/inflate{CONDITION[0]}-{CONDITION[1]}/tissue-inflate.dat", T.INFLATE)
    data, rows = C.conditions(KIND, folder)
    v, slow, fast, _ = data[CONDITION]
    m = rows[CONDITION]
    return dict(level=gen["level"], nodes=gen["wall_nodes_per_cell"], fluid=gen["fluid_spacing"],
                P=float(infl["P_mean_kPa"][-1]), lam=float(infl["stretch_mean"][-1]),
                water=float(infl["fluid_mass_pg"][-1]), v=v, m=m, slow=slow, fast=fast)


def table(rows):
    lines = ["| level | wall nodes a cell | fluid spacing at generation (um) | inflated: P (kPa) | "
             "wall stretch | water (pg) | v (m/s) | modulus 4-6% at v (kPa) | at 2v (kPa) | plates (worst) | "
             "vs 2v (worst) | converged |", "|" + "---|" * 12]
    for r in rows:
        m = r["m"]
        lines.append(f"| {r['level']} | {r['nodes']} | {r['fluid']:.3g} | {r['P']:.1f} | {r['lam']:.5f} | "
                     f"{r['water']:.4g} | {r['v']:g} | {m['E']:.0f} | {C.modulus(r['fast'], *KIND.window):.0f} | "
                     f"{C.pct(m['balance'])} | {C.pct(m['rate'])} | {'yes' if m['converged'] else 'no'} |")
    return "\n".join(lines)


def failure_table(rows):
    """Each level's failure as the reports judge it (cellmech.tissue.converged): the first wall
    rupture at v and 2v, the failure stress and its strain, and the cells that ruptured by layer."""
    lines = ["| level | first rupture (v; 2v) | first debond (v; 2v) | failure stress (kPa) | strain at peak | "
             "failure mode | ruptured cells at v (bottom / top layer) | end of the record |", "|" + "---|" * 8]
    for r in rows:
        m = r["m"]
        f, ff = m["fail"], m["fail_fast"]
        peak, at = C.failure_cells(m)
        by = ((m.get("where") or {}).get("kinds") or {}).get("wall rupture", {})
        lines.append(f"| {r['level']} | {C.pct(f['first'].get('wall rupture'))}; "
                     f"{C.pct(ff['first'].get('wall rupture'))} | {C.pct(f['first'].get('lamella debonding'))}; "
                     f"{C.pct(ff['first'].get('lamella debonding'))} | {peak} | {at} | {f['mode']} | "
                     f"{by.get('bottom', 0)} / {by.get('top', 0)} | {C.pct(float(r['slow']['strain'].max()))} |")
    return "\n".join(lines)


def figure(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    for n, r in enumerate(rows):
        ax.plot(r["slow"]["strain"], r["slow"]["stress_kPa"], color=f"C{n}", lw=1.2,
                label=f"level {r['level']}, {r['v']:g} m/s")
        ax.plot(r["fast"]["strain"], r["fast"]["stress_kPa"], color=f"C{n}", lw=0.8, ls="--",
                label=f"level {r['level']}, {2 * r['v']:g} m/s")
    ax.set_xlabel("strain (plate travel / initial height)")
    ax.set_ylabel("stress (top plate force / initial cross-section, kPa)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main(argv):
    runs = argv[1]
    rows = [level_row(f"{runs}/L{lv}") for lv in (3, 4) if os.path.isdir(f"{runs}/L{lv}")]
    print(table(rows))
    print()
    print(failure_table(rows))
    if len(rows) == 2:
        e3, e4 = rows[0]["m"]["E"], rows[1]["m"]["E"]
        print(f"\nlevel 4 against level 3: modulus {e4 / e3 - 1:+.1%}, wall stretch at turgor "
              f"{(rows[1]['lam'] - 1) / (rows[0]['lam'] - 1) - 1:+.1%} (of the strain)")
    if len(argv) > 2:
        figure(rows, argv[2])


if __name__ == "__main__":
    main(sys.argv)
