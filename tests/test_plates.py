# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 2, check 5: plates on an empty wall (lammps-inputs/in.plates, fix cell/plates).

A wall with no fluid is approached by the top plate at 1 m/s while the bottom plate stays.
Checked every step:
 * before the plate reaches the wall (t < gap / v) both plate forces are exactly zero;
 * each plate force equals k_p times the summed overlaps delta_i of the wall nodes with it,
   computed independently from the positions (1e-9 relative: both are sums of the same terms);
 * momentum balance: the wall's total momentum changes by the plate impulses,
   P(n+1) - P(n) = dt/2 [F(n) + F(n+1)] with velocity Verlet, since all internal forces (tethers,
   8-4 repulsion) cancel in pairs (round-off tolerance relative to the largest impulse).
"""
import numpy as np

import lmptest as T

KP, GAP, V, DT = 1.0e6, 0.5, 1.0, 0.001


def test_plate_force_and_impulse(rundir):
    d = rundir
    T.cellgen("cell", "-o", "wall.data", "--level", 3, "--nfluid", 0, cwd=d)
    extra = f"""
variable        dir index {T.INPUTS}
include         {T.INPUTS}/in.plates
variable        dtop atom (z>v_ztop)*(z-v_ztop)
variable        dbot atom (z<v_zb)*(v_zb-z)
compute         stop wall reduce sum v_dtop
compute         sbot wall reduce sum v_dbot
variable        KPtop equal ${{kp}}*c_stop
variable        KPbot equal ${{kp}}*c_sbot
variable        pz atom mass*vz
compute         pz all reduce sum v_pz
fix             check all ave/time 1 1 1 v_t v_Ftop v_Fbot v_KPtop v_KPbot c_pz file check.dat format " %.17g"
run             2500
"""
    T.lmp(extra, cwd=d, variables=dict(data="wall.data", nsteps=0, kp=KP, gap=GAP, vplate=V, dt=DT,
                                       every=100))
    t, Ftop, Fbot, KPtop, KPbot, P = T.load(f"{d}/check.dat")[:, 1:7].T
    before = t < GAP / V - 2 * DT
    T.check("zero plate force before contact", np.all(Ftop[before] == 0) and np.all(Fbot[before] == 0),
            f"{before.sum()} steps")
    T.check("both plates touch the wall during the run", Ftop.max() > 0 and Fbot.max() > 0,
            f"max {Ftop.max():.4g} and {Fbot.max():.4g} nN")
    scale = max(Ftop.max(), Fbot.max())
    e1 = np.max(abs(Ftop - KPtop)) / scale
    e2 = np.max(abs(Fbot - KPbot)) / scale
    T.check("top plate force = sum k_p delta", e1 < 1e-9, f"max rel err {e1:.1e}")
    T.check("bottom plate force = sum k_p delta", e2 < 1e-9, f"max rel err {e2:.1e}")
    Fatoms = Fbot - Ftop
    dP = np.diff(P)
    impulse = 0.5 * DT * (Fatoms[1:] + Fatoms[:-1])
    err = np.max(abs(dP - impulse)) / np.max(abs(impulse))
    total = abs(P[-1] - P[0] - impulse.sum()) / np.abs(impulse).sum()
    print(f"momentum: max |dP - impulse| / max impulse = {err:.2e}; over the run {total:.2e}; "
          f"final P_z = {P[-1]:.6g} pg um/us")
    T.check("momentum changes by the plate impulse every step", err < 1e-8)
