#!/usr/bin/env python3
"""Rewrites JSON result files of report format 1 (or of no stated format) as format 2, in place (docs/reports.md,
"Versions"; CHANGELOG lists the renames): one name per quantity, a "schema" in every file, and a build hash
without "-dirty" (the build's "dirty": true instead). Figures are never recomputed: a key that only repeated
another one (frame_ms_samples beside timing.samples_ms) goes, a renamed key keeps its value. Each rewritten
file records what it was in "migrated_from" (the Google Benchmark files in their context). A file already at
format 2 is left as it is; a file of a kind this script does not know is an error.

    scripts/migrate_reports.py FILE... [--check]   (--check: change nothing, exit 1 if a file needs migrating)
"""
import argparse
import json
import os
import sys

from report_schema import VERSION, schema

# Old key -> new key (None: dropped, the value is elsewhere in the report) at each place a kind has it.
RENDER = {"tile_size": "tile", "max_error_levels": "max_error"}
DISTRIBUTED = {"tile_size": "tile", "frame_ms_samples": None, "max_error_levels": "max_error"}
PER_RANK = {"peak_rss_mb": "peak_rss_mib"}
PLAN = {"tile_size": "tile"}
SCALING_ROW = {"frame_ms_samples": None, "frame_ms_min": None}
TUNE_CANDIDATE = {"max_error": "max_abs", "frame_ms_samples": None}
COMBINED_MEASUREMENT = {"speedup_vs_phong_frame": "frame_ratio", "speedup_vs_phong_kernel": "kernel_ratio",
                        "ceiling_vs_phong_frame": "ceiling_frame_ratio"}
COMBINED_CLAIM = {"max_levels_vs_phong": "max_abs_vs_phong"}
PHONG_METHODS_ROW = {"max_levels": "max_abs"}
BENCHMARK_CASE = {"tile_size": "tile"}


def rename(obj, names):
    """Renames (or drops) obj's keys per `names`, in place, keeping the key order."""
    if not isinstance(obj, dict):
        return
    items = list(obj.items())
    obj.clear()
    for key, value in items:
        new = names.get(key, key)
        if new is not None:
            obj[new] = value


def legacy_kind(doc):
    """The kind of a file written before files carried a "schema", by the keys only that kind has."""
    if isinstance(doc, list):
        return "mix-oracle"
    rows = doc.get("rows") if isinstance(doc.get("rows"), list) else []
    first = rows[0] if rows and isinstance(rows[0], dict) else {}
    rules = [("benchmark", "benchmarks" in doc and "context" in doc),
             ("combined-study", "measurements" in doc and "claims" in doc),
             ("phong-methods", "normalize" in first and "specular" in first),
             ("best-method", "best" in doc and "candidates" in doc),
             ("stages", "before" in doc and "after" in doc and "rows" in doc),
             ("host-noise", "per_cpu" in doc),
             ("distributed-model", "alpha_beta" in doc),
             ("hw-synthesis", "gates" in first),
             ("planner-sweep", "runs" in doc and "mismatches" in doc),
             ("memory", "rows" in doc and "command" in doc),
             ("scaling", "rows" in doc and "speedup_note" in doc),
             ("peer-pairs", "cases" in doc and "gl_renderer" in doc),
             ("kernel-ab", "a_options" in doc)]
    for kind, matches in rules:
        if matches:
            return kind
    raise ValueError("a file of no kind this script knows (no \"schema\", and not the keys of any kind)")


def stated(doc):
    """(kind, version) from the file's schema field, or (None, None) where it has none."""
    value = doc.get("schema") if isinstance(doc, dict) else None
    if isinstance(doc, dict) and "context" in doc and "benchmarks" in doc:
        value = doc["context"].get("schema")
    if value is None:
        return None, None
    name, _, version = str(value).partition("/")
    if not name.startswith("parashade.") or not version.isdigit():
        raise ValueError("schema %r is not parashade.<kind>/<n>" % value)
    return name[len("parashade."):], int(version)


def build(doc):
    """The header's build: "-dirty" off the hash, said by "dirty" instead."""
    b = doc.get("parashade")
    if not isinstance(b, dict) or "git_hash" not in b:
        return
    hash_ = str(b["git_hash"])
    b["dirty"] = b.get("dirty", False) or hash_.endswith("-dirty")
    if hash_.endswith("-dirty"):
        b["git_hash"] = hash_[: -len("-dirty")]


