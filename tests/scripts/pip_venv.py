"""A venv in the build folder with PyPI packages the tests compare against (flip-evaluator, kernel_tuner),
made once and reused; system site packages, for NumPy and Pillow. PARASHADE_TEST_VENVS names another folder
for them (scripts/sanitize.sh points it at the main build's, so CI's sanitizer pass does not pip again)."""
import os
import subprocess
import sys

SKIP = 77  # ctest's SKIP_RETURN_CODE for these tests


def venv_with(work, name, imports, packages):
    """The venv WORK/NAME's python, after `import IMPORTS` works in it (pip-installing PACKAGES if not); exits
    SKIP with a message when pip cannot install them (no registry reachable)."""
    venv = os.path.join(os.environ.get("PARASHADE_TEST_VENVS") or work, name)
    python = os.path.join(venv, "bin", "python")
    if not os.path.exists(python):
        made = subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", venv], capture_output=True, text=True)
        if made.returncode != 0:  # e.g. Debian without python3-venv (install-deps.sh --test installs it)
            print("SKIP: cannot make a venv at %s:\n%s" % (venv, made.stderr[-1500:]))
            sys.exit(SKIP)
    have = subprocess.run([python, "-c", "import " + ", ".join(imports)], capture_output=True)
    if have.returncode != 0:
        pip = subprocess.run([python, "-m", "pip", "install", "--disable-pip-version-check", "-q", "--timeout", "30",
                              "--retries", "1", *packages], capture_output=True, text=True)
        if pip.returncode != 0:
            print("SKIP: pip could not install %s (is the package registry reachable?):\n%s" %
                  (" ".join(packages), pip.stderr[-1500:]))
            sys.exit(SKIP)
    return python
