# SPDX-License-Identifier: GPL-2.0-or-later
"""cellgen's geometry: the icosphere (counts, orientation, volumes), the fluid lattice and the
count search, against closed forms and brute force."""
import math

import numpy as np
import pytest

from cellmech import cellgen
from cellmech.cellgen.fluid import wall_distance


@pytest.mark.parametrize("level", range(6))
def test_icosphere_counts_and_orientation(level):
    nodes, tri, edges = cellgen.icosphere(level)
    n, e, t = len(nodes), len(edges), len(tri)
    print(f"level {level}: {n} nodes, {e} edges, {t} triangles")
    assert (n, e, t) == (10 * 4 ** level + 2, 30 * 4 ** level, 20 * 4 ** level)
    assert n - e + t == 2
    assert np.allclose(np.linalg.norm(nodes, axis=1), 1.0, atol=1e-14)
    # every edge in exactly two triangles, once each way (a closed, consistently oriented surface)
    directed = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    assert len({tuple(d) for d in directed}) == 3 * t
    und = np.sort(directed, axis=1)
    _, counts = np.unique(und, axis=0, return_counts=True)
    assert len(counts) == e and np.all(counts == 2)
    a, b, c = nodes[tri[:, 0]], nodes[tri[:, 1]], nodes[tri[:, 2]]
    assert np.all(np.einsum("ij,ij->i", np.cross(b - a, c - a), a + b + c) > 0)   # outward


def test_icosahedron_area_and_volume():
    """Level 0 is the icosahedron of circumradius 1: edge a = 4/sqrt(10 + 2 sqrt5),
    area 5 sqrt3 a^2, volume 5/12 (3 + sqrt5) a^3."""
    nodes, tri, _ = cellgen.icosphere(0)
    area, vol = cellgen.mesh_area_volume(nodes, tri)
    a = 4.0 / math.sqrt(10.0 + 2.0 * math.sqrt(5.0))
    print(f"area {area:.15g} vs {5 * math.sqrt(3) * a * a:.15g}, volume {vol:.15g} vs "
          f"{5 / 12 * (3 + math.sqrt(5)) * a ** 3:.15g}")
    assert area == pytest.approx(5.0 * math.sqrt(3.0) * a * a, rel=1e-14)
    assert vol == pytest.approx(5.0 / 12.0 * (3.0 + math.sqrt(5.0)) * a ** 3, rel=1e-14)


def test_inscribed_volume_converges_to_the_sphere():
    """The inscribed polyhedron's volume approaches 4 pi/3 from below, its error falling about 4x
    a level (second order in the edge length)."""
    err = []
    for level in range(1, 6):
        area, vol = cellgen.mesh_area_volume(*cellgen.icosphere(level)[:2])
        err.append(4.0 * math.pi / 3.0 - vol)
        print(f"level {level}: volume {vol:.8f}, deficit {err[-1]:.3e}, area {area:.8f}")
        assert 0 < err[-1] and area < 4.0 * math.pi
    ratios = [err[k] / err[k + 1] for k in range(len(err) - 1)]
    print("deficit ratios", ratios)
    assert all(3.5 < r < 4.5 for r in ratios)


def brute_lattice(radius, spacing, inset):
    """The lattice as the generator used to build it: the whole grid's coordinates, then the clip."""
    n = int(math.ceil(radius / spacing)) + 1
    g = np.arange(-n, n + 1) * spacing
    X, Y, Z = np.meshgrid(g, g, g, indexing="ij")
    pts = np.column_stack([X.ravel(), Y.ravel(), Z.ravel()])
    return pts[np.linalg.norm(pts, axis=1) < radius - inset]


@pytest.mark.parametrize("radius,spacing,inset", [(30.0, 5.71, 3.2), (30.0, 3.0, 1.6), (1.0, 0.3, 0.0),
                                                   (30.0, 7.5, 0.0), (5.0, 6.0, 1.0)])
def test_fluid_lattice_matches_brute_force(radius, spacing, inset):
    pts = cellgen.fluid_lattice(radius, spacing, inset)
    ref = brute_lattice(radius, spacing, inset)
    bound = cellgen.lattice_count_bound(radius - inset, spacing)
    print(f"R {radius} s {spacing} inset {inset}: {len(pts)} points (bound {bound:.0f})")
    assert np.array_equal(pts, ref)
    assert len(pts) <= bound


def test_count_search_finds_the_largest_spacing():
    """fluid_by_count: at least n points, and a spacing a hair larger holds fewer."""
    for n in (100, 440, 3500):
        pts, s = cellgen.fluid_by_count(30.0, n, 3.2)
        more = cellgen.fluid_lattice(30.0, s * (1 + 1e-9), 3.2)
        print(f"n {n}: spacing {s:.10g}, {len(pts)} points; at s(1 + 1e-9): {len(more)}")
        assert len(pts) >= n > len(more)
    assert cellgen.fluid_by_count(30.0, 0, 3.2)[0].shape == (0, 3)
    # one particle: the centre, whatever the spacing (the search stops at its upper end, 2 R)
    pts, s = cellgen.fluid_by_count(30.0, 1, 3.2)
    assert pts.tolist() == [[0.0, 0.0, 0.0]] and s == pytest.approx(60.0)


def test_fluid_fills_a_wall_that_is_star_shaped_not_convex():
    """A tissue cell's wall is star-shaped around its centre but not convex (concave rims where
    its domes meet its flat glued faces). The fluid lattice must fill all of it, each point inside
    and at least inset from the wall: checked against brute force on a cell with six dents."""
    nodes, tri, _ = cellgen.icosphere(4)
    # r = 20 (1 - 0.25 |n . axis|^8) along each axis: dents at the six poles, concave around them
    r = 20.0 * (1.0 - 0.25 * (np.abs(nodes) ** 8).sum(axis=1))
    wall = nodes * r[:, None]
    a, b, c = wall[tri[:, 0]], wall[tri[:, 1]], wall[tri[:, 2]]
    volume = np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0
    nrm = np.cross(b - a, c - a)
    beyond = (wall @ nrm.T - np.einsum("ij,ij->i", nrm, a)) / np.linalg.norm(nrm, axis=1)
    assert beyond.max() > 1.0                                  # not convex: nodes beyond some planes
    spacing, inset = 1.0, 1.5
    full = cellgen.fluid_in_wall(wall, tri, np.zeros(3), spacing, 0.0)
    print(f"inset 0: {len(full) * spacing ** 3:.0f} um^3 of the wall's {volume:.0f}")
    assert abs(len(full) * spacing ** 3 / volume - 1.0) < 0.03   # the lattice's own error
    kept = cellgen.fluid_in_wall(wall, tri, np.zeros(3), spacing, inset)
    # brute force, on every 7th point: at least inset from every triangle, and inside the wall by
    # its winding number (the solid angles of the outward triangles seen from it sum to 4 pi)
    sample = kept[::7]
    assert np.concatenate([wall_distance(p[None], a[None], b[None], c[None]) for p in sample]).min() >= inset
    for p in sample:
        x, y, z = a - p, b - p, c - p
        lx, ly, lz = (np.linalg.norm(v, axis=1) for v in (x, y, z))
        num = np.einsum("ij,ij->i", x, np.cross(y, z))
        den = (lx * ly * lz + np.einsum("ij,ij->i", x, y) * lz + np.einsum("ij,ij->i", x, z) * ly
               + np.einsum("ij,ij->i", y, z) * lx)
        assert abs(2.0 * np.arctan2(num, den).sum() / (4.0 * math.pi) - 1.0) < 1e-6
