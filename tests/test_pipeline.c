/* tests/test_pipeline.c - trigonometry, matrices, projection accuracy and the
 * mesh vertex path of the fixed-point front end, against double precision.
 *
 * The double reference takes the *same inputs* as the fixed-point code: the
 * q16 matrices and q16 positions converted exactly to double. So every
 * difference measured here is the front end's own arithmetic.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "test_rng.h"
#include "test_features.h"
#include "left_out.h"
#include "fixel/pipeline.h"
#include "meshes.h"
#include "crc32.h"

void setUp(void) {}
void tearDown(void) {}

static const double TWO_PI = 6.283185307179586476925286766559;
static char msg[256];

/* Deterministic generator (xorshift64*), seed fixed per test. */

static double q16d(fxl_q16_t v) { return v / 65536.0; }
static fxl_q16_t dq16(double v) { return (fxl_q16_t)lround(v * 65536.0); }

static void mat_to_d(const fxl_mat4_t *m, double d[4][4])
{
    int r, c;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) d[r][c] = q16d(m->m[r][c]);
}

static void matd_mul(double o[4][4], double a[4][4], double b[4][4])
{
    double t[4][4];
    int r, c, k;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            t[r][c] = 0;
            for (k = 0; k < 4; k++) t[r][c] += a[r][k] * b[k][c];
        }
    memcpy(o, t, sizeof t);
}

/* ---- trigonometry -------------------------------------------------------- */

static void test_sin_cos_max_error_over_all_angles(void)
{
    double max_err = 0;
    int32_t a, worst = 0;
    for (a = 0; a < 65536; a++) {
        fxl_q16_t s, c;
        double x = TWO_PI * a / 65536.0, es, ec;
        fxl_sincos_q16((fxl_angle_t)a, &s, &c);
        es = fabs(q16d(s) - sin(x));
        ec = fabs(q16d(c) - cos(x));
        if (es > max_err) { max_err = es; worst = a; }
        if (ec > max_err) { max_err = ec; worst = a; }
        TEST_ASSERT_EQUAL_INT32(s, fxl_sin_q16((fxl_angle_t)a));
        TEST_ASSERT_EQUAL_INT32(c, fxl_cos_q16((fxl_angle_t)a));
    }
    printf("sin/cos max error %.3g = 2^%.2f (angle %d)\n", max_err, log2(max_err), (int)worst);
    /* Bound: final rounding 2^-17 + Taylor truncation 2^-21.6 + q30 Horner
     * rounding (~6 * 2^-31) < 2^-17 + 2^-21 (trig.c). */
    snprintf(msg, sizeof msg, "max |sin/cos error| %.3g at angle %d", max_err, (int)worst);
    TEST_ASSERT_TRUE_MESSAGE(max_err <= ldexp(1, -17) + ldexp(1, -21), msg);
    /* the brief's requirement, for the record */
    TEST_ASSERT_TRUE(max_err <= ldexp(1, -15));
}

static void test_sin_cos_exact_at_quadrant_points(void)
{
    TEST_ASSERT_EQUAL_INT32(0, fxl_sin_q16(0));
    TEST_ASSERT_EQUAL_INT32(65536, fxl_cos_q16(0));
    TEST_ASSERT_EQUAL_INT32(65536, fxl_sin_q16(16384));
    TEST_ASSERT_EQUAL_INT32(0, fxl_cos_q16(16384));
    TEST_ASSERT_EQUAL_INT32(-65536, fxl_cos_q16(32768));
    TEST_ASSERT_EQUAL_INT32(-65536, fxl_sin_q16(49152));
    TEST_ASSERT_EQUAL_INT32(46341, fxl_sin_q16(8192)); /* round(2^16 / sqrt 2) */
}

/* Angle difference in 1/65536 turns, wrapped to (-32768, 32768]. */
static double angle_diff(double got, double want)
{
    double d = fmod(got - want, 65536.0);
    if (d > 32768) d -= 65536;
    if (d < -32768) d += 65536;
    return d;
}

static void test_atan2_error_within_half_lsb_plus_cordic(void)
{
    double max_err = 0;
    int i;
    rng_seed(7);
    for (i = 0; i < 200000; i++) {
        /* radius from 2^-16 to 2^15 (log-uniform) and any direction */
        double r = ldexp(1, -16 + (int)(rng_next() % 31)) * rng_range(1, 2);
        double th = rng_range(0, TWO_PI);
        fxl_q16_t x = dq16(r * cos(th)), y = dq16(r * sin(th));
        double want, e;
        if (x == 0 && y == 0) continue;
        want = atan2((double)y, (double)x) / TWO_PI * 65536.0;
        if (want < 0) want += 65536.0;
        e = fabs(angle_diff(fxl_atan2_angle(y, x), want));
        if (e > max_err) max_err = e;
        /* Bound: rounding 0.5 LSB + CORDIC 2^-27 turns = 2^-11 LSB. */
        if (e > 0.5 + ldexp(1, -11)) {
            snprintf(msg, sizeof msg, "atan2(%d, %d) = %u, want %.4f (err %.4f LSB)", (int)y, (int)x,
                     (unsigned)fxl_atan2_angle(y, x), want, e);
            TEST_FAIL_MESSAGE(msg);
        }
    }
    printf("atan2 max error %.6f LSB (1 LSB = 1/65536 turn)\n", max_err);
    TEST_ASSERT_EQUAL_UINT16(0, fxl_atan2_angle(0, 0));
    TEST_ASSERT_EQUAL_UINT16(16384, fxl_atan2_angle(5, 0));
    TEST_ASSERT_EQUAL_UINT16(32768, fxl_atan2_angle(0, -5));
    TEST_ASSERT_EQUAL_UINT16(49152, fxl_atan2_angle(-5, 0));
    TEST_ASSERT_EQUAL_UINT16(57344, fxl_atan2_angle(INT32_MIN + 1, INT32_MAX));
}

static void test_acos_asin_error_over_all_inputs(void)
{
    double max_c = 0, max_s = 0;
    int32_t v;
    for (v = -65536; v <= 65536; v++) {
        double wc = acos(v / 65536.0) / TWO_PI * 65536.0;
        double ws = asin(v / 65536.0) / TWO_PI * 65536.0;
        double ec = fabs(fxl_acos_angle(v) - wc), es = fabs(fxl_asin_angle(v) - ws);
        if (ec > max_c) max_c = ec;
        if (es > max_s) max_s = es;
        /* Bound: rounding 0.5 LSB; sqrt(1 - c^2) is floored in q30 (error
         * 2^-30 rad) and CORDIC adds 2^-11 LSB. */
        if (ec > 0.5 + ldexp(1, -10) || es > 0.5 + ldexp(1, -10)) {
            snprintf(msg, sizeof msg, "input %d: acos err %.4f, asin err %.4f LSB", (int)v, ec, es);
            TEST_FAIL_MESSAGE(msg);
        }
    }
    printf("acos max error %.6f LSB, asin %.6f LSB\n", max_c, max_s);
    TEST_ASSERT_EQUAL_INT32(32768, fxl_acos_angle(-2 * 65536)); /* clamped */
    TEST_ASSERT_EQUAL_INT32(-16384, fxl_asin_angle(-65536));
    /* clamped on both sides, for both functions */
    TEST_ASSERT_EQUAL_INT32(0, fxl_acos_angle(98304));
    TEST_ASSERT_EQUAL_INT32(16384, fxl_asin_angle(98304));
    TEST_ASSERT_EQUAL_INT32(-16384, fxl_asin_angle(-98304));
    TEST_ASSERT_EQUAL_INT32(0, fxl_acos_angle(INT32_MAX));
    TEST_ASSERT_EQUAL_INT32(32768, fxl_acos_angle(INT32_MIN));
}

/* ---- matrices -------------------------------------------------------------- */

static void test_rotations_match_double(void)
{
    int i, r, c;
    double max_err = 0;
    for (i = 0; i < 65536; i += 97) {
        fxl_mat4_t m[3];
        double x = TWO_PI * i / 65536.0, cs = cos(x), sn = sin(x);
        double want[3][3][3] = {
            {{1, 0, 0}, {0, cs, -sn}, {0, sn, cs}},
            {{cs, 0, sn}, {0, 1, 0}, {-sn, 0, cs}},
            {{cs, -sn, 0}, {sn, cs, 0}, {0, 0, 1}}};
        int k;
        fxl_mat4_rotate_x(&m[0], (fxl_angle_t)i);
        fxl_mat4_rotate_y(&m[1], (fxl_angle_t)i);
        fxl_mat4_rotate_z(&m[2], (fxl_angle_t)i);
        for (k = 0; k < 3; k++)
            for (r = 0; r < 3; r++)
                for (c = 0; c < 3; c++) {
                    double e = fabs(q16d(m[k].m[r][c]) - want[k][r][c]);
                    if (e > max_err) max_err = e;
                }
    }
    /* entries are the sin/cos values: same bound as above */
    TEST_ASSERT_TRUE(max_err <= ldexp(1, -17) + ldexp(1, -21));
}

static void test_rotate_axis_matches_rodrigues(void)
{
    double max_err = 0;
    int i;
    rng_seed(11);
    for (i = 0; i < 2000; i++) {
        double ax[3], len, x, cs, sn, a[3];
        fxl_vec3_t axis;
        fxl_mat4_t m;
        fxl_angle_t ang = (fxl_angle_t)(rng_next() & 0xFFFF);
        int r, c;
        ax[0] = rng_range(-1, 1); ax[1] = rng_range(-1, 1); ax[2] = rng_range(-1, 1);
        len = sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
        if (len < 0.1) continue;
        axis.x = dq16(ax[0] / len); axis.y = dq16(ax[1] / len); axis.z = dq16(ax[2] / len);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_rotate_axis(&m, &axis, ang));
        /* the rotation about the q16 axis's direction (it is made unit
         * length first) */
        a[0] = q16d(axis.x); a[1] = q16d(axis.y); a[2] = q16d(axis.z);
        len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        a[0] /= len; a[1] /= len; a[2] /= len;
        x = TWO_PI * ang / 65536.0; cs = cos(x); sn = sin(x);
        for (r = 0; r < 3; r++)
            for (c = 0; c < 3; c++) {
                double k = 0, want, e;
                if (r != c) {
                    int o = 3 - r - c;
                    k = ((r + 1) % 3 == c) ? -a[o] : a[o];
                }
                want = (r == c ? cs : 0) + (1 - cs) * a[r] * a[c] + sn * k;
                e = fabs(q16d(m.m[r][c]) - want);
                if (e > max_err) max_err = e;
            }
    }
    printf("rotate_axis max entry error %.3g (2^%.2f)\n", max_err, log2(max_err));
    /* Bound: rounding 2^-17 + sin/cos q30 error (2^-21) times at most 2 +
     * the q30 products' rounding (3 * 2^-31): under 2^-16. */
    TEST_ASSERT_TRUE(max_err < ldexp(1, -16));
}

static void test_rotate_axis_rejects_non_unit_axis(void)
{
    fxl_mat4_t m;
    fxl_vec3_t bad = {FXL_Q16_ONE * 2, 0, 0}, huge = {INT32_MAX, INT32_MAX, 0};
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_rotate_axis(&m, &bad, 100));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_rotate_axis(&m, &huge, 100));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_mat4_rotate_axis(NULL, &bad, 100));
}

/* An accepted axis that is not unit length (within 2^-8) still gives a
 * rotation: the axis is normalised first. Before the fifty-fifth session
 * (0, 65536 + 256, 0) at 180 degrees gave m[1][1] = 1.0157, scaling every
 * point on the axis by that. Off-axis directions at the tolerance's edge:
 * the matrix is orthonormal to 2^-15 and keeps its axis fixed. */
