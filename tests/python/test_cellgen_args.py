# SPDX-License-Identifier: GPL-2.0-or-later
"""cellgen.py refuses bad arguments at once, in one line, with exit status 2 (issue 13, defect 5.3).

Before: `cell --inset 40` and `--nfluid 100000000` filled the memory until the kernel killed the
process, `--inset -5` wrote fluid outside the wall, `--nfluid -1` and `--spacing -2` an empty wall,
`--spacing 0`, `--radius nan`, `-o /nonexistent/x` and `sheet --nx -3` ended in tracebacks and
overlapping cells were accepted. Each case runs under a memory and a time limit, so that a
regression fails here instead of eating the machine.
"""
import os
import re
import resource
import subprocess
import sys
import time

import numpy as np
import pytest
from cellmech.cellgen.datafile import read_data

CELLGEN = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                       "tools", "cellgen.py")
MEMORY = 1 << 30  # bytes of address space for one run: numpy and scipy need ~0.5 GB of it
SECONDS = 60


def limited():
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY, MEMORY))


def cellgen(tmp_path, *args):
    t0 = time.monotonic()
    try:
        p = subprocess.run([sys.executable, CELLGEN, *map(str, args)], cwd=tmp_path, capture_output=True,
                           text=True, timeout=SECONDS, preexec_fn=limited)
    except subprocess.TimeoutExpired:
        pytest.fail(f"cellgen {' '.join(map(str, args))}: still running after {SECONDS} s")
    dt = time.monotonic() - t0
    print(f"cellgen {' '.join(map(str, args))}: rc {p.returncode}, {dt:.2f} s: {p.stderr.strip()}")
    return p, dt


# (arguments, what the message must say): the option and what came
BAD = [
    (["cell", "-o", "x.data", "--inset", 40], r"--inset: expected a distance smaller than the radius 30.* got 40"),
    (["cell", "-o", "x.data", "--nfluid", 100000000], r"--nfluid 100000000 would make 1e\+08 particles, more"),
    (["cell", "-o", "x.data", "--inset", -5], r"argument --inset: expected a finite number >= 0, got '-5'"),
    (["cell", "-o", "x.data", "--nfluid", -1], r"argument --nfluid: expected a whole number >= 0, got '-1'"),
    (["cell", "-o", "x.data", "--spacing", -2], r"argument --spacing: expected a finite number > 0, got '-2'"),
    (["cell", "-o", "x.data", "--spacing", 0], r"argument --spacing: expected a finite number > 0, got '0'"),
    (["cell", "-o", "x.data", "--spacing", 0.01], r"--spacing 0.01 .* would make .* particles, more"),
    (["cell", "-o", "x.data", "--radius", "nan"], r"argument --radius: expected a finite number > 0, got 'nan'"),
    (["cell", "-o", "x.data", "--rho0", "inf"], r"argument --rho0: expected a finite number > 0, got 'inf'"),
    (["cell", "-o", "x.data", "--level", 7], r"argument --level: expected a whole number >= 0 and <= 6, got '7'"),
    (["cell", "-o", "/nonexistent/x"], r"argument -o/--output: expected a file in an existing folder, "
                                       r"got '/nonexistent/x'"),
    (["cell", "-o", "x.data", "--centres", "0,0,0;10,0,0"], r"--centres: cells 1 and 2 are 10 apart, their "
                                                            r"walls \(radius 30\) overlap"),
    (["cell", "-o", "x.data", "--centres", "0,0"], r"--centres: expected finite 'x,y,z;x,y,z;...', got '0,0'"),
    (["cell", "-o", "x.data", "--box", 0, 1, 0, 1, 0, 1], r"--box: expected xlo xhi ylo yhi zlo zhi around"),
    (["sheet", "-o", "x.data", "--nx", -3], r"argument --nx: expected a whole number >= 2, got '-3'"),
    (["sheet", "-o", "x.data", "--nx", 2000, "--ny", 2000], r"--nx 2000 --ny 2000 would make 4e\+06"),
    (["sheet", "-o", "/nonexistent/x"], r"argument -o/--output: expected a file in an existing folder"),
    (["sheet", "-o", "x.data", "--bond", "nan"], r"argument --bond: expected a finite number > 0, got 'nan'"),
    (["tissue", "-o", "t.data", "--lattice", "sc", "--nfluid", 100000000],
     r"--lattice sc --n 2 2 2 .* would make 8e\+08 particles, more"),
    (["tissue", "-o", "t.data", "--lattice", "sc", "--fluid-spacing", 0.01],
     r"--fluid-spacing 0.01 in 8 cells would make .* particles, more"),
    (["tissue", "-o", "t.data", "--lattice", "sc", "--inset", 40],
     r"--inset: expected a distance smaller than the cell's inner radius .* got 40"),
    (["tissue", "-o", "t.data", "--lattice", "sc", "--inset", -5],
     r"argument --inset: expected a finite number >= 0, got '-5'"),
    (["tissue", "-o", "t.data", "--lattice", "sc", "--nfluid", -1],
     r"argument --nfluid: expected a whole number >= 0, got '-1'"),
    (["tissue", "-o", "t.data", "--lattice", "sc", "--n", 2, -3, 2],
     r"argument --n: expected a whole number >= 1, got '-3'"),
    (["tissue", "-o", "t.data", "--lattice", "sc", "--seed", -1],
     r"argument --seed: expected a whole number >= 0, got '-1'"),
    (["tissue", "-o", "t.data", "--lattice", "sc", "--gap", "nan"],
     r"argument --gap: expected a finite number > 0, got 'nan'"),
    (["tissue", "-o", "/nonexistent/t.data", "--lattice", "sc"],
     r"argument -o/--output: expected a file in an existing folder"),
    (["tissue", "-o", "t.data", "--random", 100000000], r"--random 100000000 .* would make .* particles, more"),
]


@pytest.mark.parametrize("args,want", BAD, ids=[" ".join(map(str, a)) for a, _ in BAD])
def test_refused_in_one_line(tmp_path, args, want):
    p, dt = cellgen(tmp_path, *args)
    lines = p.stderr.strip().splitlines()
    assert p.returncode == 2, p.stderr[-2000:]
    assert len(lines) == 1, lines
    assert lines[0].startswith(f"cellgen.py {args[0]}: error: "), lines[0]
    assert re.search(want, lines[0]), lines[0]
    assert dt < 20, f"took {dt:.1f} s: not refused at once"
    assert not os.path.exists(os.path.join(tmp_path, str(args[2]))), "wrote a file anyway"


def read_atoms(path):
    """(type, x, y, z) of every atom of a cellgen data file."""
    a = read_data(path).array("Atoms")
    return a[:, 2].astype(int), a[:, 3:6]


@pytest.mark.parametrize("inset", [0.0, 5.0, 29.0])
def test_fluid_inside_the_inset(tmp_path, inset):
    """What an accepted --inset means: every fluid particle lies closer than R - inset to the centre,
    the count reached is at least the one asked for."""
    p, _ = cellgen(tmp_path, "cell", "-o", "c.data", "--level", 2, "--nfluid", 200, "--inset", inset)
    assert p.returncode == 0, p.stderr
    typ, x = read_atoms(tmp_path / "c.data")
    r = np.linalg.norm(x[typ == 2], axis=1)
    print(f"inset {inset}: {len(r)} fluid particles, farthest at {r.max():.4f} (limit {30 - inset:g})")
    assert len(r) >= 200
    # the count search ends at the largest spacing that holds the count: its outer shell lies at
    # R - inset, just inside before the data file's 15 digits round it
    assert r.max() < (30.0 - inset) * (1 + 1e-14)
