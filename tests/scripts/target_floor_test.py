#!/usr/bin/env python3
"""scripts/target_floor.py's arithmetic on made-up figures: the kernel's fill floor from the covered share, the
ratio a kernel at its floor would give, the floors read in any time unit, covered pixels against the scene's
background. Usage: target_floor_test.py SOURCE_DIR"""
import json
import os
import sys
import tempfile

import numpy as np

from checks import check, finish, load_script

floor = load_script(sys.argv[1], "target_floor")


def near(a, b):
    return abs(a - b) <= 1e-9 * max(1.0, abs(b))


def bench(name, ms, unit="ms"):
    scale = {"ms": 1, "us": 1e3, "ns": 1e6}[unit]
    return {"name": name + "/64x32/manual_time_median", "real_time": ms * scale, "time_unit": unit}


floors = {"benchmarks": [bench("fill_limit", 0.2), bench("plane_fill_limit", 0.4, "us"),
                         bench("phong_plane_fill_limit", 3.0, "ns")]}
check(near(floor.bench_median(floors, "plane_fill_limit", "64x32"), 0.4), "microseconds read as ms")
check(near(floor.bench_median(floors, "phong_plane_fill_limit", "64x32"), 3.0), "nanoseconds read as ms")

stages = {"geometry_ms": 0.3, "setup_ms": 0.2, "binning_ms": 0.1, "kernel_ms": 1.0, "total_ms": 2.0}
g = floor.floor_row({"scene": "s", "method": "gouraud", "ratio_median": 3.0}, stages, 0.5, floors, "64x32", 5.0)
check(near(g["kernel_floor_ms"], 0.5 * 0.4 + 0.5 * 0.2), "Gouraud floor: half the pixels planes, half fill: %r" % g)
check(near(g["best_ratio"], 3.0 / ((2.0 - 1.0 + 0.3) / 2.0)), "the ratio with the kernel at its floor: %r" % g)
check(near(g["host_ms"], 0.6), "host stages: geometry, setup, binning")
p = floor.floor_row({"scene": "s", "method": "phong", "ratio_median": 2.0}, stages, 1.0, floors, "64x32", 4.0)
check(near(p["kernel_floor_ms"], 3.0), "Phong floor: every pixel at the Phong floor: %r" % p)
check(p["best_ratio"] < 2.0, "a kernel faster than its floor is not made slower: the ratio falls")

with tempfile.TemporaryDirectory() as tmp:
    scene = os.path.join(tmp, "s.json")
    with open(scene, "w") as f:
        json.dump({"background": [0.2, 0.4, 0.6]}, f)
    image = np.zeros((2, 4, 3), dtype=np.uint8)
    image[:, :] = [51, 102, 153]  # the background, rounded as the renderer writes it
    image[0, :3] = [200, 10, 10]
    check(near(floor.covered_fraction(image, scene), 3 / 8), "3 of 8 pixels differ from the background")
finish()