static void test_rotate_axis_of_tolerated_length_is_a_rotation(void)
{
    const fxl_vec3_t axes[] = {{0, 65536 + 256, 0}, {0, 65536 - 256, 0}, {37837, 37837, 37837},
                               {-37700, 37950, 37837}, {46521, 0, -46521}};
    const fxl_angle_t angles[] = {FXL_ANGLE_DEG(180), FXL_ANGLE_DEG(90), FXL_ANGLE_DEG(33), 12345};
    size_t i, j;
    int r, c, k;
    for (i = 0; i < sizeof axes / sizeof axes[0]; i++)
        for (j = 0; j < sizeof angles / sizeof angles[0]; j++) {
            fxl_mat4_t m;
            fxl_vec3_t on;
            double worst = 0;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_rotate_axis(&m, &axes[i], angles[j]));
            for (r = 0; r < 3; r++)
                for (c = 0; c < 3; c++) {
                    double dot = 0;
                    for (k = 0; k < 3; k++) dot += q16d(m.m[r][k]) * q16d(m.m[c][k]);
                    dot -= r == c ? 1.0 : 0.0;
                    if (fabs(dot) > worst) worst = fabs(dot);
                }
            snprintf(msg, sizeof msg, "axis %u angle %u: rows off orthonormal by %.3g", (unsigned)i, (unsigned)j,
                     worst);
            TEST_ASSERT_TRUE_MESSAGE(worst < ldexp(1, -15), msg);
            /* a point on the axis stays where it is */
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_transform_vector(&m, &axes[i], &on));
            TEST_ASSERT_INT32_WITHIN(8, axes[i].x, on.x);
            TEST_ASSERT_INT32_WITHIN(8, axes[i].y, on.y);
            TEST_ASSERT_INT32_WITHIN(8, axes[i].z, on.z);
        }
}

/* pipeline.h: |axis| = 1 within 2^-8. On a coordinate axis |a| is the q16
 * component itself, so the limits are 65536 +- 256 exactly; off the axes
 * one extra q16 unit of y already crosses them. */
static void test_rotate_axis_unit_tolerance_is_exactly_two_to_minus_8(void)
{
    fxl_mat4_t m;
    fxl_vec3_t a;
    const int32_t ok[] = {65536 + 256, 65536 - 256, -(65536 + 256), -(65536 - 256)};
    const int32_t bad[] = {65536 + 257, 65536 - 257, -(65536 + 257), -(65536 - 257)};
    int i;
    for (i = 0; i < 4; i++) {
        a.x = 0; a.y = ok[i]; a.z = 0;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_rotate_axis(&m, &a, 1000));
        a.y = bad[i];
        TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_rotate_axis(&m, &a, 1000));
    }
    a.x = 65536 + 256; a.y = 1; a.z = 0; /* |a|^2 exceeds (2^16 + 2^8)^2 by 1 */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_rotate_axis(&m, &a, 1000));
    a.x = 65536 - 256; /* |a|^2 = (2^16 - 2^8)^2 + 1: inside */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_rotate_axis(&m, &a, 1000));
}

static void test_mat4_mul_and_transform_match_double(void)
{
    fxl_mat4_t a, b, o, t;
    double da[4][4], db[4][4], dp[4][4];
    int r, c, i;
    double max_err = 0;
    rng_seed(3);
    for (i = 0; i < 1000; i++) {
        fxl_vec4_t v, out;
        double dv[4], dout;
        for (r = 0; r < 4; r++)
            for (c = 0; c < 4; c++) {
                a.m[r][c] = dq16(rng_range(-8, 8));
                b.m[r][c] = dq16(rng_range(-8, 8));
            }
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_mul(&o, &a, &b));
        mat_to_d(&a, da); mat_to_d(&b, db);
        matd_mul(dp, da, db);
        for (r = 0; r < 4; r++)
            for (c = 0; c < 4; c++) {
                /* exact q32 sum, rounded once: error <= 2^-17 */
                double e = fabs(q16d(o.m[r][c]) - dp[r][c]);
                if (e > max_err) max_err = e;
            }
        t = a; /* aliasing: out == a */
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_mul(&t, &t, &b));
        TEST_ASSERT_EQUAL_MEMORY(&o, &t, sizeof o);
        v.x = dq16(rng_range(-100, 100)); v.y = dq16(rng_range(-100, 100));
        v.z = dq16(rng_range(-100, 100)); v.w = FXL_Q16_ONE;
        dv[0] = q16d(v.x); dv[1] = q16d(v.y); dv[2] = q16d(v.z); dv[3] = 1;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_transform(&a, &v, &out));
        dout = da[0][0] * dv[0] + da[0][1] * dv[1] + da[0][2] * dv[2] + da[0][3];
        TEST_ASSERT_TRUE(fabs(q16d(out.x) - dout) <= ldexp(1, -17));
    }
    TEST_ASSERT_TRUE(max_err <= ldexp(1, -17));
}

static void test_mat4_mul_overflow_saturates_with_status(void)
{
    fxl_mat4_t a, o;
    fxl_vec4_t v = {FXL_Q16_INT(30000), 0, 0, FXL_Q16_ONE}, out;
    fxl_mat4_scale(&a, FXL_Q16_INT(300), FXL_Q16_ONE, FXL_Q16_ONE);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_mul(&o, &a, &a));
    TEST_ASSERT_EQUAL_INT32(INT32_MAX, o.m[0][0]);
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_ONE, o.m[1][1]);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_transform(&a, &v, &out));
    TEST_ASSERT_EQUAL_INT32(INT32_MAX, out.x);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_mat4_mul(NULL, &a, &a));
}

/* pipeline.h: points and directions ignore the fourth row, so a row that
 * overflows (here 1 * x + INT32_MAX * w) is neither computed nor reported;
 * the full fxl_mat4_transform does report it. */
static void test_transform_point_ignores_an_overflowing_fourth_row(void)
{
    fxl_mat4_t m;
    fxl_vec3_t p = {FXL_Q16_INT(3), FXL_Q16_INT(-2), FXL_Q16_ONE}, o;
    fxl_vec4_t v = {FXL_Q16_INT(3), FXL_Q16_INT(-2), FXL_Q16_ONE, FXL_Q16_ONE}, o4;
    fxl_mat4_identity(&m);
    m.m[3][0] = FXL_Q16_INT(30000);
    m.m[3][3] = INT32_MAX;
    m.m[0][3] = FXL_Q16_INT(5); /* translation: used by points, not by directions */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_transform_point(&m, &p, &o));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_INT(8), o.x);
    TEST_ASSERT_EQUAL_INT32(p.y, o.y);
    TEST_ASSERT_EQUAL_INT32(p.z, o.z);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_transform_vector(&m, &p, &o));
    TEST_ASSERT_EQUAL_INT32(p.x, o.x);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_transform(&m, &v, &o4));
    m.m[0][0] = INT32_MAX; /* the first three rows are still checked */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_transform_point(&m, &p, &o));
    TEST_ASSERT_EQUAL_INT32(INT32_MAX, o.x);
}

/* A negative entry whose four q32 products already overflow int64: each
 * is -(2^31 - 1)^2 ~ -2^62, their sum -2^64 + 2^34 - 4. pipeline.h: it
 * saturates to -INT32_MAX (not INT32_MIN) with FXL_ERR_RANGE. Wrapped
 * modulo 2^64 instead, the sum would read 2^34 - 4, i.e. +4.0 in q16,
 * "in range". */
static void test_mat4_mul_saturates_a_negative_int64_overflow(void)
{
    fxl_mat4_t a, b, o;
    int k;
    fxl_mat4_identity(&a);
    fxl_mat4_identity(&b);
    for (k = 0; k < 4; k++) {
        a.m[0][k] = INT32_MAX;
        b.m[k][0] = -INT32_MAX;
    }
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_mul(&o, &a, &b));
    TEST_ASSERT_EQUAL_INT32(-INT32_MAX, o.m[0][0]);
    /* the row and column's other entries are in range: a[0][k] * b[k][1]
     * = INT32_MAX * (k == 1) -> 2^31 - 1 q32 = 32768 - 2^-16 */
    TEST_ASSERT_EQUAL_INT32(INT32_MAX, o.m[0][1]);
}

/* pipeline.h: FXL_ERR_RANGE when up is within ~2^-16 rad of the view
 * direction (or opposite it). Looking down -z with up = (2^-16, 0, 2)
 * units the angle is atan(2^-17): refused, either sign of z; with up =
 * (4 2^-16, 0, 2) it is atan(2^-15): accepted. */
static void test_look_at_refuses_up_within_two_to_minus_16_of_the_view(void)
{
    fxl_mat4_t m;
    const fxl_vec3_t eye = {0, 0, 0}, ahead = {0, 0, -FXL_Q16_ONE};
    const fxl_vec3_t near_up = {1, 0, 2 * FXL_Q16_ONE}, near_down = {1, 0, -2 * FXL_Q16_ONE};
    const fxl_vec3_t tilted = {4, 0, 2 * FXL_Q16_ONE};
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_look_at(&m, &eye, &ahead, &near_up));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_look_at(&m, &eye, &ahead, &near_down));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_look_at(&m, &eye, &ahead, &tilted));
    /* the side vector s = (center - eye) x up = (0, -2^-14, 0) units,
     * normalised: the x row is (0, -1, 0) exactly */
    TEST_ASSERT_EQUAL_INT32(0, m.m[0][0]);
    TEST_ASSERT_EQUAL_INT32(-FXL_Q16_ONE, m.m[0][1]);
    TEST_ASSERT_EQUAL_INT32(0, m.m[0][2]);
}

static void test_perspective_matches_glu_formula(void)
{
    int deg;
    for (deg = 30; deg <= 120; deg += 5) {
        fxl_mat4_t m;
        fxl_angle_t fovy = FXL_ANGLE_DEG(deg);
        fxl_q16_t aspect = dq16(4.0 / 3.0), n = dq16(0.25), f = dq16(500);
        double fv = 1.0 / tan(TWO_PI * (fovy / 2.0) / 65536.0);
        double dn = q16d(n), df = q16d(f);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_perspective(&m, fovy, aspect, n, f));
        /* cot from q30 sin/cos: (2^-21.6 / s)(1 + cot) <= 0.36 LSB at 30 deg,
         * plus 0.5 LSB rounding; fx adds one more rounding of f / aspect. */
        snprintf(msg, sizeof msg, "fov %d: f %.6f want %.6f", deg, q16d(m.m[1][1]), fv);
        TEST_ASSERT_TRUE_MESSAGE(fabs(q16d(m.m[1][1]) - fv) <= 0.86 / 65536, msg);
        TEST_ASSERT_TRUE(fabs(q16d(m.m[0][0]) - fv / q16d(aspect)) <= 1.9 / 65536);
        TEST_ASSERT_TRUE(fabs(q16d(m.m[2][2]) - (df + dn) / (dn - df)) <= 0.5 / 65536);
        TEST_ASSERT_TRUE(fabs(q16d(m.m[2][3]) - 2 * df * dn / (dn - df)) <= 0.5 / 65536);
        TEST_ASSERT_EQUAL_INT32(-FXL_Q16_ONE, m.m[3][2]);
        TEST_ASSERT_EQUAL_INT32(0, m.m[3][3]);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_perspective(&m, fovy, aspect, n, 0));
        TEST_ASSERT_EQUAL_INT32(-FXL_Q16_ONE, m.m[2][2]);
        TEST_ASSERT_EQUAL_INT32(-2 * n, m.m[2][3]);
    }
    {
        fxl_mat4_t m;
        TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_perspective(&m, 0, 65536, 65536, 0));
        TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_perspective(&m, 32768, 65536, 65536, 0));
        TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_perspective(&m, 1000, 65536, 0, 0));
        TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_perspective(&m, 1000, 65536, 65536, 65536));
        TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_perspective(&m, 1000, 0, 65536, 0));
        /* 2 far near / (near - far) = -2147483647.23 (q16) fits: rounded once,
         * not twice (2 round(far near / d) = -2^31 was refused) */
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_perspective(&m, FXL_ANGLE_DEG(60), 65536, 2737093, 2744088));
        TEST_ASSERT_EQUAL_INT32(-2147483647, m.m[2][3]);
        /* near one unit larger: 2 far near / (near - far) = -32772.7, refused */
        TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_perspective(&m, FXL_ANGLE_DEG(60), 65536, 2737094, 2744088));
    }
}

