/* test_lod.c - level-of-detail selection, mip levels in the span loops and
 * trilinear weights, against the double-precision reference. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "unity.h"
#include "test_vertex.h"
#include "test_rng.h"
#include "test_features.h"
#include "fixel/fixel.h"
#include "reference.h"
#include "left_out.h"
#include "../src/raster_int.h"
#include "../src/persp.h"
#include "../src/sfloat.h"
#include "../src/auto.h"

void setUp(void) {}
void tearDown(void) {}

static fxl_vertex_t vtx(double x, double y, double inv_w, double u, double v)
{
    return test_vertex(x, y, inv_w, u, v, 0xFFFF);
}

static uint16_t texels[512 * 512 * 4 / 3 + 16];

static void tex512(fxl_texture_t *t)
{
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(t, texels, 512, 512, FXL_TEXFMT_RGB565, 10));
}

/* The lecture's figures: a 512x512 texture on a 32x70-pixel face has texel
 * area / pixel area = 262144 / 2240 = 117.03, log4 = 3.435; on a 2x2 face
 * 65536, log4 = 8. The core's log2 table is accurate to 1/256 level per log
 * term; two terms and the halving give < 2/256: assert within 2/256. */
void test_lod_per_triangle_matches_lecture_values(void)
{
    TEST_NEEDS(FXL_HAVE_MIPMAP);
    fxl_texture_t t;
    fxl_vertex_t a[3], b[3];
    double want = log(262144.0 / 2240.0) / log(4.0);
    tex512(&t);
    a[0] = vtx(10, 10, 1, 0, 0);
    a[1] = vtx(42, 10, 1, 1, 0);
    a[2] = vtx(10, 80, 1, 0, 1);
    TEST_ASSERT_INT_WITHIN(2, (int)lround(want * 256), fxl_lod_triangle_q8(&t, a));
    b[0] = vtx(10, 10, 1, 0, 0);
    b[1] = vtx(12, 10, 1, 1, 0);
    b[2] = vtx(10, 12, 1, 0, 1);
    TEST_ASSERT_INT_WITHIN(2, 8 * 256, fxl_lod_triangle_q8(&t, b));
}

/* The per-triangle LOD takes its texel area from the q16 coordinate
 * differences exactly while they fit int32 (halved beyond, where a product
 * would pass 2^62). Halved always (toward zero) it lost up to half a unit a
 * difference: v changing by one unit (2^-16 of the texture) across a
 * triangle read as no texel area (-128 levels instead of ~-13), and a
 * sliver in texture space - differences of ~10^9 units whose cross product
 * is small - had its LOD 0.2 level off (the fuzz's check 7 found both, with
 * a bias that lifted them into the chain). Held to the reference's log4
 * within 2/256 on both kinds, and on random triangles with differences of
 * 1 to 2^31 units. */
void test_lod_per_triangle_keeps_small_differences_and_texture_slivers_exact(void)
{
    TEST_NEEDS(FXL_HAVE_MIPMAP);
    fxl_texture_t t;
    fxl_vertex_t a[3];
    char msg[200];
    uint32_t x = 12345u;
    int i, k;
    tex512(&t);
    for (i = 0; i < 3000; i++) {
        double ref;
        int32_t got;
        for (k = 0; k < 3; k++) {
            /* a few pixels across; coordinates from one unit apart to
             * 2^31 (beyond which the core halves them) */
            const int bits = (int)((x >> 3) % 32u);
            x = x * 1664525u + 1013904223u;
            a[k] = vtx(5 + (x >> 24) % 40, 7 + (x >> 16) % 40, 1, 0, 0);
            x = x * 1664525u + 1013904223u;
            a[k].u = (fxl_q16_t)(int32_t)((x >> 1) & ((1u << bits) - 1u)) - (fxl_q16_t)((1u << bits) >> 1);
            x = x * 1664525u + 1013904223u;
            a[k].v = (fxl_q16_t)(int32_t)((x >> 1) & ((1u << bits) - 1u)) - (fxl_q16_t)((1u << bits) >> 1);
        }
        if (i % 3 == 1) {
            /* v changes by one unit only */
            a[1].v = a[0].v;
            a[2].v = a[0].v + 1;
        } else if (i % 3 == 2) {
            /* a sliver in texture space: vertex 2 one unit off the line
             * through 0 and 1 (scaled), with differences near 2^30 */
            a[0].u = -(1 << 29);
            a[0].v = -(1 << 29);
            a[1].u = (1 << 29) + (int32_t)(x & 1023u);
            a[1].v = (1 << 29);
            a[2].u = (a[1].u - a[0].u) / 2 + a[0].u;
            a[2].v = a[2].u + 1;
        }
        ref = ref_lod_triangle(&t, a);
        got = fxl_lod_triangle_q8(&t, a);
        if (!(ref > -127 && ref < 254))
            continue;   /* clamped: the lecture test covers the ends */
        snprintf(msg, sizeof msg, "triangle %d: LOD %.4f q8 %d, reference %.4f (%.1f q8)", i, got / 256.0, (int)got,
                 ref, ref * 256);
        TEST_ASSERT_TRUE_MESSAGE(fabs(got - ref * 256) <= 2.0, msg);
    }
}

/* Probe: the LOD and level each pixel's segment used. */
static uint16_t *probe_base;
static int32_t probe_lod[320 * 240];
static int32_t probe_level[320 * 240];
static uint32_t probe_frac[320 * 240];
static uint8_t probe_cp[320 * 240];   /* 1: the pixel is its segment's correction point */
static uint32_t probe_seg(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    int32_t i;
    for (i = 0; i < s->n; i++) {
        size_t k = (size_t)(s->dst - probe_base) + (size_t)i;
        probe_lod[k] = s->lod_q8;
        probe_level[k] = (int32_t)(s->lvl - tri->level);
        probe_frac[k] = s->lvl2 ? s->lod_frac_q8 : 0u;
        /* a full (unclipped) 16-pixel run starts at its correction point */
        probe_cp[k] = i == 0 && s->n == 16;
    }
    return (uint32_t)s->n;
}


/* Per-segment LOD on the floor against the exact per-pixel LOD.
 * - At a correction point the core evaluates the exact derivatives, so the
 *   only error is arithmetic: ~2^-30 relative in the derivative terms and
 *   the log2 table (< 1/256 per term): asserted within 4/256 level.
 * - Elsewhere in the segment the LOD is the correction point's. Along a
 *   floor row du/dx is constant but du/dy grows with the distance from the
 *   screen centre, so it drifts across 16 pixels (measured ~0.05 level);
 *   the bound for every pixel is 0.25 level.
 * - The same under AUTO: its floor spans would be single affine segments,
 *   but a per-segment LOD caps them at 16 pixels (with one LOD a span, the
 *   span ends were 0.84 level off).
 * Exact LODs outside [0, levels-1] are clamped as the core clamps them. */
