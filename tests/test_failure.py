# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 4, failure: tethers break above lam_f (tension only) and the cell bursts.

A coarse stiff cell is inflated to turgor and compressed (in.compress, lamf = 1.04 as in the paper):
- no tether breaks and no fluid is outside the wall before the first failure; fluid leaves after it;
- the failure strain lies where a 642-node wall can put it: the paper's 14% (2562 nodes) with the
  coarse wall's stretch spread (its mean stretch at turgor is 1.0089 against 1.0094, the max
  1.018 at the 12 five-fold defects), so between 8% and 20% -- printed, the experiment reports it;
- 1 and 2 ranks see the first failure at the same output step;
- a burst run continued from a restart written mid-burst matches the uninterrupted run on 2 ranks
  (broken tethers, triangles, special lists and the per-atom counts all come back).
"""
import re

import numpy as np
import pytest

import lmptest as T

COARSE = dict(T.COARSE)


def first_failure(rows):
    broken = np.nonzero(rows[:, 7] > 0)[0]
    return broken[0] if len(broken) else None


MODEL = dict(COARSE, dir=T.INPUTS)


@pytest.fixture(scope="module")
def turgid(rundir):
    """The coarse cell inflated to turgor (turgid.restart)."""
    T.coarse_cell(rundir)
    T.lmp(f"{T.INPUTS}/in.inflate", cwd=rundir, variables=dict(MODEL, data="cell.data", nsteps=25000,
                                                                every=500, restart_out="turgid.restart"),
          log="log.inflate")
    return rundir


@pytest.fixture(scope="module")
def compressed(turgid):
    """The turgid cell compressed to 20% (lamf 1.04) on 1 and 2 ranks: each record."""
    d = turgid
    rows = {}
    for n in (1, 2):
        T.lmp(f"{T.INPUTS}/in.compress", cwd=d, nprocs=n, log=f"log.compress{n}",
              variables=dict(MODEL, restart="turgid.restart", every=200, lamf=1.04, leaks="yes",
                             strain=0.2, out=f"compress{n}.dat"))
        rows[n] = T.load(f"{d}/compress{n}.dat")    # step t eps Ftop Fbot Feq P broken leak
    return rows


@pytest.mark.parametrize("n", (1, 2))
def test_tethers_break_under_compression(compressed, n):
    rows = compressed[n]
    k = first_failure(rows)
    T.check(f"{n} rank(s): tethers break by eps = 20%", k is not None)
    if k is None:
        return
    eps_f = rows[k, 2]
    leak_before = rows[:k, 8].max() if k > 0 else 0
    print(f"{n} rank(s): first broken tethers at step {rows[k, 0]:.0f}, eps = {eps_f:.4f} "
          f"(paper, 2562 nodes: about 0.14); broken tethers at the end {rows[-1, 7]:.0f}, "
          f"fluid outside {rows[-1, 8]:.0f} of 461")
    T.check(f"{n} rank(s): no fluid outside the wall before failure", leak_before == 0,
            f"{leak_before}")
    T.check(f"{n} rank(s): fluid leaves after failure", rows[-1, 8] > 0, f"{rows[-1, 8]:.0f}")
    T.check(f"{n} rank(s): failure strain 0.08 < eps_f < 0.20", 0.08 < eps_f < 0.20,
            f"{eps_f:.4f}")


def test_first_failure_rank_independent(compressed):
    firsts = {n: rows[first_failure(rows), 0] for n, rows in compressed.items()
              if first_failure(rows) is not None}
    if len(firsts) == 2:
        T.check("1 and 2 ranks: first failure at the same step", firsts[1] == firsts[2],
                f"{firsts[1]:.0f} vs {firsts[2]:.0f}")


@pytest.fixture(scope="module")
def burst(turgid):
    """A burst on 2 ranks, uninterrupted and continued from a restart written mid-burst: the two
    logs."""
    d = turgid
    # a burst without plates: lamf below the turgid cell's largest stretch (1.018) starts a crack
    burst = "variable        lamf index 1.016\n" + T.continue_cell("{restart}") + """
