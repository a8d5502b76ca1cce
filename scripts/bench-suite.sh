#!/bin/sh
# The benchmark suite in one command: parashade against Mesa llvmpipe (bench_llvmpipe), the modeled
# units' scaling sweep (parashade scaling), standalone peak memory (parashade render under
# /usr/bin/time), the Phong family (phong-study, combined and normalization studies, bench_normalize),
# then the report (plots, image strip, claims table) when python3-matplotlib is present.
#   scripts/bench-suite.sh [OUT_DIR]          whole suite (sizes 1920x1080, 512x512, 3840x2160; ~1 h here)
#   scripts/bench-suite.sh --quick [OUT_DIR]  CI subset: sphere_8k and fullscreen_quad at 512x512 (< 1 min)
#   scripts/bench-suite.sh --phong [OUT_DIR]  the Phong family ([Romanyuk & Romanyuk, combined shading]; [Dembitsky 2025, software/hardware rendering] ch. 2-3) and the claims table only (~5 min)
#   scripts/bench-suite.sh [--phong] --shard K/N [OUT_DIR]   shard K of N: its share of the steps (below)
#   mpirun -np N scripts/bench-suite.sh [--phong] [OUT_DIR]  the same, shard = rank (docs/distributed.md)
#   --dry-run (after --phong, with or without --shard)      list this shard's steps, run nothing
# Environment: PARASHADE_MESH_DIR (bunny, fandisk; skipped without it), PARASHADE_DEVICE, BUILD (default build).
set -eu
cd "$(dirname "$0")/.."
QUICK=0
PHONG_ONLY=0
if [ "${1:-}" = "--quick" ]; then QUICK=1; shift; fi
if [ "${1:-}" = "--phong" ]; then PHONG_ONLY=1; shift; fi
. scripts/bench_shard.sh  # sharding: step, after_all
while :; do
  case "${1:-}" in
    --shard) set_shard "${2:-}"; shift 2 ;;
    --dry-run) BENCH_DRY_RUN=1; shift ;;
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
mkdir -p "$OUT"
export POCL_CACHE_DIR="${POCL_CACHE_DIR:-$BUILD/pocl-cache}"
# The report needs Debian's python3-matplotlib: prefer a python3 that has it (a pyenv shim may not).
PYTHON="${PYTHON:-python3}"
if ! "$PYTHON" -c "import matplotlib" 2>/dev/null && /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  PYTHON=/usr/bin/python3
fi

if [ "$QUICK" = 1 ]; then
  "$BUILD/bench/bench_llvmpipe" --scenes=sphere_8k,fullscreen_quad --sizes=512x512 --images="$OUT/images" \
      --benchmark_filter='sphere_8k/512x512/(gouraud|phong)/|fullscreen_quad/512x512/gouraud/|fill_limit' \
      --benchmark_min_time=0.05 \
      --benchmark_out="$OUT/peer.json" --benchmark_out_format=json >/dev/null
  "$PYTHON" scripts/check_bench_json.py "$OUT/peer.json"
  "$BUILD/parashade" phong-study --json "$OUT/phong-study.json" >/dev/null  # ~2 s: the normalization approximation rows
  "$PYTHON" scripts/claims.py --results "$OUT" -o "$OUT/claims.md"  # the registry parses, the generator runs
  exit 0
fi

if [ "$PHONG_ONLY" = 0 ]; then
# Every case, one run per size (the 1920x1080 run holds the targets' ratios), 3 repetitions in random
# order (a noisy spell on this shared machine then does not fall on one case only); medians.
# A size whose result file exists is not run again (resume after an interruption; delete it to rerun).
for size in 1920x1080 512x512 3840x2160; do
  step "peer-$size" || continue
  if [ -s "$OUT/peer-$size.json" ]; then
    echo "bench-suite: $OUT/peer-$size.json exists: not run again" >&2
    continue
  fi
  "$BUILD/bench/bench_llvmpipe" --sizes=$size --images="$OUT/images" \
      --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true \
      --benchmark_report_aggregates_only=true --benchmark_min_time=0.3 \
      --benchmark_out="$OUT/peer-$size.json" --benchmark_out_format=json >/dev/null
  "$PYTHON" scripts/check_bench_json.py "$OUT/peer-$size.json" || echo "bench-suite: check failed: see above" >&2
done

# Interpolator count -> modeled and measured speed-up and error (Gouraud on the teapot and the sphere).
for scene in teapot sphere; do
  step "scaling-$scene" || continue
  "$BUILD/parashade" scaling "scenes/$scene.json" -q \
      --units classic,counter,interleave:2,interleave:4,interleave:8,segment:8,segment:16,segment:64,pipelined:4,pipelined:16,sierpinski \
      --arith float,fixed:12.12 --frames 9 --report "$OUT/scaling-$scene.json" >/dev/null
done

