/* test_target.c - render targets: argument checks, clipping, bands, clears,
 * byte-swapped RGB565; plus the status names every module reports with.
 *
 * Clears are checked pixel by pixel against canaries placed in the padding
 * columns (stride > width), in guard words before and after the buffer and
 * in every buffer pixel outside the clip; a failure names the element.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "fixel/config.h"
#include "fixel/target.h"

void setUp(void) {}
void tearDown(void) {}

#define ASSERT_STATUS(expected, actual) \
    TEST_ASSERT_EQUAL_INT_MESSAGE((int)(expected), (int)(actual), fxl_status_name(actual))

/* A 20 x 16 buffer with stride 24 and 8 guard words on each side. */
#define W 20
#define H 16
#define STRIDE 24
#define GUARD 8
#define CANARY 0xA55Au

static uint16_t storage[GUARD + STRIDE * H + GUARD];
static uint16_t depth_storage[GUARD + STRIDE * H + GUARD];
static uint16_t *const pix = storage + GUARD;
static uint16_t *const depth = depth_storage + GUARD;
static char msg[160];

static void fill(uint16_t *buf, size_t n, uint16_t v)
{
    size_t i;
    for (i = 0; i < n; i++) buf[i] = v;
}

static fxl_target_t make_target(fxl_pixfmt_t fmt)
{
    fxl_target_t t;
    fill(storage, sizeof storage / sizeof storage[0], CANARY);
    fill(depth_storage, sizeof depth_storage / sizeof depth_storage[0], CANARY);
    ASSERT_STATUS(FXL_OK, fxl_target_init(&t, pix, W, H, STRIDE, fmt));
    return t;
}

/* Check a whole storage array: element (x, y) of the buffer (x < stride)
 * must hold `inside` when frame pixel (origin + x, origin + y) is in `r` and
 * x < W, CANARY otherwise; the guard words must hold CANARY. */
static void expect_only_rect(const uint16_t *store, const fxl_target_t *t, const fxl_rect_t *r,
                             uint16_t inside)
{
    int32_t i;
    for (i = 0; i < GUARD; i++) {
        snprintf(msg, sizeof msg, "guard word %ld before the buffer", (long)i);
        TEST_ASSERT_EQUAL_HEX32_MESSAGE(CANARY, store[i], msg);
        snprintf(msg, sizeof msg, "guard word %ld after the buffer", (long)i);
        TEST_ASSERT_EQUAL_HEX32_MESSAGE(CANARY, store[GUARD + STRIDE * H + i], msg);
    }
    for (i = 0; i < STRIDE * H; i++) {
        int32_t bx = i % STRIDE, by = i / STRIDE;
        int32_t fx = t->origin_x + bx, fy = t->origin_y + by;
        int in = bx < W && fx >= r->x0 && fx < r->x1 && fy >= r->y0 && fy < r->y1;
        snprintf(msg, sizeof msg, "buffer (%ld,%ld) = frame (%ld,%ld), %s clip", (long)bx,
                 (long)by, (long)fx, (long)fy, in ? "inside" : "outside");
        TEST_ASSERT_EQUAL_HEX32_MESSAGE(in ? inside : CANARY, store[GUARD + i], msg);
    }
}

static void expect_rect(const fxl_rect_t *r, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    TEST_ASSERT_EQUAL_INT32(x0, r->x0);
    TEST_ASSERT_EQUAL_INT32(y0, r->y0);
    TEST_ASSERT_EQUAL_INT32(x1, r->x1);
    TEST_ASSERT_EQUAL_INT32(y1, r->y1);
}

static fxl_rect_t rect(int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    fxl_rect_t r;
    r.x0 = x0;
    r.y0 = y0;
    r.x1 = x1;
    r.y1 = y1;
    return r;
}

/* ---------------------------------------------------------------------- */
/* Status names                                                           */

static void test_status_name_of_every_code(void)
{
    TEST_ASSERT_EQUAL_STRING("FXL_OK", fxl_status_name(FXL_OK));
    TEST_ASSERT_EQUAL_STRING("FXL_ERR_ARG", fxl_status_name(FXL_ERR_ARG));
    TEST_ASSERT_EQUAL_STRING("FXL_ERR_RANGE", fxl_status_name(FXL_ERR_RANGE));
    TEST_ASSERT_EQUAL_STRING("FXL_ERR_UNSUPPORTED", fxl_status_name(FXL_ERR_UNSUPPORTED));
    TEST_ASSERT_EQUAL_STRING("FXL_ERR_NOMEM", fxl_status_name(FXL_ERR_NOMEM));
    TEST_ASSERT_EQUAL_STRING("FXL_ERR_BUSY", fxl_status_name(FXL_ERR_BUSY));
    TEST_ASSERT_EQUAL_STRING("FXL_ERR_IO", fxl_status_name(FXL_ERR_IO));
}

