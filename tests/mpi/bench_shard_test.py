#!/usr/bin/env python3
"""scripts/bench-suite.sh dealt across shards (docs/distributed.md, "Sharded sweeps"), in its dry run:
every step of the unsharded suite runs on exactly one shard, the steps that read every result run once,
on shard 0, and under mpirun each rank takes the shard of its rank. Then the join itself: shard 0 runs a
final step only after every other shard has marked its end.

    bench_shard_test.py SOURCE_DIR MPIEXEC
"""
import os
import subprocess
import sys
import tempfile

SOURCE, MPIEXEC = sys.argv[1:3]
SUITE = os.path.join(SOURCE, "scripts", "bench-suite.sh")
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL: " + what, flush=True)


def dry(out, mode, shard=None):
    cmd = ["sh", SUITE] + mode + (["--shard", shard] if shard else []) + ["--dry-run", out]
    # PYTHON=true: the suite's look for a python3 with matplotlib costs a second a run and a dry run needs none
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=120, env=dict(os.environ, PYTHON="true"))
    check(p.returncode == 0, "%s: exit %d: %s" % (" ".join(cmd), p.returncode, p.stderr.strip()))
    return p.stdout.split("\n")


def kinds(lines, kind):
    return [l.split(" ", 1)[1] for l in lines if l.startswith(kind + " ")]


with tempfile.TemporaryDirectory() as out:
    for mode in ([], ["--phong"]):
        whole = dry(out, mode)
        steps, finals = kinds(whole, "step"), kinds(whole, "final")
        check(len(steps) >= 4 and len(set(steps)) == len(steps), "%s: unsharded steps %s" % (mode, steps))
        check(finals, "%s: no final step listed" % mode)
        for n in (2, 3, len(steps) + 1) if not mode else (2, 3):  # len + 1: a shard without steps
            dealt, finals_by = [], []
            for k in range(n):
                lines = dry(out, mode, "%d/%d" % (k, n))
                dealt += kinds(lines, "step")
                finals_by.append(kinds(lines, "final"))
            check(sorted(dealt) == sorted(steps), "%s N=%d: dealt %s, unsharded %s" % (mode, n, sorted(dealt), sorted(steps)))
            check(finals_by[0] == finals and not any(finals_by[1:]),
                  "%s N=%d: final steps %s, want %s on shard 0 only" % (mode, n, finals_by, finals))

    # Under mpirun the rank is the shard: the same deal as --shard K/3.
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", PYTHON="true")
    p = subprocess.run([MPIEXEC, "--oversubscribe", "--tag-output", "-np", "3", "sh", SUITE, "--dry-run", out],
                       capture_output=True, text=True, timeout=180, env=env)
    check(p.returncode == 0, "mpirun -np 3 bench-suite.sh --dry-run: exit %d: %s" % (p.returncode, p.stderr.strip()))
    for k in range(3):
        tag = "[1,%d]<stdout>:" % k
        got = [l[len(tag):] for l in p.stdout.split("\n") if l.startswith(tag)]
        want = [l for l in dry(out, [], "%d/3" % k) if l]
        check(got == want, "mpirun rank %d listed %s, --shard %d/3 lists %s" % (k, got, k, want))

    # The join: rank 0's final step runs after the others' marks, which they leave only at their end.
    script = ('. "%s"; OUT="%s"; [ "$SHARD" -ne 0 ] && sleep 3 && echo end > "$OUT/end-$SHARD"; '
              'after_all final && ls "$OUT" | grep -c "^end-"' % (os.path.join(SOURCE, "scripts", "bench_shard.sh"), out))
    p = subprocess.run([MPIEXEC, "--oversubscribe", "-np", "3", "sh", "-c", script], capture_output=True, text=True,
                       timeout=180, env=env)
    check(p.returncode == 0 and p.stdout.strip() == "2",
          "the final step ran before the other shards ended: exit %d, saw %r ends: %s" % (p.returncode, p.stdout, p.stderr))
if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("ok")
