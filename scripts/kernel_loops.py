#!/usr/bin/env python3
"""The hot loops of an OpenCL kernel as the CPU runs it, and what the machine's vector units allow them.

On a machine without hardware performance counters (no PMU: perf counts no instructions), and where valgrind cannot
run the kernel the renderer runs (it lacks AVX-512, so PoCL compiles another), this counts instructions statically
in the kernel PoCL compiled and cached (`POCL_CACHE_DIR`), weighted by where perf's time samples fall:

  1. `perf annotate` gives each instruction of a kernel's work-group function and its share of the samples;
  2. every backward branch's target is a loop's head;
  3. for each loop, one iteration's hot path: from its head, at each branch the side with more samples, back to
     the head; a loop's share is the samples on that path;
  4. llvm-mca estimates that path's cycles per iteration at full throughput on the given CPU model (no cache
     misses, no mispredicted branches), and names the busiest execution port.

    perf record -o perf.data parashade render scene.json ...      (or any benchmark that runs the kernel)
    scripts/kernel_loops.py perf.data [--kernel render_tiles] [--loops 6] [--mcpu skylake-avx512] [--json out.json]

What it cannot say: how many times a loop ran. A loop's pixels per iteration (a 16-lane stamp: 16) come from
the kernel's source; its measured time is the kernel's time times the loop's share of the samples.
"""
import argparse
import json
import re
import shutil
import subprocess
import sys

LINE = re.compile(r"^\s*(\d+\.\d+)\s*:\s*([0-9a-f]+):\s*(\S.*?)\s*$")
MCA_ITERATIONS = 200  # llvm-mca's simulated iterations; its total cycles over them is the cost of one
# A direct jump: `jmp`/`jmpq` or a conditional one, maybe after a `bnd` or `notrack` prefix, to a hex address.
BRANCH = re.compile(r"^(?:(?:bnd|notrack)\s+)?(j[a-z]+)\s+([0-9a-f]+)\b")
# `perf report --sort dso,sym -v`: share, the DSO's full path, the symbol's address and binding, the symbol.
REPORT = re.compile(r"^\s*(\d+\.\d+)%\s+(\S+)\s.*\[\.\]\s+(_pocl_kernel_(\w+?)_workgroup\w*)\s*$")


def parse_annotate(text, what):
    """[(address, share %, instruction text)] of one function's `perf annotate --stdio` text, in address order.
    Two disassemblies in one text (one symbol in two DSOs: two builds of a kernel in one process) would mix two
    codes at the same addresses, so the script stops there."""
    if text.count("Percent |") > 1:
        sys.exit(f"kernel_loops.py: perf annotate gave {what} more than once (two builds of a kernel?)")
    rows = []
    for line in text.splitlines():
        m = LINE.match(line)
        if m:
            rows.append((int(m.group(2), 16), float(m.group(1)), m.group(3)))
    if not rows:
        sys.exit(f"kernel_loops.py: perf annotate gave no instructions for {what}")
    return sorted(rows)


def annotate(perf_data, dso, symbol):
    run = subprocess.run(["perf", "annotate", "-i", perf_data, "--stdio", "--dsos", dso, "-s", symbol],
                         capture_output=True, text=True)
    return parse_annotate(run.stdout, f"{symbol} in {dso} {run.stderr.strip()[:200]}".strip())


def parse_report(text, kernel):
    """(DSO, work-group function, share %) of each PoCL kernel (PoCL names them _pocl_kernel_NAME_workgroup) in a
    `perf report --sort dso,sym -v` text: one row per compiled copy, so two builds of a kernel stay apart."""
    found = []
    for line in text.splitlines():
        m = REPORT.match(line)
        if m and (kernel is None or m.group(4) == kernel):
            found.append((m.group(2), m.group(3), float(m.group(1))))
    return found


def kernel_symbols(perf_data, kernel):
    run = subprocess.run(["perf", "report", "-i", perf_data, "--stdio", "--no-children", "--sort", "dso,sym",
                          "-g", "none", "-v"], capture_output=True, text=True)
    return parse_report(run.stdout, kernel)


def branch(text):
    """(mnemonic, target address) of a direct jump, else None; `jmpq` is read as `jmp`."""
    m = BRANCH.match(text)
    return ("jmp" if m.group(1) == "jmpq" else m.group(1), int(m.group(2), 16)) if m else None


def loop_heads(rows):
    """The targets of backward branches: each is the head of a loop."""
    heads = set()
    for address, _, text in rows:
        b = branch(text)
        if b and b[1] < address:
            heads.add(b[1])
    return sorted(heads)


