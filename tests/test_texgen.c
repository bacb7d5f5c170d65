/* tests/test_texgen.c - texture-coordinate generation (src/texgen.c) against
 * double precision: planar, cylindrical, spherical, cube map, seams, poles.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "unity.h"
#include "test_rng.h"
#include "fixel/pipeline.h"

void setUp(void) {}
void tearDown(void) {}

static const double TWO_PI = 6.283185307179586476925286766559;
static char msg[256];
static fxl_q16_t dq16(double v) { return (fxl_q16_t)lround(v * 65536.0); }
static double q16d(fxl_q16_t v) { return v / 65536.0; }

/* difference modulo one period, in (-0.5, 0.5] */
static double wrap_diff(double a, double b)
{
    double d = fmod(a - b, 1.0);
    if (d > 0.5) d -= 1;
    if (d <= -0.5) d += 1;
    return d;
}

static fxl_vec3_t vec(double x, double y, double z)
{
    fxl_vec3_t v;
    v.x = dq16(x); v.y = dq16(y); v.z = dq16(z);
    return v;
}

static void test_planar_uses_chosen_plane_with_scale_and_offset(void)
{
    fxl_texgen_t tg;
    fxl_vec3_t p[3] = {vec(1, 2, 3), vec(-0.5, 0.25, 4), vec(0, 0, 0)};
    fxl_texcoord_t t[3];
    fxl_texgen_defaults(&tg);
    tg.mode = FXL_TEXGEN_PLANAR;
    tg.scale_u = dq16(2); tg.offset_u = dq16(0.5);
    tg.scale_v = dq16(0.25); tg.offset_v = dq16(-1);
    tg.plane = FXL_PLANE_XY;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
    TEST_ASSERT_EQUAL_INT32(dq16(2.5), t[0].u);     /* 2 * 1 + 0.5 */
    TEST_ASSERT_EQUAL_INT32(dq16(-0.5), t[0].v);    /* 0.25 * 2 - 1 */
    TEST_ASSERT_EQUAL_INT32(dq16(-0.5), t[1].u);
    tg.plane = FXL_PLANE_YZ;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
    TEST_ASSERT_EQUAL_INT32(dq16(4.5), t[0].u);     /* y */
    TEST_ASSERT_EQUAL_INT32(dq16(-0.25), t[0].v);   /* z */
    tg.plane = FXL_PLANE_XZ;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
    TEST_ASSERT_EQUAL_INT32(dq16(2.5), t[0].u);
    TEST_ASSERT_EQUAL_INT32(dq16(0), t[1].v);       /* 0.25 * 4 - 1 */
}

/* (a, b, h) as documented for each axis */
static void frame(int axis, const double p[3], double *a, double *b, double *h)
{
    if (axis == FXL_AXIS_X) { *a = p[1]; *b = p[2]; *h = p[0]; }
    else if (axis == FXL_AXIS_Y) { *a = p[2]; *b = p[0]; *h = p[1]; }
    else { *a = p[0]; *b = p[1]; *h = p[2]; }
}

