# SPDX-License-Identifier: GPL-2.0-or-later
"""Tissue on MPI, across restarts, and its failure outputs (issue 9, section 4 and "what must be
shown"), on a column of three coarse glued cells stacked along z (cellgen.py tissue --n 1 1 3),
inflated briefly:

1. Step 0 on 1 and on 2 ranks (a 1 by 1 by 2 grid: the middle cell spans both subdomains): forces,
   density rates, every column of compute cell/props (per cell) and compute cell/contacts (per cell
   pair) agree to round-off (1e-12 of each column's largest value: only the summation order differs).
2. A run that debonds (the outer cells pulled away from the middle one, a weak lamella) written to a
   restart half-way and continued on 2 ranks matches the uninterrupted run: positions, the debond
   table of fix cell_debonded (cell pair, count, area, first and last time) and the debond log.
3. Wall rupture and lamella debonding are told apart in every output: a run that only ruptures
   (compressed between plates, strong lamella) and a run that only debonds (the pull) each count
   their events the same way in every output (fix cell_broken / cell_debonded totals, compute
   cell/props columns 13 and 16-17, compute cell/contacts columns 5-6, the VTK point fields broken and
   debonded, the debond log), and count zero of the other kind.
4. Load balancing: an L of three cells on 2 ranks, LAMMPS's even split against balance / fix balance
   (-var balance 1.1): the imbalance falls under 1.1 and the run stays the 1-rank run to round-off.
5. Bad input: clear errors naming the command and the argument.
"""
import glob
import json
import os
import re

import numpy as np
import pytest

import lmptest as T

COARSE = dict(T.COARSE)
INFLATE, SETTLE = 1500, 500   # in.tissue-inflate's steps: inflation, then the settle
CONT = """
variable        restart index three.restart
include         ${dir}/tissue-restart.lmp
"""
DUMP = ("write_dump all custom {name} id x y z vx vy vz fx fy fz d_rho d_drho mass "
        "modify sort id format float %.17g\n")
# per-cell and per-pair tables at every step they are asked for
TABLES = """
fix             tp all ave/time {every} 1 {every} c_props[*] mode vector file props{tag}.dat format " %.17g"
fix             tq all ave/time {every} 1 {every} c_pairs[*] mode vector file pairs{tag}.dat format " %.17g"
"""
# the pull: outer cells move away from the middle one at 3 m/s; the weak lamella (30 kPa,
# 2 pg/us^2 = 2 mJ/m^2) opens completely at 10 delta_c = 0.25 um, within a few hundred steps
PULL = """
group           c1 molecule 1
group           c3 molecule 3
velocity        c1 set NULL NULL -3.0 sum yes
velocity        c3 set NULL NULL 3.0 sum yes
"""
# tethers can break (lamf 1.2, so fix cell_broken counts) but the pull does not load the walls
# that far (the briefly inflated walls are near 1.04 already): the pull only debonds
WEAK = dict(sigl=30.0, Gl=2.0, lamf=1.2, Lp=1.0e-9)
DEBOND_ROWS = """
variable        nrows equal 2
print           "TABLE $(f_cell_debonded[1][1]:%.0f) $(f_cell_debonded[1][2]:%.0f) $(f_cell_debonded[1][3]:%.0f) $(f_cell_debonded[1][4]:%.17g) $(f_cell_debonded[1][5]:%.17g) $(f_cell_debonded[1][6]:%.17g)"
print           "TABLE $(f_cell_debonded[2][1]:%.0f) $(f_cell_debonded[2][2]:%.0f) $(f_cell_debonded[2][3]:%.0f) $(f_cell_debonded[2][4]:%.17g) $(f_cell_debonded[2][5]:%.17g) $(f_cell_debonded[2][6]:%.17g)"
print           "TOTALS $(f_cell_broken:%.0f) $(f_cell_debonded:%.0f)"
"""


def dump(path):
    a = np.loadtxt(path, skiprows=9, ndmin=2)
    return a[np.argsort(a[:, 0])]


