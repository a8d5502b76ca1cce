"""One render with a JSON report, for the study scripts (combined_study.py, phong_methods.py, mix_oracle.py):
through the Python module parashade in this process (docs/python.md) when `binary` is None, else a `parashade
render` process (a build without -DPARASHADE_PYTHON=ON has no module). Either way the image and the report go
to tmp/NAME.png and tmp/NAME.json and the command line is printed to stderr; a failure raises parashade.Error
(the module) or subprocess.CalledProcessError (the command)."""
import json
import os
import subprocess
import sys


def module():
    """The module parashade: installed, or in build/python of this repository."""
    try:
        import parashade
    except ImportError:
        sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "python"))
        try:
            import parashade
        except ImportError as e:
            sys.exit("no Python module parashade (%s): build it (cmake -DPARASHADE_PYTHON=ON, docs/python.md) or "
                     "give --binary build/parashade to run the command" % e)
    return parashade


def render_report(binary, scene, args, tmp, name="r"):
    """Renders `scene` with `args` into tmp/NAME.png and tmp/NAME.json; returns the report and the command line
    (without the binary)."""
    report = os.path.join(tmp, name + ".json")
    cmd = [binary or "parashade", "render", scene, "-o", os.path.join(tmp, name + ".png"), "--report", report, "-q"]
    cmd += list(args)
    print("running:", " ".join(cmd), file=sys.stderr)
    if binary is None:
        module().render_command(cmd[2:])
    else:
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(report) as f:
        return json.load(f), " ".join(cmd[1:])
