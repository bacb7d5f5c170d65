/* tests/test_reference.c - the double-precision reference renderer
 * (host_sim/lib/reference.c) against hand-computed cases. Everything the
 * metrics report rests on this file. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "test_features.h"
#include "reference.h"

void setUp(void) {}
void tearDown(void) {}

#define PX(v) ((fxl_q16_t)((v) * 65536.0)) /* pixels (exact for multiples of 2^-16) */
#define K20 (1u << 20)                       /* an inv_w scale */

static fxl_vertex_t vtx(double x, double y, uint32_t inv_w, double u, double v)
{
    fxl_vertex_t r;
    memset(&r, 0, sizeof(r));
    r.x = PX(x);
    r.y = PX(y);
    r.inv_w = inv_w;
    r.u = (fxl_q16_t)(u * 65536.0);
    r.v = (fxl_q16_t)(v * 65536.0);
    r.color = 0xFFFFu;
    return r;
}

static void tri3(fxl_vertex_t t[3], double x0, double y0, double x1, double y1, double x2,
                 double y2)
{
    t[0] = vtx(x0, y0, K20, 0, 0);
    t[1] = vtx(x1, y1, K20, 0, 0);
    t[2] = vtx(x2, y2, K20, 0, 0);
}

/* ---- snapping -------------------------------------------------------------- */

void test_snap_rounds_to_nearest_sixteenth_ties_up(void)
{
    TEST_NEEDS_DEFAULT_GRID();
    /* one grid unit = 1/16 px = 4096 in q16; half a unit = 2048 */
    TEST_ASSERT_EQUAL_INT32(8, ref_snap(PX(0.5)));
    TEST_ASSERT_EQUAL_INT32(8, ref_snap(PX(0.5) + 2047));   /* below the tie */
    TEST_ASSERT_EQUAL_INT32(9, ref_snap(PX(0.5) + 2048));   /* tie -> +inf */
    TEST_ASSERT_EQUAL_INT32(0, ref_snap(-2048));            /* tie -> +inf, toward 0 */
    TEST_ASSERT_EQUAL_INT32(-1, ref_snap(-2049));
    TEST_ASSERT_EQUAL_INT32(-16, ref_snap(PX(-1.0)));
    /* INT32_MAX = 32768 px - 2^-16: (2^31 - 1 + 2048) / 4096 floors to 2^19 */
    TEST_ASSERT_EQUAL_INT32(524288, ref_snap(INT32_MAX));
    TEST_ASSERT_EQUAL_INT32(-524288, ref_snap(INT32_MIN));
}

void test_snap_equals_core_snap(void)
{
    /* The reference keeps its own copy of the snap (so it does not trust the
     * core); both must agree everywhere: a sweep around every tie of the
     * first grid units plus strided values over the whole int32 range. */
    char msg[64];
    int64_t x;
    for (x = -70000; x <= 70000; ++x) {
        if (ref_snap((fxl_q16_t)x) != fxl_snap_subpx((fxl_q16_t)x)) {
            snprintf(msg, sizeof msg, "x = %lld", (long long)x);
            TEST_FAIL_MESSAGE(msg);
        }
    }
    for (x = INT32_MIN; x <= INT32_MAX; x += 65537 * 31) {
        if (ref_snap((fxl_q16_t)x) != fxl_snap_subpx((fxl_q16_t)x)) {
            snprintf(msg, sizeof msg, "x = %lld", (long long)x);
            TEST_FAIL_MESSAGE(msg);
        }
    }
    TEST_ASSERT_EQUAL_INT32(fxl_snap_subpx(INT32_MAX), ref_snap(INT32_MAX));
}

/* ---- coverage: the four right triangles -------------------------------------- */

/* Expected sets for the right triangles with legs of 4 px through pixel centres
 * (vertices on centres, so many centres lie exactly on edges), derived from the
 * rule (y grows downward):
 * T1 (0.5,0.5) (4.5,0.5) (0.5,4.5): top edge y=0.5 and left edge x=0.5 are
 *    included, the diagonal x+y=5 has the triangle on its left (a right edge):
 *    excluded -> i >= 0, j >= 0, i + j <= 3 (10 px).
 * T2 (4.5,0.5) (0.5,0.5) (4.5,4.5): top edge included, right edge x=4.5
 *    excluded, diagonal y=x with the triangle to its right (left edge)
 *    included -> 0 <= j <= i <= 3 (10 px).
 * T3 (0.5,4.5) (4.5,4.5) (0.5,0.5): bottom edge y=4.5 excluded, left edge
 *    included, diagonal y=x with the triangle to its left excluded
 *    -> 0 <= i < j <= 3 (6 px).
 * T4 (4.5,4.5) (0.5,4.5) (4.5,0.5): bottom and right excluded, diagonal
 *    x+y=5 with the triangle to its right included -> i, j <= 3, i + j >= 4
 *    (6 px).
 * Together their edges take all eight directions (two horizontal, two
 * vertical, four diagonal). */