def last_table(path):
    """Last block of a fix ave/time mode vector file, without the row index."""
    blocks, lines = [], [ln.split() for ln in open(path) if not ln.startswith("#")]
    i = 0
    while i < len(lines):
        step, n = int(lines[i][0]), int(lines[i][1])
        blocks.append((step, np.array([[float(v) for v in r[1:]] for r in lines[i + 1:i + 1 + n]])))
        i += n + 1
    return blocks[-1]


def vtk_fields(path, names):
    """Sums of integer point fields of a fix cell/vtk file."""
    text = open(path).read().split("\n")
    npts = int(next(ln for ln in text if ln.startswith("POINT_DATA")).split()[1])
    out = {}
    for name in names:
        k = text.index(next(ln for ln in text if ln.startswith(f"SCALARS {name} ")))
        vals = " ".join(text[k + 2:k + 2 + npts]).split()
        out[name] = np.array(vals[:npts], float)
    return out


def rel_diff(a, b, scale=None):
    """Largest difference relative to each column's largest value (or to `scale` per column)."""
    scale = np.maximum(np.abs(a).max(axis=0) if scale is None else scale, 1e-300)
    return (np.abs(a - b) / scale).max()


@pytest.fixture(scope="module")
def inflated(rundir):
    """Three coarse cells in a row, inflated part way (at Lp 10) and settled: the walls stretched,
    the lamella loaded, the cells in contact (three.restart). The run folder and the settings of
    the runs that continue it."""
    d = rundir
    # debond logs are appended to (a continued run extends its record): none left from a rerun
    for old in glob.glob(f"{d}/*.log") + glob.glob(f"{d}/*.vtk"):
        os.remove(old)
    T.cellgen("tissue", "-o", "three.data", "--lattice", "sc", "--n", 1, 1, 3, "--level", 3,
              "--nfluid", 440, cwd=d)
    special = json.load(open(os.path.join(d, "three.json")))["extra_special_per_atom"]
    common = dict(COARSE, dir=T.INPUTS, Pi=-364.0, Lp=1.0e-9, special=special)
    T.lmp(f"{T.INPUTS}/in.tissue-inflate", cwd=d,
          variables=dict(common, Lp=10.0, data="three.data", nsteps=INFLATE, nsettle=SETTLE, every=500,
                         restart_out="three.restart"),
          log="log.inflate")
    return d, common


def test_step0_rank_independent(inflated):
    d, common = inflated
    res = {}
    for n in (1, 2):
        text = ("processors 1 1 2\n" if n == 2 else "") + CONT + TABLES.format(every=1, tag=f"-{n}") + \
            "run 0\n" + DUMP.format(name=f"f0-{n}.dump")
        _, log = T.lmp(text, cwd=d, nprocs=n, variables=common, log=f"log.step0-{n}")
        res[n] = (dump(f"{d}/f0-{n}.dump"), last_table(f"{d}/props-{n}.dat")[1],
                  last_table(f"{d}/pairs-{n}.dat")[1], log)
    grid = re.search(r"(\d+) by (\d+) by (\d+) MPI processor grid", res[2][3])
    a, b = res[1], res[2]
    # the middle cell's wall nodes lie on both sides of the mid-plane that splits the 2 ranks
    zmid = 0.5 * (a[0][:, 3].min() + a[0][:, 3].max())
    zc2 = a[1][1, 11]
    print(f"2 ranks on a {'x'.join(grid.groups()) if grid else '?'} grid, mid-plane z {zmid:.2f} um, "
          f"cell 2 centre z {zc2:.2f} um")
    T.check("2-rank grid splits the column along z", grid is not None and grid.groups() == ("1", "1", "2"))
    ef = rel_diff(a[0][:, 7:10], b[0][:, 7:10])
    er = rel_diff(a[0][:, 11:12], b[0][:, 11:12])
    # the centres (columns 10-12) are round-off about 0 in x and y: their scale is the column's
    # extent in z, as for any coordinate
    scale = np.abs(a[1]).max(axis=0)
    scale[9:12] = np.abs(a[1][:, 9:12]).max()
    ep = rel_diff(a[1], b[1], scale)
    eq = rel_diff(a[2], b[2])
    print(f"step 0, 1 vs 2 ranks: forces {ef:.1e}, density rate {er:.1e}, cell/props {ep:.1e} "
          f"({a[1].shape[0]} cells), cell/contacts {eq:.1e} ({a[2].shape[0]} pairs)")
    print("cell/contacts (1 rank):", *(" ".join(f"{v:.6g}" for v in row) for row in a[2]), sep="\n  ")
    T.check("step-0 forces agree on 1 and 2 ranks (1e-12)", ef < 1e-12, f"{ef:.1e}")
    T.check("step-0 density rates agree on 1 and 2 ranks (1e-12)", er < 1e-12, f"{er:.1e}")
    T.check("cell/props: every cell, every column, 1 vs 2 ranks (1e-12)",
            a[1].shape == b[1].shape == (3, 18) and ep < 1e-12, f"{ep:.1e}")
    T.check("cell/contacts: pairs 1-2 and 2-3 glued and in contact, 1 vs 2 ranks (1e-12)",
            a[2].shape == b[2].shape and a[2].shape[0] == 2 and np.all(a[2][:, 2] > 0) and eq < 1e-12,
            f"{eq:.1e}")


