# SPDX-License-Identifier: GPL-2.0-or-later
"""compute cell/shear/atom and compute cell/contacts in a tissue (issue 28, items 3, 10 and 11), on a
column of three coarse glued cells stacked along z (cellgen.py tissue --n 1 1 3), inflated briefly
as in tests/test_tissue.py, then at rest but for the middle cell, which slides along x at 1 m/s:

1. A rigid motion has no shear, and no cell's protoplasm sees another's (pair cell/sph's rule): at
   the first step every particle's shear is 0 exactly, in the cells at rest and in the moving one,
   on 1 and 2 ranks. The check is only worth something where the fluid of two cells comes within
   the kernel support 2s across their glued walls; that is asserted too. Before the fix the compute
   summed over the fluid of the neighbouring cell as well: shear up to 0.059 kPa in cells 1 and 3
   (the fluid of two cells 5.8 um apart), 0.093 kPa in cell 2.
2. After 100 steps of the slide (the lamella and the fluid of cells 1 and 3 follow) the shear of
   every particle on 1 and on 2 ranks (a 2 by 1 by 1 grid, every cell spans both subdomains) agrees
   to round-off, 1e-9 of the largest. Before the fix the ghosts' velocities were half a step older
   than the owners' at output: 3.2e-3 of the largest shear, 76 of 1271 particles off by over 1%.
3. compute cell/contacts counts only atoms of its group, on 1 and 2 ranks: with the cells 1 and 2
   its one row is the pair (1, 2), the same as with all; with cell 1 alone it has none; with the
   atoms on one side of a plane x = XCUT its lamella bonds and glued area are those of the bonds
   with both atoms on that side. After a pull that debonds part of the (weak) lamella, the debonded
   bonds of a pair count only when both cells are in the group. Before the fix the group changed
   only part of the contact area: every lamella bond and debond counted whatever the group.
"""
import json
import os

import numpy as np
import pytest

import lmptest as T

COARSE = dict(T.COARSE)
INFLATE, SETTLE = 1500, 500   # in.tissue-inflate's steps: inflation, then the settle
SLIDE = 100
XCUT = 1.234                  # the plane of the half group: no atom lies on it
CONT = """
variable        restart index three.restart
include         ${dir}/tissue-restart.lmp
group           c1 molecule 1
group           c2 molecule 2
group           c3 molecule 3
group           c12 molecule 1 2
compute         p12 c12 cell/contacts
compute         p1 c1 cell/contacts
timestep        0.001
"""
# the per-pair tables of compute cell/contacts (all: tissue-model.lmp's c_pairs) at one step
TABLES = "".join(f"fix t{c} all ave/time 1 1 1 c_{c}[*] mode vector file {c}.{{tag}}.dat "
                 f"format \" %.17g\"\n" for c in ("pairs", "p12", "p1", "{more}"))
DUMP = "modify sort id format float %.17g\n"
SLIDE_IN = CONT + f"""
region          lo block INF {XCUT} INF INF INF INF
group           lo region lo
compute         plo lo cell/contacts
compute         bonds all property/local batom1 batom2 btype
compute         shear fluid cell/shear/atom
velocity        all set 0.0 0.0 0.0 units box
velocity        c2 set 1.0 0.0 0.0 units box
""" + TABLES.replace("{more}", "plo") + f"""run             0
unfix           tpairs
unfix           tp12
unfix           tp1
unfix           tplo
write_dump      fluid custom rigid.{{tag}}.dump id mol c_shear[*] {DUMP}
write_dump      all custom atoms.{{tag}}.dump id mol type x y z d_alam {DUMP}
write_dump      all local bonds.{{tag}}.dump c_bonds[*]
run             {SLIDE}
write_dump      fluid custom slide.{{tag}}.dump id mol x y z c_shear[*] {DUMP}
"""
# cells 1 and 3 pulled away from cell 2 at 3 m/s (test_tissue.py); the weak lamella (30 kPa,
# 2 pg/us^2) opens at once where the inflation has stretched it and more within 100 steps
PULL_IN = CONT + """
velocity        c1 set NULL NULL -3.0 sum yes units box
velocity        c3 set NULL NULL 3.0 sum yes units box
run             100
compute         p3 c3 cell/contacts
""" + TABLES.replace("{more}", "p3") + "run 0\n"
WEAK = dict(sigl=30.0, Gl=2.0, lamf=1.2)
COLS = ("cell i", "cell j", "bonds", "glued area", "debonded", "debonded area", "lamella force",
        "contact force", "contacts", "contact area", "distance")


