#!/usr/bin/env python3
"""Measures render --distribute for N = 1..4 ranks on this host, fits the α–β cost model of
docs/distributed.md from an MPI ping-pong, checks it against the measured runs and predicts 16..1024 ranks
for a 100-million-triangle scene at 3840x2160.

    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 PARASHADE_MESH_DIR=/work/shared/meshes \\
        scripts/distributed_model.py --build build --scene scenes/bunny.json --size 1920x1080 \\
        --json distributed-model.json --plot docs/distributed-scaling.png

Prints the Markdown tables docs/distributed.md quotes. Needs mpirun and, for --plot, python3-matplotlib.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile


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


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default="build")
    ap.add_argument("--scene", default="scenes/bunny.json")
    ap.add_argument("--size", default="1920x1080")
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--ranks", default="1,2,3,4")
    ap.add_argument("--cores", type=int, default=os.cpu_count())
    ap.add_argument("--json")
    ap.add_argument("--plot")
    args = ap.parse_args()
    mpirun = ["mpirun", "--oversubscribe"]
    binary = os.path.join(args.build, "parashade")

    pp = json.loads(sh(mpirun + ["-np", "2", os.path.join(args.build, "parashade_mpi_ping_pong")]))
    a = {"alpha": pp["alpha_small_message_s"], "beta": pp["beta_s_per_byte"], "gamma": pp["gamma_s_per_pixel"]}
    w, h = map(int, args.size.split("x"))
    pixels = w * h

    runs = {}
    with tempfile.TemporaryDirectory() as tmp:
        for mode in ("sort-last", "sort-first"):
            for n in map(int, args.ranks.split(",")):
                rep = os.path.join(tmp, "r.json")
                sh(mpirun + ["-np", str(n), binary, "render", args.scene, "-o", os.path.join(tmp, "i.png"),
                             "--size", args.size, "--no-error", "-q", "--no-tuned", "--frames", str(args.frames),
                             "--warmup", "1", "--distribute", mode, "--report", rep])
                runs[(mode, n)] = json.load(open(rep))

    # Model of a rank's compute (prepare + render) on this host: A + B/N, slowed by max(1, N/cores) when
    # the ranks share the cores; fitted on N = 1, 2 and checked on the others.
    out = {"alpha_beta": a, "ping_pong": pp, "pixels": pixels, "runs": {}, "model": {}, "prediction": {}}
    rows = []
    for mode in ("sort-last", "sort-first"):
        ns = sorted(n for (m, n) in runs if m == mode)
        comp = {n: max(r["prepare_ms"] + r["render_ms"] for r in runs[(mode, n)]["per_rank"]) / 1e3 for n in ns}
        share = lambda n: max(1.0, n / args.cores)
        c1, c2 = comp[ns[0]] / share(ns[0]), comp[ns[1]] / share(ns[1])
        B = (c1 - c2) / (1 / ns[0] - 1 / ns[1])
        A = c1 - B / ns[0]
        out["model"][mode] = {"A_s": A, "B_s": B, "fitted_on": ns[:2]}
        for n in ns:
            r = runs[(mode, n)]
            meas_comp = max(p["composite_ms"] for p in r["per_rank"]) / 1e3
            model_comp = composite_model(mode, n, pixels, a)
            model_frame = (A + B / n) * share(n) + model_comp
            rows.append((mode, n, r["frame_ms"], model_frame * 1e3, comp[n] * 1e3, (A + B / n) * share(n) * 1e3,
                         meas_comp * 1e3, model_comp * 1e3, r["imbalance"]["render_ms"],
                         sum(p["bytes_sent"] for p in r["per_rank"]),
                         max(p["records"] for p in r["per_rank"]), max(p["peak_rss_mb"] for p in r["per_rank"])))
            out["runs"]["%s/%d" % (mode, n)] = r

    print("ping-pong (np 2, one host): alpha %.2f us, beta %.3f ns/byte (%.2f GB/s), gamma %.2f ns/pixel" %
          (a["alpha"] * 1e6, a["beta"] * 1e9, 1 / a["beta"] / 1e9, a["gamma"] * 1e9))
    print()
    print("| mode | N | frame ms measured | frame ms model | compute ms measured | compute ms model | "
          "composite ms measured | composite ms model | render imbalance | bytes sent (all ranks) | "
          "records (largest rank) | peak RSS MB (largest rank) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print("| %s | %d | %.1f | %.1f | %.1f | %.1f | %.2f | %.2f | %.2f | %d | %d | %.0f |" % r)

    # Prediction: 100M triangles, 3840x2160, one rank per node with the measured per-triangle and
    # per-pixel costs of one rank (the N = 1 run, this host's cores) and the ping-pong's α, β, γ.
    T, P = 100e6, 3840 * 2160
    print()
    print("| ranks | sort-last frame ms | of which composite | sort-first frame ms | of which composite | "
          "sort-last records per rank | sort-first records per rank |")
    print("|---:|---:|---:|---:|---:|---:|---:|")
    pred = []
    for mode in ("sort-last", "sort-first"):
        r1 = runs[(mode, 1)]["per_rank"][0]
        m = out["model"][mode]
        records = r1["records"]
        if mode == "sort-last":
            # A: per pixel on every rank (keys, read-back, pack); B: per triangle, divided among the ranks.
            per_px, per_tri = m["A_s"] / pixels, m["B_s"] / records
            out["prediction"][mode] = {"per_pixel_s": per_px, "per_triangle_s": per_tri}
        else:
            # Every rank prepares every triangle (A), the bands divide the shading (B, per pixel).
            per_tri, per_px = m["A_s"] / records, m["B_s"] / pixels
            out["prediction"][mode] = {"per_pixel_s": per_px, "per_triangle_s": per_tri}
    for N in [16, 32, 64, 128, 256, 512, 1024]:
        sl = out["prediction"]["sort-last"]
        sf = out["prediction"]["sort-first"]
        sl_c = composite_model("sort-last", N, P, a)
        sf_c = composite_model("sort-first", N, P, a)
        sl_t = sl["per_pixel_s"] * P + sl["per_triangle_s"] * T / N + sl_c
        sf_t = sf["per_triangle_s"] * T + sf["per_pixel_s"] * P / N + sf_c
        pred.append((N, sl_t * 1e3, sl_c * 1e3, sf_t * 1e3, sf_c * 1e3, T / N, T))
        print("| %d | %.0f | %.0f | %.0f | %.0f | %.2e | %.2e |" % pred[-1])
    out["prediction"]["table"] = pred

    if args.json:
        with open(args.json, "w") as f:
            json.dump(out, f, indent=1)
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4))
        for mode, mk in (("sort-last", "o"), ("sort-first", "s")):
            rr = [r for r in rows if r[0] == mode]
            ax1.plot([r[1] for r in rr], [r[2] for r in rr], mk + "-", label=mode + " measured")
            ax1.plot([r[1] for r in rr], [r[3] for r in rr], mk + "--", label=mode + " model")
        ax1.set_xlabel("ranks (one 2-core host)")
        ax1.set_ylabel("frame ms")
        ax1.set_title("measured vs model, " + os.path.basename(args.scene) + " " + args.size)
        ax1.legend(fontsize=8)
        ax2.loglog([p[0] for p in pred], [p[1] for p in pred], "o-", label="sort-last")
        ax2.loglog([p[0] for p in pred], [p[2] for p in pred], "o:", label="sort-last composite")
        ax2.loglog([p[0] for p in pred], [p[3] for p in pred], "s-", label="sort-first")
        ax2.loglog([p[0] for p in pred], [p[4] for p in pred], "s:", label="sort-first composite")
        ax2.set_xlabel("ranks")
        ax2.set_ylabel("predicted frame ms")
        ax2.set_title("prediction: 100M triangles, 3840x2160")
        ax2.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=100)


main()
