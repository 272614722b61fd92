# SPDX-License-Identifier: GPL-2.0-or-later
"""The wall's mesh: the icosahedral geodesic sphere (a cell's wall before it is placed), its area and
volume, the bending hinges of its triangles, and the quality and volumes of placed walls."""
import math

import numpy as np


def icosphere(level):
    """Unit geodesic sphere: (nodes[N,3], triangles[T,3] outward-oriented, edges[E,2])."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t),
             (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    verts = [np.array(v, float) / np.linalg.norm(v) for v in verts]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        cache = {}

        def midpoint(a, b):
            key = (a, b) if a < b else (b, a)
            if key not in cache:
                m = verts[a] + verts[b]
                verts.append(m / np.linalg.norm(m))
                cache[key] = len(verts) - 1
            return cache[key]

        new = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            new += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new
    nodes = np.array(verts)
    tri = np.array(faces, dtype=int)
    # orient every triangle outward (the subdivision keeps the base orientation, but be explicit)
    a, b, c = nodes[tri[:, 0]], nodes[tri[:, 1]], nodes[tri[:, 2]]
    flip = np.einsum("ij,ij->i", np.cross(b - a, c - a), a + b + c) < 0
    tri[flip] = tri[flip][:, [0, 2, 1]]
    edges = set()
    for a, b, c in tri:
        for u, v in ((a, b), (b, c), (c, a)):
            edges.add((min(u, v), max(u, v)))
    return nodes, tri, np.array(sorted(edges), dtype=int)


def mesh_area_volume(nodes, tri):
    a, b, c = nodes[tri[:, 0]], nodes[tri[:, 1]], nodes[tri[:, 2]]
    cr = np.cross(b - a, c - a)
    area = 0.5 * np.linalg.norm(cr, axis=1).sum()
    volume = np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0
    return area, volume


def hinges(angles):
    """Bending hinges of triangles (a, b, c): (i, j, k, l) for every edge j-k shared by two of them,
    with (i, j, k) and (l, k, j) the two triangles as they are oriented in `angles`. Each triangle
    runs its edges a->b, b->c, c->a; a consistently oriented mesh runs a shared edge once each way,
    so each edge gives one hinge, taken from its direction j < k. Boundary edges give none."""
    opposite = {}
    for a, b, c in angles:
        for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
            if (u, v) in opposite:
                raise ValueError(f"triangles not consistently oriented: edge {u + 1}-{v + 1} twice")
            opposite[(u, v)] = w
    return [(i, j, k, opposite[(k, j)]) for (j, k), i in opposite.items()
            if j < k and (k, j) in opposite]


def wall_quality(x, tri):
    """Per triangle of walls x (C, V, 3): areas, angles (deg), edge lengths, barycentre to 2nd node."""
    a, b, c = x[:, tri[:, 0]], x[:, tri[:, 1]], x[:, tri[:, 2]]
    e = [b - a, c - b, a - c]
    L = np.stack([np.linalg.norm(v, axis=2) for v in e], -1)
    cosines = [np.einsum("ctj,ctj->ct", -e[k - 1], e[k]) / (L[..., k - 1] * L[..., k])
               for k in range(3)]
    ang = np.degrees(np.arccos(np.clip(np.stack(cosines, -1), -1, 1)))
    area = 0.5 * np.linalg.norm(np.cross(e[0], -e[2]), axis=2)
    bary = np.linalg.norm((a + b + c) / 3.0 - b, axis=2)
    return area, ang, L, bary


def mesh_volumes(x, centres, tri):
    """Volume enclosed by each wall x (C, V, 3), from the tetrahedra (centre, triangle)."""
    a, b, c = (x[:, tri[:, k]] - centres[:, None, :] for k in range(3))
    return np.einsum("ctj,ctj->c", a, np.cross(b, c)) / 6.0
