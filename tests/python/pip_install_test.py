#!/usr/bin/env python3
"""`pip install .` from the repository root into a fresh venv, then issue 49's one-liner (docs/python.md):

    pip_install_test.py SOURCE_DIR BUILD_DIR

The build goes to BUILD_DIR/pip-build (removed first: a fresh CMake build) through ccache when there is one,
so a second run compiles nothing (CCACHE_BASEDIR=/work, as the build's own); ~6 min cold here, 13 s warm.
Skipped (77) when pip cannot reach the package registry for scikit-build-core. Not in the default suite
(tests/CMakeLists.txt: -DPARASHADE_PIP_TEST=ON)."""
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from pip_venv import SKIP, venv_with  # noqa: E402

SOURCE, BUILD = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
ONE_LINER = ("import parashade; print(parashade.render(parashade.load_scene('scenes/teapot.json'))"
             ".report['frame_ms'])")


def main():
    venv = os.path.join(os.environ.get("PARASHADE_TEST_VENVS") or BUILD, "pip-install-venv")
    shutil.rmtree(venv, ignore_errors=True)
    shutil.rmtree(os.path.join(BUILD, "pip-build"), ignore_errors=True)
    python = venv_with(BUILD, "pip-install-venv", ["numpy"], ["numpy"])  # fresh; Debian's NumPy
    settings = ["--config-settings=build-dir=" + os.path.join(BUILD, "pip-build")]
    if shutil.which("ccache"):
        settings.append("--config-settings=cmake.define.CMAKE_CXX_COMPILER_LAUNCHER=ccache")
    start = time.monotonic()
    pip = subprocess.run([python, "-m", "pip", "install", "--disable-pip-version-check", "--no-cache-dir", "--timeout",
                          "30", SOURCE] + settings, capture_output=True, text=True, cwd=SOURCE)
    print("pip install . took %.0f s" % (time.monotonic() - start))
    if pip.returncode != 0:
        if "scikit-build-core" in pip.stdout + pip.stderr and "No matching distribution" in pip.stdout + pip.stderr:
            print("SKIP: pip could not fetch scikit-build-core:\n" + pip.stderr[-1500:])
            sys.exit(SKIP)
        print("FAIL: pip install . failed:\n" + (pip.stdout + pip.stderr)[-4000:])
        sys.exit(1)
    run = subprocess.run([python, "-c", "import parashade; print(parashade.__file__)\n" + ONE_LINER],
                         capture_output=True, text=True, cwd=SOURCE)
    lines = run.stdout.split()
    if run.returncode != 0 or len(lines) != 2 or not lines[0].startswith(venv) or not float(lines[1]) > 0:
        print("FAIL: the one-liner in the venv:\n" + run.stdout + run.stderr[-2000:])
        sys.exit(1)
    print("ok: %s, frame_ms %s" % (lines[0], lines[1]))


main()
