#!/usr/bin/env python3
"""How fast can any mix of Gouraud and exact Phong be within an error limit? An oracle's answer, to test the
"best method within NMSE 1e-4 of exact Phong" target of issue 16 against every choice, not only the bound rule's
(docs/triangle-choice.md §8).

For each scene it renders Gouraud and exact Phong with `parashade render`, the exact reference (perspective-correct
Phong in double; `--reference-image` as EXR, split into channels by oiiotool) and the reference's visible triangle
per pixel (`--triangle-map`). A mix shows at each pixel either Gouraud's value or Phong's. Starting from all
Gouraud, the oracle gives Phong the pixels (or whole triangles) that remove the most squared error per pixel,
until the NMSE against the reference (as render computes it) is within --max-nmse:
  * per pixel: the fewest Phong pixels any mix can have, whatever decides them;
  * per triangle: a lower bound for any per-triangle choice (the fractional knapsack: triangles in order of error
    removed per pixel, the last one counted only in part);
  * a centroid rule, what a practical rule could reach: whole triangles in order of |Gouraud - Phong|^2 at the
    visible pixel nearest each one's centroid (one sample, no reference needed).
The figures are checked first: the NMSE of all-Gouraud and all-Phong computed here must equal render's.

The oracle's per-triangle choice in whole triangles (the same order, stopping at the first triangle that reaches the
limit) is then rendered for real: `combined:0 --triangle-choice list:FILE --against phong`, the combined kernel with a
choice that costs next to nothing. Its NMSE must come out as predicted (else the triangle map and the frame number
the triangles differently, and the study stops).

Then `render --method gouraud --against phong` (frames alternating in one process) gives both frames and kernels,
and the bound is Phong's frame over Gouraud's frame plus the share s of the visible pixels at Phong's extra kernel
cost per pixel: P / (G + s (K_P - K_G)), per pair of frames, the median over the pairs. It assumes an oracle that
costs nothing and a kernel that costs each pixel what its own method's kernel costs; the host stages are Gouraud's
(a mix needs Phong's normals too). So it is optimistic: a real mix is slower. It also prints the largest share the
--target ratio allows, and with --budgets the bound rule's choice (`combined:0 --triangle-choice bound
--max-error B`) rendered the same way, for comparison.

    scripts/mix_oracle.py --scenes scenes/teapot.json scenes/bunny.json --json oracle.json --markdown oracle.md
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

from render_report import render_report
from report_schema import schema

try:
    import numpy as np
    from PIL import Image
except ImportError as e:  # python3-numpy and python3-pil (python3-matplotlib brings both)
    sys.exit("mix_oracle.py: needs numpy and Pillow (%s)" % e)


def render(binary, scene, args, tmp, name, size):
    """render_report() into tmp/NAME.png and .json, at --size when given; the report."""
    return render_report(binary, scene, args + (["--size", size] if size else []), tmp, name)[0]


def rgb(path):
    return np.asarray(Image.open(path).convert("RGB"), dtype=np.float64)


def reference_levels(exr, tmp):
    """The EXR's three channels in levels (render writes them divided by 255), via one float TIFF each."""
    channels = []
    for c in "RGB":
        tif = os.path.join(tmp, "ref_%s.tif" % c)
        subprocess.run(["oiiotool", exr, "--ch", c, "-d", "float", "-o", tif], check=True)
        channels.append(np.asarray(Image.open(tif), dtype=np.float64) * 255.0)
    return np.stack(channels, axis=-1)


def triangle_ids(path):
    """render --triangle-map: index + 1 in 24 bits (R high), 0 where no triangle."""
    m = np.asarray(Image.open(path).convert("RGB"), dtype=np.int64)
    return (m[..., 0] << 16) | (m[..., 1] << 8) | m[..., 2]


def by_gain_per_weight(gain, weight, excess):
    """The items in order of gain per unit of weight, and k: the first k + 1 of them remove `excess` (k = len when
    even all do not)."""
    order = np.argsort(-(gain / weight), kind="stable")
    cum = np.cumsum(gain[order])
    return order, cum, int(np.searchsorted(cum, excess))


