"""One `parashade render` with a JSON report, for the study scripts (combined_study.py, phong_methods.py,
mix_oracle.py): the command printed to stderr, render's stdout dropped, a failure raised as
subprocess.CalledProcessError."""
import json
import os
import subprocess
import sys


def render_report(binary, scene, args, tmp, name="r"):
    """Renders `scene` with `args` into tmp/NAME.png and tmp/NAME.json; returns the report and the command line
    (without the binary)."""
    report = os.path.join(tmp, name + ".json")
    cmd = [binary, "render", scene, "-o", os.path.join(tmp, name + ".png"), "--report", report, "-q"] + list(args)
    print("running:", " ".join(cmd), file=sys.stderr)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(report) as f:
        return json.load(f), " ".join(cmd[1:])
