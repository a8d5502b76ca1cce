#!/usr/bin/env python3
"""scripts/combined_study.py's ceiling: worked by hand on made-up runs, and present, with both methods' pixels
and --size passed on, in a real study of the sphere with Phong, Gouraud and one per-triangle choice.

    combined_study_test.py SOURCE_DIR PARASHADE_BINARY|module

`module`: the study renders through the Python module (its default; PYTHONPATH names build/python), else
through the command at PARASHADE_BINARY (--binary).
"""
import json
import os
import subprocess
import sys
import tempfile

from checks import check, finish, load_script

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "schema"))
from schema_store import errors, validator  # noqa: E402  (tests/schema: the schemas as validators)

SOURCE, BINARY = sys.argv[1], sys.argv[2]
BINARY_ARGS = [] if BINARY == "module" else ["--binary", BINARY]
study = load_script(SOURCE, "combined_study")


def run(frame, kernel, pixels=None):
    r = {"frame_ms": frame, "stages_ms": {"kernel_ms": kernel}}
    if pixels:
        r["stats"] = {"triangle_choice": {"visible_pixels": pixels}}
    return r


# Phong: frame 4, kernel 3; Gouraud's kernel 1; the mix: frame 3, kernel 2, a quarter of the pixels by Phong.
# The model's kernel is 1 + 0.25 * (3 - 1) = 1.5, its frame 3 - 2 + 1.5 = 2.5, the ceiling 4 / 2.5 = 1.6.
phong, gouraud = run(4.0, 3.0), run(1.5, 1.0)
mix = run(3.0, 2.0, {"gouraud": 75, "segments": 0, "phong": 25})
got = study.ceiling(mix, phong, gouraud)
check(got is not None and abs(got - 1.6) < 1e-12, "ceiling of the worked example: %r, not 1.6" % got)
check(study.ceiling(run(3.0, 2.0), phong, gouraud) is None, "a run without visible pixels has a ceiling")
check(study.ceiling(mix, phong, None) is None, "a ceiling without a Gouraud run")
check(study.ceiling(run(3.0, 2.0, {"gouraud": 60, "segments": 15, "phong": 25}), phong, gouraud) is None,
      "a ceiling that prices segment pixels at Gouraud's cost")
check(study.ceiling(run(3.0, 2.0, {"gouraud": 0, "segments": 0, "phong": 0}), phong, gouraud) is None,
      "a ceiling from no pixels")

# The ratio to Phong: the median of the pairs' ratios where Phong ran in the same process (render --against),
# else the ratio of the two runs' medians.
same = {"frame_ms": 2.0, "stages_ms": {"kernel_ms": 1.0},
        "against": {"frame_ms": 5.0, "stages_ms": {"kernel_ms": 4.0}, "frame_ratio": {"median": 1.7},
                    "kernel_ratio": {"median": 3.5}}}
check(study.pair_ratio(same, same["against"], "frame") == 1.7, "in-process frame ratio not the pairs' median")
check(study.pair_ratio(same, same["against"], "kernel") == 3.5, "in-process kernel ratio not the pairs' median")
check(study.pair_ratio(same, phong, "frame") == 2.0, "ratio of two runs' frames: %r" % study.pair_ratio(same, phong, "frame"))
check(study.pair_ratio(same, phong, "kernel") == 3.0, "ratio of two runs' kernels")

with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "paired.json")
    proc = subprocess.run([sys.executable, os.path.join(SOURCE, "scripts", "combined_study.py")] + BINARY_ARGS + [
                           "--scenes", os.path.join(SOURCE, "scenes", "sphere.json"), "--size", "480x270", "--frames", "3",
                           "--pairing", "in-process", "--methods", "phong", "gouraud",
                           "combined:0@16 --triangle-choice bound", "--json", out],
                          capture_output=True, text=True)
    check(proc.returncode == 0, "the in-process study failed: %s" % proc.stderr[-2000:])
    if proc.returncode == 0:
        doc = json.load(open(out))
        errs = errors(validator(os.path.join(SOURCE, "schemas"), "combined-study"), doc)
        check(not errs, "the study's file does not validate against combined-study.schema.json: %s" % errs[:3])
        check(doc.get("pairing") == "in-process", "pairing not recorded: %r" % doc.get("pairing"))
        rows = {m["method"]: m for m in doc["measurements"]}
        check("--against phong" in rows["gouraud"]["command"], "Gouraud not rendered against Phong: " + rows["gouraud"]["command"])
        check("--against" not in rows["phong"]["command"], "Phong rendered against itself")
        check(rows["combined:0@16 --triangle-choice bound"].get("ceiling_frame_ratio") is not None,
              "no ceiling with in-process pairs")
        check("alternating with its own in one process" in proc.stdout, "the table does not say where its ratios come from")

with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "study.json")
    proc = subprocess.run([sys.executable, os.path.join(SOURCE, "scripts", "combined_study.py")] + BINARY_ARGS + [
                           "--scenes", os.path.join(SOURCE, "scenes", "sphere.json"), "--size", "960x540", "--frames", "1", "--methods",
                           "phong", "gouraud", "combined:0@16 --triangle-choice bound", "--json", out],
                          capture_output=True, text=True)
    check(proc.returncode == 0, "the study failed: %s" % proc.stderr[-2000:])
    if proc.returncode == 0:
        rows = {m["method"]: m for m in json.load(open(out))["measurements"]}
        mixed = rows.get("combined:0@16 --triangle-choice bound", {})
        c = mixed.get("ceiling_frame_ratio")
        pix = (mixed.get("triangle_choice") or {}).get("visible_pixels") or {}
        check(c is not None and c > 0, "no ceiling for the per-triangle choice: %r" % c)
        check(rows["phong"].get("ceiling_frame_ratio") is None, "Phong itself has a ceiling")
        check(pix.get("phong", 0) > 0 and pix.get("gouraud", 0) > 0, "the sphere's mix has no Phong or no Gouraud pixels: %r" % pix)
        check("ceiling vs Phong (frame)" in proc.stdout, "the table has no ceiling column")
        check(mixed.get("width") == 960 and mixed.get("height") == 540, "--size not passed to render: %r x %r"
              % (mixed.get("width"), mixed.get("height")))

finish()
