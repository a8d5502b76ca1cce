#!/bin/sh
# README's first command: installs the Debian packages, builds, renders the default scene to
# default.png and prints frame time and error (report in default.json).
set -eu
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
export POCL_CACHE_DIR="${POCL_CACHE_DIR:-$PWD/build/pocl-cache}"
./build/parashade render scenes/default.json -o default.png --report default.json "$@"
