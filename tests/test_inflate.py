# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 3, check 5 (coarse, as CI runs it): inflation of a cell by osmosis (lammps-inputs/in.inflate).

Coarse cell: 642 wall nodes and ~460 fluid particles, lengths of the model (s, r0, reach) scaled by
the doubled wall spacing (tools/main-job.sh does the same). The paper's resolution (2562 + 3500)
is test_inflate_paper.py, where Young-Laplace is asserted.

Asserted (each justified below):
 * the mean fluid pressure reaches -Pi within 1% (osmosis stops exactly when P = -Pi; the residual
   is the acoustic sloshing, averaged over the last outputs);
 * no fluid particle ever leaves its wall (winding number of the wall mesh, every output);
 * the fluid mass changes exactly by the integrated osmotic flux (both are sums of the same dt dm
   terms: round-off, 1e-9 relative);
 * the same under run_style respa, the wall on an inner level of half the SPH time step;
 * the equatorial force (Eq. 23) is the wall's tension: F_eq = 2 pi R T with T = G t0 (1 - lam^-6)
   at the mean stretch, within 5% (printed with its error; the equator's tethers are not the mean
   tether of the geodesic mesh).
Printed, not asserted: F_eq / (P pi R^2) at P = 100, 200, 400 kPa and the stretch against
Young-Laplace. At this resolution the wall feels 6-13% less than the mean fluid pressure: SPH
truncates the kernel at the wall, which underestimates the free surface's traction by an amount
~ s / R (here s = 6.4 um), and the ratio grows with P as the 8-4 contacts close in. At the paper's
resolution the ratio is within 1.5% of one (test_inflate_paper.py).
"""
import math

import numpy as np

import lmptest as T

G, T0 = T.STIFF["G"], T.STIFF["t0"]
COARSE = dict(T.COARSE)


def inflate(d, name, Pi, steps, G=G, t0=T0, Lp=100.0, dt=0.001, respa=False):
    out = f"{name}.dat"
    # run_style respa: tethers and triangles on the inner level (dt), the SPH and contacts on the
    # outer one (2 dt), where fix cell/fluid advances density and mass
    script = T.INPUTS + "/in.inflate" if not respa else (
        f"include {T.INPUTS}/in.inflate\nrun_style respa 2 2 bond 1 angle 1 pair 2\n"
        f"timestep {2 * dt}\nrun {steps // 2}\n")
    T.lmp(script, cwd=d, log=f"log.{name}", variables=dict(
        COARSE, dir=T.INPUTS, data="cell.data", Pi=Pi, G=G, t0=t0, Lp=Lp, dt=dt,
        nsteps=0 if respa else steps, every=steps // 20 if not respa else steps // 40, out=out,
        restart_out=f"{name}.restart"))
    # step t V A P M Nf lam lammax Feq leak dM
    return T.load(f"{d}/{out}")


def summary(a, Gw, t0, R0=30.0):
    last = a[-4:]
    P, lam, Feq = last[:, 4].mean(), last[:, 7].mean(), last[:, 9].mean()
    R = R0 * lam
    T_wall = Gw * t0 * (1 - lam ** -6)
    lam_yl = (1 - P * R / 2 / (Gw * t0)) ** (-1 / 6)
    return P, lam, Feq, R, T_wall, lam_yl


def test_stiff_inflation(coarse_cell):
    d = coarse_cell
    a = inflate(d, "stiff", -364.0, 20000)
    P, lam, Feq, R, Tw, lam_yl = summary(a, G, T0)
    print(f"stiff: P {P:.2f} kPa (target 364), mean stretch {lam:.5f} (Young-Laplace {lam_yl:.5f}), "
          f"F_eq {Feq:.4g} nN, P pi R^2 {P * math.pi * R * R:.4g} nN, ratio {Feq / (P * math.pi * R * R):.3f}")
    T.check("stiff: mean pressure reaches -Pi within 1%", abs(P / 364.0 - 1) < 0.01, f"{P / 364 - 1:+.2%}")
    T.check("stiff: no fluid outside its wall at any output", np.all(a[:, 10] == 0), f"max {a[:, 10].max():g}")
    dm_err = np.max(np.abs(a[:, 5] - a[0, 5] - a[:, 11])) / a[-1, 11]
    T.check("stiff: fluid mass changes by the integrated osmotic flux", dm_err < 1e-9,
            f"gained {a[-1, 11]:.6g} pg, mismatch {dm_err:.1e}")
    e = Feq / (2 * math.pi * R * Tw) - 1
    T.check("stiff: equatorial force = 2 pi R T(lam) of the wall (5%)", abs(e) < 0.05, f"{e:+.2%}")


def test_respa_inflation(coarse_cell):
    d = coarse_cell
    a = inflate(d, "respa", -364.0, 20000, respa=True)
    P = a[-4:, 4].mean()
    print(f"respa (bonds 1 ns, SPH 2 ns): P {P:.2f} kPa after {a[-1, 1]:g} us")
    T.check("respa: mean pressure reaches -Pi within 1%", abs(P / 364.0 - 1) < 0.01, f"{P / 364 - 1:+.2%}")
    dm_err = np.max(np.abs(a[:, 5] - a[0, 5] - a[:, 11])) / a[-1, 11]
    T.check("respa: mass change = integrated osmotic flux", dm_err < 1e-9, f"{dm_err:.1e}")
    T.check("respa: no leaks", np.all(a[:, 10] == 0))


def test_inflation_at_other_pressures(coarse_cell):
    """The inflations to 100, 200 and 400 kPa run (lmp fails the test otherwise); their
    F_eq / (P pi R^2) and stretch are printed, not asserted (see above)."""
    d = coarse_cell
    print(f"{'P target':>9s} {'P':>8s} {'lam':>8s} {'lam YL':>8s} {'F_eq':>10s} {'P pi R^2':>10s} ratio")
    for Pt in (100.0, 200.0, 400.0):
        a = inflate(d, f"yl{int(Pt)}", -Pt, 20000)
        P, lam, Feq, R, Tw, lam_yl = summary(a, G, T0)
        ratio = Feq / (P * math.pi * R * R)
        print(f"{Pt:9.0f} {P:8.2f} {lam:8.5f} {lam_yl:8.5f} {Feq:10.4g} {P * math.pi * R * R:10.4g} {ratio:.3f}")
