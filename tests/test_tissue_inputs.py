# SPDX-License-Identifier: GPL-2.0-or-later
"""Tissue inputs and styles, defects found by probing (issue 28, items 2, 5, 8, 9 and 10): each
check below failed before its fix (the numbers of the unfixed code in brackets).

2. A coarse tissue run without -var s/r0/f0 silently used the paper-resolution lengths (exit 0,
   walls unstretched: mean stretch 1.0000 instead of 1.0076, 429 of 882 fluid particles outside
   their walls). Now in.tissue-inflate reads the level's lengths from DATA.lmp (cellgen.py writes
   it), writes the ones it ran with to RESTART.lmp and tissue-restart.lmp reads them back; a
   missing file is an error unless every length comes from -var; pair cell/sph refuses a kernel
   support 2s below 1.25 fluid spacings (the paper's s in a coarse cell: 1.12) and pair
   cell/virtual an r0 below half the mean wall edge (the paper's lengths on the coarse pair stop
   at one of the two), on 1 and 2 ranks, while the lengths of every level (3, 4, 5) pass.
5. Two wall models at once: tethers plus angle_style cell/membrane ran [exit 0], and a restart of
   a bending wall continued with -var wall tether kept bending its hinges [energy 4736]. Now the
   first is refused, and the second switches them off with a warning (and RESTART.lmp carries the
   wall, so a plain continuation keeps it).
8. Tissue inputs checked wall and balance only: vplate 0 ["Divide by 0"], negative vplate or
   strain ["Invalid run command N value"], kp 0 ["Particle on or inside fix wall surface"],
   sigl 0 ["All bond coeffs are not set"], a single cell's restart (in.inflate) in
   in.tissue-compress ["Numeric index 2 is out of bounds"], in.tissue-pair -var grip 0 [a free
   pair pulled], -var ncell 1 on a pair [zeros written]. Now each names input, variable and range.
9. Blow-up advice named the wrong cause: a drag too strong for the time step and a lamella with
   a critical opening of 4e-9 um ["reduce the time step"], a forgotten timestep ["Bond atoms
   missing"]. Now each is refused at the start with its cause and bound, on 1 and 2 ranks, and a
   run that blows up later names the time step against the fluid's acoustic limit.
10. dihedral_coeff * on data without dihedrals ["Invalid range string"]; fix property/atom fields
   in another order after read_restart [a negative density, no word of the order].
"""
import json
import os
import re
import shutil

import numpy as np
import pytest

import lmptest as T
from cellmech import params

INPUTS = T.INPUTS
# the level-3 lengths, for runs that give them on the command line
L3 = {k: params.LEVELS[3][k] for k in ("s", "r0", "f0", "reach")}
PAPER = {k: params.LEVELS[4][k] for k in ("s", "r0", "f0")}
# the lengths with the reach the pair's mesh needs: given to the runs of items 5-10, so that the
# unfixed inputs (which took no lengths from a restart) reach each item's own defect
LEN = dict(L3)    # reach: the generator's for the pair (the fixture pair)
SPECIAL = [0]    # the pair's extra/special/per/atom (cellgen's pair.json), set by the fixture pair


def error_line(log):
    m = re.search(r"ERROR.*", log)
    return m.group(0)[:400] if m else "no error"


def refused(name, rc, log, pattern, nprocs=1):
    """A clear error: non-zero exit, no signal, the message matching pattern."""
    crashed = rc is None or rc < 0 or (rc >= 128 and "ERROR" not in log)
    T.check(f"{name}{'' if nprocs == 1 else f', {nprocs} ranks'}: a clear error",
            not crashed and rc != 0 and re.search(pattern, log) is not None,
            f"rc {rc}: {error_line(log)[:260]}")


def lmp(inp, d, log, nprocs=1, **variables):
    return T.lmp(inp, cwd=d, nprocs=nprocs, check=False, log=log, variables=variables)


