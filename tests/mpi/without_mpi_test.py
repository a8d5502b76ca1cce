#!/usr/bin/env python3
"""A parashade built without MPI (docs/distributed.md, "Without MPI"): it renders as before, and refuses
`render --distribute` and `scaling --mpi` with a usage error (exit 2) that says why, writing nothing.

    without_mpi_test.py PARASHADE_WITHOUT_MPI SOURCE_DIR [PARASHADE]

PARASHADE (a build with MPI, when there is one) renders the expected image; without it the image is only
checked to exist. Runs without mpirun.
"""
import os
import subprocess
import sys
import tempfile

NOMPI, SOURCE = sys.argv[1:3]
WITH_MPI = sys.argv[3] if len(sys.argv) > 3 else None
SCENE = os.path.join(SOURCE, "scenes", "teapot.json")
COMMON = ["--size", "64x48", "--frames", "1", "--warmup", "0", "--no-error", "-q", "--no-tuned"]
failures = []


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=180)
    print("  rc=%d %s" % (p.returncode, " ".join(cmd)), flush=True)
    return p.returncode, p.stdout, p.stderr


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL: " + what, flush=True)


with tempfile.TemporaryDirectory() as tmp:
    img = os.path.join(tmp, "nompi.png")
    rc, out, err = run([NOMPI, "render", SCENE, "-o", img] + COMMON)
    check(rc == 0 and os.path.exists(img), "render without MPI: exit %d: %s" % (rc, err.strip()))
    if WITH_MPI and rc == 0:
        ref = os.path.join(tmp, "mpi.png")
        rc, out, err = run([WITH_MPI, "render", SCENE, "-o", ref] + COMMON)
        check(rc == 0 and open(ref, "rb").read() == open(img, "rb").read(),
              "the build without MPI renders another image than the one with it")
    for args, flag in ((["render", SCENE, "-o", os.path.join(tmp, "d.png"), "--distribute", "sort-last"], "--distribute"),
                       (["render", SCENE, "-o", os.path.join(tmp, "d.png"), "--distribute", "sort-first",
                         "--read-scene", "rank-0"], "--distribute"),
                       (["scaling", SCENE, "--units", "classic", "--size", "64x48", "--frames", "1", "-q", "--mpi",
                         "--report", os.path.join(tmp, "s.json")], "--mpi")):
        rc, out, err = run([NOMPI] + args + (COMMON if args[0] == "render" else []))
        check(rc == 2, "%s: exit %d (want 2): %s" % (" ".join(args), rc, err.strip()))
        check(flag + " needs MPI" in err and "built without it" in err,
              "%s: the message does not say why: %s" % (" ".join(args), err.strip()))
        check(not os.path.exists(os.path.join(tmp, "d.png")) and not os.path.exists(os.path.join(tmp, "s.json")),
              "%s: wrote an output" % " ".join(args))
if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("ok")