static int expect_t(int which, int i, int j)
{
    if (i < 0 || j < 0 || i > 4 || j > 4) return 0;
    switch (which) {
    case 1: return i + j <= 3;
    case 2: return j <= i && i <= 3;
    case 3: return i < j && j <= 3;
    default: return i <= 3 && j <= 3 && i + j >= 4;
    }
}

static void make_t(int which, fxl_vertex_t t[3])
{
    switch (which) {
    case 1: tri3(t, 0.5, 0.5, 4.5, 0.5, 0.5, 4.5); break;
    case 2: tri3(t, 4.5, 0.5, 0.5, 0.5, 4.5, 4.5); break;
    case 3: tri3(t, 0.5, 4.5, 4.5, 4.5, 0.5, 0.5); break;
    default: tri3(t, 4.5, 4.5, 0.5, 4.5, 4.5, 0.5); break;
    }
}

void test_fill_rule_right_triangles_all_eight_edge_orientations(void)
{
    static const int expected_count[5] = {0, 10, 10, 6, 6};
    char msg[128];
    int which, i, j, wind;
    for (which = 1; which <= 4; ++which) {
        for (wind = 0; wind < 2; ++wind) {
            fxl_vertex_t t[3], s;
            uint8_t mask[8 * 8];
            long n;
            make_t(which, t);
            if (wind) { /* the other winding must give the same pixels */
                s = t[1]; t[1] = t[2]; t[2] = s;
            }
            n = ref_coverage_mask(t, -1, -1, 8, 8, mask);
            snprintf(msg, sizeof msg, "T%d winding %d: covered count", which, wind);
            TEST_ASSERT_EQUAL_INT_MESSAGE(expected_count[which], (int)n, msg);
            for (j = -1; j < 7; ++j) {
                for (i = -1; i < 7; ++i) {
                    int got = mask[(j + 1) * 8 + (i + 1)];
                    snprintf(msg, sizeof msg, "T%d winding %d pixel (%d,%d)", which, wind, i, j);
                    TEST_ASSERT_EQUAL_INT_MESSAGE(expect_t(which, i, j), got, msg);
                    TEST_ASSERT_EQUAL_INT_MESSAGE(got, ref_pixel_covered(t, i, j), msg);
                }
            }
        }
    }
}

/* Render two triangles sharing an edge; every pixel of the union exactly once. */
static void check_pair_once(const fxl_vertex_t *pair, int w, int h, int x1, int y1,
                            const char *name)
{
    ref_params p;
    ref_image img;
    char msg[128];
    int i, j;
    ref_params_init(&p, w, h);
    TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, pair, 2, &img));
    for (j = 0; j < h; ++j) {
        for (i = 0; i < w; ++i) {
            int want = i < x1 && j < y1;
            snprintf(msg, sizeof msg, "%s: pixel (%d,%d) covered count", name, i, j);
            TEST_ASSERT_EQUAL_INT_MESSAGE(want, img.covered[j * w + i], msg);
        }
    }
    ref_free(&img);
}

void test_fill_rule_shared_edge_drawn_once(void)
{
    fxl_vertex_t pair[6];
    /* T1 + T4 and T2 + T3 both tile the square of pixels 0..3 x 0..3 */
    make_t(1, pair);
    make_t(4, pair + 3);
    check_pair_once(pair, 8, 8, 4, 4, "T1+T4");
    make_t(2, pair);
    make_t(3, pair + 3);
    check_pair_once(pair, 8, 8, 4, 4, "T2+T3");
    /* Rectangle (0.5,0.5)-(8.5,4.5) split by a slope-1/2 diagonal: centres
     * (2j + 0.5, j + 0.5) lie on it and go to the upper triangle, for which it
     * is a left edge. Pixels 0..7 x 0..3, each once. */
    tri3(pair, 0.5, 0.5, 8.5, 0.5, 8.5, 4.5);
    tri3(pair + 3, 0.5, 0.5, 8.5, 4.5, 0.5, 4.5);
    check_pair_once(pair, 12, 8, 8, 4, "slope 1/2");
    TEST_ASSERT_EQUAL_INT(1, ref_pixel_covered(pair, 4, 2));
    TEST_ASSERT_EQUAL_INT(0, ref_pixel_covered(pair + 3, 4, 2));
}

