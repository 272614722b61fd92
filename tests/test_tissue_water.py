# SPDX-License-Identifier: GPL-2.0-or-later
"""Water in a tissue, defects found by probing (issue 28, items 4, 6 and 10): each check below
failed before its fix.

4. Enclosed cells dried straight to the outside air: the exposed wall of Eq. W4 was the wall not
   glued by lamella bonds, so the centre cell of a 3x3x3 block (no free face) counted its rounded
   edges and corners as exposed and lost more water than a face cell. Now (exposed outside, the
   default) a wall triangle is exposed when no other cell's wall lies in front of it: on a coarse
   3x3x3 block (cellgen.py tissue --lattice sc --n 3 3 3 --level 3 --nfluid 440) the centre cell
   has no exposed wall, face, edge and corner cells have one, two and three free faces' worth; a
   centre cell closed to its neighbours (cell C Lp 0) under a set flux keeps all its water; the
   water lost is the flux through the exposed area (mass balance to round-off); 2 ranks = 1 rank;
   'exposed unglued' keeps the old area as an explicit choice.
6. fix ave/time ... f_ID[*] mode vector on fix cell/fluid, defined before the first run, wrote
   zero rows for the whole run: the rows were sized at the run's setup, after fix ave/time had read
   their number.
10. A bad molecule ID in a cells file did not name the file and line; 'external psi' then 'external
   flux' silently kept the last; an empty cells file passed silently; fluid of a molecule without
   wall triangles got a wall area of 0 silently; in.tissue-dry printed LAMMPS's "chunks do not
   contain all atoms" warning.
"""
import json
import os
from types import SimpleNamespace

import numpy as np
import pytest

import lmptest as T
from cellmech.cellgen.datafile import read_data

COARSE = dict(T.COARSE)
HEAD = T.TISSUE_HEAD + """unfix           osmosis
timestep        0.001
"""
# the per-cell rows of the fix (array: ID, W, Pi, psi, exposed, covered, W0; vector: uptake),
# recorded from the run's setup on; the exposed area of all cells summed every step
RECORD = """
run             0 post no
fix             rows all ave/time {every} 1 {every} f_w[*] mode vector file {tag}.rows format " %.17g"
fix             up all ave/time {every} 1 {every} f_w mode vector file {tag}.up format " %.17g"
fix             mass all ave/time {every} 1 {every} c_props[4] mode vector file {tag}.mass format " %.17g"
variable        Aexp equal sum(f_w[5])
fix             aexp all ave/time 1 {n} {n} v_Aexp file {tag}.aexp format " %.17g"
thermo          {n}
run             {n}
"""
Q = 2.0e-4    # pg/(um^2 us): a set flux, about 0.1% of a face cell's water in 0.2 us


def blocks(path):
    """Blocks of a fix ave/time mode vector file: {step: array of rows}."""
    out, lines = {}, [ln for ln in open(path) if not ln.startswith("#")]
    k = 0
    while k < len(lines):
        step, n = map(int, lines[k].split()[:2])
        out[step] = np.array([[float(v) for v in ln.split()[1:]] for ln in lines[k + 1:k + 1 + n]])
        k += 1 + n
    return out


def classes(data):
    """Number of free faces of each cell of an sc block (0 centre, 1 face, 2 edge, 3 corner), by
    molecule ID, from the centroids of its wall nodes in the data file."""
    cen = centroids(data)
    c = np.array(list(cen.values()))
    lo, hi = c.min(0), c.max(0)
    free = ((np.abs(c - lo) < 1.0) | (np.abs(c - hi) < 1.0)).sum(1)
    return dict(zip(cen.keys(), free))


def run(d, data, special, opts, n, every, tag, nprocs=1, check=True):
    text = HEAD.format(data=data, special=special) + \
        f"fix             w fluid cell/fluid Pi ${{Pi}} Lp 2.0e-4 {opts}\n" + \
        RECORD.format(every=every, n=n, tag=tag)
    return T.lmp(text, cwd=d, nprocs=nprocs, check=check, log=f"log.{tag}",
                 variables=dict(COARSE, dir=T.INPUTS))


