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
                    [--air F] [--nfluid 440 | --fluid-spacing S] [--inset R0] [--bond-cutoff C]
                    [--no-glue] [--stats FILE]        (docs/cellgen.rst, "Tissue"; needs scipy)
"""
# The package: mesh (the icosphere wall), fluid (the fluid fill), cells (single cells, the sheet),
# tissue (the Voronoi/Laguerre block, lamella, air), datafile (read and write LAMMPS data files),
# limits (bounds on the inputs), cli (the command line).
from .cells import UNITS, build_cells, build_sheet
from .cli import main
from .datafile import DataFile, read_data, write_data, write_lengths
from .fluid import fluid_by_count, fluid_in_wall, fluid_lattice, lattice_count_bound, spacing_for_count
from .limits import MAX_PARTICLES, check_count, fail
from .mesh import hinges, icosphere, mesh_area_volume
from .tissue import LATTICES, build_tissue

__all__ = ["UNITS", "build_cells", "build_sheet", "main", "DataFile", "read_data", "write_data",
           "write_lengths", "fluid_by_count", "fluid_in_wall", "fluid_lattice", "lattice_count_bound",
           "spacing_for_count", "MAX_PARTICLES", "check_count", "fail", "hinges", "icosphere",
           "mesh_area_volume", "LATTICES", "build_tissue"]