void test_zero_area_triangle_draws_nothing(void)
{
    fxl_vertex_t t[3];
    uint8_t mask[16 * 16];
    tri3(t, 0.5, 0.5, 8.5, 4.5, 4.5, 2.5); /* collinear */
    TEST_ASSERT_EQUAL_INT(0, (int)ref_coverage_mask(t, 0, 0, 16, 16, mask));
    /* distinct before snapping, identical after: 0.5 plus a quarter of a
     * grid unit (1/64 px on the default grid) snaps to 0.5 */
    tri3(t, 0.5, 0.5, 0.5 + ldexp(1.0, -(FXL_SUBPIXEL_BITS + 2)), 8.5, 0.5, 8.5);
    TEST_ASSERT_EQUAL_INT(0, (int)ref_coverage_mask(t, 0, 0, 16, 16, mask));
}

/* An independent statement of the rule in double (exact here: coordinates are
 * multiples of 1/16 below 64 px, products stay far inside 2^53): inside all
 * edges, or on an edge whose triangle is below it (horizontal) or to its
 * right (other edges). */
static int literal_rule(const double x[3], const double y[3], double px, double py)
{
    int k;
    for (k = 0; k < 3; ++k) {
        double ax = x[(k + 1) % 3], ay = y[(k + 1) % 3];
        double bx = x[(k + 2) % 3], by = y[(k + 2) % 3];
        double cx = x[k], cy = y[k];
        double sp = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
        double sc = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
        if (sp * sc > 0) continue;
        if (sp != 0) return 0;
        if (ay == by) {
            if (!(cy > ay)) return 0; /* not a top edge */
        } else {
            double xl = ax + (cy - ay) * (bx - ax) / (by - ay);
            if (!(cx > xl)) return 0; /* not a left edge */
        }
    }
    return 1;
}

void test_coverage_equals_literal_rule_on_random_triangles(void)
{
    uint32_t seed = 12345u;
    char msg[160];
    int n, i, j, k;
    for (n = 0; n < 2000; ++n) {
        fxl_vertex_t t[3];
        double x[3], y[3];
        uint8_t mask[24 * 24];
        for (k = 0; k < 3; ++k) {
            /* coarse grids (1/2, 1/4 px) put many centres exactly on edges;
             * on the build's sub-pixel grid, so the literal rule on these
             * values is the rule on the snapped ones (1/2 px only at 1 bit) */
            const double grid = n % 2 || FXL_SUBPIXEL_BITS < 2 ? 2.0 : 4.0;
            seed = seed * 1664525u + 1013904223u;
            x[k] = (double)((seed >> 8) % 41u) / grid - 1.0;
            seed = seed * 1664525u + 1013904223u;
            y[k] = (double)((seed >> 8) % 41u) / grid - 1.0;
            t[k] = vtx(x[k], y[k], K20, 0, 0);
        }
        (void)ref_coverage_mask(t, -2, -2, 24, 24, mask);
        for (j = -2; j < 22; ++j) {
            for (i = -2; i < 22; ++i) {
                double area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
                int want = area != 0 && literal_rule(x, y, i + 0.5, j + 0.5);
                snprintf(msg, sizeof msg,
                         "triangle %d (%g,%g)(%g,%g)(%g,%g) pixel (%d,%d)", n, x[0], y[0],
                         x[1], y[1], x[2], y[2], i, j);
                TEST_ASSERT_EQUAL_INT_MESSAGE(want, mask[(j + 2) * 24 + (i + 2)], msg);
            }
        }
    }
}

/* ---- perspective ---------------------------------------------------------------- */

/* v0 (0.5,0.5) q=3K u=0; v1 (8.5,0.5) q=K u=1; v2 (0.5,8.5) q=3K u=0, v=1.
 * On edge v0-v1 with t = (x - 0.5) / 8: u = t q1 / ((1-t) q0 + t q1)
 * = t / (3 - 2t); at the midpoint t = 1/2: u = 0.5 / 2 = 0.25 exactly.
 * Barycentrics b1 = (x-0.5)/8, b2 = (y-0.5)/8 give q = K (3 - 2 b1) and
 * v = 3 b2 / (3 - 2 b1), so at the midpoint:
 *   du/dx = 3 / (3 - 2t)^2 / 8 = (3/4) / 8 = 3/32 per px,   du/dy = 0,
 *   dv/dx = 0 (b2 = 0),   dv/dy = 3 / (3 - 2 b1) / 8 = 3/16 per px. */
static void persp_tri(fxl_vertex_t t[3])
{
    t[0] = vtx(0.5, 0.5, 3 * K20, 0, 0);
    t[1] = vtx(8.5, 0.5, K20, 1, 0);
    t[2] = vtx(0.5, 8.5, 3 * K20, 0, 1);
}

