#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Set up (or reuse) everything and run the whole test suite with CTest against the default LAMMPS
# release (tools/setup.sh), then the unit tests and short cell runs against the other release the
# package supports, built beside it (build-VERSION/). OTHER_LAMMPS=0 skips the second part.
# Arguments go to the first ctest: -L fast (or unit, slow) runs one label of tests/CMakeLists.txt;
# the second part runs the tests labelled compat.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/tools/setup.sh"
(cd "$here/build" && ctest --output-on-failure -j "${JOBS:-$(nproc)}" "$@")
if [ "${OTHER_LAMMPS:-1}" = 1 ]; then
  # the release build/ was made with (setup.sh writes it into the environment file)
  used=$(source "$here/build/cellmech-env.sh" && echo "$CELLMECH_LAMMPS_VERSION")
  [ "$used" = 20250204 ] && other=20260704 || other=20250204
  echo "== the other supported LAMMPS release: $other (unit tests, plugin guard, LAMMPS's force-style harness, short runs of every example, pair cell/sph between runs, fix cell/plates on its fix wall, failures without a per-step collective)"
  LAMMPS_VERSION=$other CELLMECH_BUILD_DIR=build-$other bash "$here/tools/setup.sh"
  (cd "$here/build-$other" && ctest --output-on-failure -j "${JOBS:-$(nproc)}" \
    -L compat)
fi
