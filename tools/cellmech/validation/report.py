# SPDX-License-Identifier: GPL-2.0-or-later
"""Write validation.md and validation-summary.json from the case entries."""
import datetime
import json
import os
import platform

from .. import reporting as rp
from ..params import ROOT, WALLS


def _num(x, unit=""):
    if x is None:
        return "—"
    if unit == "" and abs(x) < 1e-2 and x != 0:
        return f"{x:.3e}"
    return f"{x:.5g}"


def _err(x):
    return "—" if x is None else f"{x:+.2%}"


def _res(r):
    if not r:
        return "—"
    if isinstance(r.get("wall_nodes"), list):
        return "; ".join(f"{w} + {f}" for w, f in zip(r["wall_nodes"], r["fluid_particles"]))
    return f"{r.get('wall_nodes')} wall nodes, {r.get('fluid_particles')} fluid particles"


def other_walls(res, wall):
    """The committed RES=paper reports of the other walls, as (wall, summary, folder relative to
    docs/): the report of one wall sets them beside its own rows. Other RES: none."""
    if res != "paper":
        return []
    docs = os.path.join(ROOT, "docs")
    got = []
    for w in WALLS:
        if w == wall:
            continue
        rel = "." if w == "tether" else f"validation-{w}"
        try:
            s = json.load(open(os.path.join(docs, rel, "validation-summary.json")))
        except (OSError, ValueError):
            continue
        if s.get("res") == res and s.get("wall", "tether") == w:
            got.append((w, s, rel))
    return got


def side_by_side(wall, entries, others):
    """Markdown lines: every row that this wall's report and another wall's report both have (same
    case, same quantity, same reference), measured and error of each wall. Cases that run both walls
    themselves (cases.BOTH_WALLS) are left out."""
    from .cases import BOTH_WALLS
    if not others:
        return []
    walls = [wall] + [w for w, _, _ in others]
    by = {wall: {e["id"].split("-")[0]: e for e in entries}}
    for w, s, _ in others:
        by[w] = {e["id"].split("-")[0]: e for e in s["cases"]}
    L = ["", "## The walls side by side", "",
         "Rows that the reports of " + ", ".join(f"`WALL={w}`" for w in walls) + " both have "
         "(same case, same quantity), each wall's measured value and its error against that "
         "wall's own reference (computed alike; where it takes the run's turgor or radius the two "
         "differ slightly; the column gives this report's). Reports: " + ", ".join(
             f"`docs/{'validation.md' if w == 'tether' else f'validation-{w}/validation.md'}`"
             for w in walls) + ". Cases " + " and ".join(BOTH_WALLS) + " run both walls "
         "themselves (see them above).", "",
         f"| case | quantity | reference ({wall}) | " + " | ".join(f"{w} | error" for w in walls) + " |",
         "|---|---|---|" + "---|---|" * len(walls)]
    n = 0
    for cid, e in sorted(by[wall].items()):
        if cid in BOTH_WALLS or not all(cid in by[w] for w in walls):
            continue
        rows = {w: {r["name"]: r for r in by[w][cid]["rows"]} for w in walls}
        for r in e["rows"]:
            if not all(r["name"] in rows[w] for w in walls) or r["reference"] is None:
                continue
            u = f" {r['unit']}" if r["unit"] else ""
            cells = " | ".join(f"{_num(rows[w][r['name']]['measured'], r['unit'])}{u} | "
                               f"{_err(rows[w][r['name']]['rel_error'])}" for w in walls)
            L.append(f"| {cid} | {r['name']} | {_num(r['reference'], r['unit'])}{u} | {cells} |")
            n += 1
    return L if n else []


