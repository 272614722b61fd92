#!/usr/bin/python3
"""cellgen: build LAMMPS data files for the cellmech plant-cell model.

Geometry of one cell (Van Liedekerke et al. 2010, MODEL.md section 1):
  * wall: icosahedral geodesic sphere of subdivision level n (10*4^n+2 nodes: 12, 42, 162, 642,
    2562, 10242), radius R, nodes projected on the sphere; tethers = mesh edges (LAMMPS bonds);
    triangles = LAMMPS angles (a, b, c) ordered so that (b-a)x(c-a) points OUT of the cell. Angles
    travel with atoms through MPI migration and restart files, which is what later styles need.
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

Usage:
  cellgen.py cell -o cell.data [--level 4] [--radius 30] [--nfluid 3500 | --spacing S | --nfluid 0]
                  [--centres "0,0,0;70,0,0"] [--rho0 1] [--wall-mass 1.3e4 | --wall-areal-density X]
                  [--pad 10] [--box xlo xhi ylo yhi zlo zhi] [--units micro|si]
  cellgen.py sheet -o sheet.data [--nx 20 --ny 20] [--bond 2.5] [--orient x|y] [--thickness 0.126]
                   [--rho-s 8.956]
"""
import argparse
import math
import sys

import numpy as np

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
    """Cubic lattice points strictly inside radius - inset, centred on the origin."""
    n = int(math.ceil(radius / spacing)) + 1
    g = (np.arange(-n, n + 1)) * spacing
    X, Y, Z = np.meshgrid(g, g, g, indexing="ij")
    pts = np.column_stack([X.ravel(), Y.ravel(), Z.ravel()])
    return pts[np.linalg.norm(pts, axis=1) < radius - inset]


def fluid_by_count(radius, nfluid, inset):
    """Largest-spacing cubic lattice clipped to the sphere that holds at least nfluid points."""
    if nfluid <= 0:
        return np.zeros((0, 3)), 0.0
    # the count is a step function of the spacing: bisect on it, then keep the closest count >= n
    lo, hi = 1e-3 * radius, 2.0 * radius
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if len(fluid_lattice(radius, mid, inset)) >= nfluid:
            lo = mid
        else:
            hi = mid
    return fluid_lattice(radius, lo, inset), lo


# ---------------------------------------------------------------------------------- data file


def write_data(path, title, box, atoms, bonds, angles, masses, refs, rho):
    """atoms: list of (mol, type, x, y, z); bonds/angles 0-based atom indices; rho per atom.

    The `cell` section (named like the fix, as write_data names it) holds, per atom, the values of
      fix ID all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
    in that order: mass, density, density rate (0), reference position."""
    with open(path, "w") as f:
        f.write(f"# {title}\n\n")
        f.write(f"{len(atoms)} atoms\n{len(bonds)} bonds\n{len(angles)} angles\n")
        f.write(f"{len(masses)} atom types\n1 bond types\n1 angle types\n\n")
        f.write(f"{box[0]:.10g} {box[1]:.10g} xlo xhi\n{box[2]:.10g} {box[3]:.10g} ylo yhi\n")
        f.write(f"{box[4]:.10g} {box[5]:.10g} zlo zhi\n\nMasses\n\n")
        for i, m in enumerate(masses, 1):
            f.write(f"{i} {m:.15g}\n")
        f.write("\nAtoms # molecular\n\n")
        for i, (mol, typ, x, y, z) in enumerate(atoms, 1):
            f.write(f"{i} {mol} {typ} {x:.15g} {y:.15g} {z:.15g}\n")
        if len(bonds):
            f.write("\nBonds\n\n")
            for k, (a, b) in enumerate(bonds, 1):
                f.write(f"{k} 1 {a + 1} {b + 1}\n")
        if len(angles):
            f.write("\nAngles\n\n")
            for k, (a, b, c) in enumerate(angles, 1):
                f.write(f"{k} 1 {a + 1} {b + 1} {c + 1}\n")
        f.write("\ncell # rmass d_rho d_drho d2_cellref[1] d2_cellref[2] d2_cellref[3]\n\n")
        for i, ((mol, typ, *_), (x, y, z), r) in enumerate(zip(atoms, refs, rho), 1):
            f.write(f"{i} {masses[typ - 1]:.15g} {r:.15g} 0 {x:.15g} {y:.15g} {z:.15g}\n")


UNITS = {
    # length, mass per unit (kg), defaults: radius, rho0, wall mass (paper, MODEL.md sec. 2)
    "micro": dict(radius=30.0, rho0=1.0, wall_mass=1.3e4, pad=10.0),
    "si": dict(radius=30e-6, rho0=1000.0, wall_mass=1.3e-11, pad=10e-6),
}


