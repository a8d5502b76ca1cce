#!/bin/sh
# The benchmark suite in one command: parashade against Mesa llvmpipe (bench_llvmpipe), the modeled
# units' scaling sweep (parashade scaling), standalone peak memory (parashade render under
# /usr/bin/time), the Phong family (phong-study, combined and normalization studies, bench_normalize),
# then the report (plots, image strip, claims table) when python3-matplotlib is present.
#   scripts/bench-suite.sh [-q] [OUT_DIR]          whole suite (sizes 1920x1080, 512x512, 3840x2160; ~15 min on the quiet 2-core VM)
#   scripts/bench-suite.sh [-q] --quick [OUT_DIR]  CI subset: sphere_8k and fullscreen_quad at 512x512 (< 1 min)
#   scripts/bench-suite.sh [-q] --no-hw [OUT_DIR]  the whole suite but the RTL's synthesis and place and route
#                                                  (~25 min of the run; they do not change with the kernels)
#   scripts/bench-suite.sh [-q] --phong [OUT_DIR]  the Phong family ([Romanyuk & Romanyuk, combined shading]; [Dembitsky 2025, software/hardware rendering] ch. 2-3) and the claims table only (~5 min)
#   scripts/bench-suite.sh [-q] [--phong] --shard K/N [OUT_DIR]   shard K of N: its share of the steps
#   mpirun -np N scripts/bench-suite.sh [-q] [--phong] [OUT_DIR]  the same, shard = rank (docs/distributed.md)
#   --dry-run (after --phong, with or without --shard)            list this shard's steps, run nothing
# Each step's output goes to OUT_DIR/logs/NN-STEP.log; one line per step says its time ("[i/N] STEP: 12.3 s",
# with the time left on a terminal); -q prints only failures. A failing step prints its log's end and stops
# the suite.
# Environment: PARASHADE_MESH_DIR (bunny, fandisk; skipped without it), PARASHADE_DEVICE, BUILD (default build).
set -eu
cd "$(dirname "$0")/.."
QUICK=0
PHONG_ONLY=0
QUIET=0
if [ "${1:-}" = "-q" ]; then QUIET=1; shift; fi
if [ "${1:-}" = "--quick" ]; then QUICK=1; shift; fi
NO_HW=0
if [ "${1:-}" = "--no-hw" ]; then NO_HW=1; shift; fi
if [ "${1:-}" = "--phong" ]; then PHONG_ONLY=1; shift; fi
. scripts/bench_shard.sh  # sharding: shard_owns, after_all
while :; do
  case "${1:-}" in
    --shard) set_shard "${2:-}"; shift 2 ;;
    --dry-run) BENCH_DRY_RUN=1; QUIET=1; shift ;;
    *) break ;;
  esac
done
if [ "$QUICK" = 1 ] && { [ "$SHARDS" -gt 1 ] || [ "$BENCH_DRY_RUN" = 1 ]; }; then
  echo "bench-suite: --quick is one short run, neither dealt across shards nor listed (--shard, --dry-run, mpirun)" >&2
  exit 2
