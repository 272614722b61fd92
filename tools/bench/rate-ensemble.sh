#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Study (not a test, not timed): how far the windowed plate-force curve of the quasistatic
# compression moves with the cell's microstate, and with the plate speed. A change that alters
# round-off (another compiler, a faster pair loop) starts the compression from another microstate
# of the same cell; this measures what that alone does to a rate comparison like
# tests/test_compress.py's (docs/performance.md, "The compression test's rate check").
#
# Each of N members inflates the cell (lammps-inputs/in.inflate, 20 us as the test) with its
# fluid displaced by up to 1e-9 um (-var jitter SEED; member 1 is not displaced: the generator's
# symmetric lattice, an atypical microstate; the test inflates its level-4 cell with seed 1), then
# compresses that inflated cell (in.compress to STRAIN) once per plate speed of RATES.
# Prints, per speed, the mean of both plates' force over strain windows (4%-wide windows at
# 6 10 14 18% as the test, and 8%-wide ones at 8 and 16%) for every member, the members' mean and
# their relative scatter; and per pair of neighbouring speeds, the paired difference (the same
# inflated cell at both speeds) per member, its mean and standard error.
#   LMP=... LAMMPS_PLUGIN_PATH=... bash tools/bench/rate-ensemble.sh WORKDIR [N]
# N members (default 6). Environment: LEVEL (default 3, the coarse cell of the tests; 4 is the
# paper's), RATES (plate speeds in m/s, default "0.5 0.25"), STRAIN (default 0.2), INFLATE (us of
# inflation, default 20), NP (MPI ranks, default 1), PYTHON.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=${1:?usage: rate-ensemble.sh WORKDIR [N]}
N=${2:-6}
LEVEL=${LEVEL:-3}
RATES=${RATES:-0.5 0.25}
STRAIN=${STRAIN:-0.2}
INFLATE=${INFLATE:-20}
NP=${NP:-1}
PYTHON=${PYTHON:-/usr/bin/python3}
source "$here/tools/common.sh"
inputs=$here/lammps-inputs
[ "$N" -ge 2 ] 2>/dev/null || { echo "rate-ensemble.sh: N must be a whole number >= 2, got '$N'" >&2; exit 2; }
mkdir -p "$work"
cd "$work"
read -r nf s r0 f0 reach dt < <(level_params "$LEVEL" nfluid s r0 f0 reach dt)
model=(-var dir "$inputs" -var s "$s" -var r0 "$r0" -var f0 "$f0" -var reach "$reach" -var dt "$dt")
"$PYTHON" "$here/tools/cellgen.py" cell -o cell.data --level "$LEVEL" --nfluid "$nf" --inset "$r0" > /dev/null
run() {    # run LOG ARGS...: one LAMMPS run, its log shown if it fails
  local log=$1
  shift
  mpi_run "$NP" "$LMP" -nocite -log "$log" -screen none "${model[@]}" "$@" > "${log%.log}.out" 2>&1 ||
    { echo "rate-ensemble.sh: run failed: $*" >&2; tail -n 20 "$log" >&2; exit 1; }
}
for k in $(seq 1 "$N"); do
  seed=$(( k == 1 ? 0 : 7919 * (k - 1) ))
  run "inflate-$k.log" -in "$inputs/in.inflate" -var data cell.data -var jitter "$seed" \
    -var nsteps "$("$PYTHON" -c "print(round($INFLATE / $dt))")" -var every 1000 \
    -var out "inflate-$k.dat" -var restart_out "inflated-$k.restart"
  for v in $RATES; do
    run "compress-$v-$k.log" -in "$inputs/in.compress" -var restart "inflated-$k.restart" \
      -var vplate "$v" -var strain "$STRAIN" -var every 100 -var out "compress-$v-$k.dat"
  done
done
PYTHONPATH=$here/tools "$PYTHON" - "$N" "$LEVEL" "$STRAIN" $RATES <<'EOF'
import sys

import numpy as np

from cellmech.validation.analysis import windowed

n, level, strain, rates = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), sys.argv[4:]
# the test's 4%-wide windows, and 8%-wide ones spanning two or three of the ring-by-ring contact
# steps of the coarse wall; those past the final strain are left out
WINDOWS = [(c, 0.02) for c in (0.06, 0.10, 0.14, 0.18)] + [(0.08, 0.04), (0.16, 0.04)]
WINDOWS = [(c, h) for c, h in WINDOWS if c + h <= strain + 1e-9]
labels = [f"{c:.2f}+-{h:.2f}" for c, h in WINDOWS]


def curve(v, k):
    a = np.loadtxt(f"compress-{v}-{k}.dat", ndmin=2)    # step tt eps Ftop Fbot ...
    F = 0.5 * (a[:, 3] + a[:, 4])
    return np.array([windowed(a[:, 2], F, [c], h)[0] for c, h in WINDOWS])


F = {v: np.array([curve(v, k) for k in range(1, n + 1)]) for v in rates}
print(f"rate ensemble: level {level}, {n} inflated microstates (member 1 unperturbed, the others "
      f"with the fluid displaced by 1e-9 um), plate speeds {' '.join(rates)} m/s, strain to {strain:g}")
print("windows (strain centre +- half width): " + "  ".join(labels))
for v in rates:
    print(f"v = {v} m/s, windowed plate force (uN) per member:")
    for k in range(n):
        print(f"  member {k + 1}: " + " ".join(f"{x * 1e-3:9.2f}" for x in F[v][k]))
    m = F[v].mean(axis=0)
    print("  mean:     " + " ".join(f"{x * 1e-3:9.2f}" for x in m))
    print("  scatter (sd / mean, one member): " + " ".join(f"{x:8.2%}" for x in F[v].std(axis=0, ddof=1) / m))
for v1, v2 in zip(rates, rates[1:]):
    d = F[v1] / F[v2] - 1
    print(f"paired difference {v1} / {v2} m/s - 1 (same inflated cell):")
    for k in range(n):
        print(f"  member {k + 1}: " + " ".join(f"{x:+8.2%}" for x in d[k]))
    print("  mean:     " + " ".join(f"{x:+8.2%}" for x in d.mean(axis=0)))
    print("  std. err: " + " ".join(f"{x:8.2%}" for x in d.std(axis=0, ddof=1) / np.sqrt(n)))
    print("  largest:  " + " ".join(f"{x:8.2%}" for x in np.abs(d).max(axis=0)))
EOF
