# SPDX-License-Identifier: GPL-2.0-or-later
"""cellgen cell --wall-mass-by-area: every wall node carries a third of its triangles' area times
one surface density (the tissue's rule), the wall's total is --wall-mass, fluid masses unchanged;
without it the wall nodes' masses are equal (the default, unchanged)."""
import numpy as np
import pytest

from cellmech import cellgen
from cellmech.cellgen.datafile import read_data


def read(path):
    """Positions and molecule/type per atom, triangles, and the per-atom masses (cell section)."""
    data = read_data(path)
    atoms = {int(w[0]): (int(w[1]), int(w[2]), np.array([float(v) for v in w[3:6]]))
             for w in data.rows("Atoms")}
    tris = np.array([[int(v) for v in w[2:5]] for w in data.rows("Angles")])
    return atoms, tris, {int(w[0]): float(w[1]) for w in data.rows("cell")}


@pytest.mark.parametrize("level", [2, 3])
def test_masses_follow_the_node_areas(tmp_path, level):
    out = tmp_path / "cell.data"
    M = 1.3e4
    cellgen.main(["cell", "-o", str(out), "--level", str(level), "--nfluid", "50", "--wall-mass", str(M),
                  "--centres", "0,0,0;70,0,0", "--wall-mass-by-area"])
    atoms, tris, mass = read(out)
    x = {i: a[2] for i, a in atoms.items()}
    area = {i: 0.0 for i in atoms}
    for a, b, c in tris:
        t = 0.5 * np.linalg.norm(np.cross(x[b] - x[a], x[c] - x[a]))
        for n in (a, b, c):
            area[n] += t / 3
    for cell in (1, 2):
        wall = [i for i, a in atoms.items() if a[0] == cell and a[1] == 1]
        m = np.array([mass[i] for i in wall])
        dens = m / np.array([area[i] for i in wall])
        fluid = {mass[i] for i, a in atoms.items() if a[0] == cell and a[1] == 2}
        print(f"level {level} cell {cell}: wall mass {m.sum():.10g}, node masses {m.min():.6g}..{m.max():.6g}, "
              f"density spread {np.ptp(dens) / dens.mean():.2e}, fluid masses {sorted(fluid)}")
        assert m.sum() == pytest.approx(M, rel=1e-12)
        assert np.ptp(dens) / dens.mean() < 1e-12
        assert m.max() / m.min() > 1.2          # the geodesic node areas do differ
        assert len(fluid) == 1


def test_default_masses_are_equal(tmp_path):
    out = tmp_path / "cell.data"
    cellgen.main(["cell", "-o", str(out), "--level", "2", "--nfluid", "0", "--wall-mass", "1.3e4"])
    atoms, _, mass = read(out)
    m = np.array([mass[i] for i, a in atoms.items() if a[1] == 1])
    print(f"default: {len(m)} wall nodes of {m[0]:.10g}")
    assert np.ptp(m) == 0 and m.sum() == pytest.approx(1.3e4, rel=1e-12)
