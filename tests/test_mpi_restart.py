# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 2, check 7: the same forces on 1 and 2 MPI ranks at step 0, and a run continued from
write_restart / read_restart that matches an uninterrupted run.

System: lammps-inputs/in.plates on a level-3 wall with fluid inside (8-4 fluid-wall and wall-wall
contacts), perturbed by a random displacement and random velocities (so tether damping and contact
damping act), plates moving. The displacement (0.1 um at random) keeps the contacts' kicks below
the neighbour skin per step: at 0.3 um a node reached 119 um/us, 0.12 um per step against a
skin of 0.1, which the styles rightly stop as a blow-up (neighbour pairs could be missed). Tolerances: forces on different rank counts differ only by the order
of summation (1e-12 of the largest force); the restarted run rebuilds its neighbour lists at the
same step as the uninterrupted one (which is split into two `run` commands), so positions agree
to round-off after 100 steps (1e-10 of the box size).
"""
import os

import numpy as np
import pytest

import lmptest as T

SETUP = """
variable        dir index {inputs}
include         {inputs}/in.plates
"""
PERTURB = """
displace_atoms  all random 0.1 0.1 0.1 4711 units box
velocity        all create 1.0e6 2024 dist gaussian mom yes rot yes
pair_coeff      * * 2.0e5 2.4 5.0
"""


def dump_table(path):
    rows = [l.split() for l in open(path).read().splitlines()[9:]]
    a = np.array(rows, float)
    return a[np.argsort(a[:, 0])]


COMMON = dict(data="cell.data", nsteps=0, vplate=2.0, zbot0=-30.2, ztop0=30.2, every=1000)


@pytest.fixture(scope="module")
def cell(rundir):
    T.cellgen("cell", "-o", "cell.data", "--level", 3, "--nfluid", 400, cwd=rundir)
    return rundir


def test_step0_forces_rank_independent(cell):
    d = cell
    step0 = SETUP.format(inputs=T.INPUTS) + PERTURB + """
run             0
write_dump      all custom f0-${np}.dump id fx fy fz modify sort id format float %.17g
"""
    forces = {}
    for np_ in (1, 2):
        T.lmp(step0, cwd=d, nprocs=np_, variables=dict(COMMON, np=np_), log=f"log.step0-{np_}")
        forces[np_] = dump_table(f"{d}/f0-{np_}.dump")
    fmax = np.abs(forces[1][:, 1:]).max()
    err = np.abs(forces[1][:, 1:] - forces[2][:, 1:]).max() / fmax
    print(f"step 0: {len(forces[1])} atoms, max |f| = {fmax:.4g} nN, 1 vs 2 ranks max diff {err:.2e}")
    T.check("same atoms on 1 and 2 ranks", np.array_equal(forces[1][:, 0], forces[2][:, 0]))
    T.check("step-0 forces on 1 and 2 ranks agree to round-off", err < 1e-12, f"{err:.1e}")


def test_restart_continues_run(cell):
    d = cell
    full = SETUP.format(inputs=T.INPUTS) + PERTURB + """
run             100
write_restart   half.restart
run             100
write_dump      all custom full.dump id x y z vx vy vz modify sort id format float %.17g
"""
    T.lmp(full, cwd=d, variables=COMMON, log="log.full")
    cont = SETUP.format(inputs=T.INPUTS) + """
pair_coeff      * * 2.0e5 2.4 5.0
run             100
write_dump      all custom cont.dump id x y z vx vy vz modify sort id format float %.17g
"""
    T.lmp(cont, cwd=d, variables=dict(COMMON, restart="half.restart"), log="log.cont")
    a, b = dump_table(f"{d}/full.dump"), dump_table(f"{d}/cont.dump")
    dx = np.abs(a[:, 1:4] - b[:, 1:4]).max()
    dv = np.abs(a[:, 4:7] - b[:, 4:7]).max() / np.abs(a[:, 4:7]).max()
    moved = np.abs(a[:, 1:4]).max()
    print(f"restart: max position diff {dx:.2e} um, velocity diff {dv:.2e} (relative)")
    T.check("restart continues the run: positions", dx < 1e-10 * moved, f"{dx:.1e} um")
    T.check("restart continues the run: velocities", dv < 1e-9, f"{dv:.1e}")
