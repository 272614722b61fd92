#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Benchmark (not a test): particle-steps per second of
#   (a) cell/full    the full cell at the paper's resolution (2562 wall nodes + 3527 fluid),
#                    lammps-inputs/in.inflate with its cell-model.lmp, 2000 steps, once for each
#                    wall of WALLS (same cell, same run: the cost of each wall side by side);
#   (b) stock-sph    the same 3527 fluid particles alone with stock LAMMPS SPH
#                    (pair sph/taitwater/morris + fix sph), tools/bench/in.stock-sph;
#   (c) cell/sph     the same particles with our pair cell/sph + fix cell/fluid Pi 0 Lp 0,
#                    tools/bench/in.cell-sph;
#   (d) respa        time to solution of the paper-resolution compression to 20% strain,
#                    single-level against run_style respa (tools/bench/respa.sh, a few minutes;
#                    RESPA=0 skips it, RESPA_REPEAT runs per scheme, default 1);
#   (e) tissue       strong scaling of the 8- and 27-cell coarse tissue blocks from 1 to 2 ranks, with
#                    LAMMPS's timing per rank and the projection to a 1000-cell tissue on 64 and
#                    256 ranks (tools/benchmark-tissue.sh -s "2 3" -p "1 2", a minute; TISSUE=0 skips
#                    it; the full study with more blocks and load balancing: that script alone);
#   (f) collectives  the global reductions a wall that can fail adds per step (target 6): the full
#                    cell of (a), tether wall, NCOLL steps (default 400) on 2 ranks, with lamf 0 (it
#                    cannot fail) and lamf 1.5 (it can, nothing does); rank 0's MPI_Allreduce calls
#                    counted through MPI's profiling interface (build/tests/cellmech_mpi_count.so,
#                    tests/unit/mpi_count.cpp; COLLECTIVES=0 skips it).
# Threads (issue 12, target 5): measured with a prototype and not kept (docs/performance.md), so
# there is no OpenMP case.
# (b) and (c) read exactly the fluid of the generated cell.data (lattice spacing 3.01 um, clipped
# inside the wall) in its fixed box, with rho0 1, c 264.6, viscosity 1 mPa s, cutoff 2s = 6.4 um
# (stock takes it as its h), dt 0.001 us, units micro, no wall, no turgor, no osmosis; the script
# checks that their "Ave neighs/atom" agree. Rates are atoms * steps / loop time from LAMMPS's
# "Loop time" line (the figure behind its "Matom-step/s"); each case runs REPEAT times and the
# fastest run is kept (the other runs only guard against a busy machine). On a shared machine the
# wall-clock rate also measures the others' load, so the table adds the rate per CPU second
# (loop time x LAMMPS's "% CPU use": the time the rank actually ran), the best over the runs of a
# case, and its ratio to stock. Memory: LAMMPS's "Per MPI rank memory allocation" (average over
# ranks, MiB as LAMMPS counts them) x ranks / atoms, in bytes per particle.
#
# Usage: tools/benchmark.sh [-np N] [-r REPEAT] [-n NSTEPS] [-k]
#   -np N      MPI ranks (N > 1 runs it through mpi_run, tools/common.sh)
#   -r REPEAT  runs per case (default 3)
#   -n NSTEPS  steps per run (default 2000)
#   -k         keep the work folder (data files and LAMMPS logs) and print its path
# Environment: LMP (else build/cellmech-env.sh is sourced), NP, REPEAT, NSTEPS, PYTHON, WALLS (the
#   walls of the full cell, lammps-inputs/cell-wall.lmp; default "tether membrane bending", or
#   WALL alone when WALL is set).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
NP=${NP:-1}
REPEAT=${REPEAT:-3}
NSTEPS=${NSTEPS:-2000}
PYTHON=${PYTHON:-/usr/bin/python3}
keep=0
while [ $# -gt 0 ]; do
  case $1 in
    -np) NP=$2; shift 2 ;;
    -r) REPEAT=$2; shift 2 ;;
    -n) NSTEPS=$2; shift 2 ;;
    -k) keep=1; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) echo "benchmark: unknown argument $1 (see -h)" >&2; exit 2 ;;
  esac
