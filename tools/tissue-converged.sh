#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Tissue compression at converged plate speeds (issue 29): a coarse block (cellgen.py tissue
# --lattice sc --n BLOCK --level 3; 2x2x2 by default) inflated at three turgors (Pi -100, -364, -600 kPa) with
# a strong and a weak middle lamella (named in tools/cellmech/params.py: `python3 -m cellmech.params
# lamella weak`; each block is inflated with the lamella it is compressed with: the inflated
# equilibrium depends on it), then
# compressed to failure (lamf 1.04) with in.tissue-compress's quasi-static protocol at two speeds,
# V and V/2 (the rate evidence), and a report (tools/cellmech/tissue/converged.py): converged
# modulus with its strain window, failure stress and strain, failure mode, the quasi-static check
# of each run and the curve of V against V/2, side by side with parenchyma measurements.
#   bash tools/tissue-converged.sh                 # results/tissue-converged (~20 min on 2 cores)
#   REPORT=docs bash tools/tissue-converged.sh     # the committed report: docs/tissue-quasistatic.md
#   BLOCK="3 3 3" STRAIN=0.15 RESPA=5 NAME=tissue-quasistatic-27 REPORT=docs bash tools/tissue-converged.sh
#                                                  # the 27-cell block (~75 min on 2 cores; respa 5
#                                                  # past rupture: docs/Howto_plates.rst)
#   EXP=tension OUT=results/tissue-converged REPORT=docs bash tools/tissue-converged.sh
#                                                  # the same blocks pulled apart (in.tissue-tension)
#                                                  # at 0.0625 and 0.125 m/s to 8% strain:
#                                                  # docs/tissue-tension-quasistatic.md
#   SEEDS="--random 27 --lloyd 5 --seed 4" STRAIN=0.15 RESPA=5 NAME=tissue-quasistatic-random-27 \
#     REPORT=docs bash tools/tissue-converged.sh   # a random Laguerre block (~2.5 h on 2 cores)
# Environment: EXP (compress or tension: in.tissue-EXP, stages EXP-PI-LAM-V; the inflations are
# shared), OUT (run folder), BLOCK (cells along x y z, "2 2 2"), SEEDS (cellgen.py tissue's seeding
# and shape options in place of the lattice block, e.g. the random Laguerre block
# "--random 27 --lloyd 5 --seed 4", docs/cellgen.rst), V (fast speed, m/s, default
# 0.5, tension 0.125: it converges only at 0.0625 m/s, docs/Howto_tissue.rst), STRAIN (0.2, tension 0.08), RESPA (inner wall steps per fluid step, in.tissue-compress -var respa; 1),
# LEVEL (the cells' wall resolution, cellgen.py --level: 3, coarse; 4, the paper's), LAMF (the walls'
# critical stretch; unset: the inputs' default, the paper's; 0: they never rupture, e.g. for a time
# to solution), NP (MPI ranks per run, 1), JOBS (runs at a time, 2), NAME (the report's file name,
# tissue-quasistatic, tension: tissue-tension-quasistatic), ONLY (space-separated stage names: gen, inflate-PI-LAM, compress-PI-LAM-V, report),
# PIS (turgors, default "-100 -364 -600"), SPEEDS (default "V/2 V"), JAWS and GRIP (what the grips
# hold, in.tissue-tension's and in.tissue-compress's -var jaws and grip; JAWS=cells GRIP=10 holds
# the 27-cell block's end layers whole and refers the strain to the middle layer; a compression
# with JAWS=cells has no plates, and goes in a run folder of its own: its stages are named as the
# plates'; it runs on one level, RESPA=1). A condition that has not
# converged gets the next rung into the same folder, e.g.
#   OUT=... PIS=-100 SPEEDS=0.125 ONLY="compress-100-strong-0.125 compress-100-weak-0.125 report"
# and the report judges each condition on the two slowest speeds it finds (V/2 against V).
# Each run's folder gets settings.json (every -var it was given and the defaults that applied; the
# report reads the lamellae from there).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[ -f "$here/build/cellmech-env.sh" ] || bash "$here/tools/setup.sh"
source "$here/build/cellmech-env.sh"
source "$here/tools/common.sh"
EXP=${EXP:-compress}
case $EXP in
  compress) V=${V:-0.5}; STRAIN=${STRAIN:-0.2}; NAME=${NAME:-tissue-quasistatic} ;;
  tension) V=${V:-0.125}; STRAIN=${STRAIN:-0.08}; NAME=${NAME:-tissue-tension-quasistatic} ;;
  *) echo "tissue-converged.sh: EXP=$EXP: expected compress or tension" >&2; exit 1 ;;
esac
BLOCK=${BLOCK:-"2 2 2"}
RESPA=${RESPA:-1}
LAMF=${LAMF:-}
if [ "$EXP" = tension ] && [ "$RESPA" != 1 ]; then
  echo "tissue-converged.sh: RESPA=$RESPA: in.tissue-tension runs on one level (respa is not safe past the lamella's first failures)" >&2
  exit 1
