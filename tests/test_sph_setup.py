# SPDX-License-Identifier: GPL-2.0-or-later
"""pair cell/sph between runs: the forces of a run that follows another one are those of a fresh
start from the same atoms, whatever happened to the atoms in between.

Why this needs a test: pair cell/sph keeps the fluid pairs of its neighbour list (the candidates)
from one neighbour-list build to the next and knew a new build by LAMMPS's build count. Every
setup (run, minimize, each rerun frame) builds the lists anew and then sets that count back to 0,
so after a `run 0` (no build in the run) the next run's setup had the same count, and atoms moved
or re-sorted in between (displace_atoms, read_dump, the atom sort of the setup) were paired by
their old indices, until the run's first re-neighbouring: pairs lost, others paired at any
distance. Found through in.compress -var jitter: the coarse cell's fluid displaced by 1e-12 um
after the run 0 changed the setup's atom sort, 776 of its 5466 pairs were lost, forces came out
10x too large and the mean pressure was 4% off 20 steps later. (Without the displacement the
sort kept the order and the pairs were right.)

A block of 6^3 fluid particles (s = 1.2 um, spacing 1 um, random velocities; not periodic, so
without ghost atoms, whose count also keys the pair list and would hide the fault), three ways,
each compared with a fresh LAMMPS started from a data file of the same atoms (write_data, which
keeps positions, velocities, masses and densities to the last bit): the forces on every particle
(dump, %.17g) must agree to 1e-10 of the largest force. The data file orders the atoms by ID where
the running LAMMPS has them in another order, so the sums of pairs come in another order: round-off
of a few eps per pair force summed over ~60 pairs, far below 1e-10; a stale pair list is off by
whole pair forces (the code before the fix: 0.76, 1.14 and 3.8e-3 of the largest force in 1-3,
NaN forces in 4).
 1. run 0, then every fluid particle displaced at random by up to 0.3 um (neighbour sets change:
    the support is 2.4 um), then run 0 again;
 2. the same with a 100-step run before the displacement (the atoms move but stay within the
    skin: no re-neighbouring, the count ends where the setup left it);
 3. rerun of a dump of two frames (the lattice, then the displaced lattice): each frame's forces;
 4. the coarse cell with every style of the model (wall elements, cell/lj84, cell/virtual,
    cell/sph, fix cell/fluid), with the tether wall and with the membrane wall: run 0, every atom
    displaced by up to 0.2 um, run 0. The fresh start reads the data file with the same
    force field (cell-model.lmp); none of the styles may keep anything of the atoms' old places.
 5. the distance test of the pair search, with a branch or without (pair_style cell/sph search;
    by default the faster one, timed as the run goes, so a run may take either): the coarse cell
    inflating (in.inflate's osmosis) over 300 steps with re-neighbouring, positions, velocities and forces of each kind
    the same to the last bit; an unknown kind stops with a message.
"""
import numpy as np

import lmptest as T

RHO0, C, P0, MU, S, DX = 1.0, 264.6, 100.0, 1.0, 1.2, 1.0
N = 6
TOL = 1e-10

# not periodic: no ghost atoms, so their count, which also keys the pair list, cannot change
HEAD = T.SPH_BOX_HEAD.replace("boundary        p p p", "boundary        m m m")
assert HEAD != T.SPH_BOX_HEAD
BOX = HEAD + f"""
lattice         sc {DX} origin 0.5 0.5 0.5
region          box block 0 {N} 0 {N} 0 {N} units box
create_box      2 box
create_atoms    1 box
mass            * 1.0
""" + T.sph_box_fluid(RHO0, C, P0, MU, S, DX) + """
velocity        fluid create 1e6 4928459 dist gaussian
timestep        0.0005
"""
FORCES = "id fx fy fz"


def frames(path):
    """the frames of a dump file, each as rows id fx fy fz sorted by id"""
    out = []
    for frame in open(path).read().split("ITEM: TIMESTEP")[1:]:
        rows = frame.split("ITEM: ATOMS")[1].strip().splitlines()[1:]
        a = np.array([[float(x) for x in l.split()] for l in rows])
        out.append(a[np.argsort(a[:, 0])])
    return out


def forces(path):
    return frames(path)[0]


def dump(name):
    return f"write_dump all custom {name} {FORCES} modify sort id format float %.17g\n"


def fresh(d, data, out):
    """forces of a new LAMMPS started from a data file"""
    T.lmp(HEAD + f"""
read_data       {data} fix cell NULL cell
""" + T.sph_box_fluid(RHO0, C, P0, MU, S, DX, set_rho=False) + "run 0\n" + dump(out),
          cwd=d, log=f"log.{out}")
    return forces(f"{d}/{out}")


def compare(name, got, ref):
    same = got.shape == ref.shape and np.array_equal(got[:, 0], ref[:, 0])
    err = np.abs(got[:, 1:] - ref[:, 1:]).max() / np.abs(ref[:, 1:]).max() if same else np.inf
    print(f"{name}: largest force {np.abs(ref[:, 1:]).max():.4g} nN, largest difference from a "
          f"fresh start {err:.2e} of it")
    T.check(f"{name}: forces = a fresh start's (1e-10)", err < TOL, f"{err:.2e}")