static void test_status_name_of_unknown_value(void)
{
    TEST_ASSERT_EQUAL_STRING("FXL_ERR_UNKNOWN", fxl_status_name((fxl_status_t)1));
    TEST_ASSERT_EQUAL_STRING("FXL_ERR_UNKNOWN", fxl_status_name((fxl_status_t)-7));
    TEST_ASSERT_EQUAL_STRING("FXL_ERR_UNKNOWN", fxl_status_name((fxl_status_t)-1000));
}

/* ---------------------------------------------------------------------- */
/* init                                                                   */

static void test_init_sets_whole_buffer_clip_and_no_depth(void)
{
    fxl_target_t t;
    memset(&t, 0xCC, sizeof t);
    ASSERT_STATUS(FXL_OK, fxl_target_init(&t, pix, W, H, STRIDE, FXL_PIXFMT_RGB565_SWAP));
    TEST_ASSERT_TRUE(t.pixels == pix);
    TEST_ASSERT_NULL(t.depth);
    TEST_ASSERT_EQUAL_INT32(W, t.width);
    TEST_ASSERT_EQUAL_INT32(H, t.height);
    TEST_ASSERT_EQUAL_INT32(STRIDE, t.stride);
    TEST_ASSERT_EQUAL_INT32(0, t.origin_x);
    TEST_ASSERT_EQUAL_INT32(0, t.origin_y);
    TEST_ASSERT_EQUAL_INT((int)FXL_PIXFMT_RGB565_SWAP, (int)t.format);
    expect_rect(&t.clip, 0, 0, W, H);
}

static void test_init_rejects_null_and_unknown_format_with_arg(void)
{
    fxl_target_t t;
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_init(NULL, pix, W, H, STRIDE, FXL_PIXFMT_RGB565));
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_init(&t, NULL, W, H, STRIDE, FXL_PIXFMT_RGB565));
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_init(&t, pix, W, H, STRIDE, (fxl_pixfmt_t)2));
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_init(&t, pix, W, H, STRIDE, (fxl_pixfmt_t)-1));
}

/* Pixels and depth values are stored as uint16_t: a buffer at an odd
 * address (a byte array cast to uint16_t *) would make every store
 * misaligned, a HardFault on a Cortex-M0+. Refused, and nothing changes. */
static void test_odd_address_buffers_are_refused_with_arg(void)
{
    static uint16_t words[STRIDE * H + 1];
    uint16_t *odd = (uint16_t *)(void *)((unsigned char *)words + 1);
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565), before;
    fxl_target_t fresh;
    memset(&fresh, 0x5A, sizeof fresh);
    memcpy(&before, &fresh, sizeof before);
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_init(&fresh, odd, W, H, STRIDE, FXL_PIXFMT_RGB565));
    TEST_ASSERT_EQUAL_MEMORY(&before, &fresh, sizeof fresh);
    memcpy(&before, &t, sizeof before);
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_set_depth(&t, odd));
    TEST_ASSERT_EQUAL_MEMORY(&before, &t, sizeof t);
}

/* The struct is plain data: a pixel or depth pointer moved to an odd
 * address by hand after init is refused by the clears as init refuses it,
 * before any (misaligned) store; the buffer keeps its canaries. Every
 * other call re-checks the pixel pointer too (set_origin once did not). */
static void test_odd_pointers_edited_in_are_refused_by_clears(void)
{
    static uint16_t words[STRIDE * H + 1];
    uint16_t *odd = (uint16_t *)(void *)((unsigned char *)words + 1);
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    const fxl_rect_t r = {0, 0, 2, 2};
    size_t k;
    for (k = 0; k < sizeof words / sizeof words[0]; k++) words[k] = CANARY;
    t.pixels = odd;
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_set_origin(&t, 3, 4));
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_set_clip(&t, &r));
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_set_depth(&t, NULL));
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_clear(&t, 0x1234u));
    for (k = 0; k < sizeof words / sizeof words[0]; k++) {
        snprintf(msg, sizeof msg, "word %lu written through an odd pixel pointer", (unsigned long)k);
        TEST_ASSERT_EQUAL_HEX32_MESSAGE(CANARY, words[k], msg);
    }
