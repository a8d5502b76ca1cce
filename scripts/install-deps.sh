#!/bin/sh
# Installs the Debian (bookworm) packages parashade builds, tests and benchmarks with (clang and its
# runtimes: the libFuzzer targets that scripts/test.sh runs, docs/robustness.md; oclgrind: the second
# OpenCL implementation of the anydevice tests, registered by the tests only, docs/pipeline.md; verilator
# and yosys: the units' RTL tests and synthesis, docs/hardware.md).
# openmpi-bin, libopenmpi-dev: render --distribute and the mpi test label (docs/distributed.md).
# python3-jsonschema: the schema tests check every report kind and scene against schemas/ (docs/reports.md).
# python3-matplotlib: scripts/report.py's plots (bench-suite.sh skips them without it).
# python3-numpy, python3-pil, openimageio-tools (oiiotool): scripts/mix_oracle.py reads render's images.
# time: GNU time, the peak memory of scripts/peak_memory.py (the PeakMemory test, bench-suite.sh).
#
# --test (scripts/test.sh, README's second command) adds what only the tests use: nextpnr-ice40 (Debian; the
# place and route of hw/, scripts/hw_pnr.py, docs/hardware.md), doxygen (the API reference's test,
# docs.api_reference), llvm (llvm-mca: scripts/kernel_loops.py and its test), pybind11-dev, python3-dev and python3-pytest (the Python module, which test.sh builds
# with -DPARASHADE_PYTHON=ON, and its pytest tests; docs/python.md) and, not packaged by Debian, Intel's CPU OpenCL runtime, the third implementation of
# the anydevice tests (docs/pipeline.md),
# from PyPI (intel-opencl-rt, intel-cmplr-lib-rt) into a Python venv (Debian's python3-venv) at the fixed prefix
# /opt/parashade/intel-opencl (about 850 MB; docs/environment.md), skipped when it is there. If pip or the
# network fails, a warning says so and the script goes on: the tests on Intel's runtime then skip, saying
# how to install it. README's first command (render-default.sh) runs without --test.
# Runs as root or through sudo; safe to run again.
set -eu
INTEL_OPENCL_PREFIX=/opt/parashade/intel-opencl
INTEL_OPENCL_PACKAGES="intel-opencl-rt==2026.2.0 intel-cmplr-lib-rt==2026.2.0"  # the versions the tests were run with
TEST=0
case "${1:-}" in
  "") ;;
  --test) TEST=1 ;;
  *) echo "usage: install-deps.sh [--test]   (--test: also Intel's CPU OpenCL runtime for the tests)" >&2; exit 2 ;;
esac
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
TEST_PACKAGES=""
if [ "$TEST" = 1 ]; then TEST_PACKAGES="python3-venv nextpnr-ice40 doxygen pybind11-dev python3-dev python3-pytest llvm"; fi
$SUDO apt-get update -q
# shellcheck disable=SC2086  # TEST_PACKAGES is empty or words
$SUDO apt-get install -y -q --no-install-recommends $TEST_PACKAGES \
    g++ cmake ninja-build pkg-config \
    pocl-opencl-icd oclgrind ocl-icd-opencl-dev opencl-c-headers opencl-clhpp-headers clinfo \
    libglm-dev libopenmesh-dev libopenimageio-dev openimageio-tools \
    nlohmann-json3-dev libcli11-dev libmuparser-dev libgtest-dev libgmock-dev libbenchmark-dev \
    libegl-dev libgl-dev libgl1-mesa-dri python3 python3-jsonschema python3-matplotlib python3-numpy python3-pil \
    clang libclang-rt-dev \
    openmpi-bin libopenmpi-dev verilator yosys time \
    ca-certificates

# Intel's runtime: a venv whose lib/ holds libintelocl.so (the ICD library tests/CMakeLists.txt registers)
# and the libraries it needs. Complete when .parashade-complete exists; a partial one is removed first.
# shellcheck disable=SC2086  # INTEL_OPENCL_PACKAGES is words
install_intel_opencl() {
  [ -e "$INTEL_OPENCL_PREFIX/.parashade-complete" ] && return 0
  echo "install-deps.sh: Intel's CPU OpenCL runtime into $INTEL_OPENCL_PREFIX (pip: $INTEL_OPENCL_PACKAGES)"
  $SUDO rm -rf "$INTEL_OPENCL_PREFIX" &&
    $SUDO mkdir -p "$(dirname "$INTEL_OPENCL_PREFIX")" &&
    $SUDO /usr/bin/python3 -m venv "$INTEL_OPENCL_PREFIX" &&
    $SUDO "$INTEL_OPENCL_PREFIX/bin/pip" install -q --no-cache-dir --disable-pip-version-check $INTEL_OPENCL_PACKAGES &&
    [ -e "$INTEL_OPENCL_PREFIX/lib/libintelocl.so" ] &&
    $SUDO touch "$INTEL_OPENCL_PREFIX/.parashade-complete"
}

if [ "$TEST" = 1 ]; then
  if ! install_intel_opencl; then
    $SUDO rm -rf "$INTEL_OPENCL_PREFIX" || true
    echo "install-deps.sh: warning: Intel's CPU OpenCL runtime could not be installed into $INTEL_OPENCL_PREFIX" \
         "(pip or the network failed, above); the anydevice tests on it will skip" >&2
  fi
fi