def build_cells(args):
    d = UNITS[args.units]
    R = args.radius if args.radius is not None else d["radius"]
    rho0 = args.rho0 if args.rho0 is not None else d["rho0"]
    if R <= 0 or rho0 <= 0:
        sys.exit("cellgen: --radius and --rho0 must be > 0")
    if args.level < 0 or args.level > 6:
        sys.exit("cellgen: --level must be between 0 and 6")
    unit, tri, edges = icosphere(args.level)
    nodes = unit * R
    area, volume = mesh_area_volume(nodes, tri)
    if args.wall_areal_density is not None:
        wall_mass = args.wall_areal_density * 4.0 * math.pi * R * R
    else:
        wall_mass = args.wall_mass if args.wall_mass is not None else d["wall_mass"]
    if wall_mass <= 0:
        sys.exit("cellgen: the wall mass must be > 0")
    mean_edge = np.linalg.norm(nodes[edges[:, 0]] - nodes[edges[:, 1]], axis=1).mean()
    # keep fluid half a wall spacing inside the wall so no particle starts in contact
    inset = args.inset if args.inset is not None else 0.5 * mean_edge
    if args.spacing is not None:
        fluid = fluid_lattice(R, args.spacing, inset)
        spacing = args.spacing
    else:
        fluid, spacing = fluid_by_count(R, args.nfluid, inset)
    centres = [tuple(float(v) for v in c.split(",")) for c in args.centres.split(";")]
    if any(len(c) != 3 for c in centres):
        sys.exit("cellgen: --centres wants 'x,y,z;x,y,z;...'")
    nf, nw = len(fluid), len(nodes)
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
    else:
        pad = args.pad if args.pad is not None else d["pad"]
        lo, hi = pts.min(axis=0) - pad, pts.max(axis=0) + pad
        box = [lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]]
    title = (f"cellgen cell: {len(centres)} cell(s), level {args.level} ({nw} wall nodes), "
             f"{nf} fluid per cell, R {R:g}, spacing {spacing:.10g}, rho0 {rho0:g}, "
             f"wall mass {wall_mass:.6g}, units {args.units}")
    rho = [rho0 if a[1] == 2 else 0.0 for a in atoms]
    write_data(args.output, title, box, atoms, bonds, angles, [m_wall, m_fluid], refs, rho)
    print(title)
    print(f"wall node mass {m_wall:.6g}, fluid particle mass {m_fluid:.6g}, "
          f"mesh area {area:.6g}, mesh volume {volume:.6g}, mean tether {mean_edge:.6g}")


def build_sheet(args):
    """Flat triangular sheet (paper Appendix 1): ny rows of nx nodes, rows offset by half a bond."""
    a = args.bond
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
    write_data(args.output, title, box, atoms, bonds, tris, [m], pts, [0.0] * len(atoms))
    print(title, f"{len(bonds)} tethers, {len(tris)} triangles, node mass {m:.6g}")


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="what", required=True)
    c = sub.add_parser("cell", help="one or more cells: geodesic wall + clipped fluid lattice")
    c.add_argument("-o", "--output", required=True)
    c.add_argument("--level", type=int, default=4, help="subdivision level (4: 2562 nodes)")
    c.add_argument("--radius", type=float, help="cell radius (default 30 um)")
    g = c.add_mutually_exclusive_group()
    g.add_argument("--nfluid", type=int, default=3500, help="fluid particles per cell (>=)")
    g.add_argument("--spacing", type=float, help="fluid lattice spacing")
    c.add_argument("--inset", type=float, help="keep fluid this far inside the wall")
    c.add_argument("--centres", default="0,0,0", help="cell centres 'x,y,z;x,y,z'")
    c.add_argument("--rho0", type=float, help="fluid density (default 1 pg/um^3 = 1000 kg/m^3)")
    w = c.add_mutually_exclusive_group()
    w.add_argument("--wall-mass", type=float, help="total wall mass of a cell (default 1.3e4 pg)")
    w.add_argument("--wall-areal-density", type=float, help="rho_s t0 (mass per wall area)")
    c.add_argument("--pad", type=float, help="box padding around the cells (10 um)")
    c.add_argument("--box", type=float, nargs=6)
    c.add_argument("--units", choices=sorted(UNITS), default="micro")
    s = sub.add_parser("sheet", help="flat triangular tether sheet (Appendix 1)")
    s.add_argument("-o", "--output", required=True)
    s.add_argument("--nx", type=int, default=20)
    s.add_argument("--ny", type=int, default=20)
    s.add_argument("--bond", type=float, default=2.5)
    s.add_argument("--thickness", type=float, default=0.126)
    s.add_argument("--orient", choices=("x", "y"), default="x", help="direction of the bond rows")
    s.add_argument("--rho-s", type=float, default=8.956, help="wall density (pg/um^3)")
    args = p.parse_args(argv)
    (build_cells if args.what == "cell" else build_sheet)(args)


if __name__ == "__main__":
    main()
