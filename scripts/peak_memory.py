#!/usr/bin/env python3
"""Peak resident memory of whole `parashade render` processes (Gouraud, --no-error, 1920x1080 unless
--size), one process per scene, measured by GNU time (%M, KiB). The process includes PoCL and its LLVM,
the OpenCL buffers and the host's geometry. Writes JSON: {"schema": "parashade.memory/1", "rows": [{"scene", "width",
"height", "triangles", "peak_rss_mib", "over_baseline_mib", "frame_ms"}], "baseline_mib", "command"}; the
baseline is the peak of `parashade devices` (the OpenCL runtime alone). The memory budget of the targets
(2 x (frame buffers + mesh) + 64 MiB) is computed by bench_llvmpipe (memory_budget_mib) for the same scene.

    scripts/peak_memory.py --binary build/parashade -o memory.json
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

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


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=os.path.join(HERE, "..", "build", "parashade"))
    ap.add_argument("--size", default="1920x1080")
    ap.add_argument("--method", default="gouraud")
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args()
    root = os.path.join(HERE, "..")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, (path, sphere) in SCENES.items():
            if name in ("bunny", "fandisk") and not os.environ.get("PARASHADE_MESH_DIR"):
                print(f"peak_memory: PARASHADE_MESH_DIR is not set: {name} skipped", file=sys.stderr)
                continue
            scene_file = os.path.join(root, path)
            if sphere:
                with open(scene_file) as f:
                    scene = json.load(f)
                scene["objects"][0]["shape"].update({"slices": sphere[0], "stacks": sphere[1]})
                scene_file = os.path.join(tmp, name + ".json")
                with open(scene_file, "w") as f:
                    json.dump(scene, f)
            report = os.path.join(tmp, "r.json")
            cmd = ["/usr/bin/time", "-f", "%M", args.binary, "render", scene_file, "-o", os.path.join(tmp, "o.png"),
                   "--method", args.method, "--size", args.size, "--no-error", "-q", "--frames", "3",
                   "--report", report]
            p = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            if p.returncode != 0:
                sys.exit(f"peak_memory: {' '.join(cmd)} failed:\n{p.stderr}")
            kib = int(p.stderr.strip().splitlines()[-1])
            with open(report) as f:
                r = json.load(f)
            rows.append({"scene": name, "width": r["width"], "height": r["height"], "method": args.method,
                         "triangles": r["triangles"]["in"], "peak_rss_mib": kib / 1024.0,
                         "frame_ms": r["frame_ms"], "device": r["device"]})
            print(f"{name}: peak {kib / 1024.0:.1f} MiB", file=sys.stderr)
        # The fixed cost of the process: the OpenCL runtime (PoCL and its LLVM) listing the devices.
        p = subprocess.run(["/usr/bin/time", "-f", "%M", args.binary, "devices"], stdout=subprocess.DEVNULL,
                           stderr=subprocess.PIPE, text=True)
        baseline = int(p.stderr.strip().splitlines()[-1]) / 1024.0 if p.returncode == 0 else None
    for r in rows:
        r["over_baseline_mib"] = r["peak_rss_mib"] - baseline if baseline is not None else None
    out = {"schema": "parashade.memory/1", "command": " ".join(sys.argv), "baseline_mib": baseline,
           "baseline_note": "peak RSS of 'parashade devices' (OpenCL runtime, no frame)", "rows": rows}
    tmp_out = args.output + ".tmp"
    with open(tmp_out, "w") as f:
        json.dump(out, f, indent=2)
    os.replace(tmp_out, args.output)


if __name__ == "__main__":
    main()
