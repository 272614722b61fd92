# SPDX-License-Identifier: GPL-2.0-or-later
"""cellmech.tissue.report: the plain-language summary at the top of docs/tissue.md is made of the
report's own numbers and the runs' settings, and a note written by hand under the title stays only
while the report is of the same runs."""
import json
import os
import types

from cellmech import params
from cellmech.tissue import report, summary


def fake_rep(tmp_path, settings):
    S = {"pair": {"force_at_5pct_pair_nN": 6.0e4, "force_at_5pct_single_nN": 2.0e4, "pull_force_max_nN": 1.4e5,
                  "sigmaA_nN": 5.0e5, "W_over_GcA": 0.7},
         "block": {"-364_strong": {"name": "compress-364-strong", "lamella": "strong", "mode": "rupture",
                                   "strain_end": 0.3, "modulus_kPa": 400.0, "peak_stress_kPa": 33.0},
                   "-364_weak": {"name": "compress-364-weak", "lamella": "weak", "mode": "debonding",
                                 "strain_end": 0.3, "modulus_kPa": 1600.0, "peak_stress_kPa": 55.0}},
         "block_trends": {"weak_turns_rupture_into_debonding_Pi-364": True, "turgor_stiffer_strong": False},
         "impact": [{"vplate_m_s": 5, "energy_pJ": 2.0e4, "ruptured_cells": 27, "fluid_lost_fraction": 0.15}],
         "water": {}, "cells": 27}
    return types.SimpleNamespace(S=S, block={"cells": 27}, times={"gen": (4, "ok"), "pair": (40, "failed(rc=1)")},
                                 p=lambda name: os.path.join(tmp_path, name),
                                 settings=lambda name, inp, lamella="strong": settings(name, lamella))


def test_summary_reads_the_numbers_and_settings(tmp_path):
    def settings(name, lamella):
        s = params.defaults(os.path.join(params.INPUTS, "in.tissue-pair" if name == "pair" else "in.tissue-compress"))
        s.update(params.lamellae()[lamella], vplate=0.75 if name == "pair" else s["vplate"])
        return s
    (tmp_path / "compress-364-strong").mkdir()
    (tmp_path / "compress-364-strong" / "tissue-compress.dat").write_text("")
    text = summary.paragraph(fake_rep(tmp_path, settings))
    print(text)
    assert text.startswith("**Summary.** Two glued cells were pressed to 10% strain at 0.75 m/s")
    assert "pull-off force 140 uN (0.28 of the lamella's strength x glued area)" in text
    assert "work of separation 0.7 of its fracture energy x glued area (not within 15% of 1)" in text
    assert "a strong (sigl 300 kPa, Gl 1 J/m^2) and a weak lamella (30 kPa, 0.1 J/m^2)" in text
    assert "apparent modulus 400-1.6e+03 kPa, peak stress 33-55 kPa" in text
    # runs without settings.json name no plate speed
    assert "at the plate speed of the run settings below" in text
    assert "Of the 2 published trends checked (section 2), 1 holds here" in text
    assert "27 of its 27 cells ruptured and lost 15% of its fluid" in text
    assert "1 of 2 stages finished" in text


def test_a_note_under_the_title_stays_with_its_runs(tmp_path):
    rep = report.Report.__new__(report.Report)
    rep.report, rep.info = str(tmp_path), "# RES=coarse\n# started 1\n"
    (tmp_path / "tissue.md").write_text("# Tissue experiments (coarse)\n\n> a note\n> on two lines\n\nGenerated ...\n")
    (tmp_path / "tissue-summary.json").write_text(json.dumps({"run_info": ["# RES=coarse", "# started 1"]}))
    assert rep.kept_note() == ["> a note", "> on two lines", ""]
    rep.info = "# RES=coarse\n# started 2\n"            # a new run: the note is not about it
    assert rep.kept_note() == []
