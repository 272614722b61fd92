# SPDX-License-Identifier: GPL-2.0-or-later
"""The experiments report (cellmech.experiments.report) from a small run folder of analytic
records: it opens with a summary whose numbers are the table's, and says whether the one criterion
the paper states (rate independence within 2%) is met. tools/experiments.sh records each run's
effective settings (settings.json, under its log name) and the report reads a run's own from there
(a folder from before the records: as before)."""
import json
import math
import os
import re
import subprocess
import sys

import numpy as np

from cellmech import params
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


# ------------------------------------------------------------ the runs' records (settings.json)
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def test_experiments_sh_records_every_run_under_its_log_name(tmp_path):
    """Every LAMMPS run of tools/experiments.sh records its effective settings first, under its log
    name: the two compressions (one input, two rates) keep one record each, and each record holds
    exactly the -var values of the command line the run got, with the input's defaults for the rest."""
    root = tmp_path / "root"
    (root / "build").mkdir(parents=True)
    # LAMMPS stands in as a script that keeps each command line it is given (no run: a second)
    stub = root / "lmp-stub"
    stub.write_text("#!/bin/sh\nexec /usr/bin/python3 -c 'import json, sys; open(\"calls.jsonl\", \"a\")"
                    ".write(json.dumps(sys.argv[1:]) + \"\\n\")' \"$@\"\n")
    stub.chmod(0o755)
    (root / "build" / "cellmech-env.sh").write_text(f"export LMP={stub}\n")
    os.symlink(os.path.join(ROOT, "tools"), root / "tools")
    os.symlink(os.path.join(ROOT, "lammps-inputs"), root / "lammps-inputs")
    out = tmp_path / "run"
    env = dict(os.environ, RES="coarse", OUT=str(out), ONLY="compress-0.5 compress-0.25 failure-qs",
               CELLMECH_ROOT=str(root), NP="1")
    for k in ("WALL", "INPUTS", "RESUME", "PLUGIN_DIR"):
        env.pop(k, None)
    p = subprocess.run(["bash", str(root / "tools" / "experiments.sh")], env=env, capture_output=True,
                       text=True, timeout=120)
    print(p.stdout, p.stderr)
    assert p.returncode == 0
    calls = [json.loads(ln) for ln in open(out / "calls.jsonl")]
    data = json.load(open(out / "settings.json"))
    logs = [c[c.index("-log") + 1] for c in calls]
    assert sorted(logs) == sorted(data) == ["log.compress-0.25", "log.compress-0.5", "log.failure-qs"]
    inputs = os.path.join(ROOT, "lammps-inputs")
    for c, log in zip(calls, logs):
        inp, var = params.lammps_vars(c)
        rec = data[log]
        assert rec["input"] == os.path.basename(inp) and rec["var"] == var
        assert rec["settings"] == dict(params.defaults(inp, inputs), **var)
    assert data["log.compress-0.5"]["var"]["vplate"] == 0.5 and data["log.compress-0.25"]["var"]["vplate"] == 0.25
    s = params.recorded_settings(str(out), "log.failure-qs")
    # the coarse level's contact distance (passed) and in.failure's time step (its default)
    assert s["r0"] == params.LEVELS[3]["r0"] and s["dt"] == params.defaults(os.path.join(inputs, "in.failure"))["dt"]
    assert params.recorded_settings(str(out), "log.compress-soft") is None


def _failure_run(d):
    """in.failure's table (step tt eps Ftop Fbot Feq P tau nzone tauall lammax nbroken): tethers
    break from eps = 6% on; no dump."""
    n = 200
    eps = np.linspace(0.0, 0.2, n)
    nb = np.where(eps > 0.06, np.round(400 * (eps - 0.06)), 0)
    np.savetxt(os.path.join(d, "failure-impact-1.dat"),
               np.c_[np.arange(n) * 10, eps / 0.5, eps, 1e5 * eps, 1e5 * eps, 5e4 * eps, np.full(n, 300.0),
                     np.zeros((n, 4)), nb])
    with open(os.path.join(d, "times.txt"), "a") as f:
        f.write("failure-impact-1 50 ok\n")


