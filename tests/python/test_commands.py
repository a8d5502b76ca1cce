"""devices(), load_scene(), compare() and tune() give what the commands' reports hold (issue 49)."""
import json

import numpy as np

from conftest import run_cli, scene


def test_devices_lists_the_commands_devices(parashade, tmp_path):
    proc = run_cli(["devices", "--report", str(tmp_path / "d.json")])
    assert proc.returncode == 0, proc.stderr
    assert parashade.devices() == json.load(open(tmp_path / "d.json"))["devices"]


def test_load_scene_says_what_render_renders(parashade):
    s = parashade.load_scene(scene("teapot.json"), size=(200, 100))
    r = parashade.render(s, frames=1, q=True, no_error=True)
    assert (s.name, s.width, s.height, s.triangles) == ("teapot", 200, 100, r.report["triangles"]["in"])
    assert r.image.shape == (100, 200, 4)


def test_compare_is_the_commands(parashade, tmp_path):
    a, b = str(tmp_path / "a.png"), str(tmp_path / "b.png")
    parashade.render(scene("sphere.json"), size=(64, 64), frames=1, method="gouraud", output=a, q=True)
    parashade.render(scene("sphere.json"), size=(64, 64), frames=1, method="phong", output=b, q=True)
    same = parashade.compare(a, a)
    assert same["passed"] and same["exact"] and same["error"]["max_abs"] == 0
    diff = parashade.compare(a, b, fail=0.5)
    proc = run_cli(["compare", a, b, "--fail", "0.5", "--report", str(tmp_path / "c.json")])
    assert proc.returncode == 1 and diff["passed"] is False
    cli = json.load(open(tmp_path / "c.json"))
    assert diff["error"] == cli["error"] and diff["max_at"] == cli["max_at"] and diff["pixels_over_fail"] > 0


def test_commands_print_nothing_on_stdout(parashade, tmp_path, capfd):
    """The command's results are the dict returned: compare and devices print none of them (the command
    prints its figures and a `wrote` line; devices its list)."""
    a = str(tmp_path / "a.png")
    parashade.render(scene("sphere.json"), size=(32, 32), frames=1, output=a, q=True)
    capfd.readouterr()
    assert parashade.compare(a, a)["passed"]
    assert parashade.devices()
    print("python's own print")
    out = capfd.readouterr().out
    assert out == "python's own print\n", out


def test_tune_searches_and_render_takes_its_best(parashade, tmp_path):
    cache = str(tmp_path / "tune.json")
    report = parashade.tune(scene("sphere.json"), params={"tile": [16, 32]}, max_error=10, size=(128, 72),
                            frames=1, budget_runs=4, cache=cache, q=True)
    assert report["best"]["params"]["tile"] in (16, 32)
    r = parashade.render(scene("sphere.json"), size=(128, 72), frames=1, tune_cache=cache, q=True)
    assert r.report["tuned"]["params"]["tile"] == report["best"]["params"]["tile"]
    assert np.asarray(r.image).shape == (72, 128, 4)