@pytest.fixture(scope="module")
def data(rundir):
    """The coarse 3x3x3 block (blk.data) and the pair (two.data); the larger special count."""
    d = rundir
    T.cellgen("tissue", "-o", "blk.data", "--lattice", "sc", "--n", 3, 3, 3, "--level", 3,
              "--nfluid", 440, cwd=d)
    T.cellgen("tissue", "-o", "two.data", "--lattice", "sc", "--n", 1, 1, 2, "--level", 3,
              "--nfluid", 440, cwd=d)
    special = max(json.load(open(os.path.join(d, f"{n}.json")))["extra_special_per_atom"]
                  for n in ("blk", "two"))
    return d, special


@pytest.fixture(scope="module")
def flux_block(data):
    """The 3x3x3 block under a set flux, its centre cell closed to its neighbours (Lp 0), on 1 and 2
    ranks: the cells' free faces, the centre, and each run's rows, uptakes, exposed area, masses."""
    d, special = data
    free = classes(os.path.join(d, "blk.data"))
    centre = next(m for m, f in free.items() if f == 0)
    names = {0: "centre", 1: "face", 2: "edge", 3: "corner"}
    n = 200
    res = {}
    for np_ in (1, 2):
        run(d, "blk.data", special, f"solute yes exchange yes external flux {Q} cell {centre} Lp 0",
            n, n, f"flux{np_}", nprocs=np_)
        res[np_] = (blocks(os.path.join(d, f"flux{np_}.rows")), blocks(os.path.join(d, f"flux{np_}.up")),
                    T.load(os.path.join(d, f"flux{np_}.aexp"))[-1, 1],
                    blocks(os.path.join(d, f"flux{np_}.mass")))
    ids = res[1][0][0][:, 0].astype(int)
    return SimpleNamespace(free=free, centre=centre, names=names, n=n, res=res, ids=ids,
                           jc=list(ids).index(centre))


def test_exposed_area_by_free_faces(flux_block):
    free, centre, names, n, ids = (flux_block.free, flux_block.centre, flux_block.names, flux_block.n,
                                   flux_block.ids)
    rows = flux_block.res[1][0]
    for when in (0, n):
        r = rows[when]
        print(f"step {when}: exposed / wall area (um^2) per class:")
        for k in range(4):
            sel = [j for j, m in enumerate(ids) if free[m] == k]
            print(f"  {names[k]:7s} ({len(sel):2d} cells): exposed {r[sel, 4].mean():9.2f} "
                  f"({r[sel, 4].min():.2f}..{r[sel, 4].max():.2f}) of {r[sel, 4].mean() + r[sel, 5].mean():.1f}")
    r0 = rows[0]
    by = {k: r0[[j for j, m in enumerate(ids) if free[m] == k], 4] for k in range(4)}
    jc = list(ids).index(centre)
    T.check("4: the centre cell (no free face) has no exposed wall, at the start and the end",
            rows[0][jc, 4] == 0.0 and rows[n][jc, 4] == 0.0,
            f"{rows[0][jc, 4]:.1f} and {rows[n][jc, 4]:.1f} um^2 (was 40% of its wall)")
    face = by[1].mean()
    T.check("4: face, edge and corner cells expose one, two and three faces' worth (10%)",
            by[1].min() > 0.1 * (r0[jc, 4] + r0[jc, 5]) and
            abs(by[2].mean() / face - 2.0) < 0.2 and abs(by[3].mean() / face - 3.0) < 0.3,
            f"face {face:.0f}, edge {by[2].mean():.0f} ({by[2].mean() / face:.2f}x), corner "
            f"{by[3].mean():.0f} ({by[3].mean() / face:.2f}x) um^2")


