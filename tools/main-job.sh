#!/usr/bin/env bash
# The main job: set up, then run the most complete experiment the package has, and write its data
# (CSV) and plots (PNG) to results/main/.
#   current: a stiff cell wall (2562 nodes) breathing in vacuo after an isotropic stretch, and the
#   same empty wall squeezed between two plates.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/tools/setup.sh"
source "$here/build/cellmech-env.sh"
out=${OUT:-$here/results/main}
mkdir -p "$out"
cd "$out"
/usr/bin/python3 "$here/tools/cellgen.py" cell -o cell-wall.data --level 4 --nfluid 0
"$LMP" -in "$here/lammps-inputs/in.breathing" -log log.breathing -screen none -var out breathing.dat
"$LMP" -in "$here/lammps-inputs/in.plates" -log log.plates -screen none -var out plates.dat
/usr/bin/python3 "$here/tools/plot_main.py" "$out"
echo "main job done: results in $out"
ls "$out"/*.csv "$out"/*.png