static void check_polar(int mode)
{
    fxl_texgen_t tg;
    double max_u = 0, max_v = 0;
    int i;
    fxl_texgen_defaults(&tg);
    tg.mode = (uint8_t)mode;
    rng_seed(17 + mode);
    for (i = 0; i < 20000; i++) {
        fxl_vec3_t p[3];
        fxl_texcoord_t t[3];
        double c[3], r = pow(10.0, rng_range(-2.7, 2)), th = rng_range(0, TWO_PI), ph = rng_range(0.05, 3.09);
        int k;
        tg.axis = (uint8_t)(i % 3);
        /* a small triangle around one point: no seam inside, no pole */
        for (k = 0; k < 3; k++) {
            double tk = th + 0.01 * k, pk = ph + 0.005 * (k == 2);
            double a = r * sin(pk) * cos(tk), b = r * sin(pk) * sin(tk), h = r * cos(pk);
            if (tg.axis == FXL_AXIS_X) { c[1] = a; c[2] = b; c[0] = h; }
            else if (tg.axis == FXL_AXIS_Y) { c[2] = a; c[0] = b; c[1] = h; }
            else { c[0] = a; c[1] = b; c[2] = h; }
            p[k] = vec(c[0], c[1], c[2]);
        }
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
        for (k = 0; k < 3; k++) {
            double q[3] = {q16d(p[k].x), q16d(p[k].y), q16d(p[k].z)}, a, b, h, wu, wv, eu, ev;
            frame(tg.axis, q, &a, &b, &h);
            wu = atan2(b, a) / TWO_PI;
            wv = mode == FXL_TEXGEN_SPHERICAL ? atan2(sqrt(a * a + b * b), h) / (TWO_PI / 2) : h;
            eu = fabs(wrap_diff(q16d(t[k].u), wu)) * 65536;
            ev = fabs(q16d(t[k].v) - wv) * 65536;
            if (eu > max_u) max_u = eu;
            if (ev > max_v) max_v = ev;
            /* u: atan2 rounding 0.5 LSB + CORDIC 2^-11 LSB. v (spherical):
             * the same, and r's floored square root of a, b scaled to
             * 2^29..2^30: 2^-29 rad / pi = 4e-5 LSB, whatever |p| (0.002
             * to 100 here; unscaled it was 2^-16 / |p| rad: 31 LSB at
             * 0.01). Cylindrical v = h exactly. */
            if (eu > 0.5 + ldexp(1, -10) || ev > (mode == FXL_TEXGEN_SPHERICAL ? 0.5 + ldexp(1, -9) : 0)) {
                snprintf(msg, sizeof msg, "mode %d axis %d point (%g %g %g): u err %.3f v err %.3f LSB",
                         mode, tg.axis, q[0], q[1], q[2], eu, ev);
                TEST_FAIL_MESSAGE(msg);
            }
        }
    }
    printf("texgen mode %d: max u error %.3f LSB, v %.3f LSB\n", mode, max_u, max_v);
}

static void test_cylindrical_matches_double(void) { check_polar(FXL_TEXGEN_CYLINDRICAL); }
static void test_spherical_matches_double(void) { check_polar(FXL_TEXGEN_SPHERICAL); }

/* Point on the unit circle around Y at theta (turns), height y. */
static fxl_vec3_t around_y(double turns, double y)
{
    return vec(sin(TWO_PI * turns), y, cos(TWO_PI * turns)); /* a = z, b = x */
}

static void test_seam_triangle_does_not_span_whole_texture(void)
{
    fxl_texgen_t tg;
    fxl_vec3_t p[3];
    fxl_texcoord_t t[3];
    double want[3] = {0.98, 0.02, 0.99}, lo = 1e9, hi = -1e9;
    int k, mode;
    for (mode = FXL_TEXGEN_CYLINDRICAL; mode <= FXL_TEXGEN_SPHERICAL; mode++) {
        fxl_texgen_defaults(&tg);
        tg.mode = (uint8_t)mode;
        for (k = 0; k < 3; k++) p[k] = around_y(want[k], 0.1 * k);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
        lo = 1e9; hi = -1e9;
        for (k = 0; k < 3; k++) {
            double u = q16d(t[k].u);
            /* the same place of a repeating texture */
            TEST_ASSERT_DOUBLE_WITHIN(1.0 / 65536, 0, wrap_diff(u, want[k]));
            if (u < lo) lo = u;
            if (u > hi) hi = u;
        }
        /* without the fix the span would be 0.97; with it 0.04 */
        snprintf(msg, sizeof msg, "mode %d: u span %.4f", mode, hi - lo);
        TEST_ASSERT_TRUE_MESSAGE(hi - lo < 0.05, msg);
        /* with a scale the period scales too */
        tg.scale_u = FXL_Q16_INT(4);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
        TEST_ASSERT_INT32_WITHIN(4, dq16(0.16) + t[0].u, t[1].u);
    }
}