def test_water_lost_through_exposed_area(flux_block):
    free, centre, n, ids, jc = flux_block.free, flux_block.centre, flux_block.n, flux_block.ids, flux_block.jc
    rows, up, aexp, mass = flux_block.res[1]
    # closed to its neighbours (Lp 0) the centre cell can lose water only to the outside
    lost = {m: -up[n][j, 0] for j, m in enumerate(ids)}
    print(f"water lost in {n} steps at q {Q}: centre {lost[centre]:.6g} pg; face cells "
          f"{np.mean([lost[m] for m in ids if free[m] == 1]):.6g}, corner cells "
          f"{np.mean([lost[m] for m in ids if free[m] == 3]):.6g}")
    T.check("4: the centre cell, closed to its neighbours, loses no water to the air (exactly)",
            lost[centre] == 0.0 and rows[n][jc, 1] == rows[0][jc, 1], f"{lost[centre]:.6g} pg")
    # mass balance: each cell's water (its fluid mass now, compute cell/props; the fix's array has
    # the state before the step's update) changes by its uptake, and all of it is the flux through
    # the exposed walls (the exchange between cells cancels)
    W0, W1 = mass[0][:, 0], mass[n][:, 0]
    total = up[n][:, 0].sum()
    expect = -Q * 0.001 * n * aexp
    own = np.abs(W1 - W0 - up[n][:, 0]).max() / W0.sum()
    bal = abs(total / expect - 1.0)
    print(f"total water {W0.sum():.12g} -> {W1.sum():.12g} pg; uptakes {total:.10g} pg, "
          f"-q dt sum(exposed) {expect:.10g} pg (rel {bal:.1e}); max |dW - U| / W = {own:.1e}")
    T.check("4: mass conserved: each cell's water changes by its uptake (1e-12 of the water)",
            own < 1e-12, f"{own:.1e}")
    T.check("4: the water lost is the flux through the exposed area (1e-9)", bal < 1e-9 and total < 0,
            f"{bal:.1e}")


def test_flux_rank_independent(flux_block):
    n = flux_block.n
    rows, up, _, _ = flux_block.res[1]
    rows2, up2, _, _ = flux_block.res[2]
    dev = max(np.abs(rows2[s][:, c] - rows[s][:, c]).max() / np.abs(rows[s][:, c]).max()
              for s in (0, n) for c in (1, 4))
    dev = max(dev, np.abs(up2[n][:, 0] - up[n][:, 0]).max() / np.abs(up[n][:, 0]).max())
    T.check("4: 2 ranks = 1 rank (water, exposed area, uptakes; 1e-10)", dev < 1e-10, f"{dev:.1e}")


def test_drying_centre_loses_least(data, flux_block):
    d, special = data
    free, centre, names, ids = flux_block.free, flux_block.centre, flux_block.names, flux_block.ids
    # against the air's potential, the neighbours' exchange on: the centre loses water only through
    # them, less than any cell with a free face
    run(d, "blk.data", special, "solute yes exchange yes external psi -3000", 300, 300, "psi")
    up = blocks(os.path.join(d, "psi.up"))
    lost = {m: -up[300][j, 0] for j, m in enumerate(ids)}
    byc = {k: [lost[m] for m in ids if free[m] == k] for k in range(4)}
    print("psi -3000 kPa, 0.3 us, water lost (pg): " +
          ", ".join(f"{names[k]} {np.mean(byc[k]):.5g}" for k in range(4)))
    T.check("4: drying in air, the centre cell loses less water than any cell with a free face",
            lost[centre] < min(byc[1]), f"centre {lost[centre]:.4g}, face cells >= {min(byc[1]):.4g} pg")


def test_exposed_unglued_option(data, flux_block):
    d, special = data
    jc = flux_block.jc
    # the old area, now an explicit choice: every space between cells counts as outside
    run(d, "blk.data", special, "solute yes exchange yes external flux 0 exposed unglued", 1, 1, "unglued")
    r = blocks(os.path.join(d, "unglued.rows"))[0]
    T.check("4: exposed unglued counts the centre cell's unglued edges and corners",
            r[jc, 4] > 0.0, f"{r[jc, 4]:.1f} um^2")


