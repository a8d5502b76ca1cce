"""Reading result files for report.py and claims.py: bench_llvmpipe / bench_frame JSON (Google Benchmark),
`parashade scaling --report` JSON, scripts/peak_memory.py JSON, bench_peer_pairs JSON, and the method variants of
scripts/combined_study.py (combined-study.json) and scripts/phong_methods.py (phong-methods.json), told
apart by their "schema" field (docs/reports.md). Each Google Benchmark case becomes one
row: {"peer", "scene", "size", "method", "name", counters...}, the median aggregate when the run had
repetitions, else the single run."""
import json
import os

from report_schema import VERSION


def load_json(path):
    with open(path) as f:
        return json.load(f)


# Result files this module reads, by their "schema" field (docs/reports.md; a Google Benchmark file's is in its
# context): the kind before the "/" and the versions it understands. Files of format 1 or without a schema:
# scripts/migrate_reports.py rewrites them.
SCHEMAS = {"parashade.benchmark": ("benchmark", {VERSION}), "parashade.scaling": ("scaling", {VERSION}),
           "parashade.memory": ("memory", {VERSION}), "parashade.peer-pairs": ("peer_pairs", {VERSION}),
           "parashade.combined-study": ("combined_study", {VERSION}),
           "parashade.phong-methods": ("phong_methods", {VERSION})}


def kind(doc):
    """A kind from SCHEMAS ("benchmark": Google Benchmark's own format), or "unknown" (another file, or
    another parashade kind). A known kind at a version this script does not read is an error, not a guess."""
    if not isinstance(doc, dict):
        return "unknown"
    schema = doc.get("schema")
    if "benchmarks" in doc and isinstance(doc.get("context"), dict):
        schema = doc["context"].get("schema")
    name, _, version = str(schema).partition("/")
    if name not in SCHEMAS:
        if schema is None and ("benchmarks" in doc or "rows" in doc or "measurements" in doc):
            raise ValueError("a result file without a schema (format 1 or older): "
                             "scripts/migrate_reports.py rewrites it")
        return "unknown"
    k, versions = SCHEMAS[name]
    if not version.isdigit() or int(version) not in versions:
        raise ValueError(f"result schema {schema}: this script reads {name}/" +
                         ",".join(str(v) for v in sorted(versions)) + " (scripts/migrate_reports.py rewrites older files)")
    return k


# The study scenes under their benchmark names: scenes/sphere.json is bench_llvmpipe's sphere_8k.
STUDY_SCENE_NAMES = {"sphere": "sphere_8k"}


def variant_rows(doc, k):
    """Whole-frame time and NMSE against exact Phong of each method variant of a study file, as rows
    {"scene", "size", "family", "label", "frame_ms", "phong_ms", "nmse"}: family "combined"
    (combined-study.json: combined:K, combined:auto@budget, triangle choices) or "phong variants"
    (phong-methods.json: the normalization and specular models; the exact/exact row is plain Phong, left
    out). phong_ms: plain Phong's frame in the same run, so a plot can use the ratio."""
    out = []
    if k == "combined_study":
        phong = {m["scene"]: m["frame_ms"] for m in doc["measurements"] if m["method"] == "phong"}
        for m in doc["measurements"]:
            if not m["method"].startswith("combined"):
                continue
            out.append({"scene": STUDY_SCENE_NAMES.get(m["scene"], m["scene"]),
                        "size": f"{m['width']}x{m['height']}", "family": "combined", "label": m["method"],
                        "frame_ms": m["frame_ms"], "phong_ms": phong.get(m["scene"]),
                        "nmse": m["error_vs_exact_phong"]["nmse"]})
    elif k == "phong_methods":
        phong = {r["scene"]: r["frame_ms"] for r in doc["rows"] if r["normalize"] == "exact" and r["specular"] == "exact"}
        for r in doc["rows"]:
            if r["normalize"] == "exact" and r["specular"] == "exact":
                continue
            # Spelled as render's options, as the combined points are.
            label = " ".join(f"--{option} {r[option]}" for option in ("normalize", "specular") if r[option] != "exact")
            out.append({"scene": STUDY_SCENE_NAMES.get(r["scene"], r["scene"]), "size": r["size"],
                        "family": "phong variants", "label": label, "frame_ms": r["frame_ms"],
                        "phong_ms": phong.get(r["scene"]), "nmse": r["nmse"]})
    return out


def benchmark_rows(doc, aggregate="median"):
    """Rows of a Google Benchmark JSON; the given aggregate ("median", "mean" or, for bench_llvmpipe,
    "min") when the run has repetitions; the median where that aggregate is missing."""
    rows = {}
    for b in doc["benchmarks"]:
        if b.get("error_occurred"):
            continue
        aggregated = b.get("run_type") == "aggregate"
        if aggregated and b.get("aggregate_name") not in (aggregate, "median"):
            continue
        name = b.get("run_name", b["name"])
        if name.endswith("/manual_time"):
            name = name[: -len("/manual_time")]
        if name in rows and (not aggregated or b.get("aggregate_name") != aggregate):
            continue  # repetitions without aggregates: keep the first; the wanted aggregate beats the median
        parts = name.split("/")
        row = dict(b)
        row["name"] = name
        row["peer"] = parts[0]
        row["scene"] = parts[1] if len(parts) > 1 else ""
        row["size"] = parts[2] if len(parts) > 2 else (parts[1] if parts[0] in ("fill_limit", "plane_fill_limit", "phong_plane_fill_limit") else "")
        row["method"] = parts[3] if len(parts) > 3 else ""
        rows[name] = row
    return list(rows.values())


def load_results(paths, aggregate="median"):
    """{"benchmark": [rows], "contexts": [context], "scaling": [docs], "memory": [rows], "peer_pairs": [docs]} from files or
    directories (every *.json in a directory)."""
    files = []
    for p in paths:
        if os.path.isdir(p):
            files += sorted(os.path.join(p, f) for f in os.listdir(p) if f.endswith(".json"))
        else:
            files.append(p)
    out = {"benchmark": [], "contexts": [], "scaling": [], "memory": [], "variants": [], "peer_pairs": [],
           "files": files}
    for path in files:
        try:
            doc = load_json(path)
        except (OSError, ValueError):
            continue
        k = kind(doc)
        if k == "benchmark":
            out["benchmark"] += benchmark_rows(doc, aggregate)
            out["contexts"].append(doc["context"])
        elif k == "scaling":
            doc["_file"] = path
            out["scaling"].append(doc)
        elif k == "memory":
            out["memory"] += doc["rows"]
            out["memory_baseline"] = doc.get("baseline_mib")
        elif k == "peer_pairs":
            out["peer_pairs"].append(doc)
        elif k in ("combined_study", "phong_methods"):
            out["variants"] += variant_rows(doc, k)
    return out


def find(rows, **want):
    for r in rows:
        if all(r.get(k) == v for k, v in want.items()):
            return r
    return None
