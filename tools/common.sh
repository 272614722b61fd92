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
