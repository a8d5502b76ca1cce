#!/bin/sh
# Configures and builds parashade (Release) into ./build: everything, or with `--target NAME` first only
# NAME and what it needs (render-default.sh builds just the parashade command). The other arguments go to
# cmake's configure step.
set -eu
cd "$(dirname "$0")/.."
TARGET=""
if [ "${1:-}" = "--target" ]; then
  TARGET="--target ${2:?build.sh: --target needs a target name}"
  shift 2
fi
GENERATOR=""
if command -v ninja >/dev/null 2>&1; then GENERATOR="-G Ninja"; fi
cmake -S . -B build $GENERATOR -DCMAKE_BUILD_TYPE=Release "$@"
# shellcheck disable=SC2086  # TARGET is empty or two words
cmake --build build --parallel "$(nproc)" $TARGET