#if FXL_HAVE_DEPTH
    t = make_target(FXL_PIXFMT_RGB565);
    t.depth = odd;
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_clear_depth(&t));
    for (k = 0; k < sizeof words / sizeof words[0]; k++) {
        snprintf(msg, sizeof msg, "word %lu written through an odd depth pointer", (unsigned long)k);
        TEST_ASSERT_EQUAL_HEX32_MESSAGE(CANARY, words[k], msg);
    }
#endif
}

static void test_init_rejects_sizes_with_range(void)
{
    fxl_target_t t;
    const fxl_pixfmt_t f = FXL_PIXFMT_RGB565;
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, 0, H, STRIDE, f));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, -1, H, STRIDE, f));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, INT32_MIN, H, STRIDE, f));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, FXL_TARGET_MAX_DIM + 1, H, 8192, f));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, W, 0, STRIDE, f));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, W, -1, STRIDE, f));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, W, INT32_MAX, STRIDE, f));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, W, FXL_TARGET_MAX_DIM + 1, STRIDE, f));
    /* stride < width */
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, W, H, W - 1, f));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, W, H, 0, f));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, W, H, INT32_MIN, f));
}

static void test_init_accepts_limits(void)
{
    /* init only records the pointer, so the sizes can exceed `storage`. */
    fxl_target_t t;
    const fxl_pixfmt_t f = FXL_PIXFMT_RGB565;
    ASSERT_STATUS(FXL_OK, fxl_target_init(&t, pix, 1, 1, 1, f));
    ASSERT_STATUS(FXL_OK, fxl_target_init(&t, pix, FXL_TARGET_MAX_DIM, FXL_TARGET_MAX_DIM,
                                          FXL_TARGET_MAX_DIM, f));
    expect_rect(&t.clip, 0, 0, FXL_TARGET_MAX_DIM, FXL_TARGET_MAX_DIM);
    ASSERT_STATUS(FXL_OK, fxl_target_init(&t, pix, W, H, W, f)); /* stride == width */
}

static void test_init_rejects_stride_beyond_limit(void)
{
    /* stride <= 4 * FXL_TARGET_MAX_DIM (the limit the draw calls check), so
     * any element offset y * stride + x stays below 2^26. */
    fxl_target_t t;
    const fxl_pixfmt_t f = FXL_PIXFMT_RGB565;
    ASSERT_STATUS(FXL_OK, fxl_target_init(&t, pix, 1, 4096, 4 * FXL_TARGET_MAX_DIM, f));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, 1, 4096, 4 * FXL_TARGET_MAX_DIM + 1, f));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, W, 2, INT32_MAX, f));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, W, 1, INT32_MAX, f));
}

static void test_init_failure_leaves_target_untouched(void)
{
    fxl_target_t t, before;
    memset(&t, 0x5C, sizeof t);
    memcpy(&before, &t, sizeof before);
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_init(&t, NULL, W, H, STRIDE, FXL_PIXFMT_RGB565));
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_init(&t, pix, W, H, STRIDE, (fxl_pixfmt_t)9));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, 0, H, STRIDE, FXL_PIXFMT_RGB565));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_init(&t, pix, W, H, 1, FXL_PIXFMT_RGB565));
    TEST_ASSERT_EQUAL_MEMORY(&before, &t, sizeof t);
}

/* ---------------------------------------------------------------------- */
/* A hand-broken target is rejected by every function                     */

typedef fxl_status_t (*target_op)(fxl_target_t *t);

static fxl_status_t op_set_origin(fxl_target_t *t) { return fxl_target_set_origin(t, 0, 0); }
static fxl_status_t op_set_clip(fxl_target_t *t)
{
    fxl_rect_t r = rect(0, 0, 1, 1);
    return fxl_target_set_clip(t, &r);
}
static fxl_status_t op_set_depth(fxl_target_t *t) { return fxl_target_set_depth(t, NULL); }
static fxl_status_t op_clear(fxl_target_t *t) { return fxl_target_clear(t, 0x1234u); }
static fxl_status_t op_clear_depth(fxl_target_t *t) { return fxl_target_clear_depth(t); }

