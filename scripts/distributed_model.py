#!/usr/bin/env python3
"""Measures render --distribute for N = 1..4 ranks on this host, fits the α–β cost model of
docs/distributed.md from an MPI ping-pong, checks it against the measured runs and predicts 16..1024 ranks
for a 100-million-triangle scene at 3840x2160.

    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 PARASHADE_MESH_DIR=/path/to/shared/meshes \\
        scripts/distributed_model.py --build build --scene scenes/bunny.json --size 1920x1080 \\
        --json distributed-model.json --plot docs/distributed-scaling.png

Only warm frames count: each run renders --warmup frames first (program builds, device and scene set-up),
then --frames timed frames, whose per-rank, per-frame prepare, render, pack and composite times the report
lists. Runs are interleaved: --rounds rounds, each going through every (mode, N) once in an order turned
by the round, and each round also times the one-process render (the frame without MPI) for comparison;
the load average is recorded before every run. Figures are medians over frames, then over rounds.

Prints the Markdown tables docs/distributed.md quotes. Needs mpirun and, for --plot, python3-matplotlib.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

from report_schema import schema


def sh(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("failed (%d): %s\n%s" % (p.returncode, " ".join(cmd), p.stderr))
    return p.stdout


def composite_model(mode, n_ranks, pixels, a):
    """Seconds to composite: ring reduce-scatter of 16-byte keys + gather (sort-last), gather of the
    bands' 4-byte pixels (sort-first). a: alpha, beta, gamma."""
    N = n_ranks
    if N == 1:
        return 0.0
    f = (N - 1) / N
    if mode == "sort-last":
        return 2 * (N - 1) * a["alpha"] + 2 * f * 16 * pixels * a["beta"] + f * pixels * a["gamma"]
    return (N - 1) * a["alpha"] + f * 4 * pixels * a["beta"]