def _seen(tmp_path, monkeypatch, name, records):
    """Report a run folder with (records: settings.json records as experiments.sh writes them) or
    without them, and what the report handed on: the failure analysis's time step and escape margin,
    and the membrane reference's G t0. Returns those and the report's lines."""
    from cellmech import membrane
    from cellmech.experiments import analyse
    seen = {}
    real_failure = analyse.failure

    def failure(dat, dump, dt, margin):
        seen["failure"] = (dt, margin)
        return real_failure(dat, dump, dt, margin)

    def curve(GT, *a, **k):
        seen["GT"] = GT
        return _membrane_curve(GT, *a, **k)
    monkeypatch.setattr(analyse, "failure", failure)
    monkeypatch.setattr(membrane, "compress_curve", curve)
    run, rep = str(tmp_path / f"run-{name}"), str(tmp_path / f"rep-{name}")
    _run(run, 1.0)
    _failure_run(run)
    inputs = os.path.join(ROOT, "lammps-inputs")
    for log, inp, var in records:
        argv = ["-in", os.path.join(inputs, inp), "-var", "dir", inputs]
        for k, v in var.items():
            argv += ["-var", k, str(v)]
        params.write_settings(argv, run, key=log)
    monkeypatch.setattr(sys, "argv", ["report.py", "--run", run, "--res", "coarse", "--report", rep])
    report.main()
    return seen, open(os.path.join(rep, "experiments.md")).read()


def test_report_reads_the_settings_of_each_run_from_its_record(tmp_path, monkeypatch):
    table = params.table()
    # a folder from before the records: run-info.txt's r0 (1.6), the time step 0.001, Table I's wall
    old, old_md = _seen(tmp_path, monkeypatch, "old", [])
    assert old["failure"] == (0.001, 1.6) and old["GT"] == report.G_T0 == table["G"] * table["t0"]
    # the records: another contact distance and time step in the failure run, another wall in the
    # compression than run-info.txt and Table I say; the report takes the run's own
    new, _ = _seen(tmp_path, monkeypatch, "new", [
        ("log.failure-impact-1", "in.failure", dict(r0=2.5, dt=0.0005, vplate=5, mu=1)),
        ("log.compress-0.5", "in.compress", dict(r0=2.5, G=4.0e5, vplate=0.5)),
        ("log.compress-0.25", "in.compress", dict(r0=2.5, G=2.0e5, vplate=0.25))])
    assert new["failure"] == (0.0005, 2.5) and new["GT"] == 4.0e5 * table["t0"]
    # records that say what the old folder's fallback assumed: the same report, word for word
    same, same_md = _seen(tmp_path, monkeypatch, "same", [
        ("log.failure-impact-1", "in.failure", dict(r0=1.6, vplate=5, mu=1)),
        ("log.compress-0.5", "in.compress", dict(r0=1.6, vplate=0.5))])
    assert same == old and same_md == old_md.replace("run-old", "run-same")


def test_failure_rows_without_a_crack_record():
    """A quasistatic failure run without its dump (tests run it short) has no crack to follow: the
    row says so instead of failing on the missing span."""
    class Rep:
        R = type("R", (), {"mark": staticmethod(lambda name: "")})
        rows, key = [], {}
    f = dict(eps_f=0.134, lat_first_mean=56.6, t_90=0.3, p_f=503.0, v_bernoulli=31.7)
    report.failure_rows(Rep, {"qs": f})
    origin = [r for r in Rep.rows if r[0] == "failure, quasistatic: origin"]
    assert len(origin) == 1 and "crack not followed (no dump)" in origin[0][2], origin
    f.update(span_02=(-23.0, 76.0), crack_speed=355.0)
    Rep.rows = []
    report.failure_rows(Rep, {"qs": f})
    origin = [r for r in Rep.rows if r[0] == "failure, quasistatic: origin"]
    assert "the crack spans -23 to 76 deg (355 m/s)" in origin[0][2], origin