static const struct {
    const char *name;
    target_op op;
} ops[] = {
    {"set_origin", op_set_origin}, {"set_clip", op_set_clip},   {"set_depth", op_set_depth},
    {"clear", op_clear},           {"clear_depth", op_clear_depth},
};

/* skip_set_origin: the broken field is the origin itself, which
 * set_origin overwrites, so set_origin is allowed to repair it. */
static void check_every_op(fxl_status_t expected, const fxl_target_t *broken, const char *what,
                           int skip_set_origin)
{
    size_t i;
    for (i = 0; i < sizeof ops / sizeof ops[0]; i++) {
        fxl_target_t t = *broken;
        fxl_status_t st;
        if (skip_set_origin && ops[i].op == op_set_origin) {
            continue;
        }
        st = ops[i].op(&t);
        snprintf(msg, sizeof msg, "%s on %s: got %s", ops[i].name, what, fxl_status_name(st));
        TEST_ASSERT_EQUAL_INT_MESSAGE((int)expected, (int)st, msg);
    }
}

static void test_every_function_rejects_null_target(void)
{
    size_t i;
    fxl_rect_t r = rect(0, 0, 1, 1);
    for (i = 0; i < sizeof ops / sizeof ops[0]; i++) {
        fxl_status_t st = ops[i].op(NULL);
        snprintf(msg, sizeof msg, "%s(NULL): got %s", ops[i].name, fxl_status_name(st));
        TEST_ASSERT_EQUAL_INT_MESSAGE((int)FXL_ERR_ARG, (int)st, msg);
    }
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_set_clip(NULL, &r));
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_set_depth(NULL, depth));
}

static void test_every_function_rejects_a_hand_broken_target(void)
{
    fxl_target_t good = make_target(FXL_PIXFMT_RGB565), bad;

    bad = good;
    bad.pixels = NULL;
    check_every_op(FXL_ERR_ARG, &bad, "pixels == NULL", 0);
    bad = good;
    bad.format = (fxl_pixfmt_t)5;
    check_every_op(FXL_ERR_ARG, &bad, "unknown format", 0);
    bad = good;
    bad.width = 0;
    check_every_op(FXL_ERR_RANGE, &bad, "width 0", 0);
    bad = good;
    bad.height = FXL_TARGET_MAX_DIM + 1;
    check_every_op(FXL_ERR_RANGE, &bad, "height too big", 0);
    bad = good;
    bad.stride = W - 1;
    check_every_op(FXL_ERR_RANGE, &bad, "stride < width", 0);
    bad = good;
    bad.origin_x = FXL_TARGET_MAX_ORIGIN + 1;
    check_every_op(FXL_ERR_RANGE, &bad, "origin_x too big", 1);
    ASSERT_STATUS(FXL_OK, fxl_target_set_origin(&bad, 0, 0));
    expect_rect(&bad.clip, 0, 0, W, H);
    bad = good;
    bad.origin_y = INT32_MIN;
    check_every_op(FXL_ERR_RANGE, &bad, "origin_y INT32_MIN", 1);
    ASSERT_STATUS(FXL_OK, fxl_target_set_origin(&bad, 0, 0));
    /* nothing was written by any of them */
    expect_only_rect(storage, &good, &good.clip, CANARY);
}

/* ---------------------------------------------------------------------- */
/* Origin                                                                 */

static void test_set_origin_accepts_limits_and_resets_clip(void)
{
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    fxl_rect_t r = rect(3, 3, 5, 5);
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    ASSERT_STATUS(FXL_OK, fxl_target_set_origin(&t, 100, 48));
    TEST_ASSERT_EQUAL_INT32(100, t.origin_x);
    TEST_ASSERT_EQUAL_INT32(48, t.origin_y);
    expect_rect(&t.clip, 100, 48, 100 + W, 48 + H);
    ASSERT_STATUS(FXL_OK, fxl_target_set_origin(&t, FXL_TARGET_MAX_ORIGIN, -FXL_TARGET_MAX_ORIGIN));
    expect_rect(&t.clip, FXL_TARGET_MAX_ORIGIN, -FXL_TARGET_MAX_ORIGIN,
                FXL_TARGET_MAX_ORIGIN + W, -FXL_TARGET_MAX_ORIGIN + H);
    ASSERT_STATUS(FXL_OK, fxl_target_set_origin(&t, -FXL_TARGET_MAX_ORIGIN, FXL_TARGET_MAX_ORIGIN));
    expect_rect(&t.clip, -FXL_TARGET_MAX_ORIGIN, FXL_TARGET_MAX_ORIGIN,
                -FXL_TARGET_MAX_ORIGIN + W, FXL_TARGET_MAX_ORIGIN + H);
}