def parse_rows(log):
    rows = [list(map(float, m.split())) for m in re.findall(r"^TABLE (.*)$", log, re.M)]
    tot = [list(map(float, m.split())) for m in re.findall(r"^TOTALS (.*)$", log, re.M)][-1]
    return np.array(rows), tot


def test_restart_continues_run(inflated):
    d, common = inflated
    pull = dict(common, **WEAK)
    full = CONT + PULL + "timestep 0.001\nrun 150\nwrite_restart half.restart\nrun 150\n" + \
        DUMP.format(name="full.dump") + DEBOND_ROWS
    _, logf = T.lmp(full, cwd=d, nprocs=2, variables=dict(pull, lamlog="full.log"), log="log.full")
    # the continued run appends to a copy of the first half's debond log
    split = INFLATE + SETTLE + 150   # the inflation's steps, then the first half
    half = [ln for ln in open(f"{d}/full.log") if ln.startswith("#") or int(ln.split()[0]) <= split]
    with open(f"{d}/cont.log", "w") as f:
        f.writelines(half)
    cont = CONT + "timestep 0.001\nrun 150\n" + DUMP.format(name="cont.dump") + DEBOND_ROWS
    _, logc = T.lmp(cont, cwd=d, nprocs=2, variables=dict(pull, restart="half.restart", lamlog="cont.log"),
                    log="log.cont")
    a, b = dump(f"{d}/full.dump"), dump(f"{d}/cont.dump")
    ta, tota = parse_rows(logf)
    tb, totb = parse_rows(logc)
    events = [ln.split() for ln in open(f"{d}/full.log") if not ln.startswith("#")]
    before = sum(1 for e in events if int(e[0]) <= split)
    print(f"pull: {len(events)} debonds ({before} before the restart), table rows (cell i, cell j, count, "
          f"area, t_first, t_last):", *(" ".join(f"{v:.8g}" for v in r) for r in ta[-2:]), sep="\n  ")
    dx = np.abs(a[:, 1:4] - b[:, 1:4]).max()
    dt = rel_diff(ta[-2:], tb[-2:])
    print(f"restart on 2 ranks: max position diff {dx:.1e} um, debond table diff {dt:.1e}")
    T.check("the pull debonds on both sides of the restart", before > 0 and len(events) > before,
            f"{before} + {len(events) - before}")
    T.check("restart continues the tissue run (positions, 1e-10 um)", dx < 1e-10, f"{dx:.1e}")
    T.check("restart continues the debond table (1e-12)", dt < 1e-12 and tota == totb, f"{dt:.1e}")
    T.check("restart continues the debond log (same events)",
            open(f"{d}/full.log").read() == open(f"{d}/cont.log").read())


