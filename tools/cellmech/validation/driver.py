# SPDX-License-Identifier: GPL-2.0-or-later
"""Validation suite driver (issue 5): `bash tools/validate.sh` runs it.

Environment:
  RES    coarse (default; level 3: 642 wall nodes, 440 fluid), paper (level 4: 2562 + 3500, plus
         the resolution study over levels 3-5), study (the same as paper), fine (level 5)
  OUT    report folder: validation.md, validation-summary.json, validation/*.png
         (default results/validation-RES; docs/ for RES=paper)
  WORK   folder for the LAMMPS runs (default results/validation-RES/work); runs already done there
         with the same settings are reused
  CASES  which cases, e.g. "1,2,5" (default all: 1-8)
  STUDY_LEVELS  levels of the resolution study (default "3 4 5")
  NP     MPI ranks per LAMMPS run (default 1)
  WALL   the wall of every run (lammps-inputs/cell-wall.lmp): tether (default) | membrane |
         bending; OUT and WORK then default to results/validation-RES-WALL (RES=paper: OUT
         docs/validation-WALL). Cases 3 and 4 (Young-Laplace, sheet) run the tethers and the
         membrane side by side whatever WALL is; the report of either wall at RES=paper sets the
         other wall's committed report beside it (section "The walls side by side").
  VARS   a variant study: "name=value ..." passed as -var to every LAMMPS run, over the
         model's own values (e.g. VARS="wrinkle=yes f0=1e5"); needs its own OUT and WORK, so
         that it never writes over a committed report
"""
import json
import os
import shutil
import sys
import time
import traceback

from ..params import RES_LEVEL, ROOT, WALLS


def parse_vars(text):
    """{name: value} of VARS ("name=value ..."); exits with a message on a malformed entry."""
    out = {}
    for item in text.split():
        name, eq, value = item.partition("=")
        if not eq or not name.isidentifier() or not value:
            sys.exit(f"validate: VARS: expected entries name=value separated by blanks, got '{item}'")
        if name in ("wall", "dir"):
            sys.exit(f"validate: VARS: '{name}' is set by the suite (use WALL for the wall)")
        out[name] = value
    return out


def locations(res, wall, variant):
    """(OUT, WORK) of this invocation: the environment's, else the defaults of RES and WALL (a
    variant study must name both)."""
    tag = "" if wall == "tether" else f"-{wall}"
    default_out = (os.path.join(ROOT, "docs") if res == "paper" and not tag else
                   os.path.join(ROOT, "docs", f"validation{tag}") if res == "paper" else
                   os.path.join(ROOT, "results", f"validation-{res}{tag}"))
    if variant and not ("OUT" in os.environ and "WORK" in os.environ):
        sys.exit("validate: VARS makes a variant study: give it its own OUT and WORK (the "
                 "defaults are the model's report and runs)")
    out = os.path.abspath(os.environ.get("OUT", default_out))
    work = os.path.abspath(os.environ.get("WORK", os.path.join(ROOT, "results", f"validation-{res}{tag}", "work")))
    return out, work


def snapshot_inputs(work):
    """A copy of the inputs as they are now, which every run of this invocation reads (see
    common.INPUTS)."""
    snap = os.path.join(work, "lammps-inputs")
    os.makedirs(snap, exist_ok=True)
    for f in os.listdir(os.path.join(ROOT, "lammps-inputs")):
        if os.path.isfile(os.path.join(ROOT, "lammps-inputs", f)):
            shutil.copy(os.path.join(ROOT, "lammps-inputs", f), snap)
    os.environ["CELLMECH_INPUTS"] = snap


def same_report(summary, res, wall):
    return (summary.get("res"), summary.get("wall", "tether")) == (res, wall)


