# SPDX-License-Identifier: GPL-2.0-or-later
"""The shape measures of the drying report (cellmech.tissue.water.shape) on bodies whose values are
known in closed form, and the splice that writes the Water section alone into an existing report."""
import math
import os
import types

import numpy as np

from cellmech.tissue import report, water


def test_shape_sphere_and_cube():
    R, a = 30.0, 48.0
    # a sphere: V, A; gyration tensor of a spherical shell R^2/3 on the diagonal
    cells = np.array([[4 / 3 * math.pi * R ** 3, 4 * math.pi * R ** 2],
                      [a ** 3, 6 * a ** 2]])
    gyr = np.array([[R ** 2 / 3] * 3 + [0.0] * 3, [a ** 2 / 4] * 3 + [0.0] * 3])
    sph, el = water.shape(cells, gyr)
    print("sphericity sphere, cube:", sph, "elongation:", el)
    assert abs(sph[0] - 1.0) < 1e-12
    assert abs(sph[1] - (math.pi / 6) ** (1 / 3)) < 1e-12   # 0.806 for a cube
    assert np.allclose(el, 1.0, atol=1e-12)


def test_shape_elongation_rotated():
    # a tensor with principal values 4, 1, 1 (radii 2:1), rotated about z by 30 degrees
    c, s = math.cos(math.pi / 6), math.sin(math.pi / 6)
    Q = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    G = Q @ np.diag([4.0, 1.0, 1.0]) @ Q.T
    g = np.array([[G[0, 0], G[1, 1], G[2, 2], G[0, 1], G[0, 2], G[1, 2]]])
    sph, el = water.shape(np.array([[1.0, 5.0]]), g)
    print("elongation of a 2:1 tensor:", el[0])
    assert abs(el[0] - 2.0) < 1e-12


def test_splice_keeps_other_sections(tmp_path):
    md = tmp_path / "tissue.md"
    md.write_text("# T\n\n## 3. Impact\n\nkeep me\n\n## Water\n\nold water\n\n## Pictures\n\nkeep too\n")
    (tmp_path / "tissue-summary.json").write_text('{"impact": 1}')
    rep = types.SimpleNamespace(report=str(tmp_path), md=[], S={})
    rep.w = rep.md.extend
    orig = water.section
    try:
        water.section = lambda r: (r.w(["## Water", "", "new water", ""]), r.S.update(water={"x": 1.0}))
        report.splice_water(rep)
    finally:
        water.section = orig
    text = md.read_text()
    print(text)
    assert "keep me" in text and "keep too" in text and "new water" in text and "old water" not in text
    assert text.index("new water") < text.index("## Pictures")
    assert open(os.path.join(tmp_path, "tissue-summary.json")).read().count('"impact"') == 1


def ellipse_line_elongation(a, b, n=200000):
    """sqrt of the ratio of the principal second moments of an ellipse's outline (per arc length),
    by dense sampling: the reference for plane_section's elongation."""
    t = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
    x, y = a * np.cos(t), b * np.sin(t)
    ds = np.hypot(a * np.sin(t), b * np.cos(t))
    return math.sqrt((ds * x * x).sum() / (ds * y * y).sum())


