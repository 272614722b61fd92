# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 3, check 2: pairwise forces are antisymmetric. An isolated cell (fluid, wall, virtual
particles, no plates, no osmosis) with random velocities and a pressurised fluid (P0 = 100 kPa)
conserves total linear momentum to round-off, and, with the fluid inviscid, angular momentum too:
every force of the model is then central (tethers, 8-4 contacts, SPH pressure) or, for the virtual
particles, the exact gradient of a central potential of the barycentre. The Morris viscosity acts
along v_ij, not r_ij; it conserves linear momentum but not angular momentum exactly, so with
viscosity the angular momentum drift is printed, not asserted.
Round-off bound: each step adds ~eps * sum|f| dt per component; over the run this stays below
1e-10 of sum |m v| (asserted).
"""
import numpy as np

import lmptest as T

COARSE = dict(T.COARSE)
EXTRA = """
velocity        all create 1.0e7 4242 dist gaussian mom yes rot yes
variable        px atom mass*vx
variable        py atom mass*vy
variable        pz atom mass*vz
variable        lx atom mass*(y*vz-z*vy)
variable        ly atom mass*(z*vx-x*vz)
variable        lz atom mass*(x*vy-y*vx)
variable        pabs atom mass*sqrt(vx*vx+vy*vy+vz*vz)
variable        labs atom mass*sqrt(x*x+y*y+z*z)*sqrt(vx*vx+vy*vy+vz*vz)
compute         mom all reduce sum v_px v_py v_pz v_lx v_ly v_lz v_pabs v_labs
fix             momrec all ave/time 10 1 10 c_mom[*] file momentum.dat format " %.17g"
run             2000
"""


def test_momentum_conserved(rundir):
    d = rundir
    T.coarse_cell(d)
    for mu in (0.0, 10.0):
        T.lmp(f"include {T.INPUTS}/in.inflate\n" + EXTRA, cwd=d, log=f"log.mu{mu}", variables=dict(
            COARSE, dir=T.INPUTS, data="cell.data", nsteps=0, Lp=0.0, Pi=0.0, P0=100.0, mu=mu))
        a = T.load(f"{d}/momentum.dat")[:, 1:]
        P, L = a[:, 0:3], a[:, 3:6]
        pscale, lscale = a[:, 6].max(), a[:, 7].max()
        dp = np.abs(P - P[0]).max() / pscale
        dl = np.abs(L - L[0]).max() / lscale
        print(f"mu = {mu}: linear momentum drift {dp:.2e}, angular momentum drift {dl:.2e} "
              f"(relative to sum |m v| = {pscale:.4g}, sum |m r x v| <= {lscale:.4g})")
        T.check(f"mu={mu}: linear momentum conserved to round-off", dp < 1e-10, f"{dp:.1e}")
        if mu == 0.0:
            T.check("inviscid: angular momentum conserved to round-off", dl < 1e-10, f"{dl:.1e}")
