#!/usr/bin/env python3
"""Every installed header compiles alone, without OpenCL (test install.headers_alone).

Installs the `headers` component of BUILD_DIR into WORK_DIR/prefix, then compiles, for each header under
include/parashade, a translation unit holding only `#include <parashade/X>` (-fsyntax-only, in parallel),
with the install's include directory and the libraries' interface definitions (DEFINITIONS, ','-separated).
A poisoned CL/ directory ahead of the system's stops any header that reaches an OpenCL header: the public
headers name OpenCL classes at most (device.hpp), a program that uses them includes <CL/opencl.hpp> itself.

usage: headers_alone.py CMAKE BUILD_DIR WORK_DIR CXX DEFINITIONS
"""
import concurrent.futures
import os
import pathlib
import shutil
import subprocess
import sys
import time

OPENCL_HEADERS = ("cl.h", "opencl.h", "opencl.hpp", "cl2.hpp", "cl_platform.h", "cl_version.h")


def install_headers(cmake, build_dir, prefix):
    subprocess.run([cmake, "--install", build_dir, "--prefix", str(prefix), "--component", "headers"],
                   check=True, stdout=subprocess.DEVNULL)


def poison_opencl(directory):
    """A CL/ directory whose every header stops the compile, naming the header that got there."""
    (directory / "CL").mkdir(parents=True)
    for name in OPENCL_HEADERS:
        (directory / "CL" / name).write_text(
            f'#error "an installed parashade header includes <CL/{name}>: public headers must not need OpenCL"\n')


def compile_alone(cxx, include, poison, definitions, header):
    source = f"#include <parashade/{header}>\n"
    command = [cxx, "-std=c++17", "-fsyntax-only", "-x", "c++", "-",
               "-I", str(poison), "-I", str(include)] + [f"-D{d}" for d in definitions]
    result = subprocess.run(command, input=source, capture_output=True, text=True)
    return header, result.returncode, result.stderr


def main():
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    cmake, build_dir, work_dir, cxx, definitions = sys.argv[1:]
    work = pathlib.Path(work_dir)
    shutil.rmtree(work, ignore_errors=True)
    prefix, poison = work / "prefix", work / "poison"
    install_headers(cmake, build_dir, prefix)
    poison_opencl(poison)
    include = prefix / "include"
    root = include / "parashade"
    headers = sorted(str(p.relative_to(root)) for p in root.rglob("*") if p.suffix in (".hpp", ".h"))
    if len(headers) < 10:
        sys.exit(f"only {len(headers)} headers installed under {root}: the install rules lost them")
    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        results = list(pool.map(lambda h: compile_alone(cxx, include, poison, definitions.split(","), h), headers))
    failed = [(h, err) for h, code, err in results if code != 0]
    for header, err in failed:
        print(f"--- <parashade/{header}> does not compile alone:\n{err}")
    print(f"{len(headers) - len(failed)} of {len(headers)} installed headers compile alone "
          f"({time.monotonic() - start:.1f} s)")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