# Fixed-point error of the units against the source's formulas ([Malovanyi 2019, parallel Gouraud] ch. 3).
if step unit-error; then
"$BUILD/parashade" unit-error --json "$OUT/unit-error.json" >/dev/null
fi

# The units' RTL synthesized (Yosys): adders, flip-flops, muxes, depth per M, P; throughput against area
# (docs/hardware.md; ~10 min). Skipped without yosys.
if ! step hw-synthesis; then :
elif command -v yosys >/dev/null 2>&1; then
  BUILD="$BUILD" "$PYTHON" scripts/hw_synth.py --out "$OUT/hw" >"$OUT/hw-synthesis.txt"
else
  echo "bench-suite: yosys is not installed: no synthesis of hw/ (scripts/install-deps.sh)" >&2
fi

# Host model of whole-triangle shading: constant increment and shift-add division ([Gouraud simplification], [Romanyuk & Obidnyk 2011, faster shading]).
if step span-setup && [ -x "$BUILD/bench/bench_span_setup" ]; then
  "$BUILD/bench/bench_span_setup" --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true \
      --benchmark_report_aggregates_only=true --benchmark_min_time=0.1 \
      --benchmark_out="$OUT/span.json" --benchmark_out_format=json >/dev/null
  "$BUILD/bench/bench_span_setup" --print-table >"$OUT/span-table.txt"  # [Romanyuk & Obidnyk 2011, faster shading] Table 1 recomputed
  "$BUILD/bench/bench_span_setup" --print-ops >"$OUT/span-ops.txt"      # operation counts, example triangle
fi

fi  # PHONG_ONLY

# Phong family ([Romanyuk & Romanyuk, combined shading]; [Dembitsky 2025, software/hardware rendering] ch. 2-3): approximation errors (parashade phong-study), the combined method's and the
# normalization / specular variants' speed and error through render reports, the host normalization
# methods in scalar C++ (bench_normalize), and the best variant at NMSE <= 1e-4 derived from the two studies.
if step phong-study; then
"$BUILD/parashade" phong-study --json "$OUT/phong-study.json" >/dev/null
fi
PHONG_SCENES="scenes/sphere.json scenes/teapot.json scenes/robot.json"
if [ -n "${PARASHADE_MESH_DIR:-}" ]; then PHONG_SCENES="$PHONG_SCENES scenes/bunny.json"; fi
# shellcheck disable=SC2086
step combined-study &&
"$PYTHON" scripts/combined_study.py --binary "$BUILD/parashade" --scenes $PHONG_SCENES --frames 11 --rounds 3 \
    --methods phong gouraud combined:2 combined:3 combined:4 combined:auto@1 combined:auto@2 combined:auto@4 \
              "combined:auto@1 --triangle-choice none" "combined:0 --triangle-choice sources" \
              "combined:0 --triangle-choice sources-literal" "combined:0 --highlight-test" \
    --json "$OUT/combined-study.json" >"$OUT/combined-study.md"
# shellcheck disable=SC2086
step phong-methods &&
"$PYTHON" scripts/phong_methods.py --binary "$BUILD/parashade" --scenes $PHONG_SCENES \
    --frames 5 --json "$OUT/phong-methods.json" >"$OUT/phong-methods.md"
if step normalize && [ -x "$BUILD/bench/bench_normalize" ]; then
  "$BUILD/bench/bench_normalize" --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true \
      --benchmark_report_aggregates_only=true --benchmark_min_time=0.1 \
      --benchmark_out="$OUT/normalize.json" --benchmark_out_format=json >/dev/null
fi
if [ "$PHONG_ONLY" = 0 ] && step memory; then
  "$PYTHON" scripts/peak_memory.py --binary "$BUILD/parashade" -o "$OUT/memory.json"
fi
# From here on every result is in: shard 0 alone goes on (the other shards have ended).
after_all best-method &&
"$PYTHON" scripts/best_method.py --combined "$OUT/combined-study.json" --methods "$OUT/phong-methods.json" \
    -o "$OUT/best-method.json"

if [ "$PHONG_ONLY" = 1 ]; then
  after_all claims || exit 0
  mkdir -p "$OUT/report"
  "$PYTHON" scripts/claims.py --results "$OUT" -o "$OUT/report/claims.md"
  echo "bench-suite: Phong family results in $OUT"
  exit 0
fi

after_all report || exit 0
if "$PYTHON" -c "import matplotlib" 2>/dev/null; then
  "$PYTHON" scripts/report.py "$OUT"/peer-*.json "$OUT"/scaling-*.json "$OUT/memory.json" --images "$OUT/images" \
      -o "$OUT/report"
else
  echo "bench-suite: python3-matplotlib is not installed: no plots (apt-get install python3-matplotlib)" >&2
fi
"$PYTHON" scripts/claims.py --results "$OUT" -o "$OUT/report/claims.md"
echo "bench-suite: results in $OUT"
