#!/usr/bin/env bash
# The main job: set up, then inflate a coarse stiff cell to turgor and compress it between plates to
# 20% strain; write the force-strain data (CSV) and plots (PNG) to results/main/, and the walls as
# VTK surfaces during the compression (walls.STEP.vtk, for ParaView).
#   coarse cell: 642 wall nodes, ~460 fluid particles (the paper's is 2562 + 3500: LEVEL=4 NFLUID=3500)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/tools/setup.sh"
source "$here/build/cellmech-env.sh"
out=${OUT:-$here/results/main}
LEVEL=${LEVEL:-3}
NFLUID=${NFLUID:-440}
NP=${NP:-1}
mkdir -p "$out"
cd "$out"
# resolution-dependent model lengths scale with the wall spacing (paper values at level 4)
# (a level coarser doubles the spacing; the contact strength f0 ~ force x length grows 2^3)
scale=$(( 1 << (4 - LEVEL) ))
read -r s r0 f0 reach < <(/usr/bin/python3 -c "k=$scale; print(3.2*k, 1.6*k, 1.0e4*k**3, 2.0*k)")
model=(-var dir "$here/lammps-inputs" -var s "$s" -var r0 "$r0" -var f0 "$f0" -var reach "$reach")
run() { if [ "$NP" -gt 1 ]; then mpirun --allow-run-as-root --oversubscribe -np "$NP" "$LMP" "$@"; else "$LMP" "$@"; fi; }
/usr/bin/python3 "$here/tools/cellgen.py" cell -o cell.data --level "$LEVEL" --nfluid "$NFLUID" --inset "$r0"
echo "inflating ..."
run -in "$here/lammps-inputs/in.inflate" -log log.inflate -screen none "${model[@]}" \
  -var data cell.data -var nsteps 25000 -var every 500 -var out inflate.dat -var restart_out inflated.restart
echo "compressing ..."
run -in "$here/lammps-inputs/in.compress" -log log.compress -screen none "${model[@]}" \
  -var restart inflated.restart -var vplate 0.5 -var every 100 -var out compress.dat -var vtk 2500
/usr/bin/python3 "$here/tools/plot_main.py" "$out"
echo "main job done: results in $out"
ls "$out"/*.csv "$out"/*.png
