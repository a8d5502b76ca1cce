#!/usr/bin/env python3
"""The units at a clock rate: place and route of hw/ on an iCE40 (docs/hardware.md, "Place and route").

For each unit, lane count (M, P) and register format (the list of scripts/hw_synth.py): Yosys synthesizes
the unit alone for the iCE40 (synth_ice40) — its LUTs (SB_LUT4), carry cells (SB_CARRY) and flip-flops
(SB_DFF*), the area — and again inside a harness (every input and output of the unit registered; the
inputs fed from one pin through a shift chain, the outputs kept without pins: the unit's ports do not
fit the package's pins), which nextpnr-ice40 places and routes once per seed. Fmax is nextpnr's
achieved frequency (its --report JSON) on the harness: register to register through the unit, so the
load path (the input registers, the multiples of dI, the lane registers) and the output path (register,
rounding, output register) are timed like the clocked path. The median over the seeds and the spread.
The modeled clocks of a scene (parashade plan, as hw_synth) give the pixels per clock;
pixels per microsecond = Fmax in MHz x pixels per clock.

  scripts/hw_pnr.py [--out DIR] [--seeds N] [--formats 12.12,9.7] [--lanes 1,2,3,4,8,16] [--resume]
  scripts/hw_pnr.py --out docs/bench-report/results/hw --check-doc docs/hardware.md   (ctest hw.pnr_table)
  scripts/hw_pnr.py --quick   the CI smoke test: classic in fixed:9.7, one seed; fails unless Fmax, LUTs,
                              carries and FFs are read; exits 77 (ctest: skipped) without nextpnr-ice40.
nextpnr runs under nice -n 15, one at a time. Needs yosys and nextpnr-ice40 (scripts/install-deps.sh --test);
the plot python3-matplotlib; the throughput a built parashade (BUILD).
"""
import argparse
import json
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hw_synth import LEN, ROOT, hw_sources, lane_param, plot_throughput_area, throughput, unit_configs  # noqa: E402
from report_schema import schema  # noqa: E402

DEVICE, PACKAGE = "hx8k", "ct256"  # iCE40HX8K: 7 680 logic cells, the largest iCE40 nextpnr 0.4 knows but the UP5K's 5 280
TARGET_MHZ = 100  # the timing-driven placer's goal; the achieved Fmax is what is reported
SKIP = 77  # ctest's skip code


def unit_lanes(unit, lanes):
    """Output lanes of a unit: N pixels per clock at most."""
    return {"classic": 1, "counter": 2}.get(unit, lanes)


def harness(unit, lanes, i, f):
    """Verilog of the harness around one configuration: registered inputs from a shift chain (one pin),
    registered outputs kept (no pins). Its flip-flops are counted in the harness's figures, not the unit's."""
    w, n = i + f, unit_lanes(unit, lanes)
    param = ", .%s(%d)" % (lane_param(unit), lanes) if lane_param(unit) else ""
    return """module pnr_harness (input wire clk, input wire rst, input wire din, output wire dout);
  localparam W = %(w)d, LEN = %(len)d, N = %(n)d, IN = 1 + 4 * W + LEN;
  reg [IN-1:0] in_r;
  always @(posedge clk) in_r <= {in_r[IN-2:0], din};
  wire ready; wire [N-1:0] valid; wire [N*LEN-1:0] x; wire [N*W-1:0] value; wire [N*8-1:0] level;
  ps_%(unit)s #(.I(%(i)d), .F(%(f)d)%(param)s) u (.clk(clk), .rst(rst), .load(in_r[0]), .ready(ready),
    .s_in(in_r[1 +: W]), .e_in(in_r[1 + W +: W]), .step_in(in_r[1 + 2 * W +: W]),
    .lane_step_in(in_r[1 + 3 * W +: W]), .length_in(in_r[1 + 4 * W +: LEN]),
    .valid(valid), .x(x), .value(value), .level(level));
  (* keep *) reg [N * (1 + LEN + W + 8):0] out_r;
  always @(posedge clk) out_r <= {ready, valid, x, value, level};
  assign dout = out_r[0] ^ in_r[IN-1];
endmodule
""" % dict(w=w, len=LEN, n=n, unit=unit, i=i, f=f, param=param)


def run(cmd, what):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError("%s failed (%s):\n%s" % (what, " ".join(cmd[:3]), (p.stdout + p.stderr)[-1500:]))
    return p


def cell_counts(netlist, top):
    """SB_LUT4, SB_CARRY and SB_DFF* cells of the top module of a synth_ice40 JSON netlist."""
    cells = json.load(open(netlist))["modules"][top]["cells"].values()
    types = [c["type"] for c in cells]
    return {"luts": types.count("SB_LUT4"), "carries": types.count("SB_CARRY"),
            "ffs": sum(t.startswith("SB_DFF") for t in types)}


