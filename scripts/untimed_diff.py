#!/usr/bin/env python3
"""Compares two bench-suite result directories on what does not depend on time: every JSON value whose key
is not a timing, load, date, memory or identity field (errors, modeled clocks, counts, synthesis figures),
and the text tables, file by file. For checking that a sharded run (`mpirun -np N scripts/bench-suite.sh`)
measured the same things as an unsharded one (docs/distributed.md, "Sharded sweeps").

    scripts/untimed_diff.py UNSHARDED_DIR SHARDED_DIR [--ignore-files NAME,...]

Prints, per file, how many values were compared and which differ; exits 1 if any differs or a file is
missing from either side.
"""
import argparse
import json
import os
import re
import sys

# Keys whose values depend on the run (time, speed, load, memory, who and when), by name.
TIMED = re.compile(r"(_ms|_s|_ns|ms$|time|per_s|fps|speed|ratio|load|created|command|git_hash|dirty|version|samples|"
                   r"iterations|repetition|rss|peak|mib|date|host|seconds|stddev|mean|median|min$|max$|cv$|"
                   r"frame_ratio|kernel_ratio|objective|threads|run_name|family_index|instance|aggregate|"
                   r"cpu|mhz|caches|executable|library|num_|best|variant|study|frames|warmup|pixel_per|"
                   r"triangle_per|mtriangle|mpixel)", re.I)


def leaves(value, path=""):
    if isinstance(value, dict):
        for k, v in value.items():
            if k == "benchmarks" and isinstance(v, dict):  # keyed by case name (benchmarks_by_name)
                for name, run in v.items():
                    yield from leaves(run, path + "/" + name)
                continue
            if TIMED.search(k):
                continue
            yield from leaves(v, path + "/" + k)
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from leaves(v, "%s[%d]" % (path, i))
    else:
        yield path, value


def benchmarks_by_name(doc):
    """Google Benchmark files: the runs keyed by name (the order is the random interleaving's)."""
    if isinstance(doc, dict) and "benchmarks" in doc:
        doc = dict(doc)  # the medians only: the other aggregates (stddev, cv ...) of untimed counters are 0 or nan
        doc["benchmarks"] = {b["name"]: b for b in doc["benchmarks"] if b.get("aggregate_name", "median") == "median"}
    return doc


def equal(x, y):
    return x == y or (isinstance(x, float) and isinstance(y, float) and x != x and y != y)  # nan is nan


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--ignore-files", default="", help="comma-separated file names to leave out")
    args = ap.parse_args()
    ignore = set(filter(None, args.ignore_files.split(",")))
    names = sorted(n for n in set(os.listdir(args.a)) | set(os.listdir(args.b))
                   if n.endswith((".json", ".txt", ".md")) and n not in ignore)
    bad = 0
    for name in names:
        pa, pb = os.path.join(args.a, name), os.path.join(args.b, name)
        if not (os.path.isfile(pa) and os.path.isfile(pb)):
            print("%s: only in %s" % (name, args.a if os.path.isfile(pa) else args.b))
            bad += 1
            continue
        if not name.endswith(".json"):
            same = open(pa).read() == open(pb).read()
            print("%s: text %s" % (name, "identical" if same else "DIFFERS"))
            bad += not same
            continue
        la = dict(leaves(benchmarks_by_name(json.load(open(pa)))))
        lb = dict(leaves(benchmarks_by_name(json.load(open(pb)))))
        differ = [k for k in sorted(set(la) | set(lb)) if not equal(la.get(k), lb.get(k))]
        print("%s: %d values compared, %d differ" % (name, len(set(la) | set(lb)), len(differ)))
        for k in differ[:10]:
            print("  %s: %r vs %r" % (k, la.get(k), lb.get(k)))
        bad += bool(differ)
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
