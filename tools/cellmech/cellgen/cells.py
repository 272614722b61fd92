# SPDX-License-Identifier: GPL-2.0-or-later
"""Single cells (an icosphere wall around a fluid lattice, one or more, each its own molecule) and
the flat tether sheet of the paper's Appendix 1."""
import argparse
import math

import numpy as np

from .. import params
from .datafile import write_data
from .fluid import fluid_by_count, fluid_lattice, lattice_count_bound
from .limits import check_count, fail, number
from .mesh import icosphere, mesh_area_volume

_R, _M, _RHO0 = params.CELL["R"], params.CELL["M_wall"], params.table()["rho0"]
UNITS = {
    # defaults: radius, rho0, wall mass (docs/model.md section 3.1; cellmech.params), box padding
    "micro": dict(radius=_R, rho0=_RHO0, wall_mass=_M, pad=10.0),
    "si": dict(radius=_R / 1e6, rho0=_RHO0 * 1e3, wall_mass=_M / 1e15, pad=10e-6),  # m, kg/m^3, kg
}


def cell_centres(text, R):
    """The centres 'x,y,z;x,y,z;...' of cells of radius R, whose walls must not touch."""
    centres = []
    for c in text.split(";"):
        try:
            centres.append(tuple(number()(v) for v in c.split(",")))
        except argparse.ArgumentTypeError:
            centres.append(())
        if len(centres[-1]) != 3:
            fail("cell", f"--centres: expected finite 'x,y,z;x,y,z;...', got '{text}'")
    cc = np.array(centres)
    dist = np.linalg.norm(cc[:, None] - cc[None], axis=2) + np.diag(np.full(len(cc), np.inf))
    if dist.min() <= 2.0 * R:
        i, j = np.unravel_index(np.argmin(dist), dist.shape)
        fail("cell", f"--centres: cells {i + 1} and {j + 1} are {dist.min():.6g} apart, their walls "
                     f"(radius {R:g}) overlap or touch: expected centres more than {2 * R:g} apart")
    return centres


def cell_fluid(R, ncells, nw, nfluid, spacing, inset):
    """The fluid lattice of one cell (by spacing, or the largest that holds nfluid) and its spacing."""
    if inset >= R and (spacing is not None or nfluid > 0):
        fail("cell", f"--inset: expected a distance smaller than the radius {R:g} (the fluid stays "
                     f"that far inside the wall), got {inset:g}")
    if spacing is not None:
        check_count("cell", int(ncells * (nw + lattice_count_bound(R - inset, spacing))),
                    f"--spacing {spacing:g} in {ncells} cell(s) of radius {R:g}")
        return fluid_lattice(R, spacing, inset), spacing
    return fluid_by_count(R, nfluid, inset)


def cell_box(pts, box, pad):
    """The box: as given (around every particle), or the particles' bounds padded by pad."""
    if box:
        lo, hi = np.array(box[0::2]), np.array(box[1::2])
        if np.any(pts.min(axis=0) <= lo) or np.any(pts.max(axis=0) >= hi):
            fail("cell", f"--box: expected xlo xhi ylo yhi zlo zhi around every particle "
                         f"({' '.join(f'{a:.6g} {b:.6g}' for a, b in zip(pts.min(0), pts.max(0)))}), "
                         f"got {' '.join(f'{v:g}' for v in box)}")
        return box
    lo, hi = pts.min(axis=0) - pad, pts.max(axis=0) + pad
    return [lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]]


def node_masses_by_area(nodes, tri, wall_mass):
    """Wall node masses in proportion to a third of each adjacent triangle's area. Equal node
    masses give the geodesic wall a surface density that varies by -23..+20% in an icosahedral
    pattern (the node areas do), which the breathing mode drives out of round; these make the
    density uniform, as a tissue's."""
    trib = np.zeros(len(nodes))
    ta = 0.5 * np.linalg.norm(np.cross(nodes[tri[:, 1]] - nodes[tri[:, 0]],
                                       nodes[tri[:, 2]] - nodes[tri[:, 0]]), axis=1)
    for k in range(3):
        np.add.at(trib, tri[:, k], ta / 3.0)
    return wall_mass * trib / trib.sum()