def synth_ice40(unit, lanes, i, f, work):
    """The unit's own iCE40 cells, and the harness's netlist for nextpnr (path)."""
    top, sources = "ps_" + unit, " ".join(hw_sources())
    params = "-chparam I %d -chparam F %d" % (i, f)
    if lane_param(unit):
        params += " -chparam %s %d" % (lane_param(unit), lanes)
    alone = os.path.join(work, "unit.json")
    run(["yosys", "-q", "-p", "read_verilog %s; hierarchy -top %s %s; synth_ice40 -top %s -json %s"
         % (sources, top, params, top, alone)], "yosys synth_ice40 on %s:%d" % (unit, lanes))
    area = cell_counts(alone, top)
    wrapper, netlist = os.path.join(work, "harness.v"), os.path.join(work, "harness.json")
    with open(wrapper, "w") as fh:
        fh.write(harness(unit, lanes, i, f))
    run(["yosys", "-q", "-p", "read_verilog %s %s; synth_ice40 -top pnr_harness -json %s" % (sources, wrapper, netlist)],
        "yosys synth_ice40 on the harness of %s:%d" % (unit, lanes))
    area["harness"] = cell_counts(netlist, "pnr_harness")
    return area, netlist


def parse_report(path):
    """Fmax (MHz) and logic cells of a nextpnr --report JSON; an error unless both are there."""
    report = json.load(open(path))
    fmax = [v.get("achieved") for v in report.get("fmax", {}).values()]
    if len(fmax) != 1 or not isinstance(fmax[0], (int, float)) or fmax[0] <= 0:
        raise ValueError("%s: no Fmax of the one clock in nextpnr's report (fmax: %r)" % (path, report.get("fmax")))
    lc = report.get("utilization", {}).get("ICESTORM_LC", {})
    if not isinstance(lc.get("used"), int) or not isinstance(lc.get("available"), int):
        raise ValueError("%s: no ICESTORM_LC utilization in nextpnr's report" % path)
    return {"fmax_mhz": fmax[0], "logic_cells": lc["used"], "logic_cells_available": lc["available"],
            "critical_path": critical_path(report)}


def register_name(cell):
    """The Verilog register a nextpnr cell name comes from ("u.acc_SB_DFFE_Q_3_DFFLC" -> "u.acc")."""
    return re.split(r"_SB_|_DFFLC|\$", cell)[0]


def critical_path(report):
    """The clock-to-clock critical path: its start and end registers (u. is the unit, in_r and out_r the
    harness's), its LUT and carry steps, its delay and the routing's part of it."""
    for c in report.get("critical_paths", []):
        if c.get("from", "").startswith("posedge") and c.get("to", "").startswith("posedge") and c.get("path"):
            steps = c["path"]
            return {"from": register_name(steps[0]["to"]["cell"]), "to": register_name(steps[-1]["to"]["cell"]),
                    "logic_steps": sum(st["type"] == "logic" for st in steps),
                    "ns": round(sum(st["delay"] for st in steps), 3),
                    "routing_ns": round(sum(st["delay"] for st in steps if st["type"] == "routing"), 3)}
    return None


def place_and_route(netlist, seed, work):
    """One nextpnr-ice40 run: its report, or the reason it failed (e.g. the design does not fit)."""
    report, log = os.path.join(work, "report-%d.json" % seed), os.path.join(work, "pnr-%d.log" % seed)
    cmd = ["nice", "-n", "15", "nextpnr-ice40", "--%s" % DEVICE, "--package", PACKAGE, "--json", netlist,
           "--seed", str(seed), "--freq", str(TARGET_MHZ), "--timing-allow-fail", "--pcf-allow-unconstrained",
           "--report", report, "-q", "-l", log]
    start = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        errors = [ln for ln in open(log).read().split("\n") if "ERROR" in ln] if os.path.exists(log) else []
        return {"seed": seed, "error": (errors or [(p.stdout + p.stderr).strip()[-300:]])[0]}
    return dict(seed=seed, seconds=round(time.time() - start, 1), **parse_report(report))


def measure(config, seeds, work):
    unit, lanes, i, f = config
    area, netlist = synth_ice40(unit, lanes, i, f, work)
    runs = [place_and_route(netlist, s, work) for s in seeds]
    row = dict(unit=unit, lanes=lanes, arith="fixed:%d.%d" % (i, f), **area, runs=runs)
    done = [r["fmax_mhz"] for r in runs if "fmax_mhz" in r]
    row["fits"] = len(done) == len(runs)
    if row["fits"]:
        row.update(fmax_mhz=statistics.median(done), fmax_min=min(done), fmax_max=max(done),
                   logic_cells=runs[0]["logic_cells"])
    return row


