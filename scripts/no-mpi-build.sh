#!/bin/sh
# Configures and builds parashade with MPI switched off (-DPARASHADE_MPI=OFF, the build a machine without
# Open MPI gets) into its own directory, then runs the no-MPI test: it renders, and refuses
# `render --distribute` and `scaling --mpi` with exit 2 and the reason (docs/distributed.md).
#   scripts/no-mpi-build.sh [BUILD_DIR]      default build-nompi; uses ccache when installed
# Not part of CI: a second build from scratch takes minutes on 2 cores without ccache (CI has none). Every
# build with MPI checks the same CLI linked with the no-MPI side instead (parashade_without_mpi, CTest
# nompi.cli); this script checks what that cannot: that CMake configures and builds with MPI off.
set -eu
cd "$(dirname "$0")/.."
DIR="${1:-build-nompi}"
GENERATOR=""
if command -v ninja >/dev/null 2>&1; then GENERATOR="-G Ninja"; fi
LAUNCHER=""
if command -v ccache >/dev/null 2>&1; then LAUNCHER="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"; fi
mkdir -p "$DIR"
# shellcheck disable=SC2086
cmake -S . -B "$DIR" $GENERATOR $LAUNCHER -DCMAKE_BUILD_TYPE=Release -DPARASHADE_MPI=OFF >"$DIR/configure.log" 2>&1 ||
  { cat "$DIR/configure.log"; exit 1; }
grep -q "render --distribute is refused" "$DIR/configure.log" ||
  { echo "no-mpi-build: CMake did not take the no-MPI branch (see $DIR/configure.log)" >&2; exit 1; }
if grep -q "parashade_without_mpi\|mpi.render" "$DIR/build.ninja" "$DIR/Makefile" 2>/dev/null; then
  echo "no-mpi-build: MPI targets or tests configured with PARASHADE_MPI=OFF" >&2
  exit 1
fi
cmake --build "$DIR" --parallel "$(nproc)" --target parashade
export POCL_CACHE_DIR="${POCL_CACHE_DIR:-$PWD/$DIR/pocl-cache}"
python3 tests/mpi/without_mpi_test.py "$DIR/parashade" "$PWD"
echo "no-mpi-build: configured, built and tested without MPI in $DIR"