void test_lod_per_segment_matches_exact_derivatives_on_floor(void)
{
    TEST_NEEDS(FXL_HAVE_MIPMAP);
    static uint16_t buf[320 * 240];
    fxl_texture_t t;
    fxl_target_t tg;
    fxl_draw_t d;
    fxl_vertex_t q[4], tri[2][3];
    double maxd = 0, maxcp = 0;
    int k, x, y, n = 0;
    char msg[160];
    tex512(&t);
    q[0] = test_project(-40, -0.577, -1, -20, -0.5);
    q[1] = test_project(40, -0.577, -1, 20, -0.5);
    q[2] = test_project(40, -0.577, -50, 20, -25);
    q[3] = test_project(-40, -0.577, -50, -20, -25);
    tri[0][0] = q[0]; tri[0][1] = q[1]; tri[0][2] = q[2];
    tri[1][0] = q[0]; tri[1][1] = q[2]; tri[1][2] = q[3];
    fxl_draw_defaults(&d);
    d.texture = &t;
    d.depth = 0;
    d.mip = FXL_MIP_NEAREST;
    d.lod = FXL_LOD_SEGMENT;
    /* subdiv16, then (k >= 2) AUTO, whose long affine segments on the
     * floor are cut at the LOD grid (raster.c) */
    for (k = 0; k < (FXL_HAVE_AUTO ? 4 : 2); k++) {
        d.persp = (int16_t)(k < 2 ? 16 : FXL_PERSP_AUTO);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&tg, buf, 320, 240, 320, FXL_PIXFMT_RGB565));
        probe_base = buf;
        for (x = 0; x < 320 * 240; x++)
            probe_lod[x] = INT32_MIN;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&tg, &d, tri[k & 1], NULL, probe_seg));
        for (y = 0; y < 240; y++)
            for (x = 0; x < 320; x++) {
                double u, v, du[2], dv[2], want, got, diff;
                if (probe_lod[y * 320 + x] == INT32_MIN)
                    continue;
                TEST_ASSERT_EQUAL_INT(0, ref_uv_at(tri[k & 1], x + 0.5, y + 0.5, 0, &u, &v, du, dv));
                want = ref_lod_pixel(&t, du, dv);
                want = want < 0 ? 0 : (want > 9 ? 9 : want);
                got = probe_lod[y * 320 + x] / 256.0;
                diff = fabs(got - want);
                if (diff > maxd) {
                    maxd = diff;
                    if (getenv("LOD_DEBUG"))
                        printf("max at (%d,%d) got %.4f want %.4f\n", x, y, got, want);
                }
                if (probe_cp[y * 320 + x] && diff > maxcp)
                    maxcp = diff;
                if (diff > 0.25) {
                    snprintf(msg, sizeof msg, "persp %d pixel (%d,%d): LOD %.4f, exact %.4f", d.persp, x, y, got,
                             want);
                    TEST_FAIL_MESSAGE(msg);
                }
                /* nearest level = round(LOD) */
                TEST_ASSERT_EQUAL_INT((int)floor(got + 0.5), probe_level[y * 320 + x]);
                n++;
            }
    }
    snprintf(msg, sizeof msg, "floor: %d pixels, max |LOD - exact| = %.5f level, at correction points %.5f",
             n, maxd, maxcp);
    TEST_MESSAGE(msg);
    TEST_ASSERT_GREATER_THAN(FXL_HAVE_AUTO ? 40000 : 20000, n);
    TEST_ASSERT_TRUE_MESSAGE(maxcp <= 4.0 / 256, msg);
}

/* Largest |LOD - exact| at the correction points of one triangle (full
 * 16-pixel segments), over pixels whose exact LOD is inside the chain by
 * half a level (clamping would hide an error there). Counts them in *n. */
static double lod_error_at_correction_points(const fxl_texture_t *t, const fxl_vertex_t tri[3], int *n)
{
    static uint16_t buf[320 * 240];
    fxl_target_t tg;
    fxl_draw_t d;
    double maxcp = 0;
    int x, y;
    const double top = t->levels - 1.5;
    fxl_draw_defaults(&d);
    d.texture = t;
    d.depth = 0;
    d.mip = FXL_MIP_NEAREST;
    d.lod = FXL_LOD_SEGMENT;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&tg, buf, 320, 240, 320, FXL_PIXFMT_RGB565));
    probe_base = buf;
    for (x = 0; x < 320 * 240; x++) {
        probe_lod[x] = INT32_MIN;
        probe_cp[x] = 0;
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&tg, &d, tri, NULL, probe_seg));
    *n = 0;
    for (y = 0; y < 240; y++)
        for (x = 0; x < 320; x++) {
            double u, v, du[2], dv[2], want, diff;
            if (probe_lod[y * 320 + x] == INT32_MIN || !probe_cp[y * 320 + x])
                continue;
            TEST_ASSERT_EQUAL_INT(0, ref_uv_at(tri, x + 0.5, y + 0.5, 0, &u, &v, du, dv));
            want = ref_lod_pixel(t, du, dv) + d.lod_bias_q8 / 256.0;
            if (want < 0.5 || want > top)
                continue;
            diff = fabs(probe_lod[y * 320 + x] / 256.0 - want);
            if (diff > maxcp)
                maxcp = diff;
            (*n)++;
        }
    return maxcp;
}

/* The per-segment LOD where its integer scaling is stressed: texture
 * coordinates 200 periods from the origin with clamp (not rebased, so u
 * needs more than 32 bits of q16), a depth ratio of 1000 across the
 * triangle, and rotated triangles whose u and v both change along x and y.
 * At correction points the LOD is exact up to the log2 table: within
 * 4/256 level, as on the floor. */
void test_lod_per_segment_exact_at_extremes(void)
{
    TEST_NEEDS(FXL_HAVE_MIPMAP);
    static const double off[2] = {0.0, 200.0};
    static const double depth[3][3] = {{1, 1, 1}, {1, 0.3, 0.05}, {1, 0.01, 0.001}};
    fxl_texture_t t;
    int w, dp, rot, n, total = 0;
    double worst = 0;
    char msg[160];
    tex512(&t);
    for (w = 0; w < 2; w++)
        for (dp = 0; dp < 3; dp++)
            for (rot = 0; rot < 4; rot++) {
                const double a = rot * 0.7 + 0.3, c = cos(a), s = sin(a);
                fxl_vertex_t tri[3];
                double err;
                int i;
                t.wrap_u = t.wrap_v = (uint8_t)(w ? FXL_WRAP_CLAMP : FXL_WRAP_REPEAT);
                for (i = 0; i < 3; i++) {
                    static const double px[3][2] = {{20, 20}, {300, 40}, {60, 230}};
                    /* u, v rotated against the screen, 8 periods across */
                    const double uu = (px[i][0] * c - px[i][1] * s) / 40.0, vv = (px[i][0] * s + px[i][1] * c) / 40.0;
                    tri[i] = vtx(px[i][0], px[i][1], depth[dp][i], off[w] + uu, off[w] + vv);
                }
                err = lod_error_at_correction_points(&t, tri, &n);
                if (err > worst)
                    worst = err;
                total += n;
                snprintf(msg, sizeof msg, "wrap %d depth %d rotation %d: %d points, max |LOD - exact| %.5f", w,
                         dp, rot, n, err);
                TEST_ASSERT_TRUE_MESSAGE(err <= 4.0 / 256, msg);
            }
    snprintf(msg, sizeof msg, "%d correction points, max |LOD - exact| = %.5f level", total, worst);
    TEST_MESSAGE(msg);
    TEST_ASSERT_GREATER_THAN(1000, total);
}

