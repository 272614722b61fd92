# SPDX-License-Identifier: GPL-2.0-or-later
"""Defects found by probing (issue 13, section 5) that need a run to show: each check below failed
before its fix.

- 5.6 a cell that burst during osmosis kept taking up water through what was left of its wall
  (fluid mass x2.2 after the burst): osmosis stops once a cell's wall is open.
- 5.7 a blow-up (time step 20x too large) ended in "increase reach in pair_style cell/virtual" on 1
  rank and LAMMPS's "Bond atoms missing" on 2: it must name the likely cause with the numbers.
- 5.8 per-cell arrays were sized by the largest molecule ID: one cell with molecule ID 1e8 asked
  for about 10 GB. Now the same cell with molecule ID 1 and 1e8 gives the same outputs, runs in
  a 3 GB address space, on 1 and 2 ranks and through a restart.
- 5.10 docs against the code: fix cell/fluid takes Pi and Lp in either order, as documented (the
  code required Pi first); the write_data / read_data round trip as bond_cell_tether.rst shows it.
- 5.11 extreme parseable coefficients ran to NaN with exit 0; a huge 'normal' overflowed to a zero
  normal; fix cell/vtk on a group without wall nodes wrote empty files; a wall without triangles
  reported volume 0.
"""
import os
import re
import resource
import subprocess

import numpy as np
import pytest

import lmptest as T
from cellmech import params

COARSE = dict(T.COARSE, dir=T.INPUTS, data="cell.data")
HEAD = T.cell_from_data("${data}")
MODEL = "include ${dir}/cell-model.lmp\nfix integrate all nve\n"
OSMOSIS = "fix osmosis fluid cell/fluid Pi -364.0 Lp 100.0\n"


def run(text, d, log, nprocs=1, limit_gb=None, timeout=300, screen=False):
    """lmp on text; with limit_gb under that address-space limit. Returns (rc, log + screen)."""
    path = os.path.join(d, f"in.{log}")
    with open(path, "w") as f:
        f.write(text)
    cmd = [T.LMP, "-in", path, "-log", log] + ([] if screen else ["-screen", "none"])
    for k, v in COARSE.items():
        cmd += ["-var", k, str(v)]
    cmd = T.mpi_command(cmd, nprocs, T.MPIEXEC)
    env = dict(os.environ, LAMMPS_PLUGIN_PATH=os.path.dirname(T.PLUGIN))

    def limit():
        if limit_gb:
            resource.setrlimit(resource.RLIMIT_AS, (limit_gb << 30, limit_gb << 30))
    try:
        p = subprocess.run(cmd, cwd=d, env=env, capture_output=True, text=True, timeout=timeout,
                           preexec_fn=limit)
        rc, out = p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired:
        rc, out = None, f"still running after {timeout} s"
    logpath = os.path.join(d, log)
    text = open(logpath).read() if os.path.exists(logpath) else ""
    return rc, text + out


def error_line(text):
    m = re.search(r"ERROR.*", text)
    return m.group(0)[:300] if m else "no error"


@pytest.fixture(scope="module")
def cell(rundir):
    T.cellgen("cell", "-o", "cell.data", "--level", 3, "--nfluid", params.LEVELS[3]["nfluid"],
              "--inset", COARSE["r0"], cwd=rundir)
    return rundir