def measure(d, log_name, inflate, **variables):
    """in.tissue-inflate, then the mean wall stretch and the fluid outside its own wall."""
    text = f"include {inflate}\n" + """compute         leakm all cell/props leaks yes
run             0 post no
print           "MEASURE $(v_lam:%.6f) $(sum(c_leakm[9]):%.0f) $(count(fluid))"
"""
    rc, log = lmp(text, d, log_name, **variables)
    m = re.findall(r"^MEASURE (\S+) (\S+) (\S+)", log, re.M)
    return rc, log, (tuple(map(float, m[-1])) if m else None)


@pytest.fixture(scope="module")
def pair(rundir):
    """The coarse single cell (one.data), pair (pair.data, bare.data) and cell (cell3.data), and the pair
    inflated briefly, every length given: the restart of items 8-10 (it writes pair.restart.lmp as
    well). Sets SPECIAL and LEN."""
    d = rundir
    for old in ("default.restart", "default.restart.lmp", "bare.data.lmp", "bare.restart",
                "bare.restart.lmp", "pair.restart"):
        if os.path.exists(os.path.join(d, old)):
            os.remove(os.path.join(d, old))
    T.cellgen("tissue", "-o", "one.data", "--lattice", "sc", "--n", 1, 1, 1, "--level", 3,
              "--nfluid", 440, cwd=d)
    T.cellgen("tissue", "-o", "pair.data", "--lattice", "sc", "--n", 1, 1, 2, "--level", 3,
              "--nfluid", 440, cwd=d)
    stats = json.load(open(os.path.join(d, "pair.json")))
    SPECIAL[0] = stats["extra_special_per_atom"]
    LEN["reach"] = max(L3["reach"], stats["triangle_quality"]["recommended_reach"])
    T.coarse_cell(d, "cell3.data")
    # bare.data: the pair without its lengths file (DATA.lmp), for the runs of item 2
    shutil.copy(os.path.join(d, "pair.data"), os.path.join(d, "bare.data"))
    lmp(os.path.join(INPUTS, "in.tissue-inflate"), d, "log.inflate", dir=INPUTS, data="pair.data",
        special=SPECIAL[0], nsteps=600, nsettle=200, every=200, restart_out="pair.restart", **LEN)
    return d


@pytest.fixture(scope="module")
def default_inflation(pair):
    """2: the default inflation of the coarse pair from cellgen's data, lengths from pair.data.lmp
    (default.restart and its RESTART.lmp): rc, log and the measure."""
    d = pair
    inflate = os.path.join(INPUTS, "in.tissue-inflate")
    rc, log, m = measure(d, "log.2-default", inflate, dir=INPUTS, data="pair.data",
                         restart_out="default.restart")
    print(f"2: default inflation, lengths from pair.data.lmp: rc {rc}, mean stretch "
          f"{m[0] if m else '?'}, fluid outside its wall {m[1] if m else '?'} of {m[2] if m else '?'}")
    return rc, log, m


def test_inflation_takes_lengths_of_data(pair, default_inflation):
    d = pair
    rc, log, m = default_inflation
    sph = re.findall(r"^pair_coeff\s+2 2 cell/sph \S+ \S+ \S+ \S+ (\S+)$", log, re.M)
    T.check("2: in.tissue-inflate takes s of the level from DATA.lmp", rc == 0 and
            sph and float(sph[-1]) == L3["s"], f"rc {rc}: s {sph[-1] if sph else '?'}")
    T.check("2: ... and the inflated walls are stretched with their fluid inside (stretch > 1.005, "
            "none outside)", m is not None and m[0] > 1.005 and m[1] == 0, str(m))
    side = os.path.join(d, "default.restart.lmp")
    text = open(side).read() if os.path.exists(side) else ""
    want = dict(LEN, dt=params.LEVELS[3]["dt"])
    got = dict(re.findall(r"^variable\s+(\w+)\s+index\s+(\S+)", text, re.M))
    T.check("2: in.tissue-inflate writes RESTART.lmp with the lengths, time step and wall it used",
            all(k in got and float(got[k]) == float(v) for k, v in want.items()) and
            got.get("wall") == "tether", str(got))


