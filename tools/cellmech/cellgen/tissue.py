# SPDX-License-Identifier: GPL-2.0-or-later
"""The tissue: a block of glued cells (docs/cellgen.rst, "Tissue"): seeds -> Laguerre (power)
cells clipped by the tissue box -> each cell's icosphere mapped onto its cell, offset inward by
gap/2, with rounded edges (and intercellular air) -> a fluid lattice inside each wall ->
middle-lamella bonds between facing wall nodes."""
import json
import math
import os
import sys
from dataclasses import dataclass

import numpy as np

from .. import params
from .datafile import write_data, write_lengths
from .fluid import fluid_in_wall, lattice_count_bound, spacing_for_count, wall_distance
from .limits import MAX_SHARPNESS, check_count, fail
from .mesh import icosphere, mesh_volumes, wall_quality

R_CELL = params.CELL["R"]                       # the single cell's radius, um
WALL_AREAL = params.CELL["M_wall"] / (4.0 * math.pi * R_CELL ** 2)   # the single cell's, pg/um^2
LATTICES = {  # basis (in lattice constants) and repeat vector of each seed lattice
    "sc": ([(0, 0, 0)], (1, 1, 1)),
    "bcc": ([(0, 0, 0), (0.5, 0.5, 0.5)], (1, 1, 1)),
    "fcc": ([(0, 0, 0), (0.5, 0.5, 0), (0.5, 0, 0.5), (0, 0.5, 0.5)], (1, 1, 1)),
    "hex": ([(0, 0, 0), (0.5, math.sqrt(3.0) / 2.0, 0)], (1, math.sqrt(3.0), 1)),
}