def test_burst_stops_osmosis(cell):
    d = cell
    """5.6: tethers break at 1.005 while osmosis inflates the cell (Lp 100)."""
    # shrink-wrapped: the fluid that escapes stays in the box
    text = ("variable lamf index 1.005\n" + HEAD + "change_box all boundary m m m\n" + MODEL +
            OSMOSIS + """
compute         props all cell/props leaks no
variable        nb equal c_props[1][13]
variable        M equal c_props[1][4]
variable        dM equal f_osmosis[1]
fix             out all print 200 "$(step) ${nb} $(v_M:%.17g) $(v_dM:%.17g)" file burst.dat screen no
timestep        0.001
run             6000
""")
    rc, log = run(text, d, "log.burst")
    T.check("5.6 burst during osmosis runs", rc == 0, f"rc {rc}: {error_line(log)}")
    if rc != 0:
        return
    rows = np.loadtxt(f"{d}/burst.dat", comments="#", ndmin=2)    # step broken M dM
    opened = np.nonzero(rows[:, 1] > 0)[0]
    T.check("5.6 the wall opens (tethers break at lamf 1.005)", len(opened) > 0)
    if not len(opened):
        return
    k = opened[0]
    print(f"5.6 fluid mass {rows[0, 2]:.1f} pg at the start, {rows[k, 2]:.1f} pg when the wall "
          f"opened (step {rows[k, 0]:.0f}, {rows[k, 1]:.0f} broken tethers), {rows[-1, 2]:.1f} pg "
          f"at step {rows[-1, 0]:.0f} ({rows[-1, 1]:.0f} broken); uptake f_osmosis "
          f"{rows[k, 3]:.1f} -> {rows[-1, 3]:.1f} pg")
    T.check("5.6 osmosis acted before the burst (mass grew)", rows[k, 2] > 1.01 * rows[0, 2])
    T.check("5.6 no uptake once the wall is open (mass and f_osmosis constant)",
            rows[-1, 2] == rows[k, 2] and rows[-1, 3] == rows[k, 3],
            f"{rows[-1, 2] - rows[k, 2]:.3g} pg, {rows[-1, 3] - rows[k, 3]:.3g} pg")


def test_blow_up_named(cell):
    d = cell
    """5.7: a time step 20 times the inputs' 0.001 us blows the cell up within a few steps."""
    text = HEAD + MODEL + OSMOSIS + "timestep 0.02\nthermo 1\nrun 200\n"
    for n in (1, 2):
        # error->one of the rank that sees it reaches that rank's screen only
        rc, out = run(text, d, f"log.blowup{n}", nprocs=n, screen=True)
        err = error_line(out)
        print(f"5.7 time step 0.02 on {n} rank(s): rc {rc}: {err}")
        T.check(f"5.7 blow-up on {n} rank(s) names the time step with the numbers",
                rc not in (0, None) and re.search(r"moved [0-9.e+-]+ .*in one step.*time step "
                                                  r"0\.02.*skin", err) is not None, err[:120])
    # a run gone NaN (here by hand: inf - inf in every velocity) stops at once with the cause
    text = (HEAD + MODEL + OSMOSIS + 'variable bad atom "(1e200*1e200)-(1e200*1e200)"\n'
            "set group all vx v_bad\ntimestep 0.001\nthermo 1\nrun 100\n")
    rc, out = run(text, d, "log.nan", screen=True)
    err = error_line(out)
    print(f"5.11 velocities NaN: rc {rc}: {err}")
    T.check("5.11 a run gone NaN stops with the cause, not exit 0", rc not in (0, None) and
            re.search(r"velocity that is not finite \(-?nan\).*NaN", err) is not None, err[:120])


