#!/usr/bin/env python3
"""rolled_floor_model.py - how many correction points would each kind of
segment need on the floor_rolled scene at a given error budget?

A double-precision model of host_sim's floor_rolled (scene.c: the floor
x = +-40, y = -0.577, z = -1 .. -50, rolled 40 degrees about the view axis,
60-degree vertical field of view, 320x240, the 64-texel checker repeated
every 2 units: 32 texels a unit). At every covered pixel it takes |u'| (the
texel-space change to the next pixel) and eta = |q_x| / q (the relative
change of q = 1/w a pixel) and asks for the longest power-of-two segment,
1 .. 256, whose error bound keeps the budget there:

  chord      L^2 |u'| eta / 4                    (what subdivision does)
  parabola   0.0482 L^3 |u'| eta^2               (AUTO's quadratic segments)
  rational   L |u'| 1.2 eta^2,  L <= 1 / (2 eta)
             perspective interpolation between exact ends, 1/q stepped by
             one Newton step a pixel from the previous pixel's value
             (docs/design.md, "The rolled floor")
  rational+p the same with a linear predictor, L |u'| 4.8 eta^4, with
             q kept within 2x (or 4x: rational+p4) of the segment's start
             and |delta u| <= 4096 texels (fixed-point range)

It prints, per kind, the covered pixels, the correction points (sum of
1/L over the pixels: one per segment) and how many pixels fall in each
length. A model, not the renderer: the renderer's own division count is
what `fixel-sim --scene floor_rolled --persp auto --depth off` prints.

The second part models whole walks: each row's covered run is cut into
segments, either as the renderer does it (aligned power-of-two blocks
counted from the span's left end, or from its far end) or greedily (the
longest segment that fits, from the span's start), choosing per segment
the kind that costs fewest Cortex-M4 instructions a pixel. The costs are
measurements (see COSTS); the rational pixel costs come from
bench/experiments/rational_span.c. The first line, the renderer's own
strategy, calibrates the model against the measured 66.7 instructions a
pixel.

Usage: rolled_floor_model.py [budget_texels]   (default 0.25)
"""
import math
import sys

WIDTH, HEIGHT = 320, 240
FOCAL_PX = (HEIGHT / 2) / math.tan(math.radians(30.0))
ROLL = math.radians(40.0)
FLOOR_Y = -0.577
TEXELS_PER_UNIT = 32.0


def floor_point(sx, sy):
    """(u, v) in texels and q = 1/w of the floor under pixel position
    (sx, sy), or None off the floor."""
    dx = (sx - WIDTH / 2) / FOCAL_PX
    dy = -(sy - HEIGHT / 2) / FOCAL_PX
    # the view ray (dx, dy, -1) in floor coordinates (roll undone)
    fy = -math.sin(ROLL) * dx + math.cos(ROLL) * dy
    if fy >= 0:
        return None
    w = FLOOR_Y / fy
    fx = (dx * math.cos(ROLL) + dy * math.sin(ROLL)) * w
    if not (-40.0 <= fx <= 40.0 and 1.0 <= w <= 50.0):
        return None
    return (TEXELS_PER_UNIT * fx, TEXELS_PER_UNIT * w, 1.0 / w)


def longest(kind, du, eta, budget):
    if eta == 0 or du == 0:
        return 256.0
    if kind == "chord":
        return math.sqrt(4 * budget / (du * eta))
    if kind == "parabola":
        return (budget / (0.0482 * du * eta * eta)) ** (1.0 / 3.0)
    if kind == "rational":
        return min(budget / (1.2 * du * eta * eta), 0.5 / eta, 4096 / du)
    if kind == "rational+p":
        return min(budget / (4.8 * du * eta ** 4), 0.5 / eta, 4096 / du)
    return min(budget / (4.8 * du * eta ** 4), 3.0 / eta, 4096 / du)   # rational+p4


