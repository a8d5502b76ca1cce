"""Bad input raises the command line's message with its exit-code category, and the interpreter goes on
(issue 49; the CLI's trust cases, docs/robustness.md)."""
import pytest

from conftest import cli_words, run_cli, scene

# (options of render, the exception's class name)
CASES = [
    ({"method": "phongg"}, "UsageError"),                              # a bad value
    ({"methd": "phong"}, "UsageError"),                                # an unknown option
    ({"size": "0x48"}, "UsageError"),                                  # an absurd size
    ({"size": "100000x100000"}, "UsageError"),
    ({"frames": -1}, "UsageError"),
    ({"units": "sierpinski:1", "coverage": "dda"}, "ConfigError"),     # a combination the table refuses
    ({"device": "no-such-device"}, "DeviceError"),
]


@pytest.mark.parametrize("options,kind", CASES, ids=[str(c[0]) for c in CASES])
def test_bad_option_raises_the_commands_error(parashade, tmp_path, options, kind):
    with pytest.raises(parashade.Error) as raised:
        parashade.render(scene("teapot.json"), q=True, **options)
    e = raised.value
    assert type(e).__name__ == kind
    proc = run_cli(["render", scene("teapot.json"), "-o", str(tmp_path / "x.png"), "-q"] + cli_words(options))
    assert proc.returncode == e.exit_code, proc.stderr
    assert "parashade: error: " + str(e).splitlines()[0] in proc.stderr


@pytest.mark.parametrize("name,content", [("missing.json", None), ("garbage.json", "{not json"),
                                         ("garbage.obj", "v 1 2\nf 1 2 99\n"), ("empty.ply", "")])
def test_bad_scene_raises_input_error(parashade, tmp_path, name, content):
    path = tmp_path / name
    if content is not None:
        path.write_text(content)
    for call in (lambda: parashade.load_scene(str(path)), lambda: parashade.render(str(path), q=True)):
        with pytest.raises(parashade.InputError) as raised:
            call()
        assert raised.value.exit_code == 3 and str(path) in str(raised.value)
    assert not list(tmp_path.glob("*.png"))


def test_outputs_need_an_image_and_nothing_half_written(parashade, tmp_path):
    with pytest.raises(parashade.UsageError):
        parashade.render(scene("sphere.json"), report=str(tmp_path / "r.json"), q=True)
    with pytest.raises(parashade.InputError):  # an output's folder that does not exist
        parashade.render(scene("sphere.json"), size=(32, 32), output=str(tmp_path / "no" / "x.png"), q=True)
    assert list(tmp_path.iterdir()) == []


def test_the_interpreter_renders_after_errors(parashade):
    r = parashade.render(scene("sphere.json"), size=(32, 32), frames=1, q=True)
    assert r.image.shape == (32, 32, 4)
