#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Set up a fresh Debian 12 machine (as root) for the cellmech LAMMPS plugin:
#   1. install build dependencies from Debian,
#   2. obtain LAMMPS (a Debian source package: LAMMPS_VERSION) unless LAMMPS_SRC is given,
#   3. build LAMMPS as a shared library with MPI + PLUGIN + MOLECULE (+ SPH, MC for reference runs;
#      + GRAPHICS where dump image lives there), cached outside the repository, one build per
#      version and options,
#   4. configure and build the plugin in ./build (CELLMECH_BUILD_DIR) against that LAMMPS.
# A second run reuses the cache and takes seconds.
#
# Environment:
#   LAMMPS_VERSION  20250204 (4 Feb 2025, Debian 13) or 20260704 (4 Jul 2026, Debian sid);
#                   default 20260704, the newest that works
#   CELLMECH_BUILD_DIR  where the plugin is built (default ./build; e.g. build-20260704)
#   LAMMPS_SRC      an existing LAMMPS source tree (the directory that holds src/ and cmake/)
#   LAMMPS_BUILD    an existing LAMMPS CMake build dir (with lmp and liblammps.so) of that tree
#   CELLMECH_CACHE  cache root (default ~/.cache/cellmech)
#   SKIP_APT=1      leave apt entirely alone: no package installs, no deb-src list, no apt-get
#                   update or source (the packages must be there; the LAMMPS source must be cached
#                   already or given as LAMMPS_SRC)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
LAMMPS_VERSION=${LAMMPS_VERSION:-20260704}
# the LAMMPS releases this package is tested with: Debian source package version and suite
case "$LAMMPS_VERSION" in
  20250204) DEB_VERSION=20250204+dfsg.1-2; DEB_SUITE=trixie ;;
  20260704) DEB_VERSION=20260704+dfsg-2; DEB_SUITE=sid ;;
  *) echo "setup: LAMMPS_VERSION must be 20250204 or 20260704, got '$LAMMPS_VERSION'" >&2; exit 2 ;;
