#!/bin/sh
# README's test command: installs the Debian packages and the test-only tools (install-deps.sh --test:
# nextpnr-ice40 and Intel's CPU OpenCL runtime), builds, and runs the whole test suite; then, as CI
# does, runs each libFuzzer target for a bounded time (scripts/fuzz.sh) and the test suite under
# AddressSanitizer + UndefinedBehaviorSanitizer (scripts/sanitize.sh). Any failure, crash or sanitizer
# report fails the script. Tests that need the shared meshes read PARASHADE_MESH_DIR and skip with a
# message when it is unset.
#
# Environment: PARASHADE_QUICK=1 skips the fuzzing and sanitizer steps (for local runs; .ci/run clears
# it), PARASHADE_FUZZ_SECONDS (default 60) is the fuzzing time per target. Timings: docs/robustness.md.
set -eu
cd "$(dirname "$0")/.."
./scripts/install-deps.sh --test
./scripts/build.sh -DPARASHADE_PYTHON=ON  # the Python module and its tests too (docs/python.md)
export POCL_CACHE_DIR="${POCL_CACHE_DIR:-$PWD/build/pocl-cache}"
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 600
if [ "${PARASHADE_QUICK:-0}" = 1 ]; then
  echo "test.sh: PARASHADE_QUICK=1: fuzzing and sanitizer runs skipped"
  exit 0
fi
start=$(date +%s)
PARASHADE_FUZZ_SKIP_INSTALL=1 ./scripts/fuzz.sh "${PARASHADE_FUZZ_SECONDS:-60}"
fuzzed=$(date +%s)
# sanitize.sh picks its own POCL_CACHE_DIR (kernels built by the instrumented host).
env -u POCL_CACHE_DIR PARASHADE_SANITIZE_SKIP_INSTALL=1 ./scripts/sanitize.sh
echo "test.sh: fuzzing $((fuzzed - start)) s, sanitizers $(($(date +%s) - fuzzed)) s"