static void test_set_origin_rejects_out_of_range_and_keeps_target(void)
{
    static const int32_t bad[] = {FXL_TARGET_MAX_ORIGIN + 1, -FXL_TARGET_MAX_ORIGIN - 1,
                                  INT32_MAX, INT32_MIN};
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565), before;
    fxl_rect_t r = rect(3, 3, 5, 5);
    size_t i;
    ASSERT_STATUS(FXL_OK, fxl_target_set_origin(&t, 7, 9));
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    memcpy(&before, &t, sizeof before);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_set_origin(&t, bad[i], 0));
        ASSERT_STATUS(FXL_ERR_RANGE, fxl_target_set_origin(&t, 0, bad[i]));
        TEST_ASSERT_EQUAL_MEMORY(&before, &t, sizeof t);
    }
}

/* ---------------------------------------------------------------------- */
/* Clip                                                                   */

static void test_set_clip_rejects_null_rect(void)
{
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_set_clip(&t, NULL));
    expect_rect(&t.clip, 0, 0, W, H);
}

static void test_set_clip_inside_is_kept(void)
{
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    fxl_rect_t r = rect(2, 3, 7, 11);
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    expect_rect(&t.clip, 2, 3, 7, 11);
    r = rect(0, 0, W, H);
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    expect_rect(&t.clip, 0, 0, W, H);
}

static void test_set_clip_is_intersected_with_buffer(void)
{
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    fxl_rect_t r = rect(-5, -5, 4, 6);
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    expect_rect(&t.clip, 0, 0, 4, 6);
    r = rect(10, 8, W + 100, H + 100);
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    expect_rect(&t.clip, 10, 8, W, H);
    r = rect(INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX);
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    expect_rect(&t.clip, 0, 0, W, H);
}

static void test_set_clip_disjoint_or_inverted_gives_empty_clip_inside_buffer(void)
{
    static const fxl_rect_t cases[] = {
        {-10, 0, -1, H},        /* left of the buffer */
        {W + 1, 0, W + 9, H},   /* right */
        {0, -9, W, -2},         /* above */
        {0, H, W, H + 5},       /* touching the bottom edge: empty */
        {8, 4, 3, 9},           /* inverted x */
        {2, 9, 6, 4},           /* inverted y */
        {5, 5, 5, 9},           /* zero width */
        {INT32_MAX, INT32_MAX, INT32_MIN, INT32_MIN},
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
        const fxl_rect_t *c = &t.clip;
        ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &cases[i]));
        snprintf(msg, sizeof msg, "case %u -> (%ld,%ld)-(%ld,%ld)", (unsigned)i, (long)c->x0,
                 (long)c->y0, (long)c->x1, (long)c->y1);
        TEST_ASSERT_TRUE_MESSAGE(c->x0 == c->x1 || c->y0 == c->y1, msg);
        TEST_ASSERT_TRUE_MESSAGE(0 <= c->x0 && c->x0 <= c->x1 && c->x1 <= W, msg);
        TEST_ASSERT_TRUE_MESSAGE(0 <= c->y0 && c->y0 <= c->y1 && c->y1 <= H, msg);
        /* An empty clip is valid and clear writes nothing. */
        ASSERT_STATUS(FXL_OK, fxl_target_clear(&t, 0x0F0Fu));
        expect_only_rect(storage, &t, c, 0x0F0Fu); /* c is empty: all canaries */
    }
}

static void test_band_clip_is_in_frame_coordinates(void)
{
    /* Band at frame rows 48..63: a clip over frame rows 50..69 keeps 50..63. */
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    fxl_rect_t r = rect(2, 50, 10, 70);
    ASSERT_STATUS(FXL_OK, fxl_target_set_origin(&t, 0, 48));
    expect_rect(&t.clip, 0, 48, W, 48 + H);
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    expect_rect(&t.clip, 2, 50, 10, 64);
    /* A clip over the previous band (rows 0..47) is empty in this one. */
    r = rect(0, 0, W, 48);
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    TEST_ASSERT_TRUE(t.clip.y0 == t.clip.y1);
    TEST_ASSERT_TRUE(t.clip.y0 >= 48 && t.clip.y1 <= 48 + H);
}

