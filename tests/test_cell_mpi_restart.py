# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 3, check 7: a fluid-filled cell (SPH, virtual particles, osmosis, tethers, contacts) gives
the same forces on 1 and 2 MPI ranks at step 0 (round-off of the summation order: 1e-12 of the
largest force), also with what a drying cell adds (the adhesion, the artificial stress and the
fluid's cohesion, at the level table's settings), and a run continued from write_restart / read_restart matches the uninterrupted
run. The continued run rebuilds its neighbour lists at the same step as the uninterrupted one
(split into two `run` commands), so positions, densities and masses agree to round-off; with the
paper's tethers and with the membrane wall with bending (-var wall bending).
"""
import numpy as np
import pytest

import lmptest as T
from cellmech import params

COARSE = dict(T.COARSE)
START = """
include         {inputs}/in.inflate
velocity        all create 1.0e7 77 dist gaussian mom yes rot yes
"""
DUMP = "write_dump all custom {name} id x y z vx vy vz fx fy fz d_rho mass modify sort id format float %.17g\n"


def table(path):
    a = np.loadtxt(path, skiprows=9)
    return a[np.argsort(a[:, 0])]


COMMON = dict(COARSE, dir=T.INPUTS, data="cell.data", nsteps=0, every=100, Lp=1.0, P0=50.0, mu=10.0)


@pytest.fixture(scope="module")
def cells(rundir):
    """The coarse cell with tethers (cell.data) and with bending hinges (cellb.data)."""
    T.coarse_cell(rundir)
    T.coarse_cell(rundir, "cellb.data", "--bending")
    return rundir


LEVEL3 = params.LEVELS[3]
DRYING = dict(Fa=LEVEL3["fa"], delta=LEVEL3["delta"], sphstress=0.2, dp=LEVEL3["dp"], sphcoh=LEVEL3["coh"])


@pytest.mark.parametrize("kind, extra", (("plain", {}), ("drying", DRYING)))
def test_step0_forces_rank_independent(cells, kind, extra):
    d = cells
    step0 = {}
    for n in (1, 2):
        T.lmp(START.format(inputs=T.INPUTS) + "run 0\n" + DUMP.format(name=f"f0-{kind}-{n}.dump"), cwd=d,
              nprocs=n, variables=dict(COMMON, **extra), log=f"log.step0-{kind}-{n}")
        step0[n] = table(f"{d}/f0-{kind}-{n}.dump")
    f1, f2 = step0[1][:, 7:10], step0[2][:, 7:10]
    err = np.abs(f1 - f2).max() / np.abs(f1).max()
    print(f"step 0: {len(f1)} atoms, max |f| {np.abs(f1).max():.4g} nN, 1 vs 2 ranks max diff {err:.2e}")
    T.check("step-0 forces on 1 and 2 ranks agree to round-off", err < 1e-12, f"{err:.1e}")


# the paper's tethers, and the membrane wall with bending (-var wall bending, its hinges from
# cellgen --bending): the continuing input gives the same -var wall
@pytest.mark.parametrize("wall, data", (("tether", "cell.data"), ("bending", "cellb.data")))
def test_restart_continues_run(cells, wall, data):
    d = cells
    var = dict(COMMON, data=data, wall=wall)
    full = START.format(inputs=T.INPUTS) + "run 200\nwrite_restart half.restart\nrun 200\n" + \
        DUMP.format(name="full.dump")
    T.lmp(full, cwd=d, nprocs=2, variables=var, log=f"log.full-{wall}")
    cont = "variable        Lp index 1.0\n" + T.continue_cell("half.restart") + """
fix             osmosis fluid cell/fluid Pi -364.0 Lp ${Lp}
timestep        0.001
run             200
""" + DUMP.format(name="cont.dump")
    T.lmp(cont, cwd=d, nprocs=2, variables={k: v for k, v in var.items() if k != "data"},
          log=f"log.cont-{wall}")
    a, b = table(f"{d}/full.dump"), table(f"{d}/cont.dump")
    dx = np.abs(a[:, 1:4] - b[:, 1:4]).max()
    drho = np.abs(a[:, 10] - b[:, 10]).max()
    dm = np.abs(a[:, 11] - b[:, 11]).max() / a[:, 11].max()
    print(f"{wall} wall, restart on 2 ranks: max position diff {dx:.2e} um, density diff "
          f"{drho:.2e}, mass diff {dm:.2e}")
    T.check(f"{wall} wall: restart continues the run (positions, 1e-10 um)", dx < 1e-10,
            f"{dx:.1e}")
    T.check(f"{wall} wall: restart continues the run (density and mass, 1e-12)",
            drho < 1e-12 and dm < 1e-12)
