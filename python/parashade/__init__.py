"""parashade from Python (docs/python.md): the library's render step, devices, compare and tune, with images
as NumPy arrays and reports as the dicts the command line's reports hold.

    import parashade
    r = parashade.render(parashade.load_scene("scenes/teapot.json"), method="phong", size=(640, 360))
    print(r.report["frame_ms"], r.image.shape)
"""
import json
import os
import tempfile

import numpy as np

from . import _parashade
from .errors import ConfigError, DeviceError, Error, InputError, UsageError  # noqa: F401
from .options import option_words

__version__ = _parashade.version
_OUTPUTS = ("output", "o", "report")  # written, not rendered: a call that differs in them keeps the renderer


class Scene:
    """A scene file (JSON, or a bare .obj .off .ply .stl mesh) checked once; render() reads it at its options'
    size. name, width, height and triangles are the scene's as loaded."""

    def __init__(self, path, info, size=""):
        self.path = os.fspath(path)
        self.size = size  # "WxH" given to load_scene, passed on to render (its own size= wins)
        self.name, self.width, self.height = info["scene"], info["width"], info["height"]
        self.triangles = info["triangles"]

    def __repr__(self):
        return "Scene(%r: %s, %dx%d, %d triangles)" % (self.path, self.name, self.width, self.height, self.triangles)


class RenderResult:
    """image: H x W x 4 uint8 (RGBA, alpha 255 where covered), or with float=True H x W x 4 float32: the unclamped
    colour in 8-bit levels and the same alpha; rgba: the 8-bit image always. report: the render report's dict
    (docs/reports.md); frame_ms, stages_ms, error: its median frame, its stage medians and its error figures."""

    def __init__(self, raw):
        self.rgba = raw["rgba"]
        rgb = raw["rgb_float"]
        self.image = self.rgba if rgb is None else np.dstack((rgb, self.rgba[..., 3].astype(np.float32)))
        self.report = json.loads(raw["report"])
        self.frame_ms = self.report["frame_ms"]
        self.stages_ms = self.report.get("stages_ms")
        self.error = self.report.get("error")

    def __repr__(self):
        return "RenderResult(%s, %dx%d, %.3f ms)" % (self.report["scene"], self.report["width"],
                                                   self.report["height"], self.frame_ms)


def _path(scene):
    return scene.path if isinstance(scene, Scene) else os.fspath(scene)


def _scene_key(path):
    try:
        return "%s@%d" % (os.path.abspath(path), os.stat(path).st_mtime_ns)
    except OSError:
        return path  # the command says what is wrong with it


def render(scene, **options):
    """Renders `scene` (a Scene or a path) as `parashade render` does, with its options by name (method="phong",
    units="interleave:4", size=(160, 90), frames=5, float=True, output="x.png", report="x.json", ...)."""
    path = _path(scene)
    if isinstance(scene, Scene) and scene.size and options.get("size") is None:
        options = dict(options, size=scene.size)
    words = [path] + option_words(options)
    kept = [_scene_key(path)] + option_words({k: v for k, v in options.items() if k not in _OUTPUTS})
    return RenderResult(_parashade.render(words, kept))


def render_command(words):
    """render's words as the command line takes them, the scene first (["scenes/sphere.json", "--method", "phong",
    "-o", "x.png"]): for scripts that hold command lines (scripts/render_report.py). render() is the same with
    keyword arguments."""
    words = [os.fspath(w) for w in words]
    kept = [_scene_key(words[0])] + words[1:] if words else []
    return RenderResult(_parashade.render(words, kept))


def _report_of(command, words):
    """Runs `command` in this process with --report into a temporary file; returns (exit code, report)."""
    with tempfile.TemporaryDirectory(prefix="parashade-") as tmp:
        path = os.path.join(tmp, "report.json")
        code = _parashade.run_command([command] + words + ["--report", path])
        with open(path) as f:
            return code, json.load(f)


def load_scene(path, size=None):
    """The scene file loaded as render loads it (at size=(W, H) or "WxH" when given); raises InputError for a
    missing or broken file."""
    size = "%dx%d" % tuple(size) if isinstance(size, (list, tuple)) else (size or "")
    return Scene(path, _parashade.scene_info(os.fspath(path), size), size)


def devices():
    """Every OpenCL device as `parashade devices --report` lists it: a list of dicts (name, platform, compute
    units, which one is the default)."""
    return _report_of("devices", [])[1]["devices"]


def compare(a, b, **options):
    """Image file `a` against reference `b` as `parashade compare` (fail=LEVELS, fail_percent=P, flip=True,
    error_map="m.png", ...): its report's dict; "passed" is False above fail=."""
    code, report = _report_of("compare", [os.fspath(a), os.fspath(b)] + option_words(options))
    report.setdefault("passed", code == 0)
    return report


def tune(scene, params=None, max_error=None, **options):
    """`parashade tune`: params={"tile": [16, 32], "work_items": [0, 64]} (--param tile=16,32 ...), max_error=
    LEVELS, and tune's other options by name (strategy="random", budget_runs=20, cache="t.json"); its report's dict."""
    options = dict(options, param=params, max_error=max_error)
    return _report_of("tune", [_path(scene)] + option_words(options))[1]


def clear_cache():
    """Drops the kept devices, their compiled kernels and the last renderer (the next render opens and builds
    again)."""
    _parashade.clear_cache()