class Summary:
    """The entries of the report in OUT: those of earlier runs into the same OUT at the same RES
    and WALL are kept for the cases not rerun, and so are those another driver writes there
    meanwhile (e.g. the resolution study run beside the other cases)."""

    def __init__(self, out, res, level, wall, wanted):
        self.out, self.res, self.level, self.wall, self.wanted = out, res, level, wall, wanted
        self.path = os.path.join(out, "validation-summary.json")
        self.entries = {}
        try:
            old = json.load(open(self.path))
            if same_report(old, res, wall):
                self.entries = {e["id"].split("-")[0]: e for e in old["cases"]}
        except (OSError, ValueError, KeyError):
            pass
        self.t_all = time.time()

    def write(self):
        try:
            disk = json.load(open(self.path))
            if same_report(disk, self.res, self.wall):
                for x in disk["cases"]:
                    k = x["id"].split("-")[0]
                    if k not in self.wanted:
                        self.entries[k] = x
        except (OSError, ValueError, KeyError):
            pass
        report.write(self.out, self.res, self.level, [self.entries[k] for k in sorted(self.entries)],
                     time.time() - self.t_all, wall=self.wall, others=report.other_walls(self.res, self.wall))


def run_case(cid, run, level, ctx, summary):
    """Case cid into the summary (written after each save); an exception makes an error entry."""
    fn = cases.CASES[cid]
    print(f"case {cid}: {fn.__name__} (RES={ctx['res']}, level {level})", flush=True)
    t = time.time()
    run.reset_time()

    def save(entry):
        d = entry.finish()
        # LAMMPS time of every run the case uses (made now or reused) plus the rest of this
        # invocation's time in the case (analysis, membrane solver, cellgen)
        d["wall_time_s"] = round(run.seconds + (time.time() - t - run.fresh_seconds), 1)
        d["elapsed_s"] = round(time.time() - t, 1)
        summary.entries[cid] = d
        summary.write()

    ctx["save"] = save
    try:
        e = fn(run, level, ctx)
        save(e)
    except Exception as exc:
        traceback.print_exc()
        e = Entry(f"{cid}-error", fn.__name__, "", {})
        e.d["status"] = "error"
        e.note(f"{type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''}")
        save(e)
    d = summary.entries[cid]
    worst = max((abs(r["rel_error"]) for r in d["rows"] if r["rel_error"] is not None), default=None)
    print(f"case {cid}: {d['status']}, {d['wall_time_s']:.0f} s" +
          (f", largest |rel. error| {worst:.2%}" if worst is not None else ""), flush=True)


def main():
    res = os.environ.get("RES", "coarse")
    wall = os.environ.get("WALL", "tether")
    if wall not in WALLS:
        sys.exit(f"validate: WALL must be one of {', '.join(WALLS)}, got {wall}")
    variant = parse_vars(os.environ.get("VARS", ""))
    out, work = locations(res, wall, variant)
    snapshot_inputs(work)
    # imported after CELLMECH_INPUTS is set: common reads it at import
    global cases, report, Entry
    from .common import Runner
    from . import cases, report
    from .entry import Entry
    if res not in RES_LEVEL:
        sys.exit(f"validate: RES must be one of {', '.join(RES_LEVEL)}")
    level = RES_LEVEL[res]
    wanted = [c.strip() for c in os.environ.get("CASES", ",".join(cases.CASES)).split(",") if c.strip()]
    unknown = [c for c in wanted if c not in cases.CASES]
    if unknown:
        sys.exit(f"validate: CASES must name cases among {','.join(cases.CASES)}, got {','.join(unknown)}")
    plotdir = os.path.join(out, "validation")
    os.makedirs(plotdir, exist_ok=True)
    run = Runner(work, nprocs=int(os.environ.get("NP", "1")), wall=wall, variant=variant)
    ctx = dict(res=res, level=level, plotdir=plotdir,
               study_levels=[int(x) for x in os.environ.get("STUDY_LEVELS", "3 4 5").split()])
    summary = Summary(out, res, level, wall, wanted)
    for cid in wanted:
        run_case(cid, run, level, ctx, summary)
    summary.write()
    print(f"report: {os.path.join(out, 'validation.md')}, {summary.path}")


if __name__ == "__main__":
    main()
