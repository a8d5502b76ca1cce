#!/usr/bin/env python3
"""Peak memory per rank of render --distribute with each way of reading the scene (docs/distributed.md,
"Memory"): every rank reads the file (--read-scene every-rank) or rank 0 reads it and scatters the shares
(--read-scene rank-0). Prints a Markdown table of each rank's peak resident size (VmHWM, from the report)
and records held, and checks that both ways give the same image bytes.

    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 PARASHADE_MESH_DIR=/path/to/shared/meshes \\
        scripts/distributed_memory.py --build build --scene scenes/bunny.json --size 1920x1080 --ranks 2,4
    scripts/distributed_memory.py --build build --sphere 2048x1024 --size 640x360 --ranks 2,4

--sphere SLICESxSTACKS renders one procedural sphere of about 2 x SLICES x STACKS triangles instead of
--scene: a mesh large enough for its share of the memory to show beside PoCL's.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default="build")
    ap.add_argument("--scene", default="scenes/bunny.json")
    ap.add_argument("--size", default="1920x1080")
    ap.add_argument("--ranks", default="2,4")
    ap.add_argument("--sphere", help="SLICESxSTACKS: a procedural sphere instead of --scene")
    args = ap.parse_args()
    binary = os.path.join(args.build, "parashade")
    print("| mode | N | read | peak RSS MB per rank | records per rank | load |")
    print("|---|---:|---|---|---|---:|")
    with tempfile.TemporaryDirectory() as tmp:
        if args.sphere:
            slices, stacks = map(int, args.sphere.split("x"))
            args.scene = os.path.join(tmp, "sphere.json")
            with open(args.scene, "w") as f:
                json.dump({"name": "sphere-" + args.sphere, "camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
                           "lights": [{"type": "directional", "direction": [1, -1, -1]}],
                           "objects": [{"shape": {"type": "sphere", "slices": slices, "stacks": stacks}}]}, f)
        for mode in ("sort-last", "sort-first"):
            for n in map(int, args.ranks.split(",")):
                images = []
                for read in ("every-rank", "rank-0"):
                    img, rep = os.path.join(tmp, read + ".png"), os.path.join(tmp, "r.json")
                    load = open("/proc/loadavg").read().split()[0]
                    cmd = ["mpirun", "--oversubscribe", "-np", str(n), binary, "render", args.scene, "-o", img,
                           "--size", args.size, "--no-error", "-q", "--no-tuned", "--frames", "1", "--warmup", "0",
                           "--distribute", mode, "--read-scene", read, "--report", rep]
                    p = subprocess.run(cmd, capture_output=True, text=True)
                    if p.returncode != 0:
                        sys.exit("failed (%d): %s\n%s" % (p.returncode, " ".join(cmd), p.stderr))
                    r = json.load(open(rep))
                    print("| %s | %d | %s | %s | %s | %s |" % (
                        mode, n, read, " / ".join("%.0f" % q["peak_rss_mib"] for q in r["per_rank"]),
                        " / ".join("%d" % q["records"] for q in r["per_rank"]), load), flush=True)
                    images.append(open(img, "rb").read())
                if images[0] != images[1]:
                    sys.exit("%s N=%d: the two ways of reading the scene gave different images" % (mode, n))


main()