/* Every fovy from 1 to 32767, odd ones included (fovy / 2 keeps its half
 * unit): f = cot(fovy / 2) within the bound derived from the q30 sin and
 * cos error e = 2^-21 + 2^-29 (pipeline_int.h): |d cot| <= e (1 + cot) / s
 * to first order (the margin 1.01 covers the second), plus 0.5 LSB for
 * rounding. Where that bound straddles INT32_MAX either status is right;
 * above it, FXL_ERR_RANGE. fovy = 1 fits: cot = 20860.76. */
static void test_perspective_every_fovy_within_derived_bound(void)
{
    const double e = ldexp(1, -21) + ldexp(1, -29);
    double worst = 0, worst_ratio = 0;
    uint32_t fovy, ok = 0;
    for (fovy = 1; fovy < 32768u; fovy++) {
        fxl_mat4_t m;
        double half = TWO_PI * fovy / 131072.0, s = sin(half), cot = cos(half) / s;
        double bound = (1.01 * e * (1 + cot) / s) * 65536.0 + 0.5; /* q16 LSB */
        double want = cot * 65536.0;
        fxl_status_t st = fxl_mat4_perspective(&m, (fxl_angle_t)fovy, FXL_Q16_ONE, FXL_Q16_ONE, 0);
        if (want - bound > (double)INT32_MAX) {
            TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, st);
            continue;
        }
        if (want + bound >= (double)INT32_MAX) continue;
        snprintf(msg, sizeof msg, "fovy %u: status %d", (unsigned)fovy, (int)st);
        TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_OK, st, msg);
        {
            double err = fabs((double)m.m[1][1] - want);
            snprintf(msg, sizeof msg, "fovy %u: f %ld want %.3f bound %.3f", (unsigned)fovy,
                     (long)m.m[1][1], want, bound);
            TEST_ASSERT_TRUE_MESSAGE(err <= bound, msg);
            if (err > worst) worst = err;
            if (err / bound > worst_ratio) worst_ratio = err / bound;
        }
        TEST_ASSERT_EQUAL_INT32(m.m[1][1], m.m[0][0]); /* aspect 1 */
        ok++;
    }
    printf("perspective: %u fovy values, max |f - cot(fovy/2)| %.3f LSB, max error/bound %.3f\n",
           (unsigned)ok, worst, worst_ratio);
    TEST_ASSERT_EQUAL_UINT32(32767u, ok);
}

/* gluLookAt in double from the q16 inputs as given: the rows s, u, -f and
 * the translation. Returns sin(angle between up and the view direction). */
static double look_at_ref(const fxl_vec3_t *fe, const fxl_vec3_t *fc, const fxl_vec3_t *fu, double want[3][4])
{
    double e[3], f[3], up[3], s[3], u[3], len, upl;
    int k;
    e[0] = q16d(fe->x); e[1] = q16d(fe->y); e[2] = q16d(fe->z);
    f[0] = q16d(fc->x) - e[0]; f[1] = q16d(fc->y) - e[1]; f[2] = q16d(fc->z) - e[2];
    up[0] = q16d(fu->x); up[1] = q16d(fu->y); up[2] = q16d(fu->z);
    len = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (k = 0; k < 3; k++) f[k] /= len;
    upl = sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
    s[0] = f[1] * up[2] - f[2] * up[1]; s[1] = f[2] * up[0] - f[0] * up[2];
    s[2] = f[0] * up[1] - f[1] * up[0];
    len = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (k = 0; k < 3; k++) s[k] /= len;
    u[0] = s[1] * f[2] - s[2] * f[1]; u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    for (k = 0; k < 3; k++) { want[0][k] = s[k]; want[1][k] = u[k]; want[2][k] = -f[k]; }
    want[0][3] = -(s[0] * e[0] + s[1] * e[1] + s[2] * e[2]);
    want[1][3] = -(u[0] * e[0] + u[1] * e[1] + u[2] * e[2]);
    want[2][3] = f[0] * e[0] + f[1] * e[1] + f[2] * e[2];
    return len / upl;
}

/* The translation bound of a look-at from eye: |eye| (units) times the
 * 2^-28 error of each q30 unit vector, three terms, plus the 2^-17 of the
 * q16 rounding. */
static double look_at_t_bound(const fxl_vec3_t *fe)
{
    const double x = q16d(fe->x), y = q16d(fe->y), z = q16d(fe->z);
    return ldexp(1, -17) + 3.0 * sqrt(x * x + y * y + z * z) * ldexp(1, -28);
}

/* Largest |m - want| over the rotation entries (rot) and translations (t). */
static void look_at_err(const fxl_mat4_t *m, double want[3][4], double *rot, double *t)
{
    int r, k;
    for (r = 0; r < 3; r++) {
        for (k = 0; k < 3; k++) {
            double er = fabs(q16d(m->m[r][k]) - want[r][k]);
            if (er > *rot) *rot = er;
        }
        if (fabs(q16d(m->m[r][3]) - want[r][3]) > *t) *t = fabs(q16d(m->m[r][3]) - want[r][3]);
    }
}

/* One look-at against its reference: the rotation entries within 2^-17 +
 * 2^-26, the translations within look_at_t_bound of eye fe. *rot, *t: the
 * largest errors; what names the case in a failure message. */
static void look_at_check(const fxl_mat4_t *m, double want[3][4], const fxl_vec3_t *fe, const char *what, double *rot,
                          double *t)
{
    const double tb = look_at_t_bound(fe);
    *rot = *t = 0;
    look_at_err(m, want, rot, t);
    snprintf(msg, sizeof msg, "%s: rotation error %.3g (q16 units %.2f), translation %.3g (bound %.3g)", what, *rot,
             *rot * 65536.0, *t, tb);
    TEST_ASSERT_TRUE_MESSAGE(*rot <= ldexp(1, -17) + ldexp(1, -26), msg);
    TEST_ASSERT_TRUE_MESSAGE(*t < tb, msg);
}

static void test_look_at_matches_double(void)
{
    int i;
    double max_rot = 0, max_t = 0;
    rng_seed(5);
    for (i = 0; i < 2000; i++) {
        double want[3][4];
        fxl_vec3_t fe, fc, fu = {0, FXL_Q16_ONE, 0};
        fxl_mat4_t m;
        fe.x = dq16(rng_range(-500, 500)); fe.y = dq16(rng_range(-500, 500)); fe.z = dq16(rng_range(-500, 500));
        fc.x = dq16(rng_range(-500, 500)); fc.y = dq16(rng_range(-500, 500)); fc.z = dq16(rng_range(-500, 500));
        if (look_at_ref(&fe, &fc, &fu, want) < 0.05) continue;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_look_at(&m, &fe, &fc, &fu));
        look_at_err(&m, want, &max_rot, &max_t);
    }
    printf("look_at max error: rotation %.3g, translation %.3g\n", max_rot, max_t);
    /* Rotation: q30 unit vectors (a few 2^-30) rounded to q16: <= 2^-17 +
     * 2^-26. Translation: |eye| <= 870 times the 2^-28 unit-vector error,
     * three terms, plus 2^-17 rounding: < 2^-17 + 3 * 870 * 2^-28 < 2^-16. */
    TEST_ASSERT_TRUE(max_rot <= ldexp(1, -17) + ldexp(1, -26));
    TEST_ASSERT_TRUE(max_t < ldexp(1, -16));
    /* The q16 range's extremes: center at a corner, eye halfway to the
     * opposite one, up as long as q16 allows, any direction (the cross
     * product's terms near 2^63 and their differences beyond). */
    max_rot = max_t = 0;
    for (i = 0; i < 2000; i++) {
        double want[3][4], rot, t;
        char what[32];
        fxl_vec3_t fe, fc, fu;
        fxl_mat4_t m;
        /* |eye| < 2^15 (the translations fit q16), center - eye up to
         * 49,150 units a component */
        fe.x = (rng_next() & 1) ? 16383 * 65536 : -16383 * 65536;
        fe.y = (rng_next() & 1) ? 16383 * 65536 : -16383 * 65536;
        fe.z = dq16(rng_range(-16383, 16383));
        fc.x = fe.x > 0 ? -32767 * 65536 : 32767 * 65536;
        fc.y = fe.y > 0 ? -32767 * 65536 : 32767 * 65536;
        fc.z = dq16(rng_range(-32767, 32767));
        fu.x = dq16(rng_range(-32767, 32767)); fu.y = dq16(rng_range(-32767, 32767)); fu.z = dq16(rng_range(-32767, 32767));
        if (look_at_ref(&fe, &fc, &fu, want) < 0.05) continue;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_look_at(&m, &fe, &fc, &fu));
        snprintf(what, sizeof what, "corner case %d", i);
        look_at_check(&m, want, &fe, what, &rot, &t);
        if (rot > max_rot) max_rot = rot;
        if (t > max_t) max_t = t;
    }
    printf("look_at at the q16 range's corners: rotation %.3g, translation %.3g\n", max_rot, max_t);
    {
        fxl_mat4_t m;
        fxl_vec3_t a = {0, 0, 0}, up = {0, FXL_Q16_ONE, 0}, above = {0, FXL_Q16_INT(3), 0};
        TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_look_at(&m, &a, &a, &up));
        TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mat4_look_at(&m, &a, &above, &up));
    }
}

/* up nearly along the view direction, at angles from 2^-17 to 2^-3 rad
 * (refused below ~2^-16.8: there either status is right, and an accepted
 * one is checked too), with view vectors and up of any length the q16
 * inputs allow: the rotation keeps the bound of the well-conditioned case
 * above, and the translation its per-eye bound. Crossing f and up after
 * rounding each to q30 erred by a few 2^-30 / sin(angle): up to 10 q16
 * units of rotation near the limit (a review's search: 10.1 at sin 1.3e-5). */
static void test_look_at_up_near_the_view_direction(void)
{
    int i, n = 0, refused = 0, near_limit = 0;
    double max_rot = 0, max_t = 0, min_sin = 1;
    rng_seed(77);
    for (i = 0; i < 4000; i++) {
        double want[3][4], d[3], p[3], len, pl, th, dl, ul, sn;
        fxl_vec3_t fe, fc, fu;
        fxl_mat4_t m;
        fxl_status_t st;
        int k;
        /* view vector of length 2^-4 .. 2^14 units, eye within 2^14; every
         * fourth case center at the q16 range's edge and eye halfway to the
         * opposite one (center - eye up to 1.5 2^31 q16 units, up 2^31) */
        for (k = 0; k < 3; k++) d[k] = rng_range(-1, 1);
        len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (len < 0.1) continue;
        if (i % 4 == 3) {
            const double c = 32767.0 / (fabs(d[0]) > fabs(d[1]) ? (fabs(d[0]) > fabs(d[2]) ? fabs(d[0]) : fabs(d[2]))
                                                                 : (fabs(d[1]) > fabs(d[2]) ? fabs(d[1]) : fabs(d[2])));
            fe.x = dq16(-d[0] * c / 2); fe.y = dq16(-d[1] * c / 2); fe.z = dq16(-d[2] * c / 2);
            fc.x = dq16(d[0] * c); fc.y = dq16(d[1] * c); fc.z = dq16(d[2] * c);
        } else {
            dl = ldexp(1, -4 + (int)(rng_next() % 18)) * rng_range(1, 2);
            fe.x = dq16(rng_range(-16384, 16384)); fe.y = dq16(rng_range(-16384, 16384)); fe.z = dq16(rng_range(-16384, 16384));
            fc.x = fe.x + dq16(d[0] / len * dl); fc.y = fe.y + dq16(d[1] / len * dl); fc.z = fe.z + dq16(d[2] / len * dl);
        }
        /* up = unit(d) cos(th) + unit(p) sin(th), p perpendicular to d, of
         * length 2^-2 .. 2^14; the q16 rounding of short vectors tilts them
         * by up to ~2^-12 rad, so the angle checked is the inputs' own (sn) */
        for (k = 0; k < 3; k++) p[k] = rng_range(-1, 1);
        pl = (p[0] * d[0] + p[1] * d[1] + p[2] * d[2]) / (len * len);
        for (k = 0; k < 3; k++) p[k] -= pl * d[k];
        pl = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        if (pl < 0.1) continue;
        th = ldexp(1, -17 + (int)(rng_next() % 14)) * rng_range(1, 2);
        ul = i % 4 == 3 ? 32767.0 : ldexp(1, -2 + (int)(rng_next() % 16)) * rng_range(1, 2);
        fu.x = dq16(ul * (cos(th) * d[0] / len + sin(th) * p[0] / pl));
        fu.y = dq16(ul * (cos(th) * d[1] / len + sin(th) * p[1] / pl));
        fu.z = dq16(ul * (cos(th) * d[2] / len + sin(th) * p[2] / pl));
        if (rng_next() & 1) { fu.x = -fu.x; fu.y = -fu.y; fu.z = -fu.z; }
        sn = look_at_ref(&fe, &fc, &fu, want);
        st = fxl_mat4_look_at(&m, &fe, &fc, &fu);
        snprintf(msg, sizeof msg, "case %d: sin %.3g status %d", i, sn, (int)st);
        if (sn >= ldexp(1, -15))
            TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_OK, st, msg);
        if (st != FXL_OK) {
            refused++;
            continue;
        }
        {
            double rot, t;
            char what[48];
            snprintf(what, sizeof what, "case %d: sin %.3g", i, sn);
            look_at_check(&m, want, &fe, what, &rot, &t);
            if (rot > max_rot) max_rot = rot;
            if (t / look_at_t_bound(&fe) > max_t) max_t = t / look_at_t_bound(&fe);
        }
        if (sn < min_sin) min_sin = sn;
        if (sn < ldexp(1, -16)) near_limit++;
        n++;
    }
    printf("look_at, up near the view direction: %d accepted (%d below sin 2^-16), %d refused, sin down to %.3g: "
           "max error rotation %.3g, translation %.3f of its bound\n", n, near_limit, refused, min_sin, max_rot, max_t);
    TEST_ASSERT_TRUE(n > 3000);
    TEST_ASSERT_TRUE(near_limit > 20);
}