def test_data_without_lengths_refused(pair):
    d = pair
    inflate = os.path.join(INPUTS, "in.tissue-inflate")
    # a data file without its lengths file, run as the usage line and cellgen's summary said (reach
    # and special given): the paper's lengths before
    rc, log, m = measure(d, "log.2-bare", inflate, dir=INPUTS, data="bare.data", special=SPECIAL[0],
                         reach=LEN["reach"], restart_out="bare-inflated.restart")
    if m:
        print(f"2: bare data, no lengths: rc {rc}, mean stretch {m[0]}, fluid outside {m[1]:.0f} "
              f"of {m[2]:.0f}")
    refused("2: a data file without DATA.lmp and no -var lengths", rc, log,
            r"ERROR: in.tissue-inflate: bare.data.lmp is missing: it holds the model lengths")


def test_paper_lengths_refused_on_coarse_tissue(pair):
    d = pair
    inflate = os.path.join(INPUTS, "in.tissue-inflate")
    # the paper's lengths given on a coarse tissue: the styles refuse them, on 1 and 2 ranks
    for n in (1, 2):
        rc, log = lmp(inflate, d, f"log.2-paper{n}", n, dir=INPUTS, data="bare.data", special=SPECIAL[0],
                      reach=LEN["reach"], nsteps=100, nsettle=10, restart_out="paper.restart", **PAPER)
        # both the paper's s and r0 are too short for it: either refusal will do
        refused("2: the paper's lengths on a coarse tissue", rc, log,
                r"Pair style cell/sph: the kernel support 2s = 6\.4 of fluid type 2 .* below 1\.25|"
                r"Pair style cell/virtual: the contact distance r0 = 1\.6 of wall type 1", n)
        # the paper's s alone, in a coarse cell free all round (cellgen tissue --n 1 1 1: the
        # spacing of a single cell, 5.69 um): 2s = 1.12 spacings
        rc, log = lmp(inflate, d, f"log.2-s{n}", n, dir=INPUTS, data="one.data",
                      nsteps=100, nsettle=10, restart_out="one.restart", s=PAPER["s"])
        refused("2: the paper's s = 3.2 in a coarse cell", rc, log,
                r"Pair style cell/sph: the kernel support 2s = 6\.4 of fluid type 2 .* spans 1\.12 "
                r"fluid spacings, below 1\.25.* Use s >= 3\.5", n)
        rc, log = lmp(inflate, d, f"log.2-r0{n}", n, dir=INPUTS, data="bare.data", special=SPECIAL[0],
                      reach=LEN["reach"], nsteps=100, nsettle=10, restart_out="paper.restart",
                      **dict(PAPER, s=L3["s"]))
        refused("2: the paper's r0 = 1.6 on a coarse tissue", rc, log,
                r"Pair style cell/virtual: the contact distance r0 = 1\.6 of wall type 1 and fluid "
                r"type 2 .* below 0\.5 times the mean edge 4\.\d+ of the wall's 2560 triangles", n)


def test_continued_run_takes_restart_lengths(pair, default_inflation):
    d = pair
    # a continued run takes the lengths of RESTART.lmp; a -var still wins
    short = dict(dir=INPUTS, restart="default.restart", strain=0.005, ramp=0, vplate=4, every=50,
                 out="c.dat", cells="c-cells.dat", pairs="c-pairs.dat")
    compress = os.path.join(INPUTS, "in.tissue-compress")
    rc, log = lmp(compress, d, "log.2-compress", **short)
    sph = re.findall(r"^pair_coeff\s+2 2 cell/sph \S+ \S+ \S+ \S+ (\S+)$", log, re.M)
    # the adhesion keyword follows when it is on (cell-model.lmp: adhargs, empty by default)
    vir = re.findall(r"^pair_coeff\s+1 2 cell/virtual (\S+) (\S+) \S+(?: adhere \S+ \S+)?\s*$", log, re.M)
    T.check("2: in.tissue-compress continues with the restart's s, f0, r0 (RESTART.lmp)",
            rc == 0 and sph and vir and float(sph[-1]) == L3["s"] and
            tuple(map(float, vir[-1])) == (L3["f0"], L3["r0"]),
            f"rc {rc}: {sph[-1:]} {vir[-1:]} {error_line(log)[:120]}")
    rc, log = lmp(compress, d, "log.2-compress-s", **dict(short, s=7.0))
    sph = re.findall(r"^pair_coeff\s+2 2 cell/sph \S+ \S+ \S+ \S+ (\S+)$", log, re.M)
    T.check("2: ... and a -var s on the command line wins", rc == 0 and sph and float(sph[-1]) == 7.0,
            f"rc {rc}: {sph[-1:]}")
    if os.path.exists(os.path.join(d, "default.restart")):
        shutil.copy(os.path.join(d, "default.restart"), os.path.join(d, "bare.restart"))
    rc, log = lmp(compress, d, "log.2-compress-bare", **dict(short, restart="bare.restart"))
    refused("2: a restart without RESTART.lmp and no -var lengths", rc, log,
            r"ERROR: tissue-restart.lmp: bare.restart.lmp is missing: it holds the model lengths")