void test_perspective_u_at_edge_midpoint_is_quarter(void)
{
    fxl_vertex_t t[3];
    double u, v, du[2], dv[2];
    persp_tri(t);
    TEST_ASSERT_EQUAL_INT(0, ref_uv_at(t, 4.5, 0.5, 0, &u, &v, du, dv));
    /* long double evaluation of exact small integers: error ~1e-18 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.25, u);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, v);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 3.0 / 32, du[0]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, du[1]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, dv[0]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 3.0 / 16, dv[1]);
    /* vertices themselves */
    TEST_ASSERT_EQUAL_INT(0, ref_uv_at(t, 8.5, 0.5, 0, &u, NULL, NULL, NULL));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.0, u);
    /* affine: the screen midpoint has the mean, 0.5 */
    TEST_ASSERT_EQUAL_INT(0, ref_uv_at(t, 4.5, 0.5, 1, &u, NULL, du, NULL));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.5, u);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.0 / 8, du[0]);
}

void test_render_gives_exact_u_and_lod_at_pixel_centre(void)
{
    static uint16_t texels[256 * 256 * 2]; /* 9-level chain fits in 4/3 of level 0 */
    fxl_texture_t tex;
    fxl_vertex_t t[3];
    ref_params p;
    ref_image img;
    size_t i = 0 * 16 + 4; /* pixel (4, 0): centre (4.5, 0.5), on the top edge */
    memset(&tex, 0, sizeof tex);
    tex.texels = texels;
    tex.log2_w = tex.log2_h = 8;
    tex.levels = 9;
    persp_tri(t);
    ref_params_init(&p, 16, 16);
    p.draw.texture = &tex;
    p.draw.persp = FXL_PERSP_EXACT;
    TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, t, 1, &img));
    TEST_ASSERT_EQUAL_INT(1, img.covered[i]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.25 * 256, img.u[i]);
    TEST_ASSERT_EQUAL_INT32(64, img.tex_x[i]);
    TEST_ASSERT_EQUAL_INT32(0, img.tex_y[i]);
    /* |(du/dx, dv/dx)| = 256 * 3/32 = 24, |(du/dy, dv/dy)| = 256 * 3/16 = 48
     * texels per pixel: LOD = log2(48) = 5.58496 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, log2(48.0), img.lod[i]);
    ref_free(&img);
    /* bias +1.5 levels (384 / 256), and clamping at levels - 1 = 8 */
    p.draw.lod_bias_q8 = 384;
    TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, t, 1, &img));
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, log2(48.0) + 1.5, img.lod[i]);
    ref_free(&img);
    p.draw.lod_bias_q8 = 4 * 256;
    TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, t, 1, &img));
    TEST_ASSERT_DOUBLE_WITHIN(0, 8.0, img.lod[i]);
    ref_free(&img);
}

void test_lod_pixel_derivatives_match_finite_differences(void)
{
    /* central differences with h = 1e-4 px have truncation error ~h^2 u''' ~
     * 1e-8 here (u''' <= 3 * 2^3 / 8^3 per px^3 on this triangle); the
     * long double evaluation adds ~1e-15 / h = 1e-11. Bound 1e-7. */
    fxl_vertex_t t[3];
    const double h = 1e-4;
    double pts[3][2] = {{2.25, 1.75}, {5.0, 2.5}, {1.1, 6.3}};
    int n;
    persp_tri(t);
    for (n = 0; n < 3; ++n) {
        double du[2], dv[2], a, b, c, d;
        (void)ref_uv_at(t, pts[n][0], pts[n][1], 0, NULL, NULL, du, dv);
        (void)ref_uv_at(t, pts[n][0] + h, pts[n][1], 0, &a, &c, NULL, NULL);
        (void)ref_uv_at(t, pts[n][0] - h, pts[n][1], 0, &b, &d, NULL, NULL);
        TEST_ASSERT_DOUBLE_WITHIN(1e-7, (a - b) / (2 * h), du[0]);
        TEST_ASSERT_DOUBLE_WITHIN(1e-7, (c - d) / (2 * h), dv[0]);
        (void)ref_uv_at(t, pts[n][0], pts[n][1] + h, 0, &a, &c, NULL, NULL);
        (void)ref_uv_at(t, pts[n][0], pts[n][1] - h, 0, &b, &d, NULL, NULL);
        TEST_ASSERT_DOUBLE_WITHIN(1e-7, (a - b) / (2 * h), du[1]);
        TEST_ASSERT_DOUBLE_WITHIN(1e-7, (c - d) / (2 * h), dv[1]);
    }
}

/* ---- LOD per triangle ----------------------------------------------------------- */

