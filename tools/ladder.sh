#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The speed ladder (issue 29): runs one plate compression at V0, V0/2, V0/4, ... (at most RUNGS
# rungs) and stops at the first speed whose force-strain curve agrees with the next-faster one
# and whose plates balance (cellmech.ladder, tools/cellmech/quasistatic.py); prints the table of
# speeds and the chosen speed.
#   tools/ladder.sh cell   RESTART V0 LO HI [RUNGS] [-- LAMMPS ARGS]   in.compress from in.inflate's restart
#   tools/ladder.sh tissue RESTART V0 LO HI [RUNGS] [-- LAMMPS ARGS]   in.tissue-compress from in.tissue-inflate's
# LO, HI: the strain range judged (e.g. 0.05 0.20 for a cell, 0.02 0.15 for a tissue; the runs go
# to HI, and a run's range ends at its first wall rupture). LAMMPS ARGS pass on to every rung
# (e.g. -var lamf 0 -var Pi -100). Environment: NP ranks (1), LEVEL of the cell's model lengths
# (3; a tissue's come with its restart), EVERY steps between records (100), WORKDIR (ladder-KIND).
# Exit 0 with a chosen speed, 1 without one after RUNGS rungs.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$here/tools/common.sh"
usage() { sed -n 3,13p "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 5 ] || usage
kind=$1 restart_arg=$2 restart=$(realpath -m "$2") v0=$3 lo=$4 hi=$5
shift 5
rungs=4
if [ $# -gt 0 ] && [ "$1" != -- ]; then rungs=$1; shift; fi
if [ $# -gt 0 ]; then [ "$1" = -- ] || usage; shift; fi
case "$kind" in cell|tissue) ;; *) echo "ladder: KIND must be cell or tissue, got '$kind'" >&2; exit 2 ;; esac
[ -f "$restart" ] || { echo "ladder: no restart file '$restart_arg'" >&2; exit 2; }
[[ "$rungs" =~ ^[1-9][0-9]*$ ]] || { echo "ladder: RUNGS must be a whole number >= 1, got '$rungs'" >&2; exit 2; }
/usr/bin/python3 -c "import sys; v, lo, hi = map(float, sys.argv[1:]); sys.exit(not (v > 0 and 0 <= lo < hi < 1))" \
  "$v0" "$lo" "$hi" 2>/dev/null ||
  { echo "ladder: expected a speed V0 > 0 (m/s) and strains 0 <= LO < HI < 1, got '$v0' '$lo' '$hi'" >&2; exit 2; }
NP=${NP:-1}
EVERY=${EVERY:-100}
LMP=${LMP:-lmp}
[ -f "$here/build/cellmech-env.sh" ] && source "$here/build/cellmech-env.sh"
work=${WORKDIR:-ladder-$kind}
mkdir -p "$work"
cd "$work"

inputs=$here/lammps-inputs
if [ "$kind" = cell ]; then
  read -r s r0 f0 reach dt < <(level_params "${LEVEL:-3}" s r0 f0 reach dt)
  input=$inputs/in.compress
  model=(-var s "$s" -var r0 "$r0" -var f0 "$f0" -var reach "$reach" -var dt "$dt")
else
  # the tables and the leak count are costly and not judged here
  input=$inputs/in.tissue-compress
  model=(-var hold 0 -var leakevery 0 -var tabevery 1000000000)
fi

done_=()
for ((k = 0; k < rungs; k++)); do
  v=$(/usr/bin/python3 -c "print(f'{$v0 / 2 ** $k:.6g}')")
  rec=rung$k-v$v.dat
  echo "ladder: rung $k, $v m/s ..." >&2
  mpi_run "$NP" "$LMP" -in "$input" -log "log.rung$k" -screen none -var dir "$inputs" \
    -var restart "$restart" "${model[@]}" -var vplate "$v" -var strain "$hi" -var every "$EVERY" \
    -var out "$rec" "$@"
  done_+=("$v:$rec")
  [ "$k" -gt 0 ] || continue
  rc=0
  /usr/bin/python3 -m cellmech.ladder "$kind" "$lo" "$hi" "${done_[@]}" || rc=$?
  [ "$rc" -eq 0 ] && exit 0
  [ "$rc" -eq 10 ] || exit "$rc"
done
echo "ladder: no speed chosen after $rungs rungs (slowest $v m/s)" >&2
exit 1