/* ---- projection accuracy target ------------------------------------------- */

/* Random rigid transform (rotation from three angles, translation t). */
static void random_rigid(fxl_mat4_t *m, double tmax)
{
    fxl_mat4_t rx, ry, rz, tr;
    fxl_mat4_rotate_x(&rx, (fxl_angle_t)(rng_next() & 0xFFFF));
    fxl_mat4_rotate_y(&ry, (fxl_angle_t)(rng_next() & 0xFFFF));
    fxl_mat4_rotate_z(&rz, (fxl_angle_t)(rng_next() & 0xFFFF));
    fxl_mat4_translate(&tr, dq16(rng_range(-tmax, tmax)), dq16(rng_range(-tmax, tmax)),
                       dq16(rng_range(-tmax, tmax)));
    fxl_mat4_mul(m, &rx, &ry);
    fxl_mat4_mul(m, m, &rz);
    fxl_mat4_mul(m, &tr, m);
}

/* Invert an affine double matrix (rotation part inverted in full). */
static void affine_inverse(double m[4][4], double inv[4][4])
{
    double a = m[0][0], b = m[0][1], c = m[0][2], d = m[1][0], e = m[1][1], f = m[1][2];
    double g = m[2][0], h = m[2][1], k = m[2][2];
    double det = a * (e * k - f * h) - b * (d * k - f * g) + c * (d * h - e * g);
    int r;
    inv[0][0] = (e * k - f * h) / det; inv[0][1] = (c * h - b * k) / det; inv[0][2] = (b * f - c * e) / det;
    inv[1][0] = (f * g - d * k) / det; inv[1][1] = (a * k - c * g) / det; inv[1][2] = (c * d - a * f) / det;
    inv[2][0] = (d * h - e * g) / det; inv[2][1] = (b * g - a * h) / det; inv[2][2] = (a * e - b * d) / det;
    for (r = 0; r < 3; r++)
        inv[r][3] = -(inv[r][0] * m[0][3] + inv[r][1] * m[1][3] + inv[r][2] * m[2][3]);
    inv[3][0] = inv[3][1] = inv[3][2] = 0;
    inv[3][3] = 1;
}

static void test_projection_accuracy_target_random_meshes(void)
{
    static const double nears[] = {0.05, 0.1, 0.3, 1, 3, 10};
    int ni;
    double worst_px = 0, worst_iw = 0;
    long checked = 0;
    rng_seed(20240611);
    for (ni = 0; ni < 6; ni++) {
        double n = nears[ni], max_px = 0, max_iw = 0;
        int mesh;
        for (mesh = 0; mesh < 20; mesh++) {
            fxl_pipeline_t p;
            fxl_xform_t xf;
            double dm[4][4], dv[4][4], dp[4][4], mv[4][4], mvp[4][4], inv[4][4];
            int v;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(&p, 320, 240));
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_set_perspective(
                                              &p, FXL_ANGLE_DEG(60), dq16(4.0 / 3.0), dq16(n),
                                              (mesh & 1) ? 0 : dq16(n * 2000)));
            random_rigid(&p.model, 2 * n);
            random_rigid(&p.view, 50 * n);
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_prepare(&p, &xf));
            mat_to_d(&p.model, dm); mat_to_d(&p.view, dv); mat_to_d(&p.proj, dp);
            matd_mul(mv, dv, dm);
            matd_mul(mvp, dp, mv);
            affine_inverse(mv, inv);
            for (v = 0; v < 200; v++) {
                /* a view-space point at depth near .. 1000 near (log-uniform)
                 * inside the frustum, mapped back to object space */
                double depth = n * pow(1000.0, rng_unit());
                double ve[3], ob[3], c[4], sx, sy, iw, e;
                fxl_vec3_t pos;
                fxl_clipvert_t cv;
                fxl_vertex_t out;
                int r;
                ve[0] = rng_range(-1, 1) * depth * 0.77;
                ve[1] = rng_range(-1, 1) * depth * 0.58;
                ve[2] = -depth;
                for (r = 0; r < 3; r++) ob[r] = inv[r][0] * ve[0] + inv[r][1] * ve[1] + inv[r][2] * ve[2] + inv[r][3];
                pos.x = dq16(ob[0]); pos.y = dq16(ob[1]); pos.z = dq16(ob[2]);
                for (r = 0; r < 4; r++)
                    c[r] = mvp[r][0] * q16d(pos.x) + mvp[r][1] * q16d(pos.y) + mvp[r][2] * q16d(pos.z) + mvp[r][3];
                if (c[3] < q16d(p.near_q16) * (1 + 1e-9)) continue; /* rounded in front of near */
                sx = 160.0 + c[0] / c[3] * 160.0;
                sy = 120.0 - c[1] / c[3] * 120.0;
                iw = q16d(p.near_q16) / c[3] * 4294967295.0;
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_clip(&xf, &pos, &cv));
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_project(&xf, &cv, &out));
                e = fmax(fabs(q16d(out.x) - sx), fabs(q16d(out.y) - sy));
                if (e > max_px) max_px = e;
                if (fabs(out.inv_w - iw) / iw > max_iw) max_iw = fabs(out.inv_w - iw) / iw;
                /* The target: 1/16 px and 2^-12 relative. */
                if (e > 1.0 / 16 || fabs(out.inv_w - iw) / iw > ldexp(1, -12)) {
                    snprintf(msg, sizeof msg, "near %g depth %g: (%.5f, %.5f) want (%.5f, %.5f), inv_w %u want %.1f",
                             n, depth, q16d(out.x), q16d(out.y), sx, sy, (unsigned)out.inv_w, iw);
                    TEST_FAIL_MESSAGE(msg);
                }
                checked++;
            }
        }
        printf("near %5.2f: max |xy error| %.3g px (2^%.1f), max inv_w rel error %.3g (2^%.1f)\n", n,
               max_px, log2(max_px), max_iw, log2(max_iw));
        if (max_px > worst_px) worst_px = max_px;
        if (max_iw > worst_iw) worst_iw = max_iw;
    }
    printf("projection: %ld vertices, worst %.3g px, inv_w %.3g\n", checked, worst_px, worst_iw);
    TEST_ASSERT_GREATER_THAN(20000, checked);
    /* Derived bound, far tighter than the target: clip coordinates carry
     * ~2^-32 units of rounding per term on |object| <= ~1000 near (2^-33 *
     * 3 * 1000 / near relative), the divide 2^-30: at 160 px per unit ndc
     * and the q16 output rounding of 2^-17 px, < 2^-12 px. */
    TEST_ASSERT_TRUE(worst_px < ldexp(1, -12));
    /* inv_w: 31-bit reciprocal and the +-1 unit between near/w * 2^32 and
     * near/w * (2^32 - 1); at w = 1000 near inv_w ~ 2^22: < 2^-20. */
    TEST_ASSERT_TRUE(worst_iw < ldexp(1, -20));
}

/* A default 320 x 240 pipeline, its transform, and a zeroed clip vertex. */
static void prepared_320x240(fxl_pipeline_t *p, fxl_xform_t *xf, fxl_clipvert_t *c)
{
    memset(c, 0, sizeof *c);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(p, 320, 240));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_prepare(p, xf));
}

static void test_project_rejects_w_at_or_behind_near(void)
{
    fxl_pipeline_t p;
    fxl_xform_t xf;
    fxl_clipvert_t c;
    fxl_vertex_t out;
    prepared_320x240(&p, &xf, &c);
    c.w = 0;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_xform_project(&xf, &c, &out));
    c.w = -((int64_t)1 << 32);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_xform_project(&xf, &c, &out));
    c.w = xf.near_q32 - 1;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_xform_project(&xf, &c, &out));
    c.w = xf.near_q32;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_project(&xf, &c, &out));
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFFu, out.inv_w);
    TEST_ASSERT_EQUAL_INT32(160 * 65536, out.x);
    TEST_ASSERT_EQUAL_INT32(120 * 65536, out.y);
    c.x = c.w * 1000; /* far outside the guard band: not clipped */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_xform_project(&xf, &c, &out));
    /* the clipper's rounding tolerance is 2^-10 of the guard band G: 1.0001 G
     * is accepted (and clamped to G), 1.01 G was not clipped: refused */
    c.x = (int64_t)((double)c.w * xf.guard_q16 / 65536.0 * 1.0001);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_project(&xf, &c, &out));
    c.x = (int64_t)((double)c.w * xf.guard_q16 / 65536.0 * 1.01);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_xform_project(&xf, &c, &out));
}

/* pipeline.h: a vertex beyond the guard band by less than 2^-10 G is
 * clamped to it. On 320 x 240, G = floor(8192 2^17 / 320) 2^-16 =
 * 3355443 / 65536 and the half width is 160 px, so x / w = +-1.0001 G
 * lands on 160 +- 3355443 * 160 / 65536 px = (160 * 65536 +- 536870880)
 * q16 units exactly, 1.0001 G or not (unclamped: 0.8 px further). */
static void test_project_clamps_a_vertex_just_beyond_the_guard_band(void)
{
    fxl_pipeline_t p;
    fxl_xform_t xf;
    fxl_clipvert_t c;
    fxl_vertex_t out;
    prepared_320x240(&p, &xf, &c);
    TEST_ASSERT_EQUAL_INT32(3355443, xf.guard_q16);
    c.w = xf.near_q32 * 2;
    c.x = (int64_t)((double)c.w * xf.guard_q16 / 65536.0 * 1.0001);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_project(&xf, &c, &out));
    TEST_ASSERT_EQUAL_INT32(160 * 65536 + 536870880, out.x);
    c.x = -c.x;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_project(&xf, &c, &out));
    TEST_ASSERT_EQUAL_INT32(160 * 65536 - 536870880, out.x);
}

/* pipeline.h: fxl_xform_clip refuses a coordinate that reaches
 * FXL_CLIP_LIMIT_Q32 and fxl_xform_project a w at it; below it both work,
 * and inv_w = near / w * 2^32 is clamped to at least 1. Model scale z 32
 * and z = -32768 units (INT32_MIN q16) give w = -z_view = 2^20 units =
 * 2^52 q32 exactly (the default perspective's w row is (0, 0, -1, 0)).
 * With near 2^-16 (the smallest) and w = 2^52 - 1 q32, near / w * 2^32 is
 * 2^-4: clamped to 1. */
