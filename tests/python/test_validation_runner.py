# SPDX-License-Identifier: GPL-2.0-or-later
"""The validation Runner's reuse of runs (cellmech.validation.common.Runner.lmp): a run is reused
when its settings are the same, and made again when a run it reads from was made with others."""
import os
import stat
import sys

# a stand-in for lmp: writes its -var out / restart_out files and its log, and counts its runs
FAKE = """#!{python}
import sys
a = sys.argv[1:]
log = a[a.index("-log") + 1]
v = {{a[i + 1]: a[i + 2] for i in range(len(a)) if a[i] == "-var"}}
for k in ("out", "restart_out"):
    if k in v:
        open(v[k], "w").write(" ".join(a))
open(log, "w").write("Total wall time: 0:00:01\\n")
open("runs.txt", "a").write(log + "\\n")
"""


def _runner(tmp_path, monkeypatch):
    fake = tmp_path / "lmp"
    fake.write_text(FAKE.format(python=sys.executable))
    fake.chmod(fake.stat().st_mode | stat.S_IEXEC)
    monkeypatch.setenv("LMP", str(fake))
    from cellmech.validation.common import Runner
    return Runner(str(tmp_path / "work"), log=lambda *a: None)


def _pair(r, nsteps):
    """A producer (writes a.restart) and a consumer that reads it, as inflate and compress."""
    r.lmp("in.inflate", "log.a", outputs=("a.dat", "a.restart"), out="a.dat", restart_out="a.restart",
          nsteps=nsteps)
    r.lmp("in.compress", "log.b", outputs=("b.dat",), restart="a.restart", out="b.dat")


def _runs(tmp_path):
    return open(tmp_path / "work" / "runs.txt").read().split()


def test_consumer_remade_when_its_input_was(tmp_path, monkeypatch):
    _pair(_runner(tmp_path, monkeypatch), 1)
    assert _runs(tmp_path) == ["log.a", "log.b"]
    _pair(_runner(tmp_path, monkeypatch), 1)           # the same settings: both reused
    assert _runs(tmp_path) == ["log.a", "log.b"]
    _pair(_runner(tmp_path, monkeypatch), 2)           # the producer changed: both made again,
    assert _runs(tmp_path) == ["log.a", "log.b"] * 2   # though the consumer's own settings did not
    _pair(_runner(tmp_path, monkeypatch), 2)
    assert _runs(tmp_path) == ["log.a", "log.b"] * 2
    assert os.path.exists(tmp_path / "work" / "b.dat")


def test_a_run_called_twice_in_one_runner_is_made_once(tmp_path, monkeypatch):
    # its own outputs are in the runner's record after the first call: they are not its inputs
    r = _runner(tmp_path, monkeypatch)
    _pair(r, 1)
    _pair(r, 1)
    assert _runs(tmp_path) == ["log.a", "log.b"]
