/* test_bench.c - the benchmark's own logic (host_sim/lib/bench_lib.c) on
 * cases with known answers: wrap-aware coordinate differences, the analytic
 * bound of affine segments against a brute-force maximum, Pareto-front
 * selection, and the QEMU trace and nm parsers. Nothing here depends on
 * timing. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench_lib.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

void test_wrap_diff_takes_the_short_way_round_the_texture(void)
{
    /* 3.0 texels vs exact 67.0 on a 64-texel side: the same place, one
     * period apart -> 0. */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, bench_wrap_diff(3u << 16, 67.0, 64));
    /* 0.5 vs -0.25: +0.75 (exact below zero, core modular). */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.75, bench_wrap_diff(0x8000u, -0.25, 64));
    /* 63.75 vs 0.25: -0.5 across the seam, not +63.5. */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, -0.5, bench_wrap_diff((63u << 16) + 0xC000u, 0.25, 64));
    /* A core value that wrapped modulo 2^32 (u = -1.0 texel) vs exact
     * -1.0 - 128: two periods of 64 -> 0. */
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 0.0, bench_wrap_diff(0xFFFF0000u, -129.0, 64));
    /* Exactly half a period is reported as -n/2 ([-n/2, n/2)). */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, -32.0, bench_wrap_diff(32u << 16, 0.0, 64));
}

/* u(x) = (a0 + a1 x) / (q0 + q1 x) on one segment [0, L]: the largest gap
 * between u and the chord through its end points, by brute force. */
static double chord_error(double a0, double a1, double q0, double q1, double L)
{
    double u0 = a0 / q0, uL = (a0 + a1 * L) / (q0 + q1 * L), m = 0;
    int i;
    for (i = 0; i <= 100000; i++) {
        double x = L * i / 100000.0;
        double e = fabs((a0 + a1 * x) / (q0 + q1 * x) - (u0 + (uL - u0) * x / L));
        if (e > m)
            m = e;
    }
    return m;
}

static double bound_at(double a0, double a1, double q0, double q1, double x, double L)
{
    double q = q0 + q1 * x, a = a0 + a1 * x;
    double du = (a1 * q - a * q1) / (q * q);   /* u' = (a' q - a q') / q^2 */
    return bench_affine_bound(L, fabs(du), q, q1);
}

/* The brute-force chord error of one segment and the bound taken at the
 * larger of its two ends; msg describes both. */
static void chord_and_bound(double a0, double a1, double q0, double q1, double L, double *e, double *b,
                            char *msg, size_t msg_size)
{
    *b = fmax(bound_at(a0, a1, q0, q1, 0, L), bound_at(a0, a1, q0, q1, L, L));
    *e = chord_error(a0, a1, q0, q1, L);
    snprintf(msg, msg_size, "chord error %.6g, bound %.6g", *e, *b);
}

void test_affine_bound_holds_and_is_tight_for_gentle_perspective(void)
{
    /* Bound from u'' = -2 u' q' / q and the chord error L^2/8 max|u''|.
     * |u' q' / q| is monotonic along a segment here, so the larger end is
     * its maximum. For L q'/q = 16 * 0.002 = 0.032 the curvature changes by
     * about 3 * 3.2 % across the segment, so the brute-force error must be
     * within 10 % below the bound. */
    double e, b;
    char msg[120];
    chord_and_bound(8.0, 0.5, 1.0, -0.002, 16.0, &e, &b, msg, sizeof msg);
    TEST_ASSERT_TRUE_MESSAGE(e <= b, msg);
    TEST_ASSERT_TRUE_MESSAGE(e >= 0.9 * b, msg);
    /* Quadratic in L: doubling L quadruples the bound. */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 4.0, bench_affine_bound(32, 2, 3, 0.5) / bench_affine_bound(16, 2, 3, 0.5));
    /* Constant depth (q' = 0): no error; q <= 0: reported as 0, not inf. */
    TEST_ASSERT_DOUBLE_WITHIN(0, 0.0, bench_affine_bound(64, 5, 1, 0));
    TEST_ASSERT_DOUBLE_WITHIN(0, 0.0, bench_affine_bound(64, 5, 0, 1));
}

void test_affine_bound_holds_for_steep_perspective(void)
{
    /* Far/near ratio 1:5 across one segment: no longer tight, still a bound. */
    double e, b;
    char msg[120];
    chord_and_bound(0.0, 1.0, 1.0, -0.05, 16.0, &e, &b, msg, sizeof msg);
    TEST_ASSERT_TRUE_MESSAGE(e <= b, msg);
}

void test_pareto_front_of_a_known_set(void)
{
    /* (3,4) is beaten by (2,3); (5,1) by (4,1); the duplicate (2,3) pair
     * stays (neither is strictly better); NaN is never on the front. */
    const double x[] = {1, 2, 3, 4, 2, 5, NAN, 0.5};
    const double y[] = {5, 3, 4, 1, 3, 1, 0.1, NAN};
    const uint8_t want[] = {1, 1, 0, 1, 1, 0, 0, 0};
    uint8_t got[8];
    size_t i, n = bench_pareto(x, y, 8, got);
    for (i = 0; i < 8; i++) {
        char msg[64];
        snprintf(msg, sizeof msg, "point %u (%g, %g)", (unsigned)i, x[i], y[i]);
        TEST_ASSERT_EQUAL_INT_MESSAGE(want[i], got[i], msg);
    }
    TEST_ASSERT_EQUAL_INT(4, (int)n);
}

