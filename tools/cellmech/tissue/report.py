#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Report of the tissue experiments (tools/tissue.sh): a glued pair pressed and pulled apart, blocks
compressed and pulled apart to failure at converged rates (the run folders of
tools/tissue-converged.sh), the fast block compressions of tools/tissue.sh as a rate study,
impacts at three speeds, water.

  report.py --run RUNDIR --res coarse|small --report REPORTDIR [--figs FIGDIR] [--converged DIR ...]

--converged: run folders of tools/tissue-converged.sh (compressions, tensions or both, any block
size); section 2, its trends and the summary's block numbers are theirs, measured by
cellmech.tissue.converged. Without them the report has no block numbers at converged rates.

Writes REPORTDIR/tissue.md, REPORTDIR/tissue-summary.json, and the plots, pictures and CSV files of
the raw curves to FIGDIR (default REPORTDIR). Every number of the report is in the summary.
"""
import argparse
import json
import os

import numpy as np

from .. import params, reporting  # noqa: E402
from . import block as block_section  # noqa: E402
from . import convblock  # noqa: E402
from . import impact as impact_section  # noqa: E402
from . import pair as pair_section  # noqa: E402
from . import tissuedata as T  # noqa: E402
from . import water  # noqa: E402
from . import summary  # noqa: E402
from .tissuedata import fmt, pct  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SPEEDS = impact_section.SPEEDS
WINDOW_US = 1.0        # moving-average window of the plate force, us of plate travel time


class Report:
    def __init__(self, run, res, report, figs, converged=()):
        self.run, self.res, self.report, self.figs = run, res, report, figs
        self.converged_dirs = list(converged)
        os.makedirs(report, exist_ok=True)
        os.makedirs(figs, exist_ok=True)
        self.rel = os.path.relpath(figs, report)
        self.times = T.times(run)
        self.S = {"res": res, "run": os.path.relpath(run, os.getcwd()) if run.startswith(os.getcwd()) else run}
        self.md = []
        self.block = T.gen_stats(os.path.join(run, "gen", "block.json"))
        self.info = open(os.path.join(run, "run-info.txt")).read() if os.path.exists(
            os.path.join(run, "run-info.txt")) else ""

    def p(self, path):
        return os.path.join(self.run, path)

    def fig(self, name):
        return os.path.join(self.figs, name)

    def link(self, name):
        return name if self.rel == "." else f"{self.rel}/{name}"

    def settings(self, name, inp, lamella="strong"):
        """The effective settings of the run in folder name (its settings.json); for a run older
        than settings.json, the input's defaults with the named lamella tools/tissue.sh gave it."""
        return params.run_settings(self.p(name), inp, params.lamellae()[lamella])

    def ok(self, stage):
        return self.times.get(stage, (0, ""))[1] == "ok"

    def tethers_total(self):
        """All wall tethers of the block: 3 n - 6 edges on each closed triangulated wall of n nodes."""
        return self.block["cells"] * (3 * self.block["wall_nodes_per_cell"] - 6)

    def w(self, *lines):
        self.md.extend(lines)

    # ------------------------------------------------------------------ 1. pair
    def pair(self):
        pair_section.section(self, WINDOW_US)

    # ------------------------------------------------------------------ 2. blocks at converged rates
    def converged_blocks(self):
        convblock.section(self, self.converged_dirs)

    # ------------------------------------------------------------------ 3. rate study
    def blocks(self):
        block_section.section(self, WINDOW_US)

    # ------------------------------------------------------------------ pictures
    def montage(self, name, prefix, title, d):
        import glob
        files = sorted(glob.glob(self.p(f"{name}/{prefix}.*.png")), key=lambda f: int(f.split(".")[-2]))
        if not files:
            return None
        files = files[-4:] if len(files) > 4 else files
        fig, ax = plt.subplots(1, len(files), figsize=(4.2 * len(files), 3.6))
        ax = np.atleast_1d(ax)
        for a, f in zip(ax, files):
            step = int(f.split(".")[-2])
            a.imshow(plt.imread(f))
            a.axis("off")
            e = float(np.interp(step, d["step"], d["strain"]))
            t = float(np.interp(step, d["step"], d["time_us"]))
            a.set_title(f"strain {e:.1%}, t = {t:.3g} us", fontsize=9)
        fig.suptitle(title, fontsize=10)
        fig.tight_layout()
        out = f"pictures-{name}.png"
        fig.savefig(self.fig(out), dpi=90)
        plt.close(fig)
        return out

    def pictures(self):
        w = self.w
        pics = []
        for (Pi, lam), (R, d, sm) in sorted(getattr(self, "runs", {}).items()):
            name = f"compress{Pi}-{lam}"
            m = self.montage(name, name, f"{name} (rate study, dynamic): cells coloured by cell; red = ruptured wall, "
                             "green = debonded", d)
            if m:
                pics.append(m)
        for v in SPEEDS:
            name = f"impact-{v}"
            if os.path.exists(self.p(f"{name}/tissue-impact.dat")):
                d = T.load(self.p(f"{name}/tissue-impact.dat"), T.COMPRESS)
                m = self.montage(name, name, f"impact at {v} m/s", d)
                if m:
                    pics.append(m)
        if pics:
            w("## Pictures", "", "`dump image` of the wall nodes (in.tissue-compress `-var img N`), about four frames per "
              "run (the last four written): nodes coloured by cell (blue to yellow), red where the wall has "
              "ruptured (broken tethers), green where the lamella has debonded; the fluid is not drawn. The VTK "
              "surfaces (`walls.STEP.vtk`, fields *broken* and *debonded*) are in each compression's run folder.", "")
            for m in pics:
                w(f"![{m}]({self.link(m)})", "")
        self.S["pictures"] = pics

    # ------------------------------------------------------------------ 4. impact
    def impacts(self):
        impact_section.section(self)

    # ------------------------------------------------------------------ inflations
    def inflations(self):
        rows = []
        for name, what in (("inflate-364", "block, Pi -364"), ("inflate-100", "block, Pi -100"),
                           ("inflate-pair", "pair, Pi -364"), ("inflate-single", "single cell, Pi -364")):
            path = self.p(f"{name}/tissue-inflate.dat")
            if not os.path.exists(path):
                continue
            d = T.load(path, T.INFLATE)
            M = d["fluid_mass_pg"]
            dM = (M[-1] - M[-2]) / M[-1] if len(M) > 1 else None
            rows.append({"run": name, "what": what, "time_us": float(d["time_us"][-1]),
                         "P_mean_kPa": float(d["P_mean_kPa"][-1]), "P_min_kPa": float(d["P_min_kPa"][-1]),
                         "P_max_kPa": float(d["P_max_kPa"][-1]), "stretch_mean": float(d["stretch_mean"][-1]),
                         "mass_change_last_interval": dM, "glued_area_um2": float(d["glued_area_um2"][-1]),
                         "debonded_bonds": int(d["debonded_bonds"][-1]), "broken_tethers": int(d["broken_tethers"][-1])})
        self.S["inflation"] = rows
        if not rows:
            return
        s = self.settings(rows[0]["run"], "in.tissue-inflate")
        self.w("## Inflation", "", f"`in.tissue-inflate` (Lp {s['Lp']:g} um/(kPa us), mu {s['mu']:g} mPa s, then a "
               f"{s['nsettle']:.0f}-step settle under "
               "a drag with osmosis on, so that the tissue is at rest): the state at its end, which "
               "every experiment continues from (Lp 1e-9 then: the cells keep their water). Mass change: relative "
               f"growth of the fluid mass over the last {s['every']:.0f} steps (how far from osmotic equilibrium).", "",
               f"| run | cells | time (us) | P mean / min / max (kPa) | mean tether stretch | mass change, last {s['every']:.0f} steps | "
               "glued area (um^2) | debonded bonds | broken tethers |", "|" + "---|" * 9)
        for r in rows:
            self.w(f"| {r['run']} | {r['what']} | {fmt(r['time_us'])} | {fmt(r['P_mean_kPa'])} / {fmt(r['P_min_kPa'])} / "
                   f"{fmt(r['P_max_kPa'])} | {r['stretch_mean']:.4f} | {pct(r['mass_change_last_interval'], 2)} | "
                   f"{fmt(r['glued_area_um2'])} | {r['debonded_bonds']} | {r['broken_tethers']} |")
        self.w("")

    # ------------------------------------------------------------------ wall times
    def walltimes(self):
        w = self.w
        total = sum(v[0] for v in self.times.values())
        w("## Wall times", "", "Runs two at a time on the machine's cores, one MPI rank each (tools/tissue.sh "
          "`JOBS`, `NP`); the elapsed time of the whole script is about half the sum.", "",
          "| stage | wall time (s) | status |", "|---|---|---|")
        for k, (s, st) in self.times.items():
            w(f"| {k} | {s} | {st} |")
        w(f"| sum | {total} | |", "")
        el = None
        lines = self.info.splitlines()
        import datetime as dt
        try:
            st = [ln for ln in lines if ln.startswith("# started")][0].split()[2:4]
            fi = [ln for ln in lines if ln.startswith("# finished")][0].split()[2:4]
            f = "%Y-%m-%d %H:%M:%S"
            el = (dt.datetime.strptime(" ".join(fi), f) - dt.datetime.strptime(" ".join(st), f)).total_seconds()
            w(f"Elapsed (first run to last): {el:.0f} s.", "")
        except (IndexError, ValueError):
            pass
        self.S["wall_times_s"] = {k: {"s": s, "status": st} for k, (s, st) in self.times.items()}
        self.S["wall_time_sum_s"] = total
        self.S["elapsed_s"] = el

    def kept_note(self):
        """The note written by hand under the title of the report being replaced (its "> " lines and
        the blank line after them), kept when that report is of this same run (its summary's
        run_info begins this run's: a run of some stages, ONLY, adds lines): it is about these runs.
        A new run's report starts without it."""
        path = os.path.join(self.report, "tissue.md")
        old = reporting.read_json(os.path.join(self.report, "tissue-summary.json"), {}).get("run_info")
        now = self.info.strip().splitlines()
        if not os.path.exists(path) or not old or old != now[:len(old)]:
            return []
        lines = reporting.read_text(path).split("\n")[2:]
        n = next((k for k, ln in enumerate(lines) if not ln.startswith("> ")), 0)
        return lines[:n] + [""] if n else []

    def head(self):
        """Title, kept note, summary, what made the report, the run settings."""
        lv = params.LEVELS[3]
        f0 = f"{lv['f0']:.0e}".replace("e+0", "e")
        conv = f"CONVERGED=\"{' '.join(self.converged_dirs)}\" " if self.converged_dirs else ""
        return [f"# Tissue experiments ({self.res})", "", *self.kept_note(), summary.paragraph(self), "",
                f"Generated by `RES={self.res} {conv}bash tools/tissue.sh` (tools/cellmech/tissue/report.py). Coarse level-3 walls "
                f"({params.wall_nodes(3)} nodes per cell, ~{lv['nfluid']} fluid particles), `-var s {lv['s']:g} -var r0 "
                f"{lv['r0']:g} -var f0 {f0}`, reach and extra/special/per/atom from the generator's statistics "
                f"(max({lv['reach']:.1f}, recommended_reach)). Block: {int(self.block['cells'])} cells. Units: um, us, "
                "pg; force nN (uN = 1000 nN), stress kPa, energy pJ = 1000 nN um.", "",
                "Run settings:", "", "```", self.info.strip(), "```", ""]

    def write(self):
        self.md = self.head() + self.md
        reporting.write_lines(os.path.join(self.report, "tissue.md"), self.md)
        self.S["cells"] = int(self.block["cells"])
        self.S["converged_runs"] = self.converged_dirs
        self.S["run_info"] = self.info.strip().splitlines()
        reporting.write_json(os.path.join(self.report, "tissue-summary.json"), self.S)


