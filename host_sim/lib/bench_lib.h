/* bench_lib.h - the testable pieces of the speed-versus-accuracy benchmark
 * (fixel-bench, host side only).
 *
 * - Texel-coordinate error: a core coordinate is a modular uint32 q16 texel
 *   value (repeat wrap); the reference gives the exact unwrapped value in
 *   texels. Their difference is taken modulo the texture side n (a power of
 *   two dividing 2^16) into [-n/2, n/2).
 * - The analytic bound of affine stepping: with u = a / q (a, q linear in x),
 *   u'' = -2 u' q' / q, so the linear interpolant between two exact points L
 *   pixels apart is off by at most L^2 / 8 * max|u''| = L^2 |u'| |q'| / (4 q)
 *   (u' in texels per pixel; |u'| taken as the length of (du/dx, dv/dx)).
 * - Pareto front of (cost, error) points, both to be minimised.
 * - QEMU exec traces (`-d exec,nochain -singlestep`, one line per executed
 *   instruction): "Trace <cpu>: <host ptr> [<cs_base>/<pc>/<flags>/<cflags>] <symbol>".
 *   Counting is armed by an execution of the `begin` address and stops at
 *   the `end` address, which closes a segment (the firmware calls its marker
 *   functions right before and after the draw calls of each configuration);
 *   while armed, lines whose pc lies in one of the half-open ranges count.
 */
#ifndef FXL_HOST_BENCH_LIB_H
#define FXL_HOST_BENCH_LIB_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* Core u (q16 texels, modular) minus exact u (texels), wrapped into
 * [-n/2, n/2) for a side of n texels (n a power of two, 1..65536). */
double bench_wrap_diff(uint32_t core_q16, double exact, uint32_t n);

/* Affine-segment bound in texels for segment length L pixels:
 * L^2 * grad_len * |dq_dx| / (4 * q). 0 when q <= 0. */
double bench_affine_bound(double L, double grad_len, double q, double dq_dx);

/* on_front[i] = 1 when no other point j has x_j <= x_i and y_j <= y_i with
 * at least one strict; equal points are all on the front. Returns how many
 * are on it. NaN points are never on the front and never dominate. */
size_t bench_pareto(const double *x, const double *y, size_t n, uint8_t *on_front);

typedef struct bench_range {
    uint32_t lo, hi;   /* [lo, hi) */
} bench_range_t;

/* Parse one trace line; returns 1 and sets *pc when it is an exec line. */
int bench_trace_pc(const char *line, uint32_t *pc);

/* Count traced instructions inside the ranges from f between each `begin`
 * and the following `end` (the markers themselves are not counted).
 * counts[0 .. max_seg - 1] receive the segments; returns the number of
 * closed segments. *unclosed (may be NULL) gets the count of a segment
 * still armed at the end of the trace (0 if none). */
size_t bench_trace_count(FILE *f, const bench_range_t *ranges, size_t nranges, uint32_t begin,
                         uint32_t end, uint64_t *counts, size_t max_seg, uint64_t *unclosed);

/* Read an `arm-none-eabi-nm -S` listing: text symbols (t/T/w/W) with a size
 * become ranges sorted by address (Thumb bit cleared). Returns the number
 * stored (<= max), or -1 when the file cannot be read. The symbols named
 * begin_name and end_name are not ranges: their addresses go to *begin and
 * *end (left unchanged when absent). */
long bench_read_nm(const char *path, bench_range_t *ranges, size_t max, const char *begin_name,
                   uint32_t *begin, const char *end_name, uint32_t *end);

#endif
