#!/usr/bin/env python3
"""Synthesis of the units' RTL (hw/) with Yosys, and the table and plot of docs/hardware.md.

For each unit, lane count (M, P) and register format: Yosys reads hw/*.v, elaborates the unit and
counts, at the word level (proc, flatten, opt, wreduce): adders ($add/$sub, by where they are: the
datapath's W-bit adders, the multiples of dI, the output rounding, the control counters), flip-flop
bits and multiplexer bits; then synthesizes to gates (synth -flatten, abc) for the gate count (the area
here) and the longest combinational path in gates (ltp -noff; the logic depth). The modeled clocks of
a scene (parashade plan, device-free) give each unit's throughput in pixels per clock.

  scripts/hw_synth.py [--out DIR] [--quick]
  --quick: the CI smoke test: segment:4 and segment:8 in fixed:9.7 only, checked against the adder count
           of docs/units.md (P/2 - 1 multiples, P - 1 outputs, 1 accumulator); no plot.
Needs yosys; the plot needs python3-matplotlib; the throughput needs a built parashade (BUILD).
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

from report_schema import schema

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LEN = 13  # hw/'s span length bits

# The sources' printed adder counts w(P) for the segment-parallel unit (the master's thesis's table).
SOURCE_W = {2: 2, 4: 4, 8: 8, 16: 14, 32: 22, 64: 32}


# The span control's registers and signals (row interpolators, pixels left, busy, valid), as hw/ names them.
CONTROL = {"first", "rest", "xr", "xa", "xb", "last", "busy", "full", "next_length", "x", "valid"}
_lines = {}


def assigned_name(src):
    """The name a cell's source line (Yosys src attribute "file:line.col-...") assigns to."""
    m = re.match(r"([^:|]+):(\d+)", src)
    if not m:
        return ""
    path, line = m.group(1), int(m.group(2))
    if path not in _lines:
        _lines[path] = open(path).read().split("\n")
    text = _lines[path][line - 1]
    a = re.search(r"assign\s+(\w+)", text) or re.search(r"(\w+)\s*(\[[^\]]*\])?\s*<=", text) or \
        re.search(r"wire\s+(\[[^\]]*\]\s*)?(\w+)\s*=", text)
    if not a:
        return ""
    return a.group(2) if a.re.pattern.startswith("wire") else a.group(1)


def is_control(src):
    return assigned_name(src) in CONTROL


def lane_param(unit):
    return {"interleave": "M", "pipelined": "M", "segment": "P"}.get(unit)


def hw_sources():
    """hw/'s Verilog files, the units and their parts."""
    return [os.path.join(ROOT, "hw", v) for v in sorted(os.listdir(os.path.join(ROOT, "hw"))) if v.endswith(".v")]


def unit_configs(formats, lane_counts):
    """(unit, lanes, I, F) per format "I.F": classic and counter (lanes 1 and 2), then at each lane count
    interleave, segment (a power of two from 2 only) and pipelined. Shared with scripts/hw_pnr.py."""
    configs = []
    for fmt in formats:
        i, f = map(int, fmt.split("."))
        configs += [("classic", 1, i, f), ("counter", 2, i, f)]
        for n in lane_counts:
            for unit in ("interleave", "segment", "pipelined"):
                if unit != "segment" or (n >= 2 and n & (n - 1) == 0):
                    configs.append((unit, n, i, f))
    return configs


