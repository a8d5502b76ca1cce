#!/usr/bin/env python3
"""A partial `parashade tune` replayed by the real Kernel Tuner (docs/tuning.md, "Kernel Tuner export").

    kernel_tuner_roundtrip_test.py SOURCE_DIR PARASHADE_BINARY WORK_DIR

Runs a small tune of the teapot (64x48, 8 points, a budget of 5, Gouraud over a 2-level error budget, one
point excluded by --restrict) with --export-kt and --export-t4, then, in a venv made in WORK_DIR/kt-venv
(system site packages; pip installs kernel_tuner 1.5.0 into it, reused by later runs):

- kernel_tuner.tune_kernel(..., simulation_mode=True, cache=EXPORT) replays the export, once over the whole
  product of its tune_params and once with the export's restrictions; each time Kernel Tuner's best
  (its util.get_best_config) must be parashade's best, and the configurations it takes as valid must be
  exactly the candidates parashade may pick (measured, same image, within the budget): an over-budget,
  unmeasured or restricted point must come back as an error;
- the T4 file must validate against the T4 results schema Kernel Tuner ships (kernel_tuner/schema/T4).

Exits 77 (ctest: skipped) with a message when pip cannot install kernel_tuner (no registry reachable).
"""
import json
import os
import subprocess
import sys
import tempfile

from pip_venv import venv_with

KERNEL_TUNER = "kernel_tuner==1.5.0"


def make_venv(work):
    return venv_with(work, "kt-venv", ["kernel_tuner", "jsonschema"], [KERNEL_TUNER])


# Runs inside the venv: replays the export and prints one JSON line of what Kernel Tuner chose.
CHILD = r'''
import json, sys, warnings
from collections import OrderedDict
from pathlib import Path
import jsonschema, kernel_tuner
from kernel_tuner import util

kt_path, t4_path = sys.argv[1], sys.argv[2]
k = json.load(open(kt_path))
tune_params = OrderedDict((n, k["tune_params"][n]) for n in k["tune_params_keys"])
out = {}
for name, restrictions in (("whole", None), ("restricted", k["restrictions"])):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        results, env = kernel_tuner.tune_kernel(k["kernel_name"], "__kernel void dummy() {}", k["problem_size"], [],
                                                tune_params, cache=kt_path, simulation_mode=True,
                                                strategy="brute_force", lang="OpenCL", restrictions=restrictions,
                                                quiet=True)
    best = util.get_best_config(results, "time")
    out[name] = {"evaluated": len(results),
                 "best": {n: best[n] for n in k["tune_params_keys"]} if "__error__" not in best else None,
                 "valid": sorted(",".join(str(r[n]) for n in k["tune_params_keys"])
                                 for r in results if "__error__" not in r)}
schema = json.load(open(Path(kernel_tuner.__file__).parent / "schema" / "T4" / "1.0.0" / "results-schema.json"))
try:
    jsonschema.validate(json.load(open(t4_path)), schema)
    out["t4"] = "valid"
except jsonschema.ValidationError as e:
    out["t4"] = "invalid: %s at %s" % (e.message, list(e.absolute_path))
out["version"] = kernel_tuner.__version__ if hasattr(kernel_tuner, "__version__") else "?"
print(json.dumps(out))
'''


def tune(binary, source, out):
    files = {k: os.path.join(out, k) for k in ("kt.json", "t4.json", "report.json", "cache.json")}
    cmd = [binary, "tune", os.path.join(source, "scenes", "teapot.json"), "--size", "64x48",
           "--param", "tile=16,32", "--param", "work_items=0,8", "--param", "partition=none",
           "--param", "method=gouraud,phong", "--max-error", "2", "--restrict", "tile*work_items<=128",
           "--budget-runs", "5", "--frames", "1", "-q", "--cache", files["cache.json"], "--report",
           files["report.json"], "--export-kt", files["kt.json"], "--export-t4", files["t4.json"]]
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        raise SystemExit("FAIL: parashade tune exited %d:\n%s%s" % (run.returncode, run.stdout, run.stderr))
    return files


def key(params, names):
    return ",".join(str(params[n]) for n in names)


def check(report, kt, chosen):
    """The failures: Kernel Tuner's choice against parashade's report (each from its own side)."""
    names = kt["tune_params_keys"]
    failures = []
    eligible = sorted(key(c["params"], names) for c in report["candidates"] if c["verified"] and c["within_budget"])
    over = [c for c in report["candidates"] if not c["within_budget"]]
    if not over:
        failures.append("no candidate is over the error budget: the test would not see one picked")
    if report["points"]["restricted"] != 2:
        failures.append("--restrict excluded %s points, not the 2 of tile 32 with 8 work-items" % report["points"]["restricted"])
    measured = len(report["candidates"])
    if measured >= report["points"]["valid"]:
        failures.append("the run measured its whole space (%d points): not a partial run" % measured)
    best = {n: report["best"]["params"][n] for n in names}
    for run in ("whole", "restricted"):
        got = chosen[run]
        if got["best"] != best:
            failures.append("%s: Kernel Tuner's best %s, parashade's %s" % (run, got["best"], best))
        if got["valid"] != eligible:
            failures.append("%s: Kernel Tuner's valid configurations %s, parashade's eligible %s" % (run, got["valid"], eligible))
    if chosen["whole"]["evaluated"] != len(kt["cache"]):
        failures.append("the whole replay evaluated %d configurations of %d" % (chosen["whole"]["evaluated"], len(kt["cache"])))
    if chosen["t4"] != "valid":
        failures.append("T4 file: " + chosen["t4"])
    return failures


def main():
    source, binary, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    python = make_venv(work)
    with tempfile.TemporaryDirectory() as out:
        files = tune(binary, source, out)
        run = subprocess.run([python, "-c", CHILD, files["kt.json"], files["t4.json"]], capture_output=True, text=True)
        if run.returncode != 0:
            print("FAIL: Kernel Tuner could not replay the export:\n" + run.stdout[-3000:] + run.stderr[-3000:])
            return 1
        chosen = json.loads(run.stdout.strip().splitlines()[-1])
        report = json.load(open(files["report.json"]))
        kt = json.load(open(files["kt.json"]))
    failures = check(report, kt, chosen)
    print("kernel_tuner %s replayed %d configurations (%d measured by parashade, %d eligible); best %s" %
          (chosen["version"], chosen["whole"]["evaluated"], len(report["candidates"]),
           len(chosen["whole"]["valid"]), chosen["whole"]["best"]))
    for f in failures:
        print("FAIL " + f)
    print("kernel tuner round trip: %s" % ("ok" if not failures else "%d failed" % len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
