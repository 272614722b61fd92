# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 4, outputs: the per-atom virial of every cellmech force (SPH pressure and Morris viscosity,
8-4 contacts, virtual particles, tethers) sums to the global virial, so `compute stress/atom`
gives the true stress. A coarse fluid-filled cell with random velocities (viscous forces on) runs a
few steps; the sum over atoms of stress/atom must equal -P V from `compute pressure`, for the pair
and the bond parts separately, on 1 and 2 ranks. Both sides are sums of the same pair terms in
another order: round-off (1e-10 of the largest component) is the bound.
"""
import re

import lmptest as T

COARSE = dict(T.COARSE)
INPUT = """
include         {inputs}/in.inflate
velocity        all create 1.0e7 77 dist gaussian mom yes rot yes
compute         sp all stress/atom NULL pair
compute         sb all stress/atom NULL bond
compute         rp all reduce sum c_sp[1] c_sp[2] c_sp[3] c_sp[4] c_sp[5] c_sp[6]
compute         rb all reduce sum c_sb[1] c_sb[2] c_sb[3] c_sb[4] c_sb[5] c_sb[6]
compute         pp all pressure NULL pair
compute         pb all pressure NULL bond
variable        V equal vol
# thermo invokes the computes on the last step, so that the virial is tallied per atom there
thermo_style    custom step c_rp[*] c_rb[*] c_pp[*] c_pb[*]
thermo          50
run             50
{prints}
"""


def test_per_atom_virial_sums_to_global(rundir):
    d = rundir
    T.coarse_cell(d)
    prints = "\n".join(
        f'print "{part}{k} $(c_r{part[0]}[{k}]:%.15g) $(-c_p{part[0]}[{k}]*v_V:%.15g)"'
        for part in ("pair", "bond") for k in range(1, 7))
    for n in (1, 2):
        _, log = T.lmp(INPUT.format(inputs=T.INPUTS, prints=prints), cwd=d, nprocs=n,
                       variables=dict(COARSE, dir=T.INPUTS, data="cell.data", nsteps=0, mu=10.0,
                                      Lp=1.0, P0=50.0), log=f"log.virial{n}")
        for part in ("pair", "bond"):
            rows = [tuple(map(float, m)) for m in
                    re.findall(rf"^{part}\d (\S+) (\S+)$", log, flags=re.M)]
            scale = max(abs(b) for _, b in rows)
            err = max(abs(a - b) for a, b in rows) / scale
            print(f"{n} rank(s), {part}: sum of per-atom virial vs global, xx yy zz xy xz yz: "
                  + ", ".join(f"{a:.6g}/{b:.6g}" for a, b in rows) + f"; max rel diff {err:.1e}")
            T.check(f"{n} rank(s): per-atom {part} virial sums to the global one", err < 1e-10,
                    f"{err:.1e}")
