/* test_fuzz_regress.c - every input the fuzzers ever flagged, replayed.
 *
 * Inputs are the bytes of a fixel-fuzz / fuzz_raster case (decoded and
 * checked by tests/fuzz/fuzz_case.h: status codes, canaries and guard
 * pages, clip, determinism, exact coverage, stats). Each entry also fixes the
 * exact status and the number of pixels written, measured when it was added.
 * So far the fuzzers (10^6 cases per CI run, 2 x 10^7 under ASan+UBSan, 10^5
 * libFuzzer runs) have found nothing in the core, so the table holds the
 * seed inputs below (edge byte patterns and random cases covering the error
 * paths) plus hand-made extreme cases; add every future finding here with the
 * bytes printed by fixel-fuzz ("FINDING ... bytes <hex>"). A change to the
 * decoder must keep every input here decoding as before (the level-row
 * vertex layout, for one, skips the layout bytes these inputs use).
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "fuzz/fuzz_case.h"

void setUp(void) {}
void tearDown(void) {}

static fz_state st;

typedef struct replay {
    const char *hex;
    fxl_status_t status;
    unsigned written;
} replay_t;

static const replay_t replays[] = {
    {"",
     FXL_OK, 0},
    {"ffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff"
         "ffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff"
         "ffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff"
         "ffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff"
         "ffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff"
         "ffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff",
     FXL_ERR_ARG, 0},
    {"0000000000000000000000000000000000000000000000000000000000000000"
         "0000000000000000000000000000000000000000000000000000000000000000"
         "0000000000000000000000000000000000000000000000000000000000000000"
         "0000000000000000000000000000000000000000000000000000000000000000"
         "0000000000000000000000000000000000000000000000000000000000000000"
         "0000000000000000000000000000000000000000000000000000000000000000",
     FXL_OK, 0},
    {"8080808080808080808080808080808080808080808080808080808080808080"
         "8080808080808080808080808080808080808080808080808080808080808080"
         "8080808080808080808080808080808080808080808080808080808080808080"
         "8080808080808080808080808080808080808080808080808080808080808080"
         "8080808080808080808080808080808080808080808080808080808080808080"
         "8080808080808080808080808080808080808080808080808080808080808080",
     FXL_OK, 0},
    {"7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f"
         "7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f"
         "7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f"
         "7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f"
         "7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f"
         "7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f",
     FXL_OK, 0},
    {"0101010101010101010101010101010101010101010101010101010101010101"
         "0101010101010101010101010101010101010101010101010101010101010101"
         "0101010101010101010101010101010101010101010101010101010101010101"
         "0101010101010101010101010101010101010101010101010101010101010101"
         "0101010101010101010101010101010101010101010101010101010101010101"
         "0101010101010101010101010101010101010101010101010101010101010101",
     FXL_OK, 0},
    {"f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0"
         "f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0"
         "f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0",
     FXL_ERR_RANGE, 0},
    {"9f41bd5bcbb0f1d7bda6ec8707d777c6f13fa60de6281c5f78de3f618b1a923f"
         "03bb3768472eeadec46328c3cc12239e9e71202100f8df0135c637f5fb2adf2a"
         "4a50f6328ae0ada0342ef0f7b032f7f7e4624c055c6a2aef254310544dd19a96",
     FXL_OK, 0},
    {"0098adb556104f5ad14e7bb2502f7b78b42d0e41f9f005f3bf5bd867048cc96b"
         "5d6094d702730bb52e9ff4f4321ec13eedd1f17658835ae48640c6761b96bfc7"
         "cc5edc4b096ef2fa173557839c5ceb255746ecb38b174faf514e2dcc14a026b8",
     FXL_OK, 0},
    {"b04fff7b29b80c14fc9988ec67083cbd9858d34074a66b250efaeaa308cd7e55"
         "d63521fbbb90f321a1e5c9691b2b6f5f260fd86b4b2474ecff9eda2bf98574f5"
         "7cb0ba517a464a7867e6251c60d2fd88f52da0ef7fde562e167d4583c88cde80",
     FXL_ERR_ARG, 0},
    {"5c10c9cbc65bb196a908c24e5d8fb4ab47d57c43c5fbb0b74bf4f257a62d94da"
         "02798cc64053ab467649d180a5accc5b5946a458bcf0d46859ecd72cdeddb073"
         "f95df455842487fa2a32d65cefda7a48b114b8abba6a2b9dc7ef9484aaef6b4d",
     FXL_OK, 9},
    {"9f8dc6dda345b8fe07322896709fa62e38c2af2ea1b70afc78fa392a0de4221c"
         "51f72e7b318c096a775961a99c1297343cb7e75f005967f347db68dd1db0d48c"
         "5ff6098c9d4d184b8b8356f3944bf55ad1216b68d090a4895e7724289861907a",
     FXL_ERR_RANGE, 0},
    {"f532f7229b1759d2e4a900611b5390ea9d8a2453a1e0e490606d6efa397e4a7a"
         "f8b56162f6dae928989842bdfb4d7f406a0551f1fb4e7ded49247a061fa89ff5"
         "713e4b0ac822d364037a888f463eef79c8093e7d44d827b8fd494b7e9bfe7984",
     FXL_ERR_RANGE, 0}
};

static size_t unhex(const char *h, uint8_t *b, size_t cap)
{
    size_t n = 0;
    while (h[0] && h[1] && n < cap) {
        unsigned v;
        sscanf(h, "%2x", &v);
        b[n++] = (uint8_t)v;
        h += 2;
    }
    return n;
}

/* want: the status; want_written: the pixels (< 0: not checked) */
static void run_case(fz_case *c, int want, int want_written, const char *what)
{
    fz_outcome o;
    char msg[FZ_MSG], m2[FZ_MSG + 120];
    int bad = fz_run_case(&st, c, &o, msg);
    snprintf(m2, sizeof m2, "%s: %s", what, bad ? msg : "ok");
    if (bad)
        fz_print_case(stdout, c);   /* the decoded input, for the record */
    TEST_ASSERT_TRUE_MESSAGE(!bad, m2);
    TEST_ASSERT_EQUAL_INT_MESSAGE(want, o.status, what);
    if (want_written >= 0)
        TEST_ASSERT_EQUAL_INT_MESSAGE(want_written, (int)o.written, what);
}

