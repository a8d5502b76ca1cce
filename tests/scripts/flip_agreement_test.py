#!/usr/bin/env python3
"""parashade's LDR-FLIP (host/reference/flip.cpp, written from the paper) against NVIDIA's own implementation,
the PyPI package `flip-evaluator`, on a set of image pairs: the mean FLIP of `parashade compare A B --flip`
and its per-pixel map (`--flip-map F.exr`) against flip_evaluator.evaluate(B, A, "LDR") on the same values.

    flip_agreement_test.py SOURCE_DIR PARASHADE_BINARY WORK_DIR

Makes a venv in WORK_DIR/flip-venv (system site packages, for NumPy and Pillow) and pip-installs
flip-evaluator into it; exits 77 (ctest: skipped) with a message when that fails (no registry reachable).
Tolerance: 1e-4 per pixel and 2e-5 on the mean. Both sides compute in float: their filters sum in other
orders and parashade takes cube roots with cbrt, which moves single pixels by about 1e-5 (measured 1.4e-5 at
most); a wrong constant moves them by 1e-3 or more (docs/pictures.md, "FLIP").
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

from pip_venv import venv_with

PIXEL_TOLERANCE = 1e-4
MEAN_TOLERANCE = 2e-5


def make_venv(work):
    return venv_with(work, "flip-venv", ["flip_evaluator", "numpy", "PIL"], ["flip-evaluator", "numpy", "pillow"])


# Runs inside the venv: writes the pairs, runs parashade compare on each and flip_evaluator on the same values,
# prints one JSON line per pair.
CHILD = r'''
import json, os, subprocess, sys
import numpy as np
from PIL import Image
import flip_evaluator as fe

binary, out = sys.argv[1], sys.argv[2]
rng = np.random.default_rng(47)

def pairs():
    h, w = 64, 96
    y, x = np.mgrid[0:h, 0:w]
    ramp = np.stack([x * 255 // (w - 1), y * 255 // (h - 1), np.full_like(x, 77)], -1).astype(np.uint8)
    yield "ramp+noise", ramp, np.clip(ramp + rng.normal(0, 6, ramp.shape), 0, 255).astype(np.uint8)
    yield "ramp+25", ramp, np.clip(ramp.astype(int) + 25, 0, 255).astype(np.uint8)
    checker = (((x // 4 + y // 4) % 2) * 255).astype(np.uint8)
    yield "checker/grey", np.stack([checker] * 3, -1), np.full((h, w, 3), 128, np.uint8)
    noise = rng.integers(0, 256, (50, 70, 3)).astype(np.uint8)
    yield "noise+noise", noise, np.clip(noise + rng.normal(0, 20, noise.shape), 0, 255).astype(np.uint8)
    disc = ((x - 48) ** 2 + (y - 32) ** 2 < 400)[..., None] * np.array([200, 120, 40]) + 20
    yield "disc/shifted", disc.astype(np.uint8), np.roll(disc, 1, axis=1).astype(np.uint8)

def read_float_tiff(path):
    return np.asarray(Image.open(path), dtype=np.float32)

for name, ref, test in pairs():
    rp, tp = os.path.join(out, "ref.png"), os.path.join(out, "test.png")
    Image.fromarray(ref).save(rp)
    Image.fromarray(test).save(tp)
    exr, tif, rep = os.path.join(out, "flip.exr"), os.path.join(out, "flip.tif"), os.path.join(out, "c.json")
    subprocess.run([binary, "compare", tp, rp, "--flip", "--flip-map", exr, "--report", rep, "-q"], check=True,
                   stdout=subprocess.DEVNULL)
    mine = json.load(open(rep))["error"]["flip"]["mean"]
    theirs_map, theirs_mean, _ = fe.evaluate(ref.astype(np.float32) / 255, test.astype(np.float32) / 255, "LDR",
                                             applyMagma=False)
    theirs_map = np.asarray(theirs_map, dtype=np.float64).reshape(ref.shape[0], ref.shape[1])
    row = {"pair": name, "size": [ref.shape[1], ref.shape[0]], "parashade": mine,
           "flip_evaluator": float(theirs_map.mean()), "flip_evaluator_own_mean": float(theirs_mean)}
    if subprocess.run(["oiiotool", exr, "-d", "float", "-o", tif], capture_output=True).returncode == 0:
        row["max_pixel_difference"] = float(np.abs(read_float_tiff(tif) - theirs_map).max())
    print(json.dumps(row))
'''


def main():
    source, binary, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    python = make_venv(work)
    version = subprocess.run([python, "-m", "pip", "show", "flip-evaluator"], capture_output=True, text=True).stdout
    version = next((l.split(":", 1)[1].strip() for l in version.splitlines() if l.startswith("Version:")), "?")
    failures, pairs = [], 0
    with tempfile.TemporaryDirectory() as out:
        if shutil.which("oiiotool") is None:
            print("note: no oiiotool (openimageio-tools): the means only, not the maps pixel by pixel")
        run = subprocess.run([python, "-c", CHILD, binary, out], capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stdout + run.stderr)
            return 1
        for line in run.stdout.splitlines():
            r = json.loads(line)
            pairs += 1
            diff = abs(r["parashade"] - r["flip_evaluator"])
            pixel = r.get("max_pixel_difference")
            print("%-13s %dx%d  parashade %.7f  flip-evaluator %s %.7f  |mean diff| %.1e  max |pixel diff| %s" %
                  (r["pair"], r["size"][0], r["size"][1], r["parashade"], version, r["flip_evaluator"], diff,
                   "%.1e" % pixel if pixel is not None else "-"))
            if diff > MEAN_TOLERANCE:
                failures.append("%s: mean FLIP %.7f, flip-evaluator %.7f" % (r["pair"], r["parashade"], r["flip_evaluator"]))
            if pixel is not None and pixel > PIXEL_TOLERANCE:
                failures.append("%s: a pixel differs by %.2e from flip-evaluator's" % (r["pair"], pixel))
    for f in failures:
        print("FAIL " + f)
    print("flip agreement: %d pairs, %d failed" % (pairs, len(failures)))
    return 1 if failures or pairs == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
