#!/usr/bin/env python3
"""Whether a speed target against llvmpipe is within reach of the kernel alone: each scene's frame split into
its host stages and its kernel (`parashade render --report`), the kernel set against its fill floor, and the
best ratio to llvmpipe that a kernel at its floor would give with the host stages as they are
(bench/README.md, run DH).

    scripts/target_floor.py --pairs OUT/paired-peer.json --floors OUT/peer-1920x1080.json \\
        --binary build/parashade --target gouraud=5 --target phong=4

The kernel's fill floor: every pixel the frame covers at the cost of `plane_fill_limit` (Gouraud: its colour
and depth from one triangle's planes, packed and written) or `phong_plane_fill_limit` (Phong: its normal
from planes, normalized, lit and written), and every other pixel at `fill_limit` (the background written),
per pixel as bench_llvmpipe measured them on the whole screen. No triangle setup, span search, depth test or
overdraw: a kernel cannot go below it on this machine. Covered pixels are those of the rendered image that
differ from the scene's background. A scene is one of bench_llvmpipe's (sphere_8k, sphere_131k, sphere_2m,
or scenes/NAME.json).
"""
import argparse
import json
import os
import sys
import tempfile

import numpy as np
from PIL import Image

from stage_table import SPHERES, render_report, scene_file

HOST = ("geometry_ms", "setup_ms", "binning_ms")
FLOOR_OF = {"gouraud": "plane_fill_limit", "phong": "phong_plane_fill_limit"}
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def bench_median(floors, name, size):
    """A bench_llvmpipe case's median time in ms (manual_time)."""
    for b in floors["benchmarks"]:
        if b["name"] in (f"{name}/{size}/manual_time_median", f"{name}/{size}/manual_time"):
            return b["real_time"] * {"ms": 1, "us": 1e-3, "ns": 1e-6}[b.get("time_unit", "ms")]
    sys.exit(f"target_floor.py: no {name}/{size} in the floors file")


def render(binary, scene, method, size, frames, tmp):
    """render's report and the image it wrote (RGB levels)."""
    report = render_report(binary, scene, ["--method", method, "--size", size, "--frames", str(frames)], tmp)
    return report, np.asarray(Image.open(os.path.join(tmp, "image.png")).convert("RGB"))


def covered_fraction(pixels, scene):
    with open(scene) as f:
        background = json.load(f).get("background", [0, 0, 0])
    level = np.round(np.clip(np.asarray(background[:3], dtype=float), 0, 1) * 255).astype(np.uint8)
    return float(np.mean(np.any(pixels != level, axis=2)))


def floor_row(case, stages, covered, floors, size, target):
    """One missed target's figures: `case` a bench_peer_pairs case, `stages` render's stages_ms, `covered` the
    share of pixels the frame covers, `floors` bench_llvmpipe's results at `size`."""
    kernel_floor = covered * bench_median(floors, FLOOR_OF[case["method"]], size) + \
        (1 - covered) * bench_median(floors, "fill_limit", size)
    frame, kernel = stages["total_ms"], stages["kernel_ms"]
    floor_share = (frame - kernel + kernel_floor) / frame  # of the frame, with the kernel at its floor
    now = case["ratio_median"]
    return {"scene": case["scene"], "method": case["method"], "ratio": now, "target": target,
            "host_ms": sum(stages[k] for k in HOST), "kernel_ms": kernel, "frame_ms": frame, "covered": covered,
            "kernel_floor_ms": kernel_floor, "best_ratio": now / floor_share}


def row(case, args, floors, tmp):
    name, method = case["scene"], case["method"]
    scene = scene_file(name if name in SPHERES else os.path.join(ROOT, "scenes", name + ".json"), tmp)
    report, pixels = render(args.binary, scene, method, args.size, args.frames, tmp)
    return floor_row(case, report["stages_ms"], covered_fraction(pixels, scene), floors, args.size,
                     args.targets[method])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--pairs", required=True, help="bench_peer_pairs --json file (the ratios to llvmpipe)")
    ap.add_argument("--floors", required=True, help="bench_llvmpipe JSON with fill_limit, plane_fill_limit and "
                                                    "phong_plane_fill_limit at the pairs' size")
    ap.add_argument("--binary", default="build/parashade")
    ap.add_argument("--frames", type=int, default=40)
    ap.add_argument("--target", action="append", default=[], help="METHOD=RATIO (default gouraud=5, phong=4)")
    ap.add_argument("--json", help="write the rows here")
    args = ap.parse_args()
    args.targets = {"gouraud": 5.0, "phong": 4.0}
    for t in args.target:
        method, ratio = t.split("=")
        args.targets[method] = float(ratio)
    with open(args.pairs) as f:
        pairs = json.load(f)
    with open(args.floors) as f:
        floors = json.load(f)
    args.size = f"{pairs['width']}x{pairs['height']}"
    print(f"| scene | method | × llvmpipe (pairs) | target | host stages ms | kernel ms | covered | kernel floor ms | "
          f"× with the kernel at its floor | remaining |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for case in pairs["cases"]:
            if case["scene"] == "fullscreen_quad":
                continue  # its targets are the floors themselves (report.py's fill table)
            r = row(case, args, floors, tmp)
            rows.append(r)
            verdict = "within the kernel's reach" if r["best_ratio"] >= r["target"] else "host stages too"
            print(f"| {r['scene']} | {r['method']} | {r['ratio']:.2f} | {r['target']:g} | {r['host_ms']:.2f} | "
                  f"{r['kernel_ms']:.2f} | {100 * r['covered']:.0f} % | {r['kernel_floor_ms']:.2f} | "
                  f"{r['best_ratio']:.2f} ({verdict}) | {r['target'] / r['ratio']:.2f}× |", flush=True)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"size": args.size, "rows": rows}, f, indent=1)


if __name__ == "__main__":
    main()
