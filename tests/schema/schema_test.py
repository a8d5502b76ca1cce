#!/usr/bin/env python3
"""The schema label (docs/reports.md): every report kind, written by the real binary on a small scene,
validates against its schema in schemas/; every scene in scenes/ validates against the scene schema;
and the schemas are strict enough to fail: a report without any one of its required keys, or a scene with
an unknown key, does not validate.

    schema_test.py PARASHADE SOURCE_DIR [MPIEXEC] [BENCH_DIR]

With BENCH_DIR (the build's bench/), the bench tools' files too: bench_host_noise, bench_kernel_ab and
bench_peer_pairs --json and a Google Benchmark program's --benchmark_out; and scripts/peak_memory.py's file
(with GNU time). The other scripts' kinds are checked on the committed results (results_test.py) and by
the Scripts.* tests that run those scripts.
"""
import copy
import glob
import json
import os
import subprocess
import sys
import tempfile

from schema_store import errors, load
from schema_store import validator as store_validator

PARASHADE, SOURCE = sys.argv[1], sys.argv[2]
MPIEXEC = sys.argv[3] if len(sys.argv) > 3 and sys.argv[3] else None
BENCH = sys.argv[4] if len(sys.argv) > 4 and sys.argv[4] else None
# Kinds the scripts write, checked elsewhere (see above).
SCRIPT_KINDS = {"combined-study", "phong-methods", "best-method", "mix-oracle", "distributed-model", "hw-synthesis", "hw-pnr",
                "stages", "planner-sweep"}
SCHEMAS = os.path.join(SOURCE, "schemas")
failures = []
skipped = set()  # kinds whose writer is not built here


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL: " + what, flush=True)


def validator(name):
    return store_validator(SCHEMAS, name)


def required_keys(v):
    """The report's top-level required keys: its own and the header's."""
    keys = list(v.schema.get("required", []))
    common = load(os.path.join(SCHEMAS, "common.schema.json"))
    return keys + common["$defs"]["header"]["required"]


def run(args, cmd_prefix=()):
    p = subprocess.run(list(cmd_prefix) + [PARASHADE] + args, capture_output=True, text=True, timeout=300)
    check(p.returncode == 0, "parashade %s: exit %d\n%s" % (" ".join(args), p.returncode, p.stderr[-2000:]))
    return p


def validate_tune_file(kind, path, breakers):
    """A file that is not a report (no header): it validates against schemas/KIND.schema.json, and each of
    `breakers` (what: doc -> broken copy) makes it fail."""
    doc, v = validated(kind, path, "file")
    if doc is None:
        return
    for key in v.schema.get("required", []):
        check(errors(v, {k: x for k, x in doc.items() if k != key}), "%s file without '%s' still validates" % (kind, key))
    for what, breaker in breakers.items():
        broken = breaker(copy.deepcopy(doc))
        check(errors(v, broken), "%s file with %s still validates" % (kind, what))


def validate_tune_files(cache_path, kt_path):
    """tune's own files: the tune cache and the Kernel Tuner export (--export-kt)."""
    def first(entries):
        return entries[0] if isinstance(entries, list) else next(iter(entries.values()))

    def invalid_but_timed(doc):  # a point not measured (or over budget) with a time Kernel Tuner would take
        e = next(e for e in doc["cache"].values() if e["status"] != "measured")
        e["time"] = 1.0
        return doc

    validate_tune_file("tune-cache", cache_path, {
        "an entry without its objective": lambda d: (first(d["entries"]).pop("objective"), d)[1],
        "a tile of 17 pixels": lambda d: (first(d["entries"])["params"].update(tile=17), d)[1],
        "a string for max_error": lambda d: (first(d["entries"]).update(max_error="1"), d)[1]})
    validate_tune_file("kernel-tuner-cache", kt_path, {
        "an entry without its status": lambda d: (first(d["cache"]).pop("status"), d)[1],
        "an invalid entry with a time": invalid_but_timed,
        "another objective": lambda d: dict(d, objective="energy")})


def validated(kind, path, what):
    """The file and its validator after checking it against schemas/KIND.schema.json; (None, None) if missing."""
    if not os.path.exists(path):
        check(False, "%s: no %s written at %s" % (kind, what, path))
        return None, None
    doc = load(path)
    v = validator(kind)
    errs = errors(v, doc)
    check(not errs, "%s %s does not validate: %s" % (kind, what, errs[:5]))
    return doc, v


def validate_report(kind, path):
    doc, v = validated(kind, path, "report")
    if doc is None:
        return
    check(doc.get("schema") == "parashade.%s/2" % kind, "%s report's schema is %r" % (kind, doc.get("schema")))
    # Strict enough to fail: without any one required key, or with the wrong kind, it must not validate.
    for key in required_keys(v):
        broken = copy.deepcopy(doc)
        broken.pop(key, None)
        check(errors(v, broken), "%s report without '%s' still validates" % (kind, key))
    other = dict(doc, schema="parashade.other/1")
    check(errors(v, other), "%s report naming another schema still validates" % kind)
    if "timing" in doc:
        broken = copy.deepcopy(doc)
        del broken["timing"]["stddev_ms"]
        check(errors(v, broken), "%s report whose timing lacks stddev_ms still validates" % kind)
    print("ok: %s (%d required keys each shown to be needed)" % (kind, len(required_keys(v))), flush=True)