void test_lod_triangle_lecture_values(void)
{
    fxl_texture_t tex;
    fxl_vertex_t t[3];
    memset(&tex, 0, sizeof tex);
    tex.log2_w = tex.log2_h = 9; /* 512 x 512 */
    /* Half of a 32 x 70 face carrying half of the texture: the ratio is the
     * face's, 512 * 512 / (32 * 70) = 262144 / 2240 = 117.03;
     * log4(117.03) = ln(117.03) / ln(4) = 4.7624 / 1.3863 = 3.4354. */
    t[0] = vtx(10, 10, K20, 0, 0);
    t[1] = vtx(42, 10, K20, 1, 0);
    t[2] = vtx(10, 80, K20, 0, 1);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, log(262144.0 / 2240.0) / log(4.0), ref_lod_triangle(&tex, t));
    TEST_ASSERT_DOUBLE_WITHIN(0.005, 3.435, ref_lod_triangle(&tex, t));
    /* 2 x 2 face: 262144 / 4 = 65536 = 4^8 */
    t[1] = vtx(12, 10, K20, 1, 0);
    t[2] = vtx(10, 12, K20, 0, 1);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 8.0, ref_lod_triangle(&tex, t));
    /* the other winding: same value */
    {
        fxl_vertex_t s = t[1];
        t[1] = t[2];
        t[2] = s;
    }
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 8.0, ref_lod_triangle(&tex, t));
}

/* ---- wrap and sampling ---------------------------------------------------------- */

void test_wrap_modes_at_boundaries(void)
{
    /* n = 4, at x = -1, 0, n-1, n, 2n, -n-1. Mirror repeats 0 1 2 3 3 2 1 0
     * with period 8 (so -1 -> 0 and -5 -> 3); border is -1 outside [0, n). */
    static const int64_t xs[6] = {-1, 0, 3, 4, 8, -5};
    static const int32_t want[4][6] = {
        {3, 0, 3, 0, 0, 3},    /* repeat */
        {0, 0, 3, 3, 0, 3},    /* mirror */
        {0, 0, 3, 3, 3, 0},    /* clamp */
        {-1, 0, 3, -1, -1, -1} /* border */
    };
    char msg[64];
    int m, k;
    for (m = 0; m < 4; ++m) {
        for (k = 0; k < 6; ++k) {
            snprintf(msg, sizeof msg, "mode %d x %lld", m, (long long)xs[k]);
            TEST_ASSERT_EQUAL_INT_MESSAGE(want[m][k], ref_wrap((fxl_wrap_t)m, xs[k], 4), msg);
        }
    }
    /* far out: -2^40 is a multiple of 8, so repeat and mirror give 0 */
    TEST_ASSERT_EQUAL_INT(0, ref_wrap(FXL_WRAP_REPEAT, -((int64_t)1 << 40), 4));
    TEST_ASSERT_EQUAL_INT(0, ref_wrap(FXL_WRAP_MIRROR, -((int64_t)1 << 40), 4));
    TEST_ASSERT_EQUAL_INT(3, ref_wrap(FXL_WRAP_MIRROR, -((int64_t)1 << 40) - 5, 4));
    TEST_ASSERT_EQUAL_INT(0, ref_wrap(FXL_WRAP_REPEAT, 12345, 1));
}

/* 4x4 RGB565 texture whose channels are linear in (x, y): red = x + 4y,
 * green = 8x, blue = 3y. Bilinear interpolation of a linear function is
 * exact, so away from the wrap the filtered value at texel-space point
 * (s, t) is the function at (s - 0.5, t - 0.5). */
static uint16_t g_lin[16];

static fxl_texture_t linear_tex(fxl_wrap_t wrap)
{
    fxl_texture_t t;
    int x, y;
    for (y = 0; y < 4; ++y) {
        for (x = 0; x < 4; ++x) {
            g_lin[y * 4 + x] = (uint16_t)(((x + 4 * y) << 11) | ((8 * x) << 5) | (3 * y));
        }
    }
    memset(&t, 0, sizeof t);
    t.texels = g_lin;
    t.log2_w = t.log2_h = 2;
    t.levels = 1;
    t.wrap_u = t.wrap_v = (uint8_t)wrap;
    return t;
}

static void check_rgb(double r5, double g6, double b5, const double rgb[3], const char *what)
{
    char msg[96];
    /* the reference expands linearly: c * 255 / 31 (or 63); 1e-9 is rounding */
    snprintf(msg, sizeof msg, "%s red", what);
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-9, r5 * 255 / 31, rgb[0], msg);
    snprintf(msg, sizeof msg, "%s green", what);
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-9, g6 * 255 / 63, rgb[1], msg);
    snprintf(msg, sizeof msg, "%s blue", what);
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-9, b5 * 255 / 31, rgb[2], msg);
}

