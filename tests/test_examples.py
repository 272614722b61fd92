# SPDX-License-Identifier: GPL-2.0-or-later
"""Every example input in lammps-inputs/ runs, in a short form, on 1 rank and on 2 ranks.

Each entry names the data the example needs (made with tools/cellgen.py) and the variables that
shorten it. A new example without an entry here fails this test, so none is left untested.
"""
import glob
import json
import os
import re

import lmptest as T

DATA = {
    "wall3.data": ("cell", "--level", 3, "--nfluid", 0),
    "cell3.data": ("cell", "--level", 3, "--nfluid", 440, "--inset", 3.2),
    "sheet.data": ("sheet", "--nx", 10, "--ny", 10),
    # two glued coarse cells stacked along z: the smallest tissue; cellgen writes pair.json beside
    "pair.data": ("tissue", "--lattice", "sc", "--n", 1, 1, 2, "--level", 3, "--nfluid", 440),
}
COARSE = dict(T.COARSE)
# in run order: in.compress and in.breathing-fluid continue from the restart in.inflate writes
SHORT = {
    "in.breathing": ("wall3.data", dict(nsteps=200)),
    "in.plates": ("wall3.data", dict(nsteps=300, gap=0.1)),
    "in.sheet": ("sheet.data", dict(lam="1.05")),
    "in.inflate": ("cell3.data", dict(COARSE, nsteps=2000, every=500, restart_out="short.restart")),
    "in.compress": ("cell3.data", dict(COARSE, restart="short.restart", strain=0.01, vtk=100)),
    "in.breathing-fluid": ("cell3.data", dict(COARSE, restart="short.restart", nsteps=200)),
    "in.impact": ("cell3.data", dict(COARSE, restart="short.restart", strain=0.02, dump=100)),
    "in.failure": ("cell3.data", dict(COARSE, restart="short.restart", vplate=5, strain=0.02, every=10,
                                      leakevery=100, bdump=50, imgevery=100)),
    # the first run compresses and writes relax-short.restart, the second starts from it
    "in.relax": ("cell3.data", dict(COARSE, restart="short.restart", compressed="relax-short.restart",
                                    strain=0.01, nhold=100, trelax=0.2)),
    "in.turgor": ("cell3.data", dict(COARSE, restart="short.restart", turgor=30, nsettle=200,
                                     settled="turgor-short.restart", strain=0.005)),
    # the tissue inputs continue from the pair in.tissue-inflate writes; special (room for the
    # lamella's special neighbours) is the generator's, filled in by the test
    "in.tissue-inflate": ("pair.data", dict(COARSE, nsteps=600, nsettle=200, every=200,
                                            restart_out="pair-short.restart")),
    "in.tissue-compress": ("pair.data", dict(COARSE, restart="pair-short.restart", vplate=4,
                                             strain=0.02, every=50, tabevery=100, leakevery=100,
                                             vtk=200, img=200)),
    "in.tissue-impact": ("pair.data", dict(COARSE, restart="pair-short.restart", vplate=10,
                                           strain=0.02, hold=0.2, tabevery=100, img=300)),
    "in.tissue-pair": ("pair.data", dict(COARSE, restart="pair-short.restart", vplate=4, press=0.02,
                                         vpull=4, pull=0.5, every=50)),
    "in.tissue-tension": ("pair.data", dict(COARSE, restart="pair-short.restart", vpull=4, strain=0.02,
                                            every=50, tabevery=100)),
    # water: one cell against two external potentials; the pair with cells of different Pi
    "in.water-potential": ("cell3.data", dict(COARSE, restart="short.restart", nlevels=1, nsteps=100,
                                              nave=50)),
    "in.water-pair": ("pair.data", dict(COARSE, restart="pair-short.restart", nsteps=200, every=50)),
    # the pair dried to 99% of its water: the stop (fix halt), the shape and VTK/fluid outputs
    "in.tissue-dry": ("pair.data", dict(COARSE, restart="pair-short.restart", target=0.99,
                                        nmax=400, every=50, vtk=100)),
}


def test_every_example_runs(rundir):
    d = rundir
    # in.relax caches its compressed state (in.turgor writes its settled one): a state left by an earlier
    # run of this test would let the 1-rank run skip the stage it must test
    for cached in ("relax-short.restart", "turgor-short.restart"):
        if os.path.exists(os.path.join(d, cached)):
            os.remove(os.path.join(d, cached))
    for name, args in DATA.items():
        T.cellgen(*args[:1], "-o", name, *args[1:], cwd=d)
    special = json.load(open(os.path.join(d, "pair.json")))["extra_special_per_atom"]
    examples = sorted(os.path.basename(p) for p in glob.glob(T.INPUTS + "/in.*"))
    T.check("every example has a short form here", set(examples) == set(SHORT),
            f"missing {sorted(set(examples) - set(SHORT))}")
    for ex in SHORT:
        data, variables = SHORT[ex]
        variables = dict(variables, dir=T.INPUTS)
        if data == "pair.data":
            variables["special"] = special
        for nprocs in (1, 2):
            rc, log = T.lmp(f"{T.INPUTS}/{ex}", cwd=d, nprocs=nprocs, check=False,
                            variables=dict(variables, data=data), log=f"log.{ex}.{nprocs}")
            perf = T.performance(log)
            ok = rc == 0 and "Total wall time" in log and "ERROR" not in log
            lost = re.search(r"Lost atoms", log)
            T.check(f"{ex} on {nprocs} rank(s)", ok and not lost, perf)
