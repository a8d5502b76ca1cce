#!/bin/sh
# README's first command: installs the Debian packages, builds the parashade command (only it, not the
# tests and benchmarks), renders the default scene to default.png and prints frame time and error (report
# in default.json). Extra arguments go to `parashade render`.
set -eu
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh --target parashade
export POCL_CACHE_DIR="${POCL_CACHE_DIR:-$PWD/build/pocl-cache}"
./build/parashade render scenes/default.json -o default.png --report default.json "$@"