def build_cells(output, level=4, radius=None, nfluid=3500, spacing=None, inset=None, centres="0,0,0",
                rho0=None, wall_mass=None, wall_areal_density=None, wall_mass_by_area=False, pad=None,
                box=None, units="micro", bending=False):
    """Write the data file of one or more cells (cellgen.py cell; docs/cellgen.rst): defaults of
    radius, rho0, wall mass and pad from UNITS[units]."""
    d = UNITS[units]
    R = radius if radius is not None else d["radius"]
    rho0 = rho0 if rho0 is not None else d["rho0"]
    centres = cell_centres(centres, R)
    nw = 10 * 4 ** level + 2
    if spacing is None:
        check_count("cell", len(centres) * (nw + nfluid),
                    f"{len(centres)} cell(s) of {nw} wall nodes and --nfluid {nfluid}")
    unit, tri, edges = icosphere(level)
    nodes = unit * R
    area, volume = mesh_area_volume(nodes, tri)
    if wall_areal_density is not None:
        wall_mass = wall_areal_density * 4.0 * math.pi * R * R
    else:
        wall_mass = wall_mass if wall_mass is not None else d["wall_mass"]
    mean_edge = np.linalg.norm(nodes[edges[:, 0]] - nodes[edges[:, 1]], axis=1).mean()
    # keep fluid half a wall spacing inside the wall so no particle starts in contact
    fluid, spacing = cell_fluid(R, len(centres), nw, nfluid, spacing,
                                inset if inset is not None else 0.5 * mean_edge)
    nf = len(fluid)
    # each fluid particle carries its lattice cell at density rho0: SPH takes m/rho as the particle's
    # volume, so m = rho0 spacing^3 keeps sum(m/rho) equal to the volume the fluid fills. (Spreading
    # rho0 V_wall over the particles instead makes every particle claim more room than it has: the
    # wall then feels a pressure ~30% above the fluid's.) Inflation fills the gap to the wall.
    m_fluid = rho0 * spacing ** 3 if nf else 1.0
    m_wall = wall_mass / nw
    atoms, bonds, angles = [], [], []
    for mol, c in enumerate(centres, 1):
        base = len(atoms)
        atoms += [(mol, 1, *(p + c)) for p in nodes] + [(mol, 2, *(p + c)) for p in fluid]
        bonds += [(base + a, base + b) for a, b in edges]
        angles += [(base + a, base + b, base + cc) for a, b, cc in tri]
    refs = [a[2:] for a in atoms]
    box = cell_box(np.array(refs), box, pad if pad is not None else d["pad"])
    title = (f"cellgen cell: {len(centres)} cell(s), level {level} ({nw} wall nodes), "
             f"{nf} fluid per cell, R {R:g}, spacing {spacing:.10g}, rho0 {rho0:g}, "
             f"wall mass {wall_mass:.6g}, units {units}")
    rho = [rho0 if a[1] == 2 else 0.0 for a in atoms]
    rmass = None
    if wall_mass_by_area:
        node_mass = node_masses_by_area(nodes, tri, wall_mass)
        rmass = [node_mass[(i - 1) % (nw + nf)] if a[1] == 1 else m_fluid
                 for i, a in enumerate(atoms, 1)]
        title += ", wall mass by area"
    write_data(output, title, box, atoms, bonds, angles, [m_wall, m_fluid], refs, rho,
               rmass=rmass, bending=bending)
    print(title)
    print(f"wall node mass {m_wall:.6g}, fluid particle mass {m_fluid:.6g}, "
          f"mesh area {area:.6g}, mesh volume {volume:.6g}, mean tether {mean_edge:.6g}")


def sheet_mesh(nx, ny, a):
    """Flat triangular mesh: ny rows of nx nodes a apart, rows offset by half a bond; its nodes,
    bonds and triangles (oriented +z)."""
    h = a * math.sqrt(3.0) / 2.0
    pts, index = [], {}
    for j in range(ny):
        for i in range(nx):
            index[(i, j)] = len(pts)
            pts.append((i * a + (0.5 * a if j % 2 else 0.0), j * h, 0.0))
    bonds, tris = [], []
    for j in range(ny):
        for i in range(nx):
            p = index[(i, j)]
            if i + 1 < nx:
                bonds.append((p, index[(i + 1, j)]))
            if j + 1 < ny:
                # even rows connect up to (i-1, i); odd rows to (i, i+1)
                up = [i - 1, i] if j % 2 == 0 else [i, i + 1]
                ups = [index[(k, j + 1)] for k in up if 0 <= k < nx]
                for q in ups:
                    bonds.append((p, q))
                if len(ups) == 2:
                    tris.append((p, ups[1], ups[0]))
                right = index.get((i + 1, j))
                upr = index.get(((i + 1) if j % 2 else i, j + 1))
                if right is not None and upr is not None:
                    tris.append((p, right, upr))
    return np.array(pts), bonds, tris


def build_sheet(output, nx=20, ny=20, bond=2.5, thickness=0.126, orient="x", rho_s=8.956, bending=False):
    """Write the data file of a flat triangular sheet (paper Appendix 1; cellgen.py sheet)."""
    a = bond
    check_count("sheet", nx * ny, f"--nx {nx} --ny {ny}")
    pts, bonds, tris = sheet_mesh(nx, ny, a)
    if orient == "y":
        # bonds along y: rotate by 90 degrees so that an X stretch pulls across the bond rows
        pts = np.column_stack([-pts[:, 1], pts[:, 0], pts[:, 2]])
        pts[:, 0] -= pts[:, 0].min()
    # node mass: areal density rho_s t0 over the node's share of the sheet area
    m = rho_s * thickness * (math.sqrt(3.0) / 2.0) * a * a
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    L = max(hi[0] - lo[0], hi[1] - lo[1])
    box = [lo[0] - L, hi[0] + L, lo[1] - L, hi[1] + L, -L, L]
    atoms = [(1, 1, *p) for p in pts]
    title = f"cellgen sheet: {nx}x{ny} nodes, bond {a:g}, bonds along {orient}"
    write_data(output, title, box, atoms, bonds, tris, [m], pts, [0.0] * len(atoms), bending=bending)
    print(title, f"{len(bonds)} tethers, {len(tris)} triangles, node mass {m:.6g}")
