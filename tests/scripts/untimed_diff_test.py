#!/usr/bin/env python3
"""scripts/untimed_diff.py on two small result directories built here: equal untimed values with different
times pass; a changed error figure, a changed text table or a missing file fails and is named.

    untimed_diff_test.py SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

from checks import check, finish

SCRIPT = os.path.join(sys.argv[1], "scripts", "untimed_diff.py")


def write(d, files):
    os.makedirs(d, exist_ok=True)
    for name, content in files.items():
        with open(os.path.join(d, name), "w") as f:
            f.write(content if isinstance(content, str) else json.dumps(content))


def run(a, b):
    p = subprocess.run([sys.executable, SCRIPT, a, b], capture_output=True, text=True)
    return p.returncode, p.stdout


def result(frame_ms, nmse, clocks):
    return {"schema": "parashade.scaling/1", "created_utc": "2026-12-03T0%d:00:00Z" % int(frame_ms),
            "rows": [{"unit": "counter", "frame_ms": frame_ms, "nmse": nmse, "modeled_clocks": clocks}],
            "benchmarks": [{"name": "parashade/teapot/64x64/gouraud/manual_time_median", "aggregate_name": "median",
                            "real_time": frame_ms, "nmse": nmse}]}


with tempfile.TemporaryDirectory() as tmp:
    a, b = os.path.join(tmp, "a"), os.path.join(tmp, "b")
    write(a, {"s.json": result(1.0, 1e-4, 100), "t.txt": "table\n"})
    write(b, {"s.json": result(7.0, 1e-4, 100), "t.txt": "table\n"})
    rc, out = run(a, b)
    check(rc == 0, "only times differ: exit %d\n%s" % (rc, out))
    write(b, {"s.json": result(7.0, 2e-4, 100)})
    rc, out = run(a, b)
    check(rc == 1 and "nmse" in out, "a changed nmse: exit %d\n%s" % (rc, out))
    write(b, {"s.json": result(7.0, 1e-4, 101)})
    rc, out = run(a, b)
    check(rc == 1 and "modeled_clocks" in out, "changed modeled clocks: exit %d\n%s" % (rc, out))
    write(b, {"s.json": result(7.0, 1e-4, 100), "t.txt": "other\n"})
    rc, out = run(a, b)
    check(rc == 1 and "t.txt: text DIFFERS" in out, "a changed text table: exit %d\n%s" % (rc, out))
    write(b, {"t.txt": "table\n"})
    os.remove(os.path.join(b, "s.json"))
    rc, out = run(a, b)
    check(rc == 1 and "s.json: only in" in out, "a missing file: exit %d\n%s" % (rc, out))

finish()
