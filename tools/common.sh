# SPDX-License-Identifier: GPL-2.0-or-later
# Sourced by the shell scripts in tools/: the Python package cellmech (tools/cellmech) on the path,
# the model's level table from it (one source: tools/cellmech/params.py), and the one MPI launch
# line (its Python form: cellmech.launch.mpi_command).
cellmech_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export PYTHONPATH="$cellmech_root/tools${PYTHONPATH:+:$PYTHONPATH}"

# mpi_run NP CMD...: CMD on NP MPI ranks ($MPIEXEC or mpirun); on one rank without a launcher.
# Open MPI refuses root without --allow-run-as-root; --oversubscribe lets 2 cores run 2+ ranks.
mpi_run() {
  local np=$1; shift
  if [ "$np" -gt 1 ]; then "${MPIEXEC:-mpirun}" --allow-run-as-root --oversubscribe -np "$np" "$@"
  else "$@"; fi
}

# level_params LEVEL KEY...: a row of the level table (nfluid s r0 f0 reach dt nodes), e.g.
#   read -r nf s r0 < <(level_params 4 nfluid s r0)
level_params() { /usr/bin/python3 -m cellmech.params level "$@"; }

# WALL: the cell wall of every run (lammps-inputs/cell-wall.lmp): tether (the paper's, default),
# membrane (Neo-Hookean triangles) or bending (membrane + hinges). wall_vars is its -var setting,
# wall_gen the cellgen.py option its data files need (the hinges, for bending), wall_tag a suffix
# for result folders ('' for the tethers, so their results stay where they were).
WALL=${WALL:-tether}
case "$WALL" in
  tether|membrane|bending) ;;
  *) echo "WALL must be tether, membrane or bending, got '$WALL'" >&2; exit 2 ;;
esac
wall_vars=(-var wall "$WALL")
wall_gen=()
wall_tag=""
if [ "$WALL" != tether ]; then wall_tag="-$WALL"; fi
if [ "$WALL" = bending ]; then wall_gen=(--bending); fi