def progress(ncell, what, k, n):
    """A line on stderr every tenth of a long stage (a block of more than 100 cells): a large
    tissue takes minutes, and a silent generator looks hung."""
    if ncell > 100 and (k == n or k % max(1, n // 10) == 0):
        print(f"cellgen.py tissue: {what}", file=sys.stderr, flush=True)


def tfail(msg):
    fail("tissue", msg)


def lattice_seeds(kind, n, a):
    """Seeds of n[0] x n[1] x n[2] repeats of lattice `kind` (constant a) and the cut block around
    them: the seeds' bounding box padded by half the distance between seed layers on each axis."""
    basis, rep = np.array(LATTICES[kind][0], float), np.array(LATTICES[kind][1], float)
    idx = np.stack(np.meshgrid(*[np.arange(k) for k in n], indexing="ij"), -1).reshape(-1, 3)
    seeds = ((idx * rep)[:, None, :] + basis[None]).reshape(-1, 3) * a
    half = []
    for ax in range(3):
        layers = np.unique(np.round(basis[:, ax] % rep[ax], 12))
        half.append(0.5 * np.diff(np.append(layers, layers[0] + rep[ax])).min() * a)
    return seeds, seeds.min(axis=0) - half, seeds.max(axis=0) + half


def random_seeds(n, lo, hi, dmin, rng):
    """Random sequential addition: n seeds in [lo, hi], pairwise >= dmin, >= dmin/2 from the faces."""
    pts = np.zeros((0, 3))
    for _ in range(2000 * n):
        p = lo + 0.5 * dmin + rng.random(3) * (hi - lo - dmin)
        if not len(pts) or np.min(np.linalg.norm(pts - p, axis=1)) >= dmin:
            pts = np.vstack([pts, p])
            if len(pts) == n:
                return pts
    tfail(f"--random {n}: could not place {n} seeds {dmin:g} apart in the box (lower --min-dist)")


def read_centres(path):
    """x y z [r] per line ('#' comments); returns (seeds, radii or None)."""
    rows, withr = [], None
    try:
        lines = open(path).read().splitlines()
    except OSError as e:
        tfail(f"--centres {path}: {e.strerror}")
    for k, line in enumerate(lines, 1):
        line = line.split("#")[0].strip()
        if not line:
            continue
        try:
            v = [float(x) for x in line.replace(",", " ").split()]
        except ValueError:
            v = []
        if len(v) not in (3, 4) or not all(map(math.isfinite, v)) or (len(v) == 4 and v[3] <= 0):
            tfail(f"--centres {path} line {k}: expected 'x y z' or 'x y z r' (r > 0), got '{line}'")
        if withr is None:
            withr = len(v) == 4
        elif withr != (len(v) == 4):
            tfail(f"--centres {path} line {k}: give r on every line or on none")
        rows.append(v)
    if not rows:
        tfail(f"--centres {path}: no centres in the file")
    rows = np.array(rows)
    return rows[:, :3], (rows[:, 3] if withr else None)


def power_cells(seeds, radii, lo, hi, stage="the cells' polyhedra"):
    """Laguerre (power) cells of the seeds with weights radii^2, clipped by the box [lo, hi].

    Returns per cell: dict(normals, offsets, nbr) of its faces n.x <= o (nbr: the cell across, or
    -1 for a box face), volume and centroid of the polyhedron."""
    from scipy.optimize import linprog
    from scipy.spatial import ConvexHull, HalfspaceIntersection, cKDTree
    n = len(seeds)
    w = radii ** 2
    scale = float(np.max(hi - lo))
    box_n = np.vstack([np.eye(3), -np.eye(3)])
    box_o = np.concatenate([hi, -lo])
    near = None
    if n > 80:  # faces come from near seeds only: keep the 60 nearest as candidates
        near = cKDTree(seeds).query(seeds, k=61)[1][:, 1:]
    cells = []
    for i in range(n):
        progress(n, f"{stage}: {i + 1} of {n}", i + 1, n)
        cand = np.delete(np.arange(n), i) if near is None else near[i]
        diff = seeds[cand] - seeds[i]
        dist = np.linalg.norm(diff, axis=1)
        nrm = np.vstack([diff / dist[:, None], box_n])
        # |x - s_i|^2 - w_i <= |x - s_j|^2 - w_j  <=>  2 x.(s_j - s_i) <= |s_j|^2 - |s_i|^2 - w_j + w_i
        off = (np.sum(seeds[cand] ** 2, 1) - seeds[i] @ seeds[i] - w[cand] + w[i]) / (2 * dist)
        off = np.concatenate([off, box_o])
        nbr = np.concatenate([cand, -np.ones(6, int)])
        # Chebyshev centre (deepest point): an interior point even where the seed is outside its cell
        lp = linprog(np.r_[0, 0, 0, -1.0], A_ub=np.column_stack([nrm, np.ones(len(nrm))]), b_ub=off,
                     bounds=[(None, None)] * 3 + [(0, None)], method="highs")
        if lp.status != 0 or lp.x[3] <= 1e-9 * scale:
            tfail(f"cell {i + 1} (seed {seeds[i]}) is empty in the power diagram: its radius is too "
                  f"small next to its neighbours'")
        hs = HalfspaceIntersection(np.column_stack([nrm, -off]), lp.x[:3])
        verts = hs.intersections
        hull = ConvexHull(verts)
        # volume and centroid from the tetrahedra (interior point, hull facet)
        a, b, c = (verts[hull.simplices[:, k]] - lp.x[:3] for k in range(3))
        vt = np.abs(np.einsum("ij,ij->i", a, np.cross(b, c))) / 6.0
        g = (vt[:, None] * (a + b + c)).sum(0) / (4.0 * vt.sum())
        # second moment about the centroid: a tetrahedron (0, a, b, c) contributes
        # V/20 (a a^T + b b^T + c c^T + (a+b+c)(a+b+c)^T) about its vertex 0
        sm = sum(np.einsum("t,ti,tj->ij", vt, v, v) for v in (a, b, c, a + b + c)) / 20.0
        moment = sm / vt.sum() - np.outer(g, g)
        # a plane is a face when the vertices on it span an area (not an edge or a corner)
        on = np.abs(verts @ nrm.T - off) < 1e-9 * scale
        active = np.zeros(len(nrm), bool)
        area = np.zeros(len(nrm))
        for k in np.nonzero(on.sum(0) >= 3)[0]:
            v = verts[on[:, k]]
            active[k] = np.linalg.svd(v - v.mean(0), compute_uv=False)[1] > 1e-6 * scale
            if active[k]:   # the face polygon's area, in the plane's own 2-D coordinates
                e = np.linalg.svd(v - v.mean(0))[2][:2]
                area[k] = ConvexHull((v - v.mean(0)) @ e.T).volume
        cells.append(dict(normals=nrm[active], offsets=off[active], nbr=nbr[active],
                          face_area=area[active], volume=float(vt.sum()), centroid=lp.x[:3] + g,
                          moment=moment, inradius=float(lp.x[3])))
    return cells


def gauge_radius(u, normals, depth, p, free=None):
    """Radial gauge of the rounded polyhedron: r(u) = [sum_k max(0, u.n_k/d_k)^p + w(u) R(u)^-p]^(-1/p).

    u (C, V, 3) unit directions; normals (C, K, 3), depth (C, K) > 0 of the faces shared with a
    neighbour (padding: normal 0). free: None (the faces are all there is), or (fnormals (C, F, 3),
    fdepth (C, F), metric (C, 3, 3)) of the faces without a neighbour and the dome, the ellipsoid
    x^T M x = 1 about the centre (R(u) = (u^T M u)^-1/2). The dome bounds a cell only towards its
    free faces: w(u) = sum_free t^p / sum_all t^p is 1 where a free face is the nearest plane and 0
    where a shared face is, so shared faces stay flat out to their edges. Sums of powers in log
    space (log-sum-exp): t^p underflows for a sharpness of a few thousand."""
    dmin = depth.min(axis=1)
    if free is not None:
        dmin = np.minimum(dmin, free[1].min(axis=1))
    dmin = dmin[:, None, None]

    def log_powers(nrm, dep):   # p log(t dmin), -inf where u faces away from the plane
        t = np.einsum("cvj,ckj->cvk", u, nrm) * (dmin / dep[:, None, :])
        with np.errstate(divide="ignore"):
            return p * np.log(np.maximum(t, 0.0))

    def lse(x, axis=-1):
        m = np.max(x, axis=axis, keepdims=True)
        m = np.where(np.isfinite(m), m, 0.0)
        with np.errstate(divide="ignore"):
            return (m + np.log(np.sum(np.exp(x - m), axis=axis, keepdims=True))).squeeze(axis)

    shared = log_powers(normals, depth)
    total = lse(shared)
    if free is not None:
        fnormals, fdepth, metric = free
        lfree = log_powers(fnormals, fdepth)
        lw = lse(lfree) - lse(np.concatenate([shared, lfree], axis=2))
        with np.errstate(divide="ignore"):   # a cell without free faces has no dome (metric 0)
            ldome = 0.5 * p * np.log(np.einsum("cvi,cij,cvj->cv", u, metric, u) * dmin[:, :, 0] ** 2)
        total = lse(np.stack([total, np.where(np.isfinite(lw), lw + ldome, -np.inf)], -1))
    return dmin[:, :, 0] * np.exp(-total / p)


def territory_volumes(cells, centres, normals, depth, free, level=5, chunk=16):
    """Per cell the volume of its territory: the polyhedron where it has neighbours, the dome of
    --surface round beyond its free faces (the gauge without gap at the largest sharpness, on a
    fine icosphere; a cell without free faces is its polyhedron, exactly)."""
    vol = np.array([c["volume"] for c in cells])
    if free is None:
        return vol
    unit, tri, _ = icosphere(level)
    rounded = np.nonzero(np.isfinite(free[1]).any(axis=1))[0]
    for k in range(0, len(rounded), chunk):   # in chunks: the table is cells x directions x faces
        sel = rounded[k:k + chunk]
        u = np.broadcast_to(unit, (len(sel), len(unit), 3))
        r = gauge_radius(u, normals[sel], depth[sel], MAX_SHARPNESS,
                         tuple(f[sel] for f in free))
        vol[sel] = mesh_volumes(u * r[..., None], np.zeros((len(sel), 3)), tri)
    return vol


def check_walls(x, centres, tri, edges):
    """Every wall closed, consistently outward-oriented, Euler characteristic 2, star-shaped around
    its centre (positive volume, every normal pointing away from it, solid angle 4 pi)."""
    directed = {}
    for t in tri:
        for u, v in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            directed[(u, v)] = directed.get((u, v), 0) + 1
    closed = (len(directed) == 2 * len(edges) and all(directed.get((u, v)) == 1 and
              directed.get((v, u)) == 1 for u, v in edges))
    euler = x.shape[1] - len(edges) + len(tri)
    if not closed or euler != 2:
        tfail(f"the wall mesh is not a closed oriented sphere (Euler characteristic {euler})")
    r = x - centres[:, None, :]
    a, b, c = r[:, tri[:, 0]], r[:, tri[:, 1]], r[:, tri[:, 2]]
    out = np.einsum("ctj,ctj->ct", np.cross(b - a, c - a), a + b + c)
    vol = np.einsum("ctj,ctj->c", a, np.cross(b, c)) / 6.0
    la, lb, lc = (np.linalg.norm(v, axis=2) for v in (a, b, c))
    dot = lambda p, q: np.einsum("ctj,ctj->ct", p, q)  # noqa: E731
    omega = 2 * np.arctan2(np.einsum("ctj,ctj->ct", a, np.cross(b, c)),
                           la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la).sum(1)
    for k in range(len(x)):
        if vol[k] <= 0 or out[k].min() <= 0 or abs(omega[k] - 4 * math.pi) > 1e-6:
            tfail(f"the wall of cell {k + 1} is not closed and outward-oriented around its centre "
                  f"(volume {vol[k]:.4g}, solid angle {omega[k]:.6g}); raise --sharpness or --smooth, "
                  f"or move its seed")
    return vol


def lamella_bonds(x, mol, cutoff):
    """For every wall node, a bond to the nearest node of any other cell within cutoff; unique."""
    from scipy.spatial import cKDTree
    tree = cKDTree(x)
    k = 32
    while True:
        d, j = tree.query(x, k=min(k, len(x)), distance_upper_bound=cutoff)
        j = np.minimum(j, len(x) - 1)
        other = np.isfinite(d) & (mol[j] != mol[:, None])
        # undecided: no other-cell node among the k found, yet the k-th is still within the cutoff
        if k >= len(x) or not np.any(~other.any(1) & np.isfinite(d[:, -1])):
            break
        k *= 2
    has = other.any(1)
    first = np.argmax(other, axis=1)
    i = np.nonzero(has)[0]
    pairs = np.sort(np.column_stack([i, j[i, first[i]]]), axis=1)
    return np.unique(pairs, axis=0) if len(pairs) else np.zeros((0, 2), int)


def unglued_faces(cells, pairs):
    """The faces of the Voronoi/Laguerre diagram that got no lamella bond: (i, j, face area)."""
    out = []
    for i, c in enumerate(cells):
        for j, a in zip(c["nbr"], c["face_area"]):
            if i < j and (i, j) not in pairs:
                out.append((i, int(j), float(a)))
    return out


def tissue_seeds(lattice, random, centres, n, R, spacing, size, min_dist, seed, nv, nfluid):
    """The seeds (lattice, random or from a file), their radii (a file's, or None), the block
    [lo, hi] around them and a description."""
    radii, vcell = None, 4.0 / 3.0 * math.pi * R ** 3
    if lattice:
        if len(n) != 3:
            tfail(f"--n needs three positive integers NX NY NZ, got {' '.join(map(str, n))}")
        basis, rep = LATTICES[lattice]
        check_count("tissue", int(np.prod(n)) * len(basis) * (nv + nfluid),
                    f"--lattice {lattice} --n {' '.join(map(str, n))} of {nv} wall nodes "
                    f"and {nfluid} fluid particles a cell")
        per_seed = float(np.prod(rep)) / len(basis)  # lattice volume per seed, in a^3
        a = spacing if spacing is not None else (vcell / per_seed) ** (1.0 / 3.0)
        seeds, lo, hi = lattice_seeds(lattice, n, a)
        how = f"lattice {lattice} {'x'.join(map(str, n))}, constant {a:.6g}"
    elif spacing is not None:
        tfail("--spacing (the lattice constant) needs --lattice")
    elif random is not None:
        check_count("tissue", random * (nv + nfluid),
                    f"--random {random} of {nv} wall nodes and {nfluid} fluid particles a cell")
        size = np.array(size if size else [(random * vcell) ** (1.0 / 3.0)] * 3, float)
        vcell = np.prod(size) / random
        dmin = min_dist if min_dist is not None else 0.7 * vcell ** (1.0 / 3.0)
        lo, hi = -0.5 * size, 0.5 * size
        seeds = random_seeds(random, lo, hi, dmin, np.random.default_rng(seed))
        how = f"random {random} seeds (seed {seed}, min distance {dmin:.4g})"
    else:
        seeds, radii = read_centres(centres)
        check_count("tissue", len(seeds) * (nv + nfluid),
                    f"--centres {centres} ({len(seeds)} cells) of {nv} wall nodes and "
                    f"{nfluid} fluid particles a cell")
        if radii is None and len(seeds) > 1:
            from scipy.spatial import cKDTree
            pad = 0.5 * np.median(cKDTree(seeds).query(seeds, k=2)[0][:, 1])
        else:
            pad = radii if radii is not None else R
        lo, hi = (seeds - np.reshape(pad, (-1, 1))).min(0), (seeds + np.reshape(pad, (-1, 1))).max(0)
        how = f"centres from {centres}" + (" (Laguerre, radii given)" if radii is not None else "")
    return seeds, radii, lo, hi, how


def place_seeds(seeds, radii, lo, hi, tissue_box, elongate, lloyd, gap):
    """The seeds in their block (--tissue-box), stretched (--elongate, at the same cell volume),
    moved by Lloyd's iterations, and checked for room for the gap between them."""
    ell = np.array(elongate if elongate else (1.0, 1.0, 1.0), float)
    ell = ell / np.prod(ell) ** (1.0 / 3.0)  # same cell volume, elongated in the ratio given
    if tissue_box:
        tb = np.array(tissue_box, float)
        lo, hi = tb[0::2], tb[1::2]
        if np.any(hi <= lo) or np.any(seeds < lo) or np.any(seeds > hi):
            tfail("--tissue-box must be xlo xhi ylo yhi zlo zhi (lo < hi) and contain every seed")
    seeds, lo, hi = seeds * ell, lo * ell, hi * ell
    radii = np.zeros(len(seeds)) if radii is None else radii
    for it in range(lloyd):
        seeds = np.array([c["centroid"] for c in power_cells(
            seeds, radii, lo, hi, stage=f"Lloyd iteration {it + 1} of {lloyd}")])
    if len(seeds) > 1:
        from scipy.spatial import cKDTree
        dd, jj = cKDTree(seeds).query(seeds, k=2)
        k = int(np.argmin(dd[:, 1]))
        other = jj[k, 1] if jj[k, 1] != k else jj[k, 0]   # two equal seeds: either may come first
        if dd[k, 1] < 2 * gap:
            tfail(f"seeds of cells {min(k, other) + 1} and {max(k, other) + 1} are {dd[k, 1]:.4g} apart, "
                  f"closer than twice the gap ({2 * gap:g}): move them or lower --gap")
    return seeds, radii, lo, hi


def remove_cells(cells, seeds, radii, remove_box, how):
    """A notch or a hole: the cells whose seeds lie inside remove_box are taken out after the
    diagram, so the cells around keep their shape and their faces towards the space become free
    surface."""
    rb = np.array(remove_box, float)
    gone = np.all((seeds >= rb[0::2]) & (seeds <= rb[1::2]), axis=1)
    if gone.all() or not gone.any():
        tfail(f"--remove-box {' '.join(f'{v:g}' for v in rb)}: expected a box holding some of the "
              f"{len(cells)} seeds but not all, it holds {int(gone.sum())}")
    remap = np.where(gone, -1, np.cumsum(~gone) - 1)    # old index -> new, -1: taken out
    for c in cells:
        c["nbr"] = np.where(c["nbr"] >= 0, remap[c["nbr"]], -1)
    cells = [c for c, g in zip(cells, gone) if not g]
    return cells, seeds[~gone], radii[~gone], how + f", {int(gone.sum())} removed by --remove-box"


@dataclass
class Gauge:
    """The rounded, offset cells the walls are mapped onto (gauge_radius): per cell its centre,
    the normals and depths of its shared faces, and free = (normals, depths, dome metric) of its
    free faces (None where the block has none: --surface cut)."""
    centres: np.ndarray
    normals: np.ndarray
    depth: np.ndarray
    free: tuple = None

    def onto(self, x, p):
        """Radial projection of walls x (C, V, 3) onto the rounded cells of sharpness p."""
        r = x - self.centres[:, None, :]
        u = r / np.linalg.norm(r, axis=2)[..., None]
        return self.centres[:, None, :] + u * gauge_radius(u, self.normals, self.depth, p,
                                                           self.free)[..., None]


def cell_gauge(cells, gap, surface, dome):
    """The Gauge of the cells: offset inward by gap/2 from their shared faces, bounded by a dome
    towards their free faces (--surface round) or by the faces themselves (cut).

    The tissue's free surface. "cut": the block's faces are flat, as a sample cut from a fruit.
    "round" (default): towards its free faces (no neighbour there) a cell is bounded by a dome,
    the ellipsoid with the polyhedron's second moments (its shape) and volume, about its
    centroid: a cube's is its equivalent sphere (0.620 a), an elongated cell's is elongated
    alike; scaled by --dome. A flat free face cannot carry a pressure without bulging, and inflation
    would first have to stretch it into a dome (to 16% for a 48 um face at 364 kPa in the
    stiff wall, four times the tethers' critical stretch of 4%): the outer walls would start a
    compression already torn. The dome acts only where a free face is the nearest plane
    (gauge_radius): faces between cells, balanced by the neighbour's turgor, stay flat to their
    edges and glued over their whole area."""
    ncell, kmax = len(cells), max(len(c["normals"]) for c in cells)
    centres = np.array([c["centroid"] for c in cells])
    normals, depth = np.zeros((ncell, kmax, 3)), np.full((ncell, kmax), np.inf)
    fnormals, fdepth = np.zeros((ncell, kmax, 3)), np.full((ncell, kmax), np.inf)
    metric = np.zeros((ncell, 3, 3))
    rounded = False
    for i, c in enumerate(cells):
        shared = np.ones(len(c["normals"]), bool)
        if surface == "round" and (c["nbr"] < 0).any():
            shared = c["nbr"] >= 0
            f = int((~shared).sum())
            fnormals[i, :f] = c["normals"][~shared]
            fdepth[i, :f] = c["offsets"][~shared] - c["normals"][~shared] @ centres[i]
            m = np.linalg.inv(5.0 * c["moment"])
            # scaled to the polyhedron's volume: a cube's is its equivalent sphere, the single
            # cell's shape; a cell free all round is the paper's sphere of its volume
            ve = 4.0 / 3.0 * math.pi / math.sqrt(np.linalg.det(m))
            metric[i] = m * (ve / c["volume"]) ** (2.0 / 3.0) / dome ** 2
            rounded = True
        k = int(shared.sum())
        normals[i, :k] = c["normals"][shared]
        depth[i, :k] = c["offsets"][shared] - c["normals"][shared] @ centres[i] - 0.5 * gap
        if k and depth[i, :k].min() <= 0:
            tfail(f"cell {i + 1} is thinner than the gap ({gap:g}) around its centroid "
                  f"{centres[i]}: lower --gap or spread the seeds")
    return Gauge(centres, normals, depth, (fnormals, fdepth, metric) if rounded else None)


def sharpness_for_air(gauge, start, tri, territory, air, sharpness):
    """The sharpness p whose walls leave the porosity air between them, and the porosity at
    --sharpness.

    Intercellular air where it is in parenchyma: at the cells' edges and corners, with the
    faces between cells still in contact and glued. Rounder cells (a smaller sharpness p)
    leave more air; p is found by bisection in log p on the unsmoothed walls (smoothing
    moves nodes along the surface: the volume hardly changes), and a final uniform scaling
    of less than a percent makes the porosity exact. Shrinking every wall instead would pull
    the faces apart beyond the bond cutoff: no lamella at all."""
    def air_at(q):
        return 1.0 - mesh_volumes(gauge.onto(start, q), gauge.centres, tri).sum() / territory.sum()
    porosity0, most = air_at(sharpness), air_at(2.0)
    if not porosity0 <= air <= most:
        tfail(f"--air {air:g}: expected a porosity between {porosity0:.4f} (the block at "
              f"--sharpness {sharpness:g}) and {most:.4f} (the roundest cells, sharpness 2)"
              + ("; --surface cut leaves more room" if gauge.free is not None else ""))
    lo_p, hi_p = math.log(2.0), math.log(sharpness)
    for _ in range(40):
        mid = 0.5 * (lo_p + hi_p)
        lo_p, hi_p = (mid, hi_p) if air_at(math.exp(mid)) > air else (lo_p, mid)
    return math.exp(0.5 * (lo_p + hi_p)), porosity0


def per_node(m, v):
    """Sparse incidence m (nodes, n) times per-cell values v (cells, n, 3) -> (cells, nodes, 3)."""
    out = m @ v.transpose(1, 0, 2).reshape(v.shape[1], -1)
    return out.reshape(m.shape[0], v.shape[0], 3).transpose(1, 0, 2)


def smooth_walls(gauge, x, p, tri, inc, smooth):
    """smooth tangential, area-weighted Laplacian steps (towards the area-weighted mean of the
    node's triangle centroids: evens out the triangle areas), each back onto the surface along
    the ray."""
    for it in range(smooth):
        a, b, c = x[:, tri[:, 0]], x[:, tri[:, 1]], x[:, tri[:, 2]]
        cr = np.cross(b - a, c - a)
        ar = np.linalg.norm(cr, axis=2)[..., None]
        vn = per_node(inc, cr)
        vn /= np.linalg.norm(vn, axis=2)[..., None]
        step = per_node(inc, ar * (a + b + c) / 3.0) / per_node(inc, np.repeat(ar, 3, axis=2)) - x
        step -= np.einsum("cvj,cvj->cv", step, vn)[..., None] * vn
        x = gauge.onto(x + 0.5 * step, p)
        progress(len(x), f"smoothing the walls, {it + 1} of {smooth}", it + 1, smooth)
    return x


@dataclass
class Walls:
    """The placed walls: positions x (cells, nodes, 3) of the mesh (tri, edges), their volumes,
    areas and each node's tributary area trib (a third of its triangles'), the triangles' quality
    (areas, angles, edges, barycentre distances: wall_quality), the sharpness p they were made
    with, the porosity, and the porosity at --sharpness (porosity0)."""
    x: np.ndarray
    tri: np.ndarray
    edges: np.ndarray
    vol: np.ndarray
    wall_area: np.ndarray
    trib: np.ndarray
    ang: np.ndarray
    elen: np.ndarray
    bary: np.ndarray
    p: float
    porosity: float
    porosity0: float


def build_walls(gauge, territory, level, sharpness, air, smooth, min_angle):
    """Each cell's icosphere mapped radially onto its rounded cell (at the sharpness that leaves
    --air between them), smoothed, checked and scaled to the porosity asked for."""
    from scipy import sparse
    unit, tri, edges = icosphere(level)
    nv, ncell = len(unit), len(gauge.centres)
    centres = gauge.centres
    start = np.broadcast_to(unit, (ncell, nv, 3)) + centres[:, None, :]
    p, porosity0 = sharpness, None
    if air is not None:
        p, porosity0 = sharpness_for_air(gauge, start, tri, territory, air, sharpness)
    x = gauge.onto(start, p)
    inc = sparse.coo_matrix((np.ones(3 * len(tri)), (tri.T.ravel(), np.tile(np.arange(len(tri)), 3))),
                            shape=(nv, len(tri))).tocsr()
    x = smooth_walls(gauge, x, p, tri, inc, smooth)
    vol = check_walls(x, centres, tri, edges)
    if air is not None:
        sc = ((1.0 - air) * territory.sum() / vol.sum()) ** (1.0 / 3.0)
        x = centres[:, None, :] + sc * (x - centres[:, None, :])
        vol = vol * sc ** 3
    else:
        porosity0 = 1.0 - vol.sum() / territory.sum()
    porosity = 1.0 - vol.sum() / territory.sum()
    area_t, ang, elen, bary = wall_quality(x, tri)
    if ang.min() < min_angle:
        k = int(np.argmin(ang.min(axis=(1, 2))))
        tfail(f"cell {k + 1} has a triangle angle of {ang.min():.3g} deg, below --min-angle "
              f"{min_angle:g}: raise --level or --smooth, or lower --sharpness")
    trib = per_node(inc, np.repeat(area_t[..., None], 3, axis=2))[..., 0] / 3.0   # (ncell, nv)
    return Walls(x, tri, edges, vol, area_t.sum(1), trib, ang, elen, bary, p, porosity, porosity0)


def tissue_fluid(walls, centres, size, nfluid, fluid_spacing, inset):
    """One fluid lattice spacing for all cells (--fluid-spacing, or the one that puts nfluid in the
    cell of mean volume), and each cell's fluid at least inset inside its wall."""
    x, tri, vol = walls.x, walls.tri, walls.vol
    ncell, nv = x.shape[:2]
    rmax = np.linalg.norm(x - centres[:, None, :], axis=2).max(axis=1)
    if fluid_spacing is not None:
        spacing = fluid_spacing
        check_count("tissue", ncell * nv + int(sum(lattice_count_bound(r, spacing) for r in rmax)),
                    f"--fluid-spacing {spacing:g} in {ncell} cells")
    elif nfluid > 0:
        m = int(np.argmin(np.abs(vol - vol.mean())))
        # no fluid fits where the inset reaches past the wall's nearest point to the centre
        a, b, c = (x[m][tri[:, k]][None] - centres[m] for k in range(3))
        rin = float(wall_distance(np.zeros((1, 3)), a, b, c)[0]) - inset
        if not rin > 0:
            tfail(f"--inset: expected a distance smaller than the cell's inner radius "
                  f"{rin + inset:.4g} (the fluid stays that far inside the wall), got {inset:g}")
        spacing = spacing_for_count(lambda s: fluid_in_wall(x[m], tri, centres[m], s, inset),
                                    nfluid, 1e-3 * size, 2.0 * size, iterations=50)
    else:
        spacing = 0.0
    fluid = [fluid_in_wall(x[i], tri, centres[i], spacing, inset) if spacing > 0 else np.zeros((0, 3))
             for i in range(ncell)]
    return spacing, fluid


@dataclass
class Lamella:
    """The middle lamella: cutoff, bonds (wall node index pairs, all walls numbered on), count
    per node (nlam), each node's lamella area (alam: its tributary area shared among its bonds),
    pairs {(i, j): (bonds, glued area)} of cells, each cell's neighbours, and the diagram's faces
    without a bond (unglued_faces)."""
    cutoff: float
    bonds: np.ndarray
    nlam: np.ndarray
    alam: np.ndarray
    pairs: dict
    nbrs: list
    unglued: list


def build_lamella(walls, cells, gap, bond_cutoff):
    """Bonds between facing wall nodes of different cells within the cutoff (default 1.5 gap); a
    warning for each face of the diagram left without one."""
    if bond_cutoff is not None and bond_cutoff <= gap:
        tfail(f"--bond-cutoff must exceed --gap ({gap:g}): facing walls start gap apart")
    cutoff = bond_cutoff if bond_cutoff is not None else 1.5 * gap
    ncell, nv = walls.x.shape[:2]
    xw, molw = walls.x.reshape(-1, 3), np.repeat(np.arange(ncell), nv)
    lam = lamella_bonds(xw, molw, cutoff)
    nlam = np.bincount(lam.ravel(), minlength=len(xw))
    alam = np.where(nlam > 0, walls.trib.ravel() / np.maximum(nlam, 1), 0.0)
    barea = 0.5 * (alam[lam[:, 0]] + alam[lam[:, 1]])
    pairs = {}
    for (i, j), ab in zip(molw[lam], barea):
        key = (min(i, j), max(i, j))
        n0, a0 = pairs.get(key, (0, 0.0))
        pairs[key] = (n0 + 1, a0 + ab)
    nbrs = [set() for _ in range(ncell)]
    for i, j in pairs:
        nbrs[i].add(j)
        nbrs[j].add(i)
    unglued = unglued_faces(cells, pairs)
    for i, j, a in unglued[:10]:
        print(f"cellgen.py tissue: warning: cells {i + 1} and {j + 1} share a face of {a:.4g} um^2 in "
              f"the diagram but no lamella bond (walls farther apart than --bond-cutoff {cutoff:g}, or "
              f"the face smaller than a wall triangle)", file=sys.stderr)
    if len(unglued) > 10:
        print(f"cellgen.py tissue: warning: {len(unglued) - 10} more faces without a lamella bond",
              file=sys.stderr)
    return Lamella(cutoff, lam, nlam, alam, pairs, nbrs, unglued)


def special_count(edges, ncell, nv, lam):
    """The most special neighbours of an atom, as LAMMPS counts them at read_data (1-2, 1-3, 1-4;
    unique) over the tethers and the lamella bonds lam (None: not glued)."""
    from scipy import sparse
    allb = np.vstack([(edges[None] + (np.arange(ncell) * nv)[:, None, None]).reshape(-1, 2)]
                     + ([lam] if lam is not None else []))
    n = ncell * nv
    A = sparse.coo_matrix((np.ones(2 * len(allb)), (np.r_[allb[:, 0], allb[:, 1]],
                          np.r_[allb[:, 1], allb[:, 0]])), shape=(n,) * 2).tocsr()
    A.data[:] = 1
    A2 = A @ A
    S = (A + A2 + A2 @ A).tocsr()
    S.setdiag(0)
    S.eliminate_zeros()
    return int(np.diff(S.indptr).max())


def tissue_atoms(walls, fluid, lam, glue, areal, m_fluid, rho0):
    """The atoms cell by cell (wall nodes, then fluid), their masses (areal density times the
    tributary area; the fluid's), densities and lamella areas, the tethers and lamella bonds
    (types 1 and 2) and the triangles."""
    x, tri, edges = walls.x, walls.tri, walls.edges
    ncell, nv = x.shape[:2]
    atoms, rmass, rho, alam_atom, bonds, angles = [], [], [], [], [], []
    wall_index = np.zeros(ncell * nv, int)
    for i in range(ncell):
        base = len(atoms)
        wall_index[i * nv:(i + 1) * nv] = base + np.arange(nv)
        atoms += [(i + 1, 1, *q) for q in x[i]] + [(i + 1, 2, *q) for q in fluid[i]]
        rmass += list(areal * walls.trib[i]) + [m_fluid] * len(fluid[i])
        rho += [0.0] * nv + [rho0] * len(fluid[i])
        alam_atom += list(lam.alam[i * nv:(i + 1) * nv] if glue else np.zeros(nv)) + [0.0] * len(fluid[i])
        bonds += [(base + a, base + b) for a, b in edges]
        angles += [(base + a, base + b, base + c) for a, b, c in tri]
    btype = [1] * len(bonds)
    if glue:
        bonds += [tuple(wall_index[b]) for b in lam.bonds]
        btype += [2] * len(lam.bonds)
    return atoms, rmass, rho, alam_atom, bonds, btype, angles


def tissue_statistics(head, counts, cells, seeds, walls, lam, fluid):
    """The statistics JSON: head (the settings and the block's volumes, in the file's order), the
    walls' porosity, volumes and quality, counts (maxlam, special, K, reach: the numbers read_data
    and pair_style cell/virtual need), each cell and each glued pair."""
    vol, wall_area = walls.vol, walls.wall_area
    centres = np.array([c["centroid"] for c in cells])
    nfl = np.array([len(f) for f in fluid])
    qual = dict(min_angle_deg=float(walls.ang.min()), min_edge=float(walls.elen.min()),
                max_edge=float(walls.elen.max()), max_barycentre_distance=float(walls.bary.max()),
                recommended_reach=counts["reach"])
    return dict(
        head, porosity=float(walls.porosity), porosity_without_air=float(walls.porosity0),
        volume_mean=float(vol.mean()), volume_rel_spread=float(vol.std() / vol.mean()),
        faces_mean=float(np.mean([len(c["normals"]) for c in cells])),
        neighbours_mean=float(np.mean([len(s) for s in lam.nbrs])),
        lamella_bonds=int(len(lam.bonds)) if head["glue"] else 0,
        max_lamella_bonds_per_node=counts["maxlam"], special_max=counts["special"],
        extra_special_per_atom=counts["K"], triangle_quality=qual,
        cell=[dict(id=i + 1, seed=[float(v) for v in seeds[i]], centre=[float(v) for v in centres[i]],
                   volume=float(vol[i]), wall_area=float(wall_area[i]), faces=len(cells[i]["normals"]),
                   free_faces=int((cells[i]["nbr"] < 0).sum()),
                   neighbours=sorted(int(j) + 1 for j in lam.nbrs[i]), nodes=walls.x.shape[1],
                   fluid=int(nfl[i]))
              for i in range(len(cells))],
        pairs=[dict(cells=[int(i) + 1, int(j) + 1], bonds=n, glued_area=float(ab))
               for (i, j), (n, ab) in sorted(lam.pairs.items())],
        unglued_faces=[dict(cells=[i + 1, j + 1], face_area=a) for i, j, a in lam.unglued])


def tissue_counts(walls, lam, glue):
    """What read_data and pair_style cell/virtual need: the most lamella bonds of a node (maxlam),
    the most special neighbours (special), read_data's extra/special/per/atom K, the largest
    barycentre-node distance (reach_need) and the reach recommended from it (25% above)."""
    ncell, nv = walls.x.shape[:2]
    special = special_count(walls.edges, ncell, nv, lam.bonds if glue else None)
    maxlam = int(lam.nlam.max()) if glue else 0
    deg = np.bincount(walls.edges.ravel(), minlength=nv)
    reach_need = float(walls.bary.max())
    return dict(maxlam=maxlam, special=special, K=maxlam * (1 + int(deg.max())) + 6,
                reach_need=reach_need, reach=math.ceil(1.25 * reach_need * 10 - 1e-9) / 10.0)


def report(title, st, counts, walls, lam, fluid, m_wall, air, path, output):
    """The summary on stdout."""
    nfl = np.array([len(f) for f in fluid])
    print(title)
    print(f"cells {st['cells']}: volume mean {walls.vol.mean():.6g} (spread "
          f"{walls.vol.std() / walls.vol.mean():.3%}), wall area mean {walls.wall_area.mean():.6g}, "
          f"faces/cell {st['faces_mean']:.3g}, neighbours/cell {st['neighbours_mean']:.3g}")
    print(f"porosity {walls.porosity:.4f} (without air {walls.porosity0:.4f}"
          + (f"; --air rounds the cells to sharpness {walls.p:.4g}" if air is not None else "")
          + f"), tissue box volume {st['box_volume']:.6g}")
    print(f"fluid: spacing {st['fluid_spacing']:.6g}, {nfl.sum()} particles ({nfl.min()}..{nfl.max()} per "
          f"cell), mass {st['fluid_mass']:.6g}; wall node mass mean {m_wall:.6g} (areal density x "
          f"tributary area)")
    print(f"lamella: {st['lamella_bonds']} bonds (cutoff {lam.cutoff:g}), {len(lam.pairs)} "
          f"{'glued' if st['glue'] else 'facing (--no-glue: not bonded)'} pairs, "
          f"area {sum(v[1] for v in lam.pairs.values()):.6g}, max {counts['maxlam']} per node")
    qual = st["triangle_quality"]
    print(f"triangles: min angle {qual['min_angle_deg']:.2f} deg, edges {qual['min_edge']:.4g}.."
          f"{qual['max_edge']:.4g}, max barycentre-node distance {counts['reach_need']:.4g} -> "
          f"pair_style cell/virtual reach >= {counts['reach']:g}")
    print(f"special neighbours: max {counts['special']} per atom; read_data ... extra/special/per/atom "
          f"{counts['K']}")
    print(f"statistics: {path}; model lengths of level {st['level']}: {output}.lmp")


def build_tissue(output, lattice=None, random=None, centres=None, n=(2, 2, 2), radius=None,
                 spacing=None, size=None, min_dist=None, lloyd=0, seed=1, tissue_box=None,
                 remove_box=None, elongate=None, level=3, gap=2.56, sharpness=16.0, surface="round",
                 dome=1.0, smooth=100, min_angle=20.0, air=None, nfluid=440, fluid_spacing=None,
                 inset=None, bond_cutoff=None, no_glue=False, rho0=1.0, wall_areal_density=None,
                 pad=10.0, stats=None, bending=False):
    """Write the tissue's data file (output), its model lengths (output.lmp) and statistics (stats,
    default output with .json); the options are cellgen.py tissue's (docs/cellgen.rst)."""
    nv = 10 * 4 ** level + 2
    R = R_CELL if radius is None else radius
    seeds, radii, lo, hi, how = tissue_seeds(lattice, random, centres, n, R, spacing, size, min_dist, seed,
                                             nv, nfluid)
    seeds, radii, lo, hi = place_seeds(seeds, radii, lo, hi, tissue_box, elongate, lloyd, gap)
    cells = power_cells(seeds, radii, lo, hi)
    if remove_box:
        cells, seeds, radii, how = remove_cells(cells, seeds, radii, remove_box, how)
    ncell, csize = len(cells), np.mean([c["volume"] for c in cells]) ** (1.0 / 3.0)
    if gap >= 0.5 * csize:
        tfail(f"--gap must be smaller than half the cell size ({0.5 * csize:.4g}), got {gap:g}")
    gauge = cell_gauge(cells, gap, surface, dome)
    # the air is the space between the walls within the tissue: each cell's territory (its
    # polyhedron, and where it is round its dome beyond the free faces) less its wall's volume
    territory = territory_volumes(cells, gauge.centres, gauge.normals, gauge.depth + 0.5 * gap, gauge.free)
    walls = build_walls(gauge, territory, level, sharpness, air, smooth, min_angle)
    # the level's fluid-wall contact distance; a level without a row in the level table (a coarser
    # mesh, with no model lengths) keeps level 3's
    inset = inset if inset is not None else params.LEVELS.get(level, params.LEVELS[3])["r0"]
    fspacing, fluid = tissue_fluid(walls, gauge.centres, csize, nfluid, fluid_spacing, inset)
    lam, glue = build_lamella(walls, cells, gap, bond_cutoff), not no_glue
    counts = tissue_counts(walls, lam, glue)
    areal = wall_areal_density if wall_areal_density is not None else WALL_AREAL
    m_fluid = rho0 * fspacing ** 3 if fspacing > 0 else 1.0
    atoms, rmass, rho, alam_atom, bonds, btype, angles = tissue_atoms(walls, fluid, lam, glue, areal,
                                                                      m_fluid, rho0)
    pts = np.array([q[2:] for q in atoms])
    blo, bhi = pts.min(0) - pad, pts.max(0) + pad
    m_wall = areal * walls.wall_area.sum() / (ncell * nv)
    title = (f"cellgen tissue: {ncell} cells ({how}), level {level} ({nv} wall nodes per cell), "
             f"gap {gap:g}, fluid spacing {fspacing:.10g}, rho0 {rho0:g}, wall areal density "
             f"{areal:.6g}, {len(lam.bonds) if glue else 0} lamella bonds; read_data ... "
             f"extra/special/per/atom {counts['K']}; pair_style cell/virtual reach >= {counts['reach']:g}; "
             f"units micro")
    write_data(output, title, [blo[0], bhi[0], blo[1], bhi[1], blo[2], bhi[2]], atoms, bonds, angles,
               [m_wall, m_fluid], pts, rho, bond_types=(2, btype), rmass=rmass, alam=alam_atom,
               bending=bending)
    write_lengths(output + ".lmp", "tissue", level, counts["reach"], counts["K"])
    head = dict(cells=ncell, seeds=how, level=level, wall_nodes_per_cell=nv, gap=gap, sharpness=walls.p,
                bond_cutoff=lam.cutoff, glue=glue, fluid_spacing=fspacing, inset=inset, fluid_mass=m_fluid,
                rho0=rho0, wall_areal_density=areal,
                tissue_box=[float(v) for v in np.ravel(np.column_stack([lo, hi]))],
                box_volume=float(np.prod(hi - lo)), block_volume=float(sum(c["volume"] for c in cells)),
                territory_volume=float(territory.sum()))
    st = tissue_statistics(head, counts, cells, seeds, walls, lam, fluid)
    path = stats if stats else os.path.splitext(output)[0] + ".json"
    with open(path, "w") as f:
        json.dump(st, f, indent=1)
    report(title, st, counts, walls, lam, fluid, m_wall, air, path, output)
