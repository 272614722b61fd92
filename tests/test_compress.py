# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 3, check 6 (coarse, as CI runs it): quasistatic compression of the inflated stiff cell
between plates to 20% strain (lammps-inputs/in.compress), at two plate speeds, 0.5 and 0.25 m/s.
Both are slow against the cell's relaxation (about 1 us; 20% strain takes 24 and 48 us), so the
force-strain curve must not depend on the rate.

The coarse wall meets the plates ring of nodes by ring of nodes, which puts steps of 2-3% strain
into the curve; forces are therefore compared as means over 4%-wide strain windows centred at
6, 10, 14 and 18% (each window spans at least one step). Asserted:
 * the two rates agree within 2% in every window (the issue's criterion);
 * the curve is smooth in the sense that matters: the windowed force rises monotonically with
   strain, and both plates carry the same load (force balance of a quasistatic cell, 5%);
 * no fluid leaks and the mean pressure stays positive.

Margin of the rate check (docs/performance.md, "The compression test's rate check and round-off"):
at this resolution one run's windowed force moves by 2-7% with the cell's microstate, which
round-off decides (20 us of a chaotic fluid). Over six microstates of this same cell
(tools/bench/rate-ensemble.sh) the two rates differ by 3.3% +- 1.0% at 14% strain and this check
passes for 2 of the 6, this cell's among them. A change of round-off alone (compiler, flags, the
order of a sum) can therefore fail it without any change of physics; measure with that script
before reading a failure as one. (The kernel's arithmetic rearranged, another order of roundings
and nothing else, reads +0.48 +0.05 +5.34 -0.10%, docs/performance.md.) At the paper's resolution one run moves by only 0.13-0.6%, but
the speeds themselves differ by up to 1.9% (0.5 against 0.25 m/s, at 6% strain) and 3.1% (0.25
against 0.125 m/s, at 14%) over a few microstates (same document): a 2% criterion is marginal
there as well.
"""
import numpy as np

import lmptest as T

COARSE = dict(T.COARSE)
WINDOWS = (0.06, 0.10, 0.14, 0.18)


def main():
    d = T.workdir("compress")
    T.inflate_coarse(d, nsteps=20000, every=5000)
    curves = {}
    for v in (0.5, 0.25):
        out = f"compress-{v}.dat"
        T.lmp(T.INPUTS + "/in.compress", cwd=d, log=f"log.compress-{v}", variables=dict(
            COARSE, dir=T.INPUTS, restart="inflated.restart", vplate=v, every=100, out=out))
        a = T.load(f"{d}/{out}")    # step t eps Ftop Fbot Feq P
        eps, Ftop, Fbot, P = a[:, 2], a[:, 3], a[:, 4], a[:, 6]
        F = 0.5 * (Ftop + Fbot)
        win = np.array([F[abs(eps - e) < 0.02].mean() for e in WINDOWS])
        top = np.array([Ftop[abs(eps - e) < 0.02].mean() for e in WINDOWS])
        bot = np.array([Fbot[abs(eps - e) < 0.02].mean() for e in WINDOWS])
        curves[v] = win
        print(f"v = {v} m/s: windowed plate force (uN) " + " ".join(f"{x * 1e-3:8.2f}" for x in win)
              + f"; final strain {eps[-1]:.3f}, final pressure {P[-1]:.1f} kPa")
        T.check(f"v={v}: force rises with strain", np.all(np.diff(win) > 0))
        imb = np.max(abs(top / bot - 1))
        T.check(f"v={v}: both plates carry the same load (5%)", imb < 0.05, f"max {imb:.1%}")
        T.check(f"v={v}: reaches 20% strain (last output within 0.5%) with positive pressure",
                eps[-1] > 0.195 and P.min() > 0)
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
    T.finish()


if __name__ == "__main__":
    main()
