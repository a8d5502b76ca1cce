#!/usr/bin/env python3
"""The project's target "the best method at NMSE <= 1e-4 against exact Phong is >= 1.5x faster than exact
Phong", derived from two result files of one suite run: the combined study (scripts/combined_study.py --json:
combined:K / combined:auto against --method phong) and the Phong variants (scripts/phong_methods.py --json:
--normalize / --specular against exact / exact). Per scene: every row whose NMSE against exact
(perspective-correct) Phong is within the limit, and the fastest of them by frame-time ratio to its own
baseline in the same run. The baselines themselves (phong, exact/exact) count as candidates with ratio 1.

    scripts/best_method.py --combined combined.json --methods phong-methods.json -o best-method.json
"""
import argparse
import json
import os

from report_schema import schema


def candidates(combined, methods):
    rows = []
    for m in (combined or {}).get("measurements", []):
        rows.append({"scene": m["scene"], "variant": "--method " + m["method"], "study": "combined_study",
                     "baseline": m["method"] == "phong",
                     "frame_ratio": 1.0 if m["method"] == "phong" else m["frame_ratio"],
                     "kernel_ratio": 1.0 if m["method"] == "phong" else m["kernel_ratio"],
                     "nmse_vs_exact_phong": m["error_vs_exact_phong"]["nmse"],
                     "ceiling_frame_ratio": m.get("ceiling_frame_ratio")})
    for r in (methods or {}).get("rows", []):
        base = r["normalize"] == "exact" and r["specular"] == "exact"
        rows.append({"scene": r["scene"], "variant": f"--method phong --normalize {r['normalize']} --specular {r['specular']}",
                     "study": "phong_methods", "baseline": base, "frame_ratio": 1.0 if base else r["frame_ratio"],
                     "kernel_ratio": 1.0 if base else r["kernel_ratio"], "nmse_vs_exact_phong": r["nmse"]})
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--combined", help="scripts/combined_study.py --json output")
    ap.add_argument("--methods", help="scripts/phong_methods.py --json output")
    ap.add_argument("--max-nmse", type=float, default=1e-4)
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args()
    docs = []
    for path in (args.combined, args.methods):
        docs.append(json.load(open(path)) if path and os.path.exists(path) else None)
    rows = candidates(*docs)
    if not rows:
        raise SystemExit("best_method: no rows in the given result files")
    def fastest(pool):
        best = {}
        for r in pool:
            if r["nmse_vs_exact_phong"] <= args.max_nmse and r["frame_ratio"] > best.get(r["scene"], {"frame_ratio": -1})["frame_ratio"]:
                best[r["scene"]] = r
        return [v for _, v in sorted(best.items())]
    out = {"schema": schema("best-method"), "max_nmse": args.max_nmse,
           "note": "frame_ratio = baseline frame time / variant frame time, baseline from the same run (exact Phong); "
                   "best_other leaves the baselines out: the fastest other variant, faster than exact Phong or not",
           "best": fastest(rows), "best_other": fastest([r for r in rows if not r["baseline"]]),
           "candidates": rows}
    tmp = args.output + ".tmp"
    with open(tmp, "w") as f:
        json.dump(out, f, indent=1)
    os.replace(tmp, args.output)
    for key in ("best", "best_other"):
        for b in out[key]:
            limit = b.get("ceiling_frame_ratio")
            print(f"best_method: {key}: {b['scene']}: {b['variant']} {b['frame_ratio']:.2f}x (NMSE {b['nmse_vs_exact_phong']:.1e}"
                  + ("" if limit is None else f"; ceiling with a kernel of no overhead {limit:.2f}x") + ")")


if __name__ == "__main__":
    main()