def validate_file(kind, path):
    """A bench tool's or script's file: it validates, names its kind at the current version, and does not
    validate without any one of its required keys."""
    if not os.path.exists(path):
        check(False, "%s: no file written at %s" % (kind, path))
        return
    doc = load(path)
    v = validator(kind)
    check(not errors(v, doc), "%s file does not validate: %s" % (kind, errors(v, doc)[:5]))
    holder = doc["context"] if kind == "benchmark" else doc
    check(holder.get("schema") == "parashade.%s/2" % kind, "%s file's schema is %r" % (kind, holder.get("schema")))
    for key in v.schema.get("required", []):
        broken = copy.deepcopy(doc)
        broken.pop(key, None)
        check(errors(v, broken), "%s file without '%s' still validates" % (kind, key))
    print("ok: %s" % kind, flush=True)


def tool_files(scene, out):
    """The bench tools' and peak_memory.py's files, written for real on a small frame."""
    def tool(name, kind, args):
        exe = os.path.join(BENCH, name)
        if not os.path.exists(exe):
            print("skipped: %s (not built)" % name)
            skipped.add(kind)
            return False
        p = subprocess.run([exe] + args, capture_output=True, text=True, timeout=300)
        check(p.returncode == 0, "%s %s: exit %d\n%s" % (name, " ".join(args), p.returncode, p.stderr[-2000:]))
        return p.returncode == 0
    if tool("bench_host_noise", "host-noise", ["--seconds", "0.2", "--json", out("host-noise.json")]):
        validate_file("host-noise", out("host-noise.json"))
    if tool("bench_kernel_ab", "kernel-ab", [scene, "--size", "64x48", "--pairs", "2", "--b", "-D PREFETCH_AHEAD=2",
                                "--json", out("kernel-ab.json")]):
        validate_file("kernel-ab", out("kernel-ab.json"))
    if tool("bench_peer_pairs", "peer-pairs", ["--scenes", "sphere_8k", "--methods", "gouraud", "--size", "64x48", "--pairs", "2",
                                 "--json", out("peer-pairs.json")]):
        validate_file("peer-pairs", out("peer-pairs.json"))
    if tool("bench_host_stages", "benchmark", ["--benchmark_filter=^host/sphere_8k/gouraud/", "--benchmark_min_time=0.01",
                                  "--benchmark_out=" + out("benchmark.json"), "--benchmark_out_format=json"]):
        validate_file("benchmark", out("benchmark.json"))
    if os.path.exists("/usr/bin/time"):
        p = subprocess.run([sys.executable, os.path.abspath(os.path.join(SOURCE, "scripts", "peak_memory.py")),
                            "--binary", os.path.abspath(PARASHADE), "--scenes", "sphere_8k", "--methods", "gouraud",
                            "--size", "64x48", "-o", out("memory.json")],
                           capture_output=True, text=True, timeout=300, cwd=os.path.abspath(SOURCE))
        check(p.returncode == 0, "peak_memory.py: exit %d\n%s" % (p.returncode, p.stderr[-2000:]))
        validate_file("memory", out("memory.json"))
    else:
        print("skipped: memory (no GNU time at /usr/bin/time)")
        skipped.add("memory")


def flip_reports(scene, small, out):
    """Issue 47: render --flip and compare --flip --fail-percent write their figures as the schemas say; a FLIP
    mean above 1, an unknown max_at channel or an infinite PSNR does not validate."""
    run(["render", scene, *small, "--frames", "1", "--warmup", "0", "-q", "--no-tuned", "--flip", "-o", out("f.png"),
         "--report", out("render-flip.json")])
    doc = load(out("render-flip.json"))
    check(errors(validator("render"), doc) == [], "render --flip report does not validate")
    check("flip" in doc["error"]["implementation"], "render --flip: no error.implementation.flip")
    run(["compare", out("f.png"), out("r.png"), "--flip", "--fail", "1", "--fail-percent", "100", "--report",
         out("compare-flip.json")])
    doc = load(out("compare-flip.json"))
    v = validator("compare")
    check(errors(v, doc) == [], "compare --flip report does not validate: %s" % errors(v, doc))
    for path, bad in ((("error", "flip", "mean"), 1.5), (("max_at",), {"x": 0, "y": 0, "channel": "A"}),
                      (("error", "psnr_db"), "inf")):
        broken = json.loads(json.dumps(doc))
        target = broken
        for key in path[:-1]:
            target = target[key]
        target[path[-1]] = bad
        check(errors(v, broken) != [], "compare report with %s = %r still validates" % (".".join(path), bad))
    print("ok: render --flip, compare --flip --fail-percent", flush=True)


def main():
    with tempfile.TemporaryDirectory(prefix="parashade-schema-") as tmp:
        return run_all(tmp)


