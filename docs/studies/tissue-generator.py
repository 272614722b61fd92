# SPDX-License-Identifier: GPL-2.0-or-later
"""The 8-cell block's converged numbers before and after the generator's fluid-fill fix
(docs/studies/tissue-generator.md). Before it, cellgen.py's fluid held 47% of a coarse cell's
volume and the inflation made up the rest; now it fills the wall at the fluid's rest density.
The old numbers are those of a tissue summary made from the old campaign (docs/tissue-summary.json
of the commit that had them; its run folders are gone), the new ones are measured here from a run
folder of tools/tissue-converged.sh, by the same code (cellmech.tissue.converged, and
convblock.jsonable for the summary's fields):
  OUT=RUNS SPEEDS="0.125 0.25" bash tools/tissue-converged.sh
  git show REV:docs/tissue-summary.json > old.json
  python3 docs/studies/tissue-generator.py RUNS old.json [compress|tension]"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools"))
from cellmech.tissue import converged as C  # noqa: E402
from cellmech.tissue import convblock as B  # noqa: E402
from cellmech.tissue import tissuedata as T  # noqa: E402


def old_conditions(summary, kind, cells=8):
    """{(pi, lam): the summary's numbers} of the campaign of KIND on CELLS cells, not held whole."""
    for c in json.load(open(summary))["block_converged"]:
        if c["experiment"] == kind.stage and c["cells"] == cells and not c["ends_held_whole"]:
            return {(int(k.split("_")[0]), k.split("_")[1]): v for k, v in c["conditions"].items()}
    raise SystemExit(f"tissue-generator: no {kind.stage} campaign of {cells} cells in {summary}")


def new_conditions(runs, kind):
    """{(pi, lam): the same numbers} of the run folder, measured now."""
    _, rows = C.conditions(kind, runs)
    return {key: B.jsonable(m) for key, m in rows.items()}


def water(runs, pi, lam):
    """The inflated block's water (pg) and mean wall stretch, from its inflation's record."""
    path = f"{runs}/inflate{pi}-{lam}/tissue-inflate.dat"
    if not os.path.exists(path):
        return None, None
    d = T.load(path, T.INFLATE)
    return float(d["fluid_mass_pg"][-1]), float(d["stretch_mean"][-1])


def number(c, key, conv):
    """A value with its verdict: 'X' converged, '(X)' not, '-' none."""
    x = c.get(key)
    if c.get("burst_before_loading"):
        return "burst"
    if x is None:
        return "-"
    return f"{x:.3g}" if c.get(conv) else f"({x:.3g})"


def change(old, new, key):
    a, b = old.get(key), new.get(key)
    if a is None or b is None or old.get("burst_before_loading") or new.get("burst_before_loading"):
        return "-"
    return f"{b / a - 1:+.0%}"


def table(old, new, runs):
    lines = ["| Pi (kPa) | lamella | v old; new (m/s) | P at start old -> new (kPa) | modulus old -> new (kPa) | change | "
             "failure stress old -> new (kPa) | change | first failure at v old -> new | mode old -> new | "
             "water now (pg), wall stretch |", "|" + "---|" * 11]
    for key in sorted(set(old) | set(new), key=lambda k: (-k[0], k[1]), reverse=True):
        o, n = old.get(key, {}), new.get(key, {})
        w, lam = water(runs, *key)
        lines.append(
            f"| {key[0]} | {key[1]} | {o.get('v_m_s', '-')}; {n.get('v_m_s', '-')} | "
            f"{o.get('P_start_kPa', float('nan')):.0f} -> {n.get('P_start_kPa', float('nan')):.0f} | "
            f"{number(o, 'modulus_kPa', 'modulus_converged')} -> {number(n, 'modulus_kPa', 'modulus_converged')} | "
            f"{change(o, n, 'modulus_kPa')} | "
            f"{number(o, 'failure_stress_kPa', 'failure_converged')} -> "
            f"{number(n, 'failure_stress_kPa', 'failure_converged')} | {change(o, n, 'failure_stress_kPa')} | "
            f"{C.pct(o.get('first_event_strain'))} -> {C.pct(n.get('first_event_strain'))} | "
            f"{o.get('mode', '-')} -> {n.get('mode', '-')} | "
            + ("-" if w is None else f"{w:.4g}, {lam:.5f}") + " |")
    return "\n".join(lines)


def main(argv):
    runs, summary = argv[1:3]
    kind = C.KINDS[argv[3] if len(argv) > 3 else "compress"]
    old, new = old_conditions(summary, kind), new_conditions(runs, kind)
    print(f"{kind.title}, 8 cells: old generator (summary {summary}) against the new ({runs}); "
          "a value in brackets has not converged")
    print(table(old, new, runs))
    both = [k for k in old if k in new and old[k]["modulus_converged"] and new[k]["modulus_converged"]]
    for k in both:
        print(f"both converged, Pi {k[0]} {k[1]}: modulus {change(old[k], new[k], 'modulus_kPa')}")


if __name__ == "__main__":
    main(sys.argv)
