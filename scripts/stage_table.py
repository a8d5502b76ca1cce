#!/usr/bin/env python3
"""Per-stage frame times of two parashade binaries side by side (before / after a change), from
`parashade render --report`: geometry, setup, binning, kernel, read-back and the whole frame, the median
over rounds of each run's median frame. Rounds alternate the binaries (and their order), so both see the
same machine.

    scripts/stage_table.py --before old/parashade --after build/parashade \\
        --scene scenes/teapot.json --scene sphere_2m --methods gouraud,phong --frames 40 --rounds 3

Two devices on one binary (alternated runs, as bench/README.md's Run DD):

    scripts/stage_table.py --before build/parashade --before-options "--device pthread" \
        --after build/parashade --after-options "--device 'Intel(R) OpenCL'" --scene scenes/bunny.json --size 1920x1080

A scene is a file, or sphere_131k / sphere_2m (scenes/sphere.json re-tessellated as bench_llvmpipe's). A method
may carry render options after it: --methods "phong,combined:0 --triangle-choice bound --max-error 4".
Prints a Markdown table (ms, before -> after); --json writes the figures.
"""
import argparse
import json
import os
import shlex
import statistics
import subprocess
import sys
import tempfile

from report_schema import schema

STAGES = ["geometry_ms", "setup_ms", "binning_ms", "kernel_ms", "readback_ms", "total_ms"]
SPHERES = {"sphere_8k": (64, 65), "sphere_131k": (256, 257), "sphere_2m": (1024, 1025)}
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def scene_file(name, tmp):
    if name not in SPHERES:
        return name
    with open(os.path.join(ROOT, "scenes", "sphere.json")) as f:
        scene = json.load(f)
    scene["objects"][0]["shape"]["slices"], scene["objects"][0]["shape"]["stacks"] = SPHERES[name]
    path = os.path.join(tmp, name + ".json")
    with open(path, "w") as f:
        json.dump(scene, f)
    return path


def render_report(binary, scene, words, tmp):
    """`parashade render SCENE WORDS` with its image at tmp/image.png and no error figures: its report's dict;
    the script stops, naming the command, when the render fails. device_pairs.py and target_floor.py use it too."""
    report = os.path.join(tmp, "report.json")
    cmd = [binary, "render", scene, "-o", os.path.join(tmp, "image.png"), "--no-error", "-q", "--report", report]
    cmd += words
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"{os.path.basename(sys.argv[0])}: {' '.join(cmd)} failed ({run.returncode}): {run.stderr.strip()}")
    with open(report) as f:
        return json.load(f)


def stages(binary, scene, method, frames, tmp, size=None, options=""):
    words = shlex.split(method)  # the method, then its own render options
    return render_report(binary, scene, ["--method", words[0], "--frames", str(frames)] + words[1:] +
                         (["--size", size] if size else []) + shlex.split(options), tmp)["stages_ms"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--before", required=True, help="parashade binary before the change")
    ap.add_argument("--after", required=True, help="parashade binary after it")
    ap.add_argument("--before-options", default="", help="render options of the before side only (e.g. its --device)")
    ap.add_argument("--after-options", default="", help="render options of the after side only")
    ap.add_argument("--scene", action="append", required=True, help="scene file or sphere_131k / sphere_2m (repeat)")
    ap.add_argument("--methods", default="gouraud,phong", help="comma-separated; each may carry render options")
    ap.add_argument("--frames", type=int, default=40)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--size", help="WIDTHxHEIGHT for every scene (default: each scene's own)")
    ap.add_argument("--json", help="write the figures here")
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name in args.scene:
            scene = scene_file(name, tmp)
            for method in args.methods.split(","):
                runs = {"before": [], "after": []}
                for i in range(args.rounds):
                    # Each round in the other order, so a phase change within a round favours neither binary.
                    for side in ("before", "after") if i % 2 == 0 else ("after", "before"):
                        runs[side].append(stages(getattr(args, side), scene, method, args.frames, tmp, args.size,
                                               getattr(args, side + "_options")))
                        print(f"[{name} {method} {side}] frame {runs[side][-1]['total_ms']:.2f} ms", file=sys.stderr)
                row = {"scene": os.path.splitext(os.path.basename(name))[0], "method": method}
                for side in runs:
                    row[side] = {k: statistics.median(r[k] for r in runs[side]) for k in STAGES}
                rows.append(row)
    print("| scene | method | " + " | ".join(k[:-3] for k in STAGES) + " |")
    print("|---|---|" + "---|" * len(STAGES))
    for r in rows:
        cells = [f"{r['before'][k]:.2f} → {r['after'][k]:.2f}" for k in STAGES]
        print(f"| {r['scene']} | {r['method']} | " + " | ".join(cells) + " |")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"schema": schema("stages"), "before": args.before, "after": args.after,
                       "before_options": args.before_options, "after_options": args.after_options, "frames": args.frames, "rounds": args.rounds,
                       "size": args.size, "rows": rows}, f, indent=1)


if __name__ == "__main__":
    main()