def test_sparse_molecule_ids(cell):
    d = cell
    """5.8: the same cell as molecule 1 and as molecule 100000000."""
    body = MODEL + OSMOSIS + """
compute         props all cell/props leaks yes
fix             rows all ave/time 50 1 50 c_props[*] mode vector file props.TAG.dat format " %.15g"
variable        dM equal f_osmosis[1]
timestep        0.001
run             100
print           "UPTAKE $(v_dM:%.17g)"
"""
    dumps = {}
    for mol, n in ((1, 1), (100000000, 1), (1, 2), (100000000, 2)):
        tag = f"{mol}.{n}"
        text = (HEAD + f"set group all mol {mol}\n" + body.replace("TAG", tag) +
                "write_restart sparse.restart\n" +
                f"write_dump all custom sparse.{tag}.dump id mol x y z vx vy vz mass d_rho "
                "modify sort id format float %.17g\n")
        rc, log = run(text, d, f"log.sparse{tag}", nprocs=n, limit_gb=3, timeout=120)
        T.check(f"5.8 one cell with molecule ID {mol} on {n} rank(s) runs in 3 GB", rc == 0,
                f"rc {rc}: {error_line(log)}")
        if rc != 0:
            continue
        # fix ave/time mode vector: a line "step nrows", then "row c1 c2 ..." for each cell
        lines = [w.split() for w in open(f"{d}/props.{tag}.dat") if not w.startswith("#")]
        a = np.array([[float(v) for v in w] for w in lines if len(w) > 2])
        uptake = float(log.split("UPTAKE ")[-1].split()[0])
        dumps[tag] = (np.loadtxt(f"{d}/sparse.{tag}.dump", skiprows=9), a, uptake)
        print(f"5.8 molecule {mol}, {n} rank(s): {len(a)} rows written, volume "
              f"{a[-1, 1]:.6g}, mass {a[-1, 4]:.9g}, uptake {uptake:.9g}")
    if len(dumps) == 4:
        for n in (1, 2):
            # the same decomposition: the same sums in the same order
            ref, tag = dumps[f"1.{n}"], f"100000000.{n}"
            dump, a, uptake = dumps[tag]
            same_atoms = np.array_equal(np.delete(ref[0], 1, axis=1), np.delete(dump, 1, axis=1))
            rows_ok = a.shape == ref[1].shape
            dprops = np.abs(a[:, 1:-1] - ref[1][:, 1:-1]).max() if rows_ok else np.inf
            scale = np.abs(ref[1][:, 1:-1]).max()
            print(f"5.8 {n} rank(s), molecule 1e8 against molecule 1: atoms identical "
                  f"{same_atoms}, props max diff {dprops:.3g} (of values up to {scale:.3g}), "
                  f"uptake {uptake:.12g} vs {ref[2]:.12g}")
            T.check(f"5.8 {tag}: same atoms, same per-cell rows, same uptake as molecule 1",
                    same_atoms and rows_ok and dprops == 0 and uptake == ref[2])
            T.check(f"5.8 {tag}: the row names the molecule ID (last column)",
                    rows_ok and np.all(a[:, -1] == 100000000), f"{a[-1, -1]:.0f}")
        # the uptake per cell survives a restart (stored by molecule ID)
        text = (T.continue_cell("sparse.restart") + OSMOSIS +
                'variable dM equal f_osmosis[1]\nrun 0\nprint "UPTAKE $(v_dM:%.17g)"\n')
        rc, log = run(text, d, "log.sparse-restart", nprocs=2, limit_gb=3, timeout=120)
        up = float(log.split("UPTAKE ")[-1].split()[0]) if rc == 0 else float("nan")
        T.check("5.8 molecule 1e8: the uptake comes back from the restart", rc == 0 and
                abs(up - dumps["100000000.2"][2]) <= 1e-12 * abs(up),
                f"rc {rc}: {up:.12g} vs {dumps['100000000.2'][2]:.12g} {error_line(log)[:100]}")


def test_docs_match_code(cell):
    d = cell
    """5.10: what the docs say runs."""
    text = HEAD + MODEL + "fix osmosis fluid cell/fluid Lp 1.0e-9 Pi -364.0\ntimestep 0.001\nrun 5\n"
    rc, log = run(text, d, "log.order")
    T.check("5.10 fix cell/fluid Lp before Pi (either order, as documented)", rc == 0,
            f"rc {rc}: {error_line(log)}")
    text = HEAD + MODEL + "fix osmosis fluid cell/fluid Pi -364.0 Pi -100.0\nrun 0\n"
    rc, log = run(text, d, "log.twice")
    T.check("5.10 fix cell/fluid with Pi given twice: an error", rc not in (0, None) and
            re.search(r"fix cell/fluid.*'Pi' given twice", log) is not None, error_line(log))

    # the round trip exactly as docs/bond_cell_tether.rst writes it
    doc = open(os.path.join(T.ROOT, "docs", "bond_cell_tether.rst")).read()
    # lines of its code blocks (indented, a data file name after the command)
    wd = re.search(r"^ +(write_data\s+\S+\.data\b.*)$", doc, flags=re.M)
    rd = re.search(r"^ +(read_data\s+\S+\.data\b.*)$", doc, flags=re.M)
    T.check("5.10 bond_cell_tether.rst shows the write_data and read_data commands",
            wd is not None and rd is not None)
    if wd is None or rd is None:
        return
    wcmd, rcmd = wd.group(1).split("#")[0].strip(), rd.group(1).split("#")[0].strip()
    wfile, rfile = wcmd.split()[1], rcmd.split()[1]
    dump = ("write_dump all custom {} id x y z vx vy vz mass d_rho "
            "modify sort id format float %.17g\n")
    first = HEAD + MODEL + OSMOSIS + "timestep 0.001\nrun 20\n" + wcmd + "\nrun 20\n" + \
        dump.format("straight.dump")
    rc, log = run(first, d, "log.wd")
    T.check(f"5.10 '{wcmd}' after a run", rc == 0, f"rc {rc}: {error_line(log)}")
    second = (HEAD.replace("read_data       ${data} fix cell NULL cell extra/special/per/atom 6",
                           rcmd.replace(rfile, wfile)) + MODEL + OSMOSIS +
              "timestep 0.001\nrun 20\n" + dump.format("roundtrip.dump"))
    rc, log = run(second, d, "log.rd")
    T.check(f"5.10 '{rcmd}' reads it back and runs", rc == 0, f"rc {rc}: {error_line(log)}")
    if rc == 0:
        a = np.loadtxt(f"{d}/straight.dump", skiprows=9)
        b = np.loadtxt(f"{d}/roundtrip.dump", skiprows=9)
        dx = np.abs(a[:, 1:4] - b[:, 1:4]).max()
        print(f"5.10 round trip: 20 steps after the data file vs straight on: max position "
              f"difference {dx:.2e} um")
        T.check("5.10 the run continued from the data file follows the straight run (1e-9 um)",
                dx < 1e-9, f"{dx:.2e}")