def splice_water(rep):
    """The Water section alone, in place of the one in REPORT/tissue.md (before "## Pictures" if it
    has none), and its key in tissue-summary.json; the rest of both files stays as it is."""
    water.section(rep)
    path = os.path.join(rep.report, "tissue.md")
    lines = open(path).read().split("\n") if os.path.exists(path) else []
    heads = [k for k, ln in enumerate(lines) if ln.startswith("## ")]
    start = next((k for k in heads if lines[k] == "## Water"), None)
    if start is None:
        end = start = next((k for k in heads if lines[k] in ("## Pictures", "## Wall times")), len(lines))
    else:
        end = next((k for k in heads if k > start), len(lines))
    lines[start:end] = rep.md
    with open(path, "w") as f:
        f.write("\n".join(lines).rstrip("\n") + "\n")
    jp = os.path.join(rep.report, "tissue-summary.json")
    summary = json.load(open(jp)) if os.path.exists(jp) else {}
    summary["water"] = json.loads(json.dumps(rep.S["water"], default=float))
    with open(jp, "w") as f:
        json.dump(summary, f, indent=1)
    print(f"report: the Water section of {path}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--run", required=True)
    ap.add_argument("--res", default="coarse")
    ap.add_argument("--report", required=True)
    ap.add_argument("--figs")
    ap.add_argument("--converged", nargs="*", default=[],
                    help="run folders of tools/tissue-converged.sh: the blocks at converged rates (section 2)")
    ap.add_argument("--only", choices=["water"],
                    help="write only this section into the existing tissue.md and summary (the other "
                    "sections stay as they are)")
    a = ap.parse_args()
    run = os.path.abspath(a.run)
    rep = Report(run, a.res, os.path.abspath(a.report), os.path.abspath(a.figs or a.report), a.converged)
    if a.only:
        splice_water(rep)
        return
    for part in (rep.inflations, rep.pair, rep.converged_blocks, rep.blocks, rep.impacts, lambda: water.section(rep), rep.pictures,
                 rep.walltimes):
        try:
            part()
        except Exception as e:  # report what is there
            import traceback
            traceback.print_exc()
            rep.w(f"({part.__name__}: failed in the report: {e})", "")
    rep.write()
    print(f"report: {os.path.join(rep.report, 'tissue.md')}")


if __name__ == "__main__":
    main()