def synthesize(unit, lanes, i, f, work):
    """Word-level cell counts and gate-level area and depth of one configuration."""
    top = "ps_" + unit
    params = ["-chparam I %d" % i, "-chparam F %d" % f]
    if lane_param(unit):
        params.append("-chparam %s %d" % (lane_param(unit), lanes))
    sources = " ".join(hw_sources())
    coarse = os.path.join(work, "coarse.json")
    script = ("read_verilog %s; hierarchy -top %s %s; proc; flatten; opt -full; wreduce; opt_clean; write_json %s; "
              "synth -flatten -top %s; stat; ltp -noff" % (sources, top, " ".join(params), coarse, top))
    log = subprocess.run(["yosys", "-p", script], capture_output=True, text=True)
    if log.returncode != 0:
        raise RuntimeError("yosys failed on %s:%d fixed:%d.%d:\n%s" % (unit, lanes, i, f, (log.stdout + log.stderr)[-2000:]))
    full = log.stdout
    w = i + f
    counts = {"adders_datapath": 0, "adders_multiples": 0, "adders_rounding": 0, "adders_control": 0,
              "comparators": 0, "ff_bits": 0, "ff_bits_datapath": 0, "mux_bits": 0}
    design = json.load(open(coarse))
    for module in design["modules"].values():
        bit_name = {}
        for name, net in module["netnames"].items():
            if not name.startswith("$"):
                for b in net["bits"]:
                    bit_name.setdefault(b, name.split(".")[-1])
        for cell in module["cells"].values():
            t = cell["type"]
            src = cell.get("attributes", {}).get("src", "")
            p = cell.get("parameters", {})
            width = int(p.get("Y_WIDTH", p.get("WIDTH", "0")), 2)
            if t in ("$add", "$sub"):
                if "ps_level.v" in src:
                    counts["adders_rounding"] += 1
                elif "ps_multiples.v" in src:
                    counts["adders_multiples"] += 1
                elif is_control(src):
                    counts["adders_control"] += 1
                else:
                    counts["adders_datapath"] += 1
            elif t in ("$eq", "$ne", "$lt", "$le", "$gt", "$ge"):
                counts["comparators"] += 1
            elif "dff" in t:
                counts["ff_bits"] += width
                if bit_name.get(cell["connections"]["Q"][0], "") not in CONTROL:
                    counts["ff_bits_datapath"] += width
            elif t in ("$mux", "$pmux"):
                counts["mux_bits"] += width
    counts["adders_w"] = counts["adders_datapath"] + counts["adders_multiples"]  # the unit's own W-bit adders
    m = re.findall(r"Number of cells:\s+(\d+)", full)
    counts["gates"] = int(m[-1]) if m else None
    d = re.findall(r"Longest topological path in \S+ \(length=(\d+)\)", full)
    counts["depth"] = int(d[-1]) if d else None
    return counts


def plan_clocks(parashade, scene, spec):
    out = subprocess.run([parashade, "plan", scene, "--units", spec, "--setup-clocks", "0"], capture_output=True,
                         text=True, check=True).stdout
    return int(re.search(r"plan round-robin, U = 1, tile \d+: modeled frame clocks (\d+)", out).group(1))


