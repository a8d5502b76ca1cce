#!/usr/bin/env python3
"""scripts/kernel_loops.py on made-up annotated code: the loop heads, one iteration's hot path (the hotter side of
each branch, a path that jumps back before its head, an outer loop whose path settles in its inner loop), the
instructions as llvm-mca reads them, and llvm-mca's estimate (a chain of divisions costs more than one of adds and
loads the divider). Usage: kernel_loops_test.py SOURCE_DIR"""
import shutil
import sys

from checks import check, finish, load_script

loops = load_script(sys.argv[1], "kernel_loops")

# (address, share %, text): an outer loop at 0x10 around an inner one at 0x20, whose iteration goes on at 0x08
# (before its head, as PoCL lays out a row's last store) and takes the hot side of a branch at 0x28.
rows = [
    (0x08, 5.0, "vmovntdq %zmm0,(%rdx)"),
    (0x0c, 1.0, "jmp    20 <k+0x20>"),
    (0x10, 0.1, "add    $0x1,%rcx"),
    (0x14, 0.1, "xor    %eax,%eax"),
    (0x20, 10.0, "vaddps %zmm1,%zmm2,%zmm3"),
    (0x24, 8.0, "vmulps %zmm3,%zmm3,%zmm4"),
    (0x28, 0.5, "je     40 <k+0x40>"),
    (0x2c, 0.0, "vdivps %zmm4,%zmm5,%zmm6"),
    (0x30, 0.0, "jmp    38 <k+0x38>"),
    (0x38, 0.0, "nop"),
    (0x40, 12.0, "vpord  %zmm4,%zmm1,%zmm1"),
    (0x44, 2.0, "jne    8 <k+0x8>"),
    (0x48, 0.1, "cmp    $0x4,%rcx"),
    (0x4c, 0.1, "jne    10 <k+0x10>"),
]
check(loops.loop_heads(rows) == [0x08, 0x10], "heads: the targets of backward branches, %r" % loops.loop_heads(rows))
check(loops.branch("jne    8 <k+0x8>") == ("jne", 8), "a branch and its target")
check(loops.branch("vaddps %zmm1,%zmm2,%zmm3") is None, "not a branch")

index = {address: i for i, (address, _, _) in enumerate(rows)}
path = loops.hot_cycle(rows, 0x08)
addresses = [rows[i][0] for i in path] if path else None
check(addresses == [0x08, 0x0c, 0x20, 0x24, 0x28, 0x40, 0x44],
      "the hot side of 0x28, back through 0x08: %r" % addresses)
check(loops.hot_cycle(rows, 0x10) is None, "an outer loop's path settles in its inner loop: no cycle through 0x10")
cold = [(a, {0x2c: 3.0, 0x40: 0.0, 0x44: 0.0}.get(a, s), t) for a, s, t in rows]
cold_path = loops.hot_cycle(cold, 0x08)
check(cold_path is not None and index[0x2c] in cold_path,
      "with 0x40 cold and the division hot, the path takes it: %r" % cold_path)

# An unconditional jump is followed whatever the samples after it: 0x08 (another loop's hot body) is skipped.
jumps = [(0x00, 1.0, "vaddps %zmm1,%zmm2,%zmm3"), (0x04, 0.0, "jmpq   10 <k+0x10>"),
         (0x08, 50.0, "vmulps %zmm3,%zmm3,%zmm4"), (0x0c, 0.0, "ret"),
         (0x10, 1.0, "vsubps %zmm1,%zmm2,%zmm3"), (0x14, 1.0, "notrack jne 0 <k>")]
jump_path = loops.hot_cycle(jumps, 0x00)
check(jump_path is not None and [jumps[i][0] for i in jump_path] == [0x00, 0x04, 0x10, 0x14],
      "jmpq taken, notrack jne read, 0x08 not on the path: %r" % jump_path)

# perf's texts: one row per compiled copy of a kernel (two builds in one process stay apart), and an annotation
# that holds two disassemblies is refused rather than merged.
report = """# Overhead  Shared Object  Symbol
    40.00%  /cache/AA/render_tiles/render_tiles.so  0x41c2             B [.] _pocl_kernel_render_tiles_workgroup
    30.00%  /cache/BB/render_tiles/render_tiles.so  0x428b             B [.] _pocl_kernel_render_tiles_workgroup
     9.00%  /cache/CC/fill_limit/fill_limit.so  0x1160             B [.] _pocl_kernel_fill_limit_workgroup
     5.00%  /usr/bin/parashade  0x20d7ba           B [.] parashade::setup_triangle_range
"""
found = loops.parse_report(report, "render_tiles")
check([d for d, _, _ in found] == ["/cache/AA/render_tiles/render_tiles.so", "/cache/BB/render_tiles/render_tiles.so"],
      "two builds of render_tiles, each with its DSO: %r" % found)
check(len(loops.parse_report(report, None)) == 3, "every PoCL kernel, no host function")
one = """ Percent |	Source code & Disassembly of render_tiles.so for cpu-clock:pppH (246 samples)
    2.50 :   41a0:   vpbroadcastd %edi,%zmm10
    0.00 :   41a6:   jne    41a0 <_pocl_kernel_render_tiles_workgroup+0xf40>
"""
check(loops.parse_annotate(one, "k") == [(0x41a0, 2.5, "vpbroadcastd %edi,%zmm10"),
                                         (0x41a6, 0.0, "jne    41a0 <_pocl_kernel_render_tiles_workgroup+0xf40>")],
      "an annotation's rows: %r" % loops.parse_annotate(one, "k"))
try:
    loops.parse_annotate(one + one, "k")
    check(False, "two disassemblies in one annotation are refused")
except SystemExit:
    pass

check(loops.for_mca("vpbroadcastd 0xb6a(%rip),%zmm4{%k1}{z}        # 2010 <f+0xa00>") ==
      "vpbroadcastd 0xb6a(%rip),%zmm4{%k1}{z}", "the comment and symbol dropped for llvm-mca")

table = """Resources:
[0]   - SKXDivider
[1]   - SKXPort0
[2]   - SKXPort5

Resource pressure per iteration:
[0]    [1]    [2]
 -     3.00   1.50
"""
check(loops.busiest_port(table) == ("SKXPort0", 3.0), "the busiest resource named: %r" % (loops.busiest_port(table),))

if shutil.which("llvm-mca") or shutil.which("llvm-mca-14"):
    adds = loops.mca(["vaddps %zmm1,%zmm2,%zmm1"] * 8, "skylake-avx512")
    divs = loops.mca(["vdivps %zmm1,%zmm2,%zmm1"] * 8, "skylake-avx512")
    check(adds.get("instructions") == 8, "eight instructions counted: %r" % adds)
    check(divs.get("cycles_per_iteration", 0) > 3 * adds.get("cycles_per_iteration", 1e9),
          "dependent divisions cost more than dependent adds: %r against %r" % (divs, adds))
    check("Div" in divs.get("busiest_port", ""), "divisions load the divider: %r" % divs)
    check("error" in loops.mca(["not_an_instruction %zmm1"], "skylake-avx512"), "llvm-mca's refusal is reported")
else:
    print("llvm-mca not installed (Debian: llvm): its estimate is not checked")
finish()