void test_fuzz_recorded_inputs_replay_clean(void)
{
    size_t i, refused = 0, n_replays = sizeof replays / sizeof replays[0];
    char counts[160];
    for (i = 0; i < n_replays; i++) {
        uint8_t b[512];
        fz_case c;
        char what[96];
        size_t n = unhex(replays[i].hex, b, sizeof b);
        const char *need;
        fz_decode(b, n, &c);
        need = fz_left_out(&c);
        snprintf(what, sizeof what, "replay %u", (unsigned)i);
        if (replays[i].status == FXL_OK && need) {
            /* A valid case drawing with a feature this build left out is
             * refused and draws nothing, culled or not (a recorded error is
             * found before the feature checks). */
            snprintf(what, sizeof what, "replay %u (needs %s)", (unsigned)i, need);
            run_case(&c, FXL_ERR_UNSUPPORTED, 0, what);
            refused++;
        } else {
            run_case(&c, replays[i].status, (int)replays[i].written, what);
        }
    }
    snprintf(counts, sizeof counts, "%u of %u recorded inputs replayed as recorded, %u refused: they need "
             "features this build lacks", (unsigned)(n_replays - refused), (unsigned)n_replays, (unsigned)refused);
    TEST_MESSAGE(counts);
}

/* A valid 16x16 target (in the RGB565 byte order this build draws),
 * untextured flat draw without depth, full clip. */
