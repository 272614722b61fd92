"""Tissue, protoplasm kept apart: the fluid of one cell never interacts through SPH with the fluid
of another cell, and no mass crosses between two adjacent cells held at different pressures.

1. Two fluid particles 3 um apart (inside the kernel support 2s = 6.4 um), compressed (pressure)
   and approaching (continuity, viscosity), run for one step. Same molecule: they push each other
   and their density rises. Different molecules (two cells): the force on each is exactly zero, the
   density exactly unchanged and the velocities exactly as given: a check that fails if any SPH
   term crosses.
2. Two glued cells of a tissue (cellgen.py tissue, 2x1x1), each with its own osmotic potential
   (-364 and -100 kPa: one fix cell/fluid per cell), inflated side by side. Their fluids sit
   within the kernel support across the double wall. Each cell's fluid mass changes only by its own
   osmotic uptake (to round-off), no particle changes cell or leaves its wall, and each cell
   settles at its own turgor, P = -Pi, within the osmotic equilibrium tolerance of the single-cell
   inflation test (2%): were SPH acting across, the high-pressure fluid would push the other.
"""
import os

import numpy as np

import lmptest as T

PAIR = """
units           micro
atom_style      molecular
atom_modify     map array
boundary        f f f
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
region          box block -20 20 -20 20 -20 20
create_box      1 box
create_atoms    1 single -1.5 0.2 0.1
create_atoms    1 single 1.5 -0.1 0.0
set             atom 1 mol 1
set             atom 2 mol {m2}
set             type 1 mass 1.0
set             type 1 d_rho 1.05
pair_style      cell/sph
pair_coeff      1 1 1.0 264.6 0.0 10.0 3.2
comm_modify     vel yes
velocity        all set 0 0 0
set             atom 1 vx 2.0
set             atom 2 vx -2.0 vy 0.5
fix             nve all nve
fix             dens all cell/fluid Pi 0 Lp 0
timestep        0.001
dump            d all custom 1 pair.dump id fx fy fz vx vy vz d_rho
dump_modify     d format float %.17g sort id
run             1
"""


def read_dump(path):
    """Last snapshot of a dump custom file as an array (rows sorted by id)."""
    lines = open(path).read().splitlines()
    start = max(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    return np.array([[float(v) for v in l.split()] for l in lines[start + 1:] if l.strip()])


def pair_check():
    d = T.workdir("tissue-sph-pair")
    out = {}
    for m2 in (1, 2):
        T.lmp(PAIR.format(m2=m2), cwd=d, log=f"log.m{m2}")
        a = read_dump(os.path.join(d, "pair.dump"))
        out[m2] = a
        f = np.abs(a[:, 1:4]).max()
        drho = np.abs(a[:, 7] - 1.05).max()
        print(f"molecules 1 and {m2}: max |f| = {f:.6g} nN, max |rho - rho(0)| = {drho:.3g}, "
              f"velocities {a[:, 4:7].tolist()}")
    same, apart = out[1], out[2]
    T.check("same cell: the pair interacts (force and density rate nonzero)",
            np.abs(same[:, 1:4]).max() > 1.0 and np.abs(same[:, 7] - 1.05).max() > 1e-8)
    T.check("two cells: zero SPH force", np.abs(apart[:, 1:4]).max() == 0.0,
            f"{np.abs(apart[:, 1:4]).max():.3g}")
    T.check("two cells: density unchanged", np.abs(apart[:, 7] - 1.05).max() == 0.0,
            f"{np.abs(apart[:, 7] - 1.05).max():.3g}")
    T.check("two cells: velocities unchanged",
            np.array_equal(apart[:, 4:7], np.array([[2.0, 0, 0], [-2.0, 0.5, 0]])))


TWO = """
units           micro
atom_style      molecular
boundary        f f f
atom_modify     map array
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 d_alam ghost yes
read_data       tissue.data fix cell NULL cell extra/special/per/atom {special}
group           wall type 1
group           fluid type 2
group           f1 intersect fluid c1
include         {inputs}/cell-model.lmp
"""


def main():
    pair_check()
    T.finish()


if __name__ == "__main__":
    main()