def warm_figures(reports):
    """One run's figures from its rounds: per round and rank, the median over the timed frames of each time;
    then the median over the rounds. The frame is rank 0's barrier-to-barrier frame."""
    keys = ("prepare_ms", "render_ms", "pack_ms", "composite_ms", "gather_ms", "rank_frame_ms")
    out = json.loads(json.dumps(reports[0]))
    out["frame_ms"] = statistics.median(r["frame_ms"] for r in reports)
    out["frame_ms_rounds"] = [r["frame_ms"] for r in reports]
    for i, rank in enumerate(out["per_rank"]):
        for key in keys:
            rank[key] = statistics.median(statistics.median(f.get(key, 0.0) for f in r["per_rank"][i]["frames"])
                                          for r in reports)
        rank["peak_rss_mib"] = max(r["per_rank"][i]["peak_rss_mib"] for r in reports)
    for key in ("render_ms", "prepare_ms"):
        out["imbalance"][key] = statistics.median(r["imbalance"][key] for r in reports)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default="build")
    ap.add_argument("--scene", default="scenes/bunny.json")
    ap.add_argument("--size", default="1920x1080")
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--warmup", type=int, default=1)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--ranks", default="1,2,3,4")
    ap.add_argument("--cores", type=int, default=os.cpu_count())
    ap.add_argument("--json")
    ap.add_argument("--plot")
    ap.add_argument("--replot", metavar="JSON", help="only draw --plot from a --json file of an earlier run")
    args = ap.parse_args()
    if args.replot:
        if not args.plot:
            sys.exit("--replot needs --plot FILE")
        with open(args.replot) as f:
            plot(json.load(f), args.plot)
        return
    if args.plot:
        try:
            import matplotlib  # noqa: F401  (checked before the runs, not after them)
        except ImportError:
            sys.exit("--plot needs matplotlib (Debian's python3-matplotlib: run this with /usr/bin/python3)")
    mpirun = ["mpirun", "--oversubscribe"]
    binary = os.path.join(args.build, "parashade")

    pp = json.loads(sh(mpirun + ["-np", "2", os.path.join(args.build, "parashade_mpi_ping_pong")]))
    a = {"alpha": pp["alpha_small_message_s"], "beta": pp["beta_s_per_byte"], "gamma": pp["gamma_s_per_pixel"]}
    w, h = map(int, args.size.split("x"))
    pixels = w * h

    ranks = list(map(int, args.ranks.split(",")))
    # The sort-last composite taken apart at each N, on the frame's buffer sizes (parashade_mpi_composite_probe).
    probe = [json.loads(sh(mpirun + ["-np", str(n), os.path.join(args.build, "parashade_mpi_composite_probe"),
                                     "--pixels", str(pixels)])) for n in ranks]
    # The one-process frames to compare with N = 1: sort-first's frame is the plain frame; sort-last's is
    # a planned frame (the units' depth pass leaves the keys), so also the one-process planned frame.
    cases = [(m, n) for m in ("sort-last", "sort-first") for n in ranks] + [("one-process", 1),
                                                                             ("one-process-planned", 1)]
    samples = {c: [] for c in cases}  # per case, one report per round
    loads = []
    common = ["--size", args.size, "--no-error", "-q", "--no-tuned", "--frames", str(args.frames),
              "--warmup", str(args.warmup)]
    with tempfile.TemporaryDirectory() as tmp:
        for rnd in range(args.rounds):
            k = rnd % len(cases)
            order = cases[k:] + cases[:k]  # interleaved: each round starts elsewhere, so a noisy spell
            if rnd % 2:                    # does not fall on one N only
                order.reverse()
            for mode, n in order:
                rep = os.path.join(tmp, "r.json")
                load = open("/proc/loadavg").read().split()[0]
                if mode.startswith("one-process"):
                    planned = ["--cu", str(args.cores)] if mode == "one-process-planned" else []
                    sh([binary, "render", args.scene, "-o", os.path.join(tmp, "i.png"), "--report", rep] + common +
                       planned)
                else:
                    sh(mpirun + ["-np", str(n), binary, "render", args.scene, "-o", os.path.join(tmp, "i.png"),
                                 "--distribute", mode, "--report", rep] + common)
                samples[(mode, n)].append(json.load(open(rep)))
                loads.append((rnd, mode, n, float(load)))
                print("round %d %s N=%d: load %s, frame %.1f ms" % (rnd, mode, n, load,
                      samples[(mode, n)][-1]["frame_ms"]), file=sys.stderr, flush=True)
    one_process = statistics.median(r["frame_ms"] for r in samples[("one-process", 1)])
    one_planned = statistics.median(r["frame_ms"] for r in samples[("one-process-planned", 1)])
    runs = {c: warm_figures(samples[c]) for c in cases if not c[0].startswith("one-process")}

    # Model of a rank's compute on this host, in core-ms (a rank's wall ms x its share of the C cores:
    # C/N for N ranks on C cores, whether they split the cores or time-share them):
    #   prepare: p x records on the rank (sort-last: R/N; sort-first: every rank prepares all R)
    #   render:  a x P + s x P / N (a: full-screen passes every rank makes; s: shading, divided)
    # p, a and s fitted over every N (median; least squares in 1/N). Composite: alpha-beta-gamma from the
    # ping-pong, nothing fitted, compared with the measured composite; pack (sort-last, local) from N = 1.
    C = args.cores
    out = {"schema": schema("distributed-model"), "alpha_beta": a, "ping_pong": pp, "composite_probe": probe, "pixels": pixels, "cores": C, "runs": {},
           "model": {}, "prediction": {}}
    rows = []
    for mode in ("sort-last", "sort-first"):
        ns = sorted(n for (m, n) in runs if m == mode)
        worst = lambda n, key: max(p[key] for p in runs[(mode, n)]["per_rank"])
        core = lambda n, key: worst(n, key) * C / n
        R = runs[(mode, ns[0])]["per_rank"][0]["records"]
        recs = lambda n: R / n if mode == "sort-last" else R
        # Least squares over every N (this loaded machine's single runs are too noisy for a two-point fit).
        p_rec = sorted(core(n, "prepare_ms") / recs(n) for n in ns)[len(ns) // 2]
        xs, ys = [1 / n for n in ns], [core(n, "render_ms") / pixels for n in ns]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        s_px = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
        a_px = my - s_px * mx
        if a_px < 0:
            a_px, s_px = 0.0, sum(y / x for x, y in zip(xs, ys)) / len(xs)
        pack = worst(ns[0], "pack_ms") * C / ns[0] / pixels if mode == "sort-last" else 0.0
        out["model"][mode] = {"prepare_core_ms_per_record": p_rec, "render_core_ms_per_pixel_fixed": a_px,
                              "render_core_ms_per_pixel_divided": s_px, "pack_core_ms_per_pixel": pack,
                              "fitted_on": ns}
        for n in ns:
            r = runs[(mode, n)]
            recs = R / n if mode == "sort-last" else R
            model_compute = (p_rec * recs + a_px * pixels + s_px * pixels / n) * n / C
            model_pack = pack * pixels * n / C
            model_comp = composite_model(mode, n, pixels, a) * 1e3
            meas_comp = max(p["composite_ms"] for p in r["per_rank"])
            meas_compute = max(p["prepare_ms"] + p["render_ms"] for p in r["per_rank"])
            rows.append((mode, n, r["frame_ms"], model_compute + model_pack + model_comp, meas_compute, model_compute,
                         max(p.get("pack_ms", 0) for p in r["per_rank"]), model_pack, meas_comp, model_comp,
                         r["imbalance"]["render_ms"], sum(p["bytes_sent"] for p in r["per_rank"]),
                         max(p["records"] for p in r["per_rank"]), max(p["peak_rss_mib"] for p in r["per_rank"])))
            out["runs"]["%s/%d" % (mode, n)] = r

    print("one-process render (no MPI): %.1f ms a frame, planned (--cu %d) %.1f ms (medians over rounds)" %
          (one_process, args.cores, one_planned))
    print("load average (1 min) before each run: %s" % ", ".join("%.1f" % l[3] for l in loads))
    out["one_process_frame_ms"] = one_process
    out["one_process_planned_frame_ms"] = one_planned
    out["loads"] = loads
    print("ping-pong (np 2, one host): alpha %.2f us, beta %.3f ns/byte (%.2f GB/s), gamma %.2f ns/pixel" %
          (a["alpha"] * 1e6, a["beta"] * 1e9, 1 / a["beta"] / 1e9, a["gamma"] * 1e9))
    for mode, m in out["model"].items():
        print("%s: prepare %.3g core-us/record, render %.3g + %.3g/N core-ns/pixel, pack %.3g core-ns/pixel" %
              (mode, m["prepare_core_ms_per_record"] * 1e3, m["render_core_ms_per_pixel_fixed"] * 1e6,
               m["render_core_ms_per_pixel_divided"] * 1e6, m["pack_core_ms_per_pixel"] * 1e6))
    print()
    print("| mode | N | frame ms measured | frame ms model | compute ms measured | compute ms model | pack ms measured "
          "| pack ms model | composite ms measured | composite ms model (α–β) | render imbalance | bytes sent "
          "(all ranks) | records (largest rank) | peak RSS MB (largest rank) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print("| %s | %d | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.2f | %.2f | %.2f | %d | %d | %.0f |" % r)
    print()
    print("The sort-last composite taken apart (parashade_mpi_composite_probe, %d pixels of 16 bytes, random keys; "
          "slowest rank, median ms):" % pixels)
    print()
    print("| N | in the frame: composite / of which gather | MPI_Alltoall | MPI_Reduce_local on N-1 blocks | both "
          "(the frame's reduce-scatter) | MPI_Reduce_scatter_block, same operator | MPI_Gather | copy of the send "
          "buffer | model (α–β–γ) |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for q in probe:
        n = q["ranks"]
        r = runs.get(("sort-last", n))
        frame = ("%.2f / %.2f" % (max(p["composite_ms"] for p in r["per_rank"]),
                                  max(p.get("gather_ms", 0.0) for p in r["per_rank"]))) if r else "-"
        print("| %d | %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |" % (
            n, frame, q["alltoall_ms"], q["reduce_local_ms"], q["alltoall_reduce_local_ms"],
            q["reduce_scatter_block_ms"], q["gather_ms"], q["copy_send_buffer_ms"],
            composite_model("sort-last", n, pixels, a) * 1e3))

    # Prediction: 100M triangles at 3840x2160, one rank per node of this VM's kind (C cores), the
    # per-record and per-pixel costs above, the ping-pong's alpha, beta, gamma.
    T, P = 100e6, 3840 * 2160
    print()
    print("| ranks | sort-last frame ms | of which composite + pack | sort-first frame ms | of which composite | "
          "records per rank sort-last / sort-first |")
    print("|---:|---:|---:|---:|---:|---|")
    pred = []
    sl, sf = out["model"]["sort-last"], out["model"]["sort-first"]
    for N in [1, 16, 32, 64, 128, 256, 512, 1024]:
        sl_c = composite_model("sort-last", N, P, a) * 1e3 + sl["pack_core_ms_per_pixel"] * P / C
        sf_c = composite_model("sort-first", N, P, a) * 1e3
        sl_t = (sl["prepare_core_ms_per_record"] * T / N + sl["render_core_ms_per_pixel_fixed"] * P +
                sl["render_core_ms_per_pixel_divided"] * P / N) / C + sl_c
        sf_t = (sf["prepare_core_ms_per_record"] * T + sf["render_core_ms_per_pixel_fixed"] * P +
                sf["render_core_ms_per_pixel_divided"] * P / N) / C + sf_c
        pred.append((N, sl_t, sl_c, sf_t, sf_c, "%.2g / %.2g" % (T / N, T)))
        print("| %d | %.0f | %.0f | %.0f | %.0f | %s |" % pred[-1])
    out["prediction"]["table"] = pred

    out["table"] = rows
    out["title"] = os.path.basename(args.scene) + " " + args.size
    if args.json:
        with open(args.json, "w") as f:
            json.dump(out, f, indent=1)
    if args.plot:
        plot(out, args.plot)


def plot(out, path):
    """Measured against the model (left) and the prediction (right) from the figures main() computed (or a
    --json file of them: --replot). Zeros (no composite at N = 1) are left out of the log axes."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    positive = lambda v: v if v > 0 else float("nan")  # noqa: E731
    rows, pred = out["table"], out["prediction"]["table"]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 4.2))
    for mode, mk, colour in (("sort-last", "o", "tab:blue"), ("sort-first", "s", "tab:orange")):
        rr = [r for r in rows if r[0] == mode]
        ns = [r[1] for r in rr]
        ax1.plot(ns, [r[2] for r in rr], mk + "-", color=colour, label=mode + " frame, measured")
        ax1.plot(ns, [r[3] for r in rr], mk + "--", color=colour, alpha=0.6, label=mode + " frame, model")
        ax1.plot(ns, [positive(r[8]) for r in rr], mk + ":", color=colour, mfc="none",
                 label=mode + " composite, measured")
        ax1.plot(ns, [positive(r[9]) for r in rr], "x:", color=colour, label=mode + " composite, α–β model")
    ax1.axhline(out["one_process_frame_ms"], color="grey", lw=0.8, label="one process, no MPI")
    ax1.axhline(out["one_process_planned_frame_ms"], color="grey", lw=0.8, ls="--", label="one process, planned frame")
    ax1.set_yscale("log")
    ax1.set_xticks(sorted({r[1] for r in rows}))
    ax1.set_xlabel("ranks (one 2-core host)")
    ax1.set_ylabel("ms")
    ax1.set_title("measured vs model, " + out.get("title", ""))
    ax1.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ranks = [q[0] for q in pred]
    ax2.loglog(ranks, [q[1] for q in pred], "o-", color="tab:blue", label="sort-last frame")
    ax2.loglog(ranks, [positive(q[2]) for q in pred], "o:", color="tab:blue", mfc="none", label="sort-last composite")
    ax2.loglog(ranks, [q[3] for q in pred], "s-", color="tab:orange", label="sort-first frame")
    ax2.loglog(ranks, [positive(q[4]) for q in pred], "s:", color="tab:orange", mfc="none",
               label="sort-first composite")
    ax2.set_xlabel("ranks")
    ax2.set_ylabel("predicted ms")
    ax2.set_title("prediction: 100M triangles, 3840x2160")
    ax2.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


main()
