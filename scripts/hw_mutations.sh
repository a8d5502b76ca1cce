#!/bin/sh
# The hw tests can fail (docs/hardware.md, "Can the tests fail?"): each case flips one bit of one unit's
# RTL (a copy of hw/ in a temporary folder), Verilates that unit alone with tests/hw's testbench and
# checks it against the vectors of the unmutated golden model. Every case must FAIL; the script exits
# non-zero if one passes. Needs verilator and a built parashade (BUILD, default build). ~30 s per case.
#   scripts/hw_mutations.sh [CASE...]     cases: see the list below (default: all)
set -eu
cd "$(dirname "$0")/.."
BUILD="${BUILD:-build}"
case "$BUILD" in /*) ;; *) BUILD="$PWD/$BUILD" ;; esac
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT

# name @ file @ sed expression (one bit) @ top @ I F LANES @ unit spec
cases='classic-start@ps_classic.v@s/acc <= s_in;/acc <= s_in ^ 1;/@classic@12 12 1@classic
classic-length@ps_classic.v@s/last <= length_in - 1.b1;/last <= length_in - 1'"'"'b0;/@classic@12 12 1@classic
counter-right-step@ps_counter.v@s/right <= right - step;/right <= right - (step ^ 1);/@counter@9 1 2@counter
counter-middle@ps_counter.v@s/busy <= xb - xa > 1;/busy <= xb - xa > 0;/@counter@9 1 2@counter
interleave-lane-step@ps_interleave.v@s/mult\[M\*W +: W\];/mult[M*W +: W] ^ 1;/@interleave@12 12 4@interleave:4
interleave-blocking@ps_interleave.v@s/busy \&\& rest > K;/busy \&\& rest >= K;/@interleave@12 12 4@interleave:4
segment-base@ps_segment.v@s/base <= base + mult\[P\*W +: W\];/base <= (base + mult[P*W +: W]) ^ 1;/@segment@12 12 16@segment:16
pipelined-shadow@ps_pipelined.v@s/next_lane_step <= mult\[M\*W +: W\];/next_lane_step <= mult[M*W +: W] ^ 1;/@pipelined@12 12 4@pipelined:4
level-tie@ps_level.v@s/whole + \$signed({{I{1.b0}}, v\[F-1\]})/whole + $signed({{I{1'"'"'b0}}, 1'"'"'b0})/@classic@12 12 1@classic
level-saturation@ps_level.v@s/|r\[I-1:8\]/|r[I-1:9]/@segment@12 12 4@segment:4
multiples-odd@ps_multiples.v@s/m\[(i-1)\*W +: W\] + step;/m[(i-1)*W +: W] + (step ^ 1);/@segment@12 12 16@segment:16'

only="$*"
status=0
echo "$cases" | while IFS='@' read -r name file expr top params spec; do
  if [ -n "$only" ] && ! echo " $only " | grep -q " $name "; then continue; fi
  set -- $params
  i=$1 f=$2 lanes=$3
  dir="$WORK/$name"
  mkdir -p "$dir"
  cp hw/*.v "$dir/"
  sed -i "$expr" "$dir/$file"
  if cmp -s "hw/$file" "$dir/$file"; then echo "$name: the mutation did not apply"; exit 1; fi
  lane_param=""
  case "$top" in interleave|pipelined) lane_param="-GM=$lanes" ;; segment) lane_param="-GP=$lanes" ;; esac
  fill=0
  [ "$top" = pipelined ] && fill=2
  cat > "$dir/rtl_models.hpp" <<HPP
#pragma once
#include "Vmut.h"
namespace hwtest {
struct ModelEntry { const char* name; const char* unit; const char* arith; int lanes, width, fill;
  Outcome (*check)(const Vectors&, int, int, int); };
inline const ModelEntry kModels[] = {{"mut", "$spec", "fixed:$i.$f", $lanes, $((i + f)), $fill, &check_rtl<Vmut>}};
}
HPP
  "$BUILD/parashade" vectors --unit "$spec" --arith "fixed:$i.$f" --spans 60 --seed "$lanes" -o "$dir/vectors.txt"
  verilator --cc --exe --build -j 1 -Wno-fatal --prefix Vmut --top-module "ps_$top" -GI="$i" -GF="$f" $lane_param \
      -Mdir "$dir/obj" -CFLAGS "-O1 -std=c++17 -I$PWD/tests/hw -I$dir" "$dir"/*.v "$PWD/tests/hw/test_rtl.cpp" \
      >"$dir/build.log" 2>&1 || { echo "$name: build failed"; tail "$dir/build.log"; exit 1; }
  echo "== $name: $file: $(diff "hw/$file" "$dir/$file" | grep '^>' | sed 's/^> *//')"
  if "$dir/obj/Vmut" mut "$dir/vectors.txt"; then
    echo "$name: PASSED with the mutation: the tests cannot see it"
    exit 1
  fi
done || status=1
exit "$status"
