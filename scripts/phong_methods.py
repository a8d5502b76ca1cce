#!/usr/bin/env python3
"""Phong normalization methods and specular models through `parashade render --report` (docs/phong-methods.md):
frame and kernel time, ratio to `--normalize exact --specular exact` (exact Phong, its frames alternating with
the variant's in the same process: `render --against phong`, the median of the pairs' ratios), error against
exact Phong, fallback spans. Prints a Markdown table; --json writes the rows. Example:

    scripts/phong_methods.py --scenes scenes/sphere.json scenes/teapot.json --frames 11
"""
import argparse
import json
import os
import tempfile

from render_report import render_report
from report_schema import schema

VARIANTS = [
    ("exact", "exact"), ("slerp", "exact"), ("quadratic:exact", "exact"), ("quadratic:quad", "exact"),
    ("quadratic:cubic", "exact"), ("quadratic:cubic-fit", "exact"),
    ("exact", "cosk:taylor:2"), ("exact", "cosk:taylor:4"), ("exact", "cosk:lobe:2"), ("exact", "cosk:lobe:4"),
    ("exact", "quadratic"), ("exact", "7n16"), ("quadratic:cubic-fit", "quadratic"),
    ("dichotomy:exact", "exact"), ("dichotomy:linear", "exact"), ("dichotomy:linear:2", "exact"),
    ("dichotomy:linear:3", "exact"), ("dichotomy:quadratic", "exact"),
    ("dichotomy:linear-fit", "exact"), ("dichotomy:quadratic-fit", "exact"), ("dichotomy:exact:4:extrapolate", "exact"),
    ("recurrence", "exact"), ("recurrence:exact:64", "exact"), ("recurrence-diff:exact", "exact"),
    ("recurrence:table", "exact"), ("recurrence:table-fixed:64", "exact"),
]


def render(args, tmp, scene, normalize, specular):
    options = ["--method", "phong", "--normalize", normalize, "--specular", specular, "--frames", str(args.frames),
               "--against", "phong"] + (["--device", args.device] if args.device else [])
    return render_report(args.binary, scene, options, tmp)[0]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=None,
                    help="a parashade command to run each render in a process of its own (default: the Python module "
                         "parashade in this process, docs/python.md; a build without -DPARASHADE_PYTHON=ON has only the command)")
    ap.add_argument("--scenes", nargs="+", default=["scenes/sphere.json", "scenes/teapot.json"])
    ap.add_argument("--frames", type=int, default=11)
    ap.add_argument("--device", default="")
    ap.add_argument("--json", default="")
    args = ap.parse_args()
    rows, device = [], None
    with tempfile.TemporaryDirectory() as tmp:
        for scene in args.scenes:
            # Each variant against exact Phong in its own process: the machine is shared, its speed drifts
            # within a run and from one process to the next.
            for n, s in VARIANTS:
                r = render(args, tmp, scene, n, s)
                b = r["against"]
                device = r["device"]
                m = r["error"]["method"]
                rows.append({"scene": r["scene"], "size": f"{r['width']}x{r['height']}", "normalize": n, "specular": s,
                             "frame_ms": r["frame_ms"], "kernel_ms": r["stages_ms"]["kernel_ms"],
                             "exact_frame_ms": b["frame_ms"], "exact_kernel_ms": b["stages_ms"]["kernel_ms"],
                             "frame_ratio": b["frame_ratio"]["median"], "kernel_ratio": b["kernel_ratio"]["median"],
                             "max_abs": m["max_abs"], "nmse": m["nmse"], "psnr_db": m["psnr_db"],
                             "fallback_spans": r["normalize"]["fallback_spans"], "span_setups": r["normalize"]["span_setups"]})
    print(f"Device: {device['name']} ({device['platform']}), {device['compute_units']} compute units; "
          f"median of {args.frames} frames after 1 warm-up; speed-up = exact time / variant time, the median of the pairs' "
          f"ratios (exact Phong's frames alternating with the variant's in one process).\n")
    print("| scene | size | normalize | specular | frame ms (exact) | kernel ms (exact) | speed-up frame / kernel | vs exact Phong: max levels / NMSE / PSNR dB | fallback spans / setups |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['scene']} | {r['size']} | {r['normalize']} | {r['specular']} | {r['frame_ms']:.1f} ({r['exact_frame_ms']:.1f}) "
              f"| {r['kernel_ms']:.1f} ({r['exact_kernel_ms']:.1f}) "
              f"| {r['frame_ratio']:.2f} / {r['kernel_ratio']:.2f} | {r['max_abs']:.1f} / {r['nmse']:.1e} / {r['psnr_db']:.1f} "
              f"| {r['fallback_spans']} / {r['span_setups']} |")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"schema": schema("phong-methods"), "device": device, "frames": args.frames, "rows": rows}, f, indent=1)


if __name__ == "__main__":
    main()
