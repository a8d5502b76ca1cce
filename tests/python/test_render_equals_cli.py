"""The module's images equal the command line's byte for byte, and its reports equal the command's except
what depends on time (issue 49): Gouraud, Phong, a fixed-point unit path, combined:auto."""
import json
import os

import numpy as np
import pytest
from PIL import Image

from conftest import cli_words, run_cli, scene, untimed

CASES = {
    "gouraud": {"method": "gouraud"},
    "phong": {"method": "phong"},
    "interleave4_fixed": {"method": "gouraud", "units": "interleave:4", "arith": "fixed:12.12"},
    "combined_auto": {"method": "combined:auto", "max_error": 2},
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_image_and_report_equal_the_commands(parashade, tmp_path, case):
    options = dict(CASES[case], size="320x180", frames=2, no_tuned=True)
    cli_png, cli_json = tmp_path / "cli.png", tmp_path / "cli.json"
    words = cli_words({k: v for k, v in options.items() if k != "no_tuned"}) + ["--no-tuned", "-q"]
    proc = run_cli(["render", scene("teapot.json"), "-o", str(cli_png), "--report", str(cli_json)] + words)
    assert proc.returncode == 0, proc.stderr

    mod_png, mod_json = tmp_path / "module.png", tmp_path / "module.json"
    r = parashade.render(scene("teapot.json"), output=str(mod_png), report=str(mod_json), q=True, **options)

    assert mod_png.read_bytes() == cli_png.read_bytes(), "the written PNGs differ"
    cli_rgb = np.asarray(Image.open(cli_png).convert("RGB"))
    assert r.image.dtype == np.uint8 and r.image.shape == (180, 320, 4)
    assert np.array_equal(r.image[..., :3], cli_rgb), "the returned array is not the command's image"
    cli_report = json.load(open(cli_json))
    assert untimed(r.report) == untimed(cli_report)
    assert untimed(json.load(open(mod_json))) == untimed(cli_report)
    assert r.frame_ms == r.report["frame_ms"] and r.stages_ms == r.report["stages_ms"] and r.error == r.report["error"]


def test_float_image_is_the_unclamped_read_back(parashade):
    r = parashade.render(scene("sphere.json"), size=(96, 64), frames=1, float=True, q=True)
    assert r.image.dtype == np.float32 and r.image.shape == (64, 96, 4)
    covered = r.rgba[..., 3] == 255
    assert covered.any() and np.array_equal(r.image[..., 3], r.rgba[..., 3].astype(np.float32))
    # The 8-bit image is the float values rounded and clamped: within one level where covered.
    diff = np.abs(np.clip(r.image[..., :3], 0, 255) - r.rgba[..., :3].astype(np.float32))[covered]
    assert diff.max() <= 1.0