def centroids(data):
    """Centroid of each cell's wall nodes (type 1) in a data file, by molecule ID."""
    a = read_data(data).array("Atoms")[:, :6]
    wall = a[a[:, 2] == 1]
    return {int(m): wall[wall[:, 1] == m, 3:6].mean(0) for m in np.unique(wall[:, 1])}


def test_what_hides_a_wall(data):
    d, special = data
    """What hides a wall: glued (lamella bonds) or another cell's wall within D in front. The glued
    pair, its cells pulled 4 um further apart (bonds stretched, intact; walls 6.6 um apart, beyond
    D = 5 um), the lamella bonds deleted (walls touching), and both."""
    c = centroids(os.path.join(d, "two.data"))
    u = (c[2] - c[1]) / np.linalg.norm(c[2] - c[1]) * 4.0
    pull = f"group c2 molecule 2\ndisplace_atoms c2 move {u[0]:.6f} {u[1]:.6f} {u[2]:.6f}\n"
    cut = "delete_bonds all bond 2 remove special\n"
    E = {}
    for name, pre, np_ in (("glued", "", 1), ("glued, pulled apart", pull, 1),
                           ("unglued, touching", cut, 1), ("unglued, touching, 2 ranks", cut, 2),
                           ("unglued, pulled apart", cut + pull, 1)):
        text = HEAD.format(data="two.data", special=special) + pre + \
            "fix             w fluid cell/fluid Pi ${Pi} Lp 1.0 exchange yes exposed outside 5.0\n" + \
            "run             0 post no\n" + \
            'print           "EXPOSED $(f_w[1][5]:%.10g) $(f_w[1][5]+f_w[1][6]:%.10g) $(f_w[2][5]:%.10g)"\n'
        _, log = T.lmp(text, cwd=d, nprocs=np_, log="log.pair", variables=dict(COARSE, dir=T.INPUTS))
        vals = [ln.split()[1:] for ln in log.splitlines() if ln.startswith("EXPOSED")][-1]
        E[name] = tuple(map(float, vals))
        print(f"{name:24s}: cell 1 exposed {E[name][0]:9.2f} of {E[name][1]:9.2f} um^2, cell 2 {E[name][2]:9.2f}")
    g = E["glued"][0]
    T.check("4: glued faces stay covered when pulled beyond D with the lamella intact (1%)",
            abs(E["glued, pulled apart"][0] / g - 1.0) < 0.01, f"{E['glued, pulled apart'][0]:.1f} vs {g:.1f}")
    T.check("4: unglued walls touching (closer than D) stay covered (5%)",
            abs(E["unglued, touching"][0] / g - 1.0) < 0.05, f"{E['unglued, touching'][0]:.1f} vs {g:.1f}")
    T.check("4: the walls that hide each other across two ranks: as on one (exactly)",
            E["unglued, touching, 2 ranks"] == E["unglued, touching"])
    T.check("4: unglued walls further apart than D are exposed: the whole wall (1%)",
            E["unglued, pulled apart"][0] > 0.99 * E["unglued, pulled apart"][1],
            f"{E['unglued, pulled apart'][0]:.1f} of {E['unglued, pulled apart'][1]:.1f}")