/* ---------------------------------------------------------------------- */
/* Clear                                                                  */

static void test_clear_whole_buffer_spares_padding_and_guards(void)
{
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    ASSERT_STATUS(FXL_OK, fxl_target_clear(&t, 0x07E0u));
    expect_only_rect(storage, &t, &t.clip, 0x07E0u);
}

static void test_clear_writes_only_inside_clip(void)
{
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    fxl_rect_t r = rect(3, 2, 17, 9);
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    ASSERT_STATUS(FXL_OK, fxl_target_clear(&t, 0x1234u));
    expect_only_rect(storage, &t, &r, 0x1234u);
    /* a one-pixel clip in the last column of the last row */
    t = make_target(FXL_PIXFMT_RGB565);
    r = rect(W - 1, H - 1, W, H);
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    ASSERT_STATUS(FXL_OK, fxl_target_clear(&t, 0xFFFFu));
    expect_only_rect(storage, &t, &r, 0xFFFFu);
}

static void test_clear_band_with_origin_48(void)
{
    /* Frame rows 48..63 live in this buffer; a frame-coordinate clip
     * (2, 50)-(10, 70) must write buffer rows 2..15, columns 2..9. */
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    fxl_rect_t r = rect(2, 50, 10, 70);
    ASSERT_STATUS(FXL_OK, fxl_target_set_origin(&t, 0, 48));
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    ASSERT_STATUS(FXL_OK, fxl_target_clear(&t, 0xBEEFu));
    expect_only_rect(storage, &t, &r, 0xBEEFu);
    TEST_ASSERT_EQUAL_HEX16(0xBEEFu, pix[2 * STRIDE + 2]);
    TEST_ASSERT_EQUAL_HEX16(0xBEEFu, pix[15 * STRIDE + 9]);
    TEST_ASSERT_EQUAL_HEX16(CANARY, pix[1 * STRIDE + 2]);
    TEST_ASSERT_EQUAL_HEX16(CANARY, pix[2 * STRIDE + 10]);
}

static void test_clear_band_with_negative_x_origin(void)
{
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    fxl_rect_t r = rect(-30, 100, -15, 104);
    ASSERT_STATUS(FXL_OK, fxl_target_set_origin(&t, -32, 96));
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    ASSERT_STATUS(FXL_OK, fxl_target_clear(&t, 0x0001u));
    expect_only_rect(storage, &t, &r, 0x0001u);
    TEST_ASSERT_EQUAL_HEX16(0x0001u, pix[4 * STRIDE + 2]); /* frame (-30, 100) */
}

static void test_clear_never_writes_outside_buffer_even_with_hand_edited_clip(void)
{
    /* The struct is public; a clip written by hand past the buffer must
     * still not reach the padding columns or the guard words. */
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    fxl_rect_t whole = rect(0, 0, W, H);
    t.clip = rect(-100, -100, 1000, 1000);
    ASSERT_STATUS(FXL_OK, fxl_target_clear(&t, 0x5555u));
    expect_only_rect(storage, &t, &whole, 0x5555u);
    t = make_target(FXL_PIXFMT_RGB565);
    t.clip = rect(INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX);
    ASSERT_STATUS(FXL_OK, fxl_target_clear(&t, 0x5555u));
    expect_only_rect(storage, &t, &whole, 0x5555u);
}

static void test_clear_native_format_stores_native_value(void)
{
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    ASSERT_STATUS(FXL_OK, fxl_target_clear(&t, 0xF81Fu));
    TEST_ASSERT_EQUAL_HEX16(0xF81Fu, pix[0]);
    TEST_ASSERT_EQUAL_HEX16(0xF81Fu, pix[(H - 1) * STRIDE + W - 1]);
}

