# SPDX-License-Identifier: GPL-2.0-or-later
"""Protoplasm shear stress (compute cell/shear/atom, paper Eqs. 24-26) in steady Poiseuille flow,
where it is known exactly: tau_xy(y) = mu du/dy = rho0 G (L/2 - y), linear across the channel,
zero on the centre line, rho0 G L/2 at the walls, whatever the viscosity.

The channel of tests/test_poiseuille.py (tests/channel.py; mirror walls, which put the no-slip
planes half a spacing out): 20 fluid layers, dx = 1 um, s = 1.2 um, mu = 1000 mPa s, G = 2 um/us^2, 0.6 us to steady state;
tau_xy averaged per layer over the last 0.2 us.
Tolerance 1% (relative L2 over the layers): the SPH gradient of Eq. 25 on this lattice carries the
factor K = -sum_j V_j dy_j^2 (dW/dr)/r_j = 0.98 (test_poiseuille.py), but so does the Morris
viscous force, so in steady state the flow settles at the gradient that makes K mu du/dy balance
the body force and K cancels; what remains is the transient (2e-4), compressibility (Ma^2 = 1e-4)
and the layers next to the mirror walls.
Also asserted: tau_xz and tau_yz vanish (below 2% of the wall stress) and |tau| = |tau_xy|.
"""
import numpy as np

import lmptest as T
from channel import DX, G, L, NSTEPS, RHO0, channel_input

SHEAR = f"""
compute         shear fluid cell/shear/atom
compute         chs fluid chunk/atom bin/1d y 0.0 {DX} units box
fix             tauprof fluid ave/chunk 100 20 {NSTEPS} chs c_shear[1] c_shear[2] c_shear[3] &
                c_shear[4] file shear.dat format " %.12g"
"""


def test_shear_stress_in_poiseuille_flow(rundir):
    d = rundir
    T.lmp(channel_input("mirror", SHEAR), cwd=d, nprocs=2)
    lines = [l for l in open(f"{d}/shear.dat") if not l.startswith("#")]
    n = int(lines[0].split()[1])
    tab = np.array([list(map(float, l.split())) for l in lines[-n:]])   # the last block
    tab = tab[(tab[:, 1] > 0) & (tab[:, 1] < L)]    # the fluid layers (the wall bins are empty)
    y, tau, txy, txz, tyz = tab[:, 1], tab[:, 3], tab[:, 4], tab[:, 5], tab[:, 6]
    exact = RHO0 * G * (L / 2 - y)
    wall = RHO0 * G * L / 2
    err = np.sqrt(np.mean((txy - exact) ** 2)) / np.sqrt(np.mean(exact ** 2))
    print(f"{'y':>6} {'tau_xy':>9} {'exact':>9}")
    for yy, t, e in zip(y, txy, exact):
        print(f"{yy:6.2f} {t:9.4f} {e:9.4f}")
    print(f"relative L2 {err:.4f}; max |tau_xz|, |tau_yz| {max(abs(txz).max(), abs(tyz).max()):.2e} "
          f"kPa; wall stress rho0 G L/2 = {wall:g} kPa")
    T.check("tau_xy = rho0 G (L/2 - y) within 1%", err < 0.01, f"{err:.2%}")
    T.check("tau_xz and tau_yz vanish", max(abs(txz).max(), abs(tyz).max()) < 0.02 * wall)
    T.check("|tau| = |tau_xy| (the only shear component)",
            np.allclose(tau, np.abs(txy), atol=0.02 * wall))
