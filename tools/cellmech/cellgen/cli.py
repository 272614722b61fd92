# SPDX-License-Identifier: GPL-2.0-or-later
"""cellgen.py's command line (tools/cellgen.py runs main): one subcommand per builder, its options
the builder's arguments."""
import argparse
import os
import re
import sys

from . import __doc__ as PACKAGE_DOC
from .cells import UNITS, build_cells, build_sheet
from .limits import MAX_LLOYD, MAX_SHARPNESS, MAX_SMOOTH, number, output_file, whole
from .tissue import LATTICES, build_tissue


class Parser(argparse.ArgumentParser):
    """argparse that reports a bad argument in one line (without the usage block)."""

    def __init__(self, *a, **k):
        super().__init__(*a, **k)
        # argparse takes '-1e9' for an option (its pattern knows '-1' and '-1.5' only), so
        # '--remove-box -1e9 ...' read as a missing value
        self._negative_number_matcher = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message}\n")


def cell_options(c):
    """cellgen.py cell's options (build_cells's arguments)."""
    c.add_argument("--level", type=whole(0, 6), help="subdivision level (4: 2562 nodes)")
    c.add_argument("--radius", type=number(above=0), help="cell radius (default 30 um)")
    g = c.add_mutually_exclusive_group()
    g.add_argument("--nfluid", type=whole(0), help="fluid particles per cell (>=)")
    g.add_argument("--spacing", type=number(above=0), help="fluid lattice spacing")
    c.add_argument("--inset", type=number(minimum=0), help="keep fluid this far inside the wall")
    c.add_argument("--centres", help="cell centres 'x,y,z;x,y,z'")
    c.add_argument("--rho0", type=number(above=0), help="fluid density (default 1 pg/um^3 = 1000 kg/m^3)")
    w = c.add_mutually_exclusive_group()
    w.add_argument("--wall-mass", type=number(above=0), help="total wall mass of a cell (default 1.3e4 pg)")
    w.add_argument("--wall-areal-density", type=number(above=0), help="rho_s t0 (mass per wall area)")
    c.add_argument("--wall-mass-by-area", action="store_true",
                   help="wall node masses in proportion to their share of the wall area (uniform "
                        "surface density) instead of equal")
    c.add_argument("--pad", type=number(minimum=0), help="box padding around the cells (10 um)")
    c.add_argument("--box", type=number(), nargs=6)
    c.add_argument("--units", choices=sorted(UNITS))


def sheet_options(s):
    """cellgen.py sheet's options (build_sheet's arguments)."""
    s.add_argument("--nx", type=whole(2))
    s.add_argument("--ny", type=whole(2))
    s.add_argument("--bond", type=number(above=0))
    s.add_argument("--thickness", type=number(above=0))
    s.add_argument("--orient", choices=("x", "y"), help="direction of the bond rows")
    s.add_argument("--rho-s", type=number(above=0), help="wall density (pg/um^3)")