def test_failures_counted_alike(inflated):
    d, common = inflated
    """Each kind of failure counted alike by every output, the other kind zero."""
    runs = {}
    # rupture: the column struck and pressed 8% at 4 m/s (the top plate at full speed from the
    # start, as an impact: in.tissue-compress's quasi-static start would not break it so soon),
    # strong lamella, tethers break at stretch 1.04
    out = dict(common, restart="three.restart", lamf=1.04, vplate=4.0, strain=0.08, every=50,
               plates="top", ramp=0, rest=0, tabevery=100, leakevery=0, vtk=100, lamlog="rupture.log",
               out="rupture.dat", cells="rupture-cells.dat", pairs="rupture-pairs.dat")
    T.lmp(f"{T.INPUTS}/in.tissue-compress", cwd=d, variables=out, log="log.rupture")
    runs["rupture"] = ("rupture-cells.dat", "rupture-pairs.dat", "rupture.log", "rupture.dat")
    # debond: the pull on 2 ranks, tables and VTK every 100 steps
    pull = CONT + PULL + TABLES.format(every=100, tag="-debond") + \
        "fix vtk wall cell/vtk 100 debond\ntimestep 0.001\nrun 300\n"
    T.lmp(pull, cwd=d, nprocs=2, variables=dict(common, **WEAK, lamlog="debond.log"), log="log.debond")
    runs["debond"] = ("props-debond.dat", "pairs-debond.dat", "debond.log", None)
    for kind, (cells, pairs, log, scal) in runs.items():
        step, props = last_table(f"{d}/{cells}")
        step2, pp = last_table(f"{d}/{pairs}")
        vtk = sorted(glob.glob(f"{d}/{'walls' if kind == 'rupture' else 'debond'}.{step}.vtk"))
        events = [ln.split() for ln in open(f"{d}/{log}") if not ln.startswith("#")]
        events = [e for e in events if int(e[0]) <= step]
        f = vtk_fields(vtk[0], ("broken", "debonded")) if vtk else None
        counts = {
            "cell/props col 13 (broken tethers)": props[:, 12].sum(),
            "VTK broken / 2": f["broken"].sum() / 2 if f else -1,
            "cell/props col 16 / 2 (debonded bonds)": props[:, 15].sum() / 2,
            "cell/contacts col 5 (debonded bonds)": pp[:, 4].sum() if len(pp) else 0.0,
            "VTK debonded / 2": f["debonded"].sum() / 2 if f else -1,
            "debond log lines": float(len(events)),
        }
        area = (props[:, 16].sum() / 2, pp[:, 5].sum() if len(pp) else 0.0,
                sum(float(e[6]) for e in events))
        if scal:
            a = T.load(f"{d}/{scal}")
            row = a[np.nonzero(a[:, 0] == step)[0][0]]
            counts["variable broken (f_cell_broken)"] = row[10]
            counts["variable debonded"] = row[11]
        print(f"{kind} run, step {step} (pairs table step {step2}):",
              *(f"{k}: {v:g}" for k, v in counts.items()),
              f"debonded area: cell/props {area[0]:.8g}, cell/contacts {area[1]:.8g}, log {area[2]:.8g} um^2",
              sep="\n  ")
        broken = [v for k, v in counts.items() if "broken" in k]
        debond = [v for k, v in counts.items() if "broken" not in k]
        T.check(f"{kind}: a VTK frame at the tables' step", f is not None and step == step2)
        if kind == "rupture":
            T.check("rupture: every output counts the same broken tethers (> 0)",
                    broken[0] > 0 and all(v == broken[0] for v in broken), str(broken))
            T.check("rupture: no output counts a debond", all(v == 0 for v in debond), str(debond))
        else:
            T.check("debond: every output counts the same debonded bonds (> 0)",
                    debond[0] > 0 and all(v == debond[0] for v in debond), str(debond))
            T.check("debond: no output counts a broken tether", all(v == 0 for v in broken), str(broken))
            T.check("debond: debonded area the same in cell/props, cell/contacts and the log (1e-9)",
                    area[0] > 0 and abs(area[1] - area[0]) < 1e-9 * area[0] and
                    abs(area[2] - area[0]) < 1e-6 * area[0], f"{area[0]:.8g}")