static void test_clear_swapped_format_stores_big_endian_bytes(void)
{
    /* MIPI DCS wants the red/high byte first on the wire, i.e. first in
     * memory, whatever the CPU's byte order. */
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565_SWAP);
    const uint8_t *bytes = (const uint8_t *)pix;
    int32_t x, y;
    ASSERT_STATUS(FXL_OK, fxl_target_clear(&t, 0xF81Fu));
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            size_t i = (size_t)(y * STRIDE + x) * 2u;
            snprintf(msg, sizeof msg, "pixel (%ld,%ld) byte 0", (long)x, (long)y);
            TEST_ASSERT_EQUAL_HEX32_MESSAGE(0xF8u, bytes[i], msg);
            snprintf(msg, sizeof msg, "pixel (%ld,%ld) byte 1", (long)x, (long)y);
            TEST_ASSERT_EQUAL_HEX32_MESSAGE(0x1Fu, bytes[i + 1], msg);
        }
        /* padding columns untouched */
        TEST_ASSERT_EQUAL_HEX16(CANARY, pix[y * STRIDE + W]);
    }
    ASSERT_STATUS(FXL_OK, fxl_target_clear(&t, 0x1234u));
    TEST_ASSERT_EQUAL_HEX16(0x12u, bytes[0]);
    TEST_ASSERT_EQUAL_HEX16(0x34u, bytes[1]);
}

static void test_clear_swapped_format_respects_clip(void)
{
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565_SWAP);
    fxl_rect_t r = rect(1, 1, 4, 3);
    const uint8_t be[2] = {0xABu, 0xCDu};
    uint16_t stored;
    memcpy(&stored, be, 2); /* the native word whose bytes are AB CD */
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    ASSERT_STATUS(FXL_OK, fxl_target_clear(&t, 0xABCDu));
    expect_only_rect(storage, &t, &r, stored);
}

/* ---------------------------------------------------------------------- */
/* Depth                                                                  */

static void test_set_depth_attaches_and_null_detaches(void)
{
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
#if FXL_HAVE_DEPTH
    ASSERT_STATUS(FXL_OK, fxl_target_set_depth(&t, depth));
    TEST_ASSERT_TRUE(t.depth == depth);
#else
    ASSERT_STATUS(FXL_ERR_UNSUPPORTED, fxl_target_set_depth(&t, depth));
#endif
    ASSERT_STATUS(FXL_OK, fxl_target_set_depth(&t, NULL));
    TEST_ASSERT_NULL(t.depth);
}

/* Clears write rows in 32-bit words where they can, from a row's first
 * 4-byte boundary (target.c, fill_row): every clip start and width on a
 * buffer whose odd stride puts alternate rows at both alignments, with
 * guard words around it, in both formats (the swapped one stores other
 * bytes). Exactly the rectangle changes. */
static void test_clear_rows_of_every_length_and_alignment(void)
{
    enum { WW = 41, WH = 4, WS = 43, WG = 4 };
    static uint16_t wide[WG + WS * WH + WG];
    int32_t x0, x1, f, i;
    for (f = 0; f < 2; f++) {
        const fxl_pixfmt_t fmt = f ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
        /* the stored word: 0x1234 native, or its bytes big-endian */
        static const unsigned char be[2] = {0x12u, 0x34u};
        uint16_t stored = 0x1234u;
        if (f)
            memcpy(&stored, be, sizeof stored);
        for (x0 = 0; x0 < 6; x0++)
            for (x1 = x0; x1 <= WW; x1++) {
                fxl_target_t t;
                fxl_rect_t r = rect(x0, 1, x1, WH);
                fill(wide, sizeof wide / sizeof wide[0], CANARY);
                ASSERT_STATUS(FXL_OK, fxl_target_init(&t, wide + WG, WW, WH, WS, fmt));
                ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
                ASSERT_STATUS(FXL_OK, fxl_target_clear(&t, 0x1234u));
                for (i = 0; i < (int32_t)(sizeof wide / sizeof wide[0]); i++) {
                    const int32_t b = i - WG, bx = b % WS, by = b / WS;
                    const int in = b >= 0 && b < WS * WH && by >= 1 && bx >= x0 && bx < x1;
                    snprintf(msg, sizeof msg, "format %d clip x %ld..%ld: word %ld (row %ld, column %ld)", (int)f,
                             (long)x0, (long)x1, (long)i, (long)by, (long)bx);
                    TEST_ASSERT_EQUAL_HEX32_MESSAGE(in ? stored : CANARY, wide[i], msg);
                }
            }
    }
}