/* lod_bound_hi (span.c): the largest per-segment LOD over a triangle,
 * which lets a triangle that stays at level 0 skip lod_at. The probe
 * takes C, lod_at's largest value at the four corners of the vertex range
 * at q_min, and calls lod_at at random points of the range (ends
 * included) and any q (lod_at clamps q): none may give more than C. Then
 * the triangle is drawn at the bias that puts C one q8 step above level
 * 0 (lod_at must stay lod_at) and at the bias that puts C at level 0
 * (lod_hi must be C, lod_at one value, every segment at LOD 0). */
static uint32_t bound_next(void)   /* 32 random bits (test_rng.h's generator) */
{
    return (uint32_t)(rng_next() >> 32);
}

/* a random value in [lo, hi] (int64), the ends one time in four */
static int64_t bound_in(int64_t lo, int64_t hi)
{
    const uint64_t w = (uint64_t)hi - (uint64_t)lo;
    const uint32_t r = bound_next();
    if (r % 4u == 0u)
        return r & 4u ? hi : lo;
    return (int64_t)((uint64_t)lo + (((uint64_t)bound_next() << 32 | bound_next()) % (w + 1u)));
}

static int bound_seen, bound_const, bound_nonzero;
static int32_t bound_corners, bound_max, bound_tri_hi;
static int64_t bound_calls, bound_gap[3000];
static char bound_msg[200];
static uint32_t probe_bound(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    if (s->lod_q8 != 0)
        bound_nonzero = 1;
    if (!bound_seen) {
        bound_seen = 1;
        bound_tri_hi = tri->lod_hi;
        if (tri->lod_per_segment && tri->nlevels > 1) {
            int k;
            int32_t first = 0;
            bound_const = 1;
            bound_corners = INT32_MIN;
            for (k = 0; k < 4; k++) {
                const int32_t r = tri->lod_at(tri, tri->q_min, tri->lod_a[0][k & 1], tri->lod_a[1][k >> 1]);
                if (r > bound_corners)
                    bound_corners = r;
            }
            for (k = 0; k < 200; k++) {
                const int64_t q = (int64_t)(((uint64_t)tri->q_min >> (bound_next() % 8)) +
                                            (uint64_t)(tri->q_max - tri->q_min + 1) * (bound_next() % 5u) / 2u);
                const int64_t u64 = bound_in(tri->lod_a[0][0], tri->lod_a[0][1]);
                const int64_t v64 = bound_in(tri->lod_a[1][0], tri->lod_a[1][1]);
                const int32_t r = tri->lod_at(tri, q, u64, v64);
                if (k == 0)
                    first = r;
                if (r != first)
                    bound_const = 0;
                if (r > bound_max)
                    bound_max = r;
                bound_calls++;
                if (r > bound_corners) {
                    snprintf(bound_msg, sizeof bound_msg,
                             "lod_at %d above its largest at the corners %d, at q %lld u %lld v %lld", (int)r,
                             (int)bound_corners, (long long)q, (long long)u64, (long long)v64);
                    TEST_FAIL_MESSAGE(bound_msg);
                }
            }
        }
    }
    return (uint32_t)s->n;
}

static int cmp_i64(const void *a, const void *b)
{
    const int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

void test_lod_bound_holds_inside_the_triangle_and_settles_level_0(void)
{
    TEST_NEEDS(FXL_HAVE_MIPMAP);
    static uint16_t buf[320 * 240];
    fxl_target_t tg;
    fxl_texture_t t;
    fxl_draw_t d;
    int i, checked = 0, settled = 0, varied = 0;
    rng_seed(2463534242u);
    tex512(&t);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&tg, buf, 320, 240, 320, FXL_PIXFMT_RGB565));
    probe_base = buf;
    fxl_draw_defaults(&d);
    d.texture = &t;
    d.lod = FXL_LOD_SEGMENT;
    for (i = 0; i < 3000; i++) {
        fxl_vertex_t v[3];
        int k, pass;
        int32_t c = 0;
        /* sizes from slivers to far past the target, depths from flat to
         * 2^24 apart, coordinates from a texel to the whole int32 range */
        const int big = (int)(bound_next() % 16u);
        const int wide = (int)(bound_next() % 31u);
        t.wrap_u = t.wrap_v = (uint8_t)(bound_next() % 2u ? FXL_WRAP_CLAMP : FXL_WRAP_REPEAT);
        d.mip = bound_next() % 2u ? FXL_MIP_LINEAR : FXL_MIP_NEAREST;
        {
            static const int16_t modes[4] = {FXL_PERSP_EXACT, 16, 8, FXL_PERSP_AUTO};
            d.persp = modes[bound_next() % 4u];
        }
        for (k = 0; k < 3; k++) {
            v[k].x = (fxl_q16_t)(int32_t)((bound_next() % (320u << big)) * 65536.0 / (1 << big) - 40 * 65536.0);
            v[k].y = (fxl_q16_t)(int32_t)((bound_next() % (240u << big)) * 65536.0 / (1 << big) - 30 * 65536.0);
            v[k].inv_w = 1u + (bound_next() >> (bound_next() % 25u));
            v[k].u = fxl__i32_of_bits(bound_next() >> wide);
            v[k].v = fxl__i32_of_bits(bound_next() >> wide);
            v[k].color = 0xFFFF;
        }
        /* pass 0: the largest bias (lod_at itself unless C is 128 levels
         * below level 0, and then C is lod_hi), C and the random points;
         * pass 1: C one q8 step above level 0; pass 2: C at level 0 */
        for (pass = 0; pass < 3; pass++) {
            int64_t bias = INT16_MAX;
            if (pass > 0) {
                bias = (pass == 1 ? 1 : 0) - (int64_t)c;
                if (bias < INT16_MIN || bias > INT16_MAX)
                    break;
            }
            d.lod_bias_q8 = (int16_t)bias;
            bound_seen = 0;
            bound_const = 0;
            bound_nonzero = 0;
            bound_max = INT32_MIN;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&tg, &d, v, NULL, probe_bound));
            if (!bound_seen || bound_max == INT32_MIN)
                break;   /* culled, nothing inside the target, or no per-segment LOD */
            snprintf(bound_msg, sizeof bound_msg, "triangle %d pass %d: corners' largest %d, lod_hi %d, bias %d", i,
                     pass, (int)bound_corners, (int)bound_tri_hi, (int)bias);
            if (pass == 0) {
                c = bound_corners;
                bound_gap[checked++] = (int64_t)c - bound_max;
                varied += !bound_const;
            }
            /* the decision: the shortcut exactly where C is at level 0 */
            TEST_ASSERT_TRUE_MESSAGE(bound_corners == c, bound_msg);
            if (c + bias <= 0) {
                TEST_ASSERT_TRUE_MESSAGE(bound_tri_hi == c && bound_const && !bound_nonzero, bound_msg);
                settled += pass == 2;
            } else {
                TEST_ASSERT_TRUE_MESSAGE(bound_tri_hi + bias > 0 && bound_tri_hi <= c, bound_msg);
            }
        }
    }
    qsort(bound_gap, (size_t)checked, sizeof bound_gap[0], cmp_i64);
    snprintf(bound_msg, sizeof bound_msg,
             "%d triangles, %lld lod_at calls at or below the corners' largest (median gap to the largest seen "
             "%lld q8); %d settled at level 0",
             checked, (long long)bound_calls, checked ? (long long)bound_gap[checked / 2] : 0LL, settled);
    TEST_MESSAGE(bound_msg);
    TEST_ASSERT_GREATER_THAN(1000, checked);
    TEST_ASSERT_GREATER_THAN(checked / 2, varied);
    TEST_ASSERT_GREATER_THAN(1000, settled);
}

