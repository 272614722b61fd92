#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Benchmark (not a test): how the cost of a tissue grows with its cells, and how it divides over
# MPI ranks. Simple cubic blocks of 1, 8, 27 and 64 coarse cells (cellgen.py tissue, level 3: 642
# wall nodes and ~440 fluid per cell, glued by the middle lamella) run the tissue force field
# (tissue-model.lmp: tethers, lamella, 8-4 contacts, SPH, virtual particles, osmosis) on 1 and on 2
# MPI ranks. Each case first inflates for WARM steps (the first steps of inflation, at Lp 10) and
# settles for SETTLE, then a run of NSTEPS is timed: particle-steps/s = atoms x steps / LAMMPS's
# loop time, and the same per cell. The cost per cell stays flat when cells/s (cell-steps per
# second) is the same for every size.
# A notched sample (27 cells in an L, cellgen.py tissue --remove-box) leaves half of its box empty:
# it runs with LAMMPS's even split and with load balancing (tissue-model.lmp's -var balance: the
# commands balance and fix balance, shift xyz). The report (tools/cellmech/scaling.py) gives the
# machine and its load, LAMMPS's timing breakdown of every run, speed-up and parallel efficiency,
# for each run on more than one rank the per-rank timing (min / avg / max over the ranks) and
# particle counts, and a projection on paper of a 1000-cell tissue on 64 and 256 ranks from the
# measured costs.
#
# Usage: tools/benchmark-tissue.sh [-n NSTEPS] [-w WARM] [-t SETTLE] [-s "1 2 3 4"] [-p "1 2"]
#                                  [-b "0 1.1"] [-r REPEAT] [-k] [-o FILE]
#   -s   edge lengths of the blocks (cells = n^3), default "1 2 3 4"
#   -p   MPI rank counts, default "1 2"
#   -b   balance thresholds of the notched sample (0: even split), default "0 1.1"; "" skips it
#   -r   runs of each case, the fastest kept (default 1)
#   -k   keep the work folder (data files and LAMMPS logs) and print its path
#   -o   also write the report (markdown) to FILE
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
NSTEPS=1000
WARM=300
SETTLE=500
SIZES="1 2 3 4"
RANKS="1 2"
NOTCH="0 1.1"
REPEAT=1
keep=0
report=""
while [ $# -gt 0 ]; do
  case $1 in
    -n) NSTEPS=$2; shift 2 ;;
    -w) WARM=$2; shift 2 ;;
    -t) SETTLE=$2; shift 2 ;;
    -s) SIZES=$2; shift 2 ;;
    -p) RANKS=$2; shift 2 ;;
    -b) NOTCH=$2; shift 2 ;;
    -r) REPEAT=$2; shift 2 ;;
    -k) keep=1; shift ;;
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
if [ "$keep" = 1 ]; then echo "benchmark-tissue: work folder $work" >&2
else trap 'rm -rf "$work"' EXIT; fi
cd "$work"
load0=$(cut -d' ' -f1-3 /proc/loadavg)
cat > in.bench <<EOF
include $here/lammps-inputs/in.tissue-inflate
run $NSTEPS
EOF
# run CASE NP BALANCE: REPEAT timed runs of CASE.data; the log of the fastest is kept as
# log.CASE.NP.BALANCE (the others only guard against a machine that was busy for a while)
run() {
  local case=$1 np=$2 bal=$3 reach special r best=""
  read -r reach special < <($py -c "import json; s = json.load(open('$case.json'))
print(max($REACH3, s['triangle_quality']['recommended_reach']), s['extra_special_per_atom'])")
  for r in $(seq "$REPEAT"); do
    echo "  $case on $np rank(s), balance $bal, run $r of $REPEAT" >&2
    mpi_run "$np" "$LMP" -in in.bench -log "try.$r" -screen none -var dir "$here/lammps-inputs" \
      "${wall_vars[@]}" -var data "$case.data" -var special "$special" -var s $S3 -var r0 $R03 -var f0 $F03 \
      -var reach "$reach" -var nsteps "$WARM" -var nsettle "$SETTLE" -var every "$WARM" -var balance "$bal" \
      -var restart_out none.restart -var out none.dat -var cells none-cells.dat
    if [ -z "$best" ] || awk -v a="$(awk '/^Loop time of/ {t = $4} END {print t}' "try.$r")" \
        -v b="$(awk '/^Loop time of/ {t = $4} END {print t}' "$best")" 'BEGIN {exit !(a < b)}'; then
      best=best.log
      cp "try.$r" "$best"
    fi
  done
  mv "$best" "log.$case.$np.$bal"
  rm -f try.*
}
for n in $SIZES; do
  $py "$here/tools/cellgen.py" tissue -o block$n.data --lattice sc --n $n $n $n --level 3 --nfluid $NF3 \
    "${wall_gen[@]}" --stats block$n.json > /dev/null
  for np in $RANKS; do run block$n "$np" 0; done
done
if [ -n "$NOTCH" ]; then
  # 27 cells in an L (a notched sample): a 5 x 3 x 5 block less the 4 x 3 x 4 corner above its
  # first layer, so that an even split of the box gives one rank the long arm and the corner
  $py "$here/tools/cellgen.py" tissue -o notch.data --lattice sc --n 5 3 5 --level 3 --nfluid $NF3 \
    "${wall_gen[@]}" --remove-box 1 1e9 -1 1e9 1 1e9 --stats notch.json > /dev/null
  for np in $RANKS; do
    for bal in $NOTCH; do
      [ "$np" -eq 1 ] && [ "$bal" != 0 ] && continue    # one rank has nothing to balance
      run notch "$np" "$bal"
    done
  done
fi
PYTHONPATH="$here/tools" $py -m cellmech.scaling "$work" --steps "$NSTEPS" --warm "$WARM" --settle "$SETTLE" \
  --load-before "$load0" --load-after "$(cut -d' ' -f1-3 /proc/loadavg)" --lammps "$($LMP -h | sed -n 's/^Large-scale.*- \(.*\)$/\1/p' | head -1)" > report.md
cat report.md
[ -n "$report" ] && cp report.md "$report"
true
