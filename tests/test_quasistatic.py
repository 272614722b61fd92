# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 29, the short test of the quasi-static checks (tools/cellmech/quasistatic.py) on real
records of lammps-inputs/in.compress: the coarse stiff cell (642 wall nodes, 440 fluid particles,
inflated to its turgor of 364 kPa over the main job's 25 us) compressed

 * fast, at 2 m/s to 10% strain: flagged dynamic, on the plates' balance and on the kinetic
   energy. The cell, at rest, is struck by the top plate and swings between the plates: over
   5-7% strain the bottom plate carries a fraction of the top one's load;
 * slowly, at 0.1 m/s to 20% strain: quasi-static over the issue's single-cell range, 5-20%.
   Why it is: a 2% window takes the plate 12 us, while the cell's rigid swing between the plates
   lasts about 1 us (tests/test_compress.py) and the slowest wave in it, sound across the cell,
   0.2 us. The protoplasm is given 100 mPa s (-var mu 100) for both runs: at water's 1 mPa s the
   coarse fluid (440 particles) rearranges under load in bursts of motion that carry 3-10% of the
   plates' work at 0.1 and at 0.05 m/s alike, no quieter at the slower speed (measured for issue
   29; docs/Howto_plates.rst, "Is it quasi-static?"); at 100 mPa s such motion is damped within
   rho dx^2 / mu = 0.3 us (dx = 5.7 um, the fluid spacing). The viscous stress the plate's motion
   adds, mu v / R = 0.3 kPa, is a thousandth of the turgor, so the slow curve is the elastic one.

Asserted, with the check's own tolerances (issue 29's 5% for the balance; 1% for KE/W): the fast
run fails both the balance and the kinetic energy criterion; the slow run passes both in every
window of 5-20%; every window was judged (none skipped, the ranges lie past first contact); the
records carry the two new columns: the plate's work never decreases and is the integral of the
recorded top plate force over the plate's travel (1%). About 35 s on one core.

Measured (this machine, LAMMPS 4 Jul 2026): fast, imbalance +153% over 5-7% strain (the bottom
plate 30 uN against the top one's 225 uN), KE/W 40-46%; slow, imbalance 0.41% at most, KE/W
0.19% at most.
"""
import numpy as np
import pytest

import lmptest as T
from cellmech import quasistatic as Q
from cellmech.tissue.tissuedata import integral, load

MU = 100.0      # mPa s, both runs (docstring)
RUNS = {        # name: (plate speed m/s, final strain, judged strain range)
    "fast": (2.0, 0.10, (0.05, 0.10)),
    "slow": (0.1, 0.20, (0.05, 0.20)),
}
# steps between records: the fast run's 0.02 us resolve the cell's ringing (sound across it, 0.2 us)
# with 10 records a period, so that the trapezoid of test_work_recorded sees it (at 0.1 us it read
# 0.14% and 1.42% in two microstates); at 2 m/s a 2% window (1.2 um) then holds 30 records
EVERY = {"fast": 20, "slow": 100}


def compress(d, name):
    v, strain, _ = RUNS[name]
    T.lmp(T.INPUTS + "/in.compress", cwd=d, log=f"log.{name}", variables=dict(
        T.COARSE, dir=T.INPUTS, restart="inflated.restart", vplate=v, strain=strain, mu=MU,
        every=EVERY[name], out=f"{name}.dat"))
    return load(f"{d}/{name}.dat", Q.CELL_COMPRESS)


@pytest.fixture(scope="module")
def compressed(rundir):
    """The coarse cell inflated, then compressed fast and slow: each run's record, its windows
    (balance, energy) and the verdict of the quasi-static checks."""
    d = rundir
    T.inflate_coarse(d, nsteps=25000, every=1000)
    out = {}
    for name, (v, strain, (lo, hi)) in RUNS.items():
        rec = compress(d, name)
        bal, en, _, ver = Q.check(rec, lo, hi)
        print(Q.report(bal, en, None, ver, f"{name}: {v} m/s to {strain:.0%} strain, mu {MU:g} mPa s"))
        print()
        out[name] = rec, bal, en, ver
    return out


@pytest.mark.parametrize("name", RUNS)
def test_work_recorded(compressed, name):
    """W never decreases (F_top >= 0, the plate moves one way) and is the integral of F_top over
    the plate's travel v (t - t0). fix cell/plates sums every step; the trapezoid here has only the
    records, and what it misses of the ringing between them depends on how densely they sample it:
    at 2 m/s, with a record every 0.1 us, 0.14% in one microstate and 1.42% in another (the
    inflation's neighbour skin 0.5 and 1.0 um), with one every 0.02 us (EVERY) 0.21% in the second.
    1% allows that several times over and still catches a sum over the wrong steps or with the
    wrong step, which is off by a factor."""
    v = RUNS[name][0]
    rec = compressed[name][0]
    W = rec[Q.WORK]
    trap = integral(rec["F_top_nN"], v * rec["time_us"])
    T.check(f"{name}: the plate's work never decreases", np.all(np.diff(W) >= -1e-9 * W[-1]))
    T.check(f"{name}: the plate's work is the integral of F_top over its travel (1%)",
            abs(W[-1] / trap - 1) < 0.01,
            f"recorded {W[-1]:.4g}, from the records {trap:.4g} nN um ({W[-1] / trap - 1:+.2%})")


@pytest.mark.parametrize("name", RUNS)
def test_every_window_judged(compressed, name):
    _, bal, en, _ = compressed[name]
    T.check(f"{name}: every window judged (none before contact, none short of records)",
            all(r.imbalance is not None for r in bal) and all(r.ratio is not None for r in en),
            f"{len(bal)} windows")


def test_fast_compression_flagged_dynamic(compressed):
    fast = compressed["fast"][3]
    T.check("fast: flagged dynamic on the balance and on the kinetic energy",
            not fast.quasistatic and fast.failed == ["balance", "ke_over_work"],
            f"imbalance {fast.numbers['balance']:.1%}, KE/W {fast.numbers['ke_over_work']:.2%}")


def test_slow_compression_quasistatic(compressed):
    slow = compressed["slow"][3]
    T.check("slow: quasi-static (balance within 5%, KE/W below 1% in every window)", slow.quasistatic,
            f"imbalance {slow.numbers['balance']:.2%}, KE/W {slow.numbers['ke_over_work']:.2%}"
            + "".join(f"; {r}" for r in slow.reasons))
