#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""cellgen: build LAMMPS data files for the cellmech plant-cell model.

Geometry of one cell (Van Liedekerke et al. 2010, docs/model.md section 2.2):
  * wall: icosahedral geodesic sphere of subdivision level n (10*4^n+2 nodes: 12, 42, 162, 642,
    2562, 10242), radius R, nodes projected on the sphere; tethers = mesh edges (LAMMPS bonds);
    triangles = LAMMPS angles (a, b, c) ordered so that (b-a)x(c-a) points OUT of the cell. Angles
    travel with atoms through MPI migration and restart files, which is what later styles need.
    The middle atom b owns its triangle (the orientation/ownership contract of src/cell_fields.h).
  * fluid: a cubic lattice clipped to the inside of the wall (as in the paper), by count or spacing.
  * per-atom cell data in a `cell` section (mass, density, density rate, rest position), read into
    `fix cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes` with
    `read_data FILE fix cell NULL cell`; bond style cell/tether takes each tether's rest length
    from the rest positions, pair style cell/sph the fluid's mass and density.
Masses come from physical inputs: fluid density rho0 times each particle's lattice cell volume,
and the wall mass (total, or areal density times the sphere area). Units are LAMMPS `units micro` (um, pg, us)
unless --units si is given (m, kg, s).

Atom types: 1 = wall, 2 = fluid. Bond type 1 = tether. Angle type 1 = triangle. One molecule ID
per cell (1, 2, ...). atom_style molecular: id mol type x y z.
--bending (cell, sheet, tissue) adds dihedral type 1 = hinge: one LAMMPS dihedral i-j-k-l per edge
shared by two wall triangles, j-k the shared edge, (i, j, k) and (l, k, j) the two triangles in the
orientation of their angles (dihedral style cell/bending); without it the file has no dihedrals.

Usage:
  cellgen.py cell -o cell.data [--level 4] [--radius 30] [--nfluid 3500 | --spacing S | --nfluid 0]
                  [--centres "0,0,0;70,0,0"] [--rho0 1] [--wall-mass 1.3e4 | --wall-areal-density X]
                  [--pad 10] [--box xlo xhi ylo yhi zlo zhi] [--units micro|si]
  cellgen.py sheet -o sheet.data [--nx 20 --ny 20] [--bond 2.5] [--orient x|y] [--thickness 0.126]
                   [--rho-s 8.956]
  cellgen.py tissue -o tissue.data (--lattice sc|bcc|fcc|hex [--n 2 2 2] [--radius 30 | --spacing A]
                    | --random N [--size LX LY LZ] [--min-dist D] | --centres FILE) [--lloyd K]
                    [--seed 1] [--elongate ax ay az] [--level 3] [--gap 2.56] [--sharpness 16]
                    [--air F] [--nfluid 440 | --fluid-spacing S] [--inset 3.2] [--bond-cutoff C]
                    [--no-glue] [--stats FILE]        (docs/cellgen.rst, "Tissue"; needs scipy)