def test_every_level_accepted(pair):
    d = pair
    # no shipped level is refused: a cell of each level with the level's lengths (run 0)
    for lvl in (3, 4, 5):
        p = params.level(lvl)
        data = f"cell{lvl}.data"
        if not os.path.exists(os.path.join(d, data)):
            T.cellgen("cell", "-o", data, "--level", lvl, "--nfluid", p["nfluid"], "--inset", p["r0"],
                      cwd=d)
        text = (T.cell_from_data(data) + "include ${dir}/cell-model.lmp\nfix integrate all nve\n"
                "fix osmosis fluid cell/fluid Pi -364.0 Lp 1.0e-9\ntimestep ${dt}\nrun 0\n")
        rc, log = lmp(text, d, f"log.2-level{lvl}", dir=INPUTS,
                      **{k: p[k] for k in ("s", "r0", "f0", "reach", "dt")})
        T.check(f"2: a level-{lvl} cell with the level's lengths is not refused", rc == 0,
                f"rc {rc}: {error_line(log)[:200]}")


def test_one_wall_model_at_a_time(pair):
    d = pair
    head = T.cell_from_data("cell3.data") + "include ${dir}/cell-model.lmp\n"
    run = ("fix integrate all nve\nfix osmosis fluid cell/fluid Pi -364.0 Lp 100.0\n"
           "timestep 0.001\nrun 50\n")
    rc, log = lmp(head + "angle_style cell/membrane\nangle_coeff * 8.0e5 0.126 0.1\n" + run, d,
                  "log.5-both", dir=INPUTS, **L3)
    refused("5: tethers plus angle_style cell/membrane", rc, log,
            r"Angle style cell/membrane: bond style cell/tether acts on the same wall: the tethers "
            r"and the membrane are two models of one wall")

    # a bending wall written to a restart, continued with the tether wall
    T.coarse_cell(d, "cellb.data", "--bending")
    rc, _ = lmp(os.path.join(INPUTS, "in.inflate"), d, "log.5-bend", dir=INPUTS, data="cellb.data",
                wall="bending", nsteps=100, every=50, out="bend.dat", restart_out="bend.restart",
                **L3)
    cont = T.continue_cell("bend.restart") + ("fix osmosis fluid cell/fluid Pi -364.0 Lp 100.0\n"
                                              "timestep 0.001\nrun 10\n"
                                              'print "HINGES $(edihed:%.10g) $(dihedrals)"\n')
    for wall in ("tether", "bending"):
        rc, log = lmp(cont, d, f"log.5-cont-{wall}", dir=INPUTS, wall=wall, **L3)
        h = re.findall(r"^HINGES (\S+) (\S+)", log, re.M)
        e = float(h[-1][0]) if h else float("nan")
        print(f"5: bending restart continued with -var wall {wall}: rc {rc}, hinge energy {e:.6g}")
        if wall == "tether":
            T.check("5: a bending restart continued with -var wall tether: hinges off, with a warning",
                    rc == 0 and e == 0.0 and re.search(r"^WARNING: cell-wall.lmp: -var wall tether: "
                                                       r"the 1920 hinges", log, re.M) is not None,
                    f"rc {rc}: energy {e:.6g}")
        else:
            T.check("5: ... continued with -var wall bending they still bend", rc == 0 and e > 0,
                    f"{e:.6g}")

    # a tissue inflated with the bending wall: its RESTART.lmp carries the wall
    T.cellgen("tissue", "-o", "pairb.data", "--lattice", "sc", "--n", 1, 1, 2, "--level", 3,
              "--nfluid", 440, "--bending", cwd=d)
    special = json.load(open(os.path.join(d, "pairb.json")))["extra_special_per_atom"]
    rc, log = lmp(os.path.join(INPUTS, "in.tissue-inflate"), d, "log.5-tissue", dir=INPUTS,
                  data="pairb.data", wall="bending", nsteps=20, nsettle=10, every=10,
                  restart_out="pairb.restart", special=special, **LEN)
    side = os.path.join(d, "pairb.restart.lmp")
    text = open(side).read() if os.path.exists(side) else ""
    T.check("5: RESTART.lmp of a bending tissue names the wall, so a continuation keeps it",
            rc == 0 and re.search(r"^variable\s+wall\s+index\s+bending$", text, re.M) is not None,
            f"rc {rc}: {error_line(log)[:100]}")


