# SPDX-License-Identifier: GPL-2.0-or-later
"""The experiments report (cellmech.experiments.report) from a small run folder of analytic
records: it opens with a summary whose numbers are the table's, and says whether the one criterion
the paper states (rate independence within 2%) is met."""
import math
import os
import re
import sys

import numpy as np

from cellmech.experiments import report


def _compress(path, scale, P=364.0, n=400):
    eps = np.linspace(-0.007, 0.22, n)
    f = scale * (0.9e6 * np.clip(eps, 0, None) ** 1.4 + P * 1e4 * np.clip(eps, 0, None))
    np.savetxt(path, np.c_[np.arange(n) * 100, np.arange(n) * 0.05, eps, f * 1.01, f, 0.3 * f, np.full(n, P)])


def _run(d, scale025):
    os.makedirs(d)
    with open(os.path.join(d, "run-info.txt"), "w") as f:
        f.write("# RES=coarse r0=1.6\n")
    _compress(os.path.join(d, "compress-0.5.dat"), 1.0)
    _compress(os.path.join(d, "compress-0.25.dat"), scale025)
    t = np.arange(0, 5, 0.002)
    z = np.zeros_like(t)
    feq = 100.0 + 2e5 * np.exp(-t / 3.0) * np.cos(2 * math.pi * t / 1.4)
    np.savetxt(os.path.join(d, "relax-stiff-1.dat"), np.c_[np.arange(len(t)), t, feq, z, z, z, z, z])
    np.savetxt(os.path.join(d, "stiff-compressed.restart.load.dat"), np.c_[np.zeros((10, 5)), np.full(10, 100.0),
                                                                           np.zeros(10)])
    with open(os.path.join(d, "times.txt"), "w") as f:
        f.write("compress-0.5 300 ok\ncompress-0.25 600 ok\nrelax-stiff-1 90 ok\n")


def _membrane_curve(GT, R, P, strains, bulk_modulus=None, material="neohookean"):
    """A stand-in for the membrane solver (seconds a curve): a force that grows with the strain,
    stiffer for the network law, as the real one's."""
    k = 1.5 if material == "network" else 1.0
    return [dict(F=k * 3.0e6 * e ** 1.5) for e in strains]


def _report(tmp_path, monkeypatch, scale025):
    from cellmech import membrane
    monkeypatch.setattr(membrane, "compress_curve", _membrane_curve)
    run, rep = str(tmp_path / "run"), str(tmp_path / "rep")
    _run(run, scale025)
    monkeypatch.setattr(sys, "argv", ["report.py", "--run", run, "--res", "coarse", "--report", rep])
    report.main()
    return open(os.path.join(rep, "experiments.md")).read().split("\n")


def test_summary_states_the_table_numbers(tmp_path, monkeypatch):
    L = _report(tmp_path, monkeypatch, 1.0)
    assert L[0] == "# The paper's experiments (coarse resolution)" and L[2].startswith("**Summary.** ")
    s = L[2]
    print(s)
    assert "3 of the 27 runs of tools/experiments.sh finished here (990 s of wall time)" in s
    rows = [ln for ln in L if ln.startswith("| compression: force at eps = 19%")]
    force = re.search(r"\| (\d+) uN at 0.5 m/s", rows[0]).group(1)
    assert f"pushes back with {force} uN" in s
    law = re.search(r"\) ([\d]+) uN \(Neo-Hookean\), ([\d]+) uN \(tether-network law\)", rows[0])
    assert law and f"{100 * (int(force) / int(law.group(2)) - 1):+.0f}%" in s
    period = re.search(r"period ([\d.]+) us", next(ln for ln in L if ln.startswith("| relaxation stiff, 1 mPa s"))).group(1)
    assert f"period of {period} us" in s
    # the same records at both speeds: rate independent
    assert "the largest difference is 0.0%, met." in s
    assert os.path.exists(tmp_path / "rep" / "experiments" / "fig4-compression.png")


def test_summary_says_when_the_rate_criterion_is_missed(tmp_path, monkeypatch):
    s = _report(tmp_path, monkeypatch, 0.95)[2]
    rate = next(ln for ln in _report_lines(tmp_path) if "rate independence" in ln)
    d = re.search(r"largest difference ([\d.]+)%", rate).group(1)
    assert float(d) > 2 and f"the largest difference is {d}%, not met." in s


def _report_lines(tmp_path):
    return open(tmp_path / "rep" / "experiments.md").read().split("\n")