void test_bilinear_hand_computed_values(void)
{
    fxl_texture_t t = linear_tex(FXL_WRAP_REPEAT);
    double rgb[3];
    /* texel centre (1.5, 2.5) -> texel (1, 2): red 9, green 8, blue 6 */
    TEST_ASSERT_EQUAL_INT(0, ref_sample_level(&t, 0, FXL_FILTER_BILINEAR, 1.5, 2.5, rgb));
    check_rgb(9, 8, 6, rgb, "centre");
    /* (2.0, 1.5): half-way between texels (1,1) and (2,1): red (5+6)/2 */
    TEST_ASSERT_EQUAL_INT(0, ref_sample_level(&t, 0, FXL_FILTER_BILINEAR, 2.0, 1.5, rgb));
    check_rgb(5.5, 12, 3, rgb, "between");
    /* (1.75, 1.25): x0 = 1, fx = 1/4, y0 = 0, fy = 3/4; weights 3/16, 1/16,
     * 9/16, 3/16 on (1,0) (2,0) (1,1) (2,1): red = 3/16 + 2/16 + 45/16 +
     * 18/16 = 4.25 = f(1.25, 0.75); green 8 * 1.25 = 10; blue 3 * 0.75 */
    TEST_ASSERT_EQUAL_INT(0, ref_sample_level(&t, 0, FXL_FILTER_BILINEAR, 1.75, 1.25, rgb));
    check_rgb(4.25, 10, 2.25, rgb, "quarter");
    /* across the wrap at (0.25, 0.5): x0 = floor(-0.25) = -1 wraps to 3,
     * fx = 0.75 is the weight of x0 + 1 = 0, so texel 3 gets 1/4:
     * red = 3/4 * 0 + 1/4 * 3 = 0.75, green = 1/4 * 24 = 6 */
    TEST_ASSERT_EQUAL_INT(0, ref_sample_level(&t, 0, FXL_FILTER_BILINEAR, 0.25, 0.5, rgb));
    check_rgb(0.75, 6, 0, rgb, "repeat edge");
    /* clamp: both columns are texel 0 */
    t = linear_tex(FXL_WRAP_CLAMP);
    TEST_ASSERT_EQUAL_INT(0, ref_sample_level(&t, 0, FXL_FILTER_BILINEAR, 0.25, 0.5, rgb));
    check_rgb(0, 0, 0, rgb, "clamp edge");
    /* point: floor -> texel (1, 1) */
    TEST_ASSERT_EQUAL_INT(0, ref_sample_level(&t, 0, FXL_FILTER_POINT, 1.99, 1.0, rgb));
    check_rgb(5, 8, 3, rgb, "point");
}

void test_border_and_texel_formats(void)
{
    static uint8_t bytes[4] = {0, 8, 200, 255};
    static uint16_t pal[256];
    fxl_texture_t t;
    double rgb[3];
    memset(&t, 0, sizeof t);
    t.texels = bytes;
    t.log2_w = 2;
    t.levels = 1;
    t.format = FXL_TEXFMT_L8;
    t.wrap_u = FXL_WRAP_BORDER;
    t.border = 0xF800u; /* pure red */
    /* L8 200 reads as FXL_RGB565(200, 200, 200): 200 >> 3 = 25, 200 >> 2 = 50 */
    TEST_ASSERT_EQUAL_INT(0, ref_texel(&t, 0, 2, 0, rgb));
    check_rgb(25, 50, 25, rgb, "L8");
    TEST_ASSERT_EQUAL_INT(0, ref_texel(&t, 0, 4, 0, rgb));
    check_rgb(31, 0, 0, rgb, "border");
    TEST_ASSERT_EQUAL_INT(0, ref_texel(&t, 0, -1, 0, rgb));
    check_rgb(31, 0, 0, rgb, "border -1");
    /* I8 through the palette; key on index 8 */
    pal[8] = 0x07E0u;
    pal[200] = 0x001Fu;
    t.format = FXL_TEXFMT_I8;
    t.palette = pal;
    t.flags = FXL_TEXF_KEY;
    t.key = 8;
    TEST_ASSERT_EQUAL_INT(0, ref_texel(&t, 0, 2, 0, rgb));
    check_rgb(0, 0, 31, rgb, "I8");
    TEST_ASSERT_EQUAL_INT(1, ref_texel(&t, 0, 1, 0, rgb));
    /* border is never transparent, even when its colour equals the key */
    t.key = 0xF800u;
    t.format = FXL_TEXFMT_RGB565;
    t.texels = g_lin;
    TEST_ASSERT_EQUAL_INT(0, ref_texel(&t, 0, 7, 0, rgb));
}

void test_colour_key_with_bilinear(void)
{
    fxl_texture_t t = linear_tex(FXL_WRAP_REPEAT);
    double rgb[3];
    t.flags = FXL_TEXF_KEY;
    t.key = g_lin[1 * 4 + 2]; /* texel (2, 1) is transparent */
    /* nearest texel of (2.0, 1.5) is (2, 1): transparent */
    TEST_ASSERT_EQUAL_INT(1, ref_sample_level(&t, 0, FXL_FILTER_BILINEAR, 2.0, 1.5, rgb));
    /* (1.9, 1.5): nearest (1, 1) opaque; footprint (1,1) 0.6, (2,1) 0.4 keyed,
     * the row below weight 0: renormalised result is texel (1, 1) itself */
    TEST_ASSERT_EQUAL_INT(0, ref_sample_level(&t, 0, FXL_FILTER_BILINEAR, 1.9, 1.5, rgb));
    check_rgb(5, 8, 3, rgb, "keyed neighbour");
    TEST_ASSERT_EQUAL_INT(1, ref_sample_level(&t, 0, FXL_FILTER_POINT, 2.5, 1.0, rgb));
}

