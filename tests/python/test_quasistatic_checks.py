# SPDX-License-Identifier: GPL-2.0-or-later
"""cellmech.quasistatic and cellmech.ladder on synthetic plate-compression records (issue 29): a
balanced slow run passes; plates out of balance, a ringing run and a half-speed curve that moved
are each flagged with their reason; windows before contact are skipped and said so; the record
columns the check names are those the inputs write."""
import os
import re

import numpy as np
import pytest

from cellmech import ladder
from cellmech import quasistatic as Q
from cellmech.params import ROOT
from cellmech.tissue import tissuedata

N = 2001        # records from 0 to 20% strain: 20 per 0.2% of strain, 200 per window
F20 = 2.0e5     # nN at 20% strain, the coarse cell's order (200 uN)


def record(top=1.0, bottom=1.0, ke_share=1e-4, ring=0.0, ring_period=0.03, scale=1.0, start=0.0):
    """A compression record ({column: array}): a load F = F20 (eps / 0.2)^1.5 (Hertz-like) from
    `start` strain on (zero before: the plates not yet touching), top and bottom plates scaled by
    `top`, `bottom`, each ringing out of phase with relative amplitude `ring` and period
    `ring_period` (strain); the plate's work the integral of F_top d(eps H) with H = 60 um; the
    kinetic energy ke_share of it; the whole curve scaled by `scale` (another speed's)."""
    eps = np.linspace(-0.01, 0.20, N)
    x = np.clip(eps - start, 0.0, None)
    F = scale * F20 * (x / 0.2) ** 1.5
    osc = ring * np.sin(2 * np.pi * eps / ring_period)
    ftop, fbot = top * F * (1 + osc), bottom * F * (1 - osc)
    work = np.concatenate([[0.0], np.cumsum(0.5 * (ftop[1:] + ftop[:-1]) * np.diff(eps) * 60.0)])
    return {"strain": eps, "F_top_nN": ftop, "F_bottom_nN": fbot, Q.KE: ke_share * work,
            Q.WORK: work, "broken_tethers": np.zeros(N)}


def test_windows_tile_the_range():
    w = Q.windows(0.05, 0.20)
    assert len(w) == 8 and w[0] == (0.05, 0.07) and w[-1] == (0.19, 0.20)
    # the last one takes the rest: between half and one and a half widths, never a sliver
    assert Q.windows(0.02, 0.079) == [(0.02, 0.04), (0.04, 0.06), (0.06, 0.079)]
    assert Q.windows(0.02, 0.068)[-1] == (0.04, 0.068)
    assert Q.windows(0.1, 0.1) == []


def test_balanced_slow_run_passes():
    bal, en, rate, v = Q.check(record(), 0.05, 0.20, half=record())
    print(Q.report(bal, en, rate, v))
    assert v.quasistatic and v.label == "quasi-static" and v.reasons == []
    assert v.numbers["balance"] < 1e-12 and v.numbers["rate"] < 1e-12
    assert v.numbers["ke_over_work"] == pytest.approx(1e-4)
    assert len(bal) == len(en) == len(rate) == 8


def test_imbalanced_plates_are_flagged():
    # the bottom plate carrying 10% less: (1 - 0.9) / 0.95 = 10.5%
    bal, en, _, v = Q.check(record(bottom=0.9), 0.05, 0.20)
    print(Q.report(bal, en, None, v))
    assert not v.quasistatic and v.label == "dynamic"
    assert v.numbers["balance"] == pytest.approx(0.1 / 0.95)
    assert len(v.reasons) == 1 and v.reasons[0].startswith("balance: the plates differ by 10.5%")
    assert "8 of 8 windows" in v.reasons[0]


def test_just_within_the_tolerance_passes():
    # 4% apart: (1 - 0.96) / 0.98 = 4.1% < 5%
    assert Q.check(record(bottom=0.96), 0.05, 0.20)[3].quasistatic


def test_ringing_run_is_flagged_on_balance_and_energy():
    # the block swinging between the plates, a period longer than a window (not averaged away),
    # with 3% of the work in motion
    bal, en, _, v = Q.check(record(ring=0.2, ring_period=0.05, ke_share=0.03), 0.05, 0.20)
    text = Q.report(bal, en, None, v)
    print(text)
    assert not v.quasistatic
    assert [r.split(":")[0] for r in v.reasons] == v.failed == ["balance", "ke_over_work"]
    assert v.numbers["ke_over_work"] == pytest.approx(0.03) and v.numbers["balance"] > 0.05
    assert "verdict: dynamic" in text and "kinetic energy is 3.00% of the plates' work" in text


def test_ringing_faster_than_a_window_averages_out():
    # ten periods per window: the window mean is the load (the reason for windows)
    assert Q.check(record(ring=0.2, ring_period=0.002), 0.05, 0.20)[3].quasistatic


