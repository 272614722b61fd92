# SPDX-License-Identifier: GPL-2.0-or-later
"""Helpers for the script tests: run lmp with the cellmech plugin, read its outputs.

Environment (set by CTest, see tests/CMakeLists.txt): LMP, CELLMECH_PLUGIN, CELLMECH_ROOT, MPIEXEC,
and PYTHONPATH=tools for the package cellmech (run by hand:
PYTHONPATH=tools python3 -m pytest -q -p no:cacheprovider tests/test_X.py). tests/conftest.py makes
these helpers pytest fixtures and fails a test whose checks (check below) failed.
"""
import os
import re
import subprocess
import sys

import numpy as np

from cellmech import params
from cellmech.launch import mpi_command, mpiexec

ROOT = os.environ.get("CELLMECH_ROOT", os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LMP = os.environ.get("LMP", "lmp")
PLUGIN = os.environ.get("CELLMECH_PLUGIN", os.path.join(ROOT, "build", "cellmechplugin.so"))
MPIEXEC = mpiexec()
INPUTS = os.path.join(ROOT, "lammps-inputs")
CELLGEN = os.path.join(ROOT, "tools", "cellgen.py")

# the coarse cell's model lengths (level 3 of the level table, cellmech/params.py), as -var settings
COARSE = {k: params.LEVELS[3][k] for k in ("s", "r0", "f0", "reach")}
# Table I (lammps-inputs/cell-model.lmp) and the cell around it, for the tests' references
TABLE, CELL, STIFF, SOFT = params.table(), params.CELL, params.stiff(), params.SOFT

failures = []


def workdir(name):
    d = os.path.join(os.getcwd(), "work-" + name)
    os.makedirs(d, exist_ok=True)
    return d


def cellgen(*args, cwd):
    subprocess.run([sys.executable, CELLGEN, *map(str, args)], cwd=cwd, check=True,
                   stdout=subprocess.DEVNULL)


def coarse_cell(cwd, out="cell.data", *extra):
    """The coarse test cell: level-3 wall (642 nodes), 440 fluid particles kept r0 of the coarse
    model from the wall; extra cellgen options (e.g. --bending) follow."""
    cellgen("cell", "-o", out, "--level", 3, "--nfluid", 440, "--inset", COARSE["r0"], *extra, cwd=cwd)


def inflate_coarse(cwd, nsteps, every=1000, jitter=0):
    """coarse_cell, then in.inflate (Table I, coarse lengths) for nsteps to inflated.restart;
    its record in inflate.dat, its log in log.inflate. jitter > 0 (a seed): the fluid starts
    displaced by up to 1e-9 um, and the names end in -jSEED (inflated-j1.restart, ...)."""
    coarse_cell(cwd)
    tag = f"-j{jitter}" if jitter else ""
    lmp(INPUTS + "/in.inflate", cwd=cwd, log=f"log.inflate{tag}", variables=dict(
        COARSE, dir=INPUTS, data="cell.data", nsteps=nsteps, every=every, out=f"inflate{tag}.dat",
        restart_out=f"inflated{tag}.restart", jitter=jitter))


def plugin_env():
    """The environment lmp runs in: LAMMPS finds the plugin in its folder."""
    return dict(os.environ, LAMMPS_PLUGIN_PATH=os.path.dirname(PLUGIN))


def lmp(input_file, cwd, nprocs=1, variables=None, check=True, log="log.lammps"):
    """Run lmp on input_file (path, or text written to cwd/in.test); return (rc, log text)."""
    if "\n" in input_file:
        path = os.path.join(cwd, "in.test")
        with open(path, "w") as f:
            f.write(input_file)
        input_file = path
    cmd = [LMP, "-in", input_file, "-log", log, "-screen", "none"]
    for k, v in (variables or {}).items():
        cmd += ["-var", k, str(v)]
    cmd = mpi_command(cmd, nprocs, MPIEXEC)
    p = subprocess.run(cmd, cwd=cwd, env=plugin_env(), capture_output=True, text=True)
    text = open(os.path.join(cwd, log)).read() if os.path.exists(os.path.join(cwd, log)) else ""
    if check and p.returncode != 0:
        print(text[-3000:], p.stdout[-2000:], p.stderr[-2000:])
        raise AssertionError(f"lmp failed (rc {p.returncode}): {' '.join(cmd)}")
    return p.returncode, text


def continue_cell(restart):
    """Input lines that continue a cell run from a restart file: restart files keep neither the
    per-atom fields' definition nor pair_style hybrid's coefficients, so both come again."""
    return f"""
units           micro
read_restart    {restart}
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
group           wall type 1
group           fluid type 2
variable        dir index {INPUTS}
include         {INPUTS}/cell-model.lmp
fix             integrate all nve
"""


def cell_from_data(data):
    """Input lines that start a cell run from a data file of tools/cellgen.py: the per-atom fields
    the styles keep, the data (with room for the special neighbours that failure and the lamella
    add) and the groups of wall and fluid."""
    return f"""
units           micro
atom_style      molecular
boundary        f f f
atom_modify     map array
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
read_data       {data} fix cell NULL cell extra/special/per/atom 6
group           wall type 1
group           fluid type 2
"""


# A periodic box of SPH fluid (type 1) and fixed SPH wall particles (type 2) on a lattice, for
# the fluid tests without a cell: the lines before the box is made, and those after its atoms are.
# a tissue data file read with tissue-model.lmp (units micro, the fields of cellgen.py tissue);
# fill in data and special with str.format, ${{dir}} stays a LAMMPS variable
TISSUE_HEAD = """
units           micro
atom_style      molecular
boundary        m m m
atom_modify     map array
variable        Pi index -364.0
variable        Lp index 10.0
variable        mu index 10.0
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 d_alam ghost yes
read_data       {data} fix cell NULL cell extra/special/per/atom {special}
include         ${{dir}}/tissue-model.lmp
"""

SPH_BOX_HEAD = """
units           micro
atom_style      molecular
atom_modify     map array
boundary        p p p
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
"""


def sph_box_fluid(rho0, c, p0, mu, s, dx, set_rho=True):
    """Input lines that make the atoms of an SPH_BOX_HEAD box fluid at rest (mass rho0 dx^3,
    density rho0, or the densities the atoms have with set_rho False) with pair cell/sph and fix
    cell/fluid (no osmosis); walls (type 2) unintegrated."""
    return f"""
set             type 1*2 mol 1
set             type 1*2 mass {rho0 * dx ** 3}
""" + (f"set             type 1*2 d_rho {rho0}\n" if set_rho else "") + f"""group           fluid type 1
pair_style      cell/sph
pair_coeff      1 1 {rho0} {c} {p0} {mu} {s}
pair_coeff      2 2 {rho0} {c} {p0} {mu} {s}
comm_modify     vel yes
neighbor        0.3 bin
fix             nve fluid nve
fix             dens fluid cell/fluid Pi 0 Lp 0
"""


def load(path):
    """Numeric table of a fix ave/time or print file (comment lines '#')."""
    return np.loadtxt(path, comments="#", ndmin=2)


def check(name, ok, detail=""):
    """One check: prints PASS or FAIL; a test with a failed check fails at its end (conftest.py)."""
    print(f"{'PASS' if ok else 'FAIL'}  {name}  {detail}")
    if not ok:
        failures.append(name)


def performance(logtext):
    m = re.findall(r"Performance: .*", logtext)
    return m[-1] if m else ""
