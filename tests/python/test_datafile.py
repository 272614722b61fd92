# SPDX-License-Identifier: GPL-2.0-or-later
"""cellmech.cellgen.datafile: read_data takes a LAMMPS data file apart (header counts, box, tilt,
sections with their comments, comments and blank lines ignored), and the writer puts cellgen's
files back together byte for byte."""
import pytest

from cellmech import cellgen
from cellmech.cellgen.datafile import format_data, read_data

# as LAMMPS's write_data writes them: a title without '#', image flags, Velocities, coefficients
LAMMPS = """LAMMPS data file via write_data, version 4 Jul 2026, timestep = 10, units = micro

3 atoms
2 atom types
1 bonds
1 bond types

-40 40 xlo xhi
-41.5 41.5 ylo yhi
0 2.5e+01 zlo zhi
0.5 0 0 xy xz yz

Masses

1 26.13
2 203.5 # fluid

Pair Coeffs # cell/sph

1 1 2.5
2 1 2.5

Atoms # molecular

1 1 1 0.5 -1 2 0 0 0
2 1 2 1.5 1 2 -1 0 0
3 1 2 2.5 1 2 0 0 1

Velocities

1 0 0 0
2 0.1 0 0
3 0 0 -0.2

Bonds

1 1 1 2

cell

1 26.13 0 0 0.5 -1 2
2 203.5 1 0 1.5 1 2
3 203.5 1 0 2.5 1 2
"""


def test_lammps_file(tmp_path):
    path = tmp_path / "w.data"
    path.write_text(LAMMPS)
    d = read_data(path)
    assert d.title.startswith("LAMMPS data file via write_data")
    assert d.counts == {"atoms": 3, "atom types": 2, "bonds": 1, "bond types": 1}
    assert d.box == [-40.0, 40.0, -41.5, 41.5, 0.0, 25.0] and d.tilt == [0.5, 0.0, 0.0]
    assert list(d.sections) == ["Masses", "Pair Coeffs", "Atoms", "Velocities", "Bonds", "cell"]
    assert d.comments["Atoms"] == "molecular" and d.comments["Pair Coeffs"] == "cell/sph"
    assert d.rows("Masses") == [["1", "26.13"], ["2", "203.5"]]      # the row's comment is not data
    atoms = d.array("Atoms")
    assert atoms.shape == (3, 9) and atoms[1, 3] == 1.5 and atoms[1, 6] == -1
    assert d.array("cell")[:, 1].tolist() == [26.13, 203.5, 203.5]
    assert d.rows("Angles") == [] and d.array("Angles", width=5).shape == (0, 5)


def test_lammps_defaults(tmp_path):
    """No box lines: LAMMPS's -0.5 0.5 on each axis; no tilt."""
    path = tmp_path / "b.data"
    path.write_text("title\n\n1 atoms\n1 atom types\n\nAtoms # atomic\n\n1 1 0 0 0\n")
    d = read_data(path)
    assert d.box == [-0.5, 0.5] * 3 and d.tilt is None and d.rows("Atoms") == [["1", "1", "0", "0", "0"]]


@pytest.mark.parametrize("what,extra", [
    ("cell", ["--level", "2", "--nfluid", "30", "--bending", "--wall-mass-by-area"]),
    ("sheet", ["--nx", "5", "--ny", "4"]),
    ("tissue", ["--lattice", "sc", "--n", "2", "1", "1", "--level", "1", "--nfluid", "5"])])
def test_cellgen_round_trip(tmp_path, what, extra):
    """Read and written again, cellgen's file is the same text; its counts are its rows'."""
    out = tmp_path / f"{what}.data"
    cellgen.main([what, "-o", str(out)] + extra)
    d = read_data(out)
    assert format_data(d) == out.read_text()
    for key, name in (("atoms", "Atoms"), ("bonds", "Bonds"), ("angles", "Angles"),
                      ("dihedrals", "Dihedrals")):
        assert d.counts.get(key, 0) == len(d.rows(name)), key
    assert len(d.rows("cell")) == d.counts["atoms"]
    assert d.comments["cell"].split()[:2] == ["rmass", "d_rho"]
