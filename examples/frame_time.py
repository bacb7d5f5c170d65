#!/usr/bin/env python3
"""frame_time.py - Cortex-M4 instruction counts per band of the firmware
example, and the frame-time model of a 320x240 RGB565 SPI panel.

Runs examples/m4_band's ELF on qemu-system-arm -M mps2-an386 with one
instruction per translation block (-singlestep, or -accel
tcg,one-insn-per-tb=on on qemu >= 8.1) and `-d exec,nochain`, so qemu logs
one "Trace" line per executed instruction. The trace is read from a pipe
and never stored. The firmware marks each frame (fw_mark_frame), the start
of its band rendering (fw_mark_render) and each band's end (the mock SPI's
pixels() call, spi_mock_pixels); instructions of the mock SPI itself
(spi_mock_*: the CRC a DMA engine would not need) are left out.

Per frame that gives:
  submit  front end (transform, clip, texgen, lighting, project, cull) and
          binning of the scene, once per frame;
  band k  clearing band k (colour and depth), drawing its triangles, and the
          driver's bookkeeping around sending it.

The model: an instruction takes CPI cycles at CLOCK MHz (default 1.25 at
120 MHz: a Cortex-M4 with zero-wait-state code, about 1.25 cycles per
instruction for this load/store- and multiply-heavy integer code; state
yours with --clock-mhz and --cpi). A band of 320 x 24 RGB565 is 15,360
bytes on an SPI clock of F MHz: 15,360 * 8 / F us. The timeline is the one
of port/band.c: band k+1 is rendered while band k is on the wire, and band
k+1's transfer starts when both are done.

  python3 examples/frame_time.py [--elf build-fw-m4/bin/m4_band.elf]
          [--clock-mhz 120] [--cpi 1.25] [--spi-mhz 40,62.5] [--profile 15]

Standard library only. Takes a few minutes (qemu logs ~90 million lines).
"""
import argparse
import bisect
import os
import subprocess
import sys
import tempfile

WIDTH, HEIGHT, BAND_ROWS = 320, 240, 24
WINDOW_BYTES = 11  # CASET 1 + 4, RASET 1 + 4, RAMWR 1


def read_symbols(nm, elf):
    """Function symbols (address, size, name), sorted by address."""
    out = subprocess.run([nm, "-S", "--defined-only", elf], check=True,
                         capture_output=True, text=True).stdout
    syms = []
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 4 and parts[2] in "tTwW":
            syms.append((int(parts[0], 16) & ~1, int(parts[1], 16), parts[3]))
    syms.sort()
    return syms


def qemu_trace_args(qemu):
    """-singlestep on qemu < 8.1, the accel property on newer ones."""
    ver = subprocess.run([qemu, "--version"], capture_output=True, text=True).stdout
    try:
        major, minor = (int(x) for x in ver.split("version ")[1].split(".")[:2])
    except (IndexError, ValueError):
        major, minor = 0, 0
    if (major, minor) >= (8, 1):
        return ["-accel", "tcg,one-insn-per-tb=on"]
    return ["-singlestep"]


def run_trace(args, syms):
    addr = {name: a for a, _, name in syms}
    for need in ("fw_mark_frame", "fw_mark_render", "spi_mock_pixels"):
        if need not in addr:
            sys.exit("frame_time.py: symbol %s not in %s" % (need, args.elf))
    starts = [a for a, _, _ in syms]
    MOCK, FRAME, RENDER, PIXELS, OTHER = 1, 2, 3, 4, 0

    def classify(pc):
        if pc == addr["fw_mark_frame"]:
            return FRAME
        if pc == addr["fw_mark_render"]:
            return RENDER
        if pc == addr["spi_mock_pixels"]:
            return PIXELS
        i = bisect.bisect_right(starts, pc) - 1
        if i >= 0 and syms[i][2].startswith("spi_mock_") and pc < syms[i][0] + max(syms[i][1], 2):
            return MOCK
        return OTHER

    tmp = tempfile.mkdtemp(prefix="fxl_frame_time_")
    out_path = os.path.join(tmp, "semihosting.txt")
    cmd = [args.qemu, "-M", "mps2-an386", "-display", "none", "-monitor", "none",
           "-serial", "none", "-chardev", "file,id=semi,path=" + out_path,
           "-semihosting-config", "enable=on,target=native,chardev=semi",
           *qemu_trace_args(args.qemu), "-d", "exec,nochain", "-D", "/dev/stderr",
           "-kernel", args.elf]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            bufsize=1 << 20)
    cls_of = {}
    pc_count = {}
    frames = []          # [submit, [band counts]]
    phase = None         # None, "submit", "band"
    count = 0
    lines = 0
    try:
        for line in proc.stderr:
            # "Trace 0: 0x<host> [<flags>/<pc>/<...>/<...>] <symbol>"
            if not line.startswith(b"Trace"):
                continue
            lines += 1
            pc_s = line.split(b"/", 2)[1]
            c = cls_of.get(pc_s)
            if c is None:
                c = cls_of[pc_s] = classify(int(pc_s, 16))
            if c == MOCK:
                continue
            if args.profile:
                pc_count[pc_s] = pc_count.get(pc_s, 0) + 1
            if c == OTHER:
                count += 1
            elif c == FRAME:
                frames.append([0, []])
                phase, count = "submit", 1
            elif c == RENDER:
                if phase == "submit":
                    frames[-1][0] = count
                phase, count = "band", 1
            elif c == PIXELS:
                if phase == "band":
                    frames[-1][1].append(count)
                count = 1
        rc = proc.wait()
        with open(out_path) as f:
            fw_out = f.read()
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        if os.path.exists(out_path):
            os.unlink(out_path)
        os.rmdir(tmp)
    if rc != 0 or "status ok" not in fw_out:
        sys.exit("frame_time.py: the firmware failed (qemu exit %d):\n%s" % (rc, fw_out))
    names = [" ".join(l.split()[1:3]) for l in fw_out.splitlines()
             if l.startswith("crc ") and not l.startswith("crc init")]
    if len(names) != len(frames):
        sys.exit("frame_time.py: %d frames in the trace, %d in the output" % (len(frames), len(names)))
    return names, frames, pc_count, lines