/* ---- whole renders ---------------------------------------------------------------- */

/* A 4x4 quad mapped 1:1 onto the linear texture: centre (i + 0.5, j + 0.5)
 * has u = i + 0.5 texels, so point sampling fetches texel (i, j). */
static void quad(fxl_vertex_t q[6], double x0, double y0, double x1, double y1, uint32_t q0,
                 uint32_t q1)
{
    q[0] = vtx(x0, y0, q0, 0, 0);
    q[1] = vtx(x1, y0, q0, 1, 0);
    q[2] = vtx(x1, y1, q1, 1, 1);
    q[3] = q[0];
    q[4] = q[2];
    q[5] = vtx(x0, y1, q1, 0, 1);
}

void test_render_point_sampled_quad_is_texture(void)
{
    fxl_texture_t t = linear_tex(FXL_WRAP_REPEAT);
    fxl_vertex_t q[6];
    ref_params p;
    ref_image img;
    char msg[64];
    int i, j;
    quad(q, 0, 0, 4, 4, K20, K20);
    ref_params_init(&p, 6, 6);
    p.draw.texture = &t;
    p.draw.mip = FXL_MIP_NONE;
    p.clear_color = 0x1234u;
    TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, q, 2, &img));
    for (j = 0; j < 6; ++j) {
        for (i = 0; i < 6; ++i) {
            size_t k = (size_t)j * 6 + (size_t)i;
            double want[3];
            snprintf(msg, sizeof msg, "pixel (%d,%d)", i, j);
            ref_rgb565_to_rgb(i < 4 && j < 4 ? g_lin[j * 4 + i] : 0x1234u, want);
            TEST_ASSERT_EQUAL_INT_MESSAGE(i < 4 && j < 4, img.drawn[k], msg);
            TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(0, want[0], img.rgb[3 * k], msg);
            TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(0, want[1], img.rgb[3 * k + 1], msg);
            if (i < 4 && j < 4) {
                TEST_ASSERT_EQUAL_INT_MESSAGE(i, img.tex_x[k], msg);
                TEST_ASSERT_EQUAL_INT_MESSAGE(j, img.tex_y[k], msg);
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-12, i + 0.5, img.u[k], msg);
                /* 1 texel per pixel: LOD log2(1) = 0 */
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-12, 0.0, img.lod[k], msg);
            } else {
                TEST_ASSERT_EQUAL_INT_MESSAGE(-1, img.tri[k], msg);
            }
        }
    }
    ref_free(&img);
}

void test_render_mip_levels_and_trilinear(void)
{
    /* 8x8 RGB565 chain: level 0 red 0, level 1 red 10, level 2 red 20,
     * level 3 red 30. A 2x2 pixel quad carrying the whole texture: 4 texels
     * per pixel -> LOD 2 per segment and per triangle (log4(64 / 4) = 2). */
    static uint16_t chain[64 + 16 + 4 + 1];
    fxl_texture_t t;
    fxl_vertex_t q[6];
    ref_params p;
    ref_image img;
    int k;
    for (k = 0; k < 85; ++k) {
        chain[k] = (uint16_t)((k < 64 ? 0 : k < 80 ? 10 : k < 84 ? 20 : 30) << 11);
    }
    memset(&t, 0, sizeof t);
    t.texels = chain;
    t.log2_w = t.log2_h = 3;
    t.levels = 4;
    quad(q, 0, 0, 2, 2, K20, K20);
    ref_params_init(&p, 2, 2);
    p.draw.texture = &t;
    for (k = 0; k < 2; ++k) {
        p.draw.lod = (uint8_t)(k ? FXL_LOD_TRIANGLE : FXL_LOD_SEGMENT);
        p.draw.mip = FXL_MIP_NEAREST;
        p.draw.lod_bias_q8 = 0;
        TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, q, 2, &img));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, 2.0, img.lod[0]);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 20 * 255.0 / 31, img.rgb[0]);
        ref_free(&img);
        /* bias -0.25 (q8 -64): LOD 1.75; nearest level round(1.75) = 2;
         * trilinear: 0.25 * level 1 + 0.75 * level 2 = red 17.5 */
        p.draw.lod_bias_q8 = -64;
        TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, q, 2, &img));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.75, img.lod[3]);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 20 * 255.0 / 31, img.rgb[3 * 3]);
        ref_free(&img);
        p.draw.mip = FXL_MIP_LINEAR;
        p.draw.filter = FXL_FILTER_BILINEAR;
        TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, q, 2, &img));
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 17.5 * 255.0 / 31, img.rgb[3 * 3]);
        ref_free(&img);
        p.draw.filter = FXL_FILTER_POINT;
    }
}