static void test_clip_limit_and_smallest_inv_w(void)
{
    fxl_pipeline_t p;
    fxl_xform_t xf;
    fxl_clipvert_t c;
    fxl_vertex_t out;
    fxl_vec3_t pos = {0, 0, INT32_MIN};
    prepared_320x240(&p, &xf, &c);
    fxl_mat4_scale(&p.model, FXL_Q16_ONE, FXL_Q16_ONE, FXL_Q16_INT(32));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_prepare(&p, &xf));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_xform_clip(&xf, &pos, &c));
    pos.z = INT32_MIN + 1; /* w = 2^52 - 2^21 */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_clip(&xf, &pos, &c));
    TEST_ASSERT_EQUAL_INT64(FXL_CLIP_LIMIT_Q32 - ((int64_t)1 << 21), c.w);
    p.near_q16 = 1;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_prepare(&p, &xf));
    memset(&c, 0, sizeof c);
    c.w = FXL_CLIP_LIMIT_Q32;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_xform_project(&xf, &c, &out));
    c.w = FXL_CLIP_LIMIT_Q32 - 1;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_project(&xf, &c, &out));
    TEST_ASSERT_EQUAL_UINT32(1, out.inv_w);
    TEST_ASSERT_EQUAL_INT32(160 * 65536, out.x);
}

/* The colour of a projected vertex: each channel (0..255 in q8) rounded
 * to 5 or 6 bits, round(c (2^bits - 1) / 65280), for every value in range;
 * every RGB565 colour survives the trip through q8 channels; outside the
 * range channels are clamped (a negative channel once packed as full
 * intensity through a truncating division and an unsigned cast). */
static void test_project_packs_channels_rounded_and_clamped(void)
{
    fxl_pipeline_t p;
    fxl_xform_t xf;
    fxl_clipvert_t c;
    fxl_vertex_t out;
    int32_t ch;
    static const int32_t beyond[] = {INT32_MIN, -70000, -3159, -1, 65281, 70000, INT32_MAX};
    size_t i;
    prepared_320x240(&p, &xf, &c);
    c.w = xf.near_q32 * 2;
    for (ch = 0; ch <= 65280; ch++) {
        const uint32_t r5 = (uint32_t)floor(ch * 31.0 / 65280.0 + 0.5);
        const uint32_t g6 = (uint32_t)floor(ch * 63.0 / 65280.0 + 0.5);
        const uint32_t b5 = (uint32_t)floor((65280 - ch) * 31.0 / 65280.0 + 0.5);
        c.r = ch;
        c.g = ch;
        c.b = 65280 - ch;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_project(&xf, &c, &out));
        TEST_ASSERT_EQUAL_HEX16((r5 << 11) | (g6 << 5) | b5, out.color);
    }
    /* Every RGB565 colour as q8 channels (round(c 65280 / (2^bits - 1)),
     * as the mesh path carries a vertex colour through the clipper) packs
     * back to itself: the mesh path's triangles inside every clip plane
     * keep the colour as it is (pipeline.c, project_inside). */
    for (i = 0; i < 65536u; i++) {
        c.r = (int32_t)floor((double)(i >> 11) * 65280.0 / 31.0 + 0.5);
        c.g = (int32_t)floor((double)((i >> 5) & 63u) * 65280.0 / 63.0 + 0.5);
        c.b = (int32_t)floor((double)(i & 31u) * 65280.0 / 31.0 + 0.5);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_project(&xf, &c, &out));
        TEST_ASSERT_EQUAL_HEX16(i, out.color);
    }
    for (i = 0; i < sizeof beyond / sizeof beyond[0]; i++) {
        const uint16_t want = beyond[i] < 0 ? 0x0000u : 0xFFFFu;
        c.r = c.g = c.b = beyond[i];
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_project(&xf, &c, &out));
        TEST_ASSERT_EQUAL_HEX16(want, out.color);
    }
}

/* A hand-filled fxl_xform_t outside the ranges fxl_pipeline_prepare gives
 * is refused by the projection and the clipper (it once reached a shift by
 * ~2^32 with near below 2^-16, a left shift of a negative guard band and
 * overflowing plane distances), while every edge of those ranges that
 * prepare produces is accepted. */
static void test_project_and_clip_refuse_a_hand_filled_xform_out_of_range(void)
{
    fxl_pipeline_t p;
    fxl_xform_t ok, xf;
    fxl_clipvert_t c, tri[3], poly[FXL_CLIP_MAX_VERTS];
    fxl_vertex_t out;
    uint32_t n;
    int k;
    prepared_320x240(&p, &ok, &c);
    c.w = (int64_t)1 << 33;
    for (k = 0; k < 3; k++)
        tri[k] = c;
    tri[1].x = c.w / 2;
    tri[2].y = c.w / 2;
    for (k = 0; k < 13; k++) {
        xf = ok;
        switch (k) {
        case 0: xf.near_q32 = 1; break;
        case 1: xf.near_q32 = 65535; break;
        case 2: xf.near_q32 = INT64_MAX - 1; break;
        case 3: xf.far_q32 = INT64_MIN + 1; break;
        case 4: xf.far_q32 = xf.near_q32; break;
        case 5: xf.guard_q16 = -1; break;
        case 6: xf.guard_q16 = 0; break;
        case 7: xf.guard_q16 = (int32_t)FXL_GUARD_MAX << 16; break; /* G x 160 px > FXL_GUARD_PX */
        case 8: xf.hw_q16 = 0; break;
        case 9: xf.hh_q16 = (int64_t)FXL_TARGET_MAX_DIM * 32768 + 1; break;
        case 10: xf.cx_q16 = INT64_MIN; break;
        case 11: xf.guard_q16 = 65535; break; /* G below 1 */
        default: xf.cy_q16 = ((int64_t)2 * FXL_TARGET_MAX_ORIGIN + FXL_TARGET_MAX_DIM) * 32768 + 1; break;
        }
        c.w = xf.near_q32 > 0 && xf.near_q32 < ((int64_t)1 << 50) ? xf.near_q32 : (int64_t)1 << 33;
        TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_RANGE, fxl_xform_project(&xf, &c, &out), "project");
        n = 7;
        TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_RANGE, fxl_clip_triangle(&xf, tri, poly, &n), "clip");
        TEST_ASSERT_EQUAL_UINT32(0, n);
    }
    /* prepare's extremes: near 2^-16 and far 2^15 - 2^-16, the smallest and
     * largest viewports at the farthest origins */
    p.near_q16 = 1;
    p.far_q16 = INT32_MAX;
    for (k = 0; k < 4; k++) {
        const int32_t side = k & 1 ? FXL_TARGET_MAX_DIM : 1;
        const int32_t o = k & 2 ? FXL_TARGET_MAX_ORIGIN : -FXL_TARGET_MAX_ORIGIN;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_set_viewport(&p, o, o, side, side));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_prepare(&p, &xf));
        c.w = xf.near_q32;
        c.x = c.y = 0;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_project(&xf, &c, &out));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_clip_triangle(&xf, tri, poly, &n));
    }
}

/* One q16 unit past each edge of the ranges fxl_xform_project documents
 * for a hand-filled xf, from an xf at all of them at once: a 4096 x 4096
 * viewport at origin (16384, 16384) has its centre at FXL_TARGET_MAX_ORIGIN
 * + FXL_TARGET_MAX_DIM / 2 px, half sizes FXL_TARGET_MAX_DIM / 2 px and G =
 * 8192 / 2048 = 4, so G times the half size is FXL_GUARD_PX exactly. A
 * half size one unit over is tried with G = 2, so that it is the half size
 * alone that is refused. */
static void test_project_xform_refused_one_unit_past_each_range(void)
{
    const int64_t centre_max = ((int64_t)FXL_TARGET_MAX_ORIGIN + FXL_TARGET_MAX_DIM / 2) * 65536;
    const int64_t half_max = (int64_t)FXL_TARGET_MAX_DIM / 2 * 65536;
    fxl_pipeline_t p;
    fxl_xform_t edge, xf;
    fxl_clipvert_t c;
    fxl_vertex_t out;
    int k;
    prepared_320x240(&p, &edge, &c);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_set_viewport(&p, FXL_TARGET_MAX_ORIGIN, FXL_TARGET_MAX_ORIGIN,
                                                             FXL_TARGET_MAX_DIM, FXL_TARGET_MAX_DIM));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_prepare(&p, &edge));
    TEST_ASSERT_EQUAL_INT64(centre_max, edge.cx_q16);
    TEST_ASSERT_EQUAL_INT64(half_max, edge.hw_q16);
    TEST_ASSERT_EQUAL_INT32(4 * 65536, edge.guard_q16);
    c.w = edge.near_q32;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_project(&edge, &c, &out));
    xf = edge;
    xf.guard_q16 = 2 * 65536;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_project(&xf, &c, &out));
    for (k = 0; k < 6; k++) {
        xf = edge;
        switch (k) {
        case 0: xf.cx_q16 = centre_max + 1; break;
        case 1: xf.cx_q16 = -centre_max - 1; break;
        case 2: xf.cy_q16 = centre_max + 1; break;
        case 3: xf.guard_q16 = 2 * 65536; xf.hw_q16 = half_max + 1; break;
        case 4: xf.guard_q16 = 2 * 65536; xf.hh_q16 = half_max + 1; break;
        default: xf.guard_q16 = 4 * 65536 + 1; break; /* G x 2048 px > FXL_GUARD_PX */
        }
        snprintf(msg, sizeof msg, "range %d one unit past its edge", k);
        TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_RANGE, fxl_xform_project(&xf, &c, &out), msg);
    }
}

/* pipeline.h, fxl_pipeline_set_viewport: |x|, |y| <= FXL_TARGET_MAX_ORIGIN;
 * fxl_pipeline_prepare: FXL_ERR_RANGE for far not beyond near (far == near
 * included; far one q16 unit beyond is fine). */
static void test_viewport_origin_and_far_plane_limits(void)
{
    fxl_pipeline_t p;
    fxl_xform_t xf;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(&p, 320, 240));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_set_viewport(&p, FXL_TARGET_MAX_ORIGIN, -FXL_TARGET_MAX_ORIGIN, 8, 8));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_pipeline_set_viewport(&p, FXL_TARGET_MAX_ORIGIN + 1, 0, 8, 8));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_pipeline_set_viewport(&p, 0, -FXL_TARGET_MAX_ORIGIN - 1, 8, 8));
    TEST_ASSERT_EQUAL_INT32(FXL_TARGET_MAX_ORIGIN, p.vp_x); /* a refused call leaves p alone */
    p.vp_x = FXL_TARGET_MAX_ORIGIN + 1; /* edited by hand: prepare checks too */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_pipeline_prepare(&p, &xf));
    p.vp_x = 0;
    p.far_q16 = p.near_q16;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_pipeline_prepare(&p, &xf));
    p.far_q16 = p.near_q16 + 1;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_prepare(&p, &xf));
    TEST_ASSERT_EQUAL_INT64(xf.near_q32 + 65536, xf.far_q32);
}

static void test_prepare_and_clip_report_overflow(void)
{
    fxl_pipeline_t p;
    fxl_xform_t xf;
    fxl_clipvert_t c;
    fxl_vec3_t far_pos = {FXL_Q16_INT(30000), FXL_Q16_INT(30000), FXL_Q16_INT(-30000)};
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(&p, 320, 240));
    fxl_mat4_scale(&p.model, FXL_Q16_INT(30000), FXL_Q16_INT(30000), FXL_Q16_INT(30000));
    fxl_mat4_scale(&p.view, FXL_Q16_INT(30000), FXL_Q16_INT(30000), FXL_Q16_INT(30000));
    /* mv entries 9e8 fit q32 int64; clip of a 30000-unit point does not */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_prepare(&p, &xf));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_xform_clip(&xf, &far_pos, &c));
    p.near_q16 = 0;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_pipeline_prepare(&p, &xf));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_pipeline_prepare(NULL, &xf));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_pipeline_set_viewport(&p, 0, 0, 0, 10));
}

