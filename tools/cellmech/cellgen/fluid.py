# SPDX-License-Identifier: GPL-2.0-or-later
"""The fluid fill: a cubic lattice clipped to the inside of a wall (a sphere or a placed tissue
wall), by spacing or by count."""
import math

import numpy as np


def fluid_lattice(radius, spacing, inset):
    """Cubic lattice points strictly inside radius - inset, centred on the origin, in (x, y, z)
    lexicographic order. Only the squared distances of the grid are held (8 bytes a grid point,
    about twice the points kept), not its coordinates."""
    rin = radius - inset
    if not rin > 0:
        return np.zeros((0, 3))
    n = int(rin / spacing) + 1
    g = np.arange(-n, n + 1) * spacing
    g2 = g * g
    inside = np.sqrt(g2[:, None, None] + g2[None, :, None] + g2[None, None, :]) < rin
    return g[np.column_stack(np.nonzero(inside))]


def lattice_count_bound(r, spacing):
    """At most this many points of a cubic lattice lie inside a ball of radius r: each owns a
    cube of side spacing that lies within radius r + spacing sqrt(3)/2."""
    return 4.0 / 3.0 * math.pi * (r / spacing + 0.5 * math.sqrt(3.0)) ** 3


def spacing_for_count(points_at, nfluid, lo, hi, iterations=100):
    """Largest spacing in [lo, hi] for which points_at(spacing) holds at least nfluid points."""
    # the count is a step function of the spacing: bisect on it, then keep the closest count >= n
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        if len(points_at(mid)) >= nfluid:
            lo = mid
        else:
            hi = mid
    return lo


def fluid_by_count(radius, nfluid, inset):
    """Largest-spacing cubic lattice clipped to the sphere that holds at least nfluid points."""
    if nfluid <= 0:
        return np.zeros((0, 3)), 0.0
    # Lower end of the search: the cubes of side s around the lattice points inside radius rin cover
    # the ball of radius rin - s sqrt(3)/2, so a spacing s with (4/3)pi(rin/s - sqrt(3)/2)^3 >= n
    # surely holds n points. Starting lower only costs memory (a fixed 1e-3 radius asked for 8e9
    # grid points when the inset left little room).
    rin = radius - inset
    lo = rin / ((3.0 * nfluid / (4.0 * math.pi)) ** (1.0 / 3.0) + 0.5 * math.sqrt(3.0))
    lo = spacing_for_count(lambda s: fluid_lattice(radius, s, inset), nfluid, lo, 2.0 * radius)
    return fluid_lattice(radius, lo, inset), lo


def wall_distance(p, a, b, c):
    """Distance from points p (n, 3) to triangles a, b, c (n, k, 3 each: k candidates a point)."""
    p = p[:, None, :]
    v0, v1, v2 = b - a, c - a, p - a
    d00, d01, d11 = (np.einsum("...i,...i", u, w) for u, w in ((v0, v0), (v0, v1), (v1, v1)))
    d20, d21 = np.einsum("...i,...i", v2, v0), np.einsum("...i,...i", v2, v1)
    den = d00 * d11 - d01 * d01
    v, w = (d11 * d20 - d01 * d21) / den, (d00 * d21 - d01 * d20) / den
    nrm = np.cross(v0, v1)
    plane = np.abs(np.einsum("...i,...i", v2, nrm)) / np.linalg.norm(nrm, axis=-1)

    def segment(q, r):
        t = np.clip(np.einsum("...i,...i", p - q, r - q) / np.einsum("...i,...i", r - q, r - q), 0.0, 1.0)
        return np.linalg.norm(p - q - t[..., None] * (r - q), axis=-1)
    edges = np.minimum(np.minimum(segment(a, b), segment(b, c)), segment(c, a))
    return np.where((v >= 0) & (w >= 0) & (v + w <= 1), plane, edges).min(axis=1)


def _ray_reach(u, a, b, c):
    """Distance along unit rays u (n, 3) from the origin to the first of triangles a, b, c (n, k, 3
    each) they cross (Moller-Trumbore); 0 where none of the k does, so that such a point is left
    out rather than let in from outside the wall."""
    e1, e2 = b - a, c - a
    h = np.cross(u[:, None, :], e2)
    det = np.einsum("...i,...i", e1, h)
    with np.errstate(divide="ignore", invalid="ignore"):
        f = 1.0 / det
        s = -a
        bu = f * np.einsum("...i,...i", s, h)
        q = np.cross(s, e1)
        bv = f * np.einsum("...i,...i", u[:, None, :], q)
        t = f * np.einsum("...i,...i", e2, q)
    hit = (np.abs(det) > 0) & (bu >= 0) & (bv >= 0) & (bu + bv <= 1) & (t > 0)
    return np.where(hit.any(axis=1), np.where(hit, t, np.inf).min(axis=1), 0.0)


def fluid_in_wall(nodes, tri, centre, spacing, inset, candidates=12):
    """Cubic lattice through the centre, the points inside the wall and at least inset from it.
    The wall is star-shaped around the centre (every cellgen wall is) but not always convex: where
    a tissue cell's domed free faces meet its flat glued ones the rims are concave, and the inner
    side of every triangle's plane holds only 36-47% of such a cell (docs/cellgen.rst). Inside: the
    ray from the centre through the point meets the wall beyond it. Clearance: the point is at
    least inset from each of the `candidates` triangles whose centroids are nearest it."""
    from scipy.spatial import cKDTree
    x = nodes - centre
    rmax = np.linalg.norm(x, axis=1).max()
    pts = fluid_lattice(rmax, spacing, inset)
    if not len(pts):
        return pts + centre
    a, b, c = x[tri[:, 0]], x[tri[:, 1]], x[tri[:, 2]]
    cen = (a + b + c) / 3.0
    k = min(candidates, len(tri))
    near, ray = cKDTree(cen), cKDTree(cen / np.linalg.norm(cen, axis=1)[:, None])
    keep = []
    # in chunks: the point-by-candidate arrays take 8 bytes x 3 x points x candidates
    for lo in range(0, len(pts), 20000):
        p = pts[lo:lo + 20000]
        r = np.linalg.norm(p, axis=1)
        u = p / np.maximum(r, 1e-300)[:, None]
        u[r == 0] = (1.0, 0.0, 0.0)
        _, j = ray.query(u, k=k)
        reach = _ray_reach(u, a[j], b[j], c[j])
        _, j = near.query(p, k=k)
        keep.append((r < reach) & (wall_distance(p, a[j], b[j], c[j]) >= inset))
    return pts[np.concatenate(keep)] + centre
