#!/usr/bin/env python3
"""Peak resident memory of whole `parashade render` processes (--no-error, 3 frames, 1920x1080 unless
--size), one process per scene and method (Gouraud and Phong unless --methods), measured by GNU time (%M,
KiB). The process includes PoCL and its LLVM, the OpenCL buffers and the host's geometry. Writes JSON:
{"schema": "parashade.memory/2", "rows": [{"scene", "method", "width", "height", "triangles", "peak_rss_mib",
"over_baseline_mib", "frame_bytes", "mesh_bytes", "budget_mib", "within_budget", "bands", "frame_ms"}],
"baseline_mib", "command"}; the baseline is the peak of `parashade devices` (the OpenCL runtime alone).
The budget of issue 16's target is 2 x (frame + mesh) + 64 MiB, with frame = width x height x 8 bytes
(RGBA8 colour + 32-bit depth) and mesh = the render report's mesh bytes (24 per vertex, 12 per triangle),
the formula of bench_llvmpipe's memory_budget_mib; within_budget compares over_baseline_mib with it.
--check exits 1 when a row is over its budget (the ctest PeakMemory.Sphere2mWithinBudget).

    scripts/peak_memory.py --binary build/parashade -o memory.json
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

from report_schema import schema

MIB = 1024.0 * 1024.0
HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = {  # benchmark name -> (scene file, sphere slices/stacks override)
    "sphere_8k": ("scenes/sphere.json", (64, 65)),
    "sphere_131k": ("scenes/sphere.json", (256, 257)),
    "sphere_2m": ("scenes/sphere.json", (1024, 1025)),
    "teapot": ("scenes/teapot.json", None),
    "robot": ("scenes/robot.json", None),
    "bunny": ("scenes/bunny.json", None),
    "fandisk": ("scenes/fandisk.json", None),
}


def measure(args, root, tmp, name, method):
    path, sphere = SCENES[name]
    if name in ("bunny", "fandisk") and not os.environ.get("PARASHADE_MESH_DIR"):
        print(f"peak_memory: PARASHADE_MESH_DIR is not set: {name} skipped", file=sys.stderr)
        return None
    scene_file = os.path.join(root, path)
    if sphere:
        with open(scene_file) as f:
            scene = json.load(f)
        scene["objects"][0]["shape"].update({"slices": sphere[0], "stacks": sphere[1]})
        scene_file = os.path.join(tmp, name + ".json")
        with open(scene_file, "w") as f:
            json.dump(scene, f)
    report = os.path.join(tmp, "r.json")
    render = [args.binary, "render", scene_file, "-o", os.path.join(tmp, "o.png"), "--method", method, "--no-error",
              "-q", "--no-tuned"]
    # Unmeasured first, the same frame once: the kernels' builds (PoCL specializes a kernel per launch shape,
    # a streamed frame's bands included) go into PoCL's cache, so the measured process finds them built
    # (LLVM's compile memory is the runtime's, not the frame's, and a cold cache would count it).
    subprocess.run(render + ["--size", args.size, "--frames", "1", "--warmup", "0"], stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    cmd = ["/usr/bin/time", "-f", "%M"] + render + ["--size", args.size, "--frames", "3", "--report", report]
    p = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        sys.exit(f"peak_memory: {' '.join(cmd)} failed:\n{p.stderr}")
    kib = int(p.stderr.strip().splitlines()[-1])
    with open(report) as f:
        r = json.load(f)
    frame_bytes = r["width"] * r["height"] * 8  # RGBA8 colour + 32-bit depth
    mesh_bytes = r["mesh"]["bytes"]
    print(f"{name} {method}: peak {kib / 1024.0:.1f} MiB", file=sys.stderr)
    return {"scene": name, "method": method, "width": r["width"], "height": r["height"],
            "triangles": r["triangles"]["in"], "peak_rss_mib": kib / 1024.0, "frame_bytes": frame_bytes,
            "mesh_bytes": mesh_bytes, "budget_mib": 2.0 * (frame_bytes + mesh_bytes) / MIB + 64.0,
            "bands": r["stats"]["bands"], "frame_ms": r["frame_ms"], "device": r["device"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=os.path.join(HERE, "..", "build", "parashade"))
    ap.add_argument("--size", default="1920x1080")
    ap.add_argument("--methods", default="gouraud,phong", help="comma-separated")
    ap.add_argument("--scenes", default=",".join(SCENES), help="comma-separated, of: " + ", ".join(SCENES))
    ap.add_argument("--check", action="store_true", help="exit 1 when a row is over its budget")
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args()
    unknown = [n for n in args.scenes.split(",") if n not in SCENES]
    if unknown:
        sys.exit(f"peak_memory: unknown scene(s) {', '.join(unknown)}; known: {', '.join(SCENES)}")
    root = os.path.join(HERE, "..")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for method in args.methods.split(","):
            for name in args.scenes.split(","):
                row = measure(args, root, tmp, name, method)
                if row:
                    rows.append(row)
        # The fixed cost of the process: the OpenCL runtime (PoCL and its LLVM) listing the devices.
        p = subprocess.run(["/usr/bin/time", "-f", "%M", args.binary, "devices"], stdout=subprocess.DEVNULL,
                           stderr=subprocess.PIPE, text=True)
        baseline = int(p.stderr.strip().splitlines()[-1]) / 1024.0 if p.returncode == 0 else None
    over = []
    for r in rows:
        r["over_baseline_mib"] = r["peak_rss_mib"] - baseline if baseline is not None else None
        r["within_budget"] = r["over_baseline_mib"] <= r["budget_mib"] if baseline is not None else None
        if baseline is not None:
            print(f"{r['scene']} {r['method']}: {r['over_baseline_mib']:.1f} MiB above the runtime, budget "
                  f"{r['budget_mib']:.1f} MiB = 2 x ({r['frame_bytes'] / MIB:.1f} frame + "
                  f"{r['mesh_bytes'] / MIB:.1f} mesh) + 64", file=sys.stderr)
        if r["within_budget"] is False:
            over.append(f"{r['scene']} {r['method']} ({r['over_baseline_mib']:.1f} > {r['budget_mib']:.1f} MiB)")
    out = {"schema": schema("memory"), "command": " ".join(sys.argv), "baseline_mib": baseline,
           "baseline_note": "peak RSS of 'parashade devices' (OpenCL runtime, no frame)", "rows": rows}
    tmp_out = args.output + ".tmp"
    with open(tmp_out, "w") as f:
        json.dump(out, f, indent=2)
    os.replace(tmp_out, args.output)
    if args.check and baseline is None:
        sys.exit("peak_memory: the baseline (parashade devices) failed")
    if args.check and over:
        sys.exit("peak_memory: over the budget: " + ", ".join(over))


if __name__ == "__main__":
    main()
