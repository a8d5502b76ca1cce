"""Fixtures of the Python module's tests (docs/python.md): the command line to hold the module to, the source
tree's scenes, and reports compared without what depends on time. Run by ctest (python.*) with PYTHONPATH at
build/python and PARASHADE_BINARY at the parashade command of the same build."""
import os
import subprocess

import pytest

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("PARASHADE_BINARY", os.path.join(SOURCE, "build", "parashade"))


def scene(name):
    return os.path.join(SOURCE, "scenes", name)


def run_cli(words, cwd=None):
    """`parashade WORDS`: the completed process (stdout and stderr as text)."""
    return subprocess.run([BINARY] + list(words), capture_output=True, text=True, cwd=cwd)


def cli_words(options):
    """Keyword options as the command's words, for the command-line side of a comparison (--name value)."""
    words = []
    for k, v in options.items():
        words += ["--" + k.replace("_", "-"), str(v)]
    return words


# The report's keys that depend on the run (its time, the machine's load, the date, the command line that made
# it) or on where the image went, by name; everything else must be equal.
UNTIMED_SKIP = {"created_utc", "host", "command_line", "image", "timing", "mpixel_per_s", "mtriangle_per_s"}


def untimed(value):
    if isinstance(value, dict):
        return {k: untimed(v) for k, v in value.items()
                if k not in UNTIMED_SKIP and not k.endswith("_ms") and not k.endswith("_ratio")}
    if isinstance(value, list):
        return [untimed(v) for v in value]
    return value


@pytest.fixture(scope="session")
def parashade():
    import parashade as module
    return module