/* ---- the mesh path ------------------------------------------------------- */

typedef struct collect {
    fxl_vertex_t tri[64][3];
    int n;
} collect_t;

static fxl_status_t collect_fn(void *user, const fxl_vertex_t tri[3])
{
    collect_t *c = (collect_t *)user;
    if (c->n >= 64) return FXL_ERR_NOMEM;
    memcpy(c->tri[c->n++], tri, sizeof(fxl_vertex_t) * 3);
    return FXL_OK;
}

/* A near-plane cut point carries t's rounding times its edge's length: with
 * a long edge and a tiny near plane (depth ratio ~10^6) it landed past the
 * lower guard plane, which no input vertex was outside and the clipper then
 * skipped; the corner's projection, and so fxl_pipeline_emit, returned
 * FXL_ERR_RANGE for a valid pipeline and an in-range triangle (found by a
 * review's search). The clipper now clips against every plane some vertex
 * of the polygon is outside, cut points included. */
static void test_clip_applies_planes_a_cut_point_is_outside(void)
{
    fxl_pipeline_t p;
    fxl_xform_t xf;
    fxl_clipvert_t cv[3], poly[FXL_CLIP_MAX_VERTS];
    fxl_vec3_t pos[3] = {{0, -2033538857, -880613520}, {-32, -32, -14}, {0, -30, -13}};
    uint16_t idx[3] = {0, 1, 2};
    fxl_mesh_t m = {pos, NULL, NULL, NULL, 3, idx, 1};
    collect_t got;
    uint32_t n, k;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(&p, 4096, 3853));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_set_perspective(&p, FXL_ANGLE_DEG(60), FXL_Q16_ONE, 85, 0));
    p.cull = FXL_CULL_NONE;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_prepare(&p, &xf));
    for (k = 0; k < 3; k++)
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_xform_clip(&xf, &pos[k], &cv[k]));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_clip_triangle(&xf, cv, poly, &n));
    TEST_ASSERT_TRUE(n >= 3);
    for (k = 0; k < n; k++) {
        fxl_vertex_t v;
        TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_OK, fxl_xform_project(&xf, &poly[k], &v), "a clipped corner projects");
    }
    got.n = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_emit(&p, &m, collect_fn, &got, NULL));
    TEST_ASSERT_EQUAL_INT((int)n - 2, got.n);
}


static const fxl_vec3_t quad_pos[4] = {
    {-FXL_Q16_ONE, -FXL_Q16_ONE, FXL_Q16_INT(-4)}, {FXL_Q16_ONE, -FXL_Q16_ONE, FXL_Q16_INT(-4)},
    {FXL_Q16_ONE, FXL_Q16_ONE, FXL_Q16_INT(-4)},   {-FXL_Q16_ONE, FXL_Q16_ONE, FXL_Q16_INT(-4)}};
static const fxl_texcoord_t quad_uv[4] = {{0, 0}, {FXL_Q16_ONE, 0}, {FXL_Q16_ONE, FXL_Q16_ONE}, {0, FXL_Q16_ONE}};

static void test_emit_culls_by_screen_winding(void)
{
    static const uint16_t ccw[6] = {0, 1, 2, 0, 2, 3}, cw[6] = {0, 2, 1, 0, 3, 2};
    fxl_pipeline_t p;
    fxl_mesh_t m;
    fxl_stats_t st;
    collect_t col;
    memset(&m, 0, sizeof m);
    m.pos = quad_pos; m.uv = quad_uv; m.vert_count = 4; m.idx = ccw; m.tri_count = 2;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(&p, 320, 240));
    memset(&st, 0, sizeof st); col.n = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_emit(&p, &m, collect_fn, &col, &st));
    TEST_ASSERT_EQUAL_INT(2, col.n); /* counter-clockwise on screen: kept by CULL_CW */
    TEST_ASSERT_EQUAL_UINT32(0, st.culled_backface);
    /* vertex 0 = (-1, -1, -4) -> left, below centre; f = cot(fovy / 2) with
     * fovy = FXL_ANGLE_DEG(60) = 10922 / 65536 turns (59.996 degrees); the
     * matrix entries are q16 (relative 2^-17), so within 2/65536 px. */
    {
        double f = 1.0 / tan(TWO_PI * 5461 / 65536.0);
        double fx = q16d(p.proj.m[0][0]);
        TEST_ASSERT_INT32_WITHIN(2, (int32_t)lround((160 - fx / 4 * 160) * 65536), col.tri[0][0].x);
        TEST_ASSERT_INT32_WITHIN(2, (int32_t)lround((120 + f / 4 * 120) * 65536), col.tri[0][0].y);
    }
    TEST_ASSERT_UINT32_WITHIN(1, 1073741824u, col.tri[0][0].inv_w); /* near / w = 1/4 */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_ONE, col.tri[0][1].u);
    TEST_ASSERT_EQUAL_HEX16(0xFFFF, col.tri[0][0].color);
    m.idx = cw;
    memset(&st, 0, sizeof st); col.n = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_emit(&p, &m, collect_fn, &col, &st));
    TEST_ASSERT_EQUAL_INT(0, col.n);
    TEST_ASSERT_EQUAL_UINT32(2, st.culled_backface);
    TEST_ASSERT_EQUAL_UINT32(2, st.triangles);
    p.cull = FXL_CULL_CCW;
    col.n = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_emit(&p, &m, collect_fn, &col, NULL));
    TEST_ASSERT_EQUAL_INT(2, col.n);
    p.cull = FXL_CULL_NONE;
    m.idx = ccw;
    col.n = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_emit(&p, &m, collect_fn, &col, NULL));
    TEST_ASSERT_EQUAL_INT(2, col.n);
    /* A zero-area triangle has no winding: not a back face under either
     * cull mode; it goes on (the rasterizer culls it as degenerate). */
    {
        static const uint16_t flat_idx[3] = {0, 1, 1};
        int k;
        m.idx = flat_idx;
        m.tri_count = 1;
        for (k = 0; k < 2; k++) {
            p.cull = k ? FXL_CULL_CCW : FXL_CULL_CW;
            memset(&st, 0, sizeof st); col.n = 0;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_emit(&p, &m, collect_fn, &col, &st));
            TEST_ASSERT_EQUAL_INT(1, col.n);
            TEST_ASSERT_EQUAL_UINT32(0, st.culled_backface);
        }
    }
}

static void test_emit_triangle_through_eye_plane_stays_in_guard_band(void)
{
    /* A floor triangle from far ahead to behind the camera, crossing w = 0. */
    static const fxl_vec3_t pos[3] = {
        {FXL_Q16_INT(-40), -37814, FXL_Q16_INT(-50)},
        {FXL_Q16_INT(40), -37814, FXL_Q16_INT(-50)},
        {0, -37814, FXL_Q16_INT(30)}};
    static const uint16_t idx[3] = {0, 2, 1};
    fxl_pipeline_t p;
    fxl_mesh_t m;
    fxl_stats_t st;
    collect_t col;
    int t, k;
    memset(&m, 0, sizeof m);
    m.pos = pos; m.vert_count = 3; m.idx = idx; m.tri_count = 1;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(&p, 320, 240));
    p.cull = FXL_CULL_NONE;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_set_perspective(&p, FXL_ANGLE_DEG(60), dq16(4.0 / 3),
                                                               dq16(0.05), 0));
    memset(&st, 0, sizeof st); col.n = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_emit(&p, &m, collect_fn, &col, &st));
    TEST_ASSERT_GREATER_OR_EQUAL(1, col.n);
    for (t = 0; t < col.n; t++)
        for (k = 0; k < 3; k++) {
            const fxl_vertex_t *v = &col.tri[t][k];
            /* guard: G = 8192 / 160 = 51.2 ndc, i.e. 160 +- 8192 px in x and
             * 120 +- 8192 * 120 / 160... both axes use the same G */
            TEST_ASSERT_TRUE(v->x >= (160 - 8192) * 65536 && v->x <= (160 + 8192) * 65536);
            TEST_ASSERT_TRUE(v->y >= (120 - 51.2 * 120 - 1) * 65536 && v->y <= (120 + 51.2 * 120 + 1) * 65536);
            TEST_ASSERT_TRUE(v->inv_w >= 1);
        }
}

static void test_emit_argument_and_index_errors(void)
{
    static const uint16_t bad_idx[3] = {0, 1, 4};
    fxl_pipeline_t p;
    fxl_mesh_t m;
    collect_t col;
    memset(&m, 0, sizeof m);
    m.pos = quad_pos; m.vert_count = 4; m.idx = bad_idx; m.tri_count = 1;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(&p, 320, 240));
    col.n = 0;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_pipeline_emit(&p, &m, collect_fn, &col, NULL));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_pipeline_emit(&p, &m, NULL, &col, NULL));
    m.pos = NULL;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_pipeline_emit(&p, &m, collect_fn, &col, NULL));
    m.pos = quad_pos;
    p.cull = 7;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_pipeline_emit(&p, &m, collect_fn, &col, NULL));
}

/* The first triangle of the quad (positions only), culling off, on a
 * default 320 x 240 pipeline. */
static void one_quad_triangle(fxl_pipeline_t *p, fxl_mesh_t *m)
{
    static const uint16_t idx[3] = {0, 1, 2};
    memset(m, 0, sizeof *m);
    m->pos = quad_pos;
    m->vert_count = 4;
    m->idx = idx;
    m->tri_count = 1;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(p, 320, 240));
    p->cull = FXL_CULL_NONE;
}

/* pipeline.h: FXL_ERR_ARG for bad enums, texgen's too: a mode one past
 * FXL_TEXGEN_CUBE, and with texgen on an axis, plane or space one past
 * its last value. Each is refused before any triangle is emitted. */
static void test_emit_refuses_texgen_enums_out_of_range(void)
{
    fxl_pipeline_t p;
    fxl_mesh_t m;
    collect_t col;
    int k;
    one_quad_triangle(&p, &m);
    for (k = 0; k < 5; k++) {
        fxl_texgen_defaults(&p.texgen);
        switch (k) {
        case 0: p.texgen.mode = FXL_TEXGEN_CUBE; break; /* valid: the control */
        case 1: p.texgen.mode = FXL_TEXGEN_CUBE + 1; break;
        case 2: p.texgen.mode = FXL_TEXGEN_CYLINDRICAL; p.texgen.axis = FXL_AXIS_Z + 1; break;
        case 3: p.texgen.mode = FXL_TEXGEN_PLANAR; p.texgen.plane = FXL_PLANE_XZ + 1; break;
        default: p.texgen.mode = FXL_TEXGEN_SPHERICAL; p.texgen.space = FXL_TEXGEN_EYE + 1; break;
        }
        col.n = 0;
        snprintf(msg, sizeof msg, "texgen case %d", k);
        TEST_ASSERT_EQUAL_INT_MESSAGE(k == 0 ? FXL_OK : FXL_ERR_ARG, fxl_pipeline_emit(&p, &m, collect_fn, &col, NULL),
                                      msg);
        TEST_ASSERT_EQUAL_INT_MESSAGE(k == 0 ? 1 : 0, col.n, msg);
    }
}

/* A normal that view * model maps to zero has no direction: the vertex is
 * lit by the ambient term alone (pipeline.c, eye_normal), which is the
 * light's formula (pipeline.h) with n = 0. With fxl_pipeline_init's light
 * (+z, ambient 64, diffuse 191) I = 64 / 255, and white gives
 * round(31 * 64 / 255) = 8 (7.78), round(63 * 64 / 255) = 16 (15.81), 8:
 * 0x4208. A unit normal toward the light gives min(1, (64 + 191) / 255) = 1:
 * white. */
