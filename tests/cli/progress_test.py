#!/usr/bin/env python3
"""Progress lines (docs/cli.md, "Conventions"): render of many frames, scaling and tune show "[i/N] ... left"
on stderr when it is a terminal (a pseudo-terminal here), and nothing of it on a pipe or with -q.

    progress_test.py PARASHADE SOURCE_DIR
"""
import os
import pty
import re
import select
import subprocess
import sys
import tempfile

PARASHADE, SOURCE = sys.argv[1], sys.argv[2]
PROGRESS = re.compile(r"\[\d+/\d+\] [0-9.]+ s elapsed, about [0-9.]+ s left")
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL: " + what, flush=True)


def on_terminal(args):
    """stderr on a pseudo-terminal; returns (exit code, what the terminal got)."""
    master, slave = pty.openpty()
    p = subprocess.Popen([PARASHADE] + args, stdout=subprocess.DEVNULL, stderr=slave, stdin=subprocess.DEVNULL)
    os.close(slave)
    got = b""
    while True:
        ready, _, _ = select.select([master], [], [], 300)
        if not ready:
            p.kill()
            break
        try:
            chunk = os.read(master, 4096)
        except OSError:  # EIO: the child closed the terminal
            break
        if not chunk:
            break
        got += chunk
    os.close(master)
    return p.wait(), got.decode(errors="replace")


def on_pipe(args):
    p = subprocess.run([PARASHADE] + args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, timeout=300)
    return p.returncode, p.stderr


def main():
    with tempfile.TemporaryDirectory(prefix="parashade-progress-") as tmp:
        return run_all(tmp)


def run_all(tmp):
    scene = os.path.join(SOURCE, "scenes", "sphere.json")
    small = ["--size", "32x24"]
    commands = {
        "render": ["render", scene, *small, "--frames", "6", "--warmup", "1", "--no-tuned", "--no-error",
                   "-o", os.path.join(tmp, "r.png")],
        "scaling": ["scaling", scene, *small, "--units", "classic,counter", "--frames", "2"],
        "tune": ["tune", scene, *small, "--budget-runs", "2", "--frames", "1", "--cache", os.path.join(tmp, "t.json")],
    }
    for name, args in commands.items():
        rc, text = on_terminal(args)
        check(rc == 0, "%s on a terminal: exit %d: %s" % (name, rc, text[-500:]))
        check(PROGRESS.search(text), "%s on a terminal shows no [i/N] progress line: %r" % (name, text[-500:]))
        rc, text = on_terminal(args + ["-q"])
        check(rc == 0 and not PROGRESS.search(text), "%s -q on a terminal still shows progress: %r" % (name, text[-500:]))
        rc, text = on_pipe(args)
        check(rc == 0 and not PROGRESS.search(text) and "\r" not in text,
              "%s on a pipe gets progress: %r" % (name, text[-500:]))
        print("ok: %s" % name, flush=True)
    if failures:
        print("progress_test: %d failure(s)" % len(failures))
        return 1
    print("progress_test: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
