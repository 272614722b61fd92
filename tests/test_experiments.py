# SPDX-License-Identifier: GPL-2.0-or-later
"""Short forms of the paper's experiments (issue 4; lammps-inputs/in.impact, in.relax, in.turgor,
in.failure) on the coarse cell (642 wall nodes, ~460 fluid particles), with the physics such a cell
still shows. The full set and its report: tools/experiments.sh.

Asserted:
 * turgor (Fig. 5): a cell brought to 300, 30 and 3 kPa and compressed carries, over the first 3%
   of strain after contact, the more force the higher its turgor (at small strain the load is
   carried by the pre-tension of the wall, P R / 2, which grows with P);
 * relaxation (Fig. 6): released from 10% strain, the stiff cell at 1 mPa s oscillates (at least
   two sign changes of the equatorial force about the centre it swings around, between excursions
   larger than 10% of the initial deviation, after smoothing over 2% of the record) and at
   1000 mPa s it does not (overdamped): the fluid's viscous damping of the cell's shape mode grows
   with mu (the paper: overdamped above about 0.5 Pa s); and at 1000 mPa s the force has come
   within 10% of the free cell's by the end (an overdamped cell returns to its free state);
 * impact at 5 m/s (Figs. 8-9): the mean shear stress in the impact zone at eps = 4% grows with
   viscosity roughly in proportion at low viscosity: tau(10 mPa s) / tau(1 mPa s) between 5 and 20
   (proportional: 10; the paper: 9.8; the velocity field is set by the plate while inertia
   dominates, so tau ~ mu, and the bound allows the coarse zone's sampling noise, +-50%);
   and the transmitted force lags the quasistatic one: the bottom plate reaches 20% of the
   quasistatic force at 8% strain later in strain under impact (the cell must first be set moving
   and the pressure wave must cross it);
 * failure (Fig. 11, lamf = 1.04): under quasistatic load the wall fails (broken tethers) before
   eps = 20%; no fluid is outside the wall before the first break and some is after; under impact
   at 1 mPa s the wall fails at a lower strain than under quasistatic load, on the side of the
   impacting plate (first broken nodes above the equator; the paper: near the plate).
"""

import numpy as np
import pytest

import lmptest as T

from cellmech.experiments import analyse as A

COARSE = dict(T.COARSE)


def run(inp, d, log, **v):
    T.lmp(f"{T.INPUTS}/{inp}", cwd=d, log=log, variables=dict(COARSE, dir=T.INPUTS, **v))


@pytest.fixture(scope="module")
def inflated(rundir):
    """The coarse cell (padded box) inflated (inflated.restart), from which every experiment starts."""
    d = rundir
    T.coarse_cell(d, "cell.data", "--pad", 40)
    run("in.inflate", d, "log.inflate", data="cell.data", nsteps=20000, every=5000, out="inflate.dat",
        restart_out="inflated.restart")
    return d


def test_turgor_ordering(inflated):
    d = inflated
    # ---- turgor ordering at small strain
    F3 = {}
    for P in (300, 30, 3):
        run("in.turgor", d, f"log.turgor-{P}", restart="inflated.restart", turgor=P,
            settled=f"turgor-{P}.restart", setout=f"settle-{P}.dat", vplate=0.5,
            strain=0.06, every=100, out=f"turgor-{P}.dat")
        a = T.load(f"{d}/turgor-{P}.dat")
        e, f = a[:, A.CMP["eps"]], 0.5 * (a[:, A.CMP["ftop"]] + a[:, A.CMP["fbot"]])
        # both plates touch once they have closed the two 0.2 um gaps (cell height ~ 2R = 60 um)
        e_c = 0.4 / 60.0
        F3[P] = A.window_mean(e, f, e_c + 0.03, 0.005)[0]
        s = T.load(f"{d}/settle-{P}.dat")
        print(f"turgor {P} kPa: settled mean pressure {s[-1, 2]:.2f} kPa; force at 3% after contact "
              f"{F3[P] / 1e3:.1f} uN")
    T.check("turgor: higher turgor carries more force at small strain (300 > 30 > 3 kPa)",
            F3[300] > F3[30] > F3[3], " ".join(f"{P}: {F3[P] / 1e3:.1f} uN" for P in (300, 30, 3)))