done
if [ -z "${LMP:-}" ]; then
  [ -f "$here/build/cellmech-env.sh" ] || { echo "benchmark: no build/cellmech-env.sh: run tools/setup.sh" >&2; exit 1; }
  # shellcheck disable=SC1091
  source "$here/build/cellmech-env.sh"
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
user_wall=${WALL:-}     # common.sh gives WALL its default
source "$here/tools/common.sh"
inputs=$here/lammps-inputs
bench=$here/tools/bench

load0=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?")
work=$(mktemp -d "${TMPDIR:-/tmp}/cellmech-bench.XXXXXX")
if [ "$keep" = 1 ]; then trap 'echo "benchmark: work folder kept: $work"' EXIT
else trap 'rm -rf "$work"' EXIT; fi
cd "$work"

# ---- the cell and its fluid ----------------------------------------------------------------------
read -r NF4 R04 < <(level_params 4 nfluid r0)
gen=$("$PYTHON" "$here/tools/cellgen.py" cell -o cell.data --level 4 --nfluid "$NF4" --inset "$R04")
# the same cell with the hinges of the bending wall (cellgen is deterministic: the same particles)
"$PYTHON" "$here/tools/cellgen.py" cell -o cell-bending.data --level 4 --nfluid "$NF4" --inset "$R04" \
  --bending > /dev/null
spacing=$(sed -n 's/.*spacing \([0-9.eE+-]*\),.*/\1/p' <<<"$gen" | head -n1)
# the fluid (type 2) of cell.data, in its box, as data files for atom_style sph and molecular
awk '
  /xlo xhi|ylo yhi|zlo zhi/ {box = box $0 "\n"; next}
  /^Masses/ {sec = "m"; next}
  /^Atoms/ {sec = "a"; next}
  /^[A-Z]/ {sec = ""; next}
  sec == "m" && NF == 2 && $1 == 2 {m = $2}
  sec == "a" && NF >= 6 && $3 == 2 {n++; x[n] = $4; y[n] = $5; z[n] = $6}
  END {
    hdr = n " atoms\n1 atom types\n\n" box "\nMasses\n\n1 " m "\n\n"
    f = "fluid-sph.data"
    printf "fluid of cell.data for stock SPH\n\n%sAtoms # sph\n\n", hdr > f
    for (i = 1; i <= n; i++) print i, 1, 1.0, 0.0, 1.0, x[i], y[i], z[i] > f
    f = "fluid-cell.data"
    printf "fluid of cell.data for cell/sph\n\n%sAtoms # molecular\n\n", hdr > f
    for (i = 1; i <= n; i++) print i, 1, 1, x[i], y[i], z[i] > f
    print m > "fluid.mass"; print n > "fluid.count"
  }' cell.data
mfluid=$(cat fluid.mass)
nfluid=$(cat fluid.count)

# ---- runs --------------------------------------------------------------------------------------
lmp() { mpi_run "$NP" "$LMP" "$@"; }
# field of the last "Loop time of T on P procs for S steps with N atoms" line: 4 T, 9 S, 12 N
loopf() { awk -v k="$2" '/^Loop time of/ {v = $k} END {print v}' "$1"; }
neighs() { awk '/^Ave neighs\/atom/ {v = $4} END {print v}' "$1"; }
cpuuse() { awk '/% CPU use with/ {v = $1} END {print v}' "$1"; }
builds() { awk '/^Neighbor list builds/ {v = $5} END {print v}' "$1"; }
# seconds the rank ran during the loop: loop time x "% CPU use" / 100
cpuloop() { awk '/^Loop time of/ {t = $4} /% CPU use with/ {c = $1 + 0} END {printf "%.6g", t * c / 100}' "$1"; }
# bytes per atom: "Per MPI rank memory allocation (min/avg/max) = a | b | c Mbytes" (avg) x ranks / atoms
mempp() { awk -v np="$NP" '/^Per MPI rank memory allocation/ {m = $(NF - 3)} /^Loop time of/ {n = $12}
  END {printf "%.0f", m * 1048576 * np / n}' "$1"; }

declare -A best log bestcpu
run_case() {   # name, then LAMMPS arguments
  local name=$1; shift
  local r t
  for r in $(seq 1 "$REPEAT"); do
    if ! lmp -nocite -log "$name.$r.log" -screen none "$@" >"$name.$r.out" 2>&1 || ! grep -q '^Loop time of' "$name.$r.log"; then
      echo "benchmark: case $name failed (LAMMPS output follows)" >&2
      tail -n 30 "$name.$r.out" "$name.$r.log" >&2 || true
      exit 1
    fi
    t=$(loopf "$name.$r.log" 4)
    local c; c=$(cpuloop "$name.$r.log")
    if [ -z "${bestcpu[$name]:-}" ] || awk -v a="$c" -v b="${bestcpu[$name]}" 'BEGIN {exit !(a < b)}'; then
      bestcpu[$name]=$c
    fi
    if [ -z "${best[$name]:-}" ] || awk -v a="$t" -v b="${best[$name]}" 'BEGIN {exit !(a < b)}'; then
      best[$name]=$t; log[$name]=$name.$r.log
    fi
  done
}

run_case stock-sph -in "$bench/in.stock-sph" -var data fluid-sph.data -var nsteps "$NSTEPS"
run_case cell-sph -in "$bench/in.cell-sph" -var data fluid-cell.data -var m "$mfluid" -var nsteps "$NSTEPS"
WALLS=${WALLS:-${user_wall:-tether membrane bending}}
full=()
for w in $WALLS; do
  case $w in tether|membrane|bending) ;; *) echo "benchmark: WALLS: unknown wall '$w' (tether, membrane or bending)" >&2; exit 2 ;; esac
  d=cell.data; [ "$w" = bending ] && d=cell-bending.data
  run_case "cell-full-$w" -in "$inputs/in.inflate" -var dir "$inputs" -var wall "$w" -var data "$d" \
    -var nsteps "$NSTEPS" -var every 1000 -var out "inflate-$w.dat" -var restart_out "inflated-$w.restart"
  full+=("cell-full-$w")
