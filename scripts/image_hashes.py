#!/usr/bin/env python3
"""Renders a fixed matrix of scene x method x unit x arithmetic x option cases and records, per case, the
SHA-256 of the image and of the report's deterministic figures (statistics, modeled clocks, plan, error).

A refactoring that must change no behaviour is checked by running it before and after:

    scripts/image_hashes.py --build build-before -o before.json
    scripts/image_hashes.py --build build -o after.json --compare before.json

--compare prints every case whose image or figures differ and exits 1 if any does; --drop KEY leaves
out a report key the change added on purpose (e.g. --drop kernel_build), so the rest is still compared.
The matrix covers the scenes, methods, units, arithmetics, divisions, coverage rules, normalizations, specular models, combined
variants, plans, tile sizes and device splits that the tests and `scripts/bench-suite.sh --quick` use; meshes
from PARASHADE_MESH_DIR (bunny, fandisk) are added when it is set.
"""
import argparse
import concurrent.futures
import hashlib
import json
import os
import subprocess
import sys
import tempfile
import time

SIZE = "192x108"
CORE_SCENES = ["scenes/default.json", "scenes/sphere.json", "scenes/teapot.json", "scenes/robot.json"]
HARD_SCENES = sorted("scenes/hard/" + f for f in os.listdir(os.path.join(os.path.dirname(__file__), "..", "scenes", "hard"))
                     if f.endswith(".json"))
MESH_SCENES = ["scenes/bunny.json", "scenes/fandisk.json"]

UNITS = ["classic", "counter", "interleave:2", "interleave:4", "interleave:4:own", "interleave:8", "segment:8",
         "segment:64", "sierpinski", "sierpinski:2", "sierpinski:1:touch", "sierpinski:1:overlap:seal"]
FIXED = ["fixed:12.12", "fixed:10.4", "fixed:9.4"]

# Every case's options; each is run on every core scene (and the mesh scenes), the first group also on the hard ones.
BASIC = [
    ["--method", "flat"], ["--method", "gouraud"], ["--method", "phong"],
    ["--method", "gouraud", "--units", "classic", "--arith", "fixed:12.12"],
    ["--method", "combined:auto"],
]
CASES = [
    ["--method", "combined:3"], ["--method", "combined:0", "--highlight-test"],
    ["--method", "combined:auto", "--max-error", "2"], ["--method", "combined:auto", "--max-error", "1", "--highlight-test"],
    ["--method", "combined:auto", "--triangle-choice", "sources"],
    ["--method", "combined:auto", "--triangle-choice", "sources-literal"],
    ["--method", "combined:auto", "--triangle-choice", "none"],
    ["--method", "combined:4", "--combined-min-width", "8"],
    ["--method", "gouraud", "--tile", "32"], ["--method", "phong", "--tile", "64"],
    ["--method", "gouraud", "--work-items", "3"],
    ["--method", "gouraud", "--units", "counter", "--arith", "fixed:12.12", "--div", "exact"],
    ["--method", "gouraud", "--units", "classic", "--arith", "fixed:12.12", "--div", "shiftadd:12"],
    ["--method", "gouraud", "--units", "classic", "--arith", "fixed:12.12", "--div", "shiftadd:10:trunc"],
    ["--method", "gouraud", "--coverage", "dda"],
    ["--method", "gouraud", "--coverage", "dda", "--arith", "fixed:12.12"],
    ["--method", "gouraud", "--units", "segment:8", "--coverage", "dda", "--arith", "fixed:10.4"],
    ["--method", "phong", "--units", "counter", "--arith", "fixed:12.12"],
    ["--method", "phong", "--units", "interleave:4"],
    ["--method", "phong", "--units", "segment:8", "--arith", "fixed:10.4"],
    ["--method", "gouraud", "--cu", "3", "--partition", "round-robin"],
    ["--method", "gouraud", "--cu", "3", "--partition", "lpt"],
    ["--method", "gouraud", "--cu", "4", "--partition", "tiles"],
    ["--method", "gouraud", "--cu", "2", "--partition", "dynamic", "--batch", "16"],
    ["--method", "phong", "--cu", "3", "--partition", "lpt"],
    ["--method", "gouraud", "--units", "interleave:4", "--arith", "fixed:12.12", "--cu", "3", "--partition", "lpt"],
    ["--method", "gouraud", "--units", "sierpinski", "--cu", "2", "--partition", "tiles"],
    ["--method", "gouraud", "--device", "sub:pthread:1"],
    ["--method", "gouraud", "--cu", "2", "--partition", "lpt", "--device", "sub:pthread:1"],
    ["--method", "phong", "--device", "sub:pthread:1+1"],
] + [["--method", "phong", "--normalize", n] for n in [
    "slerp", "quadratic:exact", "quadratic:quad", "quadratic:cubic", "quadratic:cubic-fit", "dichotomy:exact",
    "dichotomy:linear:2", "dichotomy:quadratic:3:extrapolate", "dichotomy:linear-fit", "recurrence", "recurrence-diff:table:8",
    "recurrence:table-fixed"]] + [["--method", "phong", "--specular", s] for s in [
    "cosk:taylor:2", "cosk:lobe:4", "quadratic", "7n16", "7n16:3"]] + [
    ["--method", "gouraud", "--units", u, "--arith", a] for u in UNITS for a in ["float"] + FIXED]