/* The 512 x 512 texture, a default draw of it without depth and a 320 x 240
 * target whose spans probe_seg records (probe_lod, probe_level). */
static void probe_draw_setup(fxl_texture_t *t, fxl_target_t *tg, fxl_draw_t *d)
{
    static uint16_t buf[320 * 240];
    tex512(t);
    fxl_draw_defaults(d);
    d->texture = t;
    d->depth = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(tg, buf, 320, 240, 320, FXL_PIXFMT_RGB565));
    probe_base = buf;
}

/* Bias shifts the LOD by exactly the bias (before clamping); per-triangle
 * mode uses the triangle value for every pixel. */
void test_lod_bias_and_per_triangle_mode(void)
{
    TEST_NEEDS(FXL_HAVE_MIPMAP);
    fxl_texture_t t;
    fxl_target_t tg;
    fxl_draw_t d;
    fxl_vertex_t tri[3];
    int32_t lod0[1], tri_lod;
    int x;
    probe_draw_setup(&t, &tg, &d);
    /* A flat (constant-depth) triangle: every pixel has the same LOD. */
    tri[0] = vtx(10, 10, 0.5, 0, 0);
    tri[1] = vtx(74, 10, 0.5, 1, 0);
    tri[2] = vtx(10, 74, 0.5, 0, 1);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&tg, &d, tri, NULL, probe_seg));
    lod0[0] = probe_lod[20 * 320 + 20];
    /* 512 texels over 64 px: 8 texels per pixel, LOD 3 */
    TEST_ASSERT_INT_WITHIN(2, 3 * 256, lod0[0]);
    d.lod_bias_q8 = 128;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&tg, &d, tri, NULL, probe_seg));
    TEST_ASSERT_EQUAL_INT(lod0[0] + 128, probe_lod[20 * 320 + 20]);
    d.lod_bias_q8 = -2000;   /* clamps at level 0 */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&tg, &d, tri, NULL, probe_seg));
    TEST_ASSERT_EQUAL_INT(0, probe_lod[20 * 320 + 20]);
    d.lod_bias_q8 = 5000;    /* clamps at the last level */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&tg, &d, tri, NULL, probe_seg));
    TEST_ASSERT_EQUAL_INT(9 * 256, probe_lod[20 * 320 + 20]);
    TEST_ASSERT_EQUAL_INT(9, probe_level[20 * 320 + 20]);
    d.lod_bias_q8 = 0;
    d.lod = FXL_LOD_TRIANGLE;
    tri_lod = fxl_lod_triangle_q8(&t, tri);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&tg, &d, tri, NULL, probe_seg));
    for (x = 12; x < 60; x += 7)
        TEST_ASSERT_EQUAL_INT(tri_lod, probe_lod[12 * 320 + x]);
    /* A chain shorter than the full one (2 of 10 levels): the per-triangle
     * LOD (3) clamps to its last level, for either mip mode, with a bias
     * or not (unclamped it indexed a level that does not exist). */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, texels, 512, 512, FXL_TEXFMT_RGB565, 2));
    for (x = 0; x < 4; x++) {
        d.mip = (x & 1) ? FXL_MIP_LINEAR : FXL_MIP_NEAREST;
        d.lod_bias_q8 = (x & 2) ? 1000 : 0;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&tg, &d, tri, NULL, probe_seg));
        TEST_ASSERT_EQUAL_INT(256, probe_lod[20 * 320 + 20]);
        TEST_ASSERT_EQUAL_INT(1, probe_level[20 * 320 + 20]);
    }
}

/* What the per-triangle area cannot see (raster.h, FXL_LOD_TRIANGLE): a
 * mapping whose u, v are collinear has no texel area, so its LOD is the
 * clamp and it draws level 0, however far it is minified; the per-segment
 * LOD takes the longer derivative. Here u is constant and v runs 4 periods
 * (2,048 texels) down 64 rows: 32 texels a pixel, LOD 5 (a review's 1 x N
 * strip, the mesh that has this mapping). */
void test_lod_per_triangle_of_collinear_coordinates_is_level_0_per_segment_is_not(void)
{
    TEST_NEEDS(FXL_HAVE_MIPMAP);
    fxl_texture_t t;
    fxl_target_t tg;
    fxl_draw_t d;
    fxl_vertex_t tri[3];
    probe_draw_setup(&t, &tg, &d);
    tri[0] = vtx(10, 10, 0.5, 0.25, 0);
    tri[1] = vtx(74, 10, 0.5, 0.25, 0);
    tri[2] = vtx(10, 74, 0.5, 0.25, 4);
    TEST_ASSERT_EQUAL_INT(-128 * 256, fxl_lod_triangle_q8(&t, tri));
    d.lod = FXL_LOD_SEGMENT;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&tg, &d, tri, NULL, probe_seg));
    TEST_ASSERT_INT_WITHIN(2, 5 * 256, probe_lod[20 * 320 + 20]);
    TEST_ASSERT_EQUAL_INT(5, probe_level[20 * 320 + 20]);
    d.lod = FXL_LOD_TRIANGLE;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&tg, &d, tri, NULL, probe_seg));
    TEST_ASSERT_EQUAL_INT(0, probe_lod[20 * 320 + 20]);
    TEST_ASSERT_EQUAL_INT(0, probe_level[20 * 320 + 20]);
}

/* Trilinear: the blend weight of the second level is the LOD fraction, and
 * the output equals the 5-bit blend of the two levels' samples. A texture
 * whose levels are flat colours (level n all value c_n) makes the expected
 * pixel computable by hand. */
