"""Every example input in lammps-inputs/ runs, in a short form, on 1 rank and on 2 ranks.

Each entry names the data the example needs (made with tools/cellgen.py) and the variables that
shorten it. A new example without an entry here fails this test, so none is left untested.
"""
import glob
import os
import re

import lmptest as T

DATA = {
    "wall3.data": ("cell", "--level", 3, "--nfluid", 0),
    "sheet.data": ("sheet", "--nx", 10, "--ny", 10),
}
SHORT = {
    "in.breathing": ("wall3.data", dict(nsteps=200)),
    "in.plates": ("wall3.data", dict(nsteps=300, gap=0.1)),
    "in.sheet": ("sheet.data", dict(lam="1.05")),
}


def main():
    d = T.workdir("examples")
    for name, args in DATA.items():
        T.cellgen(*args[:1], "-o", name, *args[1:], cwd=d)
    examples = sorted(os.path.basename(p) for p in glob.glob(T.INPUTS + "/in.*"))
    T.check("every example has a short form here", set(examples) == set(SHORT),
            f"missing {sorted(set(examples) - set(SHORT))}")
    for ex in examples:
        if ex not in SHORT:
            continue
        data, variables = SHORT[ex]
        for nprocs in (1, 2):
            rc, log = T.lmp(f"{T.INPUTS}/{ex}", cwd=d, nprocs=nprocs, check=False,
                            variables=dict(variables, data=data), log=f"log.{ex}.{nprocs}")
            perf = T.performance(log)
            ok = rc == 0 and "Total wall time" in log and "ERROR" not in log
            lost = re.search(r"Lost atoms", log)
            T.check(f"{ex} on {nprocs} rank(s)", ok and not lost, perf)
    T.finish()


if __name__ == "__main__":
    main()