def hot_cycle(rows, head, index=None):
    """One iteration of the loop at `head` as it mostly runs: from the head, at each conditional branch the side
    whose straight run holds more samples, until the path comes back to the head. Row indices, or None when the
    path settles in another loop (an outer loop's path meets its inner loop) or leaves the function. `index`:
    each address's row (hot_loops passes it once for all heads)."""
    index = index or {address: i for i, (address, _, _) in enumerate(rows)}

    def mass(i):  # the samples of the straight run from row i to its next branch
        total = 0.0
        while i < len(rows):
            total += rows[i][1]
            if branch(rows[i][2]):
                break
            i += 1
        return total

    path, seen, i = [], set(), index[head]
    while True:
        if i is None or i >= len(rows) or i in seen:
            return None
        seen.add(i)
        path.append(i)
        b = branch(rows[i][2])
        if b is None:
            i += 1
        else:
            target = index.get(b[1])
            if b[0] != "jmp" and (target is None or mass(i + 1) >= mass(target)):
                target = i + 1
            i = target
        if i == index[head]:
            return path


def hot_loops(rows, count):
    """The `count` hottest loops: (hot path, its share of the samples), hottest first. Loops whose heads lead to
    one hot path are one loop."""
    index = {address: i for i, (address, _, _) in enumerate(rows)}
    paths = {}
    for head in loop_heads(rows):
        path = hot_cycle(rows, head, index)
        if path:
            paths.setdefault(frozenset(path), path)
    shares = [(path, sum(rows[i][1] for i in path)) for path in paths.values()]
    return sorted(shares, key=lambda loop: -loop[1])[:count]


def for_mca(text):
    """The instruction as llvm-mca's assembler reads it: no trailing `# comment`, no `<symbol+off>`."""
    text = re.sub(r"\s+#.*$", "", text)
    return re.sub(r"\s*<[^>]*>", "", text)


def mca(instructions, mcpu):
    """llvm-mca's estimate of one iteration: instructions, cycles per iteration, busiest port and its load."""
    source = "\n".join(for_mca(t) for t in instructions) + "\n"
    tool = shutil.which("llvm-mca") or shutil.which("llvm-mca-14")
    if tool is None:
        sys.exit("kernel_loops.py: llvm-mca is not installed (apt-get install llvm)")
    run = subprocess.run([tool, f"-mcpu={mcpu}", f"-iterations={MCA_ITERATIONS}"], input=source, capture_output=True,
                         text=True)
    if run.returncode != 0:
        return {"error": run.stderr.strip().splitlines()[0] if run.stderr.strip() else "llvm-mca failed"}
    out = run.stdout
    cycles = float(re.search(r"Total Cycles:\s+(\d+)", out).group(1)) / MCA_ITERATIONS
    rthroughput = float(re.search(r"Block RThroughput:\s+([\d.]+)", out).group(1))
    pressure = busiest_port(out)
    return {"instructions": len(instructions), "cycles_per_iteration": round(cycles, 2),
            "block_rthroughput": rthroughput, "busiest_port": pressure[0], "port_cycles": pressure[1]}


def busiest_port(out):
    """(port, cycles per iteration) of the resource with the most pressure, from llvm-mca's table."""
    lines = out.splitlines()
    for k, line in enumerate(lines):
        if line.startswith("Resource pressure per iteration:"):
            names = re.findall(r"\[([\w.]+)\]", lines[k + 1])
            values = [float(v) if v != "-" else 0.0 for v in lines[k + 2].split()]
            label = dict(re.findall(r"^\[([\w.]+)\]\s+-\s+(\S+)", out, re.M))  # [0] - SKXDivider
            best = max(range(len(values)), key=lambda j: values[j])
            return label.get(names[best], names[best]), values[best]
    return "?", 0.0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("perf_data")
    ap.add_argument("--kernel", help="the kernel's name (render_tiles, plane_fill_limit, ...); default: every kernel")
    ap.add_argument("--loops", type=int, default=6, help="the hottest loops to show per kernel")
    ap.add_argument("--mcpu", default="skylake-avx512", help="llvm-mca's CPU model (default skylake-avx512)")
    ap.add_argument("--json", help="write the figures here")
    args = ap.parse_args()
    symbols = kernel_symbols(args.perf_data, args.kernel)
    if not symbols:
        which = f" of {args.kernel}" if args.kernel else ""
        sys.exit(f"kernel_loops.py: no samples in a PoCL work-group function{which} in {args.perf_data}")
    result = []
    for dso, symbol, share in symbols:
        rows = annotate(args.perf_data, dso, symbol)
        print(f"{symbol} ({dso}): {share:.1f} % of all samples")
        print("  loop at   % of kernel  instructions  cycles/iteration  busiest port (cycles)")
        entry = {"symbol": symbol, "dso": dso, "share_of_samples": share, "loops": []}
        for path, on_path in hot_loops(rows, args.loops):
            body = [rows[i][2] for i in path if not branch(rows[i][2])]
            est = mca(body, args.mcpu)
            entry["loops"].append({"head": hex(rows[path[0]][0]), "share": round(on_path, 2), **est})
            where = f"{rows[path[0]][0]:x}"
            if "error" in est:
                print(f"  {where:8s}  {on_path:10.1f}   {est['error']}")
            else:
                print(f"  {where:8s}  {on_path:10.1f}   {est['instructions']:11d}   "
                      f"{est['cycles_per_iteration']:15.2f}   {est['busiest_port']} ({est['port_cycles']:.2f})")
        result.append(entry)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"mcpu": args.mcpu, "kernels": result}, f, indent=1)


if __name__ == "__main__":
    main()
