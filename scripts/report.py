#!/usr/bin/env python3
"""Turns benchmark and sweep results into a report directory (needs python3-matplotlib):
  speed_error_SCENE_SIZE.png  frame time against NMSE vs exact Phong, every parashade method/unit/arith
                              point and the llvmpipe points, with the combined and Phong-variant points
                              of combined-study.json and phong-methods.json when given; the Pareto front
                              marked;
  speed_flip_SCENE_SIZE.png   the same against mean LDR-FLIP (bench_llvmpipe's flip_mean, in runs that
                              have it; the study files carry NMSE only);
  scaling_SCENE.png           interpolators per clock -> modeled and measured speed-up, and error
                              (`parashade scaling --report` files);
  strip_SCENE_SIZE.png        exact Phong | parashade Gouraud | llvmpipe Gouraud | parashade Phong, and
                              their error maps on one scale up to the largest error (bench_llvmpipe
                              --images=DIR);
  index.md                    the device, the ratio table against llvmpipe and the fill limit, links.
Inputs: result files or directories (bench_llvmpipe JSON, scaling JSON, peak_memory JSON, combined_study
JSON, phong_methods JSON).

    scripts/report.py bench-results/*.json --images bench-results/images -o bench-results/report
"""
import argparse
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.colors  # noqa: E402
import matplotlib.ticker as ticker  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_results import find, load_results  # noqa: E402

NMSE_FLOOR = 1e-9  # plotted in place of an NMSE of 0 (identical images) on the log axis
# The error axes of the speed/error plots: the result key, its floor on the log axis (identical images), the
# axis label and the file name's prefix. FLIP: bench_llvmpipe's flip_mean (LDR-FLIP, docs/pictures.md).
ERROR_AXES = {"nmse": (NMSE_FLOOR, "NMSE against exact Phong (log)", "speed_error"),
              "flip_mean": (1e-6, "mean LDR-FLIP against exact Phong (log)", "speed_flip")}


def point_label(r):
    return f"{r['peer']} {r['method']}"


def pareto(points, rel=0.01):
    """Points (time, nmse, row) not dominated by another: each on the front is more than `rel` less wrong
    than every faster point (so equal errors up to rounding do not all count as improvements)."""
    front = []
    for p in sorted(points, key=lambda q: (q[0], q[1])):
        if not front or p[1] < front[-1][1] * (1.0 - rel):
            front.append(p)
    return front


# Marker and colour per kind of point; the legend names kinds, not points, so it stays one row.
FAMILIES = [  # (family, label in the legend, marker, colour)
    ("llvmpipe", "llvmpipe", "s", "tab:red"),
    ("parashade", "parashade flat/Gouraud/Phong", "o", "tab:blue"),
    ("units", "parashade modeled units", "v", "tab:cyan"),
    ("combined", "combined:K / auto (combined study)", "^", "tab:green"),
    ("phong variants", "Phong normalization / specular (phong methods)", "D", "tab:purple"),
]


def point_family(r):
    if r["peer"] == "llvmpipe":
        return "llvmpipe"
    return "units" if ":" in r["method"] else "parashade"