def test_relaxation(inflated):
    d = inflated
    # ---- relaxation: oscillation at 1 mPa s, overdamped at 1000 mPa s
    res = {}
    for mu in (1, 1000):
        run("in.relax", d, f"log.relax-{mu}", restart="inflated.restart", compressed="compressed.restart",
            strain=0.1, nhold=3000, mu=mu, trelax=4.0, every=10, out=f"relax-{mu}.dat")
        a = T.load(f"{d}/relax-{mu}.dat")
        load = T.load(f"{d}/compressed.restart.load.dat")
        f_inf = float(np.mean(load[:5, A.CMP["feq"]]))
        res[mu] = A.relaxation(a[:, A.REL["t"]], a[:, A.REL["feq"]], f_inf)
        r = res[mu]
        print(f"relaxation {mu} mPa s: initial deviation {r['d0'] / 1e3:.1f} uN, tau_e {r['tau_e']:.2f} us, "
              f"crossings {r['crossings']}, period {r['period']:.2f} us")
    T.check("relaxation: the stiff cell oscillates at 1 mPa s", res[1]["crossings"] >= 2,
            f"{res[1]['crossings']} sign changes")
    T.check("relaxation: the stiff cell is overdamped at 1000 mPa s", res[1000]["crossings"] < 2,
            f"{res[1000]['crossings']} sign changes")
    T.check("relaxation: at 1000 mPa s the cell returns to its free state", np.isfinite(res[1000]["tau_e"])
            and abs(res[1000]["centre"]) < 0.1 * res[1000]["d0"],
            f"tau_e {res[1000]['tau_e']:.2f} us, offset {res[1000]['centre'] / 1e3:.1f} uN")


def test_impact(inflated):
    d = inflated
    # ---- impact: shear stress ~ mu at low viscosity; transmitted force lags the quasistatic one
    tau = {}
    for mu in (1, 10):
        run("in.impact", d, f"log.impact-{mu}", restart="inflated.restart", mu=mu, strain=0.12, every=10,
            out=f"impact-{mu}.dat", snapshot=0)
        tau[mu] = A.impact_shear(T.load(f"{d}/impact-{mu}.dat"), 0.04)[0]
    ratio = tau[10] / tau[1]
    T.check("impact: tau(10 mPa s) / tau(1 mPa s) at eps = 4% between 5 and 20", 5 <= ratio <= 20,
            f"{tau[1] * 1e3:.0f} Pa, {tau[10] * 1e3:.0f} Pa, ratio {ratio:.1f}")
    run("in.compress", d, "log.qs", restart="inflated.restart", vplate=0.5, strain=0.1, every=100,
        out="qs.dat")
    q = T.load(f"{d}/qs.dat")
    a = T.load(f"{d}/impact-1.dat")
    i8 = np.argmin(np.abs(q[:, A.CMP["eps"]] - 0.08))
    level = 0.2 * q[i8, A.CMP["fbot"]]
    lag = A.lag(a, q, level)
    T.check("impact: the transmitted force lags the quasistatic one", lag > 0,
            f"reaches {level / 1e3:.0f} uN {100 * lag:+.2f}% strain later")


def test_failure(inflated):
    d = inflated
    # ---- failure
    run("in.failure", d, "log.failure-qs", restart="inflated.restart", strain=0.2, every=100,
        leakevery=500, bdump=0, imgevery=0, snapshot=0, out="failure-qs.dat")
    fq = A.failure(f"{d}/failure-qs.dat", "none", 0.001, COARSE["r0"])
    L = T.load(f"{d}/failure-qs.dat.leaks")     # step tt eps nbroken leak Nf
    before, after = L[L[:, 3] == 0], L[L[:, 3] > 0]
    T.check("failure: the wall breaks under quasistatic load before eps = 20%", np.isfinite(fq["eps_f"]),
            f"eps_f = {100 * fq['eps_f']:.1f}%")
    T.check("failure: no fluid outside the wall before the first break",
            len(before) > 0 and before[:, 4].max() == 0, f"{len(before)} samples")
    T.check("failure: fluid leaves after the break", len(after) > 0 and after[-1, 4] > 0,
            f"{int(after[-1, 4]) if len(after) else 'no'} particles outside at the end")
    run("in.failure", d, "log.failure-impact", restart="inflated.restart", vplate=5, mu=1, strain=0.12,
        every=10, leakevery=0, bdump=20, imgevery=0, snapshot=0, out="failure-impact.dat",
        bdumpfile="failure-impact.dump")
    fi = A.failure(f"{d}/failure-impact.dat", f"{d}/failure-impact.dump", 0.001, COARSE["r0"])
    T.check("failure: under impact (1 mPa s) the wall fails at a lower strain than quasistatically",
            np.isfinite(fi["eps_f"]) and fi["eps_f"] < fq["eps_f"],
            f"impact {100 * fi['eps_f']:.1f}%, quasistatic {100 * fq['eps_f']:.1f}%")
    T.check("failure: under impact the crack starts on the side of the impacting plate",
            fi.get("lat_first_mean", -90) > 0, f"mean latitude of the first broken nodes "
            f"{fi.get('lat_first_mean', float('nan')):.0f} deg")