/* The seam shift takes the shortest arrangement of the three u's: 0.5,
 * 0.75, 0 becomes 0.5, 0.75, 1 (span 0.5), not 0.5, 0.75, 0 (0.75, what
 * shifting each to within half a period of the first gave: a cap
 * triangle of a four-sided prism). Random triples: the span is the least
 * over the circle's cuts, each u stays at its place of the texture, and
 * the first vertex's u is its own theta. */
static void test_seam_takes_the_shortest_span(void)
{
    fxl_texgen_t tg;
    fxl_vec3_t p[3];
    fxl_texcoord_t t[3];
    int i, k, j;
    fxl_texgen_defaults(&tg);
    tg.mode = FXL_TEXGEN_CYLINDRICAL;
    rng_seed(5505);
    for (i = 0; i < 5000; i++) {
        double want[3], best = 2, lo = 1e9, hi = -1e9;
        for (k = 0; k < 3; k++) {
            want[k] = i == 0 ? (k == 0 ? 0.5 : k == 1 ? 0.75 : 0.0) : rng_range(0, 1);
            p[k] = around_y(want[k], 0.1 * k);
        }
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
        for (k = 0; k < 3; k++) {
            /* cutting the circle just below vertex k's angle */
            double l2 = 1e9, h2 = -1e9;
            for (j = 0; j < 3; j++) {
                double a = want[j] - want[k];
                a -= floor(a);
                if (a < l2) l2 = a;
                if (a > h2) h2 = a;
            }
            if (h2 - l2 < best) best = h2 - l2;
        }
        for (k = 0; k < 3; k++) {
            const double u = q16d(t[k].u);
            TEST_ASSERT_DOUBLE_WITHIN(2.0 / 65536, 0, wrap_diff(u, want[k]));
            if (u < lo) lo = u;
            if (u > hi) hi = u;
        }
        /* the first vertex keeps its own theta */
        TEST_ASSERT_DOUBLE_WITHIN(2.0 / 65536, want[0], q16d(t[0].u));
        snprintf(msg, sizeof msg, "triple %d (%.4f %.4f %.4f): span %.4f, shortest %.4f", i, want[0], want[1],
                 want[2], hi - lo, best);
        TEST_ASSERT_TRUE_MESSAGE(hi - lo <= best + 3.0 / 65536, msg);
    }
}

static void test_pole_takes_mean_theta_of_other_vertices(void)
{
    fxl_texgen_t tg;
    fxl_vec3_t p[3];
    fxl_texcoord_t t[3];
    fxl_texgen_defaults(&tg);
    tg.mode = FXL_TEXGEN_SPHERICAL;
    tg.axis = FXL_AXIS_Y;
    p[0] = vec(0, 1, 0); /* north pole */
    p[1] = around_y(0.10, 0.9);
    p[2] = around_y(0.20, 0.9);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
    /* mean of 0.10 and 0.20 (each within 0.5 LSB + rounding of the mean) */
    TEST_ASSERT_INT32_WITHIN(1, dq16(0.15), t[0].u);
    TEST_ASSERT_EQUAL_INT32(0, t[0].v); /* phi = 0 at +y */
    /* pole between vertices across the seam: 0.95 and 0.05 -> 1.0 */
    p[1] = around_y(0.95, 0.9);
    p[2] = around_y(0.05, 0.9);
    p[0] = vec(0, -2, 0); /* south pole */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
    TEST_ASSERT_DOUBLE_WITHIN(2.0 / 65536, 0, wrap_diff(q16d(t[0].u), 0.0));
    TEST_ASSERT_TRUE(fabs(q16d(t[0].u) - q16d(t[1].u)) < 0.06);
    TEST_ASSERT_TRUE(fabs(q16d(t[0].u) - q16d(t[2].u)) < 0.06);
    TEST_ASSERT_EQUAL_INT32(65536, t[0].v); /* phi = 180 deg */
    /* cylinder cap centre (on the axis at h = 0) is a pole too */
    tg.mode = FXL_TEXGEN_CYLINDRICAL;
    p[0] = vec(0, 0, 0);
    p[1] = around_y(0.30, 0);
    p[2] = around_y(0.40, 0);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
    TEST_ASSERT_INT32_WITHIN(1, dq16(0.35), t[0].u);
}

