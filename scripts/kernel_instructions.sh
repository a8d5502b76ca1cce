#!/bin/sh
# Counts the instructions the render_tiles kernel executes for one `parashade render` (callgrind, counting only
# inside PoCL's work-group function), so two builds of a kernel can be compared on a host too noisy for timings.
# The count is the same from run to run; it is a proxy for time (a cache miss or a long division counts as one
# instruction), so confirm a lever with alternating timed rounds on a quiet machine.
#
#   scripts/kernel_instructions.sh BINARY SCENE [render options...]
#   scripts/kernel_instructions.sh build/parashade scenes/bunny.json --method phong
#
# Renders two frames (and one untimed frame first, so PoCL's cache holds the kernel and valgrind does not count
# the compiler). POCL_CACHE_DIR defaults to a directory per binary under /tmp. Needs valgrind.
set -eu
if [ $# -lt 2 ]; then
  echo "usage: $0 BINARY SCENE [render options...]" >&2
  exit 2
fi
binary=$1
scene=$2
shift 2
command -v valgrind >/dev/null 2>&1 || { echo "$0: valgrind is not installed (apt-get install valgrind)" >&2; exit 2; }
[ -x "$binary" ] || { echo "$0: $binary is not an executable" >&2; exit 2; }
[ -f "$scene" ] || { echo "$0: no scene file $scene" >&2; exit 2; }
POCL_CACHE_DIR="${POCL_CACHE_DIR:-/tmp/parashade-kernel-instructions-$(cksum "$binary" | cut -d' ' -f1)}"
export POCL_CACHE_DIR
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$binary" render "$scene" --no-tuned --frames 1 --no-error -q -o "$work/warm.png" "$@" >/dev/null
valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out" \
  --toggle-collect='_pocl_kernel_render_tiles_workgroup*' \
  "$binary" render "$scene" --no-tuned --frames 2 --no-error -q -o "$work/frame.png" "$@" \
  >/dev/null 2>"$work/valgrind.log" || { cat "$work/valgrind.log" >&2; exit 1; }
count=$(sed -n 's/.*Collected : *\([0-9]*\).*/\1/p' "$work/valgrind.log")
[ -n "$count" ] || { cat "$work/valgrind.log" >&2; echo "$0: no count in valgrind's output" >&2; exit 1; }
echo "$count"