void test_depth_nearer_wins_and_ties_keep_first(void)
{
    /* Two quads over the same 4x4 pixels; red quad inv_w 2^31 (depth 32768),
     * blue quad inv_w 2^30 (depth 16384). */
    fxl_vertex_t s[12];
    ref_params p;
    ref_image img;
    int order, k;
    ref_params_init(&p, 4, 4);
    p.depth_enabled = 1;
    for (order = 0; order < 2; ++order) {
        quad(s + 6 * order, 0, 0, 4, 4, 1u << 31, 1u << 31);
        quad(s + 6 * (1 - order), 0, 0, 4, 4, 1u << 30, 1u << 30);
        for (k = 0; k < 6; ++k) {
            s[6 * order + k].color = 0xF800u;
        }
        p.draw.shade = FXL_SHADE_GOURAUD; /* untextured, vertex colours */
        for (k = 0; k < 6; ++k) {
            s[6 * (1 - order) + k].color = 0x001Fu;
        }
        TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, s, 4, &img));
        for (k = 0; k < 16; ++k) {
            TEST_ASSERT_EQUAL_INT(2, img.covered[k]);
            TEST_ASSERT_DOUBLE_WITHIN(1e-9, 255.0, img.rgb[3 * k]); /* red is nearer */
            TEST_ASSERT_EQUAL_UINT16(32768, img.depth[k]);
            TEST_ASSERT_EQUAL_INT(0, img.depth_tie[k]);
        }
        ref_free(&img);
    }
    /* equal depth: the first triangle stays (strict test) and the tie is flagged */
    quad(s, 0, 0, 4, 4, 1u << 31, 1u << 31);
    quad(s + 6, 0, 0, 4, 4, (1u << 31) + 5, (1u << 31) + 5); /* same inv_w >> 16 */
    for (k = 0; k < 6; ++k) {
        s[k].color = 0xF800u;
        s[6 + k].color = 0x001Fu;
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, s, 4, &img));
    for (k = 0; k < 16; ++k) {
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 255.0, img.rgb[3 * k]);
        TEST_ASSERT_EQUAL_INT(1, img.depth_tie[k]);
        TEST_ASSERT_TRUE(img.tri[k] == 0 || img.tri[k] == 1);
    }
    ref_free(&img);
}

void test_render_argument_errors(void)
{
    fxl_vertex_t q[6];
    fxl_texture_t t = linear_tex(FXL_WRAP_REPEAT);
    ref_params p;
    ref_image img;
    quad(q, 0, 0, 4, 4, K20, K20);
    ref_params_init(&p, 4, 4);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, ref_render(NULL, q, 2, &img));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, ref_render(&p, NULL, 2, &img));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, ref_render(&p, q, -1, &img));
    TEST_ASSERT_NULL(img.covered);
    p.draw.texture = &t;
    p.draw.texenv = FXL_TEXENV_MODULATE;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, ref_render(&p, q, 2, &img));
    p.draw.texenv = FXL_TEXENV_REPLACE;
    t.levels = 4; /* a 4x4 texture has at most 3 */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, ref_render(&p, q, 2, &img));
    p.width = 0;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, ref_render(&p, q, 2, &img));
    ref_free(&img); /* safe on an empty image */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_snap_rounds_to_nearest_sixteenth_ties_up);
    RUN_TEST(test_snap_equals_core_snap);
    RUN_TEST(test_fill_rule_right_triangles_all_eight_edge_orientations);
    RUN_TEST(test_fill_rule_shared_edge_drawn_once);
    RUN_TEST(test_zero_area_triangle_draws_nothing);
    RUN_TEST(test_coverage_equals_literal_rule_on_random_triangles);
    RUN_TEST(test_perspective_u_at_edge_midpoint_is_quarter);
    RUN_TEST(test_render_gives_exact_u_and_lod_at_pixel_centre);
    RUN_TEST(test_lod_pixel_derivatives_match_finite_differences);
    RUN_TEST(test_lod_triangle_lecture_values);
    RUN_TEST(test_wrap_modes_at_boundaries);
    RUN_TEST(test_bilinear_hand_computed_values);
    RUN_TEST(test_border_and_texel_formats);
    RUN_TEST(test_colour_key_with_bilinear);
    RUN_TEST(test_render_point_sampled_quad_is_texture);
    RUN_TEST(test_render_mip_levels_and_trilinear);
    RUN_TEST(test_depth_nearer_wins_and_ties_keep_first);
    RUN_TEST(test_render_argument_errors);
    return UNITY_END();
}