def fewest_phong(gain, weight, excess):
    """The least weight whose gain reaches `excess`, items taken by gain per unit of weight (fractional knapsack:
    the last item counts in part, which makes it a lower bound for whole items). 0 when nothing is needed;
    None when even everything is not enough."""
    if excess <= 0:
        return 0.0
    order, cum, k = by_gain_per_weight(gain, weight, excess)
    if k >= len(order):
        return None
    before = cum[k - 1] if k > 0 else 0.0
    return float(weight[order][:k].sum() + weight[order][k] * (excess - before) / gain[order][k])


def sampled_rule_share(ids, x, y, G, P, t_gain, excess):
    """What a one-sample rule could do (built and measured in docs/triangle-choice.md §8: it reaches these shares,
    not the speed): whole triangles by Phong in order of |Gouraud - Phong|^2 at one pixel, the visible pixel
    nearest the triangle's visible centroid (ties: the first), until the excess is removed; the number of pixels
    (None if never). A rule on the host samples the triangle's own centroid, so this is an estimate."""
    if excess <= 0:
        return 0.0
    n = np.bincount(ids).astype(np.float64)
    cx = np.bincount(ids, weights=x) / np.maximum(n, 1)
    cy = np.bincount(ids, weights=y) / np.maximum(n, 1)
    dist = (x - cx[ids]) ** 2 + (y - cy[ids]) ** 2
    order = np.lexsort((np.arange(len(ids)), dist, ids))
    first = np.ones(len(order), dtype=bool)
    first[1:] = ids[order][1:] != ids[order][:-1]
    central = order[first]
    sample = np.zeros(len(n))
    sample[ids[central]] = ((G[central] - P[central]) ** 2).sum(axis=1)
    present = np.nonzero(n > 0)[0]
    ranked = present[np.argsort(-sample[present], kind="stable")]
    k = int(np.searchsorted(np.cumsum(t_gain[ranked]), excess))
    return float(n[ranked][:k + 1].sum()) if k < len(ranked) else None


def oracle_shares(G, P, R, ids, max_nmse, x=None, y=None):
    """Shares of the commonly covered pixels a mix must give Phong, per pixel and per triangle, and the NMSE of
    all-Gouraud and all-Phong (render's definition: squared error over the reference's squared spread). With the
    pixels' positions x, y also the share of sampled_rule_share()."""
    spread = float(((R - R.mean(axis=0)) ** 2).sum())
    eg = ((G - R) ** 2).sum(axis=1)
    ep = ((P - R) ** 2).sum(axis=1)
    excess = eg.sum() - max_nmse * spread  # the squared error the mix must remove
    gain = eg - ep
    n = len(eg)
    # Per pixel: only pixels where Phong is better help; each weighs one pixel.
    helpful = gain > 0
    per_pixel = fewest_phong(gain[helpful], np.ones(int(helpful.sum())), excess)
    # Per triangle: the triangle's pixels together.
    t_gain = np.bincount(ids, weights=gain)
    t_pixels = np.bincount(ids).astype(np.float64)
    useful = (t_gain > 0) & (t_pixels > 0)
    per_triangle = fewest_phong(t_gain[useful], t_pixels[useful], excess)
    # The whole-triangle choice: triangle ids (map numbering) in the knapsack's order up to the limit.
    listed, predicted = [], eg.sum()
    if excess > 0:
        ids_useful = np.nonzero(useful)[0]
        order, cum, k = by_gain_per_weight(t_gain[useful], t_pixels[useful], excess)
        if k < len(order):
            listed = [int(i) for i in ids_useful[order[:k + 1]]]
            predicted = eg.sum() - cum[k]
    sampled = sampled_rule_share(ids, x, y, G, P, t_gain, excess) if x is not None else None
    return {
        "pixels": n,
        "nmse_gouraud": float(eg.sum() / spread),
        "nmse_phong": float(ep.sum() / spread),
        "phong_share_per_pixel": None if per_pixel is None else per_pixel / n,
        "phong_share_per_triangle": None if per_triangle is None else per_triangle / n,
        "phong_share_centroid_rule": None if sampled is None else sampled / n,
        "oracle_triangles": listed,
        "oracle_predicted_nmse": float(predicted / spread),
    }


