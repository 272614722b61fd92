#!/usr/bin/env bash
# The main job: set up, then inflate a coarse stiff cell to turgor and compress it between plates to
# 20% strain; write the force-strain data (CSV) and plots (PNG) to results/main/, and the walls as
# VTK surfaces during the compression (walls.STEP.vtk, for ParaView).
#   coarse cell: 642 wall nodes, ~460 fluid particles; LEVEL=4: the paper's 2562 + 3500;
#   LEVEL=5: 10242 + 14000 (the paper's fine resolution); NFLUID overrides the fluid count
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/tools/setup.sh"
source "$here/build/cellmech-env.sh"
out=${OUT:-$here/results/main}
LEVEL=${LEVEL:-3}
NP=${NP:-1}
mkdir -p "$out"
cd "$out"
# Model lengths per level, as tools/validation/common.py: a level coarser doubles the wall
# spacing, r0 and reach, f0 (force x length) grows 2^3; the smoothing length follows the fluid
# spacing of the level's fluid count; the 10242-node wall's lighter nodes need dt = 0.5 ns.
case "$LEVEL" in
  3) nf=440;   s=6.4;  r0=3.2; f0=8.0e4;  reach=4.0; dt=0.001 ;;
  4) nf=3500;  s=3.2;  r0=1.6; f0=1.0e4;  reach=2.0; dt=0.001 ;;
  5) nf=14000; s=2.07; r0=0.8; f0=1.25e3; reach=1.0; dt=0.0005 ;;
  *) echo "main-job: LEVEL must be 3, 4 or 5 (642, 2562 or 10242 wall nodes), got '$LEVEL'" >&2; exit 2 ;;
esac
NFLUID=${NFLUID:-$nf}
ninfl=$(/usr/bin/python3 -c "print(round(25.0/$dt))")
model=(-var dir "$here/lammps-inputs" -var s "$s" -var r0 "$r0" -var f0 "$f0" -var reach "$reach" -var dt "$dt")
run() { if [ "$NP" -gt 1 ]; then mpirun --allow-run-as-root --oversubscribe -np "$NP" "$LMP" "$@"; else "$LMP" "$@"; fi; }
/usr/bin/python3 "$here/tools/cellgen.py" cell -o cell.data --level "$LEVEL" --nfluid "$NFLUID" --inset "$r0"
echo "inflating ..."
run -in "$here/lammps-inputs/in.inflate" -log log.inflate -screen none "${model[@]}" \
  -var data cell.data -var nsteps $ninfl -var every 500 -var out inflate.dat -var restart_out inflated.restart
echo "compressing ..."
run -in "$here/lammps-inputs/in.compress" -log log.compress -screen none "${model[@]}" \
  -var restart inflated.restart -var vplate 0.5 -var every 100 -var out compress.dat -var vtk 2500
/usr/bin/python3 "$here/tools/plot_main.py" "$out"
echo "main job done: results in $out"
ls "$out"/*.csv "$out"/*.png