static void test_emit_zero_normal_is_lit_by_ambient_only(void)
{
    static const fxl_vec3_t zero[4] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    static const fxl_vec3_t toward[4] = {{0, 0, FXL_Q16_ONE}, {0, 0, FXL_Q16_ONE}, {0, 0, FXL_Q16_ONE},
                                         {0, 0, FXL_Q16_ONE}};
    fxl_pipeline_t p;
    fxl_mesh_t m;
    collect_t col;
    int k;
    one_quad_triangle(&p, &m);
    p.lighting = 1;
    p.material = 0xFFFFu;
    /* the default light (pipeline.h, fxl_pipeline_init); one unit of 255
     * moves no RGB565 channel here, so it is checked as stored too */
    TEST_ASSERT_EQUAL_INT32(0, p.light.dir.x);
    TEST_ASSERT_EQUAL_INT32(0, p.light.dir.y);
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_ONE, p.light.dir.z);
    for (k = 0; k < 3; k++) {
        TEST_ASSERT_EQUAL_UINT8(64, p.light.ambient[k]);
        TEST_ASSERT_EQUAL_UINT8(191, p.light.diffuse[k]);
    }
    for (k = 0; k < 2; k++) {
        const uint16_t want = k ? 0xFFFFu : 0x4208u;
        int i;
        m.normal = k ? toward : zero;
        col.n = 0;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_emit(&p, &m, collect_fn, &col, NULL));
        TEST_ASSERT_EQUAL_INT(1, col.n);
        for (i = 0; i < 3; i++)
            TEST_ASSERT_EQUAL_HEX16(want, col.tri[0][i].color);
    }
}

/* Every triangle of the host meshes is counter-clockwise seen from the side
 * its vertex normals point to: geometric normal . mean vertex normal > 0. */
static void check_mesh_winding(const fxl_mesh_t *m, const char *name)
{
    uint32_t t;
    TEST_ASSERT_NOT_NULL(m->pos);
    for (t = 0; t < m->tri_count; t++) {
        const fxl_vec3_t *a = &m->pos[m->idx[3 * t]], *b = &m->pos[m->idx[3 * t + 1]];
        const fxl_vec3_t *c = &m->pos[m->idx[3 * t + 2]];
        double e1[3] = {q16d(b->x - a->x), q16d(b->y - a->y), q16d(b->z - a->z)};
        double e2[3] = {q16d(c->x - a->x), q16d(c->y - a->y), q16d(c->z - a->z)};
        double g[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        double n[3] = {0, 0, 0};
        int k;
        TEST_ASSERT_TRUE(m->idx[3 * t] < m->vert_count && m->idx[3 * t + 1] < m->vert_count &&
                         m->idx[3 * t + 2] < m->vert_count);
        for (k = 0; k < 3; k++) {
            const fxl_vec3_t *vn = &m->normal[m->idx[3 * t + k]];
            n[0] += q16d(vn->x); n[1] += q16d(vn->y); n[2] += q16d(vn->z);
        }
        if (g[0] * n[0] + g[1] * n[1] + g[2] * n[2] <= 0) {
            snprintf(msg, sizeof msg, "%s triangle %u faces against its normals", name, (unsigned)t);
            TEST_FAIL_MESSAGE(msg);
        }
    }
}

static void test_host_meshes_wind_counter_clockwise_toward_normals(void)
{
    fxl_mesh_t m;
    TEST_ASSERT_EQUAL_INT(0, meshes_sphere(&m, 1.0, 16, 8));
    TEST_ASSERT_EQUAL_UINT32(2 * 16 * 7, m.tri_count);
    check_mesh_winding(&m, "sphere");
    meshes_free(&m);
    TEST_ASSERT_EQUAL_INT(0, meshes_cylinder(&m, 1.0, -5, 5, 12, 4, 1));
    check_mesh_winding(&m, "tunnel");
    meshes_free(&m);
    TEST_ASSERT_EQUAL_INT(0, meshes_cylinder(&m, 1.0, -5, 5, 12, 4, 0));
    check_mesh_winding(&m, "cylinder");
    meshes_free(&m);
    TEST_ASSERT_EQUAL_INT(0, meshes_cube(&m, 1.0));
    TEST_ASSERT_EQUAL_UINT32(12, m.tri_count);
    check_mesh_winding(&m, "cube");
    meshes_free(&m);
    TEST_ASSERT_EQUAL_INT(0, meshes_floor(&m, -0.5, -4, 4, -10, -1, 4, 6, 2.0));
    check_mesh_winding(&m, "floor");
    meshes_free(&m);
    TEST_ASSERT_EQUAL_INT(-1, meshes_sphere(&m, 1.0, 2, 8));
}

static void test_cube_mesh_shows_at_most_three_faces(void)
{
    /* Cube rotated 30 degrees about x and y at z = -5: the back faces are
     * culled, 3 faces (6 triangles) face the camera. */
    fxl_pipeline_t p;
    fxl_mesh_t m;
    fxl_mat4_t r;
    fxl_stats_t st;
    collect_t col;
    TEST_ASSERT_EQUAL_INT(0, meshes_cube(&m, 1.0));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(&p, 320, 240));
    fxl_mat4_translate(&p.model, 0, 0, FXL_Q16_INT(-5));
    fxl_mat4_rotate_x(&r, FXL_ANGLE_DEG(30));
    fxl_mat4_mul(&p.model, &p.model, &r);
    fxl_mat4_rotate_y(&r, FXL_ANGLE_DEG(30));
    fxl_mat4_mul(&p.model, &p.model, &r);
    memset(&st, 0, sizeof st); col.n = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_emit(&p, &m, collect_fn, &col, &st));
    TEST_ASSERT_EQUAL_INT(6, col.n);
    TEST_ASSERT_EQUAL_UINT32(6, st.culled_backface);
    meshes_free(&m);
}

/* A tilted wall z = -3 - 0.3 y, x, y in [-ext, ext] as an n x n grid,
 * covers the whole view (every view ray with |dy| <= tan 30 deg hits it at
 * distance <= 3.6). Drawn without depth, the pixels written must be exactly
 * W * H: a hole or a pixel drawn twice along the clipped, fanned edges
 * would change the count. Returns the number of triangles drawn. */
enum { WALL_W = 96, WALL_H = 64, WALL_MAXN = 40 };
static uint32_t draw_wall(double ext, int n, int cull, uint32_t *pixels_out, uint32_t *outside)
{
    static uint16_t pixels[WALL_W * WALL_H];
    static fxl_vec3_t pos[(WALL_MAXN + 1) * (WALL_MAXN + 1)];
    static uint16_t idx[WALL_MAXN * WALL_MAXN * 6];
    fxl_pipeline_t p;
    fxl_mesh_t m;
    fxl_target_t t;
    fxl_draw_t d;
    fxl_stats_t st;
    int i, j, k = 0;
    for (i = 0; i <= n; i++)
        for (j = 0; j <= n; j++) {
            double x = -ext + 2 * ext * j / n, y = -ext + 2 * ext * i / n;
            pos[i * (n + 1) + j].x = dq16(x);
            pos[i * (n + 1) + j].y = dq16(y);
            pos[i * (n + 1) + j].z = dq16(-3 - 0.3 * y);
        }
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) {
            int a = i * (n + 1) + j;
            idx[k++] = (uint16_t)a; idx[k++] = (uint16_t)(a + 1); idx[k++] = (uint16_t)(a + n + 2);
            idx[k++] = (uint16_t)a; idx[k++] = (uint16_t)(a + n + 2); idx[k++] = (uint16_t)(a + n + 1);
        }
    memset(&m, 0, sizeof m);
    m.pos = pos; m.vert_count = (uint32_t)((n + 1) * (n + 1)); m.idx = idx;
    m.tri_count = (uint32_t)(n * n * 2);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(&p, WALL_W, WALL_H));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_set_perspective(&p, FXL_ANGLE_DEG(60), dq16(1.5),
                                                               dq16(0.05), 0));
    p.cull = (uint8_t)cull;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, pixels, WALL_W, WALL_H, WALL_W, drawable_rgb565()));
    fxl_draw_defaults(&d);
    d.depth = 0;
    d.texture = flat_white_texture();   /* untextured where the build has untextured draws */
    memset(&st, 0, sizeof st);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mesh_draw(&p, &t, &d, &m, &st));
    *pixels_out = st.pixels;
    if (outside) *outside = st.culled_outside;
    return st.drawn;
}

/* Settings every triangle would be refused for are refused by the mesh
 * draw before any vertex work, also when the clip planes reject the whole
 * mesh (which with valid settings is FXL_OK, one triangle culled). */
static void test_mesh_draw_refuses_bad_settings_before_culling(void)
{
    static uint16_t pixels[16 * 16];
    static const fxl_vec3_t behind[3] = {{0, 0, 3 << 16}, {1 << 16, 0, 3 << 16}, {0, 1 << 16, 3 << 16}};
    static const uint16_t idx[3] = {0, 1, 2};
    fxl_pipeline_t p;
    fxl_mesh_t m;
    fxl_target_t t;
    fxl_draw_t d;
    fxl_stats_t st;
    memset(&m, 0, sizeof m);
    m.pos = behind; m.vert_count = 3; m.idx = idx; m.tri_count = 1;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(&p, 16, 16));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, pixels, 16, 16, 16, drawable_rgb565()));
    fxl_draw_defaults(&d);
    d.depth = 0;
    d.texture = flat_white_texture();
    memset(&st, 0, sizeof st);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mesh_draw(&p, &t, &d, &m, &st));
    TEST_ASSERT_EQUAL_UINT32(1, st.culled_outside);
    d.persp = 3;   /* not a power of two */
    memset(&st, 0, sizeof st);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mesh_draw(&p, &t, &d, &m, &st));
    TEST_ASSERT_EQUAL_UINT32(0, st.triangles);
    d.persp = FXL_PERSP_SPAN;
    t.clip.x1 = 17;   /* edited past the buffer */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_mesh_draw(&p, &t, &d, &m, &st));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_draw_check(&t, &d));
}

static void test_mesh_draw_clipped_wall_covers_each_pixel_once(void)
{
    uint32_t px, px2, outside, drawn;
    /* coarse: 20-unit quads, the part below y = -10 behind the eye, the
     * rest reaching far beyond the guard band */
    drawn = draw_wall(100, 10, FXL_CULL_NONE, &px, &outside);
    printf("coarse wall: %u drawn, %u outside, %u pixels\n", (unsigned)drawn, (unsigned)outside, (unsigned)px);
    TEST_ASSERT_GREATER_THAN(0, outside);
    TEST_ASSERT_EQUAL_UINT32(WALL_W * WALL_H, px);
    /* fine: 1-unit quads, ~100 triangles sharing edges on screen */
    drawn = draw_wall(20, 40, FXL_CULL_NONE, &px, &outside);
    printf("fine wall: %u drawn, %u pixels\n", (unsigned)drawn, (unsigned)px);
    TEST_ASSERT_GREATER_THAN(50, drawn);
    TEST_ASSERT_EQUAL_UINT32(WALL_W * WALL_H, px);
    /* one cull mode drops the whole wall, the other keeps all of it */
    draw_wall(20, 40, FXL_CULL_CW, &px, NULL);
    draw_wall(20, 40, FXL_CULL_CCW, &px2, NULL);
    TEST_ASSERT_EQUAL_UINT32(WALL_W * WALL_H, px + px2);
    TEST_ASSERT_TRUE(px == 0 || px2 == 0);
}

/* ---- the vertex cache ------------------------------------------------------ */

/* Every emitted triangle, in order, for comparing draws vertex by vertex. */
typedef struct emitted {
    fxl_vertex_t v[6000][3];
    uint32_t n;
} emitted_t;

static fxl_status_t emitted_fn(void *user, const fxl_vertex_t tri[3])
{
    emitted_t *e = (emitted_t *)user;
    if (e->n >= 6000) return FXL_ERR_NOMEM;
    memcpy(e->v[e->n++], tri, sizeof(fxl_vertex_t) * 3);
    return FXL_OK;
}

enum { VC_W = 160, VC_H = 120, VC_CASES = 6 };

/* Case c of the comparison: a mesh and a pipeline set-up covering every
 * texgen mode (seams, poles and cube faces are per triangle), object and
 * eye space, lighting, per-vertex colours and the near-plane clipper
 * (the tunnel runs through the eye). */