def test_tissue_inputs_checked(pair):
    d = pair
    compress = os.path.join(INPUTS, "in.tissue-compress")
    base = dict(LEN, dir=INPUTS, restart="pair.restart", strain=0.01, vplate=4)
    for var, value, pattern in (
            ("vplate", 0, r"in.tissue-compress: -var vplate 0: expected a plate speed > 0"),
            ("vplate", -1, r"in.tissue-compress: -var vplate -1: expected a plate speed > 0"),
            ("strain", -0.1, r"in.tissue-compress: -var strain -0.1: expected a final strain "
                             r"between 0 and 1"),
            ("kp", 0, r"in.tissue-compress: -var kp 0: expected a plate stiffness > 0"),
            ("jaws", "foo", r"in.tissue-compress: -var jaws foo: expected plates .* or cells"),
            ("respa", 5, r"in.tissue-compress: -var respa 5 with jaws cells: .* use respa 1"),
            ("sigl", 0, r"tissue-model.lmp: -var sigl 0, Gl \S+: expected a lamella strength "
                        r"sigl > 0")):
        jaws = dict(jaws="cells") if var == "respa" else {}
        rc, log = lmp(compress, d, f"log.8-{var}{value}", **dict(base, **jaws, **{var: value}))
        refused(f"8: in.tissue-compress -var {var} {value}", rc, log, "ERROR: " + pattern)
    rc, log = lmp(os.path.join(INPUTS, "in.tissue-impact"), d, "log.8-impact",
                  **dict(base, vplate=0))
    refused("8: in.tissue-impact -var vplate 0", rc, log,
            r"ERROR: in.tissue-impact: -var vplate 0: expected a plate speed > 0")

    # a single cell's restart (in.inflate) in the tissue input
    T.coarse_cell(d, "cell3i.data")
    lmp(os.path.join(INPUTS, "in.inflate"), d, "log.8-cell", dir=INPUTS, data="cell3i.data",
        nsteps=50, every=50, out="cell-inflate.dat", restart_out="cell.restart", **L3)
    rc, log = lmp(compress, d, "log.8-single", **dict(base, restart="cell.restart"))
    refused("8: a single cell's restart (in.inflate) in in.tissue-compress", rc, log,
            r"ERROR: tissue-model.lmp: the data or restart file has 1 bond type, but a tissue "
            r"glues its cells by bond type 2")

    pair = os.path.join(INPUTS, "in.tissue-pair")
    short = dict(LEN, dir=INPUTS, restart="pair.restart", press=0.02, vplate=4, pull=0.5, vpull=4,
                 every=50, out="pair-press.dat", pullout="pair-pull.dat")
    rc, log = lmp(pair, d, "log.8-grip0", **dict(short, grip=0))
    refused("8: in.tissue-pair -var grip 0", rc, log,
            r"ERROR: in.tissue-pair: -var grip 0, .*expected a grip > 0")
    rc, log = lmp(pair, d, "log.8-grip", **dict(short, grip=0.01))
    refused("8: in.tissue-pair with a grip that holds no node of the bottom cell", rc, log,
            r"ERROR: in.tissue-pair: -var grip 0.01: 0 wall nodes within 0.01 um of the bottom "
            r"plate .* each grip must hold some")
    rc, log = lmp(pair, d, "log.8-ncell", **dict(short, ncell=1))
    refused("8: in.tissue-pair -var ncell 1 on a pair", rc, log,
            r"ERROR: in.tissue-pair: -var ncell 1, but the restart pair.restart holds 2 cell")
    rc, log = lmp(pair, d, "log.8-pair", **short)
    pulled = re.findall(r"^pull: (\d+) nodes in the bottom grip, (\d+) in the top grip", log, re.M)
    T.check("8: in.tissue-pair on the pair runs press and pull, both grips holding nodes",
            rc == 0 and pulled and min(map(int, pulled[-1])) > 0, f"rc {rc}: {pulled[-1:]}")


