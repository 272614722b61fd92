#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The main job: set up, then inflate a coarse stiff cell to turgor and compress it between plates to
# 20% strain; write the force-strain data (CSV) and plots (PNG) to results/main/, and the walls as
# VTK surfaces during the compression (walls.STEP.vtk, for ParaView). Then a coarse tissue of 2x2x2
# glued cells, inflated and compressed to failure: tissue-stress-strain.csv/png.
#   coarse cell: 642 wall nodes, ~460 fluid particles; LEVEL=4: the paper's 2562 + 3500;
#   LEVEL=5: 10242 + 14000 (the paper's fine resolution); NFLUID overrides the fluid count;
#   WALL=membrane|bending: the Neo-Hookean membrane wall (+ bending) for the tethers, results/main-$WALL
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
LEVEL=${LEVEL:-3}
NP=${NP:-1}
# every input is checked before any work (the setup alone can take minutes)
bad() { echo "main-job: $*" >&2; exit 2; }
case "$LEVEL" in 3|4|5) ;; *) bad "LEVEL must be 3, 4 or 5 (642, 2562 or 10242 wall nodes), got '$LEVEL'" ;; esac
[[ "$NP" =~ ^[1-9][0-9]*$ ]] || bad "NP (MPI ranks) must be a whole number >= 1, got '$NP'"
[ -z "${NFLUID:-}" ] || [[ "$NFLUID" =~ ^[1-9][0-9]*$ ]] ||
  bad "NFLUID (fluid particles in the cell) must be a whole number >= 1, got '$NFLUID'"
source "$here/tools/common.sh"
out=${OUT:-$here/results/main$wall_tag}
# the model's lengths and time step at this level: the level table (tools/cellmech/params.py)
read -r nf s r0 f0 reach dt < <(level_params "$LEVEL" nfluid s r0 f0 reach dt)
bash "$here/tools/setup.sh"
source "$here/build/cellmech-env.sh"
mkdir -p "$out"
cd "$out"
NFLUID=${NFLUID:-$nf}
ninfl=$(/usr/bin/python3 -c "print(round(25.0/$dt))")
model=(-var dir "$here/lammps-inputs" -var s "$s" -var r0 "$r0" -var f0 "$f0" -var reach "$reach" -var dt "$dt" "${wall_vars[@]}")
run() { mpi_run "$NP" "$LMP" "$@"; }
# trun ARGS...: a run, its effective settings first written to settings.json (one entry per input)
trun() { /usr/bin/python3 -m cellmech.params settings -- "$@" && run "$@"; }
/usr/bin/python3 "$here/tools/cellgen.py" cell -o cell.data --level "$LEVEL" --nfluid "$NFLUID" --inset "$r0" "${wall_gen[@]}"
echo "inflating ..."
trun -in "$here/lammps-inputs/in.inflate" -log log.inflate -screen none "${model[@]}" \
  -var data cell.data -var nsteps $ninfl -var every 500 -var out inflate.dat -var restart_out inflated.restart
echo "compressing ..."
# quasi-static (issue 29; docs/Howto_plates.rst): both plates closing at 0.25 m/s after a smooth
# start, and the protoplasm at 10 mPa s, which takes out the coarse fluid's rearrangement noise
# (+-10% on the curve at 1 mPa s) and adds a viscous stress of mu x strain rate = 0.08 kPa
trun -in "$here/lammps-inputs/in.compress" -log log.compress -screen none "${model[@]}" \
  -var restart inflated.restart -var vplate 0.25 -var plates both -var ramp 0.02 -var mu 10 \
  -var every 100 -var out compress.dat -var vtk 5000
/usr/bin/python3 "$here/tools/plot_main.py" "$out"

# A small coarse tissue: 2x2x2 cells glued by the middle lamella, inflated to turgor together and
# compressed between plates to failure (tethers break at the paper's critical stretch 1.04):
# stress-strain with the wall ruptures and lamella debonds marked (tissue-stress-strain.csv/png).
# The coarse cell's lengths whatever LEVEL is; reach and special-list room from the generator.
echo "tissue: generating, inflating, compressing to failure ..."
read -r tnf ts tr0 tf0 treach < <(level_params 3 nfluid s r0 f0 reach)
/usr/bin/python3 "$here/tools/cellgen.py" tissue -o tissue.data --lattice sc --n 2 2 2 --level 3 \
  --nfluid "$tnf" "${wall_gen[@]}" --stats tissue.json > tissue-gen.txt
read -r treach tspecial < <(/usr/bin/python3 -c "import json; s = json.load(open('tissue.json'))
print(max($treach, s['triangle_quality']['recommended_reach']), s['extra_special_per_atom'])")
tmodel=(-var dir "$here/lammps-inputs" -var s "$ts" -var r0 "$tr0" -var f0 "$tf0" -var reach "$treach" "${wall_vars[@]}")
trun -in "$here/lammps-inputs/in.tissue-inflate" -log log.tissue-inflate -screen none "${tmodel[@]}" \
  -var data tissue.data -var special "$tspecial" -var every 1000 \
  -var restart_out tissue.restart
trun -in "$here/lammps-inputs/in.tissue-compress" -log log.tissue-compress -screen none "${tmodel[@]}" \
  -var restart tissue.restart -var lamf 1.04 -var vplate 0.25 -var strain 0.15 -var vtk 15000
/usr/bin/python3 "$here/tools/plot_tissue.py" "$out"
echo "main job done: results in $out"
ls "$out"/*.csv "$out"/*.png