def test_ave_time_rows_before_first_run(data):
    d, special = data
    # fix ave/time defined before the first run, as in.tissue-dry and in.tissue-inflate define theirs
    text = HEAD.format(data="two.data", special=special) + """
fix             w fluid cell/fluid Pi ${Pi} Lp 2.0e-4 exchange yes external flux 1e-4
fix             rows all ave/time 2 1 2 f_w[*] mode vector file early.rows
fix             up all ave/time 2 1 2 f_w mode vector file early.up
run             4
"""
    T.lmp(text, cwd=d, log="log.early", variables=dict(COARSE, dir=T.INPUTS))
    rows, up = blocks(os.path.join(d, "early.rows")), blocks(os.path.join(d, "early.up"))
    shape = {s: r.shape for s, r in rows.items()}
    print(f"f_w[*] rows per record: {shape}; f_w rows: { {s: r.shape for s, r in up.items()} }")
    ok = len(rows) == 3 and all(r.shape == (2, 7) for r in rows.values()) and \
        all(list(r[:, 0]) == [1.0, 2.0] and (r[:, 1] > 0).all() for r in rows.values())
    T.check("6: fix ave/time f_w[*] mode vector defined before the first run writes the 2 cells",
            ok, str(shape))
    T.check("6: fix ave/time f_w mode vector (the uptakes) too, losing water",
            len(up) == 3 and all(r.shape == (2, 1) for r in up.values()) and (up[4][:, 0] < 0).all())


BAD = [
    # (fix options, extra file lines, what the first ERROR line must say)
    ("cells cx.txt", "# M Pi Lp\n1 -364 10\nx -300 10\n", "cells file 'cx.txt' line 3"),
    ("cells cy.txt", "1 -364 ten\n", "cells file 'cy.txt' line 1"),
    ("cells empty.txt", "# only a comment\n\n", "file 'empty.txt' has no 'M Pi Lp' line"),
    ("external psi -100 external flux 1e-4", None,
     "'external' given twice, 'external psi -100' and 'external flux 1e-4'"),
    ("exposed inside 5", None, "expects 'outside D' or 'unglued'"),
    ("exposed outside -1", None, "must be > 0"),
]


def test_bad_cells_inputs_reported(data):
    d, special = data
    for opts, content, expect in BAD:
        if content is not None:
            with open(os.path.join(d, opts.split()[1]), "w") as f:
                f.write(content)
        text = HEAD.format(data="two.data", special=special) + \
            f"fix             w fluid cell/fluid Pi ${{Pi}} Lp 1.0 exchange yes {opts}\nrun 0\n"
        rc, log = T.lmp(text, cwd=d, check=False, log="log.bad", variables=dict(COARSE, dir=T.INPUTS))
        err = [ln for ln in log.splitlines() if "ERROR" in ln]
        print(f"'{opts}': rc {rc}: {err[0] if err else 'no error'}")
        T.check(f"10: '{opts}' refused, naming what is wrong", rc != 0 and bool(err) and expect in err[0])
    # a distance beyond the ghost cutoff (2s + 1 = 13.8 um here) raises it, as it must for 2 ranks
    text = HEAD.format(data="two.data", special=special) + \
        "fix             w fluid cell/fluid Pi ${Pi} Lp 1.0 exchange yes exposed outside 20\nrun 0\n"
    rc, log = T.lmp(text, cwd=d, check=False, nprocs=2, log="log.far", variables=dict(COARSE, dir=T.INPUTS))
    T.check("exposed outside 20 raises the communication cutoff to 20 and runs",
            rc == 0 and "communication cutoff raised from 13.8 to 20" in log)
    # a fluid particle moved into a molecule of its own, which has no wall
    text = HEAD.format(data="two.data", special=special) + """
variable        last equal count(all)
set             atom ${last} mol 9
fix             w fluid cell/fluid Pi ${Pi} Lp 1.0
run 0
"""
    rc, log = T.lmp(text, cwd=d, check=False, log="log.bad", variables=dict(COARSE, dir=T.INPUTS))
    err = [ln for ln in log.splitlines() if "ERROR" in ln]
    print(f"fluid in a wall-less molecule: rc {rc}: {err[0] if err else 'no error'}")
    T.check("10: fluid of a molecule without wall triangles refused",
            rc != 0 and bool(err) and "molecule ID) 9 holds 1 fluid particle" in err[0])
    # closed on purpose (Lp 0 for that molecule) it runs
    rc, log = T.lmp(text.replace("Lp 1.0\n", "Lp 1.0 cell 9 Lp 0\n"), cwd=d, check=False,
                    log="log.bad", variables=dict(COARSE, dir=T.INPUTS))
    T.check("10: ... and accepted when that molecule is closed (cell 9 Lp 0)", rc == 0)

    # in.tissue-dry after a (very short) in.tissue-inflate: no warning from its chunks
    T.lmp(os.path.join(T.INPUTS, "in.tissue-inflate"), cwd=d, log="log.inflate", variables=dict(
        COARSE, dir=T.INPUTS, data="two.data", special=special, nsteps=20, nsettle=10, every=10,
        restart_out="two.restart"))
    rc, log = T.lmp(os.path.join(T.INPUTS, "in.tissue-dry"), cwd=d, log="log.dry", variables=dict(
        COARSE, dir=T.INPUTS, restart="two.restart", nmax=20, every=10))
    warn = [ln for ln in log.splitlines() if "WARNING" in ln]
    print("in.tissue-dry warnings: " + ("; ".join(warn) if warn else "none"))
    T.check("10: in.tissue-dry runs without LAMMPS's chunk warning",
            not any("chunks do not contain all atoms" in w for w in warn))
    cells = blocks(os.path.join(d, "tissue-dry-gyration.dat"))
    T.check("10: ... and still writes the shape (gyration tensor) of both walls",
            all(r.shape == (2, 6) and (r[:, :3] > 0).all() for r in cells.values()),
            str({s: r.shape for s, r in cells.items()}))


