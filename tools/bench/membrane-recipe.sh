#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Study (not a test, not timed): the membrane wall squeezed between plates against the membrane
# model (tools/membrane.py) with everything this model's reference assumes, one step beyond the
# validation suite's case 5 (docs/membrane.rst, "Tension-field wall and stiff contact"):
#   - the tension-field wall (-var wrinkle yes, Eq. M3): the reference's membrane carries no
#     compression;
#   - a fluid-wall contact F0_SCALE times the model's f0: the reference's contents have the Tait
#     fluid's compressibility, the model's contact layer is about 4.5 times as compliant at level 4;
#   - turgors below the first reached by letting the cell down from it by osmosis
#     (tools/bench/in.letdown), a state that settles, where a cell pumped up to a low turgor does
#     not;
#   - the plates at VPLATE, slower than the suite's 0.5 m/s (the low-turgor small-strain force is
#     rate dependent there).
# Prints, per turgor, the plate force (mean of both plates, windows of +-1% strain as case 5 at
# level 4) against the membrane model at the cell's own turgid pressure, and the volume changes.
#   LMP=... LAMMPS_PLUGIN_PATH=... bash tools/bench/membrane-recipe.sh WORKDIR
# Environment: LEVEL (4), TURGORS (kPa, the first the highest: "364 300 30 3"), VPLATE (m/s,
# 0.125), STRAIN (0.22), WRINKLE (yes), F0_SCALE (10), INFLATE and LETDOWN (us, 20 each), JOBS
# (compressions at once, 2), PYTHON.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=${1:?usage: membrane-recipe.sh WORKDIR}
LEVEL=${LEVEL:-4}
TURGORS=${TURGORS:-364 300 30 3}
VPLATE=${VPLATE:-0.125}
STRAIN=${STRAIN:-0.22}
WRINKLE=${WRINKLE:-yes}
F0_SCALE=${F0_SCALE:-10}
INFLATE=${INFLATE:-20}
LETDOWN=${LETDOWN:-20}
JOBS=${JOBS:-2}
PYTHON=${PYTHON:-/usr/bin/python3}
source "$here/tools/common.sh"
inputs=$here/lammps-inputs
mkdir -p "$work"
cd "$work"
read -r nf s r0 f0 reach dt < <(level_params "$LEVEL" nfluid s r0 f0 reach dt)
f0=$("$PYTHON" -c "print($f0 * $F0_SCALE)")
model=(-var dir "$inputs" -var s "$s" -var r0 "$r0" -var f0 "$f0" -var reach "$reach" -var dt "$dt"
  -var wall membrane -var wrinkle "$WRINKLE")
steps() { "$PYTHON" -c "print(round($1 / $dt))"; }
"$PYTHON" "$here/tools/cellgen.py" cell -o cell.data --level "$LEVEL" --nfluid "$nf" --inset "$r0" > /dev/null
run() {    # run LOG ARGS...: one LAMMPS run, its log shown if it fails
  local log=$1
  shift
  "$LMP" -nocite -log "$log" -screen none "${model[@]}" "$@" > "${log%.log}.out" 2>&1 ||
    { echo "membrane-recipe.sh: run failed: $*" >&2; tail -n 20 "$log" >&2; exit 1; }
}
read -r top rest <<< "$TURGORS"
run "inflate-$top.log" -in "$inputs/in.inflate" -var data cell.data -var Pi "-$top" \
  -var nsteps "$(steps "$INFLATE")" -var every 1000 -var out "inflate-$top.dat" \
  -var restart_out "turgid-$top.restart"
for P in $rest; do
  run "letdown-$P.log" -in "$here/tools/bench/in.letdown" -var restart "turgid-$top.restart" \
    -var Pi "-$P" -var nsteps "$(steps "$LETDOWN")" -var out "letdown-$P.dat" \
    -var restart_out "turgid-$P.restart"
done
for P in $TURGORS; do
  run "compress-$P.log" -in "$inputs/in.compress" -var restart "turgid-$P.restart" \
    -var vplate "$VPLATE" -var strain "$STRAIN" -var every 400 -var out "compress-$P.dat" &
  while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n; done
done
wait
PYTHONPATH=$here/tools "$PYTHON" - "$LEVEL" $TURGORS <<'PY'
import sys

import numpy as np

from cellmech.validation import analysis, references as ref
from cellmech.validation.cases import COMPRESS_STRAINS, membrane_reference, window_half
from cellmech.validation.common import C_PHYS, RHO0

level, turgors = int(sys.argv[1]), sys.argv[2:]
print(f"membrane wall, level {level}: force vs the membrane model at strain "
      + " / ".join(f"{s:g}" for s in COMPRESS_STRAINS) + " (windows +-"
      f"{window_half(level):g}); volume change at the last of them")
for P in turgors:
    a = np.loadtxt(f"compress-{P}.dat", ndmin=2)    # step t eps Ftop Fbot Feq P broken leak V Vf
    P0 = a[0, 6]
    F = analysis.windowed(a[:, 2], 0.5 * (a[:, 3] + a[:, 4]), COMPRESS_STRAINS, window_half(level))
    mem, why, dv = membrane_reference(P0, list(COMPRESS_STRAINS), ref.tait_density(P0, RHO0, C_PHYS),
                                      volumes=True)
    if mem is None:
        print(f"P = {P} kPa: no reference ({why})")
        continue
    k = int(np.argmin(abs(a[:, 2] - COMPRESS_STRAINS[-1])))
    err = " ".join(f"{100 * (f / m - 1):+.1f}%" for f, m in zip(F, mem))
    print(f"P = {P} kPa (turgid {P0:.2f}): {err}  | volume: wall {100 * (a[k, 9] / a[0, 9] - 1):+.2f}%, "
          f"fluid {100 * (a[k, 10] / a[0, 10] - 1):+.2f}%, model {100 * dv[-1]:+.2f}%")
PY
