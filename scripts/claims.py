#!/usr/bin/env python3
"""The claims table: reads the registry (bench/claims.json: every numeric claim of the source documents,
docs/bibliography.md, and the project's speed targets) and fills in the measured figure and the verdict
from result files in a results directory (the files scripts/bench-suite.sh writes). A claim whose result file or field is
missing is printed as "not measured" — nothing is typed in by hand.

Registry entry: {"id", "source", "statement", "source_figure", "measure", "rule", "note"?}
  measure: {"file": F, "bench": NAME, "field": K}   a Google Benchmark case (median when aggregated)
           {"file": F, "path": "rows[unit=counter,arith=fixed:12.12].modeled_speedup"}   any JSON value
           {"file": F, "regex": R}                   the first group of R in a text result, as a number
           {"ratio": [MEASURE, MEASURE]}             the first divided by the second
           {"difference": [MEASURE, MEASURE]}        the first minus the second
           null                                      not measured yet (the method is not built)
  rule:    {"op": ">=" | "<=" | "==" | "approx", "value": X (or "value_of": MEASURE), "rel": tolerance,
            "bound": "<=" | ">="   (approx only: the source's figure is a bound; a value on its wrong side that
                                    is within the tolerance is "holds only within the tolerance"),
            "requires": [{"measure": MEASURE, "op": OP, "value": X, "what": TEXT}, ...]}
           `requires` are conditions on the same run's correctness fields: a speed figure of a wrong image, or
           of a run over its error budget, "does not hold" whatever its value.

    scripts/claims.py --results bench-results -o bench-results/report/claims.md
    scripts/claims.py --results docs/bench-report/results -o docs/bench-report/claims.md --check   # ctest Claims.*
"""
import argparse
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_results import benchmark_rows, load_json  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


class NotMeasured(Exception):
    pass


def resolve_path(doc, path):
    """'a.b[k=v,k2=v2].c' or 'a[0]' in a JSON document."""
    value = doc
    for token in re.findall(r"[^.\[\]]+(?:\[[^\]]*\])?", path):
        m = re.fullmatch(r"([^\[]+)(?:\[([^\]]*)\])?", token)
        key, sel = m.group(1), m.group(2)
        if not isinstance(value, dict) or key not in value:
            raise NotMeasured(f"no '{key}' in the result")
        value = value[key]
        if sel is None:
            continue
        if sel.isdigit():
            value = value[int(sel)]
            continue
        want = dict(kv.split("=", 1) for kv in sel.split(","))
        match = [v for v in value if all(str(v.get(k)) == w for k, w in want.items())]
        if not match:
            raise NotMeasured(f"no entry {sel} in the result")
        value = match[0]
    return value


class Results:
    def __init__(self, directory, aggregate):
        self.directory = directory
        self.aggregate = aggregate
        self.cache = {}

    def doc(self, name):
        if name not in self.cache:
            path = os.path.join(self.directory, name)
            if not os.path.exists(path):
                raise NotMeasured(f"no result file {name}")
            self.cache[name] = load_json(path)
        return self.cache[name]

    def value(self, measure):
        if measure is None:
            raise NotMeasured("no method or command yet")
        if "ratio" in measure:
            a, b = (self.value(m) for m in measure["ratio"])
            return a / b
        if "difference" in measure:
            a, b = (self.value(m) for m in measure["difference"])
            return a - b
        if "regex" in measure:
            path = os.path.join(self.directory, measure["file"])
            if not os.path.exists(path):
                raise NotMeasured(f"no result file {measure['file']}")
            with open(path) as f:
                m = re.search(measure["regex"], f.read(), re.MULTILINE)
            if not m:
                raise NotMeasured(f"no match for the pattern in {measure['file']}")
            return float(m.group(1))
        doc = self.doc(measure["file"])
        if "bench" in measure:
            rows = {r["name"]: r for r in benchmark_rows(doc, self.aggregate)}
            if measure["bench"] not in rows:
                raise NotMeasured(f"no case {measure['bench']} in {measure['file']}")
            v = rows[measure["bench"]].get(measure["field"])
        else:
            v = resolve_path(doc, measure["path"])
        if v is None:
            raise NotMeasured("null in the result")
        return v


def fmt(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):  # counts: every digit
        return str(v)
    if isinstance(v, float):
        if v == 0 or not math.isfinite(v):
            return str(v)
        a = abs(v)
        return f"{v:.3g}" if 1e-3 <= a < 1e4 else f"{v:.2e}"
    return str(v)


def compare(value, op, target):
    if op == ">=":
        return value >= target
    if op == "<=":
        return value <= target
    if op == "==":
        return value == target
    raise SystemExit(f"claims: unknown rule op '{op}'")