static void test_clear_depth_writes_zero_inside_clip_only(void)
{
#if FXL_HAVE_DEPTH
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    fxl_rect_t r = rect(4, 50, 12, 58);
    ASSERT_STATUS(FXL_OK, fxl_target_set_depth(&t, depth));
    ASSERT_STATUS(FXL_OK, fxl_target_set_origin(&t, 0, 48));
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    ASSERT_STATUS(FXL_OK, fxl_target_clear_depth(&t));
    expect_only_rect(depth_storage, &t, &r, 0u);
    /* colour buffer untouched */
    expect_only_rect(storage, &t, &r, CANARY);
    /* whole buffer */
    ASSERT_STATUS(FXL_OK, fxl_target_set_origin(&t, 0, 48));
    ASSERT_STATUS(FXL_OK, fxl_target_clear_depth(&t));
    expect_only_rect(depth_storage, &t, &t.clip, 0u);
#else
    TEST_IGNORE_MESSAGE("FXL_HAVE_DEPTH is 0");
#endif
}

static void test_clear_depth_without_depth_buffer_is_an_error(void)
{
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
#if FXL_HAVE_DEPTH
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_clear_depth(&t));
    ASSERT_STATUS(FXL_OK, fxl_target_set_depth(&t, depth));
    ASSERT_STATUS(FXL_OK, fxl_target_set_depth(&t, NULL));
    ASSERT_STATUS(FXL_ERR_ARG, fxl_target_clear_depth(&t));
#else
    ASSERT_STATUS(FXL_ERR_UNSUPPORTED, fxl_target_clear_depth(&t));
#endif
    expect_only_rect(depth_storage, &t, &t.clip, CANARY);
    expect_only_rect(storage, &t, &t.clip, CANARY);
}

static void test_clear_depth_with_empty_clip_writes_nothing(void)
{
#if FXL_HAVE_DEPTH
    fxl_target_t t = make_target(FXL_PIXFMT_RGB565);
    fxl_rect_t r = rect(W, 0, W + 5, H);
    ASSERT_STATUS(FXL_OK, fxl_target_set_depth(&t, depth));
    ASSERT_STATUS(FXL_OK, fxl_target_set_clip(&t, &r));
    ASSERT_STATUS(FXL_OK, fxl_target_clear_depth(&t));
    expect_only_rect(depth_storage, &t, &r, 0u); /* r lies outside: all canaries */
#else
    TEST_IGNORE_MESSAGE("FXL_HAVE_DEPTH is 0");
#endif
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_status_name_of_every_code);
    RUN_TEST(test_status_name_of_unknown_value);
    RUN_TEST(test_init_sets_whole_buffer_clip_and_no_depth);
    RUN_TEST(test_init_rejects_null_and_unknown_format_with_arg);
    RUN_TEST(test_odd_address_buffers_are_refused_with_arg);
    RUN_TEST(test_odd_pointers_edited_in_are_refused_by_clears);
    RUN_TEST(test_init_rejects_sizes_with_range);
    RUN_TEST(test_init_accepts_limits);
    RUN_TEST(test_init_rejects_stride_beyond_limit);
    RUN_TEST(test_init_failure_leaves_target_untouched);
    RUN_TEST(test_every_function_rejects_null_target);
    RUN_TEST(test_every_function_rejects_a_hand_broken_target);
    RUN_TEST(test_set_origin_accepts_limits_and_resets_clip);
    RUN_TEST(test_set_origin_rejects_out_of_range_and_keeps_target);
    RUN_TEST(test_set_clip_rejects_null_rect);
    RUN_TEST(test_set_clip_inside_is_kept);
    RUN_TEST(test_set_clip_is_intersected_with_buffer);
    RUN_TEST(test_set_clip_disjoint_or_inverted_gives_empty_clip_inside_buffer);
    RUN_TEST(test_band_clip_is_in_frame_coordinates);
    RUN_TEST(test_clear_whole_buffer_spares_padding_and_guards);
    RUN_TEST(test_clear_writes_only_inside_clip);
    RUN_TEST(test_clear_band_with_origin_48);
    RUN_TEST(test_clear_band_with_negative_x_origin);
    RUN_TEST(test_clear_never_writes_outside_buffer_even_with_hand_edited_clip);
    RUN_TEST(test_clear_native_format_stores_native_value);
    RUN_TEST(test_clear_swapped_format_stores_big_endian_bytes);
    RUN_TEST(test_clear_swapped_format_respects_clip);
    RUN_TEST(test_set_depth_attaches_and_null_detaches);
    RUN_TEST(test_clear_rows_of_every_length_and_alignment);
    RUN_TEST(test_clear_depth_writes_zero_inside_clip_only);
    RUN_TEST(test_clear_depth_without_depth_buffer_is_an_error);
    RUN_TEST(test_clear_depth_with_empty_clip_writes_nothing);
    return UNITY_END();
}
