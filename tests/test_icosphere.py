# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 2, check 2: the cell generator (tools/cellgen.py).

Icosphere of level n: 10*4^n+2 nodes, every node of degree 6 but 12 of degree 5, a closed and
consistently outward-oriented surface (Euler characteristic V - E + F = 2, every edge shared by
two triangles traversed in opposite directions, normals pointing away from the centre), and mesh
area and volume converging to the sphere's at second order (errors shrink ~4x per level).
The data file: one molecule ID per cell, wall/fluid types, masses from rho0 and the wall mass,
fluid strictly inside the wall, reference positions equal to the positions.
"""
import math
from collections import Counter

import numpy as np

import lmptest as T

from cellmech import cellgen
from cellmech.cellgen.datafile import read_data


def test_icosphere_levels():
    prev = None
    print(f"{'n':>2} {'nodes':>6} {'edges':>6} {'faces':>6} {'area err':>10} {'vol err':>10} ratio")
    for n in range(6):
        nodes, tri, edges = cellgen.icosphere(n)
        V, E, F = len(nodes), len(edges), len(tri)
        T.check(f"level {n}: 10*4^n+2 nodes", V == 10 * 4 ** n + 2, f"{V}")
        T.check(f"level {n}: Euler characteristic 2", V - E + F == 2, f"{V - E + F}")
        deg = Counter(np.concatenate([edges[:, 0], edges[:, 1]]))
        dcount = Counter(deg.values())
        want = {5: 12, 6: V - 12} if n > 0 else {5: 12}
        T.check(f"level {n}: degrees 6 except 12 of degree 5", dict(dcount) == want, f"{dict(dcount)}")
        # consistent orientation: each directed edge appears exactly once, and its reverse once
        directed = Counter()
        for a, b, c in tri:
            for u, v in ((a, b), (b, c), (c, a)):
                directed[(u, v)] += 1
        ok = all(directed[(u, v)] == 1 and directed[(v, u)] == 1 for u, v in edges)
        T.check(f"level {n}: closed, consistently oriented", ok and len(directed) == 2 * E)
        a, b, c = nodes[tri[:, 0]], nodes[tri[:, 1]], nodes[tri[:, 2]]
        outward = np.einsum("ij,ij->i", np.cross(b - a, c - a), a + b + c) > 0
        T.check(f"level {n}: all normals outward", outward.all())
        area, vol = cellgen.mesh_area_volume(nodes, tri)
        ea, ev = 1 - area / (4 * math.pi), 1 - vol / (4 * math.pi / 3)
        ratio = "" if prev is None else f"{prev[0] / ea:.2f} {prev[1] / ev:.2f}"
        print(f"{n:2d} {V:6d} {E:6d} {F:6d} {ea:10.3e} {ev:10.3e} {ratio}")
        if prev is not None and n >= 2:
            T.check(f"level {n}: area and volume errors shrink at second order (ratio > 3.5)",
                    prev[0] / ea > 3.5 and prev[1] / ev > 3.5)
        prev = (ea, ev)


def test_two_cell_data_file(rundir):
    """The data file of two cells."""
    d = rundir
    R, rho0, M = 30.0, 1.0, 1.3e4
    T.cellgen("cell", "-o", "two.data", "--level", 3, "--nfluid", 500, "--centres",
              "0,0,0;80,0,0", "--rho0", rho0, "--wall-mass", M, cwd=d)
    data = read_data(f"{d}/two.data")
    masses = {int(t): float(m) for t, m in data.rows("Masses")}
    atoms = data.array("Atoms")
    percell = data.array("cell")
    refs = percell[:, [0, 4, 5, 6]]
    nodes, tri, edges = cellgen.icosphere(3)
    _, vmesh = cellgen.mesh_area_volume(nodes * R, tri)
    for mol, centre in ((1, (0, 0, 0)), (2, (80, 0, 0))):
        cell = atoms[atoms[:, 1] == mol]
        wall, fluid = cell[cell[:, 2] == 1], cell[cell[:, 2] == 2]
        T.check(f"cell {mol}: 642 wall nodes and >= 500 fluid", len(wall) == 642 and len(fluid) >= 500,
                f"{len(wall)} wall, {len(fluid)} fluid")
        rw = np.linalg.norm(wall[:, 3:6] - centre, axis=1)
        rf = np.linalg.norm(fluid[:, 3:6] - centre, axis=1)
        T.check(f"cell {mol}: wall on the sphere, fluid inside", np.allclose(rw, R, rtol=1e-12)
                and rf.max() < R, f"max fluid radius {rf.max():.3f}")
        mw, mf = masses[1] * len(wall), masses[2] * len(fluid)
        T.check(f"cell {mol}: wall mass = input", abs(mw / M - 1) < 1e-12, f"{mw:.6g}")
        # each fluid particle carries its lattice cell (spacing^3) at rho0; the spacing is in the title
        spacing = float(data.title.split("spacing ")[1].split(",")[0])
        T.check(f"cell {mol}: fluid mass = rho0 * N * spacing^3",
                abs(mf / (rho0 * len(fluid) * spacing ** 3) - 1) < 1e-5, f"{mf:.6g}; mesh volume "
                f"{rho0 * vmesh:.6g}")
    T.check("reference positions = positions", np.array_equal(refs[:, 1:], atoms[:, 3:6]))
    T.check("per-atom masses = type masses, fluid density rho0",
            np.array_equal(percell[:, 1], [masses[int(t)] for t in atoms[:, 2]])
            and np.all(percell[atoms[:, 2] == 2, 2] == rho0) and np.all(percell[:, 3] == 0))
    T.check("bonds and angles of both cells", len(data.rows("Bonds")) == 2 * len(edges)
            and len(data.rows("Angles")) == 2 * len(tri))
