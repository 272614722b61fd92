# SPDX-License-Identifier: GPL-2.0-or-later
"""The benchmark scripts still run and report everything they promise (issue 12: "tools/benchmark.sh
prints all of the above in one run"), in a short form. No timing is asserted: a benchmark's figures
belong in docs/performance.md and docs/tissue-benchmark.md, measured on a quiet machine.

1. tools/benchmark-tissue.sh on blocks of 8 and 27 cells and the notched 27-cell sample, 1 and 2
   ranks, even split and balanced: a row per run, the per-rank table of every 2-rank run, the
   projection to 64 and 256 ranks with efficiencies between 0 and 100%; the balanced notch holds
   its particles evenly (imbalance < 1.1, LAMMPS's Nlocal) where the even split does not.
2. tools/benchmark.sh: the stock, cell/sph and full-cell rows with their neighbour check, and case
   (f), the reductions per step of a wall that can fail.
3. tools/bench/rate-ensemble.sh with 2 members, 2 speeds, a short inflation and 8% strain: a row
   of windowed forces per member and speed, and the paired differences; member 2 (its fluid
   displaced by 1e-9 um, -var jitter of in.inflate) inflates to another microstate than member 1,
   so its forces differ (in the last digits at least), and a bad -var jitter stops in.inflate with
   a message.
"""
import os
import re
import subprocess

import numpy as np

import lmptest as T


def script(name, *args, env=None):
    p = subprocess.run(["bash", os.path.join(T.ROOT, "tools", name), *map(str, args)], capture_output=True,
                       text=True, env=dict(os.environ, LMP=T.LMP,
                                           LAMMPS_PLUGIN_PATH=os.path.dirname(T.PLUGIN), **(env or {})))
    if p.returncode:
        print(p.stdout[-3000:], p.stderr[-3000:])
    return p.returncode, p.stdout


def test_tissue_benchmark_reports():
    rc, out = script("benchmark-tissue.sh", "-s", "2 3", "-n", 40, "-w", 20, "-t", 20, "-b", "0 1.1")
    print(out)
    T.check("benchmark-tissue.sh runs", rc == 0)
    rows = {}
    for m in re.finditer(r"^\| (\w+) \| (\d+) \| [^|]+ \| (\d+) \| (\d) \| (\S+) \|.*\| ([\d.]+) \| (\d+) \|"
                         r"(?: [\d.]+ \|){5}$", out, re.M):
        rows[(m.group(1), int(m.group(4)), m.group(5))] = float(m.group(6))
    want = [(c, n, "off") for c in ("block2", "block3", "notch") for n in (1, 2)] + [("notch", 2, "1.1")]
    T.check("a row for every block, rank count and balance setting", sorted(rows) == sorted(want),
            f"{sorted(rows)}")
    per_rank = re.findall(r"^\| (\w+) \| 2 \| (\S+) \| \d+-\d+ \| \d+-\d+ \|", out, re.M)
    T.check("a per-rank row for every 2-rank run", sorted(per_rank) == sorted((c, b) for c, n, b in want if n == 2),
            f"{per_rank}")
    eff = {int(m.group(1)): float(m.group(2)) for m in
           re.finditer(r"^\| (64|256) \| [^|]+ \| [^|]+ \| [^|]+ \|.*\| 2 \| 5 \| (\d+)% \|$", out, re.M)}
    T.check("the projection gives 64 and 256 ranks an efficiency in (0, 100]",
            sorted(eff) == [64, 256] and all(0 < e <= 100 for e in eff.values()), f"{eff}")
    if ("notch", 2, "off") in rows and ("notch", 2, "1.1") in rows:
        T.check("balancing evens the notched sample (imbalance < 1.1; > 1.25 split evenly)",
                rows[("notch", 2, "1.1")] < 1.1 < 1.25 < rows[("notch", 2, "off")],
                f"{rows[('notch', 2, 'off')]} -> {rows[('notch', 2, '1.1')]}")


def test_cell_benchmark_reports():
    rc, out = script("benchmark.sh", "-r", 1, "-n", 20, env=dict(
        RESPA="0", TISSUE="0", WALLS="tether", NCOLL="40",
        CELLMECH_MPI_COUNT_LIB=os.environ.get("CELLMECH_MPI_COUNT_LIB", "")))
    print(out)
    T.check("benchmark.sh runs", rc == 0)
    for case in (r"\(b\) stock sph/taitwater/morris", r"\(c\) cell/sph \+ cell/fluid", r"\(a\) full cell, tether wall"):
        T.check(f"benchmark.sh reports {case.replace(chr(92), '')}",
                re.search(rf"^{case}\s+\d+\s+20\s+[\d.]+\s+[\d.e+]+", out, re.M) is not None)
    T.check("benchmark.sh checks the neighbours of the two fluid-only cases", "neighbour check:" in out)
    T.check("benchmark.sh reports the reductions per step of a wall that can fail (f)",
            re.search(r"^  lamf 1\.5 \(can fail, nothing does\): \d+ calls", out, re.M) is not None)


def test_rate_ensemble_reports():
    d = T.workdir("rate-ensemble")
    rc, out = script("bench/rate-ensemble.sh", d, 2,
                     env=dict(RATES="0.5 0.25", STRAIN="0.08", INFLATE="2"))
    print(out)
    T.check("rate-ensemble.sh runs", rc == 0)
    rows = re.findall(r"^  member (\d): +([-\d. ]+)$", out, re.M)
    T.check("a row of windowed forces per member and speed (the 6% window only, up to 8% strain)",
            len(rows) == 4, f"{rows}")
    T.check("paired differences 0.5 / 0.25 m/s with their mean", "paired difference 0.5 / 0.25 m/s" in out
            and re.search(r"^  mean: +[-+\d.% ]+$", out, re.M) is not None)
    a1, a2 = (np.loadtxt(f"{d}/inflate-{k}.dat", ndmin=2)[-1] for k in (1, 2))
    T.check("the displaced member inflates to another microstate", np.any(a1 != a2),
            f"volumes {a1[2]:.12g} {a2[2]:.12g}")
    _, log = T.lmp(T.INPUTS + "/in.inflate", cwd=d, check=False, log="log.jitter", variables=dict(
        T.COARSE, dir=T.INPUTS, data=f"{d}/cell.data", nsteps=1, jitter=-3))
    T.check("-var jitter -3 stops in.inflate with a message",
            "in.inflate: -var jitter -3: expected a whole number >= 0" in log)