void test_trilinear_weights_blend_levels_by_lod_fraction(void)
{
    TEST_NEEDS(FXL_HAVE_MIPMAP && FXL_HAVE_BILINEAR);
    static uint16_t buf[320 * 240];
    static uint16_t chain[64 * 64 + 32 * 32 + 16 * 16 + 8 * 8 + 4 * 4 + 2 * 2 + 1];
    static const uint16_t lv[7] = {0x001F, 0x07E0, 0xF800, 0xFFFF, 0x0000, 0x7BEF, 0x1234};
    fxl_texture_t t;
    fxl_target_t tg;
    fxl_draw_t d;
    fxl_vertex_t tri[3];
    uint32_t L, off = 0, i;
    int checked = 0, x, y;
    for (L = 0; L < 7; L++) {
        uint32_t side = 64u >> L;
        for (i = 0; i < side * side; i++)
            chain[off + i] = lv[L];
        off += side * side;
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, chain, 64, 64, FXL_TEXFMT_RGB565, 7));
    /* 64 texels over 24 px: LOD log2(64/24) = 1.415: levels 1 and 2, frac .415 */
    tri[0] = vtx(10, 10, 0.5, 0, 0);
    tri[1] = vtx(34, 10, 0.5, 1, 0);
    tri[2] = vtx(10, 34, 0.5, 0, 1);
    fxl_draw_defaults(&d);
    d.texture = &t;
    d.depth = 0;
    d.filter = FXL_FILTER_BILINEAR;
    d.mip = FXL_MIP_LINEAR;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&tg, buf, 320, 240, 320, FXL_PIXFMT_RGB565));
    probe_base = buf;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&tg, &d, tri, NULL, probe_seg));
    TEST_ASSERT_EQUAL_INT(1, probe_level[15 * 320 + 15]);
    TEST_ASSERT_INT_WITHIN(2, (int)lround((log2(64.0 / 24.0) - 1) * 256), (int)probe_frac[15 * 320 + 15]);
    fxl_target_clear(&tg, 0xDEAD);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&tg, &d, tri, NULL));
    for (y = 11; y < 20; y++)
        for (x = 11; x < 20; x++) {
            /* the same per-channel rounding blend the core documents:
             * (a * (32 - f) + b * f + 16) >> 5 with f = frac >> 3 */
            uint32_t f = probe_frac[y * 320 + x] >> 3, a = lv[1], b = lv[2];
            uint32_t r = ((((a >> 11) & 31) * (32 - f) + ((b >> 11) & 31) * f + 16) >> 5) & 31;
            uint32_t g = ((((a >> 5) & 63) * (32 - f) + ((b >> 5) & 63) * f + 16) >> 5) & 63;
            uint32_t bb = (((a & 31) * (32 - f) + (b & 31) * f + 16) >> 5) & 31;
            TEST_ASSERT_EQUAL_HEX16((r << 11) | (g << 5) | bb, buf[y * 320 + x]);
            checked++;
        }
    TEST_ASSERT_EQUAL_INT(81, checked);
}

/* Probe of the generic walk that draws for real (the loops the core picks)
 * and records each pixel's LOD and whether its segment starts there. */
static uint8_t probe_start[320 * 240];
static uint32_t probe_draw(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    int32_t i;
    for (i = 0; i < s->n; i++) {
        const size_t k = (size_t)(s->dst - probe_base) + (size_t)i;
        probe_lod[k] = s->lod_q8;
        probe_start[k] = i == 0;
    }
    return fxl__pick_seg_fn(tri)(tri, s);
}

/* Draws triangle v with d twice into 320 x 240 frames of format fmt,
 * clipped to clip when it is not NULL: gen through the generic walk
 * (probe_draw, which records each pixel's LOD and segment starts, reset
 * here), fast through fxl_draw_triangle; fails on the first pixel where
 * they differ (what names the case). With zinit, each draw has a depth
 * buffer (zgen, zfast) that starts as zinit, and the depth values must
 * agree too. Returns 1 when a specialised walk drew fast. */
static int draw_generic_and_fast_z(const fxl_draw_t *d, const fxl_vertex_t v[3], const fxl_rect_t *clip,
                                   fxl_pixfmt_t fmt, const uint16_t *zinit, uint16_t *gen, uint16_t *zgen,
                                   uint16_t *fast, uint16_t *zfast, const char *what)
{
    fxl_target_t tg;
    fxl_stats_t st;
    char msg[200];
    int x;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&tg, gen, 320, 240, 320, fmt));
    fxl_target_clear(&tg, 0xDEAD);
    if (zinit) {
        memcpy(zgen, zinit, 320 * 240 * sizeof *zgen);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&tg, zgen));
    }
    if (clip)
        fxl_target_set_clip(&tg, clip);
    probe_base = gen;
    for (x = 0; x < 320 * 240; x++)
        probe_lod[x] = INT32_MIN;
    memset(probe_start, 2, sizeof probe_start);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&tg, d, v, NULL, probe_draw));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&tg, fast, 320, 240, 320, fmt));
    fxl_target_clear(&tg, 0xDEAD);
    if (zinit) {
        memcpy(zfast, zinit, 320 * 240 * sizeof *zfast);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&tg, zfast));
    }
    if (clip)
        fxl_target_set_clip(&tg, clip);
    memset(&st, 0, sizeof st);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&tg, d, v, &st));
    for (x = 0; x < 320 * 240; x++)
        if (fast[x] != gen[x] || (zinit && zfast[x] != zgen[x])) {
            snprintf(msg, sizeof msg, "%.120s pixel (%d,%d): fast %04x/%04x generic %04x/%04x", what, x % 320,
                     x / 320, fast[x], zinit ? zfast[x] : 0, gen[x], zinit ? zgen[x] : 0);
            TEST_FAIL_MESSAGE(msg);
        }
    return st.drawn > st.generic;
}

/* The same without a depth buffer, native RGB565. */
static int draw_generic_and_fast(const fxl_draw_t *d, const fxl_vertex_t v[3], const fxl_rect_t *clip,
                                 uint16_t *gen, uint16_t *fast, const char *what)
{
    return draw_generic_and_fast_z(d, v, clip, FXL_PIXFMT_RGB565, NULL, gen, NULL, fast, NULL, what);
}

/* Under AUTO the per-segment LOD is evaluated on a 16-pixel grid from each
 * span's left end and held between grid points (auto.h), where the error
 * bound cuts segments shorter than that. A wall receding to the right
 * with a 1/64-texel budget gets segments of 1 to 8 pixels. Asserted, for
 * the generic walk, full frame and clipped at x = 101 (off the grid of
 * most spans: the walk then evaluates the grid point left of the clip
 * first): every pixel's LOD is its grid point's, and the clipped LODs are
 * the full frame's. For the fast walk: its pixels equal the generic
 * walk's, full and clipped, for point (nearest level) and trilinear (the
 * stats say it drew them, not the generic walk). */