static void base_case(fz_case *c)
{
    memset(c, 0, sizeof *c);
    c->w = c->h = c->stride = 16;
    c->format = drawable_rgb565();
    c->clip.x1 = c->clip.y1 = 16;
    fxl_draw_defaults(&c->draw);
    c->draw.depth = 0;
    c->draw.color = 0x1234;
#if !FXL_HAVE_GENERIC
    /* Untextured draws are left out: a 1x1 RGB565 repeat texture (a random
     * texel; fz_run_case counts written pixels on two backgrounds). */
    c->has_tex = 1;
    c->tex.format = FXL_TEXFMT_RGB565;
    c->tex.levels = 1;
    c->tex_seed = 1u;
    c->draw.texture = &c->tex;
#endif
}

static void set_v(fxl_vertex_t *v, int32_t x, int32_t y, uint32_t inv_w)
{
    v->x = x;
    v->y = y;
    v->inv_w = inv_w;
    v->u = v->v = 0;
    v->color = 0xFFFF;
}

void test_fuzz_int32_extreme_triangle_covers_the_whole_target(void)
{
    fz_case c;
    base_case(&c);
    /* (INT32_MIN, INT32_MAX), (INT32_MAX, INT32_MAX), (0, INT32_MIN): the
     * target (0..16)^2 lies well inside, so all 256 pixels are covered. */
    set_v(&c.v[0], INT32_MIN, INT32_MAX, 1u);
    set_v(&c.v[1], INT32_MAX, INT32_MAX, UINT32_MAX);
    set_v(&c.v[2], 0, INT32_MIN, 1u);
    run_case(&c, FXL_OK, 256, "int32 extremes");
}

void test_fuzz_inv_w_zero_is_range_error_and_draws_nothing(void)
{
    fz_case c;
    base_case(&c);
    set_v(&c.v[0], 0, 0, 0u);
    set_v(&c.v[1], 16 << 16, 0, 1u);
    set_v(&c.v[2], 0, 16 << 16, 1u);
    run_case(&c, FXL_ERR_RANGE, 0, "inv_w 0");
}

void test_fuzz_invalid_draw_fields_are_refused(void)
{
    fz_case c;
    base_case(&c);
    set_v(&c.v[0], 0, 0, 1u);
    set_v(&c.v[1], 16 << 16, 0, 1u);
    set_v(&c.v[2], 0, 16 << 16, 1u);
    c.draw.persp = 3;   /* not a power of two: raster.h FXL_ERR_RANGE */
    run_case(&c, FXL_ERR_RANGE, 0, "persp 3");
    c.draw.persp = FXL_PERSP_AUTO;
    c.draw.auto_budget = 0;   /* budget must be > 0 */
    run_case(&c, FXL_ERR_RANGE, 0, "auto budget 0");
    c.draw.auto_budget = FXL_Q16_ONE / 4;
    c.draw.filter = 2;   /* unknown enum: FXL_ERR_ARG */
    run_case(&c, FXL_ERR_ARG, 0, "filter 2");
}

void test_fuzz_sliver_thinner_than_the_grid_is_culled(void)
{
    fz_case c;
    base_case(&c);
    /* 1/64 px apart: both snap to the same 1/16 grid line, zero area */
    set_v(&c.v[0], 0, 0x8000, UINT32_MAX);
    set_v(&c.v[1], 16 << 16, 0x8000 + 0x400, 1u);
    set_v(&c.v[2], 8 << 16, 0x8000 + 0x200, 7u);
    run_case(&c, FXL_OK, 0, "sub-grid sliver");
}

int main(void)
{
    UNITY_BEGIN();
    if (fz_state_init(&st) != 0) {
        printf("cannot allocate the fuzz state\n");
        return 1;
    }
    RUN_TEST(test_fuzz_recorded_inputs_replay_clean);
    RUN_TEST(test_fuzz_int32_extreme_triangle_covers_the_whole_target);
    RUN_TEST(test_fuzz_inv_w_zero_is_range_error_and_draws_nothing);
    RUN_TEST(test_fuzz_invalid_draw_fields_are_refused);
    RUN_TEST(test_fuzz_sliver_thinner_than_the_grid_is_culled);
    return UNITY_END();
}
