#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The runs of docs/studies/tissue-pair-stiffness.md: the glued pair and the single cell, inflated
# at Pi -364 kPa and compressed quasi-statically (in.tissue-compress, lamf 0) at two speeds.
#   OUT=/tmp/pair4x bash docs/studies/tissue-pair-stiffness.sh     (~10 min on 2 cores)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
source "$here/build/cellmech-env.sh"
source "$here/tools/common.sh"
out=$(realpath -m "${OUT:-$here/results/pair-stiffness}")
mkdir -p "$out" && cd "$out"
cp -r "$here/lammps-inputs" inputs      # a copy: LAMMPS reads its input as it runs
read -r NF < <(level_params 3 nfluid)
for c in "pair 1 1 2" "single 1 1 1"; do
  set -- $c; n=$1; shift
  mkdir -p "$n"
  (cd "$n" && /usr/bin/python3 "$here/tools/cellgen.py" tissue -o "$n.data" --lattice sc --n "$@" \
     --level 3 --nfluid "$NF" --stats "$n.json" > gen.txt &&
   "$LMP" -in ../inputs/in.tissue-inflate -screen none -var dir ../inputs -var data "$n.data" \
     -var Pi -364 -var every 1000 -var restart_out "$n.restart" > /dev/null)
done
for v in 0.25 0.125; do
  for n in pair single; do
    mkdir -p "$n-$v"
    (cd "$n-$v" && "$LMP" -in ../inputs/in.tissue-compress -screen none -var dir ../inputs \
       -var restart "../$n/$n.restart" -var Pi -364 -var lamf 0 -var vplate "$v" -var strain 0.12 \
       -var every 200 -var tabevery 4000 -var leakevery 0 > /dev/null) &
  done
  wait
done