def versions():
    tool = subprocess.run(["nextpnr-ice40", "--version"], capture_output=True, text=True)
    yosys = subprocess.run(["yosys", "-V"], capture_output=True, text=True).stdout.strip()
    cpu = next((ln.split(":", 1)[1].strip() for ln in open("/proc/cpuinfo") if ln.startswith("model name")), "?") \
        if os.path.exists("/proc/cpuinfo") else platform.processor()
    return {"nextpnr": (tool.stdout + tool.stderr).strip().split("\n")[0], "yosys": yosys,
            "machine": "%s, %d logical CPUs, %s" % (cpu, os.cpu_count(), platform.platform()),
            "date": time.strftime("%Y-%m-%d", time.gmtime())}


def add_throughput(rows, a):
    """Pixels per clock (hw_synth's throughput), pixels per microsecond and per 1 000 LUTs."""
    build = os.environ.get("BUILD", os.path.join(ROOT, "build"))
    pixels, spans = throughput(os.path.join(build, "parashade"), a.scene, rows)
    for r in rows:
        r["clocks_per_pixel"] = 1 / r["pixels_per_clock"]
        if r["fits"]:
            r["pixels_per_us"] = r["fmax_mhz"] * r["pixels_per_clock"]
            r["pixels_per_us_min"] = r["fmax_min"] * r["pixels_per_clock"]
            r["pixels_per_us_max"] = r["fmax_max"] * r["pixels_per_clock"]
            r["pixels_per_us_per_1000_luts"] = r["pixels_per_us"] / (r["luts"] / 1000)
    return pixels, spans


def best_lanes(rows):
    """Per lane-parameterized unit and format: the lane count of the most pixels per microsecond, and of
    the most per 1 000 LUTs (the claims table's "M <= 4 is the optimum" reads these)."""
    best = []
    for unit in ("interleave", "segment", "pipelined"):
        for fmt in sorted({r["arith"] for r in rows}):
            mine = [r for r in rows if r["unit"] == unit and r["arith"] == fmt and r["fits"]]
            if mine:
                best.append({"unit": unit, "arith": fmt,
                             "lanes_fastest": max(mine, key=lambda r: r["pixels_per_us"])["lanes"],
                             "lanes_per_area": max(mine, key=lambda r: r["pixels_per_us_per_1000_luts"])["lanes"],
                             "lanes_measured": sorted(r["lanes"] for r in mine)})
    return best


def median_path(row):
    """The critical path of the run whose Fmax is the median: "from → to (steps)"."""
    run = min((r for r in row["runs"] if "fmax_mhz" in r), key=lambda r: abs(r["fmax_mhz"] - row["fmax_mhz"]))
    p = run.get("critical_path")
    return "%s → %s (%d)" % (p["from"], p["to"], p["logic_steps"]) if p else ""


