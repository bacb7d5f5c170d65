/* tests/test_light.c - per-vertex diffuse + ambient lighting (src/light.c)
 * against double precision, and lighting through the mesh path.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "test_rng.h"
#include "fixel/pipeline.h"

void setUp(void) {}
void tearDown(void) {}

static char msg[256];
static fxl_q16_t dq16(double v) { return (fxl_q16_t)lround(v * 65536.0); }

static fxl_vec3_t random_unit(void)
{
    double v[3], len;
    fxl_vec3_t r;
    do {
        v[0] = rng_range(-1, 1); v[1] = rng_range(-1, 1); v[2] = rng_range(-1, 1);
        len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    } while (len < 0.1 || len > 1);
    r.x = dq16(v[0] / len); r.y = dq16(v[1] / len); r.z = dq16(v[2] / len);
    return r;
}

/* The documented formula in double, before rounding, for channel c. */
static double exact_channel(const fxl_light_t *l, const fxl_vec3_t *n, uint16_t base, int c)
{
    static const int shift[3] = {11, 5, 0}, maxc[3] = {31, 63, 31};
    double ndl = (n->x / 65536.0) * (l->dir.x / 65536.0) + (n->y / 65536.0) * (l->dir.y / 65536.0) +
                 (n->z / 65536.0) * (l->dir.z / 65536.0);
    double i = (l->ambient[c] + l->diffuse[c] * fmin(1.0, fmax(0.0, ndl))) / 255.0;
    return ((base >> shift[c]) & maxc[c]) * fmin(1.0, i);
}

static void test_light_matches_double(void)
{
    static const int shift[3] = {11, 5, 0}, maxc[3] = {31, 63, 31};
    int i, exact = 0, ties = 0;
    rng_seed(77);
    for (i = 0; i < 100000; i++) {
        fxl_light_t l;
        fxl_vec3_t n = random_unit();
        uint16_t base = (uint16_t)rng_next(), out;
        int c;
        l.dir = random_unit();
        for (c = 0; c < 3; c++) {
            l.ambient[c] = (uint8_t)(rng_next() % 128);
            l.diffuse[c] = (uint8_t)(rng_next() % 256);
        }
        out = fxl_light_shade(&l, &n, base);
        for (c = 0; c < 3; c++) {
            double want = exact_channel(&l, &n, base, c);
            int got = (out >> shift[c]) & maxc[c];
            double frac = want - floor(want);
            /* light.c: the fixed result is within 63 * 2^-14 < 0.004 of the
             * exact value, so it equals round(exact) unless the exact value
             * lies within 0.004 of a tie, where it may round either way. */
            if (fabs(frac - 0.5) < 0.004) {
                ties++;
                if (fabs(got - want) > 0.504) {
                    snprintf(msg, sizeof msg, "case %d channel %d (near tie): got %d, exact %.5f", i, c, got, want);
                    TEST_FAIL_MESSAGE(msg);
                }
                continue;
            }
            if (got != (int)floor(want + 0.5)) {
                snprintf(msg, sizeof msg, "case %d channel %d: got %d, exact %.5f", i, c, got, want);
                TEST_FAIL_MESSAGE(msg);
            }
            exact++;
        }
    }
    printf("light: %d channels equal to round(double), %d near-tie channels\n", exact, ties);
    TEST_ASSERT_GREATER_THAN(290000, exact);
}

/* With n . dir exact in q16 (dir = +z, n = (0, 0, m / 65536)), the only
 * rounding before the last is I's division by 255: (num + 127) / 255 is
 * round(num / 255) within 127/255 < 1/2 unit of 2^-16, so base_c * I is
 * within 63 * 2^-17 < 0.00049 of the exact value, and the result must be
 * round(exact) everywhere farther than that from a tie: much tighter than
 * the 0.004 that the random unit vectors above need. (Truncating the
 * division instead doubles that error: ambient 114, diffuse 100, m = 30071
 * gives 63 * I = 39.50093, which must round to 40.) */
static void test_light_exact_dot_products_round_to_nearest(void)
{
    static const int shift[3] = {11, 5, 0}, maxc[3] = {31, 63, 31};
    const double eps = 63.0 / 131072.0;
    int i, checked = 0;
    fxl_light_t l;
    rng_seed(4242);
    l.dir.x = 0;
    l.dir.y = 0;
    l.dir.z = 65536;
    for (i = 0; i < 200000; i++) {
        fxl_vec3_t n;
        uint16_t base = (uint16_t)rng_next(), out;
        int c;
        n.x = 0;
        n.y = 0;
        n.z = (fxl_q16_t)(rng_next() % 65537u);
        for (c = 0; c < 3; c++) {
            l.ambient[c] = (uint8_t)(rng_next() % 256);
            l.diffuse[c] = (uint8_t)(rng_next() % 256);
        }
        if (i == 0) {   /* the example above, on green */
            n.z = 30071;
            base = 0x07E0;
            l.ambient[1] = 114;
            l.diffuse[1] = 100;
        }
        out = fxl_light_shade(&l, &n, base);
        for (c = 0; c < 3; c++) {
            double want = exact_channel(&l, &n, base, c);
            int got = (out >> shift[c]) & maxc[c];
            double frac = want - floor(want);
            if (fabs(frac - 0.5) <= eps)
                continue;
            checked++;
            if (got != (int)floor(want + 0.5)) {
                snprintf(msg, sizeof msg,
                         "ambient %d diffuse %d n.z %ld base %04x channel %d: exact %.6f, got %d", l.ambient[c],
                         l.diffuse[c], (long)n.z, base, c, want, got);
                TEST_FAIL_MESSAGE(msg);
            }
        }
    }
    TEST_ASSERT_TRUE(checked > 590000);
}

