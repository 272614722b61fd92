#!/usr/bin/env bash
# Set up (or reuse) everything and run the whole test suite with CTest.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/tools/setup.sh"
cd "$here/build"
ctest --output-on-failure -j "${JOBS:-$(nproc)}" "$@"