def test_extreme_values_refused(cell):
    d = cell
    """5.11: parseable values outside any meaningful range stop with an error."""
    sph = "pair_coeff 2 2 cell/sph {} {} 0.0 1.0 " + str(COARSE["s"]) + "\n"
    cases = [
        ("rho0 1e-300", MODEL + sph.format("1e-300", 264.6) + OSMOSIS,
         r"pair_coeff cell/sph: reference density rho0 .*1e-300"),
        ("c 1e200", MODEL + sph.format(1.0, "1e200") + OSMOSIS,
         r"pair_coeff cell/sph: sound speed c .*1e\+200"),
        ("Pi -1e300", MODEL + "fix osmosis fluid cell/fluid Pi -1e300 Lp 100.0\n",
         r"fix cell/fluid: osmotic potential Pi .*-1e\+300"),
        ("fix cell/vtk on the fluid (no wall nodes)",
         MODEL + OSMOSIS + "fix surf fluid cell/vtk 10 walls\n",
         r"[Ff]ix cell/vtk.*group fluid.*no wall"),
        ("compute cell/props on a wall without triangles",
         # Lp 0: fix cell/fluid, which needs the triangles for osmosis, does not stop it first
         MODEL + "fix osmosis fluid cell/fluid Pi 0 Lp 0\ndelete_bonds all angle 1 remove\n"
         "compute props all cell/props\n"
         "thermo_style custom step c_props[1][1]\n",
         r"[Cc]ompute cell/props.*no triangles|[Cc]ompute cell/props.*without triangles"),
    ]
    for name, body, pattern in cases:
        rc, log = run(HEAD + body + "timestep 0.001\nrun 10\n", d, "log.extreme")
        T.check(f"5.11 {name}: a clear error", rc not in (0, None) and
                re.search(pattern, log) is not None, f"rc {rc}: {error_line(log)[:160]}")

    # a huge normal is the same direction as a small one
    feq = {}
    for normal in ("1 1 0", "1e200 1e200 0"):
        text = (HEAD + MODEL + OSMOSIS + f"compute props all cell/props normal {normal} leaks no\n"
                "timestep 0.001\nrun 10\nprint \"FEQ $(c_props[1][8]:%.17g)\"\n")
        rc, log = run(text, d, "log.normal")
        feq[normal] = float(log.split("FEQ ")[-1].split()[0]) if rc == 0 else None
    print(f"5.11 equatorial force with normal 1 1 0: {feq['1 1 0']}, 1e200 1e200 0: "
          f"{feq['1e200 1e200 0']}")
    T.check("5.11 normal 1e200 1e200 0 gives the force of normal 1 1 0",
            feq["1 1 0"] is not None and feq["1 1 0"] != 0 and feq["1e200 1e200 0"] == feq["1 1 0"])