done

# ---- report ------------------------------------------------------------------------------------
cpu=$(awk -F': *' '/^model name/ {print $2; exit}' /proc/cpuinfo 2>/dev/null || true)
[ -n "$cpu" ] || cpu=$(lscpu 2>/dev/null | awk -F': *' '/Model name/ {print $2; exit}')
ver=$(awk '/^LAMMPS \(/ {print; exit}' "${log[stock-sph]}")
ref=$(awk -v n="$(loopf "${log[stock-sph]}" 12)" -v s="$(loopf "${log[stock-sph]}" 9)" \
  -v t="${best[stock-sph]}" 'BEGIN {printf "%.6e", n * s / t}')

echo "cellmech benchmark: $ver, $NP MPI rank(s), best of $REPEAT run(s) per case"
echo "machine: $(uname -n), nproc $(nproc), CPU: ${cpu:-unknown}"
load1=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?")
echo "load average (1 min) before / after: $load0 / $load1 (other work on the machine slows every case)"
echo "uptime: $(uptime)"
echo "cell: ${gen%%$'\n'*}"
echo "fluid-only cases: the $nfluid fluid particles of that cell (spacing $spacing um, mass $mfluid pg), no wall"
echo
refc=$(awk -v n="$(loopf "${log[stock-sph]}" 12)" -v s="$(loopf "${log[stock-sph]}" 9)" \
  -v t="${bestcpu[stock-sph]}" 'BEGIN {printf "%.6e", n * s / t}')
printf '%-30s %7s %6s %10s %17s %9s %12s %9s %12s %7s %6s %8s\n' case atoms steps "loop (s)" "particle-steps/s" "vs stock" "per CPU-s" "vs stock" "neighs/atom" builds "CPU" "B/atom"
for name in stock-sph cell-sph "${full[@]}"; do
  f=${log[$name]}
  case $name in
    stock-sph) label="(b) stock sph/taitwater/morris" ;;
    cell-sph) label="(c) cell/sph + cell/fluid" ;;
    cell-full-*) label="(a) full cell, ${name#cell-full-} wall" ;;
  esac
  nb=$(neighs "$f"); [ "${name#cell-full}" != "$name" ] && nb="-"   # hybrid/overlay: LAMMPS prints 0
  awk -v l="$label" -v n="$(loopf "$f" 12)" -v s="$(loopf "$f" 9)" -v t="${best[$name]}" \
    -v ref="$ref" -v nb="$nb" -v b="$(builds "$f")" -v cpu="$(cpuuse "$f")" \
    -v tc="${bestcpu[$name]}" -v refc="$refc" -v mem="$(mempp "$f")" 'BEGIN {
      r = n * s / t; rc = n * s / tc
      printf "%-30s %7d %6d %10.3f %17.4e %9.3f %12.4e %9.3f %12s %7s %6s %8s\n", l, n, s, t, r, r / ref, rc, rc / refc, nb, b, cpu, mem }'
