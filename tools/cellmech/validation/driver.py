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


def main():
    res = os.environ.get("RES", "coarse")
    wall = os.environ.get("WALL", "tether")
    if wall not in WALLS:
        sys.exit(f"validate: WALL must be one of {', '.join(WALLS)}, got {wall}")
    tag = "" if wall == "tether" else f"-{wall}"
    default_out = (os.path.join(ROOT, "docs") if res == "paper" and not tag else
                   os.path.join(ROOT, "docs", f"validation{tag}") if res == "paper" else
                   os.path.join(ROOT, "results", f"validation-{res}{tag}"))
    variant = parse_vars(os.environ.get("VARS", ""))
    if variant and not ("OUT" in os.environ and "WORK" in os.environ):
        sys.exit("validate: VARS makes a variant study: give it its own OUT and WORK (the "
                 "defaults are the model's report and runs)")
    out = os.path.abspath(os.environ.get("OUT", default_out))
    work = os.path.abspath(os.environ.get("WORK", os.path.join(ROOT, "results", f"validation-{res}{tag}", "work")))
    # a copy of the inputs as they are now (see common.INPUTS)
    snap = os.path.join(work, "lammps-inputs")
    os.makedirs(snap, exist_ok=True)
    for f in os.listdir(os.path.join(ROOT, "lammps-inputs")):
        if os.path.isfile(os.path.join(ROOT, "lammps-inputs", f)):
            shutil.copy(os.path.join(ROOT, "lammps-inputs", f), snap)
    os.environ["CELLMECH_INPUTS"] = snap
    # imported after CELLMECH_INPUTS is set: common reads it at import
    global cases, report
    from .common import Runner
    from . import cases, report
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
    summary_path = os.path.join(out, "validation-summary.json")
    # entries of earlier runs into the same OUT at the same RES are kept for cases not rerun
    entries = {}
    try:
        old = json.load(open(summary_path))
        if (old.get("res"), old.get("wall", "tether")) == (res, wall):
            entries = {e["id"].split("-")[0]: e for e in old["cases"]}
    except (OSError, ValueError, KeyError):
        pass
    t_all = time.time()

    def write():
        # another driver may be writing the same report (e.g. the resolution study run beside the
        # other cases): keep its entries for the cases this one does not run
        try:
            disk = json.load(open(summary_path))
            if (disk.get("res"), disk.get("wall", "tether")) == (res, wall):
                for x in disk["cases"]:
                    k = x["id"].split("-")[0]
                    if k not in wanted:
                        entries[k] = x
        except (OSError, ValueError, KeyError):
            pass
        report.write(out, res, level, [entries[k] for k in sorted(entries)], time.time() - t_all,
                     wall=wall, others=report.other_walls(res, wall))

    for cid in wanted:
        fn = cases.CASES[cid]
        print(f"case {cid}: {fn.__name__} (RES={res}, level {level})", flush=True)
        t = time.time()
        run.reset_time()

        def save(entry):
            d = entry.finish()
            # LAMMPS time of every run the case uses (made now or reused) plus the rest of this
            # invocation's time in the case (analysis, membrane solver, cellgen)
            d["wall_time_s"] = round(run.seconds + (time.time() - t - run.fresh_seconds), 1)
            d["elapsed_s"] = round(time.time() - t, 1)
            entries[cid] = d
            write()

        ctx["save"] = save
        try:
            e = fn(run, level, ctx)
            save(e)
        except Exception as exc:
            traceback.print_exc()
            e = cases.Entry(f"{cid}-error", fn.__name__, "", {})
            e.d["status"] = "error"
            e.note(f"{type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''}")
            save(e)
        d = entries[cid]
        worst = max((abs(r["rel_error"]) for r in d["rows"] if r["rel_error"] is not None), default=None)
        print(f"case {cid}: {d['status']}, {d['wall_time_s']:.0f} s" +
              (f", largest |rel. error| {worst:.2%}" if worst is not None else ""), flush=True)
    write()
    print(f"report: {os.path.join(out, 'validation.md')}, {summary_path}")


if __name__ == "__main__":
    main()