void test_trace_pc_parses_qemu_exec_lines_only(void)
{
    uint32_t pc = 0;
    TEST_ASSERT_EQUAL_INT(1, bench_trace_pc("Trace 0: 0x7f83d4000100 [00800408/0000008c/00000110/ff000201] "
                                            "Reset_Handler\n",
                                            &pc));
    TEST_ASSERT_EQUAL_HEX32(0x8cu, pc);
    TEST_ASSERT_EQUAL_INT(0, bench_trace_pc("IN: fxl_draw_triangle\n", &pc));
    TEST_ASSERT_EQUAL_INT(0, bench_trace_pc("Trace 0: 0x7f83d4000100 [garbage\n", &pc));
    TEST_ASSERT_EQUAL_INT(0, bench_trace_pc("Trace 0: 0x7f83d4000100 [00800408/zz/00000110/ff000201]\n", &pc));
}

static void trace_line(FILE *f, uint32_t pc)
{
    fprintf(f, "Trace 0: 0x7f0000001000 [00000000/%08x/00000110/ff000201] fn\n", (unsigned)pc);
}

void test_trace_count_counts_ranges_between_markers(void)
{
    /* Ranges [0x100, 0x200) and [0x400, 0x404); begin 0x10, end 0x20.
     * Segment 0: 0x100 0x104 0x1fe 0x400 inside, 0x300 and 0x404 outside -> 4.
     * Segment 1: 0x150 -> 1. Then an armed segment with 0x100 that never
     * ends -> unclosed 1. Lines before the first begin never count. */
    const bench_range_t r[2] = {{0x100, 0x200}, {0x400, 0x404}};
    const uint32_t seq[] = {0x100, 0x10, 0x100, 0x104, 0x300, 0x1fe, 0x400, 0x404, 0x20,
                            0x150, 0x10, 0x150, 0x20, 0x10, 0x100};
    uint64_t counts[4] = {0}, unclosed = 99;
    size_t i, n;
    FILE *f = tmpfile();
    TEST_ASSERT_NOT_NULL(f);
    fprintf(f, "IN: something else\n");
    for (i = 0; i < sizeof seq / sizeof seq[0]; i++) {
        trace_line(f, seq[i]);
        if (i == 3) {
            /* a line longer than the parser's buffer is skipped whole */
            int k;
            fputs("Trace 0: 0x1 [00000000/00000100/0/0] ", f);
            for (k = 0; k < 2000; k++)
                fputc('x', f);
            fputc('\n', f);
        }
    }
    rewind(f);
    n = bench_trace_count(f, r, 2, 0x10, 0x20, counts, 4, &unclosed);
    fclose(f);
    TEST_ASSERT_EQUAL_INT(2, (int)n);
    /* the long line carries pc 0x100 inside segment 0: it counts (its
     * head was parsed), so 5 */
    TEST_ASSERT_EQUAL_UINT64(5, counts[0]);
    TEST_ASSERT_EQUAL_UINT64(1, counts[1]);
    TEST_ASSERT_EQUAL_UINT64(1, unclosed);
}

void test_read_nm_keeps_sized_text_symbols_and_markers(void)
{
    char path[] = "/tmp/fxl_test_bench_nmXXXXXX";
    int fd = mkstemp(path);
    FILE *f;
    bench_range_t r[8];
    uint32_t b = 0, e = 0;
    long n;
    TEST_ASSERT_TRUE(fd >= 0);
    f = fdopen(fd, "w");
    TEST_ASSERT_NOT_NULL(f);
    fputs("00000201 00000010 T fxl_draw_triangle\n"   /* Thumb bit set: cleared */
          "00000101 00000008 t seg_point\n"
          "20000000 00000100 B fb\n"                  /* not text */
          "000000e9 00000002 T bench_begin\n"
          "000000ed 00000002 T bench_end\n"
          "00000300 T nosize\n",                      /* no size: skipped */
          f);
    fclose(f);
    n = bench_read_nm(path, r, 8, "bench_begin", &b, "bench_end", &e);
    remove(path);
    TEST_ASSERT_EQUAL_INT(2, (int)n);
    /* sorted by address */
    TEST_ASSERT_EQUAL_HEX32(0x100u, r[0].lo);
    TEST_ASSERT_EQUAL_HEX32(0x108u, r[0].hi);
    TEST_ASSERT_EQUAL_HEX32(0x200u, r[1].lo);
    TEST_ASSERT_EQUAL_HEX32(0x210u, r[1].hi);
    TEST_ASSERT_EQUAL_HEX32(0xE8u, b);
    TEST_ASSERT_EQUAL_HEX32(0xECu, e);
    TEST_ASSERT_EQUAL_INT(-1, (int)bench_read_nm("/nonexistent/fxl_nm", r, 8, NULL, NULL, NULL, NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_wrap_diff_takes_the_short_way_round_the_texture);
    RUN_TEST(test_affine_bound_holds_and_is_tight_for_gentle_perspective);
    RUN_TEST(test_affine_bound_holds_for_steep_perspective);
    RUN_TEST(test_pareto_front_of_a_known_set);
    RUN_TEST(test_trace_pc_parses_qemu_exec_lines_only);
    RUN_TEST(test_trace_count_counts_ranges_between_markers);
    RUN_TEST(test_read_nm_keeps_sized_text_symbols_and_markers);
    return UNITY_END();
}