done
for name in "${full[@]}"; do
  awk -v l="${name#cell-full-}" -v n="$nfluid" -v s="$(loopf "${log[$name]}" 9)" -v t="${best[$name]}" \
    -v ref="$ref" -v t0="${best[${full[0]}]}" -v l0="${full[0]#cell-full-}" \
    -v c="${bestcpu[$name]}" -v c0="${bestcpu[${full[0]}]}" 'BEGIN {
    r = n * s / t
    printf "(a) %s wall, counting its %d fluid particles only: %.4e fluid-particle-steps/s, %.3f x stock SPH; time per step %.3f x the %s wall (CPU time per step %.3f x)\n", l, n, r, r / ref, t / t0, l0, c / c0 }'
done
echo
echo "CPU: LAMMPS's \"% CPU use\" of the kept run; well under 100% means the rank waited for the CPU."
echo "per CPU-s: particle-steps per second the rank ran (best run of each case); B/atom: memory per particle."
echo "LAMMPS timing breakdown of the kept runs (% of loop time):"
for name in stock-sph cell-sph "${full[@]}"; do
  awk -v l="$name" '/^Section \|/ {on = 1; next} on && /^-+$/ {next}
    on && NF >= 2 && $2 == "|" {out = out sprintf(" %s %s", $1, $NF)} on && /^Other/ {on = 0}
    END {printf "  %-10s%s\n", l, out}' "${log[$name]}"
done
nb=$(neighs "${log[stock-sph]}"); nc=$(neighs "${log[cell-sph]}")
if [ "$nb" = "$nc" ]; then
  echo "neighbour check: stock-sph and cell-sph both have Ave neighs/atom = $nb (same lattice, same cutoff 6.4 + skin 0.5)"
else
  echo "neighbour check: MISMATCH: stock-sph Ave neighs/atom = $nb, cell-sph = $nc" >&2
  exit 1
fi
if [ "${RESPA:-1}" != 0 ]; then
  echo
  NP=$NP PYTHON=$PYTHON bash "$bench/respa.sh" "$work/respa" "${RESPA_REPEAT:-1}"
fi
if [ "${TISSUE:-1}" != 0 ]; then
  echo
  echo "(e) tissue on MPI: the 8- and 27-cell coarse blocks, 1 and 2 ranks, best of $REPEAT"
  PYTHON=$PYTHON bash "$here/tools/benchmark-tissue.sh" -s "2 3" -p "1 2" -b "" -r "$REPEAT"
fi
if [ "${COLLECTIVES:-1}" != 0 ]; then
  echo
  counter=${CELLMECH_MPI_COUNT_LIB:-$here/build/tests/cellmech_mpi_count.so}
  ncoll=${NCOLL:-400}
  if [ -f "$counter" ]; then
    echo "(f) global reductions per step (target 6): the full cell, tether wall, $ncoll steps on 2 ranks; rank 0's MPI_Allreduce calls"
    for lamf in 0 1.5; do
      mpi_run 2 env LD_PRELOAD="$counter" CELLMECH_MPI_COUNT="$work/count.$lamf" "$LMP" -nocite \
        -log "coll.$lamf.log" -screen none -in "$inputs/in.inflate" -var dir "$inputs" -var wall tether \
        -var data cell.data -var nsteps "$ncoll" -var every 100 -var out "coll-$lamf.dat" \
        -var restart_out "coll-$lamf.restart" -var lamf "$lamf" >"coll.$lamf.out" 2>&1 ||
        { echo "benchmark: case (f) failed" >&2; tail -n 20 "coll.$lamf.out" >&2; exit 1; }
    done
    read -r c0 _ < "$work/count.0.0"
    read -r c1 _ < "$work/count.1.5.0"
    awk -v c0="$c0" -v c1="$c1" -v n="$ncoll" -v b="$(builds coll.1.5.log)" 'BEGIN {
      printf "  lamf 0 (cannot fail): %d calls, %.2f per step\n", c0, c0 / n
      printf "  lamf 1.5 (can fail, nothing does): %d calls, %d more over %d steps with %d neighbour builds (%.3f per step; the former failure check: 1 per step)\n", c1, c1 - c0, n, b, (c1 - c0) / n }'
  else
    echo "(f) skipped: no $counter (it is built with the tests: cmake --build build)"
  fi
fi
