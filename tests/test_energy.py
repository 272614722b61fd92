# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 5, case 7 (coarse): inviscid energy balance. With viscosity, tether damping, contact damping
and osmosis off, a cell whose fluid starts at P0 = 100 kPa pushes its wall out and oscillates;
kinetic + potential energy (tethers, 8-4 contacts, virtual particles and the fluid's internal
energy sum m e(rho), de/drho = P/rho^2, tallied by pair cell/sph) must be conserved.

Bound: velocity Verlet for the positions with the density leapfrogging the velocities is second
order and time-reversible; its energy error oscillates with amplitude ~ (omega dt)^2 times the
energy in the fastest modes, omega ~ c/s = 41 rad/us here, dt = 1 ns: 1.7e-3. Asserted: the
largest deviation from the initial total stays below 1e-3 of the largest kinetic energy, and the
secular drift (slope of a linear fit times the run time) below 2e-4 of it.
"""

import lmptest as T

from cellmech.validation.analysis import energy_balance  # shared with tools/validate.sh, case 7

COARSE = dict(T.COARSE)
EXTRA = """
variable        etot equal ke+pe
variable        kin equal ke
variable        tt equal time
fix             erec all ave/time 20 1 20 v_tt v_kin v_etot file energy.dat format " %.15g"
run             20000
"""


def test_inviscid_energy_conserved(rundir):
    d = rundir
    T.coarse_cell(d)
    T.lmp(f"include {T.INPUTS}/in.inflate\n" + EXTRA, cwd=d, variables=dict(
        COARSE, dir=T.INPUTS, data="cell.data", nsteps=0, Lp=0.0, Pi=0.0, P0=100.0, mu=0.0,
        gamma=0.0, gc=0.0))
    a = T.load(f"{d}/energy.dat")
    t, ke, e = a[:, 1], a[:, 2], a[:, 3]
    dev, drift = energy_balance(t, ke, e)
    print(f"{len(t)} samples over {t[-1]:g} us: max KE {ke.max():.6g}, total energy {e[0]:.6g} -> "
          f"{e[-1]:.6g}; max deviation {dev:.2e}, secular drift {drift:.2e} (of max KE)")
    T.check("inviscid: energy deviation below 1e-3 of the kinetic energy", dev < 1e-3, f"{dev:.1e}")
    T.check("inviscid: no secular energy drift (2e-4)", drift < 2e-4, f"{drift:.1e}")