def table(rows):
    lines = ["| unit | lanes | arith | Fmax MHz: median (min–max) | LUTs | carries | FFs | logic cells (harness) | "
             "clocks/pixel | pixels/µs (min–max) | pixels/µs per 1 000 LUTs | critical path (steps) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if not r["fits"]:
            lines.append("| %s | %d | %s | does not fit: %s | %d | %d | %d | | %.3f | | | |" % (
                r["unit"], r["lanes"], r["arith"], next(x["error"] for x in r["runs"] if "error" in x)[:80],
                r["luts"], r["carries"], r["ffs"], r["clocks_per_pixel"]))
            continue
        lines.append("| %s | %d | %s | %.1f (%.1f–%.1f) | %d | %d | %d | %d | %.3f | %.1f (%.1f–%.1f) | %.1f | %s |" % (
            r["unit"], r["lanes"], r["arith"], r["fmax_mhz"], r["fmax_min"], r["fmax_max"], r["luts"], r["carries"],
            r["ffs"], r["logic_cells"], r["clocks_per_pixel"], r["pixels_per_us"], r["pixels_per_us_min"],
            r["pixels_per_us_max"], r["pixels_per_us_per_1000_luts"], median_path(r)))
    return "\n".join(lines) + "\n"


def check_doc(doc, result):
    """The table in the docs is the committed result's (ctest hw.pnr_table)."""
    want = table(json.load(open(result))["rows"])
    if want in open(doc).read():
        print("hw_pnr --check-doc: %s holds the table of %s" % (doc, result))
        return 0
    print("FAIL: %s does not hold the table of %s; it should read:\n%s" % (doc, result, want))
    return 1


def quick(work):
    """The smoke test: one small unit placed and routed; every figure must be read."""
    row = measure(("classic", 1, 9, 7), [1], work)
    print(json.dumps(row, indent=1))
    run0 = row["runs"][0]
    missing = [k for k in ("luts", "carries", "ffs") if not row[k] > 0] + \
        [k for k in ("fmax_mhz", "logic_cells") if not run0.get(k, 0) > 0]
    if missing:
        print("FAIL: not read from the place and route of classic fixed:9.7: %s" % ", ".join(missing))
        return 1
    print("hw_pnr --quick: ok (Fmax %.1f MHz, %d LUTs, %d carries, %d FFs, %.1f s)"
          % (run0["fmax_mhz"], row["luts"], row["carries"], row["ffs"], run0["seconds"]))
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default="bench-results/hw", help="folder for hw-pnr.json/.md and the plots")
    ap.add_argument("--quick", action="store_true", help="CI smoke test (see above)")
    ap.add_argument("--seeds", type=int, default=3, help="nextpnr seeds 1..N per configuration")
    ap.add_argument("--formats", default="12.12,9.7")
    ap.add_argument("--lanes", default="1,2,3,4,8,16", help="M or P (segment: the powers of two only)")
    ap.add_argument("--resume", action="store_true", help="keep the configurations OUT/hw-pnr.json has; run the rest")
    ap.add_argument("--scene", default=os.path.join(ROOT, "scenes", "teapot.json"))
    ap.add_argument("--plot-only", action="store_true",
                    help="the table (OUT/hw-pnr.md) and the plots again from OUT/hw-pnr.json (no place and route)")
    ap.add_argument("--check-doc", metavar="FILE", help="exit 1 unless FILE holds OUT/hw-pnr.json's table verbatim")
    a = ap.parse_args()
    if a.plot_only:
        rows = json.load(open(os.path.join(a.out, "hw-pnr.json")))["rows"]
        with open(os.path.join(a.out, "hw-pnr.md"), "w") as fh:
            fh.write(table(rows))
        return plot(rows, a)
    if a.check_doc:
        return check_doc(a.check_doc, os.path.join(a.out, "hw-pnr.json"))
    for tool in ("yosys", "nextpnr-ice40"):
        if not shutil.which(tool):
            print("hw_pnr: %s not found (scripts/install-deps.sh --test installs it): skipped" % tool)
            return SKIP
    result_path = os.path.join(a.out, "hw-pnr.json")
    rows = json.load(open(result_path))["rows"] if a.resume and os.path.exists(result_path) else []
    done = {(r["unit"], r["lanes"], r["arith"]) for r in rows}
    with tempfile.TemporaryDirectory() as work:
        if a.quick:  # writes nothing to OUT
            return quick(work)
        os.makedirs(a.out, exist_ok=True)
        for config in unit_configs(a.formats.split(","), [int(n) for n in a.lanes.split(",")]):
            if (config[0], config[1], "fixed:%d.%d" % config[2:]) in done:
                continue
            rows.append(measure(config, range(1, a.seeds + 1), work))
            with open(result_path, "w") as fh:  # so far: an interrupted sweep goes on with --resume
                json.dump({"rows": rows}, fh, indent=1)
            r = rows[-1]
            print("%-10s %2d %s: %s, %d LUTs, %d carries, %d FFs" % (
                r["unit"], r["lanes"], r["arith"], "Fmax %.1f MHz (%.1f-%.1f)" % (r["fmax_mhz"], r["fmax_min"], r["fmax_max"])
                if r["fits"] else "does not fit", r["luts"], r["carries"], r["ffs"]), flush=True)
    pixels, spans = add_throughput(rows, a)
    result = dict(schema=schema("hw-pnr"), **versions(), device="iCE40%s (%s)" % (DEVICE.upper(), PACKAGE), target_mhz=TARGET_MHZ,
                  seeds=a.seeds, scene=os.path.basename(a.scene), pixels=pixels, spans=spans,
                  best=best_lanes(rows), rows=rows)
    with open(result_path, "w") as fh:
        json.dump(result, fh, indent=1)
    with open(os.path.join(a.out, "hw-pnr.md"), "w") as fh:
        fh.write(table(rows))
    print(table(rows))
    return plot(rows, a)


def plot(rows, a):
    return plot_throughput_area(
        rows, a.out, "hw-pnr-throughput-area", "hw_pnr", "luts", "pixels_per_us",
        ("area: iCE40 LUTs of the unit (Yosys synth_ice40)",
         "pixels per µs = Fmax × pixels/clock, %s" % os.path.basename(a.scene),
         "Throughput in time against area, iCE40%s (median of seeds, bars: spread)" % DEVICE.upper()),
        spread=("pixels_per_us_min", "pixels_per_us_max"), keep=lambda r: r["fits"])

if __name__ == "__main__":
    sys.exit(main())