def table(path):
    """The last block of a fix ave/time mode vector file: {(i, j): 11 columns}."""
    lines = [l.split() for l in open(path) if not l.startswith("#")]
    k = max(n for n, l in enumerate(lines) if len(l) == 2)
    nrows = int(lines[k][1])
    rows = [np.array(list(map(float, l[1:]))) for l in lines[k + 1:k + 1 + nrows]]
    return {(int(r[0]), int(r[1])): r for r in rows}


def dump(path):
    return np.loadtxt(path, skiprows=9, ndmin=2)


def same_rows(a, b, tol=1e-12):
    """Tables with the same pairs and every column within tol of the column's largest value."""
    if a.keys() != b.keys():
        return False
    for k in a:
        scale = np.maximum(np.maximum(abs(a[k]), abs(b[k])), 1e-300)
        if np.any(abs(a[k] - b[k]) > tol * scale):
            return False
    return True


@pytest.fixture(scope="module")
def inflated(rundir):
    """The column of three cells inflated part way (at Lp 10) and settled (three.restart): the run
    folder and the settings of the runs that continue it."""
    d = rundir
    # debond logs are appended to: none left from a rerun
    if os.path.exists(f"{d}/debond.log"):
        os.remove(f"{d}/debond.log")
    T.cellgen("tissue", "-o", "three.data", "--lattice", "sc", "--n", 1, 1, 3, "--level", 3,
              "--nfluid", 440, cwd=d)
    special = json.load(open(os.path.join(d, "three.json")))["extra_special_per_atom"]
    common = dict(COARSE, dir=T.INPUTS, Pi=-364.0, Lp=1.0e-9, special=special)
    # inflated part way (at Lp 10) and settled: the fluid reaches out to its walls, the cells press
    # on each other
    T.lmp(f"{T.INPUTS}/in.tissue-inflate", cwd=d,
          variables=dict(common, Lp=10.0, data="three.data", nsteps=INFLATE, nsettle=SETTLE,
                         every=500, restart_out="three.restart"),
          log="log.inflate")
    return d, common


@pytest.fixture(scope="module")
def slid(inflated):
    """The middle cell's slide on 1 and 2 ranks (a 2 by 1 by 1 grid)."""
    d, common = inflated
    for n in (1, 2):
        text = ("processors 2 1 1\n" if n == 2 else "") + SLIDE_IN.replace("{tag}", str(n))
        T.lmp(text, cwd=d, nprocs=n, variables=common, log=f"log.slide{n}")
    return d


def test_rigid_motion_has_no_shear(slid):
    d = slid
    # 1. rigid motion: zero shear everywhere, exactly
    atoms = dump(f"{d}/atoms.1.dump")    # id mol type x y z alam
    fluid = atoms[atoms[:, 2] == 2]
    f1, f2 = fluid[fluid[:, 1] == 1, 3:6], fluid[fluid[:, 1] == 2, 3:6]
    gap = np.sqrt(((f1[:, None, :] - f2[None, :, :]) ** 2).sum(axis=2)).min()
    support = 2.0 * COARSE["s"]
    print(f"closest fluid of cells 1 and 2: {gap:.3f} um apart (kernel support 2s = {support} um)")
    T.check("the fluid of two glued cells comes within the kernel support (the check can fail)",
            gap < support, f"{gap:.3f} um")
    for n in (1, 2):
        r = dump(f"{d}/rigid.{n}.dump")    # id mol tau txy txz tyz
        per_cell = {m: abs(r[r[:, 1] == m, 2:]).max() for m in (1, 2, 3)}
        print(f"{n} rank(s), step 0, cell 2 at 1 m/s: max |tau| per cell " +
              ", ".join(f"{m}: {v:.3g}" for m, v in per_cell.items()) + " kPa; nonzero on "
              f"{int((r[:, 2] != 0).sum())} of {len(r)} particles")
        T.check(f"rigid motion: every particle's shear is 0 ({n} rank(s))",
                max(per_cell.values()) == 0.0, f"max {max(per_cell.values()):.3g} kPa")


