#!/usr/bin/env python3
"""m4_count.py - helpers of host_sim/scripts/bench.sh for the Cortex-M runs.

  m4_count.py ranges NM_IN NM_OUT LIB_NM
      From the firmware's `arm-none-eabi-nm -S` listing keep the functions
      the trace counter may count: text symbols of the core archive (LIB_NM,
      `nm` of libfixel.a), the libgcc helpers they call (names starting with
      "__"), memcpy/memset, and the markers bench_begin / bench_end. (The
      firmware's linker script puts .rodata in the .text output section, so
      nm shows the data arrays as text too: they are dropped here.) Prints a
      QEMU -dfilter argument covering the kept functions.
  m4_count.py icount FW_OUT
      Firmware output of an `-icount shift=0` run -> lines
      "scene method filter instructions icount": (ticks - harness ticks) *
      instructions / ticks of the calibration loop.
  m4_count.py trace FW_OUT COUNTS
      Pair the firmware's configuration lines with the per-segment counts of
      `fixel-bench count-trace` -> "scene method filter instructions trace".
  m4_count.py peak FW_OUT
      The benchmark firmware's measured stack depths ("stack ..." lines,
      examples/common/fw_stack.h) -> "draw BYTES SCENE METHOD FILTER" and
      "frontend BYTES MESH LEVEL CACHE", the deepest of each kind.
  m4_count.py linked ELF_NM LIB_NM [APP_NM]
      Bytes of the core that a program actually linked: the sizes of the
      ELF's symbols (code and constant data) that the core archive defines,
      plus the compiler runtime helpers they pulled in (every other symbol
      not defined by the program's own objects, APP_NM). Prints
      "total code data runtime" (total = code + runtime).
  m4_count.py stack CI_DIR ROOT_FUNCTION [CALLER=CALLEE ...]
      Worst-case stack of ROOT_FUNCTION from gcc -fcallgraph-info=su files:
      the largest sum of frame sizes along any call chain. An indirect call
      (the span-loop pointer) may reach any static function that nothing
      calls directly (only its address is taken) in the same file; the
      CALLER=CALLEE pairs add calls through pointers handed across files
      (fxl_pipeline_emit=draw_one: fxl_mesh_draw's callback). Prints
      "bytes chain...".
Standard library only.
"""
import os
import re
import sys

HARNESS = re.compile(r"^(main|bench_nop|run|spin|put_\w+|ticks_\w+|fw_\w+|semihost|"
                     r"Reset_Handler|Default_Handler|vectors)$")


def defined_symbols(nm_path, kinds):
    """Names an `nm` listing defines with a type letter in kinds."""
    names = set()
    with open(nm_path) as f:
        for line in f:
            p = line.split()
            if len(p) >= 3 and p[-2] in kinds:
                names.add(p[-1])
    return names


def cmd_ranges(nm_in, nm_out, lib_nm):
    core = defined_symbols(lib_nm, "tTwW")
    extra = {"memcpy", "memset", "bench_begin", "bench_end"}
    kept = []
    with open(nm_in) as f:
        lines = f.readlines()
    with open(nm_out, "w") as out:
        for line in lines:
            p = line.split()
            if len(p) != 4 or p[2] not in "tTwW":
                continue
            if HARNESS.match(p[3]) or not (p[3] in core or p[3] in extra or p[3].startswith("__")):
                continue
            out.write(line)
            a = int(p[0], 16) & ~1
            kept.append((a, a + int(p[1], 16)))
    kept.sort()
    merged = []
    for a, b in kept:
        if merged and a <= merged[-1][1]:
            merged[-1] = (merged[-1][0], max(b, merged[-1][1]))
        else:
            merged.append((a, b))
    print(",".join("0x%x..0x%x" % (a, b - 1) for a, b in merged if b > a))


def cfg_lines(path):
    calib = None
    rows = []
    with open(path) as f:
        for line in f:
            p = line.split()
            if len(p) == 3 and p[0] == "calib":
                calib = (int(p[1]), int(p[2]))
            elif len(p) == 7 and p[0] == "cfg":
                rows.append((p[1], p[2], p[3], int(p[4]), int(p[5]), p[6]))
    return calib, rows


def cmd_icount(fw_out):
    calib, rows = cfg_lines(fw_out)
    if not calib or calib[0] <= 0:
        sys.exit("m4_count.py: no calibration line in %s" % fw_out)
    per_tick = calib[1] / calib[0]
    for scene, method, filt, ticks, harness, status in rows:
        if status != "ok":
            print("# %s %s %s: draw error" % (scene, method, filt))
            continue
        print("%s %s %s %.0f icount" % (scene, method, filt, max(ticks - harness, 0) * per_tick))


def cmd_trace(fw_out, counts_path):
    _, rows = cfg_lines(fw_out)
    with open(counts_path) as f:
        counts = [int(x) for x in f.read().split()]
    if len(counts) != len(rows):
        sys.exit("m4_count.py: %d configurations but %d trace segments" % (len(rows), len(counts)))
    for (scene, method, filt, _, _, status), n in zip(rows, counts):
        if status == "ok":
            print("%s %s %s %d trace" % (scene, method, filt, n))


