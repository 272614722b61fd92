# SPDX-License-Identifier: GPL-2.0-or-later
"""validation.md's verdict (cellmech.validation.report.verdict): computed from the case's rows, it
says whether every row with a tolerance is within it; the summary paragraph opens the report."""
from cellmech.validation import report


def _case(cid, rows, status="ok"):
    return dict(id=f"{cid}-x", title=f"case {cid}", paper="p", status=status, resolution={}, wall_time_s=10.0,
                notes=[], plots=[], rows=[dict(name=n, measured=m, reference=1.0, rel_error=e, unit="",
                                               tolerance=t, group=None) for n, m, e, t in rows])


def test_verdict_from_the_rows():
    assert report.verdict(_case(1, [("a", 1.01, 0.01, 0.05), ("b", 1.2, 0.2, None)])) == "pass"
    # a row beside its tolerance fails even when the case ran ("status ok")
    assert report.verdict(_case(2, [("a", 1.01, 0.01, 0.05), ("b", 1.1, -0.1, 0.05)])) == "fails 1 of 2 rows"
    # the bound is strict, as the table's "rows within tolerance"; a judged row without a value fails
    assert report.verdict(_case(3, [("a", 1.05, 0.05, 0.05), ("b", None, None, 0.05)])) == "fails 2 of 2 rows"
    assert report.verdict(_case(4, [("a", 1.2, 0.2, None)])) == "no tolerance"
    assert report.verdict(_case(5, [], status="skipped")) == "not run"
    assert report.verdict(_case(6, [], status="error")) == "error"
    assert report.verdict(_case(7, [("a", 1.0, 0.0, 0.1)], status="partial")) == "pass (partial)"


def test_report_opens_with_the_summary_and_has_the_verdict_column():
    cases = [_case(1, [("a", 1.01, 0.01, 0.05)]), _case(2, [("a", 1.3, 0.3, 0.1), ("b", 1.0, 0.0, 0.1)]),
             _case(6, [], status="skipped")]
    meta = dict(res="coarse", wall="tether", generated_utc="2026-01-01 00:00 UTC", cpu_count=2, mpi_ranks=1,
                elapsed_s=30.0)
    L = report.markdown(meta, cases)
    print("\n".join(L[:12]))
    assert L[0] == "# Validation of the cell model (RES=coarse)" and L[2].startswith("**Summary.** ")
    assert "checked the `tether` wall in 2 of 3 cases" in L[2] and "1 case passes" in L[2]
    assert "Case 2, case 2, fails 1 of 2 rows; the farthest, a, is off by 30% against a tolerance of 10%" in L[2]
    assert "Not judged: 6 (not run)" in L[2]
    head = next(k for k, ln in enumerate(L) if ln.startswith("| case | status | verdict |"))
    assert L[head + 2].split(" | ")[2] == "pass" and L[head + 3].split(" | ")[2] == "fails 1 of 2 rows"
    assert "*Verdict:* fails 1 of 2 rows" in L