"""
import argparse
import math
import os
import re
import sys

import numpy as np

from .. import params

# The most particles one data file may hold. cellgen keeps every particle in Python lists while it
# writes the file (0.44 kB of memory each, measured at 3e5), so this bound keeps a run within about
# 1 GB and half a minute: a count beyond it (a typo such as --nfluid 100000000, or a tiny --spacing) is refused
# before any work instead of filling the memory until the kernel kills the process. It is 80 times
# the paper's finest cell (10242 wall nodes + 14000 fluid particles).
MAX_PARTICLES = 2_000_000
# Bounds on the tissue's iterations: Lloyd's iterations converge in tens (the seeds' centroids move
# by less than 1% of a cell after 20 on a random block) and smoothing in hundreds; a sharpness
# beyond 1000 is the polyhedron itself to 0.1% (an edge is pulled in by 2^(-1/p)). A larger value
# is a typo that would run for hours.
MAX_LLOYD, MAX_SMOOTH, MAX_SHARPNESS = 100, 10_000, 1000.0


def fail(what, msg):
    """Stop with one line and exit status 2, as argparse does for a bad argument."""
    print(f"cellgen.py {what}: error: {msg}", file=sys.stderr)
    sys.exit(2)


class Parser(argparse.ArgumentParser):
    """argparse that reports a bad argument in one line (without the usage block)."""

    def __init__(self, *a, **k):
        super().__init__(*a, **k)
        # argparse takes '-1e9' for an option (its pattern knows '-1' and '-1.5' only), so
        # '--remove-box -1e9 ...' read as a missing value
        self._negative_number_matcher = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message}\n")


def number(above=None, minimum=None, below=None, maximum=None):
    """argparse type: a finite float with bounds (nan and inf pass float() but no geometry)."""
    cond = " and".join(f" {op} {v:g}" for op, v in ((">", above), (">=", minimum), ("<", below),
                                                    ("<=", maximum)) if v is not None)

    def parse(text):
        try:
            v = float(text)
        except ValueError:
            v = math.nan
        if not (math.isfinite(v) and (above is None or v > above) and (minimum is None or v >= minimum)
                and (below is None or v < below) and (maximum is None or v <= maximum)):
            raise argparse.ArgumentTypeError(f"expected a finite number{cond}, got '{text}'")
        return v
    return parse


def whole(minimum=None, maximum=None):
    """argparse type: an integer within [minimum, maximum]."""
    cond = " and ".join(f"{op} {v}" for op, v in ((">=", minimum), ("<=", maximum)) if v is not None)

    def parse(text):
        try:
            v = int(text)
        except ValueError:
            v = None
        if v is None or (minimum is not None and v < minimum) or (maximum is not None and v > maximum):
            raise argparse.ArgumentTypeError(f"expected a whole number {cond}, got '{text}'")
        return v
    return parse


def output_file(text):
    """argparse type: a file that can be written (checked before the work, not after it)."""
    folder = os.path.dirname(text) or "."
    if not os.path.isdir(folder):
        raise argparse.ArgumentTypeError(f"expected a file in an existing folder, got '{text}' "
                                         f"(no folder '{folder}')")
    if os.path.isdir(text) or not os.access(folder, os.W_OK):
        raise argparse.ArgumentTypeError(f"expected a file that can be written, got '{text}'")
    return text


def check_count(what, n, option):
    if n > MAX_PARTICLES:
        fail(what, f"{option} would make {n:.4g} particles, more than cellgen's limit of "
                   f"{MAX_PARTICLES:.0e} (MAX_PARTICLES, about 1 GB of memory)")

# ---------------------------------------------------------------------------------- geometry


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


# ---------------------------------------------------------------------------------- data file


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


def write_data(path, title, box, atoms, bonds, angles, masses, refs, rho, bond_types=None,
               rmass=None, alam=None, bending=False):
    """atoms: list of (mol, type, x, y, z); bonds/angles 0-based atom indices; rho per atom.

    The `cell` section (named like the fix, as write_data names it) holds, per atom, the values of
      fix ID all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
    in that order: mass, density, density rate (0), reference position.
    Tissues: bond_types = (number of bond types, type of each bond), rmass = per-atom masses
    (default: the type's mass), alam = per-atom lamella area, written as a last column d_alam.
    bending: also the hinges of the triangles as dihedrals of type 1 (hinges())."""
    nbt, btype = bond_types if bond_types is not None else (1, [1] * len(bonds))
    dihedrals = hinges(angles) if bending else []
    with open(path, "w") as f:
        f.write(f"# {title}\n\n")
        f.write(f"{len(atoms)} atoms\n{len(bonds)} bonds\n{len(angles)} angles\n")
        if bending:
            f.write(f"{len(dihedrals)} dihedrals\n")
        f.write(f"{len(masses)} atom types\n{nbt} bond types\n1 angle types\n")
        f.write("1 dihedral types\n\n" if bending else "\n")
        f.write(f"{box[0]:.10g} {box[1]:.10g} xlo xhi\n{box[2]:.10g} {box[3]:.10g} ylo yhi\n")
        f.write(f"{box[4]:.10g} {box[5]:.10g} zlo zhi\n\nMasses\n\n")
        for i, m in enumerate(masses, 1):
            f.write(f"{i} {m:.15g}\n")
        f.write("\nAtoms # molecular\n\n")
        for i, (mol, typ, x, y, z) in enumerate(atoms, 1):
            f.write(f"{i} {mol} {typ} {x:.15g} {y:.15g} {z:.15g}\n")
        if len(bonds):
            f.write("\nBonds\n\n")
            for k, ((a, b), t) in enumerate(zip(bonds, btype), 1):
                f.write(f"{k} {t} {a + 1} {b + 1}\n")
        if len(angles):
            f.write("\nAngles\n\n")
            for k, (a, b, c) in enumerate(angles, 1):
                f.write(f"{k} 1 {a + 1} {b + 1} {c + 1}\n")
        if len(dihedrals):
            f.write("\nDihedrals\n\n")
            for k, (i, j, kk, l) in enumerate(dihedrals, 1):
                f.write(f"{k} 1 {i + 1} {j + 1} {kk + 1} {l + 1}\n")
        f.write("\ncell # rmass d_rho d_drho d2_cellref[1] d2_cellref[2] d2_cellref[3]"
                + (" d_alam" if alam is not None else "") + "\n\n")
        for i, ((mol, typ, *_), (x, y, z), r) in enumerate(zip(atoms, refs, rho), 1):
            m = masses[typ - 1] if rmass is None else rmass[i - 1]
            extra = "" if alam is None else f" {alam[i - 1]:.15g}"
            f.write(f"{i} {m:.15g} {r:.15g} 0 {x:.15g} {y:.15g} {z:.15g}{extra}\n")


_R, _M, _RHO0 = params.CELL["R"], params.CELL["M_wall"], params.table()["rho0"]
UNITS = {
    # defaults: radius, rho0, wall mass (docs/model.md section 3.1; cellmech.params), box padding
    "micro": dict(radius=_R, rho0=_RHO0, wall_mass=_M, pad=10.0),
    "si": dict(radius=_R / 1e6, rho0=_RHO0 * 1e3, wall_mass=_M / 1e15, pad=10e-6),  # m, kg/m^3, kg
}


def build_cells(args):
    d = UNITS[args.units]
    R = args.radius if args.radius is not None else d["radius"]
    rho0 = args.rho0 if args.rho0 is not None else d["rho0"]
    centres = []
    for c in args.centres.split(";"):
        try:
            centres.append(tuple(number()(v) for v in c.split(",")))
        except argparse.ArgumentTypeError:
            centres.append(())
        if len(centres[-1]) != 3:
            fail("cell", f"--centres: expected finite 'x,y,z;x,y,z;...', got '{args.centres}'")
    cc = np.array(centres)
    dist = np.linalg.norm(cc[:, None] - cc[None], axis=2) + np.diag(np.full(len(cc), np.inf))
    if dist.min() <= 2.0 * R:
        i, j = np.unravel_index(np.argmin(dist), dist.shape)
        fail("cell", f"--centres: cells {i + 1} and {j + 1} are {dist.min():.6g} apart, their walls "
                     f"(radius {R:g}) overlap or touch: expected centres more than {2 * R:g} apart")
    nw = 10 * 4 ** args.level + 2
    if args.spacing is None:
        check_count("cell", len(centres) * (nw + args.nfluid),
                    f"{len(centres)} cell(s) of {nw} wall nodes and --nfluid {args.nfluid}")
    unit, tri, edges = icosphere(args.level)
    nodes = unit * R
    area, volume = mesh_area_volume(nodes, tri)
    if args.wall_areal_density is not None:
        wall_mass = args.wall_areal_density * 4.0 * math.pi * R * R
    else:
        wall_mass = args.wall_mass if args.wall_mass is not None else d["wall_mass"]
    mean_edge = np.linalg.norm(nodes[edges[:, 0]] - nodes[edges[:, 1]], axis=1).mean()
    # keep fluid half a wall spacing inside the wall so no particle starts in contact
    inset = args.inset if args.inset is not None else 0.5 * mean_edge
    if inset >= R and (args.spacing is not None or args.nfluid > 0):
        fail("cell", f"--inset: expected a distance smaller than the radius {R:g} (the fluid stays "
                     f"that far inside the wall), got {inset:g}")
    if args.spacing is not None:
        check_count("cell", int(len(centres) * (nw + lattice_count_bound(R - inset, args.spacing))),
                    f"--spacing {args.spacing:g} in {len(centres)} cell(s) of radius {R:g}")
        fluid = fluid_lattice(R, args.spacing, inset)
        spacing = args.spacing
    else:
        fluid, spacing = fluid_by_count(R, args.nfluid, inset)
    nf = len(fluid)
    # each fluid particle carries its lattice cell at density rho0: SPH takes m/rho as the particle's
    # volume, so m = rho0 spacing^3 keeps sum(m/rho) equal to the volume the fluid fills. (Spreading
    # rho0 V_wall over the particles instead makes every particle claim more room than it has: the
    # wall then feels a pressure ~30% above the fluid's.) Inflation fills the gap to the wall.
    m_fluid = rho0 * spacing ** 3 if nf else 1.0
    m_wall = wall_mass / nw
    atoms, bonds, angles, refs = [], [], [], []
    for mol, c in enumerate(centres, 1):
        base = len(atoms)
        for p in nodes:
            atoms.append((mol, 1, *(p + c)))
        for p in fluid:
            atoms.append((mol, 2, *(p + c)))
        bonds += [(base + a, base + b) for a, b in edges]
        angles += [(base + a, base + b, base + cc) for a, b, cc in tri]
    refs = [a[2:] for a in atoms]
    pts = np.array(refs)
    if args.box:
        box = args.box
        lo, hi = np.array(box[0::2]), np.array(box[1::2])
        if np.any(pts.min(axis=0) <= lo) or np.any(pts.max(axis=0) >= hi):
            fail("cell", f"--box: expected xlo xhi ylo yhi zlo zhi around every particle "
                         f"({' '.join(f'{a:.6g} {b:.6g}' for a, b in zip(pts.min(0), pts.max(0)))}), "
                         f"got {' '.join(f'{v:g}' for v in box)}")
    else:
        pad = args.pad if args.pad is not None else d["pad"]
        lo, hi = pts.min(axis=0) - pad, pts.max(axis=0) + pad
        box = [lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]]
    title = (f"cellgen cell: {len(centres)} cell(s), level {args.level} ({nw} wall nodes), "
             f"{nf} fluid per cell, R {R:g}, spacing {spacing:.10g}, rho0 {rho0:g}, "
             f"wall mass {wall_mass:.6g}, units {args.units}")
    rho = [rho0 if a[1] == 2 else 0.0 for a in atoms]
    rmass = None
    if args.wall_mass_by_area:
        # equal node masses give the geodesic wall a surface density that varies by -23..+20% in
        # an icosahedral pattern (the node areas do), which the breathing mode drives out of round;
        # a third of each adjacent triangle's area per node makes the density uniform, as a tissue's
        trib = np.zeros(nw)
        ta = 0.5 * np.linalg.norm(np.cross(nodes[tri[:, 1]] - nodes[tri[:, 0]],
                                           nodes[tri[:, 2]] - nodes[tri[:, 0]]), axis=1)
        for k in range(3):
            np.add.at(trib, tri[:, k], ta / 3.0)
        node_mass = wall_mass * trib / trib.sum()
        rmass = [node_mass[(i - 1) % (nw + nf)] if a[1] == 1 else m_fluid
                 for i, a in enumerate(atoms, 1)]
        title += ", wall mass by area"
    write_data(args.output, title, box, atoms, bonds, angles, [m_wall, m_fluid], refs, rho,
               rmass=rmass, bending=args.bending)
    print(title)
    print(f"wall node mass {m_wall:.6g}, fluid particle mass {m_fluid:.6g}, "
          f"mesh area {area:.6g}, mesh volume {volume:.6g}, mean tether {mean_edge:.6g}")


def build_sheet(args):
    """Flat triangular sheet (paper Appendix 1): ny rows of nx nodes, rows offset by half a bond."""
    a = args.bond
    check_count("sheet", args.nx * args.ny, f"--nx {args.nx} --ny {args.ny}")
    h = a * math.sqrt(3.0) / 2.0
    pts, index = [], {}
    for j in range(args.ny):
        for i in range(args.nx):
            index[(i, j)] = len(pts)
            pts.append((i * a + (0.5 * a if j % 2 else 0.0), j * h, 0.0))
    bonds, tris = [], []
    for j in range(args.ny):
        for i in range(args.nx):
            p = index[(i, j)]
            if i + 1 < args.nx:
                bonds.append((p, index[(i + 1, j)]))
            if j + 1 < args.ny:
                # even rows connect up to (i-1, i); odd rows to (i, i+1)
                up = [i - 1, i] if j % 2 == 0 else [i, i + 1]
                ups = [index[(k, j + 1)] for k in up if 0 <= k < args.nx]
                for q in ups:
                    bonds.append((p, q))
                if len(ups) == 2:
                    tris.append((p, ups[1], ups[0]))
                right = index.get((i + 1, j))
                upr = index.get(((i + 1) if j % 2 else i, j + 1))
                if right is not None and upr is not None:
                    tris.append((p, right, upr))
    pts = np.array(pts)
    if args.orient == "y":
        # bonds along y: rotate by 90 degrees so that an X stretch pulls across the bond rows
        pts = np.column_stack([-pts[:, 1], pts[:, 0], pts[:, 2]])
        pts[:, 0] -= pts[:, 0].min()
    # node mass: areal density rho_s t0 over the node's share of the sheet area
    m = args.rho_s * args.thickness * (math.sqrt(3.0) / 2.0) * a * a
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    L = max(hi[0] - lo[0], hi[1] - lo[1])
    box = [lo[0] - L, hi[0] + L, lo[1] - L, hi[1] + L, -L, L]
    atoms = [(1, 1, *p) for p in pts]
    title = f"cellgen sheet: {args.nx}x{args.ny} nodes, bond {a:g}, bonds along {args.orient}"
    write_data(args.output, title, box, atoms, bonds, tris, [m], pts, [0.0] * len(atoms),
               bending=args.bending)
    print(title, f"{len(bonds)} tethers, {len(tris)} triangles, node mass {m:.6g}")


# ---------------------------------------------------------------------------------- tissue
# A block of glued cells (docs/cellgen.rst, "Tissue"): seeds -> Laguerre (power) cells clipped by
# the tissue box -> each cell's icosphere mapped onto its cell, offset inward by gap/2, with rounded
# edges -> a fluid lattice inside each wall -> middle-lamella bonds between facing wall nodes.

R0_COARSE = params.LEVELS[3]["r0"]              # fluid-wall contact distance r0, level 3, um
WALL_AREAL = _M / (4.0 * math.pi * _R ** 2)      # the single cell's wall mass per area, pg/um^2
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


def mesh_volumes(x, centres, tri):
    """Volume enclosed by each wall x (C, V, 3), from the tetrahedra (centre, triangle)."""
    a, b, c = (x[:, tri[:, k]] - centres[:, None, :] for k in range(3))
    return np.einsum("ctj,ctj->c", a, np.cross(b, c)) / 6.0


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


def write_lengths(path, what, level, reach, special):
    """The model lengths of the data file's level, as the LAMMPS include the inputs read before
    their own defaults (in.tissue-inflate: include ${data}.lmp): a coarse tissue run with the
    paper's lengths holds neither its fluid nor its turgor. A -var on the command line still wins."""
    lines = [f"# written by cellgen.py {what} with {os.path.basename(path)[:-4]}: the model lengths of "
             f"its wall level {level}"]
    if level in params.LEVELS:
        row = params.LEVELS[level]
        lines.append("# from the level table (tools/cellmech/params.py LEVELS)")
        for k, note in (("s", "smoothing length, um"), ("r0", "fluid-wall contact distance, um"),
                        ("f0", "fluid-wall 8-4 strength, nN um"), ("dt", "time step, us")):
            lines.append(f"variable {k:8s} index {row[k]:<10g} # {note}")
        reach = max(reach, row["reach"])
    else:
        lines.append(f"# level {level} has no row in the level table (levels {', '.join(map(str, params.LEVELS))}):"
                     " give -var s r0 f0 dt")
    lines.append(f"variable {'reach':8s} index {reach:<10g} # cell/virtual reach, um (>= the mesh's)")
    lines.append(f"variable {'special':8s} index {special:<10d} # read_data extra/special/per/atom")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def build_tissue(args):
    from scipy import sparse
    rng = np.random.default_rng(args.seed)
    R = _R if args.radius is None else args.radius
    nv = 10 * 4 ** args.level + 2
    ell = np.array(args.elongate if args.elongate else (1.0, 1.0, 1.0), float)
    ell = ell / np.prod(ell) ** (1.0 / 3.0)  # same cell volume, elongated in the ratio given
    radii, vcell = None, 4.0 / 3.0 * math.pi * R ** 3
    # ---- seeds and the tissue block
    if args.lattice:
        if len(args.n) != 3:
            tfail(f"--n needs three positive integers NX NY NZ, got {' '.join(map(str, args.n))}")
        basis, rep = LATTICES[args.lattice]
        check_count("tissue", int(np.prod(args.n)) * len(basis) * (nv + args.nfluid),
                    f"--lattice {args.lattice} --n {' '.join(map(str, args.n))} of {nv} wall nodes "
                    f"and {args.nfluid} fluid particles a cell")
        per_seed = float(np.prod(rep)) / len(basis)  # lattice volume per seed, in a^3
        a = args.spacing if args.spacing is not None else (vcell / per_seed) ** (1.0 / 3.0)
        seeds, lo, hi = lattice_seeds(args.lattice, args.n, a)
        how = f"lattice {args.lattice} {'x'.join(map(str, args.n))}, constant {a:.6g}"
    elif args.spacing is not None:
        tfail("--spacing (the lattice constant) needs --lattice")
    elif args.random is not None:
        check_count("tissue", args.random * (nv + args.nfluid),
                    f"--random {args.random} of {nv} wall nodes and {args.nfluid} fluid particles a cell")
        size = np.array(args.size if args.size else [(args.random * vcell) ** (1.0 / 3.0)] * 3, float)
        vcell = np.prod(size) / args.random
        dmin = args.min_dist if args.min_dist is not None else 0.7 * vcell ** (1.0 / 3.0)
        lo, hi = -0.5 * size, 0.5 * size
        seeds = random_seeds(args.random, lo, hi, dmin, rng)
        how = f"random {args.random} seeds (seed {args.seed}, min distance {dmin:.4g})"
    else:
        seeds, radii = read_centres(args.centres)
        check_count("tissue", len(seeds) * (nv + args.nfluid),
                    f"--centres {args.centres} ({len(seeds)} cells) of {nv} wall nodes and "
                    f"{args.nfluid} fluid particles a cell")
        if radii is None and len(seeds) > 1:
            from scipy.spatial import cKDTree
            pad = 0.5 * np.median(cKDTree(seeds).query(seeds, k=2)[0][:, 1])
        else:
            pad = radii if radii is not None else R
        lo, hi = (seeds - np.reshape(pad, (-1, 1))).min(0), (seeds + np.reshape(pad, (-1, 1))).max(0)
        how = f"centres from {args.centres}" + (" (Laguerre, radii given)" if radii is not None else "")
    if args.tissue_box:
        tb = np.array(args.tissue_box, float)
        lo, hi = tb[0::2], tb[1::2]
        if np.any(hi <= lo) or np.any(seeds < lo) or np.any(seeds > hi):
            tfail("--tissue-box must be xlo xhi ylo yhi zlo zhi (lo < hi) and contain every seed")
    seeds, lo, hi = seeds * ell, lo * ell, hi * ell
    radii = np.zeros(len(seeds)) if radii is None else radii
    ncell = len(seeds)
    for it in range(args.lloyd):
        seeds = np.array([c["centroid"] for c in power_cells(
            seeds, radii, lo, hi, stage=f"Lloyd iteration {it + 1} of {args.lloyd}")])
    if ncell > 1:
        from scipy.spatial import cKDTree
        dd, jj = cKDTree(seeds).query(seeds, k=2)
        k = int(np.argmin(dd[:, 1]))
        other = jj[k, 1] if jj[k, 1] != k else jj[k, 0]   # two equal seeds: either may come first
        if dd[k, 1] < 2 * args.gap:
            tfail(f"seeds of cells {min(k, other) + 1} and {max(k, other) + 1} are {dd[k, 1]:.4g} apart, closer than "
                  f"twice the gap ({2 * args.gap:g}): move them or lower --gap")
    cells = power_cells(seeds, radii, lo, hi)
    if args.remove_box:
        # A notch or a hole: the cells whose seeds lie inside are taken out after the diagram, so
        # the cells around keep their shape and their faces towards the space become free surface
        rb = np.array(args.remove_box, float)
        gone = np.all((seeds >= rb[0::2]) & (seeds <= rb[1::2]), axis=1)
        if gone.all() or not gone.any():
            tfail(f"--remove-box {' '.join(f'{v:g}' for v in rb)}: expected a box holding some of the "
                  f"{ncell} seeds but not all, it holds {int(gone.sum())}")
        remap = np.where(gone, -1, np.cumsum(~gone) - 1)    # old index -> new, -1: taken out
        for c in cells:
            c["nbr"] = np.where(c["nbr"] >= 0, remap[c["nbr"]], -1)
        cells = [c for c, g in zip(cells, gone) if not g]
        seeds, radii, ncell = seeds[~gone], radii[~gone], int((~gone).sum())
        how += f", {int(gone.sum())} removed by --remove-box"
    size = np.mean([c["volume"] for c in cells]) ** (1.0 / 3.0)
    if args.gap >= 0.5 * size:
        tfail(f"--gap must be smaller than half the cell size ({0.5 * size:.4g}), got {args.gap:g}")
    # ---- walls: the icosphere mapped radially onto the rounded, offset cell around its centroid
    unit, tri, edges = icosphere(args.level)
    nv, kmax = len(unit), max(len(c["normals"]) for c in cells)
    centres = np.array([c["centroid"] for c in cells])
    # The tissue's free surface. "cut": the block's faces are flat, as a sample cut from a fruit.
    # "round" (default): towards its free faces (no neighbour there) a cell is bounded by a dome,
    # the ellipsoid with the polyhedron's second moments (its shape) and volume, about its
    # centroid: a cube's is its equivalent sphere (0.620 a), an elongated cell's is elongated
    # alike; scaled by --dome. A flat free face cannot carry a pressure without bulging, and inflation
    # would first have to stretch it into a dome (to 16% for a 48 um face at 364 kPa in the
    # stiff wall, four times the tethers' critical stretch of 4%): the outer walls would start a
    # compression already torn. The dome acts only where a free face is the nearest plane
    # (gauge_radius): faces between cells, balanced by the neighbour's turgor, stay flat to their
    # edges and glued over their whole area.
    normals, depth = np.zeros((ncell, kmax, 3)), np.full((ncell, kmax), np.inf)
    fnormals, fdepth = np.zeros((ncell, kmax, 3)), np.full((ncell, kmax), np.inf)
    metric = np.zeros((ncell, 3, 3))
    rounded = False
    for i, c in enumerate(cells):
        shared = np.ones(len(c["normals"]), bool)
        if args.surface == "round" and (c["nbr"] < 0).any():
            shared = c["nbr"] >= 0
            f = int((~shared).sum())
            fnormals[i, :f] = c["normals"][~shared]
            fdepth[i, :f] = c["offsets"][~shared] - c["normals"][~shared] @ centres[i]
            m = np.linalg.inv(5.0 * c["moment"])
            # scaled to the polyhedron's volume: a cube's is its equivalent sphere, the single
            # cell's shape; a cell free all round is the paper's sphere of its volume
            ve = 4.0 / 3.0 * math.pi / math.sqrt(np.linalg.det(m))
            metric[i] = m * (ve / c["volume"]) ** (2.0 / 3.0) / args.dome ** 2
            rounded = True
        k = int(shared.sum())
        normals[i, :k] = c["normals"][shared]
        depth[i, :k] = c["offsets"][shared] - c["normals"][shared] @ centres[i] - 0.5 * args.gap
        if k and depth[i, :k].min() <= 0:
            tfail(f"cell {i + 1} is thinner than the gap ({args.gap:g}) around its centroid "
                  f"{centres[i]}: lower --gap or spread the seeds")
    free = (fnormals, fdepth, metric) if rounded else None

    def onto(x, p):  # radial projection onto the rounded cells
        r = x - centres[:, None, :]
        u = r / np.linalg.norm(r, axis=2)[..., None]
        return centres[:, None, :] + u * gauge_radius(u, normals, depth, p, free)[..., None]

    # the cells' polyhedra tile the block: the box less what --remove-box took out
    block_volume = float(sum(c["volume"] for c in cells))
    # the air is the space between the walls within the tissue: each cell's territory (its
    # polyhedron, and where it is round its dome beyond the free faces) less its wall's volume
    territory = territory_volumes(cells, centres, normals, depth + 0.5 * args.gap, free)
    start = np.broadcast_to(unit, (ncell, nv, 3)) + centres[:, None, :]
    p, porosity0 = args.sharpness, None
    if args.air is not None:
        # Intercellular air where it is in parenchyma: at the cells' edges and corners, with the
        # faces between cells still in contact and glued. Rounder cells (a smaller sharpness p)
        # leave more air; p is found by bisection in log p on the unsmoothed walls (smoothing
        # moves nodes along the surface: the volume hardly changes), and a final uniform scaling
        # of less than a percent makes the porosity exact. Shrinking every wall instead would pull
        # the faces apart beyond the bond cutoff: no lamella at all.
        def air_at(q):
            return 1.0 - mesh_volumes(onto(start, q), centres, tri).sum() / territory.sum()
        porosity0, most = air_at(args.sharpness), air_at(2.0)
        if not porosity0 <= args.air <= most:
            tfail(f"--air {args.air:g}: expected a porosity between {porosity0:.4f} (the block at "
                  f"--sharpness {args.sharpness:g}) and {most:.4f} (the roundest cells, sharpness 2)"
                  + ("; --surface cut leaves more room" if rounded else ""))
        lo_p, hi_p = math.log(2.0), math.log(args.sharpness)
        for _ in range(40):
            mid = 0.5 * (lo_p + hi_p)
            lo_p, hi_p = (mid, hi_p) if air_at(math.exp(mid)) > args.air else (lo_p, mid)
        p = math.exp(0.5 * (lo_p + hi_p))
    x = onto(start, p)
    deg = np.bincount(edges.ravel(), minlength=nv)
    inc = sparse.coo_matrix((np.ones(3 * len(tri)), (tri.T.ravel(), np.tile(np.arange(len(tri)), 3))),
                            shape=(nv, len(tri))).tocsr()

    def per_node(m, v):  # sparse (nv, n) times per-cell values (ncell, n, 3) -> (ncell, nv, 3)
        out = m @ v.transpose(1, 0, 2).reshape(v.shape[1], -1)
        return out.reshape(nv, ncell, 3).transpose(1, 0, 2)

    for it in range(args.smooth):
        # tangential, area-weighted Laplacian step (towards the area-weighted mean of the node's
        # triangle centroids: evens out the triangle areas), then back onto the surface along the ray
        a, b, c = x[:, tri[:, 0]], x[:, tri[:, 1]], x[:, tri[:, 2]]
        cr = np.cross(b - a, c - a)
        ar = np.linalg.norm(cr, axis=2)[..., None]
        vn = per_node(inc, cr)
        vn /= np.linalg.norm(vn, axis=2)[..., None]
        step = per_node(inc, ar * (a + b + c) / 3.0) / per_node(inc, np.repeat(ar, 3, axis=2)) - x
        step -= np.einsum("cvj,cvj->cv", step, vn)[..., None] * vn
        x = onto(x + 0.5 * step, p)
        progress(ncell, f"smoothing the walls, {it + 1} of {args.smooth}", it + 1, args.smooth)
    vol = check_walls(x, centres, tri, edges)
    box_volume = float(np.prod(hi - lo))
    if args.air is not None:
        sc = ((1.0 - args.air) * territory.sum() / vol.sum()) ** (1.0 / 3.0)
        x = centres[:, None, :] + sc * (x - centres[:, None, :])
        vol = vol * sc ** 3
    else:
        porosity0 = 1.0 - vol.sum() / territory.sum()
    porosity = 1.0 - vol.sum() / territory.sum()
    area_t, ang, elen, bary = wall_quality(x, tri)
    if ang.min() < args.min_angle:
        k = int(np.argmin(ang.min(axis=(1, 2))))
        tfail(f"cell {k + 1} has a triangle angle of {ang.min():.3g} deg, below --min-angle "
              f"{args.min_angle:g}: raise --level or --smooth, or lower --sharpness")
    trib = per_node(inc, np.repeat(area_t[..., None], 3, axis=2))[..., 0] / 3.0   # (ncell, nv)
    wall_area = area_t.sum(1)
    # ---- fluid: one spacing for all cells
    inset = args.inset if args.inset is not None else R0_COARSE
    rmax = np.linalg.norm(x - centres[:, None, :], axis=2).max(axis=1)
    if args.fluid_spacing is not None:
        spacing = args.fluid_spacing
        check_count("tissue", ncell * nv + int(sum(lattice_count_bound(r, spacing) for r in rmax)),
                    f"--fluid-spacing {spacing:g} in {ncell} cells")
    elif args.nfluid > 0:
        m = int(np.argmin(np.abs(vol - vol.mean())))
        # no fluid fits where the inset reaches past the nearest triangle plane around the centre
        a, b, c = (x[m][tri[:, k]] - centres[m] for k in range(3))
        nrm = np.cross(b - a, c - a)
        rin = (np.einsum("ij,ij->i", nrm, a) / np.linalg.norm(nrm, axis=1)).min() - inset
        if not rin > 0:
            tfail(f"--inset: expected a distance smaller than the cell's inner radius "
                  f"{rin + inset:.4g} (the fluid stays that far inside the wall), got {inset:g}")
        spacing = spacing_for_count(lambda s: fluid_in_wall(x[m], tri, centres[m], s, inset),
                                    args.nfluid, 1e-3 * size, 2.0 * size, iterations=50)
    else:
        spacing = 0.0
    fluid = [fluid_in_wall(x[i], tri, centres[i], spacing, inset) if spacing > 0 else np.zeros((0, 3))
             for i in range(ncell)]
    # ---- middle lamella
    if args.bond_cutoff is not None and args.bond_cutoff <= args.gap:
        tfail(f"--bond-cutoff must exceed --gap ({args.gap:g}): facing walls start gap apart")
    cutoff = args.bond_cutoff if args.bond_cutoff is not None else 1.5 * args.gap
    xw, molw = x.reshape(-1, 3), np.repeat(np.arange(ncell), nv)
    lam = lamella_bonds(xw, molw, cutoff)
    nlam = np.bincount(lam.ravel(), minlength=len(xw))
    alam = np.where(nlam > 0, trib.ravel() / np.maximum(nlam, 1), 0.0)
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
    # ---- special neighbours, as LAMMPS counts them at read_data (1-2, 1-3, 1-4; unique)
    glue = not args.no_glue
    allb = np.vstack([(edges[None] + (np.arange(ncell) * nv)[:, None, None]).reshape(-1, 2)]
                     + ([lam] if glue else []))
    A = sparse.coo_matrix((np.ones(2 * len(allb)), (np.r_[allb[:, 0], allb[:, 1]],
                          np.r_[allb[:, 1], allb[:, 0]])), shape=(len(xw),) * 2).tocsr()
    A.data[:] = 1
    A2 = A @ A
    S = (A + A2 + A2 @ A).tocsr()
    S.setdiag(0)
    S.eliminate_zeros()
    special = int(np.diff(S.indptr).max())
    maxlam = int(nlam.max()) if glue else 0
    K = maxlam * (1 + int(deg.max())) + 6
    reach_need = float(bary.max())
    reach = math.ceil(1.25 * reach_need * 10 - 1e-9) / 10.0
    # ---- atoms, masses, data file
    areal = args.wall_areal_density if args.wall_areal_density is not None else WALL_AREAL
    m_fluid = args.rho0 * spacing ** 3 if spacing > 0 else 1.0
    atoms, rmass, rho, alam_atom, bonds, btype, angles = [], [], [], [], [], [], []
    wall_index = np.zeros(len(xw), int)
    for i in range(ncell):
        base = len(atoms)
        wall_index[i * nv:(i + 1) * nv] = base + np.arange(nv)
        atoms += [(i + 1, 1, *q) for q in x[i]] + [(i + 1, 2, *q) for q in fluid[i]]
        rmass += list(areal * trib[i]) + [m_fluid] * len(fluid[i])
        rho += [0.0] * nv + [args.rho0] * len(fluid[i])
        alam_atom += list(alam[i * nv:(i + 1) * nv] if glue else np.zeros(nv)) + [0.0] * len(fluid[i])
        bonds += [(base + a, base + b) for a, b in edges]
        angles += [(base + a, base + b, base + c) for a, b, c in tri]
    btype = [1] * len(bonds)
    if glue:
        bonds += [tuple(wall_index[b]) for b in lam]
        btype += [2] * len(lam)
    pts = np.array([q[2:] for q in atoms])
    blo, bhi = pts.min(0) - args.pad, pts.max(0) + args.pad
    box = [blo[0], bhi[0], blo[1], bhi[1], blo[2], bhi[2]]
    m_wall = areal * wall_area.sum() / (ncell * nv)
    title = (f"cellgen tissue: {ncell} cells ({how}), level {args.level} ({nv} wall nodes per cell), "
             f"gap {args.gap:g}, fluid spacing {spacing:.10g}, rho0 {args.rho0:g}, wall areal density "
             f"{areal:.6g}, {len(lam) if glue else 0} lamella bonds; read_data ... "
             f"extra/special/per/atom {K}; pair_style cell/virtual reach >= {reach:g}; units micro")
    write_data(args.output, title, box, atoms, bonds, angles, [m_wall, m_fluid], pts, rho,
               bond_types=(2, btype), rmass=rmass, alam=alam_atom, bending=args.bending)
    write_lengths(args.output + ".lmp", "tissue", args.level, reach, K)
    # ---- statistics
    nfl = np.array([len(f) for f in fluid])
    qual = dict(min_angle_deg=float(ang.min()), min_edge=float(elen.min()), max_edge=float(elen.max()),
                max_barycentre_distance=reach_need, recommended_reach=reach)
    stats = dict(
        cells=ncell, seeds=how, level=args.level, wall_nodes_per_cell=nv, gap=args.gap,
        sharpness=p, bond_cutoff=cutoff, glue=glue, fluid_spacing=spacing, inset=inset,
        fluid_mass=m_fluid, rho0=args.rho0, wall_areal_density=areal,
        tissue_box=[float(v) for v in np.ravel(np.column_stack([lo, hi]))], box_volume=box_volume,
        block_volume=block_volume, territory_volume=float(territory.sum()),
        porosity=float(porosity), porosity_without_air=float(porosity0),
        volume_mean=float(vol.mean()), volume_rel_spread=float(vol.std() / vol.mean()),
        faces_mean=float(np.mean([len(c["normals"]) for c in cells])),
        neighbours_mean=float(np.mean([len(s) for s in nbrs])),
        lamella_bonds=int(len(lam)) if glue else 0, max_lamella_bonds_per_node=maxlam,
        special_max=special, extra_special_per_atom=K, triangle_quality=qual,
        cell=[dict(id=i + 1, seed=[float(v) for v in seeds[i]], centre=[float(v) for v in centres[i]],
                   volume=float(vol[i]), wall_area=float(wall_area[i]), faces=len(cells[i]["normals"]),
                   neighbours=sorted(int(j) + 1 for j in nbrs[i]), nodes=nv, fluid=int(nfl[i]))
              for i in range(ncell)],
        pairs=[dict(cells=[int(i) + 1, int(j) + 1], bonds=n, glued_area=float(ab))
               for (i, j), (n, ab) in sorted(pairs.items())],
        unglued_faces=[dict(cells=[i + 1, j + 1], face_area=a) for i, j, a in unglued])
    import json
    import os
    path = args.stats if args.stats else os.path.splitext(args.output)[0] + ".json"
    with open(path, "w") as f:
        json.dump(stats, f, indent=1)
    print(title)
    print(f"cells {ncell}: volume mean {vol.mean():.6g} (spread {vol.std() / vol.mean():.3%}), "
          f"wall area mean {wall_area.mean():.6g}, faces/cell {stats['faces_mean']:.3g}, "
          f"neighbours/cell {stats['neighbours_mean']:.3g}")
    print(f"porosity {porosity:.4f} (without air {porosity0:.4f}"
          + (f"; --air rounds the cells to sharpness {p:.4g}" if args.air is not None else "")
          + f"), tissue box volume {box_volume:.6g}")
    print(f"fluid: spacing {spacing:.6g}, {nfl.sum()} particles ({nfl.min()}..{nfl.max()} per cell), "
          f"mass {m_fluid:.6g}; wall node mass mean {m_wall:.6g} (areal density x tributary area)")
    print(f"lamella: {stats['lamella_bonds']} bonds (cutoff {cutoff:g}), {len(pairs)} "
          f"{'glued' if glue else 'facing (--no-glue: not bonded)'} pairs, "
          f"area {sum(v[1] for v in pairs.values()):.6g}, max {maxlam} per node")
    print(f"triangles: min angle {qual['min_angle_deg']:.2f} deg, edges {qual['min_edge']:.4g}.."
          f"{qual['max_edge']:.4g}, max barycentre-node distance {reach_need:.4g} -> "
          f"pair_style cell/virtual reach >= {reach:g}")
    print(f"special neighbours: max {special} per atom; read_data ... extra/special/per/atom {K}")
    print(f"statistics: {path}; model lengths of level {args.level}: {args.output}.lmp")


def main(argv=None):
    p = Parser(prog="cellgen.py", description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="what", required=True)
    c = sub.add_parser("cell", help="one or more cells: geodesic wall + clipped fluid lattice")
    c.add_argument("-o", "--output", required=True, type=output_file)
    c.add_argument("--level", type=whole(0, 6), default=4, help="subdivision level (4: 2562 nodes)")
    c.add_argument("--radius", type=number(above=0), help="cell radius (default 30 um)")
    g = c.add_mutually_exclusive_group()
    g.add_argument("--nfluid", type=whole(0), default=3500, help="fluid particles per cell (>=)")
    g.add_argument("--spacing", type=number(above=0), help="fluid lattice spacing")
    c.add_argument("--inset", type=number(minimum=0), help="keep fluid this far inside the wall")
    c.add_argument("--centres", default="0,0,0", help="cell centres 'x,y,z;x,y,z'")
    c.add_argument("--rho0", type=number(above=0), help="fluid density (default 1 pg/um^3 = 1000 kg/m^3)")
    w = c.add_mutually_exclusive_group()
    w.add_argument("--wall-mass", type=number(above=0), help="total wall mass of a cell (default 1.3e4 pg)")
    w.add_argument("--wall-areal-density", type=number(above=0), help="rho_s t0 (mass per wall area)")
    c.add_argument("--wall-mass-by-area", action="store_true",
                   help="wall node masses in proportion to their share of the wall area (uniform "
                        "surface density) instead of equal")
    c.add_argument("--pad", type=number(minimum=0), help="box padding around the cells (10 um)")
    c.add_argument("--box", type=number(), nargs=6)
    c.add_argument("--units", choices=sorted(UNITS), default="micro")
    s = sub.add_parser("sheet", help="flat triangular tether sheet (Appendix 1)")
    s.add_argument("-o", "--output", required=True, type=output_file)
    s.add_argument("--nx", type=whole(2), default=20)
    s.add_argument("--ny", type=whole(2), default=20)
    s.add_argument("--bond", type=number(above=0), default=2.5)
    s.add_argument("--thickness", type=number(above=0), default=0.126)
    s.add_argument("--orient", choices=("x", "y"), default="x", help="direction of the bond rows")
    s.add_argument("--rho-s", type=number(above=0), default=8.956, help="wall density (pg/um^3)")
    t = sub.add_parser("tissue", help="a block of glued polyhedral cells (Voronoi/Laguerre walls)")
    t.add_argument("-o", "--output", required=True, type=output_file)
    g = t.add_mutually_exclusive_group(required=True)
    g.add_argument("--lattice", choices=sorted(LATTICES), help="seeds on a lattice")
    g.add_argument("--random", type=whole(1), metavar="N", help="N random seeds in a box")
    g.add_argument("--centres", metavar="FILE", help="seeds from a file: x y z [r] per line")
    t.add_argument("--n", type=whole(1), nargs="+", default=[2, 2, 2], metavar="N",
                   help="lattice repeats NX NY NZ (default 2 2 2)")
    r = t.add_mutually_exclusive_group()
    r.add_argument("--radius", type=number(above=0), help="equivalent-sphere cell radius (default 30 um)")
    r.add_argument("--spacing", type=number(above=0), help="lattice constant instead of --radius")
    t.add_argument("--size", type=number(above=0), nargs=3, metavar="L", help="--random: box LX LY LZ")
    t.add_argument("--min-dist", type=number(above=0), help="--random: minimum seed distance")
    t.add_argument("--lloyd", type=whole(0, MAX_LLOYD), default=0, metavar="K",
                   help="Lloyd iterations (default 0)")
    t.add_argument("--seed", type=whole(0), default=1, help="random seed (default 1)")
    t.add_argument("--tissue-box", type=number(), nargs=6, metavar="X",
                   help="block that clips the cells: xlo xhi ylo yhi zlo zhi")
    t.add_argument("--remove-box", type=number(), nargs=6, metavar="X",
                   help="leave empty the cells whose seeds lie in xlo xhi ylo yhi zlo zhi (a notch)")
    t.add_argument("--elongate", type=number(above=0), nargs=3, metavar="F", help="stretch factors ax ay az")
    t.add_argument("--level", type=whole(0, 6), default=3, help="icosphere level of each wall (default 3)")
    t.add_argument("--gap", type=number(above=0), default=2.56, help="wall-wall gap (default 2.56 um)")
    t.add_argument("--sharpness", type=number(minimum=2, maximum=MAX_SHARPNESS), default=16.0,
                   help="edge rounding exponent p (16)")
    t.add_argument("--surface", choices=("round", "cut"), default="round",
                   help="free surface of the block: domed cells (round) or flat faces (cut)")
    t.add_argument("--dome", type=number(above=0), default=1.0,
                   help="round surface: dome radius / the cell's equivalent radius (1.0)")
    t.add_argument("--smooth", type=whole(0, MAX_SMOOTH), default=100, help="tangential smoothing iterations (100)")
    t.add_argument("--min-angle", type=number(minimum=0), default=20.0,
                   help="smallest triangle angle allowed (20)")
    t.add_argument("--air", "--porosity", type=number(), help="target porosity (intercellular air)")
    f = t.add_mutually_exclusive_group()
    f.add_argument("--nfluid", type=whole(0), default=440, help="fluid count of a mean cell (440)")
    f.add_argument("--fluid-spacing", type=number(above=0), help="fluid lattice spacing")
    t.add_argument("--inset", type=number(minimum=0), help="fluid distance from the wall (default 3.2 um)")
    t.add_argument("--bond-cutoff", type=number(above=0), help="lamella bond cutoff (default 1.5 gap)")
    t.add_argument("--no-glue", action="store_true", help="no middle-lamella bonds")
    t.add_argument("--rho0", type=number(above=0), default=1.0, help="fluid density (1 pg/um^3)")
    t.add_argument("--wall-areal-density", type=number(above=0),
                   help="wall mass per area (1.3e4/(4 pi 30^2))")
    t.add_argument("--pad", type=number(minimum=0), default=10.0, help="box padding around the atoms (10 um)")
    t.add_argument("--stats", type=output_file, help="statistics JSON (default: output name with .json)")
    for sp in (c, s, t):
        sp.add_argument("--bending", action="store_true",
                        help="also write the bending hinges (Dihedrals) for dihedral style cell/bending")
    args = p.parse_args(argv)
    try:
        {"cell": build_cells, "sheet": build_sheet, "tissue": build_tissue}[args.what](args)
        sys.stdout.flush()
    except BrokenPipeError:
        # the summary piped into head: the files are written; no traceback for the closed pipe
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())


if __name__ == "__main__":
    main()
