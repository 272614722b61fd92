#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Benchmark (not a test): how the cost of a tissue grows with its cells. Simple cubic blocks of
# 1, 8, 27 and 64 coarse cells (cellgen.py tissue, level 3: 642 wall nodes and ~440 fluid per cell,
# glued by the middle lamella) run the tissue force field (tissue-model.lmp: tethers, lamella,
# 8-4 contacts, SPH, virtual particles, osmosis) on 1 and on 2 MPI ranks. Each case first inflates
# for WARM steps (the first steps of inflation, at Lp 10), then a second run of NSTEPS is timed:
# particle-steps/s = atoms x steps / LAMMPS's loop time, and the same per cell. The cost per cell
# stays flat when cells/s (cell-steps per second) is the same for every size. LAMMPS's timing
# breakdown (Pair, Bond, Neigh, Comm, Modify) of each run is printed, with the machine and its load.
#
# Usage: tools/benchmark-tissue.sh [-n NSTEPS] [-w WARM] [-t SETTLE] [-s "1 2 3 4"] [-p "1 2"] [-o FILE]
#   -s   edge lengths of the blocks (cells = n^3), default "1 2 3 4"
#   -p   MPI rank counts, default "1 2"
#   -o   also write the report (markdown) to FILE
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
NSTEPS=1000
WARM=300
SETTLE=500
SIZES="1 2 3 4"
RANKS="1 2"
report=""
while [ $# -gt 0 ]; do
  case $1 in
    -n) NSTEPS=$2; shift 2 ;;
    -w) WARM=$2; shift 2 ;;
    -t) SETTLE=$2; shift 2 ;;
    -s) SIZES=$2; shift 2 ;;
    -p) RANKS=$2; shift 2 ;;
    -o) report=$(cd "$(dirname "$2")" && pwd)/$(basename "$2"); shift 2 ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) echo "benchmark-tissue: unknown argument $1 (see -h)" >&2; exit 2 ;;
  esac
done
if [ -z "${LMP:-}" ]; then
  [ -f "$here/build/cellmech-env.sh" ] || { echo "benchmark-tissue: run tools/setup.sh first" >&2; exit 1; }
  source "$here/build/cellmech-env.sh"
fi
source "$here/tools/common.sh"
py=/usr/bin/python3
# the coarse level-3 cell's fluid count and lengths: the level table (tools/cellmech/params.py)
read -r NF3 S3 R03 F03 REACH3 < <(level_params 3 nfluid s r0 f0 reach)
work=$(mktemp -d /tmp/cellmech-bench-tissue.XXXXXX)
trap 'rm -rf "$work"' EXIT
cd "$work"
out=$work/report.md
{
  echo "# Tissue benchmark"
  echo
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'),"\
    "load before the runs $(cut -d' ' -f1-3 /proc/loadavg); LAMMPS $($LMP -h | sed -n 's/^Large-scale.*- \(.*\)$/\1/p' | head -1)"
  echo "each case: in.tissue-inflate's $WARM steps of inflation (Lp 10, Pi -364 kPa) and $SETTLE of its settle,"\
    "then $NSTEPS timed steps (dt 0.001 us). neighbours/cell: glued neighbour cells (6 inside a large block);"\
    "builds: neighbour list builds in the timed steps"
  echo
  echo "| cells | neighbours/cell | atoms | ranks | particle-steps/s | cell-steps/s | per cell vs 1 cell | builds | Pair % | Bond % | Neigh % | Comm % | Modify % |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
} > "$out"
cat "$out"
declare -A base
for n in $SIZES; do
  $py "$here/tools/cellgen.py" tissue -o t$n.data --lattice sc --n $n $n $n --level 3 --nfluid $NF3 \
    "${wall_gen[@]}" --stats t$n.json > /dev/null
  read -r reach special nbc < <($py -c "import json; s = json.load(open('t$n.json'))
print(max($REACH3, s['triangle_quality']['recommended_reach']), s['extra_special_per_atom'], s['neighbours_mean'] if s['cells'] > 1 else 0)")
  cat > in.bench <<EOF
include $here/lammps-inputs/in.tissue-inflate
run $NSTEPS
EOF
  for np in $RANKS; do
    mpi_run "$np" "$LMP" -in in.bench -log log.$n.$np -screen none -var dir "$here/lammps-inputs" "${wall_vars[@]}" \
      -var data t$n.data -var special "$special" -var s $S3 -var r0 $R03 -var f0 $F03 \
      -var reach "$reach" -var nsteps "$WARM" -var nsettle "$SETTLE" -var every "$WARM" -var restart_out none.restart \
      -var out none.dat -var cells none-cells.dat
    row=$($py - "log.$n.$np" "$((n * n * n))" "$np" "${base[$np]:-0}" "$nbc" <<'PY'
import re, sys
log, cells, np_, base = open(sys.argv[1]).read(), int(sys.argv[2]), sys.argv[3], float(sys.argv[4])
nbc = float(sys.argv[5])
m = re.findall(r"Loop time of ([\d.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", log)[-1]
t, steps, atoms = float(m[0]), int(m[1]), int(m[2])
tail = log[log.rfind("MPI task timing breakdown"):]
pct = {k: float(re.search(rf"^{k}\s*\|.*\|\s*([\d.]+)\s*$", tail, re.M).group(1))
       for k in ("Pair", "Bond", "Neigh", "Comm", "Modify")}
rate, crate = atoms * steps / t, cells * steps / t
rel = f"{crate / base:.2f}" if base > 0 else "1.00"
builds = int(re.findall(r"Neighbor list builds = (\d+)", tail)[-1])
print(f"| {cells} | {nbc:.2g} | {atoms} | {np_} | {rate:.3g} | {crate:.4g} | {rel} | {builds} | "
      + " | ".join(f"{pct[k]:.1f}" for k in ("Pair", "Bond", "Neigh", "Comm", "Modify")) + " |")
print(crate)
PY
)
    echo "$row" | head -1 | tee -a "$out"
    [ -z "${base[$np]:-}" ] && base[$np]=$(echo "$row" | tail -1)
  done
done
echo >> "$out"
echo "load after the runs $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$out"
[ -n "$report" ] && cp "$out" "$report"
true