def cmd_stack(ci_dir, root, extra=()):
    frames = {}   # short name -> bytes (largest if names repeat)
    edges = {}    # short name -> set of short names
    home = {}     # short name -> .ci file that defines it
    node_re = re.compile(r'node: \{ title: "([^"]+)" label: "[^"]*?\\n[^"]*?\\n(\d+) bytes')
    edge_re = re.compile(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')

    def short(t):
        return t.rsplit(":", 1)[-1].split(".")[0]

    for name in sorted(os.listdir(ci_dir)):
        if not name.endswith(".ci"):
            continue
        with open(os.path.join(ci_dir, name)) as f:
            text = f.read()
        for m in node_re.finditer(text):
            s = short(m.group(1))
            frames[s] = max(frames.get(s, 0), int(m.group(2)))
            home.setdefault(s, name)
        for m in edge_re.finditer(text):
            t = short(m.group(2))
            if t == "__indirect_call":
                t = "__indirect_call@" + name   # resolved per file below
            edges.setdefault(short(m.group(1)), set()).add(t)
    # An indirect call (the span-loop pointer) may reach the static functions
    # of the same file that nothing calls directly: only their address is
    # taken, which is how the span loops are chosen.
    called = set()
    for targets in edges.values():
        called.update(targets)
    for n in list(edges.values()):
        for t in list(n):
            if t.startswith("__indirect_call@"):
                f = t.split("@", 1)[1]
                edges.setdefault(t, set()).update(
                    c for c in frames
                    if home.get(c) == f and c not in called and not c.startswith("fxl_") and c != root)

    for pair in extra:
        caller, sep, callee = pair.partition("=")
        # a misspelt name would count as a 0-byte leaf: a bound too small
        if not sep or caller not in frames or callee not in frames:
            sys.exit("m4_count.py: %s: want CALLER=CALLEE, both functions of %s" % (pair, ci_dir))
        edges.setdefault(caller, set()).add(callee)

    def worst(n, path):
        if n in path:
            return (0, [n + "(cycle)"])
        best = (0, [])
        for c in sorted(edges.get(n, ())):   # sorted: the same chain on ties, every run
            w = worst(c, path | {n})
            if w[0] > best[0]:
                best = w
        return (frames.get(n, 0) + best[0], [n] + best[1])

    if root not in frames:
        sys.exit("m4_count.py: %s not found in %s" % (root, ci_dir))
    total, chain = worst(root, frozenset())
    print("%d %s" % (total, " > ".join("%s(%d)" % (c.split("@")[0], frames.get(c, 0)) for c in chain)))


def cmd_peak(fw_out):
    best = {}
    with open(fw_out) as f:
        for line in f:
            p = line.split()
            if len(p) == 5 and p[0] == "stack":
                kind, rest = "draw", p[1:4]
            elif len(p) == 6 and p[0] == "stack" and p[1] == "fe":
                kind, rest = "frontend", p[2:5]
            else:
                continue
            depth = int(p[-1])
            if depth > best.get(kind, (-1,))[0]:
                best[kind] = (depth, rest)
    if not best:
        sys.exit("m4_count.py: no stack lines in %s" % fw_out)
    for kind in ("draw", "frontend"):
        if kind in best:
            print("%s %d %s" % (kind, best[kind][0], " ".join(best[kind][1])))


def cmd_linked(elf_nm, lib_nm, app_nm=None):
    core = defined_symbols(lib_nm, "tTrRdDbB")
    app = defined_symbols(app_nm, "tTrRdDbB") if app_nm else None
    code = data = runtime = 0
    with open(elf_nm) as f:
        for line in f:
            p = line.split()
            if len(p) != 4:
                continue
            size = int(p[1], 16)
            if p[3] in core:
                if p[2] in "tT":
                    code += size
                else:
                    data += size
            elif app is not None and p[3] not in app and p[2] in "tT":
                # libgcc's division, shift and multiply helpers
                runtime += size
    print("%d %d %d %d" % (code + runtime, code, data, runtime))


def main(argv):
    if len(argv) >= 5 and argv[1] == "ranges":
        cmd_ranges(argv[2], argv[3], argv[4])
    elif len(argv) >= 3 and argv[1] == "icount":
        cmd_icount(argv[2])
    elif len(argv) >= 4 and argv[1] == "trace":
        cmd_trace(argv[2], argv[3])
    elif len(argv) >= 3 and argv[1] == "peak":
        cmd_peak(argv[2])
    elif len(argv) >= 4 and argv[1] == "linked":
        cmd_linked(argv[2], argv[3], argv[4] if len(argv) >= 5 else None)
    elif len(argv) >= 4 and argv[1] == "stack":
        cmd_stack(argv[2], argv[3], argv[4:])
    else:
        sys.stderr.write(__doc__)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
