# SPDX-License-Identifier: GPL-2.0-or-later
"""cellgen --bending: the hinges (LAMMPS dihedrals i-j-k-l of dihedral style cell/bending) are one
per edge shared by two wall triangles, with j-k that edge and (i, j, k), (l, k, j) the two triangles
as the data file orients them; without the option the data files have no dihedrals."""
import numpy as np
import pytest

from cellmech import cellgen
from cellmech.cellgen.datafile import read_data


def read(path):
    """Header counts and the Angles and Dihedrals sections of a cellgen data file."""
    data = read_data(path)
    return data.counts, {k: [tuple(int(v) for v in w[2:]) for w in data.rows(k)]
                         for k in ("Angles", "Dihedrals", "Bonds")}


def check_hinges(tris, dihedrals):
    """Every dihedral: (i, j, k) and (l, k, j) are triangles of the file up to a cyclic turn (the
    same orientation), and no edge has two hinges. Returns the set of hinge edges."""
    cyc = set()
    for a, b, c in tris:
        cyc |= {(a, b, c), (b, c, a), (c, a, b)}
    edges = set()
    for i, j, k, l in dihedrals:
        assert (i, j, k) in cyc, f"hinge {i}-{j}-{k}-{l}: (i, j, k) is not a triangle in its orientation"
        assert (l, k, j) in cyc, f"hinge {i}-{j}-{k}-{l}: (l, k, j) is not a triangle in its orientation"
        e = (min(j, k), max(j, k))
        assert e not in edges, f"edge {e} has two hinges"
        edges.add(e)
    return edges


def tri_edges(tris):
    e = {}
    for a, b, c in tris:
        for u, v in ((a, b), (b, c), (c, a)):
            e[(min(u, v), max(u, v))] = e.get((min(u, v), max(u, v)), 0) + 1
    return e


@pytest.mark.parametrize("level", [0, 1, 2, 3])
def test_closed_wall_has_a_hinge_per_edge(tmp_path, level):
    out = tmp_path / "cell.data"
    cellgen.main(["cell", "-o", str(out), "--level", str(level), "--nfluid", "0",
                  "--centres", "0,0,0;70,0,0", "--bending"])
    counts, sec = read(out)
    nedge = 2 * 30 * 4 ** level    # two closed icospheres
    print(f"level {level}: {counts['dihedrals']} dihedrals, {nedge} edges, {counts['bonds']} tethers")
    assert counts["dihedrals"] == len(sec["Dihedrals"]) == nedge == counts["bonds"]
    assert counts["dihedral types"] == 1
    edges = check_hinges(sec["Angles"], sec["Dihedrals"])
    assert edges == set(tri_edges(sec["Angles"]))
    # the hinges' edges are the tethers
    assert edges == {(min(a, b), max(a, b)) for a, b in sec["Bonds"]}


def test_sheet_hinges_are_its_interior_edges(tmp_path):
    out = tmp_path / "sheet.data"
    cellgen.main(["sheet", "-o", str(out), "--nx", "7", "--ny", "6", "--bending"])
    _, sec = read(out)
    e = tri_edges(sec["Angles"])
    interior = {k for k, n in e.items() if n == 2}
    # a sheet of nx x ny nodes: 3 nx ny - 2 nx - 2 ny + 1 ... counted from its triangles instead:
    # E = (3 T + boundary) / 2 and the boundary has 2 (nx - 1) + 2 (ny - 1) edges
    nb = 2 * (7 - 1) + 2 * (6 - 1)
    print(f"sheet 7x6: {len(sec['Angles'])} triangles, {len(e)} edges, {nb} on the boundary, "
          f"{len(sec['Dihedrals'])} hinges")
    assert len(e) - len(interior) == nb
    assert check_hinges(sec["Angles"], sec["Dihedrals"]) == interior


def test_tissue_hinges_close_every_wall(tmp_path):
    out = tmp_path / "tissue.data"
    cellgen.main(["tissue", "-o", str(out), "--lattice", "sc", "--n", "2", "1", "1", "--level", "1",
                  "--nfluid", "4", "--bending"])
    counts, sec = read(out)
    print(f"tissue of 2 level-1 cells: {counts['dihedrals']} hinges, {len(sec['Angles'])} triangles")
    assert counts["dihedrals"] == 2 * 120 == 3 * len(sec["Angles"]) // 2
    assert check_hinges(sec["Angles"], sec["Dihedrals"]) == set(tri_edges(sec["Angles"]))


def test_without_the_option_no_dihedrals(tmp_path):
    for what, extra in (("cell", ["--level", "1", "--nfluid", "0"]), ("sheet", ["--nx", "4", "--ny", "4"])):
        out = tmp_path / f"{what}.data"
        cellgen.main([what, "-o", str(out)] + extra)
        text = out.read_text()
        assert "ihedral" not in text


def test_inconsistent_orientation_is_refused():
    with pytest.raises(ValueError, match="consistently oriented"):
        cellgen.hinges([(0, 1, 2), (0, 1, 3)])
    # a correctly oriented pair gives the one hinge with its triangles in their orientation
    assert cellgen.hinges([(0, 1, 2), (1, 0, 3)]) == [(2, 0, 1, 3)]
