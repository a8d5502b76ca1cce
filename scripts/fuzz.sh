#!/bin/sh
# Builds the libFuzzer targets (tests/fuzz: the JSON scene parser and the OBJ, OFF, PLY and STL loaders)
# with clang, AddressSanitizer and UndefinedBehaviorSanitizer into ./build-fuzz, and runs each for
# SECONDS (default 60). Prints the executions per target; exits non-zero when a target finds a crash, a
# sanitizer report, an exception other than parashade::InputError, or a load that breaks the documented
# guarantees, and prints the saved input's path and the report.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]       TARGET: scene mesh_obj mesh_off mesh_ply mesh_stl
#
# Environment: PARASHADE_FUZZ_ARGS (extra libFuzzer flags, e.g. "-fork=2 -ignore_crashes=1"),
# PARASHADE_FUZZ_TIMEOUT (seconds one input may take, default 10), PARASHADE_FUZZ_CHECK_OUTPUT=0 (accept
# any successful load), PARASHADE_FUZZ_SKIP_BUILD=1 (use the targets already in build-fuzz: no install,
# no build). Installs the Debian packages it needs (as root or through sudo).
# Longer runs, the corpus and how findings are handled: docs/robustness.md.
set -eu
cd "$(dirname "$0")/.."
ROOT=$PWD

SECONDS_PER_TARGET=60
if [ $# -gt 0 ]; then
  case "$1" in
    ''|*[!0-9]*) ;;
    *) SECONDS_PER_TARGET=$1; shift ;;
  esac
fi
TARGETS=${*:-scene mesh_obj mesh_off mesh_ply mesh_stl}
for t in $TARGETS; do
  case "$t" in
    scene|mesh_obj|mesh_off|mesh_ply|mesh_stl) ;;
    *) echo "fuzz.sh: unknown target '$t' (scene mesh_obj mesh_off mesh_ply mesh_stl)" >&2; exit 2 ;;
  esac
done

if [ "${PARASHADE_FUZZ_SKIP_BUILD:-0}" != 1 ]; then
  # clang and its runtimes (libFuzzer, ASan, UBSan; Debian's default version, 14 on bookworm) are in
  # install-deps.sh. PARASHADE_FUZZ_SKIP_INSTALL=1: test.sh installed them already.
  if [ "${PARASHADE_FUZZ_SKIP_INSTALL:-0}" != 1 ]; then ./scripts/install-deps.sh; fi

  GENERATOR=""
  if command -v ninja >/dev/null 2>&1; then GENERATOR="-G Ninja"; fi
  build_start=$(date +%s)
  # shellcheck disable=SC2086  # GENERATOR is empty or two words
  cmake -S . -B build-fuzz $GENERATOR -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
        ${PARASHADE_FUZZ_CMAKE_ARGS:-} \
        -DPARASHADE_FUZZ=ON -DPARASHADE_BUILD_TESTS=OFF -DPARASHADE_BUILD_BENCH=OFF
  cmake --build build-fuzz --target fuzz_targets --parallel "$(nproc)"
  echo "fuzz.sh: targets built in $(( $(date +%s) - build_start )) s"
fi
mkdir -p build-fuzz/logs
# Leak checking stays on (libFuzzer reports a leak as a finding); every UBSan report stops the run.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:handle_abort=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

failed=""
summary=""
for t in $TARGETS; do
  work="build-fuzz/corpus/$t"        # inputs found in this and earlier runs (not committed)
  artifacts="build-fuzz/artifacts/$t"
  log="build-fuzz/logs/$t.log"
  rm -rf "$artifacts"
  mkdir -p "$work" "$artifacts"
  # The target writes each input to a file in a directory of its own under TMPDIR: keep those (and any
  # that a crashed run leaves behind) inside the build tree.
  TMPDIR="$ROOT/build-fuzz/tmp/$t"
  export TMPDIR
  rm -rf "$TMPDIR"
  mkdir -p "$TMPDIR"
  echo "fuzz.sh: fuzz_$t for ${SECONDS_PER_TARGET} s (log: $log)"
  rc=0
  # shellcheck disable=SC2086  # PARASHADE_FUZZ_ARGS is a list of flags
  "build-fuzz/fuzz/fuzz_$t" -max_total_time="$SECONDS_PER_TARGET" -timeout="${PARASHADE_FUZZ_TIMEOUT:-10}" \
      -rss_limit_mb=2048 -dict="tests/fuzz/dict/$t.dict" -artifact_prefix="$artifacts/" -print_final_stats=1 \
      ${PARASHADE_FUZZ_ARGS:-} "$work" "tests/fuzz/corpus/$t" >"$log" 2>&1 || rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  per_second=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
  if [ -z "$execs" ]; then  # -fork mode prints no final stats: its last status line "#N: cov: ..."
    execs=$(sed -n 's/^#\([0-9]*\): cov:.*/\1/p' "$log" | tail -n 1)
    per_second=$(sed -n 's/^#[0-9]*: cov:.* exec\/s: \([0-9]*\).*/\1/p' "$log" | tail -n 1)
  fi
  # With -fork and -ignore_crashes libFuzzer goes on after a finding and exits 0: the saved inputs count.
  found=$(find "$artifacts" -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
  if [ "$rc" -eq 0 ] && [ "$found" -gt 0 ]; then rc=1; fi
  coverage=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2)
  corpus=$(find "$work" -type f | wc -l)
  if [ "$rc" -eq 0 ]; then
    line="fuzz_$t: ok, ${execs:-?} executions in ${SECONDS_PER_TARGET} s (${per_second:-?}/s), coverage ${coverage:-?} edges, corpus $corpus"
  else
    line="fuzz_$t: FAILED (exit $rc, $found saved input(s)) after ${execs:-?} executions"
    failed="$failed $t"
    echo "---- fuzz_$t report (from $log) ----"
    grep -E 'parashade fuzz finding|ERROR: |SUMMARY: |runtime error|#[0-9]+ 0x' "$log" | head -n 40 || true
    grep -E 'Test unit written to|Crash|crash-|leak-|timeout-|oom-' "$log" | grep -v '^INFO' | tail -n 5 || true
    for f in "$artifacts"/*; do
      if [ -f "$f" ]; then echo "fuzz.sh: crashing input: $ROOT/$f"; fi
    done
    echo "fuzz.sh: reproduce with: build-fuzz/fuzz/fuzz_$t <input>"
  fi
  echo "$line"
  summary="$summary$line
"
done

echo "---- fuzz.sh summary ----"
printf '%s' "$summary"
if [ -n "$failed" ]; then
  echo "fuzz.sh: findings in:$failed" >&2
  exit 1
fi
