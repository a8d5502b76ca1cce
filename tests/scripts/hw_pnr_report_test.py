#!/usr/bin/env python3
"""scripts/hw_pnr.py's readers on files written here in nextpnr-ice40 0.4's and Yosys's shapes (no nextpnr
needed): a report with its Fmax, logic cells and critical path is read; one without an Fmax, with two
clocks or without the utilization is an error; the iCE40 cells are counted in the top module only.

    hw_pnr_report_test.py SOURCE_DIR
"""
import json
import os
import sys
import tempfile

from checks import check, finish, load_script

hw_pnr = load_script(sys.argv[1], "hw_pnr")
CLK = "clk$SB_IO_IN_$glb_clk"


def step(kind, delay, cell_from, cell_to):
    return {"type": kind, "delay": delay, "from": {"cell": cell_from, "port": "O"}, "to": {"cell": cell_to, "port": "I0"}}


def report(**replace):
    """A report as nextpnr-ice40 0.4 writes it (--report): fmax per clock, utilization per bel, critical paths."""
    doc = {"fmax": {CLK: {"achieved": 131.5, "constraint": 100}},
           "utilization": {"ICESTORM_LC": {"available": 7680, "used": 717}, "SB_IO": {"available": 256, "used": 4}},
           "critical_paths": [
               {"from": "<async>", "to": "posedge " + CLK, "path": [step("routing", 9.0, "din", "in_r_SB_DFF_Q_0_DFFLC")]},
               {"from": "posedge " + CLK, "to": "posedge " + CLK, "path": [
                   step("clk-to-q", 0.5, "u.r_SB_DFFE_Q_LC", "in_r_SB_DFF_Q_47_DFFLC"),
                   step("routing", 1.25, "in_r_SB_DFF_Q_47_DFFLC", "u.x_SB_LUT4_O_LC"),
                   step("logic", 0.25, "u.x_SB_LUT4_O_LC", "u.x_SB_LUT4_O_LC"),
                   step("routing", 0.5, "u.x_SB_LUT4_O_LC", "u.r_SB_DFFE_Q_46_D_SB_LUT4_O_LC"),
                   step("setup", 0.5, "u.r_SB_DFFE_Q_46_D_SB_LUT4_O_LC", "u.r_SB_DFFE_Q_46_D_SB_LUT4_O_LC")]}]}
    doc.update(replace)
    return doc


def parse(tmp, doc):
    path = os.path.join(tmp, "report.json")
    with open(path, "w") as f:
        json.dump(doc, f)
    try:
        return hw_pnr.parse_report(path)
    except ValueError as e:
        return "error: %s" % e


with tempfile.TemporaryDirectory() as tmp:
    got = parse(tmp, report())
    check(isinstance(got, dict) and got["fmax_mhz"] == 131.5 and got["logic_cells"] == 717
          and got["logic_cells_available"] == 7680, "a whole report: %r" % (got,))
    path = got.get("critical_path") if isinstance(got, dict) else None
    check(path == {"from": "in_r", "to": "u.r", "logic_steps": 1, "ns": 3.0, "routing_ns": 1.75},
          "the clock-to-clock critical path (in_r to u.r, one LUT, 3 ns of which 1.75 routing): %r" % (path,))
    for what, doc in (("no fmax", report(fmax={})),
                      ("two clocks", report(fmax={CLK: {"achieved": 131.5}, "clk2": {"achieved": 90.0}})),
                      ("no achieved", report(fmax={CLK: {"constraint": 100}})),
                      ("Fmax 0", report(fmax={CLK: {"achieved": 0}})),
                      ("no utilization", report(utilization={}))):
        got = parse(tmp, doc)
        check(isinstance(got, str) and got.startswith("error:"), "%s must be an error, read %r" % (what, got))

    netlist = os.path.join(tmp, "netlist.json")
    cells = ["SB_LUT4", "SB_LUT4", "SB_LUT4", "SB_CARRY", "SB_CARRY", "SB_DFF", "SB_DFFE", "SB_DFFESR", "SB_GB"]
    with open(netlist, "w") as f:
        json.dump({"modules": {
            "pnr_harness": {"cells": {"c%d" % i: {"type": t} for i, t in enumerate(cells)}},
            "SB_LUT4": {"cells": {"s": {"type": "$specify2"}}},
            "other": {"cells": {"x": {"type": "SB_LUT4"}}}}}, f)
    got = hw_pnr.cell_counts(netlist, "pnr_harness")
    check(got == {"luts": 3, "carries": 2, "ffs": 3}, "the top module's LUTs 3, carries 2, FFs 3: %r" % (got,))

check(hw_pnr.register_name("u.acc_SB_DFFE_Q_3_DFFLC") == "u.acc", "register of u.acc_SB_DFFE_Q_3_DFFLC")
check(hw_pnr.register_name("out_r_SB_DFF_Q_12_DFFLC") == "out_r", "register of out_r_SB_DFF_Q_12_DFFLC")
counter = hw_pnr.harness("counter", 2, 9, 7)
check("ps_counter #(.I(9), .F(7))" in counter and "N = 2" in counter and "W = 16" in counter,
      "the counter's harness: two lanes of 16 bits, no lane parameter\n" + counter)
check("ps_segment #(.I(12), .F(12), .P(8))" in hw_pnr.harness("segment", 8, 12, 12), "segment:8's harness sets P")
finish()