static void vc_case(int c, fxl_angle_t spin, fxl_mesh_t *m, fxl_pipeline_t *p)
{
    fxl_mat4_t r, tr;
    int ok = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(p, VC_W, VC_H));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_set_perspective(p, FXL_ANGLE_DEG(60), dq16(4.0 / 3.0),
                                                               dq16(0.1), 0));
    fxl_mat4_rotate_y(&r, (fxl_angle_t)(FXL_ANGLE_DEG(25) + spin));
    fxl_mat4_translate(&tr, 0, 0, FXL_Q16_INT(-4));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mat4_mul(&p->model, &tr, &r));
    p->light.dir.x = dq16(-0.48); p->light.dir.y = dq16(0.6); p->light.dir.z = dq16(0.64);
    switch (c) {
    case 0: /* UV sphere, spherical texgen: seam column and pole fans, lit */
        ok = meshes_sphere(m, 1.3, 32, 16) == 0;
        p->texgen.mode = FXL_TEXGEN_SPHERICAL;
        p->texgen.scale_u = FXL_Q16_INT(2);
        p->lighting = 1;
        break;
    case 1: /* tunnel through the eye: cylindrical, near clipping */
        ok = meshes_cylinder(m, 1.0, -2.0, 30.0, 24, 32, 1) == 0;
        fxl_mat4_rotate_x(&p->model, FXL_ANGLE_DEG(-90));
        p->texgen.mode = FXL_TEXGEN_CYLINDRICAL;
        p->texgen.scale_u = FXL_Q16_INT(4);
        p->cull = FXL_CULL_NONE;
        break;
    case 2: /* cube, cube map in eye space, per-vertex colours, lit */
        ok = meshes_cube(m, 1.0) == 0 && meshes_set_color(m, 0xF81Fu) == 0;
        p->texgen.mode = FXL_TEXGEN_CUBE;
        p->texgen.space = FXL_TEXGEN_EYE;
        p->lighting = 1;
        break;
    case 3: /* floor grid, planar XZ texgen in eye space */
        ok = meshes_floor(m, -1.0, -6.0, 6.0, -8.0, 3.0, 12, 11, 1.0) == 0;
        p->texgen.mode = FXL_TEXGEN_PLANAR;
        p->texgen.plane = FXL_PLANE_XZ;
        p->texgen.space = FXL_TEXGEN_EYE;
        break;
    case 4: /* sphere with its own uv, lit, no texgen */
        ok = meshes_sphere(m, 1.0, 20, 10) == 0;
        p->lighting = 1;
        break;
    default: /* cube, mesh uv, material colour, nothing else */
        ok = meshes_cube(m, 1.2) == 0;
        p->material = 0x07E0u;
        break;
    }
    TEST_ASSERT_TRUE_MESSAGE(ok, "mesh builder failed");
}

/* Draw case c with the given cache (NULL: none); emitted triangles to *e,
 * returns the frame CRC. */
static uint32_t vc_draw(int c, fxl_angle_t spin, fxl_vcache_entry_t *cache, uint32_t count,
                        emitted_t *e, fxl_stats_t *st)
{
    static uint16_t pixels[VC_W * VC_H];
    static const uint16_t texels[16] = {0xF800, 0x07E0, 0x001F, 0xFFFF, 0x0000, 0xFFE0, 0x07FF, 0xF81F,
                                        0x8410, 0x4208, 0xC618, 0x2104, 0xA145, 0x18E3, 0x7BEF, 0xFD20};
    fxl_texture_t tex;
    fxl_pipeline_t p;
    fxl_mesh_t m;
    fxl_target_t t;
    fxl_draw_t d;
    uint32_t crc;
    vc_case(c, spin, &m, &p);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_set_vertex_cache(&p, cache, count));
    e->n = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_emit(&p, &m, emitted_fn, e, NULL));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 4, 4, FXL_TEXFMT_RGB565, 1));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, pixels, VC_W, VC_H, VC_W, drawable_rgb565()));
    (void)fxl_target_clear(&t, 0);
    fxl_draw_defaults(&d);
    d.depth = 0;
    d.texture = &tex;
#if FXL_HAVE_GENERIC   /* else flat REPLACE: the vertex colours are still compared in first_difference */
    d.shade = FXL_SHADE_GOURAUD;
    d.texenv = FXL_TEXENV_MODULATE;
#endif
    memset(st, 0, sizeof *st);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mesh_draw(&p, &t, &d, &m, st));
    crc = fxl_host_crc_target(&t);
    meshes_free(&m);
    return crc;
}

/* Field by field (fxl_vertex_t has padding bytes memcmp would see):
 * index of the first differing triangle, or -1. */
static long first_difference(const emitted_t *a, const emitted_t *b)
{
    uint32_t i, k;
    for (i = 0; i < a->n && i < b->n; i++)
        for (k = 0; k < 3; k++) {
            const fxl_vertex_t *p = &a->v[i][k], *q = &b->v[i][k];
            if (p->x != q->x || p->y != q->y || p->inv_w != q->inv_w || p->u != q->u || p->v != q->v ||
                p->color != q->color)
                return (long)i;
        }
    return a->n == b->n ? -1 : (long)i;
}

static void test_vertex_cache_output_bit_identical(void)
{
    static emitted_t ref, got;
    /* Full size, a size that forces evictions within triangles (7 entries:
     * ring neighbours collide), a single entry, and an oversized cache. */
    static fxl_vcache_entry_t cache[2000];
    static const uint32_t sizes[4] = {2000, 7, 1, 600};
    int c, k;
    for (c = 0; c < VC_CASES; c++) {
        fxl_stats_t s0, s1;
        uint32_t crc0 = vc_draw(c, 0, NULL, 0, &ref, &s0);
        TEST_ASSERT_GREATER_THAN(0, ref.n);
        for (k = 0; k < 4; k++) {
            uint32_t i, crc1;
            /* Garbage left by an earlier draw must not matter: fill the
             * cache with a pattern that looks like valid tags. */
            for (i = 0; i < sizes[k]; i++) {
                memset(&cache[i], 0x11 * (int)(i % 7), sizeof cache[i]);
                cache[i].tag = i;
            }
            crc1 = vc_draw(c, 0, cache, sizes[k], &got, &s1);
            snprintf(msg, sizeof msg, "case %d cache %u: %u triangles vs %u without", c, (unsigned)sizes[k],
                     (unsigned)got.n, (unsigned)ref.n);
            TEST_ASSERT_EQUAL_UINT32_MESSAGE(ref.n, got.n, msg);
            {
                long d = first_difference(&ref, &got);
                if (d >= 0) {
                    snprintf(msg, sizeof msg,
                             "case %d cache %u: triangle %ld differs (x0 %ld vs %ld, inv_w0 %lu vs %lu, u0 %ld vs %ld)",
                             c, (unsigned)sizes[k], d, (long)ref.v[d][0].x, (long)got.v[d][0].x,
                             (unsigned long)ref.v[d][0].inv_w, (unsigned long)got.v[d][0].inv_w,
                             (long)ref.v[d][0].u, (long)got.v[d][0].u);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
            snprintf(msg, sizeof msg, "case %d cache %u: frame CRC", c, (unsigned)sizes[k]);
            TEST_ASSERT_EQUAL_HEX32_MESSAGE(crc0, crc1, msg);
            TEST_ASSERT_EQUAL_UINT32(s0.drawn, s1.drawn);
            TEST_ASSERT_EQUAL_UINT32(s0.pixels, s1.pixels);
            TEST_ASSERT_EQUAL_UINT32(s0.culled_backface, s1.culled_backface);
            TEST_ASSERT_EQUAL_UINT32(s0.culled_outside, s1.culled_outside);
        }
        /* The same cache reused for a second draw with another model
         * matrix: entries of the first draw must not leak into it. */
        (void)vc_draw(c, FXL_ANGLE_DEG(40), cache, 2000, &got, &s1);
        crc0 = vc_draw(c, FXL_ANGLE_DEG(40), NULL, 0, &ref, &s0);
        (void)vc_draw(c, 0, cache, 2000, &got, &s1);
        {
            uint32_t crc1 = vc_draw(c, FXL_ANGLE_DEG(40), cache, 2000, &got, &s1);
            snprintf(msg, sizeof msg, "case %d: reused cache, frame CRC", c);
            TEST_ASSERT_EQUAL_HEX32_MESSAGE(crc0, crc1, msg);
            TEST_ASSERT_EQUAL_INT_MESSAGE(-1, (int)first_difference(&ref, &got), msg);
        }
    }
}

static void test_vertex_cache_arguments(void)
{
    fxl_pipeline_t p;
    fxl_vcache_entry_t e[4];
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(&p, 32, 32));
    TEST_ASSERT_NULL(p.vcache);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_pipeline_set_vertex_cache(NULL, e, 4));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_pipeline_set_vertex_cache(&p, NULL, 4));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_set_vertex_cache(&p, e, 4));
    TEST_ASSERT_EQUAL_UINT32(4, p.vcache_count);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_set_vertex_cache(&p, NULL, 0));
    TEST_ASSERT_NULL(p.vcache);
    /* the size macro sizes static arrays */
    TEST_ASSERT_EQUAL_UINT32(sizeof e, FXL_VCACHE_BYTES(4));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_sin_cos_max_error_over_all_angles);
    RUN_TEST(test_sin_cos_exact_at_quadrant_points);
    RUN_TEST(test_atan2_error_within_half_lsb_plus_cordic);
    RUN_TEST(test_acos_asin_error_over_all_inputs);
    RUN_TEST(test_rotations_match_double);
    RUN_TEST(test_rotate_axis_matches_rodrigues);
    RUN_TEST(test_rotate_axis_rejects_non_unit_axis);
    RUN_TEST(test_rotate_axis_of_tolerated_length_is_a_rotation);
    RUN_TEST(test_rotate_axis_unit_tolerance_is_exactly_two_to_minus_8);
    RUN_TEST(test_mat4_mul_and_transform_match_double);
    RUN_TEST(test_mat4_mul_overflow_saturates_with_status);
    RUN_TEST(test_transform_point_ignores_an_overflowing_fourth_row);
    RUN_TEST(test_mat4_mul_saturates_a_negative_int64_overflow);
    RUN_TEST(test_perspective_matches_glu_formula);
    RUN_TEST(test_perspective_every_fovy_within_derived_bound);
    RUN_TEST(test_look_at_matches_double);
    RUN_TEST(test_look_at_up_near_the_view_direction);
    RUN_TEST(test_look_at_refuses_up_within_two_to_minus_16_of_the_view);
    RUN_TEST(test_projection_accuracy_target_random_meshes);
    RUN_TEST(test_project_rejects_w_at_or_behind_near);
    RUN_TEST(test_project_clamps_a_vertex_just_beyond_the_guard_band);
    RUN_TEST(test_clip_limit_and_smallest_inv_w);
    RUN_TEST(test_project_packs_channels_rounded_and_clamped);
    RUN_TEST(test_project_and_clip_refuse_a_hand_filled_xform_out_of_range);
    RUN_TEST(test_project_xform_refused_one_unit_past_each_range);
    RUN_TEST(test_viewport_origin_and_far_plane_limits);
    RUN_TEST(test_prepare_and_clip_report_overflow);
    RUN_TEST(test_clip_applies_planes_a_cut_point_is_outside);
    RUN_TEST(test_emit_culls_by_screen_winding);
    RUN_TEST(test_emit_triangle_through_eye_plane_stays_in_guard_band);
    RUN_TEST(test_emit_argument_and_index_errors);
    RUN_TEST(test_emit_refuses_texgen_enums_out_of_range);
    RUN_TEST(test_emit_zero_normal_is_lit_by_ambient_only);
    RUN_TEST(test_host_meshes_wind_counter_clockwise_toward_normals);
    RUN_TEST(test_cube_mesh_shows_at_most_three_faces);
    RUN_TEST(test_mesh_draw_clipped_wall_covers_each_pixel_once);
    RUN_TEST(test_mesh_draw_refuses_bad_settings_before_culling);
    RUN_TEST(test_vertex_cache_output_bit_identical);
    RUN_TEST(test_vertex_cache_arguments);
    return UNITY_END();
}
