# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 3, check 6, at the paper's resolution (level 4: 2562 wall nodes, 3500 fluid particles; about
2 minutes on one core): quasistatic compression of the inflated stiff cell between plates to 20%
strain (lammps-inputs/in.compress), at two plate speeds, 0.5 and 0.25 m/s. Both are slow against
the cell's relaxation (about 1 us; 20% strain takes 24 and 48 us), so the force-strain curve must
not depend on the rate.

The wall meets the plates ring of nodes by ring of nodes, which puts steps into the curve; forces
are therefore compared as means over 4%-wide strain windows centred at 6, 10, 14 and 18%.
Asserted:
 * the two rates agree within 2% in every window (the issue's criterion);
 * the windowed force rises monotonically with strain;
 * both plates carry the same load (5%) once the cell's own acceleration is taken out: after the
   first contact the cell rattles between the plates, and the bottom plate's force less the top
   one's is the rate of change of its z momentum (in.compress records it), which over a window is
   the momentum's change over the window's time. At 0.5 m/s the raw difference is about 6% in
   the first window (the cell, at rest, brought to half the plate speed: m v / 2 over the window's
   4.8 us is about 7 uN), printed beside the corrected one;
 * the cell reaches 20% strain with positive pressure, no fluid leaks, and the main job's CSV
   tables (tools/plot_main.py) hold these outputs.

Why level 4 and not the coarse cell (docs/studies/performance.md, "The compression test's rate check and
round-off"): at level 3 one run's windowed force moves by 2-7% with the cell's microstate, and
over six microstates the two rates differ by 3.3% +- 1.0% at 14% strain: the coarse cell does not
meet 2% on average, and which code passed was round-off's choice (2 of 6 microstates did; the
kernel's arithmetic rearranged read +5.3%). At level 4 one run moves by 0.13-0.6%, and over six
microstates the rates differ by +1.40% +- 0.06% (largest 1.55%), +0.91%, +0.38% and +0.88%
(largest 1.57%) in the four windows: the criterion holds in every microstate and the scatter
resolves it. The cell's inflation starts from its fluid displaced by up to 1e-9 um (in.inflate
-var jitter, seed 1): the generator's lattice is symmetric, and inflated as it is it ends in an
atypical microstate that round-off picks (at level 4 the one member at +1.93% in the first
window; in test_respa the coarse cell's unjittered state holds its pressure 2.5% above the
jittered ones').
"""
import numpy as np

import lmptest as T

WINDOWS = (0.06, 0.10, 0.14, 0.18)
HALF = 0.02     # half width of the strain windows


def test_quasistatic_compression_paper(rundir):
    d = rundir
    L4 = T.params.LEVELS[4]     # the paper's resolution: cell-model.lmp's own lengths
    T.cellgen("cell", "-o", "cell.data", "--level", 4, "--nfluid", L4["nfluid"], "--inset", L4["r0"],
              cwd=d)
    T.lmp(T.INPUTS + "/in.inflate", cwd=d, log="log.inflate", variables=dict(
        dir=T.INPUTS, data="cell.data", nsteps=20000, every=1000, out="inflate.dat",
        restart_out="inflated.restart", jitter=1))
    curves = {}
    for v in (0.5, 0.25):
        out = f"compress-{v}.dat"
        T.lmp(T.INPUTS + "/in.compress", cwd=d, log=f"log.compress-{v}", variables=dict(
            dir=T.INPUTS, restart="inflated.restart", vplate=v, every=100, out=out))
        a = T.load(f"{d}/{out}")    # step t eps Ftop Fbot Feq P broken leak V Vf pz
        t, eps, Ftop, Fbot, P, leak, pz = a[:, 1], a[:, 2], a[:, 3], a[:, 4], a[:, 6], a[:, 8], a[:, 11]
        F = 0.5 * (Ftop + Fbot)
        win = np.array([F[abs(eps - e) < HALF].mean() for e in WINDOWS])
        curves[v] = win
        print(f"v = {v} m/s: windowed plate force (uN) " + " ".join(f"{x * 1e-3:8.2f}" for x in win)
              + f"; final strain {eps[-1]:.3f}, final pressure {P[-1]:.1f} kPa")
        T.check(f"v={v}: force rises with strain", np.all(np.diff(win) > 0))
        raw, net = [], []
        for e in WINDOWS:
            k = np.flatnonzero(abs(eps - e) < HALF)
            # over the window: mean of bottom - top, and the momentum's change over its time
            dpdt = (pz[k[-1]] - pz[k[0]]) / (t[k[-1]] - t[k[0]])
            diff = (Fbot[k] - Ftop[k]).mean()
            raw.append(diff / F[k].mean())
            net.append((diff - dpdt) / F[k].mean())
        print(f"v = {v} m/s: (bottom - top) / load per window " + " ".join(f"{x:+.2%}" for x in raw)
              + "; less the cell's d(p_z)/dt " + " ".join(f"{x:+.2%}" for x in net))
        imb = np.max(np.abs(net))
        T.check(f"v={v}: both plates carry the same load, the cell's acceleration taken out (5%)",
                imb < 0.05, f"max {imb:.2%}")
        T.check(f"v={v}: reaches 20% strain (last output within 0.5%) with positive pressure",
                eps[-1] > 0.195 and P.min() > 0)
        T.check(f"v={v}: no fluid outside the wall", np.all(leak == 0))
    # the main job's plotting step (tools/plot_main.py) on these outputs: CSV columns as labelled
    import shutil
    import subprocess
    import sys
    shutil.copy(f"{d}/compress-0.5.dat", f"{d}/compress.dat")
    subprocess.run([sys.executable, T.ROOT + "/tools/plot_main.py", d], check=True)
    inf = np.genfromtxt(f"{d}/inflation.csv", delimiter=",", names=True)
    fs = np.genfromtxt(f"{d}/force-strain.csv", delimiter=",", names=True)
    T.check("main-job CSV: final mean pressure is the turgor (1%)",
            abs(inf["mean_pressure_kPa"][-1] / 364.0 - 1) < 0.01, f"{inf['mean_pressure_kPa'][-1]:.2f}")
    T.check("main-job CSV: strain runs from 0 to 20%, forces in uN",
            fs["strain"][0] >= 0 and fs["strain"][-1] > 0.195 and
            abs(fs["F_top_uN"][-1] * 1e3 / T.load(f"{d}/compress-0.5.dat")[-1, 3] - 1) < 1e-9)

    diff = curves[0.5] / curves[0.25] - 1
    print("rate difference per window: " + " ".join(f"{x:+.2%}" for x in diff))
    T.check("two quasistatic rates give the same curve within 2%", np.all(abs(diff) < 0.02),
            f"max {np.max(abs(diff)):.2%}")
