# SPDX-License-Identifier: GPL-2.0-or-later
"""compute cell/props counts fluid outside its own wall (winding number of the closed wall mesh,
with a ball around the centre skipped as surely inside). A check that can fail: in a coarse cell,
fluid particles are added at known places - outside the wall (beyond a node, beyond a face),
just inside it between the nodes, and in the second cell's wall region but belonging to the first
- and the leak column must count exactly the outside ones, on 1 and on 2 ranks.
"""
import pytest

import lmptest as T

COARSE = dict(T.COARSE)
EXTRA = """
# cell 1 at the origin, cell 2 at x = 80. Outside cell 1: beyond a face and beyond a node;
# inside cell 1 close to its wall; and a cell-1 particle sitting inside cell 2 (outside its own wall)
variable        n0 equal $(count(all))
create_atoms    2 single 0 0 31.5
create_atoms    2 single 33 0 0
create_atoms    2 single 0 27.5 3
create_atoms    2 single 80 0 0
group           added id > ${n0}
set             group added mol 1
set             group added mass 10.0
set             group added d_rho 1.0
variable        leak1 equal c_props[1][9]
variable        leak2 equal c_props[2][9]
variable        nf1 equal c_props[1][5]
run             0
print           "LEAKS ${leak1} ${leak2} ${nf1}"
"""


@pytest.fixture(scope="module")
def two_cells(rundir):
    T.cellgen("cell", "-o", "two.data", "--level", 3, "--nfluid", 200, "--inset", 3.2,
              "--centres", "0,0,0;80,0,0", "--pad", 20, cwd=rundir)
    return rundir


@pytest.mark.parametrize("n", (1, 2))
def test_outside_fluid_counted_as_leak(two_cells, n):
    d = two_cells
    _, log = T.lmp(f"include {T.INPUTS}/in.inflate\n" + EXTRA, cwd=d, nprocs=n,
                   variables=dict(COARSE, dir=T.INPUTS, data="two.data", nsteps=0, Lp=0.0),
                   log=f"log.{n}")
    line = [l for l in log.splitlines() if l.startswith("LEAKS")][-1].split()
    leak1, leak2, nf1 = float(line[1]), float(line[2]), float(line[3])
    print(f"{n} rank(s): cell 1 leaks {leak1:g}, cell 2 leaks {leak2:g}, cell 1 fluid {nf1:g}")
    T.check(f"{n} rank(s): the three outside particles of cell 1 are counted", leak1 == 3)
    T.check(f"{n} rank(s): no leak in cell 2", leak2 == 0)