void test_auto_lod_is_held_on_a_16_pixel_grid_whatever_the_clip(void)
{
    TEST_NEEDS(FXL_HAVE_MIPMAP && FXL_HAVE_AUTO);
    static uint16_t fast[320 * 240], gen[320 * 240];
    static int32_t lod_full[320 * 240];
    const fxl_rect_t clip = {101, 0, 301, 240};
    fxl_texture_t t;
    fxl_draw_t d;
    fxl_vertex_t q[4], tri[2][3];
    int k, x, y, c, mode, off_grid = 0, changes = 0, fast_walks = 0;
    char msg[160];
    /* 256 x 256: the fast walks take textures up to 2^16 texels */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, texels, 256, 256, FXL_TEXFMT_RGB565, 9));
    for (x = 0; x < 256 * 256 * 4 / 3; x++)
        texels[x] = (uint16_t)(x * 2654435761u >> 16);
    /* on screen, so each span's left end is drawn */
    q[0] = test_project(-1, -0.8, -2.5, 0, 0);
    q[1] = test_project(30, -0.8, -60, 40, 0);
    q[2] = test_project(30, 0.8, -60, 40, 3);
    q[3] = test_project(-1, 0.8, -2.5, 0, 3);
    tri[0][0] = q[0]; tri[0][1] = q[1]; tri[0][2] = q[2];
    tri[1][0] = q[0]; tri[1][1] = q[2]; tri[1][2] = q[3];
    for (mode = 0; mode < 2; mode++) {
        if (mode == 1 && !FXL_HAVE_BILINEAR)
            continue;
        fxl_draw_defaults(&d);
        d.texture = &t;
        d.depth = 0;
        d.persp = FXL_PERSP_AUTO;
        d.lod = FXL_LOD_SEGMENT;
        d.filter = mode ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
        d.mip = mode ? FXL_MIP_LINEAR : FXL_MIP_NEAREST;
        for (k = 0; k < 2; k++)
            for (c = 0; c < 2; c++) {
                snprintf(msg, sizeof msg, "mode %d tri %d clip %d", mode, k, c);
                fast_walks += draw_generic_and_fast(&d, tri[k], c ? &clip : NULL, gen, fast, msg);
                for (y = 0; y < 240; y++) {
                    int32_t *row = probe_lod + y * 320, xl = -1;
                    for (x = 0; x < 320; x++) {
                        if (row[x] == INT32_MIN)
                            continue;
                        if (c) {
                            /* clipped: the full frame's LOD */
                            TEST_ASSERT_EQUAL_INT32(lod_full[y * 320 + x], row[x]);
                            continue;
                        }
                        if (xl < 0)
                            xl = x;   /* full frame: the span's left end */
                        TEST_ASSERT_EQUAL_INT32(row[xl + ((x - xl) & ~15)], row[x]);
                        lod_full[y * 320 + x] = row[x];
                        if (probe_start[y * 320 + x] && ((x - xl) & 15) != 0)
                            off_grid++;
                        if (((x - xl) & 15) == 0 && x > xl && row[x - 1] != row[x])
                            changes++;
                    }
                }
            }
    }
    snprintf(msg, sizeof msg, "%d segments start off the grid, the LOD changes at %d grid points; %d fast draws",
             off_grid, changes, (int)fast_walks);
    TEST_MESSAGE(msg);
    /* not vacuous: short segments between grid points, and a LOD that
     * does change along the spans */
    TEST_ASSERT_TRUE_MESSAGE(off_grid > 1000 && changes > 100, msg);
}

/* AUTO on several levels (segments capped at the 16-pixel LOD grid): the
 * fast walk draws a span whose every 16-pixel block fits the error bound
 * as fixed 16-pixel segments after one test (fxl__auto_span_fits_cap),
 * and the other spans of the same triangle segment by segment. A near
 * quad turned about the vertical axis, both ways (q falling along x, and
 * rising), 4 texture repeats, the default budget: q varies ~4x across
 * each, so AUTO segments it per segment (auto.c), and the generic walk's
 * segments show both kinds of span (counted on spans with both ends on
 * screen). Asserted: the fast walk's pixels equal the generic walk's,
 * full frame and clipped at x = 101, and it drew them. A test that
 * claims a span fits where one block does not (the fall of q along the
 * span left out, say) draws that span with the wrong segments. */
void test_auto_spans_that_fit_the_cap_take_fixed_segments(void)
{
    TEST_NEEDS(FXL_HAVE_MIPMAP && FXL_HAVE_AUTO && FXL_HAVE_BILINEAR);
    static uint16_t fast[320 * 240], gen[320 * 240];
    const fxl_rect_t clip = {101, 0, 301, 240};
    fxl_texture_t t;
    fxl_draw_t d;
    int side, k, c, x, y, uniform = 0, mixed = 0, fast_walks = 0;
    char msg[160];
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, texels, 256, 256, FXL_TEXFMT_RGB565, 9));
    for (x = 0; x < 256 * 256 * 4 / 3; x++)
        texels[x] = (uint16_t)(x * 2654435761u >> 16);
    fxl_draw_defaults(&d);
    d.texture = &t;
    d.depth = 0;
    d.persp = FXL_PERSP_AUTO;
    d.lod = FXL_LOD_SEGMENT;
    d.filter = FXL_FILTER_BILINEAR;
    d.mip = FXL_MIP_LINEAR;
    for (side = 0; side < 2; side++) {
        /* corners (+-1.6, +-1.2) turned 55 degrees about y, centre z = -3.2 */
        const double a = (side ? -55.0 : 55.0) * 3.14159265358979323846 / 180.0;
        const double cx[4] = {-1.6, 1.6, 1.6, -1.6}, cy[4] = {-1.2, -1.2, 1.2, 1.2};
        fxl_vertex_t q[4], tri[2][3];
        for (k = 0; k < 4; k++)
            q[k] = test_project(cx[k] * cos(a), cy[k], -3.2 - cx[k] * sin(a), (cx[k] + 1.6) / 8.0, (1.2 - cy[k]) / 8.0);
        tri[0][0] = q[0]; tri[0][1] = q[1]; tri[0][2] = q[2];
        tri[1][0] = q[0]; tri[1][1] = q[2]; tri[1][2] = q[3];
        for (k = 0; k < 2; k++)
            for (c = 0; c < 2; c++) {
                snprintf(msg, sizeof msg, "side %d tri %d clip %d", side, k, c);
                fast_walks += draw_generic_and_fast(&d, tri[k], c ? &clip : NULL, gen, fast, msg);
                if (c)
                    continue;
                for (y = 0; y < 240; y++) {
                    /* the span's segment lengths, but the last */
                    const uint8_t *row = probe_start + y * 320;
                    int xl = -1, xr = -1, last = -1, short_seg = 0, seg16 = 0;
                    for (x = 0; x < 320; x++)
                        if (row[x] != 2) {
                            xl = xl < 0 ? x : xl;
                            xr = x + 1;
                        }
                    if (xl <= 0 || xr >= 320)
                        continue;   /* empty, or cut by the frame */
                    for (x = xl; x < xr; x++)
                        if (row[x] == 1) {
                            if (last >= 0) {
                                short_seg |= x - last < 16;
                                seg16 |= x - last == 16;
                            }
                            last = x;
                        }
                    uniform += seg16 && !short_seg;
                    mixed += seg16 && short_seg;
                }
            }
    }
    snprintf(msg, sizeof msg, "spans of 16-pixel segments %d, with shorter ones %d; %d fast draws", uniform, mixed,
             fast_walks);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE_MESSAGE(uniform > 50 && mixed > 50, msg);
    /* which builds have the trilinear fast walk: test_stats_count_generic_draws */
    TEST_ASSERT_EQUAL_INT(FXL__FAST_SPANS && FXL_FAST_NATIVE && FXL_FAST_BILINEAR && FXL_FAST_NO_DEPTH && FXL_FAST_MIP
                              ? 8
                              : 0,
                          fast_walks);
}