def test_slide_shear_rank_independent(slid):
    d = slid
    # 2. the slide on 1 and 2 ranks
    a, b = dump(f"{d}/slide.1.dump"), dump(f"{d}/slide.2.dump")    # id mol x y z tau txy txz tyz
    dx = abs(a[:, 2:5] - b[:, 2:5]).max()
    tmax = abs(a[:, 5]).max()
    dtau = abs(a[:, 5:] - b[:, 5:]).max()
    off = int((abs(a[:, 5] - b[:, 5]) > 0.01 * abs(a[:, 5])).sum())
    print(f"after {SLIDE} steps: positions 1 vs 2 ranks {dx:.1e} um; max |tau| {tmax:.4g} kPa "
          f"(cells 1, 3: {abs(a[a[:, 1] != 2, 5]).max():.4g}); 1 vs 2 ranks max |dtau| {dtau:.2e} "
          f"kPa ({dtau / tmax:.1e} of the largest), {off} of {len(a)} particles differ by over 1%")
    T.check("the slide: 1 and 2 ranks at the same positions (1e-10 um)", dx < 1e-10, f"{dx:.1e}")
    T.check("the slide shears the fluid (max |tau| > 0.01 kPa)", tmax > 0.01, f"{tmax:.3g}")
    T.check("the slide: every particle's shear the same on 1 and 2 ranks (1e-9 of the largest)",
            dtau <= 1e-9 * tmax, f"{dtau / tmax:.1e}")


def test_contacts_count_group_atoms(slid):
    d = slid
    # 3. compute cell/contacts with a group, at step 0
    tabs = {n: {c: table(f"{d}/{c}.{n}.dat") for c in ("pairs", "p12", "p1", "plo")}
            for n in (1, 2)}
    t = tabs[1]
    for c in ("pairs", "p12", "p1", "plo"):
        print(f"cell/contacts {c}:", *(" ".join(f"{v:.6g}" for v in r) for r in t[c].values()),
              sep="\n  ")
    T.check("cell/contacts all: pairs (1, 2) and (2, 3)", set(t["pairs"]) == {(1, 2), (2, 3)},
            str(sorted(t["pairs"])))
    T.check("cell/contacts on cells 1 and 2: the row (1, 2) alone, the same as with all",
            set(t["p12"]) == {(1, 2)} and (1, 2) in t["pairs"] and
            same_rows({(1, 2): t["p12"][(1, 2)]}, {(1, 2): t["pairs"][(1, 2)]}, 0.0),
            str(sorted(t["p12"])))
    T.check("cell/contacts on cell 1 alone: no rows", len(t["p1"]) == 0, str(sorted(t["p1"])))
    # the lamella bonds (between two cells) with both atoms on the low side of the plane
    atoms = dump(f"{d}/atoms.1.dump")    # id mol type x y z alam
    pos = {int(r[0]): r for r in atoms}
    bonds = dump(f"{d}/bonds.1.dump").astype(int)
    want = {}
    for i, j, _ in bonds:
        ai, aj = pos[i], pos[j]
        if ai[1] == aj[1] or ai[3] > XCUT or aj[3] > XCUT:
            continue
        key = (int(min(ai[1], aj[1])), int(max(ai[1], aj[1])))
        w = want.setdefault(key, [0, 0.0])
        w[0] += 1
        w[1] += 0.5 * (ai[6] + aj[6])
    got = {k: (int(r[2]), r[3]) for k, r in t["plo"].items()}
    print("half group x <= %g: lamella bonds, glued area" % XCUT, got, "expected", want)
    T.check("cell/contacts on the atoms with x <= XCUT: the lamella bonds with both atoms there",
            set(got) == set(want) and all(got[k][0] == want[k][0] and
                                          abs(got[k][1] - want[k][1]) <= 1e-9 * want[k][1]
                                          for k in want) and
            all(0 < want[k][0] < t["pairs"][k][2] for k in want), "")
    for c in ("pairs", "p12", "p1", "plo"):
        T.check(f"cell/contacts {c}: 1 and 2 ranks agree (1e-12)", same_rows(tabs[1][c], tabs[2][c]))


def test_debonded_bonds_counted_in_group(inflated):
    d, common = inflated
    T.lmp(PULL_IN.replace("{tag}", "pull"), cwd=d, variables=dict(common, **WEAK), log="log.pull")
    t = {c: table(f"{d}/{c}.pull.dat") for c in ("pairs", "p12", "p1", "p3")}
    print("after the pull, debonded bonds per pair:",
          {c: {k: int(r[4]) for k, r in t[c].items()} for c in t})
    T.check("the pull debonds both interfaces",
            set(t["pairs"]) == {(1, 2), (2, 3)} and all(r[4] > 0 for r in t["pairs"].values()))
    T.check("debonded bonds on cells 1 and 2: the row (1, 2) alone, the same as with all",
            set(t["p12"]) == {(1, 2)} and (1, 2) in t["pairs"] and
            same_rows({(1, 2): t["p12"][(1, 2)]}, {(1, 2): t["pairs"][(1, 2)]}, 0.0),
            str(sorted(t["p12"])))
    T.check("debonded bonds on cell 1 or cell 3 alone: no rows",
            len(t["p1"]) == 0 and len(t["p3"]) == 0, f"{sorted(t['p1'])} {sorted(t['p3'])}")