def test_load_balance(inflated):
    d, common = inflated
    """Load balancing (tissue-model.lmp's -var balance): three cells in an L (a 2 x 1 x 2 block less
    one corner) on 2 ranks split along x. LAMMPS's even split gives one rank two cells and the other
    one; balance and fix balance (shift xyz) move the cut so that both hold the same within 10%,
    and the run is the one rank's run but for the order of the sums."""
    T.cellgen("tissue", "-o", "ell.data", "--lattice", "sc", "--n", 2, 1, 2, "--level", 3, "--nfluid", 440,
              "--remove-box", 1, 1e9, -1, 1e9, 1, 1e9, cwd=d)
    special = json.load(open(os.path.join(d, "ell.json")))["extra_special_per_atom"]
    res = {}
    for tag, n, bal in (("one", 1, 0), ("even", 2, 0), ("balanced", 2, 1.1)):
        text = ("processors 2 1 1\n" if n == 2 else "") + f"include {T.INPUTS}/in.tissue-inflate\n" + \
            DUMP.format(name=f"ell-{tag}.dump")
        _, log = T.lmp(text, cwd=d, nprocs=n, log=f"log.ell-{tag}",
                       variables=dict(common, Lp=10.0, special=special, data="ell.data", nsteps=300,
                                      nsettle=100, every=100, balance=bal, restart_out="ell.restart",
                                      out=f"ell-{tag}.dat", cells=f"ell-{tag}-cells.dat"))
        nl = [tuple(map(float, m)) for m in
              re.findall(r"^Nlocal:\s*([\d.eE+-]+) ave\s+([\d.eE+-]+) max\s+([\d.eE+-]+) min", log, re.M)]
        res[tag] = (dump(f"{d}/ell-{tag}.dump"), nl[-1][1] / nl[-1][0], "Balancing ..." in log)
    a, b, c = res["one"][0], res["even"][0], res["balanced"][0]
    dx_even = np.abs(a[:, 1:4] - b[:, 1:4]).max()
    dx_bal = np.abs(a[:, 1:4] - c[:, 1:4]).max()
    print(f"L of 3 cells on 2 ranks: most particles on a rank / mean {res['even'][1]:.3f} with the even split, "
          f"{res['balanced'][1]:.3f} balanced; positions after 400 steps against 1 rank: {dx_even:.1e} um "
          f"(even split), {dx_bal:.1e} um (balanced)")
    T.check("the even split loads one rank with two cells of three (imbalance > 1.25)", res["even"][1] > 1.25,
            f"{res['even'][1]:.3f}")
    T.check("-var balance 1.1 runs balance and brings the imbalance under 1.1",
            res["balanced"][2] and res["balanced"][1] < 1.1 and not res["even"][2], f"{res['balanced'][1]:.3f}")
    # only the order of the sums differs: round-off, grown over 400 steps (the restart check above
    # allows 1e-10 um for the same decomposition; 1e-11 um is 1e-13 of the block)
    T.check("balanced 2-rank run = 1-rank run (positions, 1e-11 um)", dx_bal < 1e-11 and dx_even < 1e-11,
            f"{dx_bal:.1e}")


def test_bad_inputs_refused(inflated):
    d, common = inflated
    cases = [
        (CONT + "compute c all cell/contacts 2.0\nrun 0\n", common,
         r"Illegal compute cell/contacts command: expected no arguments after the style, got 1"),
        # the per-atom fields without ghost values: the lamella's rest lengths and areas at the
        # subdomain boundary would be garbage
        ("""units micro
atom_style molecular
boundary m m m
fix cell all property/atom rmass d_rho d_drho d2_cellref 3 d_alam
read_data three.data fix cell NULL cell extra/special/per/atom ${special}
include ${dir}/tissue-model.lmp
run 0
""", common, r"requires .* communicated to ghosts"),
        # a balance threshold below 1 (or negative) is not a threshold
        (CONT + "run 0\n", dict(common, balance=0.5),
         r"ERROR: tissue-model.lmp: -var balance 0.5: expected 0 \(even split\) or a threshold >= 1"),
        (CONT + "run 0\n", dict(common, balance=-1),
         r"ERROR: tissue-model.lmp: -var balance -1: expected 0 \(even split\) or a threshold >= 1"),
        (CONT + "run 0\n", dict(common, balance="yes"), r"ERROR: Variable balance: Non-numeric"),
    ]
    for k, (text, variables, pattern) in enumerate(cases):
        rc, log = T.lmp(text, cwd=d, variables=variables, check=False, log=f"log.bad{k}")
        err = re.search(r"ERROR.*", log)
        T.check(f"bad input {k + 1}: clear error", rc != 0 and err is not None and
                re.search(pattern, log) is not None, err.group(0)[:160] if err else "no error")
