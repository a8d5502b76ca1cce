"""What the script tests share: a scripts/ file loaded as a module, and checks that collect their failures and
set the exit code at the end (every check runs, so one run names every failure)."""
import importlib.util
import os
import sys

failures = []


def load_script(source_dir, name):
    """scripts/NAME.py of the source tree as a module (scripts/ on the path, for the modules it imports)."""
    scripts = os.path.join(source_dir, "scripts")
    if scripts not in sys.path:
        sys.path.insert(0, scripts)
    spec = importlib.util.spec_from_file_location(name, os.path.join(source_dir, "scripts", name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL: " + what)


def finish():
    """Exit 1 naming the count if any check failed, else print ok."""
    if failures:
        sys.exit("%d failure(s)" % len(failures))
    print("ok")
