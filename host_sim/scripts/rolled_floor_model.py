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
             (docs/design.md, "Open: the rolled floor")
  rational+p the same with a linear predictor, L |u'| 4.8 eta^4, with
             q kept within 2x (or 4x: rational+p4) of the segment's start
             and |delta u| <= 4096 texels (fixed-point range)

It prints, per kind, the covered pixels, the correction points (sum of
1/L over the pixels: one per segment) and how many pixels fall in each
length. A model, not the renderer: the renderer's own division count is
what `fixel-sim --scene floor_rolled --persp auto --depth off` prints.

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


if __name__ == "__main__":
    main()