def test_half_speed_curve_that_moved_is_flagged():
    bal, en, rate, v = Q.check(record(), 0.05, 0.20, half=record(scale=0.9))
    print(Q.report(bal, en, rate, v))
    assert not v.quasistatic
    assert v.numbers["rate"] == pytest.approx(0.1 / 0.9)
    assert len(v.reasons) == 1 and v.reasons[0].startswith("rate: halving the speed moves the curve by 11.1%")
    # 3% apart passes
    assert Q.check(record(), 0.05, 0.20, half=record(scale=0.97))[3].quasistatic


def test_windows_before_contact_are_skipped_and_said_so():
    # contact at 3% strain: the window from 0 to 2% has no load on either plate
    rec = record(start=0.03)
    bal, en, _, v = Q.check(rec, 0.0, 0.20)
    text = Q.report(bal, en, None, v)
    print(text)
    assert bal[0].imbalance is None and "both plates below 2%" in bal[0].skipped
    assert en[0].ratio is None and "balance skipped" in text.splitlines()[2]
    assert v.quasistatic


def test_no_load_at_all_cannot_pass():
    rec = record(scale=0.0)
    v = Q.check(rec, 0.05, 0.20)[3]
    assert not v.quasistatic and v.numbers["balance"] is None
    assert v.reasons[0].startswith("balance: no window to judge (both plates below")


def test_unrecorded_energy_cannot_pass():
    # a record of an input older than issue 29: no kinetic energy or work (zeros on loading)
    rec = dict(record(), **{Q.KE: np.zeros(N), Q.WORK: np.zeros(N)})
    v = Q.check(rec, 0.05, 0.20)[3]
    assert not v.quasistatic and v.reasons == ["ke_over_work: no window to judge (no plate work recorded)"]


def test_range_ends_at_the_first_rupture():
    rec = record()
    rec["broken_tethers"] = np.where(rec["strain"] >= 0.081, 3.0, 0.0)
    assert Q.intact_range(rec, 0.02, 0.30) == (0.02, pytest.approx(0.081, abs=2e-4))
    bal = Q.check(rec, 0.02, 0.30)[0]
    assert bal[-1].hi == pytest.approx(0.081, abs=2e-4) and len(bal) == 3


def test_ladder_chooses_the_first_converged_speed():
    # 2 m/s out of balance (its plates' mean 1.2 F); 1 m/s balanced but 10% off 0.5 m/s;
    # 0.25 m/s within 1% of 0.5 m/s: the ladder stops at 0.25
    rungs = [(2.0, record(bottom=0.5, scale=1.6)), (1.0, record(scale=1.1)), (0.5, record()),
             (0.25, record(scale=0.99))]
    for n, want in ((2, None), (3, None), (4, 3)):
        ver = ladder.rung_verdicts(rungs[:n], 0.05, 0.20)
        print(ladder.table(ver, ladder.choose(ver), "cell", 0.05, 0.20))
        assert ladder.choose(ver) == want
    ver = ladder.rung_verdicts(rungs, 0.05, 0.20)
    assert [r.split(":")[0] for r in ver[2][1].reasons] == ["rate"]
    assert "chosen speed: 0.25 m/s" in ladder.table(ver, 3, "cell", 0.05, 0.20)
    # with 1 m/s within 2% of 0.5 m/s the ladder stops at 0.5 (the slower of the pair)
    rungs[1] = (1.0, record(scale=1.02))
    assert ladder.choose(ladder.rung_verdicts(rungs[:3], 0.05, 0.20)) == 2
    # the kinetic energy is printed, not judged: 0.5 m/s with 3% of the work in motion is chosen
    rungs[2] = (0.5, record(ke_share=0.03))
    ver = ladder.rung_verdicts(rungs[:3], 0.05, 0.20)
    text = ladder.table(ver, ladder.choose(ver), "cell", 0.05, 0.20)
    print(text)
    assert ladder.choose(ver) == 2 and ver[2][1].failed == ["ke_over_work"]
    assert "(printed, not judged)" in text and "<- chosen" in text


def _recorded(path):
    """The values an input's `fix rec ... ave/time` writes (v_X, c_X), continuation lines joined."""
    text = re.sub(r"&\s*\n\s*", " ", open(path).read())
    line = next(ln for ln in text.splitlines() if re.match(r"fix\s+rec\s+all\s+ave/time", ln))
    return [w for w in line.split() if w.startswith(("v_", "c_"))]


@pytest.mark.parametrize("name, cols", [("in.compress", Q.CELL_COMPRESS),
                                        ("in.tissue-compress", tissuedata.COMPRESS)])
def test_columns_are_what_the_inputs_record(name, cols):
    vals = _recorded(os.path.join(ROOT, "lammps-inputs", name))
    print(name, vals)
    assert len(vals) == len(cols) and vals[-2:] == ["c_ke", "v_W"] and cols[-2:] == [Q.KE, Q.WORK]