def main():
    budget = float(sys.argv[1]) if len(sys.argv) > 1 else 0.25
    samples = []
    for sy in range(HEIGHT):
        for sx in range(WIDTH):
            p = floor_point(sx + 0.5, sy + 0.5)
            if p is None:
                continue
            n = floor_point(sx + 1.5, sy + 0.5) or floor_point(sx - 0.5, sy + 0.5)
            if n is None:
                continue
            samples.append((math.hypot(n[0] - p[0], n[1] - p[1]), abs(n[2] - p[2]) / p[2]))
    etas = sorted(e for _, e in samples)
    print("budget %.4f texels, %d covered pixels; eta median %.4f, 90%% %.4f, 99%% %.4f, max %.4f" %
          (budget, len(samples), etas[len(etas) // 2], etas[int(len(etas) * 0.9)], etas[int(len(etas) * 0.99)],
           etas[-1]))
    for kind in ("chord", "parabola", "rational", "rational+p", "rational+p4"):
        hist = {}
        points = 0.0
        for du, eta in samples:
            length = max(1.0, min(256.0, longest(kind, du, eta, budget)))
            length = 2 ** int(math.log2(length))
            hist[length] = hist.get(length, 0) + 1
            points += 1.0 / length
        lengths = " ".join("%d:%d" % (k, hist[k]) for k in sorted(hist))
        print("%-12s %6.0f correction points   pixels by length %s" % (kind, points, lengths))


# Cortex-M4 -O2 instruction counts (qemu -icount, floor_rolled AUTO point
# unless stated): (per segment, per pixel). Affine: subdiv16's walk on the
# floor (exact end ~97, bookkeeping ~75) plus the chooser (~62). Quadratic:
# exact end ~105, chooser ~69, steps and bookkeeping ~205. Rational: the
# same exact end and chooser plus ~75 to derive its constants (estimated);
# per pixel the two passes of rational_span.c, unrolled, by Newton steps.
COSTS = {
    "affine": (235, 7.5),
    "quad": (380, 10.0),
    "rational": (250, {1: 19.5, 2: 23.75, 3: 26.75}),
}
EXACT_PIXEL = 168          # a 1-pixel segment (lean_run, exact point)
SPAN_TOTAL = 166000        # span starts, edges, row set-up of the whole frame
SUBDIV16 = 24.49           # docs/bench/results.csv, floor_rolled subdiv16 point


def rows_of_floor():
    rows = []
    for sy in range(HEIGHT):
        run = [floor_point(sx + 0.5, sy + 0.5) for sx in range(WIDTH)]
        run = [p for p in run if p is not None]
        if run:
            rows.append(run)
    return rows


def segment_stats(run, i, length):
    """q_min, q_max, the largest relative change of q a pixel, the largest
    texel step a pixel and the largest distance from the start, over pixels
    i .. i + length (clipped to the run)."""
    last = min(i + length, len(run) - 1)
    qs = [run[m][2] for m in range(i, last + 1)]
    qmin, qmax = min(qs), max(qs)
    eta = max([abs(qs[m + 1] - qs[m]) for m in range(len(qs) - 1)] or [0.0]) / qmin
    step = max([math.hypot(run[m + 1][0] - run[m][0], run[m + 1][1] - run[m][1]) for m in range(i, last)] or [0.0])
    reach = max(math.hypot(run[m][0] - run[i][0], run[m][1] - run[i][1]) for m in range(i, last + 1))
    return qmin, qmax, eta, step, reach


def fitting_kinds(run, i, length, budget, kinds):
    """(kind, Newton steps) pairs whose bound holds over the segment."""
    if i + 1 >= len(run):
        return [(k, 1) for k in kinds]
    qmin, qmax, eta, step, reach = segment_stats(run, i, length)
    out = []
    if "affine" in kinds and length * length / 4 * step * eta <= budget:
        out.append(("affine", 0))
    if "quad" in kinds and length <= 32 and 0.0482 * length ** 3 * step * eta * eta <= budget:
        out.append(("quad", 0))
    if "rational" in kinds and qmax <= 4 * qmin and reach <= 4096:
        # Newton from the previous pixel's 1/q: relative error <= (2.25 eta)^(2^n)
        for n in (1, 2, 3):
            if reach * ((2.25 * eta) ** (2 ** n) + 2.0 ** -24) <= budget:
                out.append(("rational", n))
                break
    return out


def cost_of(kind, n, pixels):
    per_segment, per_pixel = COSTS[kind]
    if isinstance(per_pixel, dict):
        per_pixel = per_pixel[n]
    return per_segment + per_pixel * pixels


def walk_model(rows, budget, kinds, partition):
    """Modelled M4 instructions of the frame and the segment counts."""
    total, counts = float(SPAN_TOTAL), {}
    for run0 in rows:
        run = run0
        if partition == "aligned-far" and run[-1][2] > run[0][2]:
            run = run0[::-1]   # count the blocks from the end where q is smallest
        i = 0
        while i < len(run):
            cap = 8
            if partition != "greedy" and i:
                cap = min(cap, (i & -i).bit_length() - 1)
            best = (float(EXACT_PIXEL), 1, "exact")
            lengths = range(1, len(run) - i + 1) if partition == "greedy" else [1 << k for k in range(1, cap + 1)]
            for length in lengths:
                if partition == "greedy" and length > 256:
                    break
                px = min(length, len(run) - i)
                fit = fitting_kinds(run, i, length, budget, kinds)
                if not fit and partition == "greedy":
                    break
                for kind, n in fit:
                    c = cost_of(kind, n, px)
                    if c / px < best[0] / best[1]:
                        best = (c, px, kind)
            total += best[0]
            counts[best[2]] = counts.get(best[2], 0) + 1
            i += best[1]
    return total, counts


def walks(budget):
    rows = rows_of_floor()
    pixels = sum(len(r) for r in rows)
    print("\nwalk model: modelled Cortex-M4 instructions a pixel (subdiv16 measures %.2f)" % SUBDIV16)
    for label, kinds, partition in (
            ("renderer today: aligned from the left, chords + parabolas", ("affine", "quad"), "aligned"),
            ("aligned from the far end, chords + parabolas", ("affine", "quad"), "aligned-far"),
            ("greedy from the span start, chords + parabolas", ("affine", "quad"), "greedy"),
            ("aligned from the left, + rational", ("affine", "quad", "rational"), "aligned"),
            ("aligned from the far end, + rational", ("affine", "quad", "rational"), "aligned-far"),
            ("greedy from the span start, + rational", ("affine", "quad", "rational"), "greedy")):
        total, counts = walk_model(rows, budget, kinds, partition)
        segs = " ".join("%s %d" % (k, counts[k]) for k in sorted(counts))
        print("  %-58s %5.1f (%.2f x)   %s" % (label, total / pixels, total / pixels / SUBDIV16, segs))


if __name__ == "__main__":
    main()
    walks(float(sys.argv[1]) if len(sys.argv) > 1 else 0.25)