static void test_light_back_facing_gets_ambient_and_bright_saturates(void)
{
    fxl_light_t l;
    fxl_vec3_t up = {0, FXL_Q16_ONE, 0}, down = {0, -FXL_Q16_ONE, 0};
    memset(&l, 0, sizeof l);
    l.dir = up;
    l.ambient[0] = l.ambient[1] = l.ambient[2] = 51;    /* 0.2 */
    l.diffuse[0] = l.diffuse[1] = l.diffuse[2] = 255;
    /* facing away: 0.2 * (31, 63, 31) = (6.2, 12.6, 6.2) -> (6, 13, 6) */
    TEST_ASSERT_EQUAL_HEX16((6u << 11) | (13u << 5) | 6u, fxl_light_shade(&l, &down, 0xFFFF));
    /* facing the light: 1.2 saturates at 1 */
    TEST_ASSERT_EQUAL_HEX16(0xFFFF, fxl_light_shade(&l, &up, 0xFFFF));
    /* NULL light: base colour unchanged */
    TEST_ASSERT_EQUAL_HEX16(0x1234, fxl_light_shade(NULL, &up, 0x1234));
}

static fxl_status_t grab(void *user, const fxl_vertex_t tri[3])
{
    memcpy(user, tri, 3 * sizeof *tri);
    return FXL_OK;
}

static void test_mesh_lighting_uses_eye_space_normals(void)
{
    /* A triangle at z = -4 facing +z in object space; the model rotates it
     * 60 degrees about y, so its eye-space normal makes 60 degrees with the
     * light at +z: n . L = 0.5. */
    static const fxl_vec3_t pos[3] = {{0, 0, FXL_Q16_INT(-4)}, {FXL_Q16_ONE, 0, FXL_Q16_INT(-4)},
                                      {0, FXL_Q16_ONE, FXL_Q16_INT(-4)}};
    static const fxl_vec3_t nrm[3] = {{0, 0, FXL_Q16_ONE}, {0, 0, FXL_Q16_ONE}, {0, 0, FXL_Q16_ONE}};
    static const uint16_t idx[3] = {0, 1, 2};
    fxl_pipeline_t p;
    fxl_mesh_t m;
    fxl_vertex_t tri[3];
    fxl_mat4_t rot, tr, back;
    memset(&m, 0, sizeof m);
    m.pos = pos; m.normal = nrm; m.vert_count = 3; m.idx = idx; m.tri_count = 1;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_init(&p, 320, 240));
    p.cull = FXL_CULL_NONE;
    p.lighting = 1;
    p.light.dir.x = 0; p.light.dir.y = 0; p.light.dir.z = FXL_Q16_ONE;
    p.light.ambient[0] = p.light.ambient[1] = p.light.ambient[2] = 0;
    p.light.diffuse[0] = p.light.diffuse[1] = p.light.diffuse[2] = 255;
    /* rotate about the triangle's own point (0, 0, -4) so it stays in view */
    fxl_mat4_translate(&tr, 0, 0, FXL_Q16_INT(-4));
    fxl_mat4_translate(&back, 0, 0, FXL_Q16_INT(4));
    fxl_mat4_rotate_y(&rot, FXL_ANGLE_DEG(60));
    fxl_mat4_mul(&p.model, &tr, &rot);
    fxl_mat4_mul(&p.model, &p.model, &back);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_emit(&p, &m, grab, tri, NULL));
    /* 0.5 * (31, 63, 31) = (15.5, 31.5, 15.5): ties, rounding up in exact
     * arithmetic; cos(59.996 deg) = 0.50005 > 0.5 makes it (16, 32, 16). */
    TEST_ASSERT_EQUAL_HEX16((16u << 11) | (32u << 5) | 16u, tri[0].color);
    /* without lighting: the material colour */
    p.lighting = 0;
    p.material = 0x07E0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_pipeline_emit(&p, &m, grab, tri, NULL));
    TEST_ASSERT_EQUAL_HEX16(0x07E0, tri[2].color);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_light_matches_double);
    RUN_TEST(test_light_exact_dot_products_round_to_nearest);
    RUN_TEST(test_light_back_facing_gets_ambient_and_bright_saturates);
    RUN_TEST(test_mesh_lighting_uses_eye_space_normals);
    return UNITY_END();
}