def bound(phong_frame, gouraud_frame, phong_kernel, gouraud_kernel, share):
    if share is None:
        return None
    return phong_frame / (gouraud_frame + share * max(phong_kernel - gouraud_kernel, 0.0))


def paired_bound(phong_frames, gouraud_frames, phong_kernel, gouraud_kernel, share):
    """bound() per pair of alternating frames, the median: a spell of a slow host (bench/README.md, run AE) slows
    both frames of a pair, so the pairs' median holds where the two medians would not."""
    if share is None:
        return None
    return statistics.median(bound(p, g, phong_kernel, gouraud_kernel, share)
                             for p, g in zip(phong_frames, gouraud_frames))


def allowed_share(phong_frame, gouraud_frame, phong_kernel, gouraud_kernel, target):
    extra = phong_kernel - gouraud_kernel
    return (phong_frame / target - gouraud_frame) / extra if extra > 0 else None


def agree(a, b, rel=0.005):
    return abs(a - b) <= rel * max(abs(a), abs(b))


def mix_run(binary, scene, size, choice, frames, tmp):
    """combined:0 with a per-triangle choice, its frames alternating with exact Phong's: the share of the visible
    pixels it gives Phong, its NMSE, and the pairs' ratios."""
    r = render(binary, scene, ["--method", "combined:0", "--triangle-choice"] + choice +
               ["--frames", str(frames), "--against", "phong"], tmp, "mix", size)
    v = r["stats"]["triangle_choice"]["visible_pixels"]
    total = v["gouraud"] + v["segments"] + v["phong"]
    return {"phong_share": v["phong"] / total if total else None, "nmse": r["error"]["method"]["nmse"],
            "frame_ratio": r["against"]["frame_ratio"]["median"], "frame_ratio_p10": r["against"]["frame_ratio"]["p10"],
            "frame_ratio_p90": r["against"]["frame_ratio"]["p90"],
            "kernel_ratio": r["against"]["kernel_ratio"]["median"],
            "choice_ms": r["stages_ms"].get("choice_ms", 0.0), "frame_ms": r["frame_ms"]}


def oracle_run(binary, scene, size, shares, max_nmse, frames, tmp):
    """The oracle's whole-triangle choice rendered (list:FILE, map ids minus one); stops the study when its NMSE is
    not the predicted one."""
    if not shares["oracle_triangles"]:
        return None
    listing = os.path.join(tmp, "oracle-phong.txt")
    with open(listing, "w") as f:
        f.write("\n".join(str(i - 1) for i in shares["oracle_triangles"]) + "\n")
    m = mix_run(binary, scene, size, ["list:" + listing], frames, tmp)
    if not agree(m["nmse"], shares["oracle_predicted_nmse"], 0.01) or m["nmse"] > max_nmse * 1.001:
        sys.exit("mix_oracle.py: the oracle's choice on %s rendered with NMSE %.4g, predicted %.4g (limit %g): the "
                 "triangle map and the frame do not number the triangles alike" % (
                     scene, m["nmse"], shares["oracle_predicted_nmse"], max_nmse))
    m["triangles"] = len(shares["oracle_triangles"])
    return m


def study(binary, scene, size, max_nmse, frames, target, budgets, tmp):
    row = measure_scene(binary, scene, size, max_nmse, frames, target, budgets, tmp)
    row.pop("oracle_triangles")  # thousands of ids; the rendered choice keeps their count
    return row


def pixels_render_covers(error):
    """The covered pixels of render's error figures: those it compared and those whose front surface a float
    depth tie flips, which it leaves out and the triangle map counts."""
    return error["pixels_compared"] + error.get("front_surface_mismatch", 0)


