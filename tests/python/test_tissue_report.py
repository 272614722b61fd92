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
         "block_rate_study": {"-364_strong": {"name": "compress-364-strong", "lamella": "strong", "mode": "rupture",
                                              "strain_end": 0.3, "modulus_kPa": 400.0, "peak_stress_kPa": 33.0,
                                              "quasistatic": False},
                              "-364_weak": {"name": "compress-364-weak", "lamella": "weak", "mode": "debonding",
                                            "strain_end": 0.3, "modulus_kPa": 1600.0, "peak_stress_kPa": 55.0,
                                            "quasistatic": False}},
         "block_rate_study_definitions": {"vplate_m_s": 2.0},
         "block_converged": [{"cells": 8, "experiment": "compress",
                              "lamellae": {"strong": {"sigl_kPa": 300.0, "Gl": 1000.0},
                                           "weak": {"sigl_kPa": 30.0, "Gl": 100.0}},
                              "conditions": {"-364_strong": {"v_m_s": 0.25, "modulus_kPa": 900.0, "modulus_converged": True,
                                                             "failure_stress_kPa": 70.0, "failure_converged": True,
                                                             "mode": "wall rupture"},
                                             "-100_strong": {"v_m_s": 0.125, "modulus_kPa": 500.0,
                                                             "modulus_converged": False, "failure_stress_kPa": 80.0,
                                                             "failure_converged": False, "mode": "wall rupture"}}}],
         "block_trends": {"compress_8_weak_turns_rupture_into_debonding_Pi-364": True,
                          "compress_8_turgor_stiffer_strong": False, "compress_8_turgor_stiffer_weak": None},
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
    # the block's numbers are the converged ones only: the modulus that has not converged and the
    # fast runs' numbers are not among them
    assert "8-cell blocks compressed at 0.125 and 0.25 m/s" in text
    assert "Converged modulus: 900 kPa (8-cell compression, 1 of 2 conditions)" in text
    assert "Converged failure stress: 70 kPa (8-cell compression, 1 of 2 conditions)" in text
    assert "500 kPa" not in text and "1.6e+03" not in text and "33 kPa" not in text and "55 kPa" not in text
    assert ("Of the 3 published trends checked against the converged numbers (section 2), 1 holds, 1 does not, "
            "and 1 cannot be told") in text
    assert "The 2 compressions of the 27-cell block at 2 m/s are a rate study (section 3)" in text
    assert "the quasi-static checks call 2 of 2 dynamic" in text
    assert "27 of its 27 cells ruptured and lost 15% of its fluid" in text
    assert "1 of 2 stages finished" in text


def test_a_note_under_the_title_stays_with_its_runs(tmp_path):
    rep = report.Report.__new__(report.Report)
    rep.report, rep.info = str(tmp_path), "# RES=coarse\n# started 1\n"
    (tmp_path / "tissue.md").write_text("# Tissue experiments (coarse)\n\n> a note\n> on two lines\n\nGenerated ...\n")
    (tmp_path / "tissue-summary.json").write_text(json.dumps({"run_info": ["# RES=coarse", "# started 1"]}))
    assert rep.kept_note() == ["> a note", "> on two lines", ""]
    # the same run with some stages run again (tools/tissue.sh ONLY= adds lines): still its note
    rep.info = "# RES=coarse\n# started 1\n# ONLY=\"water-dry\": started 3\n"
    assert rep.kept_note() == ["> a note", "> on two lines", ""]
    rep.info = "# RES=coarse\n# started 2\n"            # a new run: the note is not about it
    assert rep.kept_note() == []
