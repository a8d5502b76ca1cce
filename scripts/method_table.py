#!/usr/bin/env python3
"""Renders scenes with each method through `parashade render --report` and prints one Markdown table of
frame time (median, stage breakdown) and error (implementation and method). Device and compute units
are printed above the table. Example:

    scripts/method_table.py --scenes scenes/sphere.json scenes/teapot.json scenes/robot.json
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=os.path.join(os.path.dirname(__file__), "..", "build", "parashade"))
    ap.add_argument("--scenes", nargs="+", default=["scenes/sphere.json", "scenes/teapot.json", "scenes/robot.json"])
    ap.add_argument("--methods", nargs="+", default=["flat", "gouraud", "phong"])
    ap.add_argument("--frames", type=int, default=21)
    ap.add_argument("--device", default="")
    ap.add_argument("--extra", default="", help="further arguments for 'parashade render', one string")
    args = ap.parse_args()

    rows, device = [], None
    with tempfile.TemporaryDirectory() as tmp:
        for scene in args.scenes:
            for method in args.methods:
                report = os.path.join(tmp, "r.json")
                cmd = [args.binary, "render", scene, "-o", os.path.join(tmp, "out.png"), "--method", method,
                       "--frames", str(args.frames), "--report", report, "-q"] + args.extra.split()
                if args.device:
                    cmd += ["--device", args.device]
                print("running:", " ".join(cmd), file=sys.stderr)
                subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
                with open(report) as f:
                    r = json.load(f)
                device = r["device"]
                s, i, m = r["stages_ms"], r["error"]["implementation"], r["error"]["method"]
                rows.append(
                    f"| {r['scene']} | {r['width']}x{r['height']} | {r['triangles']['in']} / {r['triangles']['after_culling']} "
                    f"| {method} | {r['frame_ms']:.2f} | {s['geometry_ms']:.2f} / {s['setup_ms']:.2f} / {s['binning_ms']:.2f} / "
                    f"{s['kernel_ms']:.2f} / {s['readback_ms']:.2f} | {r['mpixel_per_s']:.0f} "
                    f"| {i['max_abs']:.2f} / {i['nmse']:.1e} | {m['max_abs']:.1f} / {m['nmse']:.1e} / {m['psnr_db']:.1f} |")
    print(f"Device: {device['name']} ({device['platform']}, driver {device['driver']}), "
          f"{device['compute_units']} compute units. Frame: median of {args.frames} after 1 warm-up.\n")
    print("| scene | size | triangles in / after culling | method | frame ms | geometry / setup / binning / kernel / read-back ms "
          "| Mpixel/s | vs own ideal: max levels / NMSE | vs exact Phong: max levels / NMSE / PSNR dB |")
    print("|---|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
