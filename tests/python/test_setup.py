# SPDX-License-Identifier: GPL-2.0-or-later
"""tools/setup.sh with SKIP_APT=1 leaves apt alone: no apt-get, apt, dpkg or apt-cache call and no
deb-src list, even where the LAMMPS source still has to be fetched (it stops and says so)."""
import os
import subprocess

from cellmech import params


def test_skip_apt_touches_no_apt(tmp_path):
    fake = tmp_path / "bin"
    fake.mkdir()
    calls = tmp_path / "calls"
    for tool in ("apt-get", "apt", "dpkg", "apt-cache"):
        (fake / tool).write_text(f"#!/bin/sh\necho {tool} \"$@\" >> {calls}\nexit 0\n")
        (fake / tool).chmod(0o755)
    lists = sorted(os.listdir("/etc/apt/sources.list.d")) if os.path.isdir("/etc/apt/sources.list.d") else []
    env = dict(os.environ, SKIP_APT="1", PATH=f"{fake}:{os.environ['PATH']}",
               CELLMECH_CACHE=str(tmp_path / "cache"), CELLMECH_BUILD_DIR=str(tmp_path / "build"))
    env.pop("LAMMPS_SRC", None)
    p = subprocess.run(["bash", os.path.join(params.ROOT, "tools", "setup.sh")], env=env,
                       capture_output=True, text=True, timeout=120)
    print(p.returncode, p.stdout, p.stderr)
    assert p.returncode == 2
    assert "SKIP_APT=1 leaves apt alone" in p.stderr and "LAMMPS_SRC" in p.stderr
    assert not calls.exists(), calls.read_text()
    now = sorted(os.listdir("/etc/apt/sources.list.d")) if os.path.isdir("/etc/apt/sources.list.d") else []
    assert now == lists
