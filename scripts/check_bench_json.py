#!/usr/bin/env python3
"""Checks a bench_llvmpipe JSON result is produced and sane (used by the CI smoke test and the suite):
the GL renderer is llvmpipe; every case ran (no error, no skip); frame times, throughputs and peak memory
are positive and finite; the peer and parashade agree on geometry (coverage mismatches at most
--max-mismatch of the compared pixels: a few edge pixels, not a different picture); the error against
exact Phong is finite (and its mean FLIP, where the run has it, in [0, 1]), and llvmpipe's and parashade's
NMSE for the same scene, size and method agree within a factor --nmse-agree (the same picture shaded the
same way), and below --max-nmse except for flat shading and on fullscreen_quad (two triangles: Gouraud's
worst case; a large NMSE is right there). Exit 0 when sane, 1 otherwise.

    scripts/check_bench_json.py peer.json
"""
import argparse
import json
import math
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("results")
    ap.add_argument("--max-mismatch", type=float, default=0.005, help="fraction of compared pixels")
    ap.add_argument("--max-nmse", type=float, default=0.05)
    ap.add_argument("--nmse-agree", type=float, default=2.0)
    args = ap.parse_args()
    with open(args.results) as f:
        r = json.load(f)
    problems = []
    renderer = r.get("context", {}).get("gl_renderer", "")
    if "llvmpipe" not in renderer:
        problems.append(f"GL renderer is '{renderer}', not llvmpipe")
    benches = [b for b in r.get("benchmarks", []) if b.get("run_type") == "iteration" or b.get("aggregate_name") == "median"]
    if not benches:
        problems.append("no benchmark results")
    peers = set()
    nmse_by_case = {}
    for b in benches:
        name = b.get("run_name", b["name"])
        if b.get("error_occurred"):
            problems.append(f"{name}: {b.get('error_message')}")
            continue
        for key in ("frame_ms", "mpixel_per_s"):
            v = b.get(key)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                problems.append(f"{name}: {key} = {v}")
        if name.startswith(("fill_limit", "plane_fill_limit", "phong_plane_fill_limit")):
            continue
        peers.add(name.split("/")[0])
        if not (b.get("peak_rss_mib", 0) > 0):
            problems.append(f"{name}: peak_rss_mib = {b.get('peak_rss_mib')}")
        if "pixels_compared" in b:
            compared, mismatch = b["pixels_compared"], b["coverage_mismatch"]
            if compared <= 0 or mismatch > args.max_mismatch * compared:
                problems.append(f"{name}: {mismatch:.0f} coverage mismatches of {compared:.0f} pixels")
            nmse = b.get("nmse")
            if not (isinstance(nmse, (int, float)) and math.isfinite(nmse)) or \
                    (nmse >= args.max_nmse and "/fullscreen_quad/" not in name and "/flat" not in name):
                problems.append(f"{name}: NMSE against exact Phong = {nmse}")
            nmse_by_case[name] = nmse
            flip = b.get("flip_mean")
            if flip is not None and not (isinstance(flip, (int, float)) and 0 <= flip <= 1):
                problems.append(f"{name}: mean FLIP against exact Phong = {flip} (LDR-FLIP is in [0, 1])")
    for name, nmse in nmse_by_case.items():
        if not name.startswith("llvmpipe/"):
            continue
        other = nmse_by_case.get("parashade/" + name[len("llvmpipe/"):])
        if other is not None and nmse > 0 and other > 0 and max(nmse / other, other / nmse) > args.nmse_agree:
            problems.append(f"{name}: NMSE {nmse:.3g} against parashade's {other:.3g}: not the same picture")
    for p in ("llvmpipe", "parashade"):
        if p not in peers:
            problems.append(f"no {p} case in the results")
    for p in problems:
        print("check_bench_json:", p, file=sys.stderr)
    if problems:
        return 1
    print(f"check_bench_json: {len(benches)} results sane (GL renderer {renderer})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