def verdict(e):
    """Whether every row of case e that has a tolerance is within it: "pass", "fails N of M rows"
    (a row with a tolerance and no measured error counts as outside), "no tolerance" when no row
    states one (compared, not judged), "not run" (skipped), "error"; a pass of a case whose status
    is not ok says the status."""
    if e["status"] == "skipped":
        return "not run"
    if e["status"] == "error":
        return "error"
    judged = [r for r in e["rows"] if r["tolerance"] is not None]
    if not judged:
        return "no tolerance"
    fails = sum(not (r["rel_error"] is not None and abs(r["rel_error"]) < r["tolerance"]) for r in judged)
    if fails:
        return f"fails {fails} of {len(judged)} rows"
    return "pass" if e["status"] == "ok" else f"pass ({e['status']})"


def summary(meta, entries, how):
    """The report's opening paragraph in plain words: what ran, which cases pass, which fail and
    by how much, which are compared only."""
    v = {e["id"].split("-")[0]: verdict(e) for e in entries}
    ran = [e for e in entries if e["status"] != "skipped"]
    said = [f"`{how} bash tools/validate.sh` checked the `{meta['wall']}` wall in {len(ran)} of "
            f"{len(entries)} cases against references computed from the paper's formulas and the "
            f"model's parameters (the cases' wall times add up to "
            f"{sum(e.get('wall_time_s') or 0 for e in entries):.0f} s)."]
    passed = [k for k, x in v.items() if x.startswith("pass")]
    failed = [(k, x) for k, x in v.items() if x.startswith("fails")]
    said.append(f"{len(passed)} {'case passes' if len(passed) == 1 else 'cases pass'} (every row with a tolerance "
                "within it)" + (": " + ", ".join(passed) if passed else "") + ".")
    for e in entries:
        k = e["id"].split("-")[0]
        if v[k].startswith("fails"):
            worst = max((r for r in e["rows"] if r["tolerance"] is not None and r["rel_error"] is not None),
                        key=lambda r: abs(r["rel_error"]) / r["tolerance"], default=None)
            said.append(f"Case {k}, {e['title']}, {v[k]}" + (
                f"; the farthest, {worst['name'].strip()}, is off by {100 * abs(worst['rel_error']):.3g}% "
                f"against a tolerance of {100 * worst['tolerance']:.3g}%" if worst else "") + ".")
    compared = [k for k, x in v.items() if x == "no tolerance"]
    if compared:
        said.append(f"Compared only (no tolerance stated): {', '.join(compared)}.")
    other = [f"{k} ({x})" for k, x in v.items() if x in ("not run", "error")]
    if other:
        said.append(f"Not judged: {', '.join(other)}.")
    if not failed:
        said.append("No case misses its tolerance.")
    return rp.summary(*said)


def case_table(entries):
    """The overview: one row per case."""
    L = rp.table(["case", "status", "verdict", "resolution", "wall time", "rows within tolerance",
                  "largest abs. error", "paper"])
    for e in entries:
        errs = [abs(r["rel_error"]) for r in e["rows"] if r["rel_error"] is not None]
        tol = [r for r in e["rows"] if r["tolerance"] is not None and r["rel_error"] is not None]
        ok = sum(abs(r["rel_error"]) < r["tolerance"] for r in tol)
        wt = e.get("wall_time_s")
        L.append(f"| {e['title']} | {e['status']} | {verdict(e)} | {_res(e.get('resolution'))} | "
                 f"{'—' if wt is None else f'{wt:.0f} s'} | {f'{ok} of {len(tol)}' if tol else '—'} | "
                 f"{f'{max(errs):.2%}' if errs else '—'} | {e['paper']} |")
    return L