/* A cylinder's theta is atan2(b, a) at any height: a ring far up a tall
 * cylinder keeps its u (the sphere's pole rule, r <= 2^-10 |h|, set every
 * vertex of a ring above 1024 radii to u = 0). Up to the cylinder's own
 * rule, r 2^14 > |h| + 1: each u within the atan2 bound of check_polar,
 * v = h exactly, on every axis and on both sides of h = 0. */
static void test_tall_cylinder_keeps_its_theta(void)
{
    static const double ring[][2] = {   /* {r, h} */
        {1, 1030}, {1, 5000}, {1, 16000}, {0.1, 103}, {0.1, 1600}, {0.01, 11}, {0.01, 160},
    };
    static const double turns[3] = {0.10, 0.20, 0.15};
    fxl_texgen_t tg;
    double max_u = 0;
    size_t i;
    int axis, sign, k;
    fxl_texgen_defaults(&tg);
    tg.mode = FXL_TEXGEN_CYLINDRICAL;
    for (axis = 0; axis < 3; axis++)
        for (sign = -1; sign <= 1; sign += 2)
            for (i = 0; i < sizeof ring / sizeof ring[0]; i++) {
                fxl_vec3_t p[3];
                fxl_texcoord_t t[3];
                tg.axis = (uint8_t)axis;
                for (k = 0; k < 3; k++) {
                    const double a = ring[i][0] * cos(TWO_PI * turns[k]), b = ring[i][0] * sin(TWO_PI * turns[k]);
                    const double h = sign * ring[i][1];
                    if (axis == FXL_AXIS_X) p[k] = vec(h, a, b);
                    else if (axis == FXL_AXIS_Y) p[k] = vec(b, h, a);
                    else p[k] = vec(a, b, h);
                }
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
                for (k = 0; k < 3; k++) {
                    double q[3] = {q16d(p[k].x), q16d(p[k].y), q16d(p[k].z)}, a, b, h, eu;
                    frame(axis, q, &a, &b, &h);
                    eu = fabs(wrap_diff(q16d(t[k].u), atan2(b, a) / TWO_PI)) * 65536;
                    if (eu > max_u) max_u = eu;
                    if (eu > 0.5 + ldexp(1, -10) || t[k].v != dq16(h)) {
                        snprintf(msg, sizeof msg, "axis %d r %g h %g vertex %d: u %.6f (err %.3f LSB), v %.6f",
                                 axis, ring[i][0], h, k, q16d(t[k].u), eu, q16d(t[k].v));
                        TEST_FAIL_MESSAGE(msg);
                    }
                }
            }
    printf("tall cylinder: max u error %.3f LSB\n", max_u);
}

/* u, v of vertex p0 of a triangle whose other two vertices are 1 unit
 * from the Y axis at h units, 0.30 and 0.40 turns round it (mean 0.35),
 * under texgen `mode` about Y. */
static fxl_texcoord_t pole_test_vertex(int mode, fxl_vec3_t p0, double h)
{
    fxl_texgen_t tg;
    fxl_vec3_t p[3];
    fxl_texcoord_t t[3];
    fxl_texgen_defaults(&tg);
    tg.mode = (uint8_t)mode;
    tg.axis = FXL_AXIS_Y;
    p[0] = p0;
    p[1] = around_y(0.30, h);
    p[2] = around_y(0.40, h);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
    return t[0];
}

/* A cylinder's pole: within 2^-14 (|h| + 1) of the axis, where the q16
 * rounding of an eye-space transform can put a point on it (a cap's
 * centre). It takes the mean theta of the other two (0.35 turns here);
 * just outside, a vertex keeps its own. */
