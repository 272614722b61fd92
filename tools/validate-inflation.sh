#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Inflation of the stiff cell at the paper's resolution (2562 wall nodes, 3500 fluid particles) to
# P = 100, 200, 364 and 400 kPa: mean pressure, stretch against Young-Laplace, equatorial force
# against P pi R^2, leaks, mass balance. Prints a table and the wall time. Not part of CI.
# WALL=membrane|bending: that wall (lammps-inputs/cell-wall.lmp), into inflation-paper-WALL.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$here/build/cellmech-env.sh"
source "$here/tools/common.sh"
read -r NF4 R04 < <(level_params 4 nfluid r0)
out=${OUT:-$here/results/inflation-paper$wall_tag}
mkdir -p "$out" && cd "$out"
/usr/bin/python3 "$here/tools/cellgen.py" cell -o cell.data --level 4 --nfluid $NF4 --inset $R04 "${wall_gen[@]}"
for P in ${PRESSURES:-100 200 364 400}; do
  start=$(date +%s)
  "$LMP" -in "$here/lammps-inputs/in.inflate" -log "log.$P" -screen none -var dir "$here/lammps-inputs" \
    "${wall_vars[@]}" -var data cell.data -var Pi "-$P" -var nsteps ${NSTEPS:-20000} -var every 1000 -var out "inflate-$P.dat" \
    -var restart_out "inflated-$P.restart"
  echo "P=$P kPa: wall time $(( $(date +%s) - start )) s"
done
/usr/bin/python3 - "$out" <<'PY'
import math, sys
import numpy as np
from cellmech.params import CELL, stiff
G, t0, R0 = stiff()["G"], stiff()["t0"], CELL["R"]
print(f"{'P target':>8} {'P':>8} {'lam':>8} {'lam YL':>8} {'F_eq':>10} {'P pi R^2':>10} {'ratio':>6} leaks  mass-flux")
for f in sorted(__import__('glob').glob(sys.argv[1] + '/inflate-*.dat'), key=lambda s: int(s.split('-')[-1][:-4])):
    a = np.loadtxt(f, ndmin=2)
    last = a[-4:]
    P, lam, Feq = last[:, 4].mean(), last[:, 7].mean(), last[:, 9].mean()
    R = R0 * lam
    lam_yl = (1 - P * R / 2 / (G * t0)) ** (-1 / 6)
    dm = np.max(np.abs(a[:, 5] - a[0, 5] - a[:, 11])) / a[-1, 11]
    print(f"{f.split('-')[-1][:-4]:>8} {P:8.2f} {lam:8.5f} {lam_yl:8.5f} {Feq:10.4g} {P*math.pi*R*R:10.4g} "
          f"{Feq/(P*math.pi*R*R):6.3f} {int(a[:,10].max()):5d}  {dm:.1e}")
PY
