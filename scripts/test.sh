#!/bin/sh
# README's test command: installs the Debian packages, builds, and runs the whole test suite.
# Tests that need the shared meshes read PARASHADE_MESH_DIR and skip with a message when it is unset.
set -eu
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
export POCL_CACHE_DIR="${POCL_CACHE_DIR:-$PWD/build/pocl-cache}"
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 600