fi
OUT="${1:-bench-results}"
BUILD="${BUILD:-build}"
case "$BUILD" in /*) ;; *) BUILD="$PWD/$BUILD" ;; esac
mkdir -p "$OUT/logs"
export POCL_CACHE_DIR="${POCL_CACHE_DIR:-$BUILD/pocl-cache}"
# The report needs Debian's python3-matplotlib: prefer a python3 that has it (a pyenv shim may not).
PYTHON="${PYTHON:-python3}"
if ! "$PYTHON" -c "import matplotlib" 2>/dev/null && /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  PYTHON=/usr/bin/python3
fi

# The suite runs twice: first only counting its steps (COUNTING=1: `step` counts, `say` is silent), then
# for real, so that each step line can say [i/N].
COUNTING=1
STEPS=0
DONE=0
STARTED=$(date +%s.%N)
TERMINAL=0
if [ -t 1 ] && [ "$QUIET" = 0 ]; then TERMINAL=1; fi

say() { if [ "$COUNTING" = 0 ] && [ "$QUIET" = 0 ]; then echo "bench-suite: $*"; fi; }
warn() { if [ "$COUNTING" = 0 ]; then echo "bench-suite: $*" >&2; fi; }

# step NAME COMMAND...: a step of this shard's share (every step when unsharded; scripts/bench_shard.sh).
step() {
  shard_owns || return 0
  run_step "" "$@"
}
# final_step NAME COMMAND...: a step that reads every shard's results: shard 0 alone, once the others ended.
final_step() {
  if [ "$COUNTING" = 0 ]; then after_all; fi  # the other shards leave here
  [ "$SHARD" -eq 0 ] || return 0
  run_step final "$@"
}

# run_step KIND NAME COMMAND...: runs COMMAND with its stdout and stderr in OUT/logs/NN-NAME.log and prints
# one line with its time; a failure prints the log's last lines and stops the suite. The dry run lists it.
run_step() {
  kind=$1
  name=$2
  shift 2
  if [ "$COUNTING" = 1 ]; then
    STEPS=$((STEPS + 1))
    return 0
  fi
  if [ "$BENCH_DRY_RUN" = 1 ]; then
    echo "${kind:-step} $name"
    return 0
  fi
  DONE=$((DONE + 1))
  log="$OUT/logs/$(printf %02d "$DONE")-$(printf %s "$name" | tr -c 'A-Za-z0-9.-' '_').log"
  t0=$(date +%s.%N)
  if [ "$TERMINAL" = 1 ]; then printf '[%d/%d] %s ...\r' "$DONE" "$STEPS" "$name"; fi
  rc=0
  "$@" >"$log" 2>&1 || rc=$?
  t1=$(date +%s.%N)
  if [ "$rc" != 0 ]; then
    echo "bench-suite: [$DONE/$STEPS] $name FAILED (exit $rc); the end of $log:" >&2
    tail -n 20 "$log" >&2
    exit "$rc"
  fi
  if [ "$QUIET" = 0 ]; then
    left=""
    if [ "$TERMINAL" = 1 ] && [ "$DONE" -lt "$STEPS" ]; then
      left=$(awk -v s="$STARTED" -v t="$t1" -v d="$DONE" -v n="$STEPS" \
        'BEGIN { printf ", about %.0f s left", (t - s) / d * (n - d) }')
    fi
    awk -v a="$t0" -v b="$t1" -v i="$DONE" -v n="$STEPS" -v name="$name" -v left="$left" -v file="$log" \
      'BEGIN { printf "bench-suite: [%d/%d] %s: %.1f s%s (log %s)\n", i, n, name, b - a, left, file }'
  fi
}

# The steps' commands; those whose result is their stdout write it themselves (the log keeps stderr).
# have_bench NAME: whether the build has that benchmark program (benchmarks can be off); says so when not.
have_bench() {
  [ -x "$BUILD/bench/$1" ] && return 0
  echo "bench-suite: no $BUILD/bench/$1: skipped" >&2
  return 1
}
peer_quick() {
  "$BUILD/bench/bench_llvmpipe" --scenes=sphere_8k,fullscreen_quad --sizes=512x512 --images="$OUT/images" \
      --benchmark_filter='sphere_8k/512x512/(gouraud|phong)/|fullscreen_quad/512x512/gouraud/|fill_limit' \
      --benchmark_min_time=0.05 \
      --benchmark_out="$OUT/peer.json" --benchmark_out_format=json
}
# Every case, one run per size (the 1920x1080 run holds the targets' ratios), 3 repetitions in random
# order (a noisy spell on this shared machine then does not fall on one case only); medians.
# A size whose result file exists is not run again (resume after an interruption; delete it to rerun).
peer_size() {
  if [ -s "$OUT/peer-$1.json" ]; then
    echo "bench-suite: $OUT/peer-$1.json exists: not run again" >&2
    return 0
  fi
  "$BUILD/bench/bench_llvmpipe" --sizes="$1" --images="$OUT/images" \
      --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true \
      --benchmark_report_aggregates_only=true --benchmark_min_time=0.3 \
      --benchmark_out="$OUT/peer-$1.json" --benchmark_out_format=json
  "$PYTHON" scripts/check_bench_json.py "$OUT/peer-$1.json" || echo "bench-suite: check failed: see above" >&2
}
# The targets' scenes frame by frame against llvmpipe (bench/README.md, "Against the peer on a noisy host").
peer_pairs() {
  have_bench bench_peer_pairs || return 0
  "$BUILD/bench/bench_peer_pairs" --pairs 30 --json "$OUT/paired-peer.json"
}
# Interpolator count -> modeled and measured speed-up and error (Gouraud on the teapot and the sphere).
scaling_scene() {
  "$BUILD/parashade" scaling "scenes/$1.json" -q \
      --units classic,counter,interleave:2,interleave:4,interleave:8,segment:8,segment:16,segment:64,pipelined:4,pipelined:16,sierpinski \
      --arith float,fixed:12.12 --frames 9 --report "$OUT/scaling-$1.json"
}
hw_synthesis() { BUILD="$BUILD" "$PYTHON" scripts/hw_synth.py --out "$OUT/hw" >"$OUT/hw-synthesis.txt"; }
hw_pnr() { BUILD="$BUILD" "$PYTHON" scripts/hw_pnr.py --out "$OUT/hw" --seeds 3 >"$OUT/hw-pnr.txt"; }
span_setup() {
  have_bench bench_span_setup || return 0
  "$BUILD/bench/bench_span_setup" --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true \
      --benchmark_report_aggregates_only=true --benchmark_min_time=0.1 \
      --benchmark_out="$OUT/span.json" --benchmark_out_format=json
  "$BUILD/bench/bench_span_setup" --print-table >"$OUT/span-table.txt"  # [Romanyuk & Obidnyk 2011, faster shading] Table 1 recomputed
  "$BUILD/bench/bench_span_setup" --print-ops >"$OUT/span-ops.txt"      # operation counts, example triangle
}
combined_study() {
  # shellcheck disable=SC2086
  "$PYTHON" scripts/combined_study.py --binary "$BUILD/parashade" --scenes $PHONG_SCENES --frames 11 --rounds 5 \
      --pairing in-process \
      --methods phong gouraud combined:2 combined:3 combined:4 combined:auto@1 combined:auto@2 combined:auto@4 \
                "combined:auto@1 --triangle-choice none" "combined:0 --triangle-choice sources" \
                "combined:0 --triangle-choice sources-literal" "combined:0 --highlight-test" \
                "combined:0@2 --triangle-choice bound" "combined:0@4 --triangle-choice bound" \
                "combined:0@8 --triangle-choice bound" "combined:0@16 --triangle-choice bound" \
                "combined:0@20 --triangle-choice bound" \
      --json "$OUT/combined-study.json" >"$OUT/combined-study.md"
}
phong_methods() {
  # shellcheck disable=SC2086
  "$PYTHON" scripts/phong_methods.py --binary "$BUILD/parashade" --scenes $PHONG_SCENES \
      --frames 11 --json "$OUT/phong-methods.json" >"$OUT/phong-methods.md"
}
# Any Gouraud/Phong mix within NMSE 1e-4 against an oracle's (docs/triangle-choice.md §8), on the target scenes.
mix_oracle() {
  # shellcheck disable=SC2086
  "$PYTHON" scripts/mix_oracle.py --binary "$BUILD/parashade" --scenes $ORACLE_SCENES --frames 30 --budgets 8 16 20 \
      --json "$OUT/mix-oracle.json" --markdown "$OUT/mix-oracle.md" >/dev/null
}
normalize_bench() {
  have_bench bench_normalize || return 0
  "$BUILD/bench/bench_normalize" --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true \
      --benchmark_report_aggregates_only=true --benchmark_min_time=0.1 \
      --benchmark_out="$OUT/normalize.json" --benchmark_out_format=json
}
# The host's steadiness now (bench/README.md, "Is the host steady?"): recorded before and after the run.
host_noise() {
  have_bench bench_host_noise || return 0
  "$BUILD/bench/bench_host_noise" --json "$OUT/host-noise-$1.json"
}
report() {
  "$PYTHON" scripts/report.py "$OUT"/peer-*.json "$OUT"/paired-peer.json "$OUT"/scaling-*.json "$OUT/memory.json" \
      "$OUT/combined-study.json" "$OUT/phong-methods.json" --images "$OUT/images" -o "$OUT/report"
}

PHONG_SCENES="scenes/sphere.json scenes/teapot.json scenes/robot.json"
ORACLE_SCENES="scenes/sphere.json scenes/teapot.json"
if [ -n "${PARASHADE_MESH_DIR:-}" ]; then
  PHONG_SCENES="$PHONG_SCENES scenes/bunny.json"
  ORACLE_SCENES="$ORACLE_SCENES scenes/bunny.json"
fi

suite() {
  if [ "$QUICK" = 1 ]; then
    step "peer 512x512 (quick)" peer_quick
    step "check peer.json" "$PYTHON" scripts/check_bench_json.py "$OUT/peer.json"
    step "phong-study" "$BUILD/parashade" phong-study -q --report "$OUT/phong-study.json"  # ~2 s
    step "claims" "$PYTHON" scripts/claims.py --results "$OUT" -o "$OUT/claims.md"  # the registry parses, the generator runs
    return 0
  fi

  step "host noise (before)" host_noise before
  if [ "$PHONG_ONLY" = 0 ]; then
    for size in 1920x1080 512x512 3840x2160; do step "peer $size" peer_size "$size"; done
    step "peer pairs 1920x1080" peer_pairs
    for scene in teapot sphere; do step "scaling $scene" scaling_scene "$scene"; done
    # Fixed-point error of the units against the source's formulas ([Malovanyi 2019, parallel Gouraud] ch. 3).
    step "unit-error" "$BUILD/parashade" unit-error -q --report "$OUT/unit-error.json"
    # The units' RTL synthesized (Yosys): adders, flip-flops, muxes, depth per M, P; throughput against area
    # (docs/hardware.md; ~10 min). Skipped without yosys.
    if [ "$NO_HW" = 1 ]; then
      :  # --no-hw
    elif command -v yosys >/dev/null 2>&1; then
      step "hw synthesis" hw_synthesis
    else
      warn "yosys is not installed: no synthesis of hw/ (scripts/install-deps.sh)"
    fi
    # The same units placed and routed on an iCE40HX8K (nextpnr-ice40, 3 seeds each, niced, one at a time):
    # Fmax, LUTs, carries, FFs, pixels per microsecond (docs/hardware.md, "Place and route"; ~15 min).
    if [ "$NO_HW" = 1 ]; then
      :  # --no-hw
    elif command -v yosys >/dev/null 2>&1 && command -v nextpnr-ice40 >/dev/null 2>&1; then
      step "hw place and route" hw_pnr
    else
      warn "yosys or nextpnr-ice40 is not installed: no place and route of hw/ (scripts/install-deps.sh --test)"
    fi
    # Host model of whole-triangle shading: constant increment and shift-add division ([Gouraud simplification], [Romanyuk & Obidnyk 2011, faster shading]).
    step "span setup" span_setup
  fi

  # Phong family ([Romanyuk & Romanyuk, combined shading]; [Dembitsky 2025, software/hardware rendering] ch. 2-3): approximation errors (parashade phong-study), the combined method's and the
  # normalization / specular variants' speed and error through render reports, the host normalization
  # methods in scalar C++ (bench_normalize), and the best variant at NMSE <= 1e-4 derived from the two studies.
  step "phong-study" "$BUILD/parashade" phong-study -q --report "$OUT/phong-study.json"
  step "combined study" combined_study
  step "phong methods" phong_methods
  step "mix oracle" mix_oracle
  step "normalize bench" normalize_bench
  if [ "$PHONG_ONLY" = 0 ]; then
    step "peak memory" "$PYTHON" scripts/peak_memory.py --binary "$BUILD/parashade" -o "$OUT/memory.json"
  fi
  step "host noise (after)" host_noise after

  # From here on every result is in: shard 0 alone goes on (the other shards have ended).
  final_step "best method" "$PYTHON" scripts/best_method.py --combined "$OUT/combined-study.json" \
      --methods "$OUT/phong-methods.json" -o "$OUT/best-method.json"
  if [ "$PHONG_ONLY" = 0 ]; then
    if "$PYTHON" -c "import matplotlib" 2>/dev/null; then
      final_step "report" report
    else
      warn "python3-matplotlib is not installed: no plots (apt-get install python3-matplotlib)"
    fi
  fi
  final_step "claims" "$PYTHON" scripts/claims.py --results "$OUT" -o "$OUT/report/claims.md"
}

suite
COUNTING=0
STEP_INDEX=0  # the real pass deals the steps again, in the same order
if [ "$QUICK" = 0 ]; then mkdir -p "$OUT/report"; fi
suite
say "results in $OUT (logs in $OUT/logs)"