def case_list(mesh_dir):
    scenes = list(CORE_SCENES) + (MESH_SCENES if mesh_dir else [])
    out = []
    for s in scenes:
        for opts in BASIC + CASES:
            out.append((s, opts))
    for s in HARD_SCENES:
        for opts in BASIC:
            out.append((s, opts))
    return out


def deterministic(report, extra_drops=()):
    """The report without timings, host load, device names or paths: what must not change. extra_drops:
    keys a change added on purpose (--drop), left out so the rest can be compared with an earlier run."""
    drop_keys = set(extra_drops) | {"device", "devices", "device_info", "host", "command", "time", "load", "scene_file", "output", "tuned", "image",
                 # the report header (docs/reports.md): which build, when, from which command line
                 "schema", "parashade", "created_utc", "command_line", "timing"}

    def strip(v):
        if isinstance(v, dict):
            return {k: strip(x) for k, x in v.items()
                    if k not in drop_keys and not k.endswith("_ms") and not k.endswith("per_s")
                    and not k.startswith("timings")
                    and k not in ("stages_ms", "frames_ms", "per_frame_ms", "samples")}
        if isinstance(v, list):
            return [strip(x) for x in v]
        return v
    return strip(report)


def run_case(build, scene, opts, tmp, index, drops):
    image = os.path.join(tmp, "case%d.png" % index)
    report = os.path.join(tmp, "case%d.json" % index)
    cmd = [os.path.join(build, "parashade"), "render", scene, "-o", image, "--size", SIZE, "--frames", "1",
           "--warmup", "0", "--no-tuned", "-q", "--report", report] + opts
    p = subprocess.run(cmd, capture_output=True, text=True)
    key = " ".join([scene] + opts)
    if p.returncode != 0:
        return key, {"exit": p.returncode, "stderr": p.stderr.strip().splitlines()[-1:] }
    with open(image, "rb") as f:
        image_hash = hashlib.sha256(f.read()).hexdigest()
    with open(report) as f:
        figures = json.dumps(deterministic(json.load(f), drops), sort_keys=True)
    os.remove(image)
    os.remove(report)
    return key, {"exit": 0, "image": image_hash, "figures": hashlib.sha256(figures.encode()).hexdigest()}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build", help="build directory holding the parashade binary")
    ap.add_argument("-o", "--out", required=True, help="write the hashes as JSON here")
    ap.add_argument("--compare", help="hashes JSON of an earlier run: report every difference, exit 1 on any")
    ap.add_argument("--jobs", type=int, default=2, help="renders run at once (default 2)")
    ap.add_argument("--drop", action="append", default=[], metavar="KEY",
                    help="leave report key KEY (at any depth) out of the figures: a key the change added on purpose")
    args = ap.parse_args()
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    if not os.access(os.path.join(args.build, "parashade"), os.X_OK):
        sys.exit("image_hashes.py: no parashade binary in '%s'" % args.build)
    env_devices = os.environ.get("POCL_DEVICES")
    if env_devices is None:
        os.environ["POCL_DEVICES"] = "pthread"
    cases = case_list(os.environ.get("PARASHADE_MESH_DIR"))
    results = {}
    start = time.time()
    with tempfile.TemporaryDirectory() as tmp, concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(run_case, args.build, s, o, tmp, i, args.drop) for i, (s, o) in enumerate(cases)]
        for n, fut in enumerate(concurrent.futures.as_completed(futures), 1):
            key, value = fut.result()
            results[key] = value
            if sys.stderr.isatty():
                print("\r[%d/%d] %.0f s" % (n, len(cases), time.time() - start), end="", file=sys.stderr)
    if sys.stderr.isatty():
        print(file=sys.stderr)
    with open(args.out, "w") as f:
        json.dump(results, f, indent=1, sort_keys=True)
    refused = sum(1 for v in results.values() if v["exit"] != 0)
    print("image_hashes.py: %d cases (%d rendered, %d refused) in %.0f s -> %s"
          % (len(results), len(results) - refused, refused, time.time() - start, args.out))
    if not args.compare:
        return 0
    with open(args.compare) as f:
        before = json.load(f)
    def same(a, b):  # a refused case must stay refused with the same exit code; its message may change
        if a is None or b is None:
            return a is b
        if a["exit"] != 0 or b["exit"] != 0:
            return a["exit"] == b["exit"]
        return a == b
    differ = [k for k in sorted(set(before) | set(results)) if not same(before.get(k), results.get(k))]
    for k in differ:
        print("DIFFERS: %s\n  before %s\n  after  %s" % (k, before.get(k), results.get(k)))
    image_differ = sum(1 for k in differ if before.get(k) and results.get(k) and before[k]["exit"] == 0
                       and results[k]["exit"] == 0 and before[k]["image"] != results[k]["image"])
    print("image_hashes.py: %d of the differing cases differ in the image" % image_differ)
    same_images = sum(1 for k, v in results.items() if v["exit"] == 0 and before.get(k) == v)
    print("image_hashes.py: %d of %d cases identical (%d images byte-identical with identical figures), %d differ"
          % (len(results) - len(differ), len(results), same_images, len(differ)))
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