def place_labels(fig, ax, items):
    """Names beside points (x, y, text), each moved up or down from its point until it overlaps no name placed
    before it (points close together, such as Phong and the combined method at the same error, would print
    their names over each other)."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    placed = []
    for x, y, text in sorted(items, key=lambda i: (i[0], -i[1])):
        for dy in (3, -9, 12, -18, 21, -27, 30):
            label = ax.annotate(text, (x, y), textcoords="offset points", xytext=(5, dy), fontsize=6.5)
            box = label.get_window_extent(renderer)
            if not any(box.overlaps(b) for b in placed) or dy == 30:
                break
            label.remove()  # try the next offset
        placed.append(box)


def speed_error_plot(rows, variants, scene, size, out_dir, metric="nmse"):
    """Frame time against an error vs exact Phong (ERROR_AXES: NMSE, or FLIP's mean where the run has it):
    the peer run's points and, from the study files (other runs of the same scene and size, at another
    load), the combined and Phong-variant points placed by their time ratio to plain Phong in their own
    run, times parashade Phong's time in this run (the studies carry NMSE only)."""
    floor, ylabel, prefix = ERROR_AXES[metric]
    pts = [(r["frame_ms"], max(r[metric], floor), point_family(r), point_label(r)) for r in rows
           if r["scene"] == scene and r["size"] == size and r["peer"] in ("llvmpipe", "parashade")
           and isinstance(r.get(metric), (int, float)) and math.isfinite(r[metric])]
    phong = find(rows, peer="parashade", scene=scene, size=size, method="phong")
    if phong:
        pts += [(v["frame_ms"] / v["phong_ms"] * phong["frame_ms"], max(v[metric], floor), v["family"], v["label"])
                for v in variants if v["scene"] == scene and v["size"] == size and v.get("phong_ms")
                and isinstance(v.get(metric), (int, float)) and math.isfinite(v[metric])]
    if len(pts) < 2:
        return None
    fig, ax = plt.subplots(figsize=(11, 7))
    front = pareto([(t, e, (fam, lab)) for t, e, fam, lab in pts])
    on_front = {(p[0], p[1], p[2]) for p in front}
    for fam, legend, marker, colour in FAMILIES:
        sel = [p for p in pts if p[2] == fam]
        if sel:
            ax.scatter([p[0] for p in sel], [p[1] for p in sel], marker=marker, s=46, color=colour, label=legend,
                       edgecolors="none", zorder=3, alpha=0.9)
    ax.scatter([p[0] for p in front], [p[1] for p in front], s=110, facecolors="none", edgecolors="black",
               linewidth=1.2, zorder=4)
    ax.step([p[0] for p in front], [p[1] for p in front], where="post", color="black", linestyle="--",
            linewidth=1, label="Pareto front (circled)", zorder=2)
    ax.set_xscale("log")
    ax.set_yscale("log")
    # Label the minor ticks too: a decade or less is all most plots span.
    ax.xaxis.set_major_formatter(ticker.FormatStrFormatter("%g"))
    ax.xaxis.set_minor_formatter(ticker.FormatStrFormatter("%g"))
    ax.yaxis.set_minor_formatter(ticker.LogFormatterSciNotation(labelOnlyBase=False, minor_thresholds=(2, 0.5)))
    ax.tick_params(axis="both", which="minor", labelsize=7)
    ax.set_xlabel("frame time, ms (median, whole frame; log)")
    ax.set_ylabel(ylabel)
    ax.set_title(f"{scene} {size}: speed against error (study points: their run's time ratio to Phong "
                 f"x this run's Phong)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=3, fontsize=8, frameon=False)
    xs, es = [p[0] for p in pts], [p[1] for p in pts]
    ax.set_xlim(min(xs) / 1.2, max(xs) * 1.5)  # room for the names on the right
    ax.set_ylim(min(es) / 1.5, max(es) * 1.5)
    fig.tight_layout()
    # Names only where they matter: the Pareto front and the plain methods of both peers (placed last, once the
    # axes are final, so that place_labels can see where they fall).
    place_labels(fig, ax, [(t, e, lab.replace("parashade ", "")) for t, e, fam, lab in pts
                           if (t, e, (fam, lab)) in on_front or fam in ("llvmpipe", "parashade")])
    name = f"{prefix}_{scene}_{size}.png"
    fig.savefig(os.path.join(out_dir, name), dpi=110)
    plt.close(fig)
    return name


def interpolators(unit):
    """Intensities per clock of a unit name as `parashade scaling` writes it."""
    parts = unit.split(":")
    if parts[0] == "classic":
        return 1
    if parts[0] == "counter":
        return 2
    if parts[0] in ("interleave", "segment"):
        return int(parts[1])
    if parts[0] == "sierpinski":
        depth = int(parts[1]) if len(parts) > 1 and parts[1].isdigit() else 1
        return 4 ** depth
    return None


def scaling_plot(doc, out_dir):
    """Three panels, one line per unit family (classic, then counter / interleave:M / segment:P /
    sierpinski): modeled speed-up (the same in every arithmetic), measured frame speed-up per
    arithmetic, and the max error against the ideal Gouraud."""
    rows = [r for r in doc["rows"] if interpolators(r["unit"])]
    families = {"counter": ("tab:green", "^"), "interleave": ("tab:blue", "o"), "segment": ("tab:orange", "s"),
                "sierpinski": ("tab:purple", "D")}
    ariths = sorted({r["arith"] for r in rows})
    styles = dict(zip(ariths, ["-", "--", ":"]))
    fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(15, 4.8))
    for fam, (colour, marker) in families.items():
        for arith in ariths:
            sel = sorted([r for r in rows if r["arith"] == arith and
                          (r["unit"] == "classic" or (r["unit"].startswith(fam) and not r["unit"].endswith(":own")))],
                         key=lambda r: interpolators(r["unit"]))
            if len(sel) < 2:
                continue
            x = [interpolators(r["unit"]) for r in sel]
            if arith == ariths[0]:  # modeled clocks do not depend on the arithmetic
                ax1.plot(x, [r["modeled_speedup"] for r in sel], marker=marker, color=colour, label=fam)
            ax2.plot(x, [r["measured_speedup"] for r in sel], marker=marker, color=colour, linestyle=styles[arith],
                     label=f"{fam}, {arith}")
            ax3.plot(x, [r["error"]["implementation"].get("max_abs") for r in sel], marker=marker, color=colour,
                     linestyle=styles[arith], label=f"{fam}, {arith}")
    ax1.plot([1, 64], [1, 64], color="grey", linewidth=0.8, linestyle=":", label="ideal (= interpolators)")
    ax1.set_title("modeled clocks: classic / unit", fontsize=9)
    ax2.set_title("measured whole frame: classic / unit (emulation)", fontsize=9)
    ax3.set_title("max abs error vs ideal Gouraud", fontsize=9)
    for ax in (ax1, ax2, ax3):
        ax.set_xscale("log", base=2)
        ax.set_xlabel("interpolators (intensities per clock; log2)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    ax1.set_yscale("log", base=2)
    ax1.set_ylabel("speed-up over classic (log2)")
    ax2.set_ylabel("speed-up over classic, same arithmetic")
    ax3.set_yscale("log")
    ax3.set_ylabel("8-bit levels (log)")
    fig.suptitle(f"{doc['scene']} {doc['width']}x{doc['height']}: modeled shading units "
                 f"({doc['device']['name']}, {doc['device'].get('compute_units', '?')} CU; "
                 f"medians of {doc.get('frames', '?')} frames)", fontsize=10)
    fig.tight_layout()
    name = f"scaling_{doc['scene']}.png"
    fig.savefig(os.path.join(out_dir, name), dpi=110)
    plt.close(fig)
    return name


def load_rgb(path):
    img = mpimg.imread(path)
    if img.dtype != np.uint8:
        img = np.round(img * 255.0)
    return img[..., :3].astype(np.float64)


def block_max(a, k):
    """a shrunk k times in each direction, each pixel the largest of its k x k block (edges padded)."""
    h, w = a.shape
    padded = np.zeros(((h + k - 1) // k * k, (w + k - 1) // k * k), dtype=a.dtype)
    padded[:h, :w] = a
    return padded.reshape(padded.shape[0] // k, k, padded.shape[1] // k, k).max(axis=(1, 3))


def strip_plot(images, scene, size, out_dir):
    exact_path = os.path.join(images, f"{scene}_{size}_exact.png")
    if not os.path.exists(exact_path):
        return None
    columns = [("parashade", "gouraud"), ("llvmpipe", "gouraud"), ("parashade", "phong"), ("llvmpipe", "phong")]
    cols = [(p, m, os.path.join(images, f"{p}_{scene}_{size}_{m}.png")) for p, m in columns]
    cols = [c for c in cols if os.path.exists(c[2])]
    if not cols:
        return None
    exact = load_rgb(exact_path)
    diffs = [np.abs(load_rgb(path) - exact).max(axis=2) for _, _, path in cols]
    # One colour scale for every map, up to the largest error of any (at least 1 level, never clipped):
    # the maps compare with each other and the worst pixel keeps its true value. Viridis, as
    # `parashade render --error-map` and `compare --error-map` draw it; gamma 0.4 is their default scale too.
    vmax = max(1.0, max(float(d.max()) for d in diffs))
    # A thumbnail drops most pixels: each map is shrunk by the largest error of each block, so an error of
    # one pixel still shows; the scale is a power law (gamma 0.4), so 1 level shows beside 124.
    norm = matplotlib.colors.PowerNorm(gamma=0.4, vmin=0, vmax=vmax)
    fig, axes = plt.subplots(2, len(cols) + 1, figsize=(5.2 * (len(cols) + 1), 6.6))
    axes[0][0].imshow(exact.astype(np.uint8))
    axes[0][0].set_title("exact Phong (reference)", fontsize=10)
    axes[1][0].axis("off")
    axes[1][0].text(0.0, 0.5, f"error maps:\n|image - exact|, max over RGB,\nin 8-bit levels; one colour scale\n"
                    f"0..{vmax:.0f} levels (the largest error),\npower law 0.4; each thumbnail pixel\n"
                    f"the largest error of its block", fontsize=10, va="center")
    im = None
    for k, ((p, m, path), diff) in enumerate(zip(cols, diffs), start=1):
        axes[0][k].imshow(load_rgb(path).astype(np.uint8))
        axes[0][k].set_title(f"{p} {m}", fontsize=10)
        im = axes[1][k].imshow(block_max(diff, 4), cmap="viridis", norm=norm, interpolation="nearest")
        axes[1][k].set_title(f"error: max {diff.max():.0f}, mean {diff.mean():.2f} levels", fontsize=9)
    for row in axes:
        for ax in row:
            ax.set_xticks([])
            ax.set_yticks([])
    if im is not None:
        cb = fig.colorbar(im, ax=list(axes[1][1:]), fraction=0.02, pad=0.01)
        cb.set_label("levels", fontsize=9)
    fig.suptitle(f"{scene} {size}", fontsize=10)
    name = f"strip_{scene}_{size}.png"
    fig.savefig(os.path.join(out_dir, name), dpi=110)
    plt.close(fig)
    return name


def ratio_table(rows):
    """Markdown: per scene and size, parashade against llvmpipe (frame time ratio = llvmpipe / parashade)."""
    lines = ["| scene | size | triangles | parashade Gouraud ms | llvmpipe Gouraud ms | Gouraud x | "
             "parashade Phong ms | llvmpipe Phong ms | Phong x | coverage mismatch (G, par./llvm.) | "
             "NMSE Gouraud par. / llvm. |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    keys = sorted({(r["scene"], r["size"]) for r in rows if r["peer"] == "llvmpipe"},
                  key=lambda k: (int(k[1].split("x")[0]), k[0]))
    for scene, size in keys:
        cells = [scene, size]
        pg = find(rows, peer="parashade", scene=scene, size=size, method="gouraud")
        lg = find(rows, peer="llvmpipe", scene=scene, size=size, method="gouraud")
        pp = find(rows, peer="parashade", scene=scene, size=size, method="phong")
        lp = find(rows, peer="llvmpipe", scene=scene, size=size, method="phong")
        cells.append(f"{(pg or lg or {}).get('triangles_in', float('nan')):.0f}")
        for p, l in ((pg, lg), (pp, lp)):
            cells += [f"{p['frame_ms']:.2f}" if p else "-", f"{l['frame_ms']:.2f}" if l else "-",
                      f"**{l['frame_ms'] / p['frame_ms']:.2f}**" if p and l else "-"]
        cells.append(f"{pg.get('coverage_mismatch', float('nan')):.0f} / {lg.get('coverage_mismatch', float('nan')):.0f}"
                     if pg and lg else "-")
        cells.append(f"{pg.get('nmse', float('nan')):.2e} / {lg.get('nmse', float('nan')):.2e}" if pg and lg else "-")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def fill_table(rows):
    """The full-screen quad's frames against the floors of its size: the fill limit, the Gouraud plane floor and
    the Phong floor (bench_llvmpipe; a floor missing from the run shows as -)."""
    lines = ["| size | fill limit ms | Gouraud floor ms | quad Gouraud ms | x fill limit | x Gouraud floor | "
             "Phong floor ms | quad Phong ms | x Phong floor | quad llvmpipe Gouraud ms |", "|---|---|---|---|---|---|---|---|---|---|"]

    def ms(r, digits=3):
        return f"{r['frame_ms']:.{digits}f}" if r else "-"

    def ratio(a, b):
        return f"**{a['frame_ms'] / b['frame_ms']:.2f}**" if a and b else "-"

    for f in sorted([r for r in rows if r["peer"] == "fill_limit"], key=lambda r: int(r["size"].split("x")[0])):
        size = f["size"]
        plane = find(rows, peer="plane_fill_limit", size=size)
        phong_floor = find(rows, peer="phong_plane_fill_limit", size=size)
        qg = find(rows, peer="parashade", scene="fullscreen_quad", size=size, method="gouraud")
        qp = find(rows, peer="parashade", scene="fullscreen_quad", size=size, method="phong")
        lg = find(rows, peer="llvmpipe", scene="fullscreen_quad", size=size, method="gouraud")
        lines.append(f"| {size} | {ms(f)} | {ms(plane)} | {ms(qg)} | {ratio(qg, f)} | {ratio(qg, plane)} | "
                     f"{ms(phong_floor, 2)} | {ms(qp, 2)} | {ratio(qp, phong_floor)} | {ms(lg)} |")
    return "\n".join(lines)


def throughput_table(rows):
    """Large triangles (fullscreen_quad): pixel throughput; small triangles (sphere_2m): triangle throughput."""
    lines = ["| size | method | quad Mpixel/s parashade / llvmpipe | sphere_2m Mtriangle/s parashade / llvmpipe |",
             "|---|---|---|---|"]
    sizes = sorted({r["size"] for r in rows if r["peer"] == "llvmpipe"}, key=lambda s: int(s.split("x")[0]))
    for size in sizes:
        for method in ("gouraud", "phong"):
            cells = []
            for scene, field in (("fullscreen_quad", "mpixel_per_s"), ("sphere_2m", "mtriangle_per_s")):
                p = find(rows, peer="parashade", scene=scene, size=size, method=method)
                l = find(rows, peer="llvmpipe", scene=scene, size=size, method=method)
                cells.append(f"{p[field]:.1f} / {l[field]:.1f}" if p and l else "-")
            lines.append(f"| {size} | {method} | {cells[0]} | {cells[1]} |")
    return "\n".join(lines)


def memory_table(memory, baseline):
    lines = ["| scene | size | method | peak RSS MiB (whole `parashade render`) | above the OpenCL runtime's MiB | "
             "budget MiB | within |",
             "|---|---|---|---|---|---|---|"]
    for m in memory:
        size = f"{m['width']}x{m['height']}"
        method = m.get("method", "gouraud")
        over = m.get("over_baseline_mib")
        budget = m.get("budget_mib")
        if over is None or budget is None:
            lines.append(f"| {m['scene']} | {size} | {method} | {m['peak_rss_mib']:.1f} | - | - | - |")
            continue
        lines.append(f"| {m['scene']} | {size} | {method} | {m['peak_rss_mib']:.1f} | {over:.1f} | {budget:.1f} | "
                     f"{'yes' if over <= budget else '**no**'} |")
    return "\n".join(lines) + (f"\n\nThe OpenCL runtime alone (`parashade devices`): {baseline:.1f} MiB. "
                                "Budget = 2 x (RGBA8 + 32-bit depth frame + mesh) + 64 MiB." if baseline else "")


def pairs_table(doc):
    """Markdown: bench_peer_pairs' paired frames, llvmpipe / parashade per pair: median [p10, p90]."""
    lines = [f"{doc['pairs']} pairs a row at {doc['width']}x{doc['height']}, each one parashade frame and one "
             f"llvmpipe frame right after each other (`bench_peer_pairs`; {doc['device']}, "
             f"{doc['compute_units']} compute units; LP_NUM_THREADS={doc['lp_num_threads']}).", "",
             "| scene | method | parashade ms | llvmpipe ms | x (median of the pairs) | p10 | p90 |",
             "|---|---|---|---|---|---|---|"]
    for c in doc["cases"]:
        lines.append(f"| {c['scene']} | {c['method']} | {c['parashade_median_ms']:.2f} | {c['llvmpipe_median_ms']:.2f} "
                     f"| **{c['ratio_median']:.2f}** | {c['ratio_p10']:.2f} | {c['ratio_p90']:.2f} |")
    return "\n".join(lines)


def steadiness_line(files):
    """The host's steadiness before and after the run (bench_host_noise via bench-suite.sh), when its
    host-noise-{before,after}.json lie beside the result files; else an empty string."""
    parts = []
    folders = sorted({os.path.dirname(os.path.abspath(f)) for f in files})
    for when in ("before", "after"):
        for folder in folders:
            path = os.path.join(folder, f"host-noise-{when}.json")
            if os.path.exists(path):
                with open(path) as f:
                    j = json.load(f)
                # Files before the calibration (run AE) hold one threshold for both probes.
                alu_max = j.get("max_alu_spread", j.get("max_spread"))
                memory_max = j.get("max_memory_spread", j.get("max_spread"))
                limits = (f"both at most {alu_max:.2f}" if alu_max == memory_max
                          else f"the ALU loop at most {alu_max:.2f}, the memory sweep at most {memory_max:.2f}")
                parts.append(f"{when} the run {'steady' if j['steady'] else '**not steady**'} (p90/min of the ALU "
                             f"loop {j['worst_alu_p90_over_min']:.3f}, of the memory sweep "
                             f"{j['worst_memory_p90_over_min']:.3f}; steady: {limits})")
                break
    return ("Host steadiness (`bench_host_noise`): " + "; ".join(parts) + ".") if parts else ""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("results", nargs="+", help="result JSON files or directories")
    ap.add_argument("--images", help="bench_llvmpipe --images directory (image strips)")
    ap.add_argument("-o", "--output", required=True, help="report directory")
    ap.add_argument("--aggregate", default="median", choices=["median", "mean", "min"],
                    help="which statistic of repeated runs (min: the fastest repetition)")
    ap.add_argument("--note", default="", help="a line about the machine or the run, printed under the title")
    args = ap.parse_args()
    res = load_results(args.results, args.aggregate)
    rows = res["benchmark"]
    if not rows and not res["scaling"] and not res["peer_pairs"]:
        sys.exit("report: no benchmark or scaling results in " + " ".join(args.results))
    os.makedirs(args.output, exist_ok=True)
    md = ["# parashade benchmark report", ""]
    for ctx in res["contexts"][:1]:
        md += [f"Generated from: {', '.join(os.path.basename(f) for f in res['files'])}. Run {ctx.get('date', '?')} "
               f"on {ctx.get('host_name', '?')}: OpenCL device `{ctx.get('device', '?')}` ({ctx.get('platform', '?')}), "
               f"{ctx.get('compute_units', '?')} compute units; peer `{ctx.get('gl_renderer', '-')}` "
               f"({ctx.get('gl_version', '-')}), LP_NUM_THREADS={ctx.get('lp_num_threads', '-')}; "
               f"{ctx.get('num_cpus', '?')} CPUs, load average {ctx.get('load_avg', '?')}.", ""]
    steadiness = steadiness_line(res["files"])
    if steadiness:
        md += [steadiness, ""]
    if args.note:
        md += [args.note, ""]
    md += [f"Times: the {args.aggregate} over repetitions (where the run had repetitions).", ""]
    if rows:
        md += ["## Frame time against llvmpipe (x = llvmpipe ms / parashade ms; > 1: parashade faster)", "",
               "Whole frame on both sides (parashade: vertex stage, clip/cull, setup, binning, upload, kernel, "
               "read-back; llvmpipe: clear, draw, glReadPixels, meshes resident in vertex buffers). Back faces "
               "culled by both exactly when the scene says so.", "", ratio_table(rows), "",
               "## Large triangles against the fill limit", "", fill_table(rows), "",
               "## Pixel throughput (large triangles) and triangle throughput (small triangles)", "",
               throughput_table(rows), ""]
    for doc in res["peer_pairs"]:
        md += ["## Frame time against llvmpipe, frame by frame (x = llvmpipe ms / parashade ms)", "",
               pairs_table(doc), ""]
    if res["memory"]:
        md += ["## Peak memory", "", memory_table(res["memory"], res.get("memory_baseline")), ""]
    sizes = sorted({r["size"] for r in rows if r["peer"] == "llvmpipe"}, key=lambda s: int(s.split("x")[0]))
    scenes = sorted({r["scene"] for r in rows if r["peer"] == "llvmpipe"})
    plots = []
    for size in sizes:
        for scene in scenes:
            for metric in ERROR_AXES:
                n = speed_error_plot(rows, res["variants"], scene, size, args.output, metric)
                if n:
                    plots.append(n)
    if plots:
        md += ["## Speed against error", ""] + [f"- [{p}]({p})" for p in plots] + [""]
    scal = [scaling_plot(d, args.output) for d in res["scaling"]]
    if scal:
        md += ["## Scaling of the modeled units", ""] + [f"![{p}]({p})" for p in scal] + [""]
    if args.images and os.path.isdir(args.images):
        strips = []
        for size in sizes:
            for scene in scenes:
                n = strip_plot(args.images, scene, size, args.output)
                if n:
                    strips.append(n)
        if strips:
            md += ["## Image strips", ""] + [f"- [{p}]({p})" for p in strips] + [""]
    md += ["## Claims", "", "[claims.md](claims.md) (scripts/claims.py)", ""]
    tmp = os.path.join(args.output, "index.md.tmp")
    with open(tmp, "w") as f:
        f.write("\n".join(md))
    os.replace(tmp, os.path.join(args.output, "index.md"))
    print(f"report: {len(plots)} speed/error plots, {len(scal)} scaling plots -> {args.output}/index.md")


if __name__ == "__main__":
    main()
