# SPDX-License-Identifier: GPL-2.0-or-later
"""The one MPI launch line: cellmech.launch.mpi_command (Python) and mpi_run (tools/common.sh)."""
import os
import subprocess

import pytest

from cellmech import params
from cellmech.launch import mpi_command, mpiexec


def test_one_rank_needs_no_launcher():
    assert mpi_command(["lmp", "-in", "in.x", 3], 1) == ["lmp", "-in", "in.x", "3"]


def test_ranks(monkeypatch):
    monkeypatch.delenv("MPIEXEC", raising=False)
    assert mpiexec() == "mpirun"
    assert mpi_command(["lmp"], 2) == ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2",
                                       "lmp"]
    monkeypatch.setenv("MPIEXEC", "/usr/bin/mpiexec.openmpi")
    assert mpi_command(["lmp"], 4)[:1] == ["/usr/bin/mpiexec.openmpi"]
    assert mpi_command(["lmp"], 4, "srun")[:1] == ["srun"]
    with pytest.raises(ValueError, match="nprocs must be >= 1, got 0"):
        mpi_command(["lmp"], 0)


def test_shell_and_python_agree():
    """mpi_run in tools/common.sh builds the same line (echo as the launcher shows it)."""
    common = os.path.join(params.ROOT, "tools", "common.sh")
    for np_ in (1, 3):
        p = subprocess.run(["bash", "-c", f"source {common} && mpi_run {np_} echo lmp -in in.x"],
                           env=dict(os.environ, MPIEXEC="echo"), capture_output=True, text=True,
                           timeout=30)
        want = mpi_command(["echo", "lmp", "-in", "in.x"], np_, "echo")[1:]
        print(np_, p.stdout.strip(), want)
        assert p.returncode == 0 and p.stdout.split() == want


def test_no_other_copies_in_tools():
    """No script or module of tools/ spells the launch line itself."""
    own = {os.path.join(params.ROOT, "tools", "common.sh"), os.path.join(params.ROOT, "tools", "cellmech",
                                                                         "launch.py")}
    found = []
    for base, _, files in os.walk(os.path.join(params.ROOT, "tools")):
        for f in files:
            path = os.path.join(base, f)
            if f.endswith((".py", ".sh")) and path not in own and "--oversubscribe" in open(path).read():
                found.append(os.path.relpath(path, params.ROOT))
    print(found)
    assert found == []
