#!/usr/bin/env python3
"""scripts/mix_oracle.py: the knapsack and the shares worked by hand on made-up pixels, and a real study of the
sphere at 320x180 whose own check (its NMSE of all-Gouraud and all-Phong equal to render's) must pass.

    mix_oracle_test.py SOURCE_DIR PARASHADE_BINARY
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

from checks import check, finish, load_script

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "schema"))
from schema_store import errors, validator  # noqa: E402  (tests/schema: the schemas as validators)

SOURCE, BINARY = sys.argv[1], sys.argv[2]
oracle = load_script(SOURCE, "mix_oracle")


def near(a, b):
    return a is not None and abs(a - b) < 1e-12


# Gains 6, 3, 1 per pixel: removing 7 takes the first whole and a third of the second.
one = np.ones(3)
check(near(oracle.fewest_phong(np.array([1.0, 6.0, 3.0]), one, 7.0), 1 + 1 / 3), "knapsack of 7 from 6, 3, 1")
check(near(oracle.fewest_phong(np.array([1.0, 6.0, 3.0]), one, 0.0), 0.0), "nothing to remove")
check(oracle.fewest_phong(np.array([1.0, 6.0, 3.0]), one, 11.0) is None, "more than everything removes")
# By gain per pixel: a 2-pixel triangle removing 8 (4 a pixel) goes before a 1-pixel one removing 3.
check(near(oracle.fewest_phong(np.array([3.0, 8.0]), np.array([1.0, 2.0]), 8.0), 2.0), "by gain per pixel")

# Four pixels, reference grey 0, 100, 100, 200 (spread 3 x 20000 over the channels); Phong exact; Gouraud off by
# 10 at pixel 1 and by 20 at pixel 3 in every channel (squared error 300 and 1200). All-Gouraud NMSE 1500 / 60000
# = 0.025; at most 0.01 (600) leaves 900 to remove. Per pixel: pixel 3 removes 1200, 900 of it is 3/4 of the
# pixel (the knapsack counts the last item in part: a lower bound), share 0.75 / 4. Per triangle, pixels 0-1 are
# triangle 1 and 2-3 triangle 2: triangle 2 removes 1200 over 2 pixels, 900 of it is 3/4 of them: 1.5 pixels,
# share 3/8.
R = np.repeat(np.array([0.0, 100.0, 100.0, 200.0])[:, None], 3, axis=1)
G = R + np.repeat(np.array([0.0, 10.0, 0.0, 20.0])[:, None], 3, axis=1)
s = oracle.oracle_shares(G, R.copy(), R, np.array([1, 1, 2, 2]), 0.01)
check(near(s["nmse_gouraud"], 0.025) and near(s["nmse_phong"], 0.0), "NMSE of the made-up images: %r" % s)
check(near(s["phong_share_per_pixel"], 0.1875), "per-pixel share %r, not 3/16" % s["phong_share_per_pixel"])
check(near(s["phong_share_per_triangle"], 0.375), "per-triangle share %r, not 3/8" % s["phong_share_per_triangle"])
check(s["oracle_triangles"] == [2] and near(s["oracle_predicted_nmse"], 0.005),
      "whole-triangle oracle %r, predicted NMSE %r: not triangle 2 and 300 / 60000" % (s["oracle_triangles"],
                                                                                       s["oracle_predicted_nmse"]))
# The centroid rule: three triangles of three pixels in a row each (reference 0, 100, 200; spread 3 x 3 x 20000),
# Gouraud off at the middle pixel only in triangle 0 (10: 300) and 2 (5: 75), at both ends only in triangle 1 (20:
# 2400). All-Gouraud 2775; at most 0.005 (900) leaves 1875 to remove. The samples rank 0, 2, 1: all nine pixels
# before enough is removed, where the oracle takes 1875 / 2400 of triangle 1 (its three pixels counted in part).
R3 = np.repeat(np.tile([0.0, 100.0, 200.0], 3)[:, None], 3, axis=1)
G3 = R3 + np.repeat(np.array([0, 10, 0, 20, 0, 20, 0, 5, 0.0])[:, None], 3, axis=1)
ids3, x3, y3 = np.array([0, 0, 0, 1, 1, 1, 2, 2, 2]), np.arange(9.0), np.zeros(9)
s3 = oracle.oracle_shares(G3, R3.copy(), R3, ids3, 0.005, x3, y3)
check(near(s3["phong_share_centroid_rule"], 1.0) and near(s3["phong_share_per_triangle"], 1875 / 2400 * 3 / 9),
      "centroid rule %r (not 1) against the oracle's %r (not 0.26)" % (s3["phong_share_centroid_rule"],
                                                                     s3["phong_share_per_triangle"]))
check(s["phong_share_centroid_rule"] is None, "a centroid share without positions")
# Phong 4 ms (kernel 3), Gouraud 2 ms (kernel 1): a quarter of the pixels by Phong costs 0.5 ms more, 4 / 2.5.
check(oracle.pixels_render_covers({"pixels_compared": 99, "front_surface_mismatch": 1}) == 100,
      "a pixel whose front surface flipped is covered, though render does not compare it")
check(oracle.pixels_render_covers({"pixels_compared": 99}) == 99, "reports without the count")
check(near(oracle.bound(4.0, 2.0, 3.0, 1.0, 0.25), 1.6), "bound of the worked example")
check(near(oracle.allowed_share(4.0, 2.0, 3.0, 1.0, 1.6), 0.25), "share the target allows")
# Per pair: 4 / 2.5 = 1.6, 8 / 4.5, 2 / 1.5; the median is 1.6 (the medians' ratio would be 4 / 2.5 too, but the
# slow pair 8 / 4 must not count as 8 / 2.5).
check(near(oracle.paired_bound([4.0, 8.0, 2.0], [2.0, 4.0, 1.0], 3.0, 1.0, 0.25), 1.6), "bound per pair")

with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "o.json")
    r = subprocess.run([sys.executable, os.path.join(SOURCE, "scripts", "mix_oracle.py"), "--binary", BINARY,
                        "--scenes", os.path.join(SOURCE, "scenes", "sphere.json"), "--size", "320x180",
                        "--frames", "3", "--budgets", "2", "--json", out], capture_output=True, text=True)
    check(r.returncode == 0, "real study failed: " + r.stderr[-800:])
    if r.returncode == 0:
        doc = json.load(open(out))
        errs = errors(validator(os.path.join(SOURCE, "schemas"), "mix-oracle"), doc)
        check(not errs, "the study's file does not validate against mix-oracle.schema.json: %s" % errs[:3])
        row = doc["rows"][0]
        check(row["size"] == "320x180", "size not passed on: " + row["size"])
        pp, pt = row["phong_share_per_pixel"], row["phong_share_per_triangle"]
        check(pp is not None and pt is not None and 0 < pp <= pt <= 1,
              "per-pixel share %r should be positive and at most the per-triangle %r" % (pp, pt))
        check(row["bound_per_pixel"] >= row["bound_per_triangle"], "fewer Phong pixels gave a lower bound")
        check(row["phong_share_centroid_rule"] is not None and row["phong_share_centroid_rule"] >= pt,
              "the centroid rule's share %r below the per-triangle oracle's %r"
              % (row["phong_share_centroid_rule"], pt))
        rule = row["rules"][0]
        check(rule["max_error"] == 2 and (rule["nmse"] > row["max_nmse"] or rule["phong_share"] >= pt),
              "the bound rule's share %r below the per-triangle oracle's %r" % (rule["phong_share"], pt))

finish()
