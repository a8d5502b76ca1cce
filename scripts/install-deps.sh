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
# Runs as root or through sudo; safe to run again.
set -eu
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends \
    g++ cmake ninja-build pkg-config \
    pocl-opencl-icd oclgrind ocl-icd-opencl-dev opencl-c-headers opencl-clhpp-headers clinfo \
    libglm-dev libopenmesh-dev libopenimageio-dev openimageio-tools \
    nlohmann-json3-dev libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev \
    libegl-dev libgl-dev libgl1-mesa-dri python3 python3-jsonschema python3-matplotlib python3-numpy python3-pil \
    clang libclang-rt-dev \
    openmpi-bin libopenmpi-dev verilator yosys time \
    ca-certificates
