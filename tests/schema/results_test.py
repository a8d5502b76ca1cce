#!/usr/bin/env python3
"""The committed result files (docs/bench-report/results, docs/*.json) say what they are and are what they say
(docs/reports.md, "Committed results"): each carries a "schema" of the current format (a Google Benchmark file in
its context), validates against schemas/<kind>.schema.json (a distributed model's runs against the
render-distributed schema too), and names its build by a bare hash, never "<hash>-dirty" (a dirty build says
"dirty": true). The check is shown to fail on a file without a schema, of an old version, or with a dirty hash.

    results_test.py SOURCE_DIR
"""
import copy
import glob
import os
import re
import sys

from schema_store import errors, load, validator

SOURCE = sys.argv[1]
SCHEMAS = os.path.join(SOURCE, "schemas")
VERSION = 2
DIRTY = re.compile(r"^[0-9a-f]{7,40}-dirty$")
validators = {}


def stated(doc):
    """The schema field: top-level, or in a Google Benchmark file's context."""
    if isinstance(doc, dict) and isinstance(doc.get("context"), dict) and "benchmarks" in doc:
        return doc["context"].get("schema")
    return doc.get("schema") if isinstance(doc, dict) else None


def dirty_hashes(value, path=""):
    """Paths of strings that look like a dirty build's hash."""
    if isinstance(value, dict):
        return [p for k, v in value.items() for p in dirty_hashes(v, path + "/" + k)]
    if isinstance(value, list):
        return [p for i, v in enumerate(value) for p in dirty_hashes(v, "%s/%d" % (path, i))]
    return [path] if isinstance(value, str) and DIRTY.match(value) else []


def problems(doc):
    schema = stated(doc)
    m = re.match(r"^parashade\.([a-z-]+)/([0-9]+)$", str(schema))
    if not m:
        return ["no schema (or not parashade.<kind>/<n>): %r" % schema]
    kind, version = m.group(1), int(m.group(2))
    if version != VERSION:
        return ["format %d, not %d (scripts/migrate_reports.py)" % (version, VERSION)]
    if not os.path.exists(os.path.join(SCHEMAS, kind + ".schema.json")):
        return ["no schemas/%s.schema.json" % kind]
    if kind not in validators:
        validators[kind] = validator(SCHEMAS, kind)
    out = ["does not validate: " + e for e in errors(validators[kind], doc)[:5]]
    if kind == "distributed-model":
        validators.setdefault("render-distributed", validator(SCHEMAS, "render-distributed"))
        for name, run in doc.get("runs", {}).items():
            out += ["runs/%s does not validate: %s" % (name, e) for e in errors(validators["render-distributed"], run)[:3]]
    out += ["a dirty build's hash at " + p for p in dirty_hashes(doc)]
    return out


def main():
    paths = sorted(glob.glob(os.path.join(SOURCE, "docs", "bench-report", "results", "**", "*.json"), recursive=True)
                   + glob.glob(os.path.join(SOURCE, "docs", "*.json")))
    failures = []
    if len(paths) < 10:
        failures.append("only %d committed result files found under %s/docs" % (len(paths), SOURCE))
    kinds = set()
    for path in paths:
        doc = load(path)
        for p in problems(doc):
            failures.append("%s: %s" % (os.path.relpath(path, SOURCE), p))
        kinds.add(str(stated(doc)))
    # The check can fail: a memory file without its schema, at format 1, or naming a dirty build.
    sample = load(os.path.join(SOURCE, "docs", "bench-report", "results", "memory.json"))
    for what, broken in (("without a schema", {k: v for k, v in sample.items() if k != "schema"}),
                         ("at format 1", dict(sample, schema="parashade.memory/1")),
                         ("with a dirty hash", dict(copy.deepcopy(sample), parashade={"git_hash": "2a21195f6b06-dirty"}))):
        if not problems(broken):
            failures.append("a result file %s passes" % what)
    for f in failures:
        print("FAIL: " + f)
    if failures:
        sys.exit("results_test: %d failure(s)" % len(failures))
    print("results_test: ok (%d files; %s)" % (len(paths), ", ".join(sorted(kinds))))


if __name__ == "__main__":
    main()
