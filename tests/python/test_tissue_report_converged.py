# SPDX-License-Identifier: GPL-2.0-or-later
"""cellmech.tissue.report with converged campaigns (report.py --converged): the block section, its
trends and the summary take the converged numbers of tools/tissue-converged.sh's run folders as
cellmech.tissue.converged measures them, say where a condition has not converged, and keep
tools/tissue.sh's fast compressions apart as a rate study labelled dynamic by the quasi-static
checks. Small synthetic run folders, as tests/python/test_converged_report.py builds them."""
import json

import numpy as np

from cellmech import quasistatic as Q
from cellmech.tissue import report, summary
from cellmech.tissue.tissuedata import COMPRESS

E = np.linspace(0.0, 0.1, 201)
GEN = {"cells": 8, "seeds": "lattice sc 2x2x2, constant 48.36", "wall_nodes_per_cell": 642, "volume_mean": 48.0 ** 3,
       "faces_mean": 6.0, "neighbours_mean": 3.0, "cell": [{"fluid": 440}] * 8, "lamella_bonds": 400,
       "pairs": [{"glued_area": 1000.0}] * 12}


def record(stress, bottom=1.0):
    """A compression's record (COMPRESS columns): the stress over E, the bottom plate carrying
    `bottom` of the top plate's force, a little kinetic energy against the plates' work."""
    d = {name: np.zeros_like(E) for name in COMPRESS}
    d["strain"], d["stress_kPa"], d["time_us"] = E, stress, E * 100.0
    d["F_top_nN"] = stress * 1.0e4
    d["F_bottom_nN"] = bottom * d["F_top_nN"]
    d["P_mean_kPa"] = np.full_like(E, 364.0)
    d["glued_area_um2"] = np.full_like(E, 12000.0)
    d[Q.WORK] = np.cumsum(stress) * 1e3 + 1.0
    return d


def save(folder, name, d):
    folder.mkdir(parents=True)
    np.savetxt(folder / name, np.column_stack([np.arange(len(E))] + [d[n] for n in COMPRESS]))


def converged_campaign(root):
    """-364 and -100 kPa strong: the same curve at v and 2v (converged); -364 weak: 2v 12.5%
    stiffer (not converged). A report page of the kind's title beside them."""
    for pi, lam, slope, fast in ((-364, "strong", 900.0, 900.0), (-100, "strong", 500.0, 500.0),
                                 (-364, "weak", 700.0, 787.5)):
        for v, s in ((0.25, slope), (0.5, fast)):
            save(root / f"compress{pi}-{lam}-{v:g}", "tissue-compress.dat", record(s * E))
    (root / "gen").mkdir()
    (root / "gen" / "block.json").write_text(json.dumps(GEN))
    (root / "run-info.txt").write_text("BLOCK='2 2 2' SPEEDS='0.25 0.5'\n")
    (root / "tq.md").write_text("# Tissue compression at converged plate speeds\n")


def fast_run(root):
    """tools/tissue.sh's folder with one compression at 2 m/s whose bottom plate carries nothing."""
    save(root / "compress-364-strong", "tissue-compress.dat", record(3000.0 * E, bottom=0.0))
    (root / "compress-364-strong" / "tissue-compress-cells.dat").write_text("")
    (root / "gen").mkdir()
    (root / "gen" / "block.json").write_text(json.dumps(GEN))
    (root / "run-info.txt").write_text("# RES=small block='2 2 2' vcompress=2 strain=0.1\n")


def test_the_block_section_takes_converged_numbers_and_labels_the_fast_runs_dynamic(tmp_path):
    converged_campaign(tmp_path / "conv")
    fast_run(tmp_path / "run")
    rep = report.Report(str(tmp_path / "run"), "small", str(tmp_path / "rep"), str(tmp_path / "rep" / "figs"),
                        [str(tmp_path / "conv")])
    rep.converged_blocks()
    rep.blocks()
    md = "\n".join(rep.md)
    # section 2: converged.py's numbers, the unconverged one named so, a link to the campaign's page
    (c,) = rep.S["block_converged"]
    ok, moved = c["conditions"]["-364_strong"], c["conditions"]["-364_weak"]
    assert ok["modulus_converged"] and abs(ok["modulus_kPa"] - 900.0) < 1e-6
    assert not moved["modulus_converged"] and moved["vs_2v_worst"] > Q.TOL_RATE
    assert "| -364 | strong | 0.25 | 364 | 900 |" in md
    assert "| -364 | weak | 0.25 | 364 | not converged (700 at v) |" in md
    assert "../conv/tq.md" in md
    # the trends read the converged moduli: 500 kPa at -100, 900 at -364 (the fast run's 3000 is not)
    assert rep.S["block_trends"]["compress_8_turgor_stiffer_strong"] is True
    assert rep.S["block_trends"]["compress_8_turgor_stiffer_weak"] is None
    # section 3: the fast run is a rate study, dynamic by the checks
    R = rep.S["block_rate_study"]["-364_strong"]
    assert R["quasistatic"] is False and R["qs_balance_worst"] > Q.TOL_BALANCE
    assert "## 3. Rate study: block of 8 cells compressed at 2 m/s (dynamic)" in md
    assert "| rupture | dynamic (" in md or "| none | dynamic (" in md
    text = summary.paragraph(rep)
    assert "Converged modulus: 500-900 kPa (8-cell compression, 2 of 3 conditions)" in text
    assert "3e+03" not in text and "The 1 compression of the 8-cell block at 2 m/s is a rate study" in text
    assert "the quasi-static checks call 1 of 1 dynamic" in text