/* The mip walks with a depth buffer: on a level floor (z constant along
 * every row, where the fast walks hold the depth in a register:
 * span_walk.h's constant-z copy) and on the same floor tilted 3 degrees
 * about the view axis (z varies along rows: the walk itself), every pixel
 * and depth value of the fast walk equals the generic walk's. Per-segment
 * LOD on a 256 x 256 chain (9 levels), each filter (point and bilinear on
 * the nearest level, point-mip-linear, trilinear), native and swapped
 * RGB565, segments of 16 and 8, full frame and clipped at x = 101. A
 * depth buffer that rejects one pixel in three (nearest there) checks the
 * rejections too. */
void test_mip_walks_with_depth_match_generic(void)
{
    TEST_NEEDS(FXL_HAVE_MIPMAP && FXL_HAVE_DEPTH);
    static uint16_t fast[320 * 240], gen[320 * 240], zfast[320 * 240], zgen[320 * 240], zinit[320 * 240];
    static const fxl_filter_t filt[4] = {FXL_FILTER_POINT, FXL_FILTER_BILINEAR, FXL_FILTER_POINT,
                                         FXL_FILTER_BILINEAR};
    static const fxl_mipmode_t mip[4] = {FXL_MIP_NEAREST, FXL_MIP_NEAREST, FXL_MIP_LINEAR, FXL_MIP_LINEAR};
    const fxl_rect_t clip = {101, 0, 301, 240};
    fxl_texture_t t;
    fxl_draw_t d;
    fxl_vertex_t tri[2][2][3];
    int tilt, k, m, f, c, ps, x, drawn = 0, fast_walks = 0, refused = 0;
    char msg[160];
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, texels, 256, 256, FXL_TEXFMT_RGB565, 9));
    for (x = 0; x < 256 * 256 * 4 / 3; x++)
        texels[x] = (uint16_t)(x * 2654435761u >> 16);
    for (x = 0; x < 320 * 240; x++)
        zinit[x] = x % 3 == 0 ? 0xFFFF : 0;
    for (tilt = 0; tilt < 2; tilt++) {
        /* floor y = -1 from z = -1.2 to -60, 24 texture repeats deep */
        const double a = tilt ? 3.0 * 3.14159265358979323846 / 180.0 : 0.0;
        const double cx[4] = {-6, 6, 6, -6}, cz[4] = {-1.2, -1.2, -60, -60};
        fxl_vertex_t q[4];
        for (k = 0; k < 4; k++)
            q[k] = test_project(cx[k] * cos(a) + sin(a), -cos(a) + cx[k] * sin(a), cz[k], (cx[k] + 6) / 2,
                                -cz[k] / 2.5);
        tri[tilt][0][0] = q[0]; tri[tilt][0][1] = q[1]; tri[tilt][0][2] = q[2];
        tri[tilt][1][0] = q[0]; tri[tilt][1][1] = q[2]; tri[tilt][1][2] = q[3];
    }
    /* not vacuous: the level floor's rows are at one depth (two vertices
     * of each triangle on one row at one 1/w), the tilted one's are not */
    TEST_ASSERT_EQUAL_INT32(tri[0][0][0].y, tri[0][0][1].y);
    TEST_ASSERT_EQUAL_UINT32(tri[0][0][0].inv_w, tri[0][0][1].inv_w);
    TEST_ASSERT_TRUE(tri[1][0][0].y != tri[1][0][1].y);
    for (m = 0; m < 4; m++)
        for (f = 0; f < 2; f++) {
            const fxl_pixfmt_t fmt = f ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
            fxl_draw_defaults(&d);
            d.texture = &t;
            d.depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
            d.lod = FXL_LOD_SEGMENT;
            d.filter = (uint8_t)filt[m];
            d.mip = (uint8_t)mip[m];
            if (left_out_feature(&d, &t, fmt, 1) != NULL) {
                refused++;
                continue;
            }
            for (ps = 0; ps < 2; ps++)
                for (tilt = 0; tilt < 2; tilt++)
                    for (k = 0; k < 2; k++)
                        for (c = 0; c < 2; c++) {
                            d.persp = ps ? 8 : 16;
                            snprintf(msg, sizeof msg, "filter %d mip %d swap %d persp %d tilt %d tri %d clip %d",
                                     (int)d.filter, (int)d.mip, f, (int)d.persp, tilt, k, c);
                            fast_walks += draw_generic_and_fast_z(&d, tri[tilt][k], c ? &clip : NULL, fmt, zinit,
                                                                  gen, zgen, fast, zfast, msg);
                            drawn++;
                        }
        }
    snprintf(msg, sizeof msg, "%d draws compared (%d by a fast walk), %d filter x format pairs left out", drawn,
             fast_walks, refused);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE_MESSAGE(drawn > 0, msg);
    /* every draw a specialised walk could take, it took */
    if (FXL__FAST_SPANS && FXL_FAST_NATIVE && FXL_FAST_SWAPPED && FXL_FAST_POINT && FXL_FAST_BILINEAR && FXL_FAST_DEPTH &&
        FXL_FAST_MIP && FXL_HAVE_BILINEAR)
        TEST_ASSERT_EQUAL_INT_MESSAGE(drawn, fast_walks, msg);
}

/* The LOD and AUTO's bounds take logarithms in three forms (64-bit,
 * 32-bit, soft-float mantissa): all must give fxl__log2_q8's value, which
 * the bounds' margins are worked out for, and stay within its stated
 * accuracy of the true log2. */
/* fxl__sf_dot2 (the AUTO set-up's |N|, auto.c) within its stated error of
 * the exact a b + sign c d: < 2^max(e_ab, e_cd) + 2^-30 |result|,
 * long double reference (exact for these 62-bit products on x86-64),
 * with mantissas at the extremes (INT32_MIN, 1, 0), exponents far apart
 * and near cancellation. */