MOVED = "displace_atoms  fluid random 0.3 0.3 0.3 8123 units box\n"


def test_run0_after_moved_atoms(rundir):
    d = rundir
    for name, before in (("run 0, atoms moved, run 0", "run 0\n"),
                         ("run 100, atoms moved, run 0", "run 100\n")):
        tag = "r0" if before == "run 0\n" else "r100"
        T.lmp(BOX + before + MOVED + "run 0\n" + dump(f"{tag}.dump") +
              f"write_data {tag}.data\n", cwd=d, log=f"log.{tag}")
        compare(name, forces(f"{d}/{tag}.dump"), fresh(d, f"{tag}.data", f"{tag}-fresh.dump"))


def test_rerun_frames(rundir):
    d = rundir
    # rerun: the frames' positions from a dump; velocities are those of the rerun's data
    T.lmp(BOX + "write_data rr0.data\n" + "write_dump all custom frames.dump id x y z modify sort id "
          "format float %.17g\n" + MOVED + "write_data rr1.data\nreset_timestep 1\n" +
          "write_dump all custom frames.dump id x y z modify sort id format float %.17g append yes\n",
          cwd=d, log="log.frames")
    T.lmp(BOX + "dump f all custom 1 rerun.dump " + FORCES + "\n"
          "dump_modify f sort id format float %.17g\n"
          "rerun frames.dump dump x y z\n", cwd=d, log="log.rerun")
    got = frames(f"{d}/rerun.dump")
    T.check("rerun wrote both frames", len(got) == 2, f"{len(got)}")
    for k, frame in enumerate(got):
        compare(f"rerun frame {k + 1}", frame, fresh(d, f"rr{k}.data", f"rr{k}-fresh.dump"))


def test_cell_between_runs(coarse_cell):
    d = coarse_cell
    # the whole cell: every style of the model between two runs
    for wall in ("tether", "membrane"):
        model = f"""
variable        dir index {T.INPUTS}
variable        wall index {wall}
""" + "".join(f"variable        {k} index {v}\n" for k, v in T.COARSE.items()) + f"""
include         {T.INPUTS}/cell-model.lmp
fix             integrate all nve
fix             osmosis fluid cell/fluid Pi 0 Lp 0
"""
        tag = f"cell-{wall}"
        T.lmp(T.cell_from_data("cell.data") + model + "velocity all create 1e8 5512 dist gaussian\n"
              "run 0\ndisplace_atoms all random 0.2 0.2 0.2 4411 units box\nrun 0\n" +
              dump(f"{tag}.dump") + f"write_data {tag}.data nocoeff\n", cwd=d, log=f"log.{tag}")
        T.lmp(T.cell_from_data(f"{tag}.data") + model + "run 0\n" + dump(f"{tag}-fresh.dump"),
              cwd=d, log=f"log.{tag}-fresh")
        compare(f"the coarse cell, {wall} wall: run 0, atoms moved, run 0",
                forces(f"{d}/{tag}.dump"), forces(f"{d}/{tag}-fresh.dump"))


def test_distance_search_kinds_agree(coarse_cell):
    d = coarse_cell
    # the two kinds of distance test: the same pairs in the same order
    src = open(T.INPUTS + "/cell-model.lmp").read()
    key = "pair_style      hybrid/overlay cell/sph "
    assert src.count(key) == 1, "cell-model.lmp no longer sets cell/sph first in its hybrid/overlay"
    runs = {}
    for kind in ("auto", "branch", "branchless", "fast"):
        with open(f"{d}/cell-model-{kind}.lmp", "w") as f:
            f.write(src.replace(key, f"{key}search {kind} "))
        model = f"variable        dir index {T.INPUTS}\n" + "".join(
            f"variable        {k} index {v}\n" for k, v in T.COARSE.items()) + f"""
include         cell-model-{kind}.lmp
fix             integrate all nve
fix             osmosis fluid cell/fluid Pi -364 Lp 100
timestep        0.001
run             300
write_dump      all custom search-{kind}.dump id x y z vx vy vz fx fy fz modify sort id &
                format float %.17g
"""
        rc, log = T.lmp(T.cell_from_data("cell.data") + model, cwd=d, log=f"log.search-{kind}",
                        check=kind != "fast")
        if kind == "fast":
            T.check("pair_style cell/sph search fast stops with its message", rc != 0 and
                    "pair_style cell/sph search: expected auto, branch or branchless, got 'fast'"
                    in log)
            continue
        builds = int(log.split("Neighbor list builds =")[1].split()[0])
        T.check(f"search {kind}: the 300 steps re-neighboured", builds > 0, f"{builds} builds")
        runs[kind] = frames(f"{d}/search-{kind}.dump")[0]
    for kind in ("branch", "branchless"):
        T.check(f"pair_style cell/sph search {kind} = search auto, every bit (x, v, f after 300 "
                "steps)", np.array_equal(runs[kind], runs["auto"]))