def test_blow_up_causes_named(pair):
    d = pair
    inflate = os.path.join(INPUTS, "in.tissue-inflate")
    for n in (1, 2):
        rc, log = lmp(inflate, d, f"log.9-drag{n}", n, dir=INPUTS, data="pair.data", nsteps=0,
                      nsettle=20, drag=1.0e6, restart_out="drag.restart", special=SPECIAL[0], **LEN)
        refused("9: a drag too strong for the time step", rc, log,
                r"ERROR: Fix viscous settle: the drag gamma = 1e\+06 on atom \d+ \(mass [0-9.]+\) "
                r"is more than the time step 0.001 can integrate: gamma dt = 1000 >= 2 x mass", n)
        # critical opening delta_c = Gc / (e sigma_c (1 - 11 e^-10)) = 4e-9 um at sigma_c 300 kPa
        gl = 4.0e-9 * 300.0 * np.e * (1 - 11 * np.exp(-10))
        rc, log = lmp(os.path.join(INPUTS, "in.tissue-compress"), d, f"log.9-lamella{n}", n,
                      dir=INPUTS, restart="pair.restart", strain=0.01, vplate=4, Gl=f"{gl:.10g}",
                      **LEN)
        refused("9: a lamella of critical opening 4e-9 um", rc, log,
                r"ERROR: Bond style cell/lamella: bond type 2 \(sigma_c 300, Gc [0-9.e-]+\) has a "
                r"critical opening delta_c = 4e-09 too small for the time step 0.001.*omega dt = "
                r"[0-9.]+, and velocity Verlet needs omega dt < 2", n)
        # a forgotten timestep: the units' default (micro: 2 us)
        text = (T.cell_from_data("cell3.data") + "include ${dir}/cell-model.lmp\nfix integrate all nve\n"
                "fix osmosis fluid cell/fluid Pi -364.0 Lp 100.0\nrun 100\n")
        rc, log = lmp(text, d, f"log.9-timestep{n}", n, dir=INPUTS, **L3)
        refused("9: a forgotten timestep (units micro: 2 us)", rc, log,
                r"ERROR: Pair style cell/sph: the time step 2 is 331 times the acoustic limit 0.25 "
                r"s/c = 0.006047 .* did the input forget 'timestep'", n)
    # a run that blows up later names the time step against the acoustic limit (1 rank: the error
    # of the rank that sees it reaches the log there)
    text = (T.cell_from_data("cell3.data") + "include ${dir}/cell-model.lmp\nfix integrate all nve\n"
            "fix osmosis fluid cell/fluid Pi -364.0 Lp 100.0\ntimestep 0.02\nrun 200\n")
    rc, log = lmp(text, d, "log.9-blowup", dir=INPUTS, **L3)
    refused("9: a run blown up at 3.3 times the acoustic limit", rc, log,
            r"moved [0-9.e+-]+ distance units in one step .* The likely cause is a time step 3.31 "
            r"times the fluid's acoustic limit 0.25 s/c")