def test_plane_section_sphere_and_ellipsoid():
    from cellmech.cellgen import icosphere
    unit, tri, _ = icosphere(5)
    R = 30.0
    # the icosphere's section is a polygon inscribed in the circle: at level 5 (edges ~ R/26) its
    # area is short by (pi^2/3)(h/R)^2 ~ 0.5% at most (measured: 0.03%, the plane runs along
    # edges), its perimeter by half that
    sec = water.plane_section(R * unit, tri, np.zeros(3), np.array([0.0, 0.0, 1.0]))
    area, perim, feret, el = sec
    print("sphere: area / pi R^2", area / (math.pi * R * R), "perimeter / 2 pi R", perim / (2 * math.pi * R),
          "Feret / 2R", feret / (2 * R), "elongation", el)
    assert abs(area / (math.pi * R * R) - 1) < 0.01
    assert abs(perim / (2 * math.pi * R) - 1) < 0.005
    assert abs(feret / (2 * R) - 1) < 0.005
    assert abs(el - 1) < 0.01
    # the ellipsoid x 2: the section normal to z is the ellipse of semi-axes 2R, R; normal to x the
    # circle of radius R, turned about an off-centre point (the enclosed area does not depend on it)
    pts = R * unit * np.array([2.0, 1.0, 1.0])
    area, perim, feret, el = water.plane_section(pts, tri, np.array([0.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0]))
    ref = ellipse_line_elongation(2 * R, R)
    print("ellipse: area / 2 pi R^2", area / (2 * math.pi * R * R), "Feret / 4R", feret / (4 * R),
          "elongation", el, "reference", ref)
    assert abs(area / (2 * math.pi * R * R) - 1) < 0.01
    assert abs(feret / (4 * R) - 1) < 0.005
    assert abs(el / ref - 1) < 0.01
    # the plane x = 0 through an off-centre point: the same circle of radius R (the signed triangles'
    # sum does not depend on the point they are taken about)
    area, *_ = water.plane_section(pts, tri, np.array([0.0, 5.0, -3.0]), np.array([1.0, 0.0, 0.0]))
    print("circle about an off-centre point: area / pi R^2", area / (math.pi * R * R))
    assert abs(area / (math.pi * R * R) - 1) < 0.01


def test_bvh_gap_zero_when_volume_follows_water():
    """Boyle-van 't Hoff with a slack wall: turgid at the start (V0, turgor P0), then at zero
    pressure, the fluid at its rest density: V/V0 = W/W0 rho(P0)/rho(0) has no gap; 10% less volume
    is -10% at every water content."""
    x = np.linspace(1.0, 0.2, 41)
    B = water.params.table()["rho0"] * water.params.table()["c"] ** 2 / 7.0
    P0 = 364.0
    d = dict(water_fraction=x, turgor_mean_kPa=np.full_like(x, P0),
             volume_um3=np.where(x < 1.0, 1e5 * x * (1 + P0 / B) ** (1 / 7), 1e5))
    gap = water.bvh_gap(d)
    print(gap)
    assert set(gap) == {"0.9", "0.8", "0.7", "0.6", "0.4", "0.2"}
    assert max(abs(v) for v in gap.values()) < 1e-12
    d["volume_um3"] = d["volume_um3"] * np.where(x < 1.0, 0.9, 1.0)
    assert all(abs(v + 0.1) < 1e-12 for v in water.bvh_gap(d).values())


def test_water_by_class_of_a_cubic_block(tmp_path):
    """A 3x3x3 block's cells sorted by free faces (centre 1, face 6, edge 12, corner 8 cells) from
    their centroids; each cell's water at the end over that at the start, averaged per class."""
    from cellmech.tissue import waterblock
    rows0, rows1 = [], []
    for i in range(3):
        for j in range(3):
            for k in range(3):
                free = sum(v != 1 for v in (i, j, k))
                r = [0.0] * 18
                r[3], r[9:12] = 1000.0, [40.0 * i, 40.0 * j, 40.0 * k]
                rows0.append(r)
                rows1.append(r[:3] + [1000.0 * (1 - 0.2 * free)] + r[4:])
    path = tmp_path / "cells.dat"
    with open(path, "w") as f:
        for step, rows in ((0, rows0), (1000, rows1)):
            f.write(f"{step} {len(rows)}\n")
            for n, r in enumerate(rows):
                f.write(f"{n + 1} " + " ".join(str(v) for v in r) + "\n")
    w = waterblock.water_by_class(str(path))
    print(w)
    assert sorted(w) == [0, 1, 2, 3] and all(abs(w[k] - (1 - 0.2 * k)) < 1e-12 for k in range(4))