def failed_requirement(rule, results):
    """The first of the rule's `requires` that the run fails, as text; None when it meets them all."""
    for req in rule.get("requires", []):
        value = results.value(req["measure"])
        if not compare(value, req["op"], req["value"]):
            return f"{req['what']}: {fmt(value)}, needs {req['op']} {fmt(req['value'])}"
    return None


def verdict(value, rule, results):
    op = rule["op"]
    target = results.value(rule["value_of"]) if "value_of" in rule else rule["value"]
    if op in (">=", "<=", "=="):
        ok = compare(value, op, target)
        by = f"{value / target:.2f}x the figure" if target and op != "==" else ""
    elif op == "approx":
        rel = rule.get("rel", 0.05)
        ok = abs(value - target) <= rel * abs(target)
        by = f"{(value - target) / target * 100:+.1f} % (tolerance {rel * 100:g} %)" if target else ""
    else:
        raise SystemExit(f"claims: unknown rule op '{op}'")
    failed = failed_requirement(rule, results)
    if failed:
        return "does not hold", (by + "; " if by else "") + "but " + failed, target
    if ok and op == "approx" and "bound" in rule and not compare(value, rule["bound"], target):
        return "holds only within the tolerance", f"{by}; past the figure, a bound ({rule['bound']})", target
    return ("holds" if ok else "does not hold"), by, target


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--registry", default=os.path.join(HERE, "..", "bench", "claims.json"))
    ap.add_argument("--results", required=True, help="directory with the result files")
    ap.add_argument("-o", "--output", required=True, help="Markdown file to write")
    ap.add_argument("--aggregate", default="median", choices=["median", "mean", "min"],
                    help="which statistic of repeated benchmark runs (min: the fastest repetition)")
    ap.add_argument("--check", action="store_true",
                    help="write nothing: exit 1 (with a diff) unless OUTPUT is byte for byte what would be written")
    args = ap.parse_args()
    registry = load_json(args.registry)
    results = Results(args.results, args.aggregate)
    lines = ["# Claims of the sources and the project's targets, measured", "",
             f"Generated by `scripts/claims.py --results {args.results}` from the registry "
             "`bench/claims.json`; every measured figure comes from a result file named in the last column; "
             f"benchmark times are the {args.aggregate} over repetitions. The source column cites docs/bibliography.md.", "",
             "| id | source | claim (source's statement) | source figure | measured | verdict | from |",
             "|---|---|---|---|---|---|---|"]
    counts = {}
    for c in registry["claims"]:
        try:
            value = results.value(c["measure"])
            v, by, target = verdict(value, c["rule"], results)
            if "value_of" in c["rule"]:  # the figure is itself measured: show it
                by = f"against {fmt(target)}; {by}"
            measured = fmt(value) + (f" ({by})" if by else "")
        except NotMeasured as e:
            v, measured = "not measured", str(e)
        except (ZeroDivisionError, TypeError) as e:
            v, measured = "not measured", f"unusable result ({e})"
        counts[v] = counts.get(v, 0) + 1
        src = c["measure"]
        parts = (src.get("ratio") or src.get("difference") or [src]) if src else []
        parts += [c["rule"]["value_of"]] if "value_of" in c["rule"] else []
        parts += [r["measure"] for r in c["rule"].get("requires", [])]
        files = sorted({m["file"] for m in parts if "file" in m})
        note = f" — {c['note']}" if c.get("note") else ""
        cells = [c["id"], c["source"], c["statement"] + note, c["source_figure"], measured, f"**{v}**",
                 ", ".join(files) or "-"]
        lines.append("| " + " | ".join(cell.replace("|", "\\|") for cell in cells) + " |")  # a '|' in a claim ends a cell
    lines += ["", "Totals: " + ", ".join(f"{k} {n}" for k, n in sorted(counts.items())), ""]
    text = "\n".join(lines)
    if args.check:
        with open(args.output, encoding="utf-8") as f:
            committed = f.read()
        if committed != text:
            import difflib
            sys.stdout.writelines(difflib.unified_diff(committed.splitlines(True), text.splitlines(True),
                                                       args.output, "regenerated"))
            print(f"\nclaims --check: {args.output} differs from what the registry and the results give")
            sys.exit(1)
        print(f"claims --check: {args.output} regenerates byte for byte")
        return
    tmp = args.output + ".tmp"
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, args.output)
    print(f"claims: {len(registry['claims'])} claims, " + ", ".join(f"{k} {n}" for k, n in sorted(counts.items())))


if __name__ == "__main__":
    main()