def run_all(tmp):
    scene = os.path.join(SOURCE, "scenes", "sphere.json")
    out = lambda name: os.path.join(tmp, name)  # noqa: E731
    small = ["--size", "64x48"]

    run(["render", scene, *small, "--frames", "2", "--warmup", "1", "-q", "--no-tuned", "-o", out("r.png"),
         "--report", out("render.json")])
    validate_report("render", out("render.json"))
    run(["render", scene, *small, "--frames", "2", "--warmup", "1", "-q", "--no-tuned", "-o", out("d.png"),
         "--against-device", "pthread", "--report", out("render-against-device.json")])
    validate_report("render", out("render-against-device.json"))
    run(["render", scene, *small, "--frames", "2", "--warmup", "1", "-q", "--device", "all", "-o", out("s.png"),
         "--report", out("render-split.json")])
    validate_report("render-split", out("render-split.json"))
    if MPIEXEC:
        run(["render", scene, *small, "--frames", "1", "--warmup", "0", "-q", "--no-tuned", "--distribute",
             "sort-last", "-o", out("d.png"), "--report", out("render-distributed.json")],
            [MPIEXEC, "--oversubscribe", "-np", "2"])
        validate_report("render-distributed", out("render-distributed.json"))
    else:
        print("skipped: render-distributed (built without MPI)")
    run(["plan", scene, *small, "--cu", "1,4", "--report", out("plan.json")])
    validate_report("plan", out("plan.json"))
    run(["scaling", scene, *small, "--units", "classic,counter", "--frames", "2", "-q", "--report", out("scaling.json")])
    validate_report("scaling", out("scaling.json"))
    run(["tune", scene, *small, "--budget-runs", "2", "--frames", "1", "-q", "--cache", out("tune-cache.json"),
         "--report", out("tune.json"), "--objective", "pareto", "--restrict", "tile*work_items<=4096",
         "--export-kt", out("kernel-tuner-cache.json")])
    validate_report("tune", out("tune.json"))
    validate_tune_files(out("tune-cache.json"), out("kernel-tuner-cache.json"))
    run(["unit-error", "--units", "counter", "--lengths", "1,4", "--trials", "20", "--report", out("unit-error.json")])
    validate_report("unit-error", out("unit-error.json"))
    run(["phong-study", "--report", out("phong-study.json")])
    validate_report("phong-study", out("phong-study.json"))
    run(["devices", "--report", out("devices.json")])
    validate_report("devices", out("devices.json"))
    run(["vectors", "--unit", "counter", "--spans", "2", "-o", out("v.txt"), "--report", out("vectors.json")])
    validate_report("vectors", out("vectors.json"))
    run(["combinations", "--report", out("combinations.json")])
    validate_report("combinations", out("combinations.json"))
    run(["compare", out("r.png"), out("r.png"), "--report", out("compare.json")])
    validate_report("compare", out("compare.json"))
    flip_reports(scene, small, out)
    if BENCH:
        tool_files(scene, out)

    # Every schema file is a report kind this test wrote (or the scene or common schema): none unchecked.
    kinds = {os.path.basename(p)[: -len(".schema.json")] for p in glob.glob(os.path.join(SCHEMAS, "*.schema.json"))}
    written = {os.path.basename(p)[:-5] for p in glob.glob(os.path.join(tmp, "*.json"))}
    unchecked = (kinds - written - {"scene", "common"} - SCRIPT_KINDS - (set() if MPIEXEC else {"render-distributed"})
                 - (set() if BENCH else {"host-noise", "kernel-ab", "peer-pairs", "benchmark", "memory"}) - skipped)
    check(not unchecked, "schemas without a report in this test: %s" % sorted(unchecked))

    # Scenes: every committed scene validates; an unknown key, a missing "objects", a light without its
    # direction and a perspective camera with an orthographic height do not.
    sv = validator("scene")
    scenes = sorted(glob.glob(os.path.join(SOURCE, "scenes", "**", "*.json"), recursive=True))
    check(len(scenes) >= 5, "only %d scenes found" % len(scenes))
    for path in scenes:
        errs = errors(sv, load(path))
        check(not errs, "%s does not validate against scene.schema.json: %s" % (path, errs[:3]))
    base = load(scene)
    bad = {"unknown key": dict(base, colour=[1, 1, 1]),
           "no objects": {k: v for k, v in base.items() if k != "objects"},
           "light without direction": dict(base, lights=[{"type": "directional"}]),
           "perspective camera with height": dict(base, camera=dict(base["camera"], height=2)),
           "shape with an unknown parameter": dict(base, objects=[{"shape": {"type": "sphere", "radius": 2}}]),
           "object with shape and mesh": dict(base, objects=[{"shape": "sphere", "mesh": "a.obj"}]),
           "resolution beyond the 12-bit limit": dict(base, resolution=[8192, 64])}
    for what, doc in bad.items():
        check(errors(sv, doc), "scene with %s still validates" % what)
    print("ok: %d scenes, %d broken ones refused" % (len(scenes), len(bad)))

    if failures:
        print("schema_test: %d failure(s)" % len(failures))
        return 1
    print("schema_test: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
