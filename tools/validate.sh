#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Validation suite (issue 5): runs the validation cases at one resolution and writes a report
# (validation.md with tables and PNG plots, validation-summary.json).
#   RES=coarse (default)  642 wall nodes + 440 fluid; minutes     -> results/validation-coarse/
#   RES=paper             2562 + 3500, and the resolution study over 642/2562/10242 wall nodes
#                                                               -> docs/validation.md, docs/validation/
#   RES=study             as paper, report in results/validation-study/
#   RES=fine              10242 + 14000 (hours on one core)     -> results/validation-fine/
# OUT=folder puts the report elsewhere; CASES="1,3" runs some cases; NP=2 uses 2 MPI ranks per run.
# VARS="wrinkle=yes f0=1e5" (with its own OUT and WORK) passes -var settings to every run: a variant study.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# on a fresh machine, set up first (LAMMPS and the plugin); later runs reuse the build
[ -f "$here/build/cellmech-env.sh" ] || bash "$here/tools/setup.sh"
source "$here/build/cellmech-env.sh"
export CELLMECH_SPECTRUM=${CELLMECH_SPECTRUM:-$here/build/cellmech-spectrum}
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
source "$here/tools/common.sh"
exec /usr/bin/python3 -m cellmech.validation.driver "$@"