fix             osmosis fluid cell/fluid Pi -364.0 Lp 1.0e-9
compute         props all cell/props leaks yes
thermo_style    custom step f_cell_broken c_props[1][13] c_props[1][9] bonds angles
thermo          100
timestep        0.001
run             0
change_box      all boundary m m m
"""
    dump = ("write_dump all custom {} id x y z vx vy vz d_rho f_cell_broken "
            "modify sort id format float %.17g\n")
    # the uninterrupted run also writes the walls as VTK at its end (step 26200), to be read back
    T.lmp(burst.format(restart="turgid.restart") + "run 600\nwrite_restart burst.restart\n" +
          "fix surf wall cell/vtk 200 walls\nrun 600\n" + dump.format("full.dump") +
          'print "BROKEN $(f_cell_broken) BONDS $(bonds) TETHERS $(c_props[1][13])"\n' +
          'print "ANGLES $(angles)"\n',
          cwd=d, nprocs=2, variables=MODEL, log="log.burst-full")
    cont = burst.format(restart="burst.restart")
    _, log = T.lmp(cont + "run 600\n" + dump.format("cont.dump") +
                   'print "BROKEN $(f_cell_broken) BONDS $(bonds)"\n', cwd=d, nprocs=2,
                   variables=MODEL, log="log.burst-cont")
    return open(f"{d}/log.burst-full").read(), log


def test_restart_mid_burst(turgid, burst):
    d = turgid
    full_log, log = burst
    b_full = full_log.split("BROKEN ")[-1].split()[:3]
    b_cont = log.split("BROKEN ")[-1].split()[:3]
    print(f"burst: broken tethers / bonds left, uninterrupted {b_full[0]} / {b_full[2]}, "
          f"restarted {b_cont[0]} / {b_cont[2]}")
    T.check("burst breaks tethers", float(b_full[0]) > 0, b_full[0])
    T.check("restart keeps the broken-tether count and the bond count", b_full == b_cont)
    a = np.loadtxt(f"{d}/full.dump", skiprows=9)
    b = np.loadtxt(f"{d}/cont.dump", skiprows=9)
    dx = np.abs(a[:, 1:4] - b[:, 1:4]).max()
    dn = np.abs(a[:, 8] - b[:, 8]).max()
    print(f"burst restart on 2 ranks: max position diff {dx:.2e} um, per-atom broken-count diff {dn}")
    T.check("restart mid-burst continues the run (positions, 1e-10 um)", dx < 1e-10, f"{dx:.1e}")
    T.check("restart mid-burst keeps the per-atom broken counts", dn == 0)


def test_crack_in_vtk(turgid, burst):
    d = turgid
    full_log, _ = burst
    b_full = full_log.split("BROKEN ")[-1].split()[:3]
    # the crack as ParaView sees it (fix cell/vtk, read with the VTK library): the nodes' broken
    # tether counts add up to twice the broken tethers, and the torn triangles are gone
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkPolyDataReader()
    reader.SetFileName(f"{d}/walls.26200.vtk")
    reader.ReadAllScalarsOn()
    reader.Update()
    poly = reader.GetOutput()
    node_counts = vtk_to_numpy(poly.GetPointData().GetArray("broken"))
    n_props = float(full_log.split("TETHERS ")[-1].split()[0])
    angles = int(re.findall(r"^ANGLES (\d+)", full_log, flags=re.M)[-1])
    print(f"VTK: nodes' broken counts sum to {int(node_counts.sum())} (2 x {b_full[0]}), "
          f"{poly.GetNumberOfPolys()} triangles (topology: {angles} of 1280); "
          f"compute cell/props broken tethers {n_props:.0f}")
    T.check("VTK broken counts = 2 x broken tethers = 2 x compute cell/props column 13",
            node_counts.sum() == 2 * float(b_full[0]) == 2 * n_props)
    T.check("VTK triangles = angles left in the topology < 1280",
            poly.GetNumberOfPolys() == angles < 1280)