static void test_cylinder_pole_is_within_rounding_of_the_axis(void)
{
    static const struct { int32_t a, b; double h; int pole; } c[] = {
        {0, 0, 1000, 1},     {3, -2, 0, 1},        {4, 0, 0, 1},       {5, 0, 0, 0},
        {0, -3, 0.5, 1},     {-2, 2, 1000, 1},     {3277, 0, 1000, 1}, /* 0.05: 2^-14 1001 = 0.061 */
        {4588, 0, 1000, 0},  /* 0.07 */            {0, 4588, -1000, 0},
    };
    size_t i;
    for (i = 0; i < sizeof c / sizeof c[0]; i++) {
        fxl_vec3_t p0;
        fxl_texcoord_t t[1];
        double want;
        p0.x = c[i].b;   /* axis Y: a = z, b = x */
        p0.y = dq16(c[i].h);
        p0.z = c[i].a;
        t[0] = pole_test_vertex(FXL_TEXGEN_CYLINDRICAL, p0, c[i].h);
        want = c[i].pole ? 0.35 : atan2((double)c[i].b, (double)c[i].a) / TWO_PI;
        if (fabs(wrap_diff(q16d(t[0].u), want)) * 65536 > 1.0) {
            snprintf(msg, sizeof msg, "(a %d, b %d) units at h %g: u %.6f, want %.6f (%s)", (int)c[i].a,
                     (int)c[i].b, c[i].h, q16d(t[0].u), want, c[i].pole ? "a pole" : "its own theta");
            TEST_FAIL_MESSAGE(msg);
        }
    }
}

/* The cylinder's pole rule, r <= 2^-14 (|h| + 1), decided to a quarter of
 * a q16 unit far up the axis too (positions scaled up before the square
 * root). At h = 3071 units the limit is 3072 / 16384 = 0.1875 units =
 * 12288 q16; a vertex at (a, b) = (12288, 100) q16 is 12288.41 q16 from
 * the axis, just outside: it keeps its own theta, atan2(100, 12288) =
 * 84.88 LSB, not the others' mean (0.35 turns). r floored to whole q16
 * units there (12288) would make it a pole. */
static void test_cylinder_pole_limit_far_up_the_axis(void)
{
    const int32_t h = 3 * (1 << 26) - (1 << 16);   /* 3071 units */
    fxl_vec3_t p0;
    fxl_texcoord_t t[1];
    double want;
    p0.x = 100;   /* axis Y: a = z, b = x */
    p0.y = h;
    p0.z = 12288;
    t[0] = pole_test_vertex(FXL_TEXGEN_CYLINDRICAL, p0, q16d(h));
    want = atan2(100.0, 12288.0) / TWO_PI * 65536;
    snprintf(msg, sizeof msg, "u %ld, want %.3f (its own theta)", (long)t[0].u, want);
    TEST_ASSERT_TRUE_MESSAGE(fabs(t[0].u - want) <= 0.5 + ldexp(1, -10), msg);
    TEST_ASSERT_EQUAL_INT32(h, t[0].v);
}

/* The sphere's pole rule, r <= 2^-10 |h| (docs/pipeline.md; within 2^-10
 * rad of the axis), at its edge: at h = 1024 units a vertex 1 unit from
 * the axis is a pole (the mean theta of the others, 0.35 turns), one 1.5
 * units away is not (its own theta, 0.25 turns: a = 0, b > 0). */