def test_failure_where_by_layer(tmp_path):
    """tissuedata.failure_where: the cells that ruptured or debonded during a run, by their layer
    along z at the start; 3 layers (bottom, middle, top) or 2 (bottom, top)."""
    from cellmech.tissue import tissuedata as TD

    def table(nz, broken, debonded):
        path = tmp_path / f"cells{nz}.dat"
        with open(path, "w") as f:
            for step, on in ((0, False), (500, True)):
                f.write(f"{step} {4 * nz}\n")
                for n in range(4 * nz):
                    r = [0.0] * 18
                    r[TD.CELL_ZC] = 40.0 * (n // 4)
                    r[TD.CELL_NBROKEN] = 3.0 if on and n in broken else 0.0
                    r[TD.CELL_NDEBONDED] = 2.0 if on and n in debonded else 0.0
                    f.write(f"{n + 1} " + " ".join(str(v) for v in r) + "\n")
        return str(path)
    w3 = TD.failure_where(table(3, broken={0, 1, 9}, debonded={5}))
    print(w3)
    assert w3 == dict(layers=3, kinds={"wall rupture": {"bottom": 2, "top": 1},
                                       "lamella debonding": {"middle": 1}})
    w2 = TD.failure_where(table(2, broken=set(), debonded={0, 7}))
    assert w2 == dict(layers=2, kinds={"lamella debonding": {"bottom": 1, "top": 1}})


def test_debonds_by_interface(tmp_path):
    """tissuedata.failure_where with the per-pair table: the lamella bonds that let go during the
    run, by the layers of the two cells they glued (a pair that appears only later counts from 0)."""
    from cellmech.tissue import tissuedata as TD
    cells, pairs = tmp_path / "cells.dat", tmp_path / "pairs.dat"
    z = {1: 0.0, 2: 40.0, 3: 80.0, 4: 0.0, 5: 40.0, 6: 80.0}
    deb = {1: 2.0, 2: 2.0, 4: 1.0, 5: 1.0}   # cells 1-2 and 4-5 (bottom-middle) let go
    with open(cells, "w") as f:
        for step, on in ((0, False), (500, True)):
            f.write(f"{step} 6\n")
            for n in range(1, 7):
                r = [0.0] * 18
                r[TD.CELL_ZC] = z[n]
                r[TD.CELL_NDEBONDED] = deb.get(n, 0.0) if on else 0.0
                f.write(f"{n} " + " ".join(str(v) for v in r) + "\n")
    col = TD.PAIRS.index("debonded_bonds")
    with open(pairs, "w") as f:
        for step, table in ((0, {(1, 2): 0, (2, 3): 0}), (500, {(1, 2): 7, (2, 3): 0, (4, 5): 3})):
            f.write(f"{step} {len(table)}\n")
            for n, ((i, j), d) in enumerate(table.items()):
                r = [0.0] * len(TD.PAIRS)
                r[0], r[1], r[col] = i, j, d
                f.write(f"{n + 1} " + " ".join(str(v) for v in r) + "\n")
    w = TD.failure_where(str(cells), str(pairs))
    print(w)
    assert w["kinds"] == {"lamella debonding": {"bottom": 2, "middle": 2}}
    assert w["interfaces"] == {"bottom-middle": 10}
    assert "held_interfaces" not in w
    # with the cells the jaws hold (cell 1): 1-2 is a held cell's interface, 4-5 two free cells'
    held = tmp_path / "held.txt"
    held.write_text("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\n"
                    "ITEM: ATOMS mol\n1\n1\n")
    assert TD.held_cells(str(held)) == {1} and TD.held_cells(str(tmp_path / "none.txt")) is None
    w = TD.failure_where(str(cells), str(pairs), TD.held_cells(str(held)))
    assert w["held_interfaces"] == {"held-free": 7, "free-free": 3}
