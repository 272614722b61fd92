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


def fluid_in_wall(nodes, tri, centre, spacing, inset):
    """Cubic lattice through the centre, points at distance >= inset inside the wall (convex or
    star-shaped around the centre with all triangles facing away from it: a point on the inner
    side of every triangle's plane, by >= inset, is inside and >= inset from every triangle)."""
    rmax = np.linalg.norm(nodes - centre, axis=1).max()
    pts = fluid_lattice(rmax, spacing, inset) + centre
    a, b, c = nodes[tri[:, 0]], nodes[tri[:, 1]], nodes[tri[:, 2]]
    nrm = np.cross(b - a, c - a)
    nrm /= np.linalg.norm(nrm, axis=1)[:, None]
    plane = np.einsum("ij,ij->i", nrm, a)
    # in chunks: the point-by-triangle table would otherwise take 8 bytes x points x triangles
    chunk = max(1, 4_000_000 // len(tri))
    keep = np.concatenate([(plane[None, :] - pts[k:k + chunk] @ nrm.T).min(axis=1) >= inset
                           for k in range(0, len(pts), chunk)] or [np.zeros(0, bool)])
    return pts[keep]
