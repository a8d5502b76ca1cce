#!/usr/bin/env python3
"""Measured frame time of the planned frame (docs/planner.md) across strategies, modeled unit counts U and
PoCL thread counts: renders each scene plainly and with `--cu U --partition P` for every P and U, under
POCL_MAX_PTHREAD_COUNT = each of --threads, in rounds (configurations interleaved, so outside load spreads
over all of them). Every planned image is compared byte for byte with the plain one of the same thread
count. Prints Markdown tables of the median (over rounds) of each run's median frame time, with the units'
depth pass and resolve kernel times beside it, and writes everything to --json. Example:

    PARASHADE_MESH_DIR=/path/to/meshes scripts/planner_sweep.py --scenes scenes/teapot.json scenes/bunny.json \\
        --rounds 3 --json planner-sweep.json
"""
import argparse
import filecmp
import json
import os
import statistics
import subprocess
import sys
import tempfile

from report_schema import schema

STRATEGIES = ["round-robin", "lpt", "tiles", "dynamic"]


def render(binary, scene, size, frames, threads, extra, out, report):
    env = dict(os.environ)
    if threads:  # 0: PoCL's default
        env["POCL_MAX_PTHREAD_COUNT"] = str(threads)
    cmd = [binary, "render", scene, "--size", size, "-o", out, "--frames", str(frames), "--no-error", "-q",
           "--no-tuned", "--report", report] + extra
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, env=env)
    with open(report) as f:
        r = json.load(f)
    st = r["stages_ms"]
    return {"frame_ms": r["frame_ms"], "kernel_ms": st.get("kernel_ms"), "unit_pass_ms": st.get("unit_pass_ms"),
            "planning_ms": st.get("planning_ms"), "key_merge_ms": st.get("key_merge_ms"), "device": r["device"]["name"],
            "compute_units": r["device"]["compute_units"], "mapping": r.get("plan", {}).get("mapping")}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=os.path.join(os.path.dirname(__file__), "..", "build", "parashade"))
    ap.add_argument("--scenes", nargs="+", default=["scenes/teapot.json"])
    ap.add_argument("--units", default="1,2,4,8,16,32")
    ap.add_argument("--threads", default="1,2", help="POCL_MAX_PTHREAD_COUNT values")
    ap.add_argument("--size", default="1920x1080")
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--json", default="")
    args = ap.parse_args()
    units = [int(u) for u in args.units.split(",")]
    threads = [int(t) for t in args.threads.split(",")]
    configs = [("plain", 0)] + [(p, u) for p in STRATEGIES for u in units]

    runs = {}  # (scene, threads, strategy, U) -> list of measurements
    mismatches = []
    with tempfile.TemporaryDirectory() as tmp:
        report = os.path.join(tmp, "r.json")
        total = len(args.scenes) * args.rounds * len(threads) * len(configs)
        done = 0
        for scene in args.scenes:
            for rnd in range(args.rounds):
                for th in threads:
                    plain_png = os.path.join(tmp, f"plain-{th}.png")
                    for strategy, u in configs:
                        extra = [] if strategy == "plain" else ["--cu", str(u), "--partition", strategy]
                        out = plain_png if strategy == "plain" else os.path.join(tmp, "planned.png")
                        m = render(args.binary, scene, args.size, args.frames, th, extra, out, report)
                        runs.setdefault((scene, th, strategy, u), []).append(m)
                        if strategy != "plain" and not filecmp.cmp(out, plain_png, shallow=False):
                            mismatches.append((scene, th, strategy, u, rnd))
                        done += 1
                        print(f"[{done}/{total}] {os.path.basename(scene)} threads {th} {strategy} U={u}: "
                              f"{m['frame_ms']:.1f} ms", file=sys.stderr)

    def med(scene, th, strategy, u, key):
        vals = [m[key] for m in runs[(scene, th, strategy, u)] if m[key] is not None]
        return statistics.median(vals) if vals else None

    device = next(iter(runs.values()))[0]["device"]
    print(f"Device: {device}; POCL_MAX_PTHREAD_COUNT = {args.threads}; {args.size}; median over {args.rounds} "
          f"rounds of each run's median of {args.frames} frames. Images identical to the plain frame: "
          f"{'all' if not mismatches else 'NOT ALL: ' + str(mismatches)}.\n")
    for scene in args.scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        print(f"{name}: frame ms, threads {' / '.join(map(str, threads))} (plain: "
              + " / ".join(f"{med(scene, th, 'plain', 0, 'frame_ms'):.1f}" for th in threads) + ")\n")
        print("| strategy | " + " | ".join(f"U={u}" for u in units) + " |")
        print("|---|" + "---|" * len(units))
        for p in STRATEGIES:
            cells = [" / ".join(f"{med(scene, th, p, u, 'frame_ms'):.1f}" for th in threads) for u in units]
            print(f"| {p} | " + " | ".join(cells) + " |")
        print(f"\n{name}: units' depth pass ms / resolve kernel ms, threads {threads[-1]}\n")
        print("| strategy | " + " | ".join(f"U={u}" for u in units) + " |")
        print("|---|" + "---|" * len(units))
        for p in STRATEGIES:
            cells = [f"{med(scene, threads[-1], p, u, 'unit_pass_ms'):.1f} / {med(scene, threads[-1], p, u, 'kernel_ms'):.1f}"
                     for u in units]
            print(f"| {p} | " + " | ".join(cells) + " |")
        print()
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"schema": schema("planner-sweep"), "device": device, "size": args.size, "frames": args.frames, "rounds": args.rounds,
                       "mismatches": mismatches,
                       "runs": [{"scene": s, "threads": th, "strategy": p, "units": u, "measurements": ms}
                                for (s, th, p, u), ms in runs.items()]}, f, indent=1)
    return 1 if mismatches else 0


if __name__ == "__main__":
    sys.exit(main())