def test_dihedrals_and_field_order_checked(pair):
    d = pair
    text = T.cell_from_data("cell3.data") + "dihedral_style cell/bending\ndihedral_coeff * 8.0e5 0.126\n"
    rc, log = lmp(text, d, "log.10-dihedral", dir=INPUTS)
    refused("10: dihedral_coeff * on a data file without dihedrals", rc, log,
            r"ERROR: Dihedral_coeff cell/bending: the system has no dihedral types, so no hinges")
    text = """units           micro
read_restart    pair.restart
fix             cell all property/atom rmass d2_cellref 3 d_rho d_drho d_alam ghost yes
include         ${dir}/tissue-model.lmp
timestep        0.001
run             10
"""
    rc, log = lmp(text, d, "log.10-order", dir=INPUTS, Pi=-364.0, Lp=1.0e-9, **LEN)
    refused("10: fix property/atom fields in another order after read_restart", rc, log,
            r"ERROR: .*after read_restart: is fix property/atom defined with the same fields in "
            r"the same order")


def _dump_z(path):
    """{molecule: (type, z)} arrays of a write_dump custom id mol type z file."""
    a = np.loadtxt(path, skiprows=9, ndmin=2)
    return a[:, 1].astype(int), a[:, 2].astype(int), a[:, 3]