static void test_sphere_pole_limit_is_two_to_minus_10(void)
{
    static const struct { int32_t r; int pole; } c[] = {{65536, 1}, {98304, 0}};
    size_t i;
    for (i = 0; i < sizeof c / sizeof c[0]; i++) {
        fxl_vec3_t p0;
        fxl_texcoord_t t[1];
        p0.x = c[i].r;
        p0.y = 1024 << 16;
        p0.z = 0;
        t[0] = pole_test_vertex(FXL_TEXGEN_SPHERICAL, p0, 0.9);
        snprintf(msg, sizeof msg, "r %ld at h 1024 units: u %ld (%s)", (long)c[i].r, (long)t[0].u,
                 c[i].pole ? "a pole" : "its own theta");
        TEST_ASSERT_TRUE_MESSAGE(c[i].pole ? labs((long)t[0].u - (long)dq16(0.35)) <= 1 : t[0].u == 16384, msg);
    }
}

/* Seam ties: with u = 0, 3/8, 5/8 turns (exact from atan2: the points are
 * on the axes and diagonals) the gap across the period (3/8) equals the
 * widest inner one (0 -> 3/8). Either cut spans 5/8; texgen.c takes the
 * one across the period first, which leaves the u's as atan2 gives them,
 * in [0, 1]. */
static void test_seam_tie_leaves_the_u_in_place(void)
{
    fxl_texgen_t tg;
    fxl_vec3_t p[3];
    fxl_texcoord_t t[3];
    fxl_texgen_defaults(&tg);
    tg.mode = FXL_TEXGEN_CYLINDRICAL;
    tg.axis = FXL_AXIS_Y;   /* a = z, b = x */
    p[0] = vec(0, 0, 1);           /* theta 0 */
    p[1] = vec(0.7, 0, -0.7);      /* 3/8 */
    p[2] = vec(-0.7, 0, -0.7);     /* 5/8 */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
    TEST_ASSERT_EQUAL_INT32(0, t[0].u);
    TEST_ASSERT_EQUAL_INT32(24576, t[1].u);
    TEST_ASSERT_EQUAL_INT32(40960, t[2].u);
}

/* A triangle wholly at the pole (every vertex within 2^-10 rad of the
 * axis) has no theta at all: it gets one u at every corner, 0 (as for the
 * triangle on the axis in test_texgen_rejects_bad_arguments), not the
 * vertices' own thetas, here 1/4, 1/2 and 3/4 turn apart on a triangle one
 * q16 unit across. */
static void test_triangle_wholly_at_the_pole_gets_one_u(void)
{
    fxl_texgen_t tg;
    fxl_vec3_t p[3];
    fxl_texcoord_t t[3];
    int k;
    fxl_texgen_defaults(&tg);
    tg.mode = FXL_TEXGEN_SPHERICAL;
    tg.axis = FXL_AXIS_Y;   /* a = z, b = x */
    p[0].x = 1;  p[0].y = FXL_Q16_ONE; p[0].z = 0;    /* theta 1/4 */
    p[1].x = 0;  p[1].y = FXL_Q16_ONE; p[1].z = -1;   /* 1/2 */
    p[2].x = -1; p[2].y = FXL_Q16_ONE; p[2].z = 0;    /* 3/4 */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
    for (k = 0; k < 3; k++)
        TEST_ASSERT_EQUAL_INT32(0, t[k].u);
}

/* Cube map, a vertex on its face's plane (major coordinate 0, here x = 0
 * on face +X, chosen by the triangle's sum): texgen.c takes |major| as one
 * q16 unit there (a vertex behind the face plane clamps the same way), so
 * sc = -z = 2^-16 and tc = -y = -2^-16 give s = (1 + 1) / 2 = 1, t = 0:
 * the tile's edge, u = round(65536 / 3) = 21845, v = 0. The others, on
 * the x axis, map to the tile's centre: u = round(32768 / 3) = 10923, v =
 * 16384. */
static void test_cube_vertex_on_the_face_plane_maps_to_the_tile_edge(void)
{
    fxl_texgen_t tg;
    fxl_vec3_t p[3];
    fxl_texcoord_t t[3];
    fxl_texgen_defaults(&tg);
    tg.mode = FXL_TEXGEN_CUBE;
    p[0].x = 0; p[0].y = 1; p[0].z = -1;
    p[1] = vec(3, 0, 0);
    p[2] = p[1];
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
    TEST_ASSERT_EQUAL_INT32(21845, t[0].u);
    TEST_ASSERT_EQUAL_INT32(0, t[0].v);
    TEST_ASSERT_EQUAL_INT32(10923, t[1].u);
    TEST_ASSERT_EQUAL_INT32(16384, t[1].v);
}