def test_dry_saves_and_rehydrates(data):
    """in.tissue-dry -var save 1 writes the last state, and -var back 1 -var psi 0 -var W0 W
    continues it in pure water: the water comes back, its fraction of W (the turgid water), and
    the halt looks the other way (a rehydration stops as the fraction rises to target)."""
    d, special = data
    T.lmp(os.path.join(T.INPUTS, "in.tissue-inflate"), cwd=d, log="log.inflate-back", variables=dict(
        COARSE, dir=T.INPUTS, data="two.data", special=special, nsteps=20, nsettle=10, every=10,
        restart_out="back.restart"))
    T.lmp(os.path.join(T.INPUTS, "in.tissue-dry"), cwd=d, log="log.dry-back", variables=dict(
        COARSE, dir=T.INPUTS, restart="back.restart", nmax=40, every=10, save=1, out="dry-back.csv"))
    dry = np.genfromtxt(os.path.join(d, "dry-back.csv"), delimiter=",", names=True)
    W0 = dry["water_pg"][0]
    T.check("dry: save 1 writes tissue-dry.restart and its lengths' file",
            all(os.path.exists(os.path.join(d, f)) for f in ("tissue-dry.restart", "tissue-dry.restart.lmp")))
    for target, steps in ((2.0, 40), (0.5, 10)):
        T.lmp(os.path.join(T.INPUTS, "in.tissue-dry"), cwd=d, log="log.back", variables=dict(
            COARSE, dir=T.INPUTS, restart="tissue-dry.restart", nmax=40, every=10, back=1, psi=0.0,
            W0=f"{W0:.17g}", target=target, out="back.csv"))
        b = np.genfromtxt(os.path.join(d, "back.csv"), delimiter=",", names=True)
        print(f"target {target}: dried to {dry['water_fraction'][-1]:.10f}, back from {b['water_fraction'][0]:.10f} "
              f"to {b['water_fraction'][-1]:.10f} in {b['time_us'][-1] / 0.001:.0f} steps")
        T.check(f"back (target {target}): starts where the drying ended, as a fraction of W0 (1e-12)",
                abs(b["water_fraction"][0] / dry["water_fraction"][-1] - 1) < 1e-12)
        T.check(f"back (target {target}): stops after {steps} steps",
                abs(b["time_us"][-1] / 0.001 - steps) < 1e-6)
        if target > 1:
            T.check("back: in pure water the water comes back", np.all(np.diff(b["water_pg"]) > 0))
