#!/usr/bin/env python3
"""Every property of every schema in schemas/ says what it is: a non-empty `description`, and where the value
is a number (or an array of numbers), the unit it is in, one of UNITS (docs/reports.md, "Glossary"): a
reader should never have to guess a unit from a key's name.

    descriptions_test.py SCHEMAS_DIR
"""
import glob
import json
import os
import re
import sys

# Units a description may name; "count", "ratio", "factor" and "unitless" for pure numbers.
UNITS = ["ms", "s", "MiB", "bytes", "levels", "dB", "clocks", "pixels", "pixels per clock", "degrees", "world units",
         "count", "ratio", "fraction", "factor", "unitless", "linear 0..1", "%", "millions of pixels per second",
         "bits", "gates", "adders", "MHz"]
UNIT_RE = re.compile(r"(?<![A-Za-z])(" + "|".join(re.escape(u) for u in UNITS) + r")(?![A-Za-z])")


def numeric(prop):
    """True when the property holds a number or an array of numbers."""
    types = prop.get("type", [])
    types = types if isinstance(types, list) else [types]
    if "number" in types or "integer" in types:
        return True
    items = prop.get("items")
    return "array" in types and isinstance(items, dict) and numeric(items)


def walk(schema, path, found):
    """(path, property schema) of every property under `schema`, through $defs, items and the combinators."""
    if not isinstance(schema, dict):
        return
    for key, prop in schema.get("properties", {}).items():
        found.append((path + "/" + key, prop))
        walk(prop, path + "/" + key, found)
    for key in ("items", "additionalProperties", "if", "then", "else", "not"):
        walk(schema.get(key), path + ("[]" if key == "items" else ""), found)
    for key in ("oneOf", "anyOf", "allOf", "prefixItems"):
        for sub in schema.get(key, []):
            walk(sub, path, found)
    for name, sub in schema.get("$defs", {}).items():
        walk(sub, "#/$defs/" + name, found)


def problems(schema):
    found, out = [], []
    walk(schema, "", found)
    for path, prop in found:
        text = prop.get("description", "") if isinstance(prop, dict) else ""
        if not text.strip():
            out.append(path + ": no description")
        elif numeric(prop) and not UNIT_RE.search(text):
            out.append(path + ": a number whose description names no unit (%r)" % text)
    return out, len(found)


def main():
    folder = sys.argv[1]
    paths = sorted(glob.glob(os.path.join(folder, "*.schema.json")))
    if not paths:
        sys.exit("descriptions_test: no schemas in " + folder)
    # The check itself can fail: a property without a description, and a number without a unit, are named.
    bad, _ = problems({"properties": {"a": {"type": "integer"}, "b": {"type": "number", "description": "speed"}}})
    if len(bad) != 2:
        sys.exit("descriptions_test: the check does not catch a missing description or unit: %s" % bad)
    failures, total = [], 0
    for path in paths:
        with open(path) as f:
            out, n = problems(json.load(f))
        total += n
        failures += ["%s%s" % (os.path.basename(path), p) for p in out]
    for f in failures:
        print("FAIL: " + f)
    if failures:
        sys.exit("descriptions_test: %d of %d properties lack a description or unit" % (len(failures), total))
    print("descriptions_test: ok (%d properties in %d schemas)" % (total, len(paths)))


if __name__ == "__main__":
    main()
