#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Benchmark (d), multiple time stepping (issue 12, target 3): the paper-resolution compression
# (level 4, lammps-inputs/in.inflate then in.compress to 20% strain at 0.5 m/s) single-level
# (Verlet, dt 0.001 us) against run_style respa with the wall and the plates on the inner level
# (dt 0.001; fix cell/plates reports the plates' mean force over the inner steps) and the fluid
# and contacts on the outer level (in.compress -var respa N: outer step N dt).
# Prints, per scheme, LAMMPS's loop time, its "% CPU use", the CPU time of the loop (loop x CPU
# use), both against single-level, and the windowed plate-force curve (analysis.windowed at
# strains 0.05 0.10 0.15 0.20, half width cases.window_half(4)) against single-level's.
# Called by tools/benchmark.sh (RESPA=0 there skips it); alone:
#   LMP=... LAMMPS_PLUGIN_PATH=... bash tools/bench/respa.sh WORKDIR [REPEAT]
# WORKDIR gets the cell and the runs; REPEAT full compressions per scheme (default 1), the schemes
# interleaved, fastest loop kept. Environment: RESPAS (default "1 3 4 5"; 1 is single-level, the
# reference), NP (MPI ranks, default 1), PYTHON.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=${1:?usage: respa.sh WORKDIR [REPEAT]}
REPEAT=${2:-1}
RESPAS=${RESPAS:-1 3 4 5}
NP=${NP:-1}
PYTHON=${PYTHON:-/usr/bin/python3}
source "$here/tools/common.sh"
inputs=$here/lammps-inputs
case " $RESPAS " in *" 1 "*) ;; *) echo "respa.sh: RESPAS must hold 1 (the single-level reference), got '$RESPAS'" >&2; exit 2 ;; esac
mkdir -p "$work"
cd "$work"
read -r nf s r0 f0 reach dt < <(level_params 4 nfluid s r0 f0 reach dt)
model=(-var dir "$inputs" -var s "$s" -var r0 "$r0" -var f0 "$f0" -var reach "$reach" -var dt "$dt")
"$PYTHON" "$here/tools/cellgen.py" cell -o respa-cell.data --level 4 --nfluid "$nf" --inset "$r0" > /dev/null
# the validation's inflation of the stiff cell (Runner.inflate: 20 us, Lp 100)
mpi_run "$NP" "$LMP" -nocite -in "$inputs/in.inflate" -log respa-inflate.log -screen none "${model[@]}" \
  -var data respa-cell.data \
  -var nsteps "$("$PYTHON" -c "print(round(20.0 / $dt))")" -var every 1000 -var out respa-inflate.dat \
  -var restart_out respa-inflated.restart > respa-inflate.out 2>&1 && [ -f respa-inflated.restart ] ||
  { echo "respa.sh: inflation failed" >&2; tail -n 20 respa-inflate.log >&2; exit 1; }
for r in $(seq 1 "$REPEAT"); do
  for n in $RESPAS; do
    if ! mpi_run "$NP" "$LMP" -nocite -in "$inputs/in.compress" -log "respa-$n.$r.log" -screen none \
      "${model[@]}" -var restart respa-inflated.restart -var vplate 0.5 -var every 100 \
      -var respa "$n" -var out "respa-$n.$r.dat" > "respa-$n.$r.out" 2>&1 ||
      ! grep -q '^Loop time of' "respa-$n.$r.log"; then
      echo "respa.sh: compression with -var respa $n failed (LAMMPS log follows)" >&2
      tail -n 20 "respa-$n.$r.log" >&2
      exit 1
    fi
  done
done
PYTHONPATH=$here/tools "$PYTHON" - "$REPEAT" $RESPAS <<'EOF'
import re
import sys

import numpy as np

from cellmech.validation.analysis import windowed
from cellmech.validation.cases import window_half

repeat, schemes = int(sys.argv[1]), [int(n) for n in sys.argv[2:]]
CENTRES = (0.05, 0.10, 0.15, 0.20)


def loop(log):
    """(loop time, % CPU use, outer steps, neighbour builds) of the run's last loop."""
    text = open(log).read()
    t, steps = re.findall(r"^Loop time of (\S+) on \d+ procs for (\d+) steps", text, re.M)[-1]
    cpu = re.findall(r"^(\S+)% CPU use", text, re.M)[-1]
    builds = re.findall(r"^Neighbor list builds = (\d+)", text, re.M)[-1]
    return float(t), float(cpu), int(steps), int(builds)


best = {}
for n in schemes:
    runs = [loop(f"respa-{n}.{r}.log") + (r,) for r in range(1, repeat + 1)]
    best[n] = min(runs, key=lambda x: x[0])
    best[n] = best[n] + (min(x[0] * x[1] / 100 for x in runs),)
half = window_half(4)
curves = {}
for n in schemes:
    a = np.loadtxt(f"respa-{n}.{best[n][4]}.dat", ndmin=2)     # step tt eps Ftop Fbot ...
    curves[n] = windowed(a[:, 2], 0.5 * (a[:, 3] + a[:, 4]), CENTRES, half)
t1, c1 = best[1][0], best[1][5]
print(f"(d) multiple time stepping: level-4 compression to 20% strain at 0.5 m/s, best of {repeat}, "
      f"plate force windowed at {' '.join(map(str, CENTRES))} (half width {half:g})")
print(f"{'scheme':<34} {'steps':>6} {'loop (s)':>9} {'CPU':>6} {'CPU (s)':>8} {'speed-up':>9} "
      f"{'per CPU-s':>9} {'builds':>6}  plate force (uN) / difference")
for n in schemes:
    t, cpu, steps, builds, _, c = best[n]
    label = "single level, dt 0.001" if n == 1 else f"respa 2 {n}: outer {n * 0.001:g}, wall 0.001"
    F = " ".join(f"{x * 1e-3:8.2f}" for x in curves[n])
    d = "" if n == 1 else "  " + " ".join(f"{x:+.2%}" for x in curves[n] / curves[1] - 1)
    print(f"{label:<34} {steps:>6} {t:>9.2f} {cpu:>5.1f}% {c:>8.2f} {t1 / t:>8.2f}x {c1 / c:>8.2f}x "
          f"{builds:>6}  {F}{d}")
EOF