def measure_scene(binary, scene, size, max_nmse, frames, target, budgets, tmp):
    g = render(binary, scene, ["--method", "gouraud", "--frames", "1", "--triangle-map", os.path.join(tmp, "ids.png"),
                               "--reference-image", os.path.join(tmp, "ref.exr"), "--error-reference", "exact"],
               tmp, "gouraud", size)
    p = render(binary, scene, ["--method", "phong", "--frames", "1"], tmp, "phong", size)
    ids = triangle_ids(os.path.join(tmp, "ids.png"))
    covered = ids > 0
    R = reference_levels(os.path.join(tmp, "ref.exr"), tmp)[covered]
    ys, xs = np.nonzero(covered)  # row-major, as the boolean index orders the pixels
    shares = oracle_shares(rgb(os.path.join(tmp, "gouraud.png"))[covered], rgb(os.path.join(tmp, "phong.png"))[covered],
                           R, ids[covered], max_nmse, xs.astype(np.float64), ys.astype(np.float64))
    for name, rep in (("gouraud", g), ("phong", p)):
        mine, theirs = shares["nmse_" + name], rep["error"]["method"]["nmse"]
        compared = pixels_render_covers(rep["error"]["method"])
        if not agree(mine, theirs) or compared != shares["pixels"]:
            sys.exit("mix_oracle.py: %s on %s: NMSE %.4g over %d pixels here, render's %.4g over %d: the images were "
                     "not read as render compares them" % (name, scene, mine, shares["pixels"], theirs, compared))
    t = render(binary, scene, ["--method", "gouraud", "--frames", str(frames), "--against", "phong", "--no-error"],
               tmp, "timed", size)
    G, KG = t["frame_ms"], t["stages_ms"]["kernel_ms"]
    P, KP = t["against"]["frame_ms"], t["against"]["stages_ms"]["kernel_ms"]
    Gs, Ps = t["timing"]["samples_ms"], t["against"]["samples_ms"]
    return {
        "scene": g["scene"], "scene_file": scene, "size": "%dx%d" % (g["width"], g["height"]),
        "device": g["device"].get("name", ""), "compute_units": g["device"].get("compute_units"),
        "max_nmse": max_nmse, "target": target, **shares,
        "frames": frames, "gouraud_frame_ms": G, "gouraud_kernel_ms": KG, "phong_frame_ms": P, "phong_kernel_ms": KP,
        "gouraud_vs_phong_frame": t["against"]["frame_ratio"]["median"],
        "bound_per_pixel": paired_bound(Ps, Gs, KP, KG, shares["phong_share_per_pixel"]),
        "bound_per_triangle": paired_bound(Ps, Gs, KP, KG, shares["phong_share_per_triangle"]),
        "share_the_target_allows": allowed_share(P, G, KP, KG, target),
        "oracle_choice": oracle_run(binary, scene, size, shares, max_nmse, frames, tmp),
        "rules": [dict(max_error=b, **mix_run(binary, scene, size, ["bound", "--max-error", "%g" % b], frames, tmp))
                  for b in budgets],
    }


def fmt(x, spec):
    return "—" if x is None else format(x, spec)


def allowed_text(share):
    """The share the target allows, or "none" where even all-Gouraud misses it (a negative share)."""
    return "—" if share is None else "none" if share < 0 else "%.1f" % (100 * share)