void test_sf_dot2_within_its_error(void)
{
    static const int32_t edge[6] = {INT32_MIN, INT32_MAX, 1, -1, 0, 1 << 30};
    uint32_t st = 99u;
    int i, k, worst_i = -1;
    double worst = 0;
    char msg[160];
    for (i = 0; i < 400000; i++) {
        fxl__sf_t x[4], r;
        long double want, got, tol;
        const int sign = (i & 1) ? 1 : -1;
        for (k = 0; k < 4; k++) {
            st = st * 1664525u + 1013904223u;
            x[k].m = (i % 7 == 0) ? edge[(st >> 8) % 6] : (int32_t)(st ^ (st << 13));
            st = st * 1664525u + 1013904223u;
            x[k].e = (int)((st >> 16) % 160) - 80;
        }
        if (i % 5 == 0) {
            /* near cancellation: c d = a b, perturbed in the last bits */
            x[2] = x[0];
            x[3] = x[1];
            {
                const int64_t t = (int64_t)x[3].m + (int64_t)((st >> 20) & 3) - 1;
                x[3].m = t > INT32_MAX ? INT32_MAX : (t < INT32_MIN ? INT32_MIN : (int32_t)t);
            }
            if (sign > 0)
                x[2].m = x[2].m == INT32_MIN ? INT32_MAX : -x[2].m;
        }
        r = fxl__sf_dot2(x[0], x[1], x[2], x[3], sign);
        want = ldexpl((long double)x[0].m * x[1].m, x[0].e + x[1].e) +
               sign * ldexpl((long double)x[2].m * x[3].m, x[2].e + x[3].e);
        got = ldexpl((long double)r.m, r.e);
        tol = ldexpl(1.0L, x[0].e + x[1].e > x[2].e + x[3].e ? x[0].e + x[1].e : x[2].e + x[3].e) +
              ldexpl(fabsl(want), -30);
        snprintf(msg, sizeof msg, "case %d: %ld*2^%d * %ld*2^%d %c %ld*2^%d * %ld*2^%d", i, (long)x[0].m, x[0].e,
                 (long)x[1].m, x[1].e, sign > 0 ? '+' : '-', (long)x[2].m, x[2].e, (long)x[3].m, x[3].e);
        TEST_ASSERT_TRUE_MESSAGE(fabsl(got - want) <= tol, msg);
        if (tol > 0 && (double)(fabsl(got - want) / tol) > worst) {
            worst = (double)(fabsl(got - want) / tol);
            worst_i = i;
        }
    }
    snprintf(msg, sizeof msg, "worst error / stated bound %.3f (case %d)", worst, worst_i);
    TEST_MESSAGE(msg);
}

/* AUTO's affine segment length (auto.h, fxl__auto_fit_log2) from the log2
 * table's values of G and budget: L = 2^k must satisfy L^2 / 4 * G <=
 * budget for the true values (the table errs by up to 1.94 q8 steps; the
 * margin covers it), and 2 L must not, less 1% (the margin costs no more
 * than that). A geometric sweep of G < 2^30 and budget < 2^40. */
void test_auto_fit_log2_bounds_the_true_values(void)
{
#if !FXL_HAVE_AUTO
    TEST_NEEDS(FXL_HAVE_AUTO);
#else
    uint64_t g, b;
    long pairs = 0;
    for (g = 1; g < ((uint64_t)1 << 30); g += g / 16 + 1)
        for (b = 1; b < ((uint64_t)1 << 40); b += b / 256 + 1) {
            const int k = fxl__auto_fit_log2(fxl__log2_q8(g), fxl__log2_q8(b), 30);
            /* L^2 / 4 * G <= budget  <=>  4^k G <= 4 budget (k < 30: < 2^90, in long double's
             * 64-bit mantissa exactly as a power of two times G) */
            const long double lhs = ldexpl((long double)g, 2 * k), rhs = 4.0L * (long double)b;
            pairs++;
            if (k > 0 && lhs > rhs) {
                char msg[96];
                snprintf(msg, sizeof msg, "G %llu budget %llu: k %d too long", (unsigned long long)g,
                         (unsigned long long)b, k);
                TEST_FAIL_MESSAGE(msg);
            }
            if (k < 30 && 4.0L * lhs <= 0.99L * rhs) {
                char msg[96];
                snprintf(msg, sizeof msg, "G %llu budget %llu: k %d, %d fits", (unsigned long long)g,
                         (unsigned long long)b, k, k + 1);
                TEST_FAIL_MESSAGE(msg);
            }
        }
    TEST_ASSERT_GREATER_THAN(1000000, pairs);
#endif
}

void test_log2_q8_forms_agree(void)
{
#if !(FXL_HAVE_MIPMAP || FXL_HAVE_AUTO)
    TEST_NEEDS(FXL_HAVE_MIPMAP || FXL_HAVE_AUTO);
#else
    uint32_t x;
    int k, e;
    for (x = 1; x < (1u << 20); x++) {
        const int32_t want = fxl__log2_q8(x);
        /* non-decreasing (lod_bound's monotonic argument rests on it) */
        TEST_ASSERT_TRUE(x == 1u || want >= fxl__log2_q8(x - 1u));
        TEST_ASSERT_EQUAL_INT32(want, fxl__log2_q8_32(x));
        if (x >= 256)
            TEST_ASSERT_EQUAL_INT32(want, fxl__log2_q8_u32(x));
    }
    for (k = 1; k < 32; k++) {
        const uint32_t p = (uint32_t)1 << k;
        const uint32_t xs[3] = {p - 1u, p, p + 1u};
        int i;
        for (i = 0; i < 3; i++) {
            const int32_t got = fxl__log2_q8_32(xs[i]);
            const double truth = log2((double)xs[i]) * 256.0;
            TEST_ASSERT_EQUAL_INT32(fxl__log2_q8(xs[i]), got);
            TEST_ASSERT_TRUE(got > truth - 1.94 && got < truth + 0.5);
        }
    }
    TEST_ASSERT_EQUAL_INT32(fxl__log2_q8(0xFFFFFFFFu), fxl__log2_q8_32(0xFFFFFFFFu));
    for (e = -100; e <= 100; e += 37) {
        const int32_t ms[6] = {1, -1, 255, -256, INT32_MAX, INT32_MIN};
        int i;
        for (i = 0; i < 6; i++) {
            fxl__sf_t f;
            const uint64_t a = ms[i] < 0 ? (uint64_t)0 - (uint64_t)(int64_t)ms[i] : (uint64_t)ms[i];
            f.m = ms[i];
            f.e = e;
            TEST_ASSERT_EQUAL_INT32(fxl__log2_q8(a) + e * 256, fxl__sf_log2_q8(f));
        }
    }
    {
        fxl__sf_t z;
        z.m = 0;
        z.e = 5;
        TEST_ASSERT_EQUAL_INT32(INT32_MIN / 4, fxl__sf_log2_q8(z));
    }
#endif
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_lod_per_triangle_matches_lecture_values);
    RUN_TEST(test_lod_per_triangle_keeps_small_differences_and_texture_slivers_exact);
    RUN_TEST(test_lod_per_triangle_of_collinear_coordinates_is_level_0_per_segment_is_not);
    RUN_TEST(test_lod_per_segment_matches_exact_derivatives_on_floor);
    RUN_TEST(test_lod_per_segment_exact_at_extremes);
    RUN_TEST(test_lod_bound_holds_inside_the_triangle_and_settles_level_0);
    RUN_TEST(test_lod_bias_and_per_triangle_mode);
    RUN_TEST(test_trilinear_weights_blend_levels_by_lod_fraction);
    RUN_TEST(test_auto_lod_is_held_on_a_16_pixel_grid_whatever_the_clip);
    RUN_TEST(test_auto_spans_that_fit_the_cap_take_fixed_segments);
    RUN_TEST(test_mip_walks_with_depth_match_generic);
    RUN_TEST(test_log2_q8_forms_agree);
    RUN_TEST(test_auto_fit_log2_bounds_the_true_values);
    RUN_TEST(test_sf_dot2_within_its_error);
    return UNITY_END();
}