def throughput(parashade, scene, rows):
    """Pixels per modeled clock on the scene: pixels = pipelined:1's clocks (one clock per pixel, the
    load hidden); interleave and pipelined beyond 16 lanes (the unit table's limit) from segment:M's
    clocks, which are the same ceil(L/M) + 1 per span, minus one load clock per span for pipelined."""
    cache = {}

    def clocks(spec):
        if spec not in cache:
            cache[spec] = plan_clocks(parashade, scene, spec)
        return cache[spec]

    pixels = clocks("pipelined:1")
    spans = clocks("classic") - pixels
    for r in rows:
        u, n = r["unit"], r["lanes"]
        if u in ("classic", "counter"):
            c = clocks(u)
        elif u == "segment" or (u == "interleave" and n > 16):
            c = clocks("segment:%d" % n) if n >= 2 else clocks("classic")
        elif u == "interleave":
            c = clocks("interleave:%d" % n)
        else:  # pipelined
            c = clocks("pipelined:%d" % n) if n <= 16 else clocks("segment:%d" % n) - spans
        r["scene_clocks"] = c
        r["pixels_per_clock"] = pixels / c
    return pixels, spans


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default="bench-results/hw", help="folder for hw-synthesis.json/.md and the plot")
    ap.add_argument("--quick", action="store_true", help="CI smoke test (see above)")
    ap.add_argument("--scene", default=os.path.join(ROOT, "scenes", "teapot.json"))
    ap.add_argument("--formats", default="12.12,9.7")
    ap.add_argument("--plot-only", action="store_true", help="plot OUT/hw-synthesis.json again (no synthesis)")
    a = ap.parse_args()
    if a.plot_only:
        return plot(json.load(open(os.path.join(a.out, "hw-synthesis.json")))["rows"], a)
    if a.quick:
        configs = [("segment", 4, 9, 7), ("segment", 8, 9, 7)]
    else:
        configs = unit_configs(a.formats.split(","), (2, 4, 8, 16, 32, 64))
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for unit, n, i, f in configs:
            c = synthesize(unit, n, i, f, work)
            rows.append(dict(unit=unit, lanes=n, arith="fixed:%d.%d" % (i, f), **c))
            print("%-10s %2d fixed:%d.%-2d adders %3d datapath + %2d multiples + %2d rounding + %2d control, FF %5d bits, "
                  "mux %5d bits, %6s gates, depth %s" % (unit, n, i, f, c["adders_datapath"], c["adders_multiples"],
                  c["adders_rounding"], c["adders_control"], c["ff_bits"], c["mux_bits"], c["gates"], c["depth"]),
                  flush=True)
    if a.quick:
        bad = 0
        for r in rows:
            p = r["lanes"]
            ours = (p // 2 - 1) + (p - 1) + 1
            got = r["adders_multiples"] + r["adders_datapath"]
            if got != ours or r["adders_rounding"] != p:
                print("FAIL: segment:%d has %d datapath adders (%d rounding), docs/units.md's construction %d (%d)"
                      % (p, got, r["adders_rounding"], ours, p))
                bad += 1
        print("hw_synth --quick: %s" % ("ok" if not bad else "%d failures" % bad))
        return 1 if bad else 0
    build = os.environ.get("BUILD", os.path.join(ROOT, "build"))
    pixels, spans = throughput(os.path.join(build, "parashade"), a.scene, rows)
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "hw-synthesis.json"), "w") as fh:
        json.dump({"schema": schema("hw-synthesis"), "scene": os.path.basename(a.scene), "pixels": pixels, "spans": spans, "rows": rows}, fh, indent=1)
    lines = ["| unit | lanes | arith | adders: datapath + multiples (+ rounding, control) | sources' w(P) | FF bits | "
             "mux bits | gates | depth | %s pixels/clock |" % os.path.basename(a.scene).split(".")[0],
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        w = SOURCE_W.get(r["lanes"], "") if r["unit"] == "segment" else ""
        lines.append("| %s | %d | %s | %d + %d (+ %d, %d) | %s | %d | %d | %d | %d | %.2f |" % (
            r["unit"], r["lanes"], r["arith"], r["adders_datapath"], r["adders_multiples"], r["adders_rounding"],
            r["adders_control"], w, r["ff_bits"], r["mux_bits"], r["gates"], r["depth"], r["pixels_per_clock"]))
    with open(os.path.join(a.out, "hw-synthesis.md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    return plot(rows, a)


UNIT_MARKERS = (("classic", "o"), ("counter", "s"), ("interleave", "^"), ("segment", "v"), ("pipelined", "D"))


def plot_throughput_area(rows, out, stem, prog, x, y, labels, spread=None, keep=lambda r: True):
    """One plot per format of throughput (row key y) against area (row key x), a line per unit, the lane counts
    of the multi-lane units annotated; spread=(low key, high key) draws error bars. labels: (x label, y label,
    title), the x label followed by the format. Shared by hw_synth.py and hw_pnr.py."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("%s: python3-matplotlib not found: no plot" % prog, file=sys.stderr)
        return 0
    for fmt in sorted({r["arith"] for r in rows}):
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for unit, marker in UNIT_MARKERS:
            pts = sorted(((r[x], r[y], r["lanes"], r) for r in rows if r["unit"] == unit and r["arith"] == fmt and keep(r)),
                         key=lambda p: p[:3])
            if not pts:
                continue
            xs, ys = [p[0] for p in pts], [p[1] for p in pts]
            if spread:
                ax.errorbar(xs, ys, yerr=[[p[1] - p[3][spread[0]] for p in pts], [p[3][spread[1]] - p[1] for p in pts]],
                            marker=marker, label=unit, capsize=2)
            else:
                ax.plot(xs, ys, marker=marker, label=unit)
            for px, py, n, _ in pts:
                if unit not in ("classic", "counter"):
                    ax.annotate(str(n), (px, py), textcoords="offset points", xytext=(3, 3), fontsize=7)
        ax.set_xscale("log")
        ax.set_xlabel("%s, %s" % (labels[0], fmt))
        ax.set_ylabel(labels[1])
        ax.set_title(labels[2])
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
        fig.tight_layout()
        path = os.path.join(out, "%s-%s.png" % (stem, fmt.replace(":", "-").replace(".", "_")))
        fig.savefig(path, dpi=110)
        print("plot:", path)
    return 0


def plot(rows, a):
    return plot_throughput_area(rows, a.out, "hw-throughput-area", "hw_synth", "gates", "pixels_per_clock",
                                ("area: gates after synthesis (Yosys synth + abc)",
                                 "pixels per modeled clock, %s" % os.path.basename(a.scene),
                                 "Throughput against area (lanes annotated)"))

if __name__ == "__main__":
    sys.exit(main())