def markdown(rows):
    lines = ["| scene | size | NMSE Gouraud / Phong | Phong share needed: per pixel / per triangle / centroid rule "
             "| share %sx allows | frame G / P ms | kernel G / P ms | bound per pixel / per triangle |"
             % fmt(rows[0]["target"], "g"),
             "|---|---|---|---|---|---|---|---|"]
    pct = lambda v: fmt(None if v is None else 100 * v, ".1f")
    for r in rows:
        lines.append("| %s | %s | %.2e / %.2e | %s / %s / %s %% | %s %% | %.2f / %.2f | %.2f / %.2f | %s / %s |" % (
            r["scene"], r["size"], r["nmse_gouraud"], r["nmse_phong"],
            pct(r["phong_share_per_pixel"]), pct(r["phong_share_per_triangle"]), pct(r["phong_share_centroid_rule"]),
            allowed_text(r["share_the_target_allows"]),
            r["gouraud_frame_ms"], r["phong_frame_ms"], r["gouraud_kernel_ms"], r["phong_kernel_ms"],
            fmt(r["bound_per_pixel"], ".2f") + "x", fmt(r["bound_per_triangle"], ".2f") + "x"))
    lines += ["", "Rendered (`combined:0`, frames alternating with exact Phong's; ratio = Phong / this, median of the "
              "pairs, p10-p90):", "",
              "| scene | size | choice | Phong share of visible pixels | NMSE | frame ratio | kernel ratio "
              "| choice ms |",
              "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        runs = ([("oracle (`list`, %d triangles)" % r["oracle_choice"]["triangles"], r["oracle_choice"])]
                if r["oracle_choice"] else []) + [("bound `--max-error %g`" % b["max_error"], b) for b in r["rules"]]
        for name, m in runs:
            lines.append("| %s | %s | %s | %s %% | %.2e | %.2fx (%.2f-%.2f) | %.2fx | %.2f |" % (
                r["scene"], r["size"], name, fmt(None if m["phong_share"] is None else 100 * m["phong_share"], ".1f"),
                m["nmse"], m["frame_ratio"], m["frame_ratio_p10"], m["frame_ratio_p90"], m["kernel_ratio"],
                m["choice_ms"]))
    r = rows[0]
    lines.append("")
    lines.append("Device: %s, %s compute units; NMSE limit %g against exact Phong's reference; frames: medians of %d "
                 "alternating in one process (`render --method gouraud --against phong`). Bound = P / (G + s (K_P - "
                 "K_G)) per pair of frames (kernels: medians), the median over the pairs: a free oracle and a kernel "
                 "that costs each pixel its own method's cost (optimistic)."
                 % (r["device"], r["compute_units"], r["max_nmse"], r["frames"]))
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scenes", nargs="+", required=True, help="scene files (.json)")
    ap.add_argument("--binary", default=os.environ.get("PARASHADE", "build/parashade"), help="parashade binary")
    ap.add_argument("--size", default="", help="WIDTHxHEIGHT for every scene (default: the scene's)")
    ap.add_argument("--max-nmse", type=float, default=1e-4, help="NMSE limit against exact Phong (default 1e-4)")
    ap.add_argument("--target", type=float, default=1.5, help="the speed-up over exact Phong asked (default 1.5)")
    ap.add_argument("--frames", type=int, default=30, help="timed frame pairs (default 30)")
    ap.add_argument("--budgets", type=float, nargs="*", default=[],
                    help="also the bound rule's choice at these --max-error budgets (levels)")
    ap.add_argument("--json", help="write the rows as JSON here")
    ap.add_argument("--markdown", help="write the table here (it is printed either way)")
    a = ap.parse_args()
    if not (a.max_nmse > 0 and a.target > 0 and a.frames > 0 and all(b > 0 for b in a.budgets)):
        ap.error("--max-nmse, --target, --frames and --budgets must be positive")
    if shutil.which("oiiotool") is None:
        sys.exit("mix_oracle.py: needs oiiotool (Debian: openimageio-tools) to read the reference's EXR")
    if not os.access(a.binary, os.X_OK):
        sys.exit("mix_oracle.py: no parashade binary at %s (--binary)" % a.binary)
    rows = []
    for scene in a.scenes:
        with tempfile.TemporaryDirectory() as tmp:
            try:
                rows.append(study(a.binary, scene, a.size, a.max_nmse, a.frames, a.target, a.budgets, tmp))
            except subprocess.CalledProcessError as e:
                sys.exit("mix_oracle.py: %s failed (exit %d)" % (" ".join(e.cmd[:3]), e.returncode))
    table = markdown(rows)
    print(table, end="")
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write(table)
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"schema": schema("mix-oracle"), "rows": rows}, f, indent=1)


if __name__ == "__main__":
    main()
