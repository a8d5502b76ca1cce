#!/usr/bin/env python3
"""The units' depth pass as work-items of one device against the same units on its sub-devices
(docs/planner.md, "Mapping the units onto OpenCL"): renders SCENE plainly, then with `--cu U --partition P`
on --device and on each --sub selector, the configurations interleaved in rounds (outside load spreads
over all of them). Every planned image is compared byte for byte with the plain one. Prints a Markdown
table of medians over rounds (each run's value is already the median of its frames): the units' pass
(first start to last end), each sub-device's own pass, the key merge, the resolve kernel and the frame.

    scripts/unit_mapping_sweep.py scenes/teapot.json --units 2,8 --partition lpt --rounds 5
"""
import argparse
import filecmp
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from planner_sweep import render  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene")
    ap.add_argument("--binary", default=os.path.join(os.path.dirname(__file__), "..", "build", "parashade"))
    ap.add_argument("--device", default="pthread")
    ap.add_argument("--sub", default="sub:pthread:1", help="comma list of sub-device selectors")
    ap.add_argument("--units", default="2,8")
    ap.add_argument("--partition", default="lpt")
    ap.add_argument("--size", default="1920x1080")
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--rounds", type=int, default=5)
    args = ap.parse_args()
    devices = [args.device] + args.sub.split(",")
    units = [int(u) for u in args.units.split(",")]
    runs, mismatches = {}, []
    with tempfile.TemporaryDirectory() as tmp:
        report, plain, out = (os.path.join(tmp, n) for n in ("r.json", "plain.png", "planned.png"))
        for rnd in range(args.rounds):
            render(args.binary, args.scene, args.size, args.frames, 0, ["--device", args.device], plain, report)
            for u in units:
                for d in devices:
                    extra = ["--device", d, "--cu", str(u), "--partition", args.partition]
                    m = render(args.binary, args.scene, args.size, args.frames, 0, extra, out, report)
                    runs.setdefault((d, u), []).append(m)
                    if not filecmp.cmp(out, plain, shallow=False):
                        mismatches.append((d, u, rnd))
                    print(f"[round {rnd + 1}/{args.rounds}] {d} U={u}: pass {m['unit_pass_ms']:.2f} ms, "
                          f"frame {m['frame_ms']:.1f} ms", file=sys.stderr)

    def med(d, u, get):
        return statistics.median(get(m) for m in runs[(d, u)])

    print(f"{os.path.basename(args.scene)} {args.size}, --partition {args.partition}; median over {args.rounds} "
          f"rounds of each run's median of {args.frames} frames. Images identical to the plain frame: "
          f"{'all' if not mismatches else 'NOT ALL: ' + str(mismatches)}.\n")
    print("| U | --device | units per device/sub-device | units' pass ms | each sub-device's pass ms | key merge ms "
          "| resolve ms | frame ms |")
    print("|---|---|---|---|---|---|---|---|")
    for u in units:
        for d in devices:
            shares = runs[(d, u)][0]["mapping"]["shares"]
            split = " + ".join(str(s["units"]) for s in shares)
            each = " / ".join(f"{med(d, u, lambda m, k=k: m['mapping']['shares'][k]['pass_ms']):.2f}"
                              for k in range(len(shares))) if len(shares) > 1 else "—"
            merge = f"{med(d, u, lambda m: m['key_merge_ms'] or 0):.2f}" if len(shares) > 1 else "—"
            print(f"| {u} | `{d}` | {split} | {med(d, u, lambda m: m['unit_pass_ms']):.2f} | {each} | {merge} | "
                  f"{med(d, u, lambda m: m['kernel_ms']):.2f} | {med(d, u, lambda m: m['frame_ms']):.1f} |")
    return 1 if mismatches else 0


if __name__ == "__main__":
    sys.exit(main())