def case_section(e):
    """The section of one case: its rows, notes and plots."""
    L = ["", f"## {e['id'].split('-')[0]}. {e['title']}", "",
         f"*Paper:* {e['paper']}  ", f"*Resolution:* {_res(e.get('resolution'))}  ",
         f"*Wall time:* {e.get('wall_time_s')} s  ", f"*Status:* {e['status']}  ", f"*Verdict:* {verdict(e)}", ""]
    if e["rows"]:
        L += rp.table(["quantity", "measured", "reference", "rel. error", "tolerance"])
        for r in e["rows"]:
            u = f" {r['unit']}" if r["unit"] else ""
            tol = "" if r["tolerance"] is None else f"{r['tolerance']:g}"
            L.append(f"| {r['name']} | {_num(r['measured'], r['unit'])}{u} | "
                     f"{_num(r['reference'], r['unit'])}{u} | {_err(r['rel_error'])} | {tol} |")
        L.append("")
    for n in e["notes"]:
        L += [n, ""]
    for p in e["plots"]:
        L += [f"![{p}](validation/{p})", ""]
    return L


def markdown(meta, entries, others=()):
    """validation.md's lines from the run's metadata (validation-summary.json's) and its entries."""
    res, wall = meta["res"], meta.get("wall", "tether")
    how = f"RES={res}" if wall == "tether" else f"WALL={wall} RES={res}"
    if meta.get("vars"):
        how += f" VARS=\"{meta['vars']}\""
    L = [f"# Validation of the cell model ({how})", "", summary(dict(meta, wall=wall), entries, how), "",
         f"Wall: `{wall}` (lammps-inputs/cell-wall.lmp). "
         + rp.generated_by(f"{how} bash tools/validate.sh", when=meta["generated_utc"],
                           note=f"{meta['cpu_count']} cores; each LAMMPS run on {meta['mpi_ranks']} MPI rank(s), NP")
         + ". Every reference value is computed by `tools/cellmech/validation/references.py` (or "
         "`tools/membrane.py`) from the paper's formulas and the model parameters; the relative "
         "error is measured / reference - 1. The tolerance column holds the paper's criterion "
         "where it states one (the energy bounds are the test suite's). The verdict says whether "
         "every row of the case that has a tolerance is within it. "
         "Machine-readable: `validation-summary.json`.",
         "", "Wall time of a case: the LAMMPS wall time (from the logs) of every run the case "
         "uses, plus its analysis time (membrane solver, spectra). Runs shared between cases "
         "(the same inflation, say) are made once and counted in each case that uses them.", ""]
    L += case_table(entries)
    for e in entries:
        L += case_section(e)
    L += side_by_side(wall, entries, others)
    L += ["", f"Total time of this invocation: {meta['elapsed_s']:.0f} s."]
    return L


def write(out, res, level, entries, elapsed, wall="tether", others=()):
    os.makedirs(out, exist_ok=True)
    meta = dict(res=res, wall=wall, level=level, generated_utc=datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC"),
                host=platform.node(), cpu_count=os.cpu_count(), mpi_ranks=int(os.environ.get("NP", "1")),
                elapsed_s=round(elapsed, 1))
    if os.environ.get("VARS"):
        meta["vars"] = os.environ["VARS"]
    with open(os.path.join(out, "validation-summary.json"), "w") as f:
        json.dump(dict(meta, cases=entries), f, indent=1)
    rp.write_lines(os.path.join(out, "validation.md"), markdown(dict(meta, elapsed_s=elapsed), entries, others))


def main(argv=None):
    """Write validation.md again from a stored validation-summary.json (its own metadata, the other
    walls' committed reports beside it at RES=paper): a report's text changes without its runs."""
    import argparse
    p = argparse.ArgumentParser(description=main.__doc__)
    p.add_argument("summary", help="validation-summary.json")
    p.add_argument("--out", help="folder of the validation.md written (default: the summary's)")
    a = p.parse_args(argv)
    s = rp.read_json(a.summary)
    wall = s.get("wall", "tether")
    out = a.out or os.path.dirname(os.path.abspath(a.summary))
    rp.write_lines(os.path.join(out, "validation.md"),
                   markdown(s, s["cases"], other_walls(s["res"], wall)))
    print(f"report: {os.path.join(out, 'validation.md')}")


if __name__ == "__main__":
    main()
