#!/usr/bin/env python3
"""Two OpenCL devices compared in paired frames: `parashade render --device A --against-device B`, whose frames
alternate the devices in one process, so a host whose speed drifts biases neither (docs/reports.md). Each
scene and method runs in both orders (A's renderer first, then B's first), --runs times each; every run
gives the median over its pairs of B's time / A's time, for the kernel and the whole frame (> 1: A faster).

    OCL_ICD_VENDORS=build/opencl-vendors LD_LIBRARY_PATH=build/intel-opencl-libs \\
    scripts/device_pairs.py --binary build/parashade --a pthread --b "Intel(R) OpenCL" \\
        --scene scenes/teapot.json --scene scenes/bunny.json --scene sphere_131k --size 1920x1080

Each device takes the layout parashade chooses for it (its tuned entry unless --no-tuned is in --options).
Prints a Markdown table: per scene and method, every run's kernel and frame ratio and their medians.
"""
import argparse
import os
import shlex
import statistics
import sys
import tempfile

from stage_table import render_report, scene_file


def pair_ratios(binary, scene, method, main, other, frames, size, options, tmp):
    """(kernel, frame) medians of the pairs' ratios `other` ms / `main` ms from one render --against-device."""
    words = ["--method", method, "--frames", str(frames), "--device", main, "--against-device", other]
    against = render_report(binary, scene, words + (["--size", size] if size else []) + shlex.split(options),
                            tmp)["against"]
    return against["kernel_ratio"]["median"], against["frame_ratio"]["median"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default="build/parashade")
    ap.add_argument("--a", required=True, help="device A (index or name, as render --device)")
    ap.add_argument("--b", required=True, help="device B")
    ap.add_argument("--scene", action="append", required=True, help="scene file or sphere_131k / sphere_2m (repeat)")
    ap.add_argument("--methods", default="gouraud,phong", help="comma-separated")
    ap.add_argument("--frames", type=int, default=60, help="pairs per run")
    ap.add_argument("--runs", type=int, default=2, help="runs in each order")
    ap.add_argument("--size", help="WIDTHxHEIGHT for every scene (default: each scene's own)")
    ap.add_argument("--options", default="", help="render options of both devices (e.g. --no-tuned)")
    args = ap.parse_args()
    print(f"| scene | method | kernel B/A, runs | kernel median | frame B/A, runs | frame median |")
    print("|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for name in args.scene:
            scene = scene_file(name, tmp)
            for method in args.methods.split(","):
                kernel, frame = [], []
                for i in range(args.runs):
                    for a_first in (True, False):  # B's renderer is the against side in one order, A's in the other
                        main, other = (args.a, args.b) if a_first else (args.b, args.a)
                        k, f = pair_ratios(args.binary, scene, method, main, other, args.frames, args.size,
                                           args.options, tmp)
                        kernel.append(k if a_first else 1 / k)
                        frame.append(f if a_first else 1 / f)
                        print(f"[{name} {method} run {i + 1}, A {'main' if a_first else 'against'}] kernel B/A "
                              f"{kernel[-1]:.3f}, frame {frame[-1]:.3f}", file=sys.stderr)
                cells = lambda v: " / ".join(f"{x:.2f}" for x in v)
                label = os.path.splitext(os.path.basename(name))[0]
                print(f"| {label} | {method} | {cells(kernel)} | {statistics.median(kernel):.2f} | {cells(frame)} | "
                      f"{statistics.median(frame):.2f} |", flush=True)


if __name__ == "__main__":
    main()