esac
BUILD_DIR=${CELLMECH_BUILD_DIR:-$here/build}
case "$BUILD_DIR" in /*) ;; *) BUILD_DIR=$here/$BUILD_DIR ;; esac
CACHE=${CELLMECH_CACHE:-$HOME/.cache/cellmech}
JOBS=${JOBS:-$(nproc)}
log() { printf '[setup] %s\n' "$*"; }

# ---- 1. packages -------------------------------------------------------------------------------
pkgs=(build-essential cmake pkg-config git openmpi-bin libopenmpi-dev libfftw3-dev
  libgtest-dev libgmock-dev libyaml-dev libpng-dev zlib1g-dev python3-numpy python3-scipy python3-matplotlib python3-vtk9 dpkg-dev
  python3-pytest)
if [ "${SKIP_APT:-0}" != 1 ]; then
  missing=()
  for p in "${pkgs[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
  if [ ${#missing[@]} -gt 0 ]; then
    log "installing: ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  fi
fi

# ---- 2. LAMMPS source --------------------------------------------------------------------------
if [ -z "${LAMMPS_SRC:-}" ]; then
  LAMMPS_SRC=$CACHE/src/lammps-$LAMMPS_VERSION
  if [ ! -f "$LAMMPS_SRC/src/lammps.h" ]; then
    if [ "${SKIP_APT:-0}" = 1 ]; then
      echo "setup: SKIP_APT=1 leaves apt alone, and no LAMMPS source is cached in $LAMMPS_SRC:" \
        "give LAMMPS_SRC=/path/to/lammps, or run once without SKIP_APT to download it" >&2
      exit 2
    fi
    mkdir -p "$CACHE/src"
    list=/etc/apt/sources.list.d/cellmech-$DEB_SUITE-src.sources
    if [ ! -f $list ]; then
      log "adding deb-src entry for Debian $DEB_SUITE"
      cat >$list <<SRC
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: $DEB_SUITE
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
      apt-get update -qq
    fi
    log "downloading LAMMPS source package $DEB_VERSION"
    (cd "$CACHE/src" && apt-get source --download-only --tar-only "lammps=$DEB_VERSION" >/dev/null)
    tarballs=("$CACHE"/src/lammps_"${DEB_VERSION%-*}".orig.tar.*)
    tarball=${tarballs[0]}
    tmp=$CACHE/src/unpack.$$
    mkdir -p "$tmp" && tar -xf "$tarball" -C "$tmp"
    # one top folder (lammps-DATE/) or the tree itself, as the two releases pack it
    top=("$tmp"/*)
    if [ ${#top[@]} -eq 1 ] && [ -d "${top[0]}/src" ]; then
      mv "${top[0]}" "$LAMMPS_SRC" && rmdir "$tmp"
    else
      mv "$tmp" "$LAMMPS_SRC"
    fi
  fi
fi
[ -f "$LAMMPS_SRC/src/lammps.h" ] || { echo "LAMMPS_SRC=$LAMMPS_SRC has no src/lammps.h" >&2; exit 1; }

# ---- 3. LAMMPS build (cached) ------------------------------------------------------------------
lmp_opts=(-DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=on -DBUILD_MPI=on -DBUILD_OMP=off
  -DLAMMPS_SIZES=smallbig -DPKG_PLUGIN=on -DPKG_MOLECULE=on -DPKG_SPH=on -DPKG_MC=on
  -DWITH_PNG=on -DWITH_JPEG=off -DWITH_FFMPEG=off -DWITH_GZIP=on -DFFT=KISS)
# newer LAMMPS moved dump image (used by the examples) into the GRAPHICS package
[ -d "$LAMMPS_SRC/src/GRAPHICS" ] && lmp_opts+=(-DPKG_GRAPHICS=on)
if [ -z "${LAMMPS_BUILD:-}" ]; then
  key=$(printf '%s ' "$LAMMPS_VERSION" "$LAMMPS_SRC" "${lmp_opts[@]}" | sha1sum | cut -c1-10)
  LAMMPS_BUILD=$CACHE/build/lammps-$LAMMPS_VERSION-$key
  if [ ! -x "$LAMMPS_BUILD/lmp" ] || [ ! -f "$LAMMPS_BUILD/.complete" ]; then
    log "building LAMMPS in $LAMMPS_BUILD (about 7 minutes on 2 cores)"
    mkdir -p "$LAMMPS_BUILD"
    cmake -S "$LAMMPS_SRC/cmake" -B "$LAMMPS_BUILD" "${lmp_opts[@]}" >"$LAMMPS_BUILD/configure.log"
    cmake --build "$LAMMPS_BUILD" -j "$JOBS" >"$LAMMPS_BUILD/build.log" 2>&1 ||
      { tail -n 40 "$LAMMPS_BUILD/build.log"; exit 1; }
    touch "$LAMMPS_BUILD/.complete"
  else
    log "reusing cached LAMMPS build $LAMMPS_BUILD"
  fi
fi
# The lmp we use must resolve its own liblammps, not some other one on the system. (ldd's output
# is read whole first: `ldd | grep -q` under pipefail fails at random when grep's early exit
# cuts ldd off with SIGPIPE.)
lmp_libs=$(ldd "$LAMMPS_BUILD/lmp")
if [[ "$lmp_libs" != *"$LAMMPS_BUILD/liblammps"* ]]; then
  echo "error: $LAMMPS_BUILD/lmp does not load $LAMMPS_BUILD/liblammps.so:" >&2
  grep -i lammps <<<"$lmp_libs" >&2
  exit 1
fi

# ---- 4. the plugin -----------------------------------------------------------------------------
cmake -S "$here" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release \
  -DLAMMPS_SOURCE_DIR="$LAMMPS_SRC/src" -DLAMMPS_BINARY_DIR="$LAMMPS_BUILD" >"$BUILD_DIR-configure.log" ||
  { cat "$BUILD_DIR-configure.log"; exit 1; }
cmake --build "$BUILD_DIR" -j "$JOBS"
# environment for users and scripts: `source build/cellmech-env.sh`, then `lmp -in ...`
cat >"$BUILD_DIR/cellmech-env.sh" <<ENV
export LMP="$LAMMPS_BUILD/lmp"
export LAMMPS_PLUGIN_PATH="$BUILD_DIR"
export PATH="$LAMMPS_BUILD:\$PATH"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export CELLMECH_LAMMPS_VERSION=$LAMMPS_VERSION
ENV
log "LAMMPS: $LAMMPS_BUILD/lmp"
log "plugin: $BUILD_DIR/cellmechplugin.so"
