#!/bin/sh
# Builds parashade and its tests with AddressSanitizer and UndefinedBehaviorSanitizer into ./build-asan
# (RelWithDebInfo at -O1 -g1, no benchmarks) and runs the test suite under them, but for the tests that only
# check kernels (listed below). The host code is instrumented; kernels run on PoCL as usual. Extra arguments go
# to cmake's configure step.
# Installs the Debian packages it needs (as root or through sudo). Prints how long each step took.
# Tests that need the shared meshes read PARASHADE_MESH_DIR, as with scripts/test.sh.
# See docs/robustness.md for the sanitizer options and why they are what they are.
set -eu
cd "$(dirname "$0")/.."
if [ "${PARASHADE_SANITIZE_SKIP_INSTALL:-0}" != 1 ]; then ./scripts/install-deps.sh; fi

GENERATOR=""
if command -v ninja >/dev/null 2>&1; then GENERATOR="-G Ninja"; fi

# Any sanitizer report fails the program that printed it (so the test), with a stack trace. Leak
# checking stays on, with one suppression: PoCL 3.1 and its LLVM 15 leak when they compile a kernel
# (a cold POCL_CACHE_DIR: 37 tests failed on ~8 700 leaked blocks, every one allocated inside
# libLLVM-15 or libpocl, none with a parashade frame); a warm cache leaks nothing. ASAN_OPTIONS,
# UBSAN_OPTIONS and LSAN_OPTIONS from the caller are kept and win (appended last). The same options
# apply at build time, when gtest_discover_tests runs the test programs to list their tests.
mkdir -p build-asan
printf '%s\n' '# Leaks inside the OpenCL kernel compiler (scripts/sanitize.sh, docs/robustness.md).' \
    'leak:libpocl.so' 'leak:libLLVM' > build-asan/lsan.supp
# intercept_tls_get_addr=0: GCC 12's runtime (up to GCC 13 / LLVM 16) takes some dynamic TLS blocks (PoCL
# and LLVM are dlopen'ed with TLS) for a pre-2.25 glibc header and reads garbage as their bounds, and
# LeakSanitizer's tracer then dies at exit ("Tracer caught signal 11"), a test failing after every
# assertion passed: 7 of 40 runs of one test without the option, 0 of 40 with it (2026-12-01).
ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:strict_string_checks=1:check_initialization_order=1:intercept_tls_get_addr=0:${ASAN_OPTIONS:-}"
UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
LSAN_OPTIONS="suppressions=$PWD/build-asan/lsan.supp:print_suppressions=0:${LSAN_OPTIONS:-}"
export ASAN_OPTIONS UBSAN_OPTIONS LSAN_OPTIONS

start=$(date +%s)
# -O1 -g1: the optimization ASan's documentation advises, and line tables for the stack traces; compiling the
# CLI and test sources under ASan at -O2 with full debug information took twice as long (docs/robustness.md).
# shellcheck disable=SC2086  # GENERATOR is empty or two words
cmake -S . -B build-asan $GENERATOR -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
      -DPARASHADE_SANITIZE=ON -DPARASHADE_BUILD_BENCH=OFF -DPARASHADE_BUILD_TESTS=ON "$@"
cmake --build build-asan --parallel "$(nproc)"
built=$(date +%s)

export POCL_CACHE_DIR="${POCL_CACHE_DIR:-$PWD/build-asan/pocl-cache}"
# No timing is taken here, so PoCL's workers need not be pinned (the renderer pins them unless this is
# set).
export POCL_AFFINITY="${POCL_AFFINITY:-0}"
# The tests' PyPI venvs (flip-evaluator, kernel_tuner: tests/scripts/pip_venv.py) from the main build when it
# has them: the same packages, without a second minute of pip.
if [ -d build ] && [ -z "${PARASHADE_TEST_VENVS:-}" ]; then export PARASHADE_TEST_VENVS="$PWD/build"; fi
status=0
# -LE anydevice: the Oclgrind runs (tests/anydevice, docs/pipeline.md) check the kernels, which the
# sanitizers do not instrument; under them they would only double their time.
# Not under the sanitizers: the install label and docs.api_reference (they configure, compile and install the
# package and run Doxygen; the main suite runs them, and no host code of theirs runs here); the anydevice label (Oclgrind is itself an instrumenting interpreter), mpi
# (Open MPI's own allocations would fill LeakSanitizer's report; its ranks run the same renderer the other
# tests run) and hw (Verilator's models of the RTL, no parashade code but the vectors' writer).
# Nor the tests that only compare two kernel builds' images on one host path (stamps against row segments, a
# deferral threshold, a tile size, the lanes shape against the vector shape): each case is a PoCL kernel build, which the sanitizers do not instrument, and
# the host code they run is run under the sanitizers by the other tests. Under ASan they took 17 % of the
# sanitized tests' time (docs/robustness.md).
# Nor CliDistributeAlone: it runs --distribute outside mpirun (an Open MPI singleton), whose MCA components
# leak in modules LeakSanitizer cannot name, so no suppression matches them; the mpi label is left out alike.
kernel_only='^(StampLayout\.|LanesShape\.|CombinedKernel\.TilesDoNotChangeThePixels$|CliDeterminism\.(DeferralThreshold|TileSize)DoesNotChangeTheImage$|CliDistributeAlone\.)'
ctest --test-dir build-asan --output-on-failure --parallel "$(nproc)" --timeout 1800 -LE 'anydevice|mpi|hw|install' \
  -E "$kernel_only|^docs\.api_reference$" || status=$?
done_at=$(date +%s)

echo "sanitize.sh: build $((built - start)) s, tests $((done_at - built)) s, total $((done_at - start)) s"
exit "$status"