def test_tension_jaws(pair):
    """Issue 29: in.tissue-tension -var jaws cells holds the whole walls of the cells its grips
    touch (a specimen's ends glued into its jaws), so that the grips do not set where a block fails
    (the 27-cell block held by a ring of nodes broke in its gripped layer), and refers the strain to
    the gauge between them. On a stack of three coarse cells, inflated briefly: each grip holds
    exactly one cell's wall nodes and no fluid; the gauge printed is the gap between the held
    walls, measured from the atoms; a pull runs with it. With jaws nodes a grip deeper than the
    fluid-wall distance held fluid particles too (group ID intersect only adds atoms): the grip
    holds only the wall nodes within its depth. A block two cells high, or a bad keyword, is refused."""
    d = pair
    tension = os.path.join(INPUTS, "in.tissue-tension")
    base = dict(LEN, dir=INPUTS, restart="pair.restart", vpull=4, strain=0.02, every=50,
                tabevery=100, rest=0)
    rc, log = lmp(tension, d, "log.29-jawsfoo", **dict(base, jaws="foo"))
    refused("29: in.tissue-tension -var jaws foo", rc, log,
            r"ERROR: in.tissue-tension: -var jaws foo: expected nodes .* or cells")
    rc, log = lmp(tension, d, "log.29-jawspair", **dict(base, jaws="cells", special=SPECIAL[0]))
    refused("29: in.tissue-tension -var jaws cells on a pair", rc, log,
            r"ERROR: in.tissue-tension: -var jaws cells: the cells the two grips touch leave no "
            r"free cell between them")

    T.cellgen("tissue", "-o", "stack.data", "--lattice", "sc", "--n", 1, 1, 3, "--level", 3,
              "--nfluid", 440, cwd=d)
    stats = json.load(open(os.path.join(d, "stack.json")))
    lens = dict(L3, reach=max(L3["reach"], stats["triangle_quality"]["recommended_reach"]))
    lmp(os.path.join(INPUTS, "in.tissue-inflate"), d, "log.29-stack", dir=INPUTS, data="stack.data",
        special=stats["extra_special_per_atom"], nsteps=600, nsettle=200, every=200,
        restart_out="stack.restart", **lens)
    with open(os.path.join(d, "atoms.lmp"), "w") as f:
        f.write("write_dump all custom atoms.txt id mol type z modify sort id\n")
    run = dict(base, **lens, restart="stack.restart", more="atoms.lmp")
    for jaws, grip in (("cells", 2.0), ("nodes", 5.0)):
        rc, log = lmp(tension, d, f"log.29-{jaws}", **dict(run, jaws=jaws, grip=grip))
        m = re.findall(r"^grips: (\d+) nodes in the bottom grip, (\d+) in the top grip, H0 (\S+) um",
                       log, re.M)
        T.check(f"29: jaws {jaws}: the pull runs", rc == 0 and m, f"rc {rc}: {error_line(log)}")
        if not m:
            continue
        nbot, ntop, h0 = int(m[-1][0]), int(m[-1][1]), float(m[-1][2])
        mol, typ, z = _dump_z(os.path.join(d, "atoms.txt"))
        wall = typ == 1
        lo, hi = z[wall].min(), z[wall].max()
        if jaws == "cells":
            pulled = m[-1]
            bottom, top = mol[wall][np.argmin(z[wall])], mol[wall][np.argmax(z[wall])]
            per_cell = [int((wall & (mol == c)).sum()) for c in (bottom, top)]
            gauge = z[wall & (mol == top)].min() - z[wall & (mol == bottom)].max()
            print(f"29: jaws cells: grips {nbot} and {ntop} nodes, the end cells' walls {per_cell}; "
                  f"gauge {h0} um printed, {gauge:.4f} um between the held walls")
            T.check("29: jaws cells: each grip holds its end cell's whole wall and no fluid",
                    [nbot, ntop] == per_cell, f"{[nbot, ntop]} against {per_cell}")
            T.check("29: jaws cells: the strain refers to the gauge between the held walls",
                    abs(h0 - gauge) <= 5e-4 * gauge, f"{h0} against {gauge:.5g}")
            held = sorted(set(np.loadtxt(os.path.join(d, "tissue-tension-held.txt"), skiprows=9, ndmin=1)
                              .astype(int)))
            T.check("29: jaws cells: the held cells are written for the report",
                    held == sorted({int(bottom), int(top)}), f"{held} against {[bottom, top]}")
        else:
            near = [(wall & (z <= lo + grip)).sum(), (wall & (z >= hi - grip)).sum()]
            fluid = [(~wall & (z <= lo + grip)).sum(), (~wall & (z >= hi - grip)).sum()]
            print(f"29: jaws nodes, grip {grip} um: grips {nbot} and {ntop} nodes; wall nodes "
                  f"within the grip {near}, fluid particles within it {fluid}")
            T.check("29: jaws nodes: a grip deeper than the fluid-wall distance holds wall nodes only",
                    [nbot, ntop] == [int(n) for n in near] and min(fluid) > 0,
                    f"{[nbot, ntop]} against {near} (fluid within the grip: {fluid})")

    # pressed instead of pulled: in.tissue-compress -var jaws cells holds the same cells and moves
    # them together, the strain over the same gauge, both forces positive in compression
    compress = os.path.join(INPUTS, "in.tissue-compress")
    press = dict(run, vplate=4, jaws="cells", grip=2.0, leakevery=0)
    del press["vpull"], press["more"]
    rc, log = lmp(compress, d, "log.29-press", **press)
    m = re.findall(r"^grips: (\d+) nodes in the bottom grip, (\d+) in the top grip, H0 (\S+) um", log, re.M)
    T.check("29: in.tissue-compress -var jaws cells runs", rc == 0 and m, f"rc {rc}: {error_line(log)}")
    if m:
        rec = np.loadtxt(os.path.join(d, "tissue-compress.dat"), ndmin=2)
        eps, ftop, fbot = rec[-1, 2], rec[-1, 4], rec[-1, 5]
        step = rec[-1, 2] - rec[-2, 2]    # a record's travel: the last may fall short by one
        held = sorted(set(np.loadtxt(os.path.join(d, "tissue-compress-held.txt"), skiprows=9, ndmin=1)
                          .astype(int)))
        print(f"29: jaws cells pressed: H0 {m[-1][2]} um (pulled: {pulled[2]}), strain {eps:.4f}, "
              f"Ftop {ftop:.4g} nN, Fbot {fbot:.4g} nN, held cells {held}")
        T.check("29: pressed by the held cells: the same grips and gauge as the pull",
                m[-1] == pulled, f"{m[-1]} against {pulled}")
        T.check("29: pressed by the held cells: the block pushes back on both (compression > 0)",
                ftop > 0 and fbot > 0 and 0 <= run["strain"] - eps <= 1.01 * step,
                f"{ftop:.4g}, {fbot:.4g}, strain {eps:.4g} of {run['strain']} (a record: {step:.3g})")
        T.check("29: pressed by the held cells: the held cells are written for the report",
                len(held) == 2, f"{held}")
