#!/usr/bin/env python3
"""One scene's speed-vs-error table of the whole Phong family, from the two result files of one suite run
(scripts/bench-suite.sh --phong): the combined study (methods against --method phong, same round) and the
normalization / specular variants (against --normalize exact --specular exact, run right before each).
Rows sorted by speed-up; error against exact (perspective-correct) Phong. Example:

    scripts/speed_error_table.py --results docs/bench-report/results --scene teapot
"""
import argparse
import json
import os


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--results", required=True, help="directory with combined-study.json and phong-methods.json")
    ap.add_argument("--scene", default="teapot")
    args = ap.parse_args()
    rows = []
    with open(os.path.join(args.results, "combined-study.json")) as f:
        combined = json.load(f)
    for m in combined["measurements"]:
        if m["scene"] != args.scene:
            continue
        e = m["error_vs_exact_phong"]
        rows.append(("--method " + m["method"].replace("@", " --max-error "), m["frame_ratio"],
                     m["kernel_ratio"], m["frame_ms"], e["nmse"], e["psnr_db"], e["max_abs"],
                     m["error_vs_phong"]["max_abs"]))
    with open(os.path.join(args.results, "phong-methods.json")) as f:
        variants = json.load(f)
    for r in variants["rows"]:
        if r["scene"] != args.scene or (r["normalize"] == "exact" and r["specular"] == "exact"):
            continue
        rows.append((f"--method phong --normalize {r['normalize']} --specular {r['specular']}", r["frame_ratio"],
                     r["kernel_ratio"], r["frame_ms"], r["nmse"], r["psnr_db"], r["max_abs"], None))
    rows.sort(key=lambda row: -row[1])
    device = combined["device"]
    print(f"{args.scene}, {device['name']} ({device['compute_units']} compute units). Speed-up: frame (kernel) time of "
          "the baseline over the variant's, measured in the same run; error against exact Phong (NMSE, PSNR, "
          "max levels) and, for the combined rows, max levels against its own ideal (screen-space Phong).\n")
    print("| variant | speed-up frame | kernel | frame ms | NMSE | PSNR dB | max levels | max vs Phong |")
    print("|---|---|---|---|---|---|---|---|")
    for name, fr, kr, ms, nmse, psnr, mx, own in rows:
        own_text = f"{own:.2f}" if own is not None else ""
        print(f"| {name} | {fr:.2f} | {kr:.2f} | {ms:.1f} | {nmse:.2e} | {psnr:.2f} | {mx:.2f} | {own_text} |")


if __name__ == "__main__":
    main()
