# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 5: the validation suite (tools/validate.sh, tools/cellmech/validation/) at RES=coarse, as CI runs
it: 642 wall nodes, ~460 fluid particles (level 3), a few minutes on one core. The report and the
JSON summary are written to work-validation/; each case is checked against a tolerance that the
coarse resolution justifies (below, next to each check), and the summary must hold every case with
its measured values, references, relative errors, resolution and wall time.

Resolution scales used below (level 3): fluid-wall contact distance r0 = 3.2 um, R = 30 um, so
r0/R = 0.107; kernel support 2s = 12.8 um. The SPH fluid ends a contact layer of thickness ~r0
inside the wall, where the analytic models have a continuous fluid up to the wall: its pressure
acts on a sphere of radius between R - r0 and R, an area (and force) factor between
(1 - r0/R)^2 = 1 - 2 r0/R and 1. The tolerance 2 r0/R = 21% of the fluid-coupled cases is that
bound, not an estimate; the paper-resolution tests (test_inflate_paper, test_breathing_fluid)
assert the paper's 5-6% at r0/R = 0.053.
"""
import json
import os
import subprocess
import sys

import pytest

import lmptest as T

R0, RC0 = T.CELL["R"], T.COARSE["r0"]
LAYER = 2 * RC0 / R0


def rows(case, group=None, contains=""):
    return [r for r in case["rows"] if (group is None or r["group"] == group) and contains in r["name"]]


@pytest.fixture(scope="module")
def suite(rundir):
    """tools/validate.sh's driver at RES=coarse: its environment and its summary's cases by number."""
    d = rundir
    env = dict(os.environ, RES="coarse", OUT=d, WORK=os.path.join(d, "work"),
               LAMMPS_PLUGIN_PATH=os.path.dirname(T.PLUGIN))
    p = subprocess.run([sys.executable, "-m", "cellmech.validation.driver"], env=env, capture_output=True,
                       text=True)
    print(p.stdout[-6000:], p.stderr[-3000:])
    T.check("validate.sh driver ran", p.returncode == 0, f"rc {p.returncode}")
    summary = json.load(open(os.path.join(d, "validation-summary.json")))
    return env, {c["id"].split("-")[0]: c for c in summary["cases"]}


def test_summary_and_report(rundir, suite):
    d = rundir
    _, cases = suite
    T.check("summary has cases 1-8", sorted(cases) == [str(i) for i in range(1, 9)], f"{sorted(cases)}")
    for k, c in sorted(cases.items()):
        keys = all(x in c for x in ("measured", "reference", "rel_error", "resolution", "wall_time_s"))
        res = c["resolution"]
        T.check(f"case {k}: measured/reference/rel_error/resolution/wall time present", keys and
                "wall_nodes" in res and "fluid_particles" in res and c["wall_time_s"] is not None)
        # only the resolution study (three levels, ~12 min at the finest) is skipped at coarse
        allowed = ("ok", "skipped") if k == "6" else ("ok",)
        T.check(f"case {k}: status {c['status']}", c["status"] in allowed)
        if c["status"] != "skipped":
            T.check(f"case {k}: has results", len(c["rows"]) > 0)
    T.check("report validation.md with plots", os.path.exists(os.path.join(d, "validation.md")) and
            all(os.path.exists(os.path.join(d, "validation", p)) for c in cases.values() for p in c["plots"]))


def within(name, r, tol):
    e = r["rel_error"]
    T.check(name, e is not None and abs(e) < tol, f"{r['name']}: {e:+.2%} (tol {tol:.1%})"
            if e is not None else "no error")


def test_cases_within_tolerances(suite):
    _, cases = suite
    # 1: the wall alone has no fluid layer; the geodesic network's own frequency is Eq. A5 times
    # its mesh factor (1.0031 at level 3), the Neo-Hookean amplitude shift is of order lam - 1 =
    # 0.2%: the paper's 1% holds at this level as well.
    for r in [x for x in cases["1"]["rows"] if x["name"].endswith("vs Eq. A5")]:
        within(f"1: {r['name']} (1%)", r, 0.01)
    # 2: ground breathing mode at c = 100 and 250 m/s within the contact-layer bound. At
    # c = 50 m/s the ground period is about 0.8 us and the level-3 fluid (7 particles across
    # the cell) carries it no better than the drift of the turgid cell: printed, not asserted.
    for c in ("100", "250"):
        r = rows(cases["2"], group=f"c{c}", contains="mode 1 vs A4 (c, rho0)")
        T.check(f"2: c={c} ground mode found", len(r) == 1)
        for x in r:
            within(f"2: c={c} ground mode vs Eq. A4 (2 r0/R)", x, LAYER)
    T.check("2: c=50 three modes found", len(rows(cases["2"], group="c50", contains="(c, rho0)")) == 3)
    # 3: equatorial force against P pi R^2 within the contact-layer bound; the turgor itself is
    # set by osmosis to -Pi whatever the resolution (1%, as test_inflate).
    for r in rows(cases["3"], group="Feq"):
        within(f"3: {r['name']} (2 r0/R)", r, LAYER)
    for r in rows(cases["3"], group="P"):
        within(f"3: {r['name']} (1%)", r, 0.01)
    # 4: the sheet is the paper's 400 nodes at every RES: test_sheet's criteria. Small-strain
    # modulus of the spring network within 5% (second-order tether term 2.5%, the rest edges);
    # Eq. A1 at lam 1.01 within 5%; Eq. A2 within 20% from lam 1.15 on (the paper's statement).
    for r in rows(cases["4"], group="modulus"):
        within(f"4: {r['name']} (5%)", r, 0.05)
    for r in [x for x in cases["4"]["rows"] if "vs Eq." in x["name"]]:
        if "free, lam 1.01" in r["name"]:
            within(f"4: {r['name']} (5%)", r, 0.05)
        if "fixed, lam 1.15" in r["name"] or "fixed, lam 1.20" in r["name"]:
            within(f"4: {r['name']} (20%)", r, 0.20)
    # 5: the plate force against the membrane model (tools/membrane.py), for the stiff cell at
    # 364 kPa: the fluid-contact bound as above, on the windowed force against the model averaged
    # over the same records (analysis.windowed_curve).
    c5 = cases["5"]
    stiff = [r for r in rows(c5, group="P364") if r["reference"] is not None]
    T.check("5: membrane reference compared at 364 kPa", len(stiff) >= 4, f"{len(stiff)} strains")
    for r in stiff:
        within(f"5: {r['name']} vs membrane (2 r0/R)", r, LAYER)
    # the lower turgors are let down from 364 kPa (in.turgor) and settle there: the turgor is set
    # by osmosis (1%, as test_inflate), and the fluid's mass has stopped moving (a cell pumped up
    # directly to 3 kPa still took in 0.4% per 4 us at level 4, docs/studies/membrane-wall.rst; 1e-3 is a
    # quarter of that)
    for P in ("300", "30", "3"):
        st = rows(c5, group=f"P{P}-settle")
        T.check(f"5: {P} kPa cell settled from 364 kPa (two rows)", len(st) == 2, f"{len(st)} rows")
        for r in st:
            if r["reference"] is not None:
                within(f"5: {r['name']} (1%)", r, 0.01)
            else:
                T.check(f"5: {r['name']} below 1e-3", abs(r["measured"]) < 1e-3, f"{r['measured']:+.2e}")
    # 6: not run at coarse (it needs the 10242-node level); the report says so.
    T.check("6: resolution study skipped at RES=coarse with a statement",
            cases["6"]["status"] == "skipped" and len(cases["6"]["notes"]) > 0)
    # 7: test_energy's bounds (second-order, time-reversible integrator; see there).
    for r in cases["7"]["rows"]:
        T.check(f"7: {r['name']} below {r['tolerance']:g}", r["measured"] < r["tolerance"],
                f"{r['measured']:.2e}")
    # 8: the bending wall breathing 20 periods below sigma_c at level 3 (omega to Eq. A5 within
    # 0.5%, the swing kept within 5%): the rows that carry a tolerance are held to it
    for r in [x for x in cases["8"]["rows"] if x["tolerance"] is not None]:
        within(f"8: {r['name']}", r, r["tolerance"])


def test_variant_study(rundir, suite):
    d = rundir
    env, _ = suite
    # a variant study (VARS): its -var settings reach every run and the report says so; it never
    # writes the default (committed) report; malformed entries are refused
    driver = [sys.executable, "-m", "cellmech.validation.driver"]
    for vars_, extra, expect in (("wrinkle", {}, "expected entries name=value"),
                                 ("wall=bending", {}, "'wall' is set by the suite"),
                                 ("wrinkle=yes", {"OUT": None, "WORK": None}, "its own OUT and WORK")):
        e = dict(env, VARS=vars_, CASES="1", **{k: v for k, v in extra.items() if v})
        for k, v in extra.items():
            if v is None:
                e.pop(k, None)
        p = subprocess.run(driver, env=e, capture_output=True, text=True)
        print(f"VARS={vars_!r}: rc {p.returncode}, {p.stderr.strip()[-200:]}")
        T.check(f"VARS={vars_!r} is refused with a message", p.returncode != 0 and expect in p.stderr,
                p.stderr.strip()[-200:])
    dv = os.path.join(d, "variant")
    e = dict(env, VARS="wrinkle=no", CASES="1", WALL="membrane", OUT=dv, WORK=os.path.join(dv, "work"))
    p = subprocess.run(driver, env=e, capture_output=True, text=True)
    T.check("a variant study runs", p.returncode == 0, p.stderr[-500:])
    stamps = [json.load(open(os.path.join(dv, "work", f))) for f in os.listdir(os.path.join(dv, "work"))
              if f.startswith("log.") and f.endswith(".stamp")]
    print(f"variant runs: {len(stamps)}, -var wrinkle in each: {[s.get('wrinkle') for s in stamps]}")
    T.check("every run of the variant study carries its -var", stamps and all(s.get("wrinkle") == "no" for s in stamps))
    head = open(os.path.join(dv, "validation.md")).read().split("\n")[2]
    T.check("the variant's report names its VARS", 'VARS="wrinkle=no"' in head, head[:200])
    T.check("the variant's summary names its VARS",
            json.load(open(os.path.join(dv, "validation-summary.json"))).get("vars") == "wrinkle=no")