def timeline(submit_s, bands_s, xfer_s):
    """port/band.c: render band k, wait for transfer k-1 to end, start
    transfer k, render band k+1, ...; fxl_band_render returns when the last
    transfer has ended. Returns that time (the frame time)."""
    t = submit_s
    xfer_end = t
    for r in bands_s:
        t = max(t + r, xfer_end)     # rendered, and the previous transfer is done
        xfer_end = t + xfer_s        # transfer k starts; the CPU goes on
    return xfer_end


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--elf", default="build-fw-m4/bin/m4_band.elf")
    ap.add_argument("--qemu", default="qemu-system-arm")
    ap.add_argument("--nm", default="arm-none-eabi-nm")
    ap.add_argument("--clock-mhz", type=float, default=120.0)
    ap.add_argument("--cpi", type=float, default=1.25)
    ap.add_argument("--spi-mhz", default="40,62.5")
    ap.add_argument("--profile", type=int, default=0, metavar="N",
                    help="also list the N functions that execute the most instructions")
    args = ap.parse_args()
    spis = [float(x) for x in args.spi_mhz.split(",")]
    syms = read_symbols(args.nm, args.elf)
    names, frames, pc_count, lines = run_trace(args, syms)
    sec_per_insn = args.cpi / (args.clock_mhz * 1e6)
    band_bytes = WIDTH * BAND_ROWS * 2
    frame_bytes = WIDTH * HEIGHT * 2 + WINDOW_BYTES

    print("# %s: %d instructions traced; model: %.4g MHz, %.3g cycles/instruction"
          % (os.path.basename(args.elf), lines, args.clock_mhz, args.cpi))
    print()
    print("## SPI link, 320x240 RGB565 (%d bytes per frame incl. window commands)" % frame_bytes)
    print()
    print("| SPI clock | frame transfer | link-limited frame rate | one 320x24 band |")
    print("|---|---|---|---|")
    for f in spis:
        tf = frame_bytes * 8 / (f * 1e6)
        print("| %g MHz | %.2f ms | %.1f fps | %.3f ms |" % (f, tf * 1e3, 1 / tf, band_bytes * 8 / (f * 1e6) * 1e3))
    print()
    print("## Instructions per frame and per band (Cortex-M4, qemu, mock SPI excluded)")
    print()
    print("| frame | submit (front end + binning) | band min / mean / max | bands total "
          "| render time per band, max (us) | frame render total (ms) |")
    print("|---|---|---|---|---|---|")
    for name, (submit, bands) in zip(names, frames):
        total = submit + sum(bands)
        print("| %s | %d | %d / %d / %d | %d | %.0f | %.2f |" % (
            name, submit, min(bands), sum(bands) // len(bands), max(bands), sum(bands),
            max(bands) * sec_per_insn * 1e6, total * sec_per_insn * 1e3))
    print()
    print("## Frame time with band double buffering (port/band.c timeline)")
    print()
    head = "| frame |" + "".join(" %g MHz: frame (ms) / fps / render hidden? |" % f for f in spis)
    print(head)
    print("|---|" + "---|" * len(spis))
    for name, (submit, bands) in zip(names, frames):
        row = "| %s |" % name
        for f in spis:
            xfer = band_bytes * 8 / (f * 1e6)
            t = timeline(submit * sec_per_insn, [b * sec_per_insn for b in bands], xfer)
            t += WINDOW_BYTES * 8 / (f * 1e6)
            slow = sum(1 for b in bands[1:] if b * sec_per_insn > xfer)
            hidden = "yes" if slow == 0 else "no (%d of %d bands longer than a transfer)" % (slow, len(bands) - 1)
            row += " %.2f / %.1f / %s |" % (t * 1e3, 1 / t, hidden)
        print(row)
    if args.profile:
        funcs = {}
        starts = [a for a, _, _ in syms]
        for pc_s, n in pc_count.items():
            pc = int(pc_s, 16)
            i = bisect.bisect_right(starts, pc) - 1
            name = syms[i][2] if i >= 0 else "?"
            funcs[name] = funcs.get(name, 0) + n
        tot = sum(funcs.values())
        print()
        print("## Where the instructions go (all frames, mock SPI excluded)")
        print()
        print("| function | instructions | share |")
        print("|---|---|---|")
        for name, n in sorted(funcs.items(), key=lambda kv: -kv[1])[:args.profile]:
            print("| %s | %d | %.1f%% |" % (name, n, 100.0 * n / tot))


if __name__ == "__main__":
    main()