static void test_cube_faces_and_atlas_layout(void)
{
    /* face centres: (major axis direction, face index) */
    static const double dir[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    fxl_texgen_t tg;
    double max_err = 0;
    int f, i;
    fxl_texgen_defaults(&tg);
    tg.mode = FXL_TEXGEN_CUBE;
    for (f = 0; f < 6; f++) {
        fxl_vec3_t p[3];
        fxl_texcoord_t t[3];
        p[0] = vec(dir[f][0] * 2, dir[f][1] * 2, dir[f][2] * 2);
        p[1] = p[0]; p[2] = p[0];
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
        /* centre of tile (f % 3, f / 3) in the 3x2 atlas */
        TEST_ASSERT_INT32_WITHIN(1, dq16(((f % 3) + 0.5) / 3), t[0].u);
        TEST_ASSERT_INT32_WITHIN(1, dq16(((f / 3) + 0.5) / 2), t[0].v);
    }
    /* random small triangles on the faces of a cube of half-size 3 */
    rng_seed(5);
    for (i = 0; i < 6000; i++) {
        fxl_vec3_t p[3];
        fxl_texcoord_t t[3];
        double c[3][3];
        int k, ax, sg;
        f = i % 6; ax = f / 2; sg = (f % 2) ? -1 : 1;
        for (k = 0; k < 3; k++) {
            int j;
            for (j = 0; j < 3; j++) c[k][j] = rng_range(-2.9, 2.9);
            c[k][ax] = 3 * sg;
            p[k] = vec(c[k][0], c[k][1], c[k][2]);
        }
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
        for (k = 0; k < 3; k++) {
            double x = q16d(p[k].x), y = q16d(p[k].y), z = q16d(p[k].z), ma, sc, tc, wu, wv, e;
            switch (f) {
            case 0: ma = x; sc = -z; tc = -y; break;
            case 1: ma = -x; sc = z; tc = -y; break;
            case 2: ma = y; sc = x; tc = z; break;
            case 3: ma = -y; sc = x; tc = -z; break;
            case 4: ma = z; sc = x; tc = -y; break;
            default: ma = -z; sc = -x; tc = -y; break;
            }
            wu = ((f % 3) + (sc / ma + 1) / 2) / 3;
            wv = ((f / 3) + (tc / ma + 1) / 2) / 2;
            e = fmax(fabs(q16d(t[k].u) - wu), fabs(q16d(t[k].v) - wv)) * 65536;
            if (e > max_err) max_err = e;
            /* s, t are rounded (0.5 LSB) and then divided by 3 (u) or 2 (v)
             * with rounding: u <= 0.5 / 3 + 1 / 3 = 0.5 LSB, v <= 0.25 +
             * 0.5 = 0.75 LSB. */
            if (e > 0.75 + 1e-9) {
                snprintf(msg, sizeof msg, "face %d vertex %d: error %.3f LSB", f, k, e);
                TEST_FAIL_MESSAGE(msg);
            }
        }
    }
    printf("cube map max error %.3f LSB\n", max_err);
}

static void test_texgen_rejects_bad_arguments(void)
{
    fxl_texgen_t tg;
    fxl_vec3_t p[3];
    fxl_texcoord_t t[3];
    memset(p, 0, sizeof p);
    fxl_texgen_defaults(&tg);
    tg.mode = 9;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texgen_triangle(&tg, p, t));
    tg.mode = FXL_TEXGEN_CUBE + 1;   /* one past each limit too */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texgen_triangle(&tg, p, t));
    tg.mode = FXL_TEXGEN_SPHERICAL;
    tg.space = FXL_TEXGEN_EYE + 1;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texgen_triangle(&tg, p, t));
    tg.space = FXL_TEXGEN_OBJECT;
    tg.plane = FXL_PLANE_XZ + 1;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texgen_triangle(&tg, p, t));
    tg.plane = FXL_PLANE_XY;
    tg.axis = 3;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texgen_triangle(&tg, p, t));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texgen_triangle(NULL, p, t));
    /* all three on the axis: defined output, no division by zero */
    tg.axis = FXL_AXIS_Y;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
    TEST_ASSERT_EQUAL_INT32(0, t[0].u);
}