def report_body(doc, kind):
    """The renames inside one parashade command's report (render, plan, scaling, tune, ...)."""
    build(doc)
    rename(doc, DISTRIBUTED if kind == "render-distributed" else RENDER)
    if isinstance(doc.get("plan"), dict):
        rename(doc["plan"], PLAN)
    for plan in doc.get("plans", []) if kind == "plan" else []:
        rename(plan, PLAN)
    for rank in doc.get("per_rank", []) if kind == "render-distributed" else []:
        rename(rank, PER_RANK)
    for row in doc.get("rows", []) if kind == "scaling" else []:
        rename(row, SCALING_ROW)
        if isinstance(row.get("plan"), dict):
            rename(row["plan"], PLAN)
    if kind == "tune":
        for c in doc.get("candidates", []) + ([doc["best"]] if isinstance(doc.get("best"), dict) else []):
            rename(c, TUNE_CANDIDATE)


def migrate(doc):
    """(the format-2 document, whether it changed)."""
    kind, version = stated(doc)
    if version == VERSION:
        return doc, False
    if version is not None and version > VERSION:
        raise ValueError("format %d is newer than this script's %d" % (version, VERSION))
    was = "parashade.%s/%d" % (kind, version) if kind else "none"
    kind = kind or legacy_kind(doc)
    if kind == "mix-oracle":
        return {"schema": schema(kind), "migrated_from": was, "rows": doc}, True
    if kind == "benchmark":
        for case in doc["benchmarks"]:
            rename(case, BENCHMARK_CASE)
        doc["context"].update(schema=schema(kind), migrated_from=was)
        return doc, True
    if kind == "combined-study":
        for m in doc.get("measurements", []):
            rename(m, COMBINED_MEASUREMENT)
        for c in doc.get("claims", []):
            rename(c, COMBINED_CLAIM)
    elif kind == "phong-methods":
        for r in doc.get("rows", []):
            rename(r, PHONG_METHODS_ROW)
    elif kind == "distributed-model":
        for run in doc.get("runs", {}).values():
            run.update(migrate(run)[0])
    elif kind not in ("memory", "peer-pairs", "kernel-ab", "host-noise", "best-method", "stages", "hw-synthesis",
                      "planner-sweep"):
        report_body(doc, kind)
    out = {"schema": schema(kind), "migrated_from": was}
    out.update((k, v) for k, v in doc.items() if k not in out)
    return out, True


def formatted(text, doc):
    """doc as the scripts write it, with the indent the file had."""
    indent = 1 if text.startswith("{\n \"") or text.startswith("[\n {") else 2
    return json.dumps(doc, indent=indent, ensure_ascii=False) + "\n"


def benchmark_text(text, doc):
    """A Google Benchmark file edited as text, so that its own number format stays: the context's schema lines
    and the renamed counters; checked to parse to the migrated document."""
    context = doc["context"]
    lines = "".join('    "%s": %s,\n' % (k, json.dumps(context[k])) for k in ("schema", "migrated_from"))
    out = text.replace('"context": {\n', '"context": {\n' + lines, 1)
    for old, new in BENCHMARK_CASE.items():
        out = out.replace('"%s":' % old, '"%s":' % new)
    if json.loads(out) != doc:
        raise ValueError("the text edit of a Google Benchmark file does not give the migrated document")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="+")
    ap.add_argument("--check", action="store_true", help="change nothing; exit 1 naming each file not at format 2")
    args = ap.parse_args()
    stale = []
    for path in args.files:
        with open(path) as f:
            text = f.read()
        try:
            doc, changed = migrate(json.loads(text))
        except (ValueError, KeyError, TypeError) as e:
            sys.exit("migrate_reports: %s: %s" % (path, e))
        if not changed:
            continue
        stale.append(path)
        if args.check:
            continue
        tmp = path + ".tmp"
        with open(tmp, "w") as f:
            f.write(benchmark_text(text, doc) if "benchmarks" in doc else formatted(text, doc))
        os.replace(tmp, path)
        print("migrate_reports: %s -> %s" % (path, doc.get("schema") or doc["context"]["schema"]))
    if args.check and stale:
        sys.exit("migrate_reports: not at format %d: %s" % (VERSION, " ".join(stale)))


if __name__ == "__main__":
    main()
