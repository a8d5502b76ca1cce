#!/bin/sh
# Configures and builds parashade (Release) into ./build. Extra arguments go to cmake's configure step.
set -eu
cd "$(dirname "$0")/.."
GENERATOR=""
if command -v ninja >/dev/null 2>&1; then GENERATOR="-G Ninja"; fi
cmake -S . -B build $GENERATOR -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build --parallel "$(nproc)"