fi
NP=${NP:-1}
JOBS=${JOBS:-2}
out=$(realpath -m "${OUT:-$here/results/tissue-converged}")
report=${REPORT:-$out}
[ "$report" = docs ] && report=$here/docs
INPUTS=$here/lammps-inputs
py=/usr/bin/python3
mkdir -p "$out"
cd "$out"
want() { [ -z "${ONLY:-}" ] || [[ " $ONLY " == *" $1 "* ]]; }
# stage NAME CMD...: in its own folder, its wall time in times.txt
stage() {
  local name=$1; shift
  want "$name" || return 0
  local t0 rc=0; t0=$(date +%s)
  mkdir -p "$out/$name"
  (cd "$out/$name" && "$@") || rc=$?
  echo "$name $(( $(date +%s) - t0 )) $([ $rc -eq 0 ] && echo ok || echo "failed(rc=$rc)")" >> "$out/times.txt"
  [ $rc -eq 0 ] || echo "  $name failed, see $out/$name/log.lammps" >&2
}
bg() { while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n || true; done; stage "$@" & }
# the named lamellae (tools/cellmech/params.py): sigl (kPa) and Gl (pg/us^2) of each
declare -A SIGL GL
for lam in strong weak; do read -r "SIGL[$lam]" "GL[$lam]" < <($py -m cellmech.params lamella $lam sigl Gl); done
PIS=${PIS:-"-100 -364 -600"}
LEVEL=${LEVEL:-3}
read -r NF < <(level_params "$LEVEL" nfluid)
SEEDS=${SEEDS:-"--lattice sc --n $BLOCK"}
# shellcheck disable=SC2086  # SEEDS is a list of cellgen options
gen() { $py "$here/tools/cellgen.py" tissue -o block.data $SEEDS --level "$LEVEL" --nfluid "$NF" \
          --stats block.json > block.txt; }
stage gen gen
# lmp ARGS...: a LAMMPS run, its effective settings first written to ./settings.json
lmp() { $py -m cellmech.params settings -- "$@" && mpi_run "$NP" "$LMP" "$@"; }
infl() {  # PI LAM
  lmp -in "$INPUTS/in.tissue-inflate" -screen none -var dir "$INPUTS" -var data "$out/gen/block.data" \
    -var Pi "$1" -var sigl "${SIGL[$2]}" -var Gl "${GL[$2]}" -var every 1000 -var restart_out block.restart
}
for pi in $PIS; do for lam in strong weak; do bg "inflate$pi-$lam" infl "$pi" "$lam"; done; done
wait
comp() {  # PI LAM SPEED
  lmp -in "$INPUTS/in.tissue-compress" -screen none -var dir "$INPUTS" \
    -var restart "$out/inflate$1-$2/block.restart" -var Pi "$1" -var sigl "${SIGL[$2]}" -var Gl "${GL[$2]}" \
    ${LAMF:+-var lamf "$LAMF"} -var vplate "$3" -var strain "$STRAIN" -var respa "$RESPA" -var every 200 -var tabevery 4000 \
    -var leakevery 0 ${JAWS:+-var jaws "$JAWS"} ${GRIP:+-var grip "$GRIP"}
}
pull() {  # PI LAM SPEED
  lmp -in "$INPUTS/in.tissue-tension" -screen none -var dir "$INPUTS" \
    -var restart "$out/inflate$1-$2/block.restart" -var Pi "$1" -var sigl "${SIGL[$2]}" -var Gl "${GL[$2]}" \
    ${LAMF:+-var lamf "$LAMF"} -var vpull "$3" -var strain "$STRAIN" -var every 200 -var tabevery 4000 \
    ${JAWS:+-var jaws "$JAWS"} ${GRIP:+-var grip "$GRIP"}
}
declare -A run_of=([compress]=comp [tension]=pull)
half=$($py -c "print($V / 2)")
SPEEDS=${SPEEDS:-"$half $V"}
for v in $SPEEDS; do for pi in $PIS; do for lam in strong weak; do
  bg "$EXP$pi-$lam-$v" "${run_of[$EXP]}" "$pi" "$lam" "$v"
done; done; done
wait
# what ran, appended for each call that compressed or pulled (the report prints it)
if [ -z "${ONLY:-}" ] || [[ "$ONLY" == *"$EXP"* ]]; then
  echo "$([ "$EXP" = tension ] && echo "EXP=tension ")$([ "$LEVEL" = 3 ] || echo "LEVEL=$LEVEL ")${JAWS:+JAWS=$JAWS }${GRIP:+GRIP=$GRIP }BLOCK='$BLOCK' ${SEEDS:+SEEDS='$SEEDS' }${LAMF:+LAMF=$LAMF }STRAIN=$STRAIN SPEEDS='$SPEEDS' PIS='$PIS' RESPA=$RESPA NP=$NP on $(nproc) cores, $(date -u '+%Y-%m-%d %H:%M UTC')" >> run-info.txt
fi
if want report; then
  mkdir -p "$report"
  (cd "$here/tools" && $py -m cellmech.tissue.converged "$out" "$report" "$NAME" "$EXP")
fi
