# SPDX-License-Identifier: GPL-2.0-or-later
"""The validation report's walls-side-by-side section (cellmech.validation.report.side_by_side)."""
from cellmech.validation import report


def _entry(cid, rows):
    return dict(id=f"{cid}-x", rows=[dict(name=n, measured=m, reference=r, unit="nN",
                                          rel_error=None if r is None else m / r - 1)
                                     for n, m, r in rows])


def test_rows_of_both_walls_matched_by_case_and_name():
    mine = [_entry("5", [("F at 0.10", 105.0, 100.0), ("F at 0.20", 190.0, 200.0),
                         ("only here", 1.0, 1.0)]),
            _entry("3", [("F_eq", 99.0, 100.0)])]       # runs both walls itself: left out
    other = dict(cases=[_entry("5", [("F at 0.20", 240.0, 200.0), ("F at 0.10", 117.0, 100.0)]),
                        _entry("3", [("F_eq", 98.0, 100.0)])])
    L = report.side_by_side("membrane", mine, [("tether", other, ".")])
    rows = [x for x in L if x.startswith("| 5 |")]
    assert rows == ["| 5 | F at 0.10 | 100 nN | 105 nN | +5.00% | 117 nN | +17.00% |",
                    "| 5 | F at 0.20 | 200 nN | 190 nN | -5.00% | 240 nN | +20.00% |"]
    assert not [x for x in L if x.startswith("| 3 |")]


def test_nothing_in_common_writes_no_section():
    mine = [_entry("5", [("a", 1.0, 1.0)])]
    assert report.side_by_side("membrane", mine, [("tether", dict(cases=[_entry("6", [("a", 1.0, 1.0)])]), ".")]) == []
    assert report.side_by_side("membrane", mine, []) == []


def test_case5_protocol_per_wall():
    """Case 5: the tethers keep the paper's protocol; the membrane walls meet the membrane model on
    its terms (tension-field element, f0 x 10 at every level, slower plates), in files of their own."""
    import pytest
    from cellmech.params import LEVELS
    from cellmech.validation import cases, common
    assert cases.case5_protocol("tether", 4) == ({}, "", cases.PAPER_VPLATE, {})
    for wall in ("membrane", "bending"):
        for lvl in LEVELS:
            model, name, v, prep = cases.case5_protocol(wall, lvl)
            assert model["wrinkle"] == "yes"
            # its cells at rest: longer than the defaults at every level (Young-Laplace creeps)
            assert prep["t_inflate"] > common.T_INFLATE[lvl] and prep["t_settle"] > common.T_SETTLE[lvl]
            assert float(model["f0"]) == pytest.approx(cases.MEMBRANE_CASE5["f0_scale"] * LEVELS[lvl]["f0"])
            assert name and v < cases.PAPER_VPLATE
    # records of another model or speed never share a file (a run's stamp would replace another's)
    names = {cases.compress_record(4, 364.0, n, v) for n in ("", "-case5") for v in (0.5, 0.125)}
    assert len(names) == 4