/* Ties of the major axis (|sum x| = |sum y| >= |sum z|, a triangle centred
 * on a cube edge) go to the first axis in face order, x before y before z
 * (texgen.c cube), so the same mesh gets the same atlas tile on every
 * build. Centred on the x = y edge: face +X, tile (0, 0); on y = z: +Y,
 * tile (2, 0); on x = -z: +X again. */
static void test_cube_major_axis_ties_take_the_first_axis(void)
{
    static const double c[3][3] = {{2, 2, 0.5}, {0.5, 2, 2}, {2, 0.5, -2}};
    static const int face[3] = {FXL_CUBE_POS_X, FXL_CUBE_POS_Y, FXL_CUBE_POS_X};
    fxl_texgen_t tg;
    int k, i;
    fxl_texgen_defaults(&tg);
    tg.mode = FXL_TEXGEN_CUBE;
    for (k = 0; k < 3; k++) {
        fxl_vec3_t p[3];
        fxl_texcoord_t t[3];
        /* three vertices around the centre, symmetric so the sums tie exactly */
        p[0] = vec(c[k][0], c[k][1], c[k][2]);
        p[1] = vec(c[k][0] + 0.25, c[k][1] + 0.25, c[k][2] + 0.25 * (k == 2 ? -1 : 1));
        p[2] = vec(c[k][0] - 0.25, c[k][1] - 0.25, c[k][2] - 0.25 * (k == 2 ? -1 : 1));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texgen_triangle(&tg, p, t));
        for (i = 0; i < 3; i++) {
            snprintf(msg, sizeof msg, "edge %d vertex %d: u %ld v %ld not in tile %d", k, i, (long)t[i].u,
                     (long)t[i].v, face[k]);
            TEST_ASSERT_TRUE_MESSAGE(t[i].u >= dq16((face[k] % 3) / 3.0) - 1 && t[i].u <= dq16((face[k] % 3 + 1) / 3.0) + 1 &&
                                         t[i].v >= dq16((face[k] / 3) / 2.0) - 1 && t[i].v <= dq16((face[k] / 3 + 1) / 2.0) + 1,
                                     msg);
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_planar_uses_chosen_plane_with_scale_and_offset);
    RUN_TEST(test_cylindrical_matches_double);
    RUN_TEST(test_spherical_matches_double);
    RUN_TEST(test_seam_triangle_does_not_span_whole_texture);
    RUN_TEST(test_seam_takes_the_shortest_span);
    RUN_TEST(test_pole_takes_mean_theta_of_other_vertices);
    RUN_TEST(test_tall_cylinder_keeps_its_theta);
    RUN_TEST(test_cylinder_pole_is_within_rounding_of_the_axis);
    RUN_TEST(test_cylinder_pole_limit_far_up_the_axis);
    RUN_TEST(test_sphere_pole_limit_is_two_to_minus_10);
    RUN_TEST(test_seam_tie_leaves_the_u_in_place);
    RUN_TEST(test_triangle_wholly_at_the_pole_gets_one_u);
    RUN_TEST(test_cube_faces_and_atlas_layout);
    RUN_TEST(test_cube_major_axis_ties_take_the_first_axis);
    RUN_TEST(test_cube_vertex_on_the_face_plane_maps_to_the_tile_edge);
    RUN_TEST(test_texgen_rejects_bad_arguments);
    return UNITY_END();
}