def tissue_options(t):
    """cellgen.py tissue's options (build_tissue's arguments)."""
    g = t.add_mutually_exclusive_group(required=True)
    g.add_argument("--lattice", choices=sorted(LATTICES), help="seeds on a lattice")
    g.add_argument("--random", type=whole(1), metavar="N", help="N random seeds in a box")
    g.add_argument("--centres", metavar="FILE", help="seeds from a file: x y z [r] per line")
    t.add_argument("--n", type=whole(1), nargs="+", metavar="N",
                   help="lattice repeats NX NY NZ (default 2 2 2)")
    r = t.add_mutually_exclusive_group()
    r.add_argument("--radius", type=number(above=0), help="equivalent-sphere cell radius (default 30 um)")
    r.add_argument("--spacing", type=number(above=0), help="lattice constant instead of --radius")
    t.add_argument("--size", type=number(above=0), nargs=3, metavar="L", help="--random: box LX LY LZ")
    t.add_argument("--min-dist", type=number(above=0), help="--random: minimum seed distance")
    t.add_argument("--lloyd", type=whole(0, MAX_LLOYD), metavar="K",
                   help="Lloyd iterations (default 0)")
    t.add_argument("--seed", type=whole(0), help="random seed (default 1)")
    t.add_argument("--tissue-box", type=number(), nargs=6, metavar="X",
                   help="block that clips the cells: xlo xhi ylo yhi zlo zhi")
    t.add_argument("--remove-box", type=number(), nargs=6, metavar="X",
                   help="leave empty the cells whose seeds lie in xlo xhi ylo yhi zlo zhi (a notch)")
    t.add_argument("--elongate", type=number(above=0), nargs=3, metavar="F", help="stretch factors ax ay az")
    t.add_argument("--level", type=whole(0, 6), help="icosphere level of each wall (default 3)")
    t.add_argument("--gap", type=number(above=0), help="wall-wall gap (default 2.56 um)")
    t.add_argument("--sharpness", type=number(minimum=2, maximum=MAX_SHARPNESS),
                   help="edge rounding exponent p (16)")
    t.add_argument("--surface", choices=("round", "cut"),
                   help="free surface of the block: domed cells (round) or flat faces (cut)")
    t.add_argument("--dome", type=number(above=0),
                   help="round surface: dome radius / the cell's equivalent radius (1.0)")
    t.add_argument("--smooth", type=whole(0, MAX_SMOOTH), help="tangential smoothing iterations (100)")
    t.add_argument("--min-angle", type=number(minimum=0),
                   help="smallest triangle angle allowed (20)")
    t.add_argument("--air", "--porosity", type=number(), help="target porosity (intercellular air)")
    f = t.add_mutually_exclusive_group()
    f.add_argument("--nfluid", type=whole(0), help="fluid count of a mean cell (440)")
    f.add_argument("--fluid-spacing", type=number(above=0), help="fluid lattice spacing")
    t.add_argument("--inset", type=number(minimum=0), help="fluid distance from the wall (default r0 of the level: 3.2 um at level 3, 1.6 at 4)")
    t.add_argument("--bond-cutoff", type=number(above=0), help="lamella bond cutoff (default 1.5 gap)")
    t.add_argument("--no-glue", action="store_true", help="no middle-lamella bonds")
    t.add_argument("--rho0", type=number(above=0), help="fluid density (1 pg/um^3)")
    t.add_argument("--wall-areal-density", type=number(above=0),
                   help="wall mass per area (1.3e4/(4 pi 30^2))")
    t.add_argument("--pad", type=number(minimum=0), help="box padding around the atoms (10 um)")
    t.add_argument("--stats", type=output_file, help="statistics JSON (default: output name with .json)")


SUBCOMMANDS = {  # help, options, builder
    "cell": ("one or more cells: geodesic wall + clipped fluid lattice", cell_options, build_cells),
    "sheet": ("flat triangular tether sheet (Appendix 1)", sheet_options, build_sheet),
    "tissue": ("a block of glued polyhedral cells (Voronoi/Laguerre walls)", tissue_options, build_tissue),
}


def parser():
    p = Parser(prog="cellgen.py", description=PACKAGE_DOC.split("\n")[0])
    sub = p.add_subparsers(dest="what", required=True)
    for name, (what, options, _) in SUBCOMMANDS.items():
        # an option not given is not passed: the builders' signatures hold the defaults
        sp = sub.add_parser(name, help=what, argument_default=argparse.SUPPRESS)
        sp.add_argument("-o", "--output", required=True, type=output_file)
        options(sp)
        sp.add_argument("--bending", action="store_true",
                        help="also write the bending hinges (Dihedrals) for dihedral style cell/bending")
    return p


def main(argv=None):
    options = vars(parser().parse_args(argv))
    try:
        SUBCOMMANDS[options.pop("what")][2](**options)
        sys.stdout.flush()
    except BrokenPipeError:
        # the summary piped into head: the files are written; no traceback for the closed pipe
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
