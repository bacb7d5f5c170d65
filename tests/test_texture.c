/* tests/test_texture.c - texture descriptors: validation, level layout, wrap
 * addressing, texel formats and the colour key (src/texture.c, src/texel.h). */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "fixel/fixel.h"
#include "test_vertex.h"
#include "../src/texel.h"

void setUp(void) {}
void tearDown(void) {}

static uint16_t g_rgb[64 * 64 * 2];
static uint8_t g_bytes[64 * 64 * 2];
static uint16_t g_palette[256];

/* ---- validation ---------------------------------------------------------- */

static fxl_texture_t valid_rgb565(void)
{
    fxl_texture_t t;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, g_rgb, 8, 4, FXL_TEXFMT_RGB565, 4));
    return t;
}

void test_init_fills_defaults_and_validates(void)
{
    fxl_texture_t t = valid_rgb565();
    TEST_ASSERT_EQUAL_UINT8(3, t.log2_w);
    TEST_ASSERT_EQUAL_UINT8(2, t.log2_h);
    TEST_ASSERT_EQUAL_UINT8(4, t.levels);
    TEST_ASSERT_EQUAL_UINT8(FXL_WRAP_REPEAT, t.wrap_u);
    TEST_ASSERT_EQUAL_UINT8(FXL_WRAP_REPEAT, t.wrap_v);
    TEST_ASSERT_EQUAL_UINT8(0, t.flags);
    TEST_ASSERT_NULL(t.palette);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_validate(&t));
}

void test_init_rejects_bad_arguments(void)
{
    fxl_texture_t t;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_init(NULL, g_rgb, 8, 8, FXL_TEXFMT_RGB565, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_init(&t, NULL, 8, 8, FXL_TEXFMT_RGB565, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_init(&t, g_rgb, 0, 8, FXL_TEXFMT_RGB565, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_init(&t, g_rgb, 8, 0, FXL_TEXFMT_RGB565, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_init(&t, g_rgb, 8, 8, (fxl_texfmt_t)3, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED,
                          fxl_texture_init(&t, g_rgb, 12, 8, FXL_TEXFMT_RGB565, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED,
                          fxl_texture_init(&t, g_rgb, 8, 3, FXL_TEXFMT_RGB565, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED,
                          fxl_texture_init(&t, g_rgb, 2u << FXL_TEX_MAX_LOG2, 8,
                                           FXL_TEXFMT_RGB565, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_texture_init(&t, g_rgb, 8, 8, FXL_TEXFMT_RGB565, 0));
    /* 8x8 has 4 levels (8, 4, 2, 1): 5 is one too many. */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_texture_init(&t, g_rgb, 8, 8, FXL_TEXFMT_RGB565, 5));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, g_rgb, 8, 8, FXL_TEXFMT_RGB565, 4));
}

void test_validate_error_paths(void)
{
    fxl_texture_t t;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_validate(NULL));

    t = valid_rgb565(); t.texels = NULL;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_validate(&t));
    t = valid_rgb565(); t.log2_w = FXL_TEX_MAX_LOG2 + 1;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_texture_validate(&t));
    t = valid_rgb565(); t.log2_h = 255;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_texture_validate(&t));
    t = valid_rgb565(); t.levels = 0;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_texture_validate(&t));
    /* 8x4: 1 + max(3, 2) = 4 levels at most. */
    t = valid_rgb565(); t.levels = 5;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_texture_validate(&t));
    t = valid_rgb565(); t.format = 3;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_validate(&t));
    t = valid_rgb565(); t.wrap_u = 4;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_validate(&t));
    t = valid_rgb565(); t.wrap_v = 200;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_validate(&t));
    t = valid_rgb565(); t.reserved = 1;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_validate(&t));
    t = valid_rgb565(); t.flags = 0x02;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_validate(&t));
    /* I8 without a palette, then with one. */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, g_bytes, 8, 8, FXL_TEXFMT_I8, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_validate(&t));
    t.palette = g_palette;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_validate(&t));
    /* An 8-bit format cannot store a key above 255. */
    t.flags = FXL_TEXF_KEY; t.key = 256;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_texture_validate(&t));
    t.key = 255;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_validate(&t));
    /* Every wrap mode on both axes is accepted. */
    t = valid_rgb565(); t.wrap_u = FXL_WRAP_BORDER; t.wrap_v = FXL_WRAP_MIRROR;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_validate(&t));
}

void test_texfmt_bytes(void)
{
    TEST_ASSERT_EQUAL_UINT32(2, fxl_texfmt_bytes(FXL_TEXFMT_RGB565));
    TEST_ASSERT_EQUAL_UINT32(1, fxl_texfmt_bytes(FXL_TEXFMT_L8));
    TEST_ASSERT_EQUAL_UINT32(1, fxl_texfmt_bytes(FXL_TEXFMT_I8));
    TEST_ASSERT_EQUAL_UINT32(0, fxl_texfmt_bytes((fxl_texfmt_t)7));
}

/* ---- level layout --------------------------------------------------------- */

/* Check the level sizes of a full chain against a hand-written list, the
 * offsets against their running sum, and the total against the closed form.
 * For w = 2^a, h = 2^b, a >= b: levels 0..b shrink by 4 (sum (4wh - 2^(a-b))/3)
 * and levels b+1..a form the 1-D tail 2^(a-b-1) + ... + 1 = 2^(a-b) - 1, so
 *   total = (4wh + 2 * 2^(a-b) - 3) / 3 = (4wh + 2 * max/min - 3) / 3,
 * i.e. 3 * total <= 4 * (level 0) + 2 * (max side / min side) - 3: at most
 * 4/3 of level 0 plus the 1-D tail term. Asserted exactly. */
static void check_chain(uint32_t w, uint32_t h, uint32_t expect_levels, const uint32_t *sizes)
{
    fxl_texture_t t;
    uint32_t n, sum = 0, ratio = w > h ? w / h : h / w;
    char msg[96];

    TEST_ASSERT_EQUAL_UINT32(expect_levels, fxl_mip_levels(w, h));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, g_rgb, w, h, FXL_TEXFMT_RGB565,
                                                  expect_levels));
    for (n = 0; n < expect_levels; n++) {
        uint32_t lw = 1u << fxl__level_log2(t.log2_w, n), lh = 1u << fxl__level_log2(t.log2_h, n);
        snprintf(msg, sizeof msg, "%ux%u level %u: %ux%u", (unsigned)w, (unsigned)h,
                 (unsigned)n, (unsigned)lw, (unsigned)lh);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(sizes[2 * n], lw, msg);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(sizes[2 * n + 1], lh, msg);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(sum, fxl_texture_level_offset(&t, n), msg);
        sum += lw * lh;
    }
    TEST_ASSERT_EQUAL_UINT32(sum, fxl_texture_level_offset(&t, expect_levels));
    TEST_ASSERT_EQUAL_UINT32((4u * w * h + 2u * ratio - 3u) / 3u, sum);
    TEST_ASSERT_LESS_OR_EQUAL(4u * w * h + 2u * ratio - 3u, 3u * sum);
    TEST_ASSERT_EQUAL_UINT32(sum * 2u, fxl_mip_size(w, h, FXL_TEXFMT_RGB565, expect_levels));
    TEST_ASSERT_EQUAL_UINT32(sum, fxl_mip_size(w, h, FXL_TEXFMT_L8, expect_levels));
}

void test_levels_512x512(void)
{
    static const uint32_t s[] = {512, 512, 256, 256, 128, 128, 64, 64, 32, 32,
                                 16,  16,  8,   8,   4,   4,   2,  2,  1,  1};
    check_chain(512, 512, 10, s);
    /* Square: (4 * 262144 - 1) / 3 = 349525 texels < 4/3 of level 0. */
    TEST_ASSERT_EQUAL_UINT32(349525u * 2u, fxl_mip_size(512, 512, FXL_TEXFMT_RGB565, 10));
}

void test_levels_128x32_non_square(void)
{
    static const uint32_t s[] = {128, 32, 64, 16, 32, 8, 16, 4, 8, 2, 4, 1, 2, 1, 1, 1};
    check_chain(128, 32, 8, s);
    /* 4096 + 1024 + 256 + 64 + 16 + 4 + 2 + 1 */
    TEST_ASSERT_EQUAL_UINT32(5463u, fxl_mip_size(128, 32, FXL_TEXFMT_L8, 8));
}

void test_levels_1x1_and_1x1024(void)
{
    static const uint32_t one[] = {1, 1};
    static uint32_t tall[22];
    uint32_t n;
    check_chain(1, 1, 1, one);
    for (n = 0; n < 11; n++) {
        tall[2 * n] = 1;
        tall[2 * n + 1] = 1024u >> n;
    }
    check_chain(1, 1024, 11, tall);
    /* 1-D chain: 1024 + 512 + ... + 1 = 2047 = (4096 + 2048 - 3) / 3. */
    TEST_ASSERT_EQUAL_UINT32(2047u, fxl_mip_size(1, 1024, FXL_TEXFMT_I8, 11));
}

void test_level_offset_partial_chain_and_bad_input(void)
{
    fxl_texture_t t;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, g_rgb, 16, 16, FXL_TEXFMT_RGB565, 2));
    /* Levels past the chain clamp to its end (256 + 64 texels). */
    TEST_ASSERT_EQUAL_UINT32(320, fxl_texture_level_offset(&t, 2));
    TEST_ASSERT_EQUAL_UINT32(320, fxl_texture_level_offset(&t, 9));
    TEST_ASSERT_EQUAL_UINT32(0, fxl_texture_level_offset(NULL, 1));
    TEST_ASSERT_EQUAL_UINT32(0, fxl_mip_levels(0, 4));
    TEST_ASSERT_EQUAL_UINT32(0, fxl_mip_levels(6, 4));
    TEST_ASSERT_EQUAL_UINT32(0, fxl_mip_levels(2u << FXL_TEX_MAX_LOG2, 1));
    TEST_ASSERT_EQUAL_UINT32(0, fxl_mip_size(16, 16, FXL_TEXFMT_RGB565, 6));
    TEST_ASSERT_EQUAL_UINT32(0, fxl_mip_size(16, 16, FXL_TEXFMT_RGB565, 0));
    TEST_ASSERT_EQUAL_UINT32(0, fxl_mip_size(16, 16, (fxl_texfmt_t)9, 1));
}

/* ---- wrap addressing ------------------------------------------------------ */

/* Coordinates probed for a side of n: -2n-1, -n-1, -n, -1, 0, n-1, n, 2n,
 * INT32_MIN, INT32_MAX. The expected indices follow from the definitions
 * (repeat: c mod n; mirror: m = c mod 2n, m < n ? m : 2n-1-m; clamp; border
 * -1 outside [0, n)); INT32_MIN = -2^31 is a multiple of 2n, INT32_MAX is
 * -1 modulo 2n. */
enum { NPROBE = 10 };

static void probes(int32_t n, int32_t c[NPROBE])
{
    c[0] = -2 * n - 1; c[1] = -n - 1; c[2] = -n; c[3] = -1; c[4] = 0;
    c[5] = n - 1;      c[6] = n;      c[7] = 2 * n; c[8] = INT32_MIN; c[9] = INT32_MAX;
}

static void expected(fxl_wrap_t mode, int32_t n, int32_t e[NPROBE])
{
    int32_t i;
    static const int32_t rep_k[NPROBE] = {-1, -1, 0, -1, 0, -1, 0, 0, 0, -1};
    /* in units: value k >= 0 is the index k, -1 means n-1 (repeat) */
    switch (mode) {
    case FXL_WRAP_REPEAT:
        for (i = 0; i < NPROBE; i++)
            e[i] = rep_k[i] < 0 ? n - 1 : rep_k[i];
        break;
    case FXL_WRAP_MIRROR: {
        /* -2n-1 = 2n-1 mod 2n -> 0; -n-1 = n-1 -> n-1; -n = n -> n-1; -1 -> 0;
         * 0; n-1; n -> n-1; 2n -> 0; MIN -> 0; MAX = 2n-1 -> 0. */
        const int32_t m[NPROBE] = {0, n - 1, n - 1, 0, 0, n - 1, n - 1, 0, 0, 0};
        memcpy(e, m, sizeof m);
        break;
    }
    case FXL_WRAP_CLAMP: {
        const int32_t m[NPROBE] = {0, 0, 0, 0, 0, n - 1, n - 1, n - 1, 0, n - 1};
        memcpy(e, m, sizeof m);
        break;
    }
    case FXL_WRAP_BORDER:
    default: {
        const int32_t m[NPROBE] = {-1, -1, -1, -1, 0, n - 1, -1, -1, -1, -1};
        memcpy(e, m, sizeof m);
        break;
    }
    }
}

/* Independent 64-bit reference of the same definitions. */
static int32_t ref_wrap(int64_t c, int64_t n, fxl_wrap_t mode)
{
    int64_t m;
    switch (mode) {
    case FXL_WRAP_REPEAT:
        return (int32_t)(((c % n) + n) % n);
    case FXL_WRAP_MIRROR:
        m = ((c % (2 * n)) + 2 * n) % (2 * n);
        return (int32_t)(m < n ? m : 2 * n - 1 - m);
    case FXL_WRAP_CLAMP:
        return (int32_t)(c < 0 ? 0 : c >= n ? n - 1 : c);
    default:
        return (int32_t)(c < 0 || c >= n ? -1 : c);
    }
}

void test_wrap_boundaries_every_mode(void)
{
    static const uint32_t sizes[] = {0, 1, 3, 8, FXL_TEX_MAX_LOG2};
    static const char *names[] = {"repeat", "mirror", "clamp", "border"};
    uint32_t s, i;
    int mode;
    char msg[128];

    for (s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        int32_t n = (int32_t)1 << sizes[s], c[NPROBE], e[NPROBE];
        probes(n, c);
        for (mode = 0; mode <= FXL_WRAP_BORDER; mode++) {
            expected((fxl_wrap_t)mode, n, e);
            for (i = 0; i < NPROBE; i++) {
                int32_t got = fxl__wrap(c[i], sizes[s], (fxl_wrap_t)mode);
                snprintf(msg, sizeof msg, "%s n=%ld coord=%ld: got %ld", names[mode], (long)n,
                         (long)c[i], (long)got);
                TEST_ASSERT_EQUAL_INT_MESSAGE(e[i], got, msg);
                TEST_ASSERT_EQUAL_INT_MESSAGE(ref_wrap(c[i], n, (fxl_wrap_t)mode), got, msg);
            }
        }
    }
}

void test_wrap_matches_reference_on_a_sweep(void)
{
    /* Every coordinate in [-5n, 5n] and a sparse sweep of the whole int32
     * range, n = 8, against the 64-bit reference. */
    int mode;
    int64_t c;
    char msg[128];
    for (mode = 0; mode <= FXL_WRAP_BORDER; mode++) {
        for (c = -40; c <= 40; c++) {
            int32_t got = fxl__wrap((int32_t)c, 3, (fxl_wrap_t)mode);
            snprintf(msg, sizeof msg, "mode %d coord %ld", mode, (long)c);
            TEST_ASSERT_EQUAL_INT_MESSAGE(ref_wrap(c, 8, (fxl_wrap_t)mode), got, msg);
        }
        for (c = INT32_MIN; c <= INT32_MAX; c += 0x01234567) {
            int32_t got = fxl__wrap((int32_t)c, 3, (fxl_wrap_t)mode);
            snprintf(msg, sizeof msg, "mode %d coord %ld", mode, (long)c);
            TEST_ASSERT_EQUAL_INT_MESSAGE(ref_wrap(c, 8, (fxl_wrap_t)mode), got, msg);
        }
    }
}

/* ---- fetch ---------------------------------------------------------------- */

/* 8x4 RGB565 level 0 with texel (x, y) = 0x100 * y + x, then a 4x2 level 1
 * with 0x8000 | (0x100 * y + x): a fetch tells where it read from. */
static void fill_addressed(void)
{
    uint32_t x, y;
    for (y = 0; y < 4; y++)
        for (x = 0; x < 8; x++)
            g_rgb[y * 8 + x] = (uint16_t)(0x100 * y + x);
    for (y = 0; y < 2; y++)
        for (x = 0; x < 4; x++)
            g_rgb[32 + y * 4 + x] = (uint16_t)(0x8000 | (0x100 * y + x));
}

void test_fetch_wraps_each_axis_independently(void)
{
    fxl_texture_t t = valid_rgb565();
    int tr = 7;
    fill_addressed();
    t.wrap_u = FXL_WRAP_MIRROR;
    t.wrap_v = FXL_WRAP_CLAMP;
    /* x = -1 mirrors to 0, y = 9 clamps to 3 */
    TEST_ASSERT_EQUAL_HEX16(0x0300, fxl_texture_fetch(&t, 0, -1, 9, &tr));
    TEST_ASSERT_EQUAL_INT(0, tr);
    /* x = 8 mirrors to 7, y = INT32_MIN clamps to 0 */
    TEST_ASSERT_EQUAL_HEX16(0x0007, fxl_texture_fetch(&t, 0, 8, INT32_MIN, &tr));
    /* level 1 is 4x2: x = -5 mirrors (mod 8 = 3) to 3, y = INT32_MAX clamps to 1 */
    TEST_ASSERT_EQUAL_HEX16(0x8103, fxl_texture_fetch(&t, 1, -5, INT32_MAX, &tr));
    t.wrap_u = FXL_WRAP_REPEAT;
    t.wrap_v = FXL_WRAP_REPEAT;
    /* repeat: x = -1 -> 7, y = -1 -> 3 */
    TEST_ASSERT_EQUAL_HEX16(0x0307, fxl_texture_fetch(&t, 0, -1, -1, NULL));
    TEST_ASSERT_EQUAL_HEX16(0x0000, fxl_texture_fetch(&t, 0, INT32_MIN, INT32_MIN, NULL));
    TEST_ASSERT_EQUAL_HEX16(0x0307, fxl_texture_fetch(&t, 0, INT32_MAX, INT32_MAX, NULL));
}

void test_fetch_border_reads_border_colour_never_transparent(void)
{
    fxl_texture_t t = valid_rgb565();
    int tr = 7;
    fill_addressed();
    t.wrap_u = FXL_WRAP_BORDER;
    t.wrap_v = FXL_WRAP_REPEAT;
    t.border = 0xF800;
    t.flags = FXL_TEXF_KEY;
    t.key = 0xF800; /* even a border equal to the key value is opaque */
    TEST_ASSERT_EQUAL_HEX16(0xF800, fxl_texture_fetch(&t, 0, -1, 0, &tr));
    TEST_ASSERT_EQUAL_INT(0, tr);
    TEST_ASSERT_EQUAL_HEX16(0xF800, fxl_texture_fetch(&t, 0, 8, 0, &tr));
    TEST_ASSERT_EQUAL_HEX16(0x0207, fxl_texture_fetch(&t, 0, 7, -2, &tr));
    /* only v is border here */
    t.wrap_u = FXL_WRAP_CLAMP;
    t.wrap_v = FXL_WRAP_BORDER;
    TEST_ASSERT_EQUAL_HEX16(0xF800, fxl_texture_fetch(&t, 0, 3, 4, &tr));
    TEST_ASSERT_EQUAL_HEX16(0x0307, fxl_texture_fetch(&t, 0, 100, 3, &tr));
}

void test_fetch_l8_expands_grey(void)
{
    fxl_texture_t t;
    static const uint8_t l[4] = {0, 255, 0x80, 0x47};
    int tr;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, l, 2, 2, FXL_TEXFMT_L8, 1));
    TEST_ASSERT_EQUAL_HEX16(0x0000, fxl_texture_fetch(&t, 0, 0, 0, &tr));
    TEST_ASSERT_EQUAL_HEX16(0xFFFF, fxl_texture_fetch(&t, 0, 1, 0, &tr));
    /* 0x80: r5 = b5 = 16, g6 = 32 -> 0x8410 */
    TEST_ASSERT_EQUAL_HEX16(0x8410, fxl_texture_fetch(&t, 0, 0, 1, &tr));
    /* 0x47 = 71: r5 = b5 = 8, g6 = 17 -> (8 << 11) | (17 << 5) | 8 = 0x4228 */
    TEST_ASSERT_EQUAL_HEX16(0x4228, fxl_texture_fetch(&t, 0, 1, 1, &tr));
    TEST_ASSERT_EQUAL_INT(0, tr);
    t.flags = FXL_TEXF_KEY;
    t.key = 0x47;
    fxl_texture_fetch(&t, 0, 1, 1, &tr);
    TEST_ASSERT_EQUAL_INT(1, tr);
    fxl_texture_fetch(&t, 0, 0, 1, &tr);
    TEST_ASSERT_EQUAL_INT(0, tr);
}

void test_fetch_i8_palette_and_key_on_index(void)
{
    fxl_texture_t t;
    static const uint8_t idx[8] = {0, 1, 2, 3, 255, 254, 1, 0};
    int tr, i;
    for (i = 0; i < 256; i++)
        g_palette[i] = (uint16_t)(i * 257);
    /* two palette entries with the same colour: the key is on the index */
    g_palette[3] = 0x1234;
    g_palette[254] = 0x1234;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, idx, 4, 2, FXL_TEXFMT_I8, 1));
    t.palette = g_palette;
    t.flags = FXL_TEXF_KEY;
    t.key = 3;
    TEST_ASSERT_EQUAL_HEX16(0x0101, fxl_texture_fetch(&t, 0, 1, 0, &tr));
    TEST_ASSERT_EQUAL_INT(0, tr);
    TEST_ASSERT_EQUAL_HEX16(0xFFFF, fxl_texture_fetch(&t, 0, 0, 1, &tr));
    TEST_ASSERT_EQUAL_HEX16(0x1234, fxl_texture_fetch(&t, 0, 3, 0, &tr));
    TEST_ASSERT_EQUAL_INT(1, tr);
    TEST_ASSERT_EQUAL_HEX16(0x1234, fxl_texture_fetch(&t, 0, 1, 1, &tr));
    TEST_ASSERT_EQUAL_INT(0, tr);
}

void test_fetch_rgb565_key(void)
{
    fxl_texture_t t = valid_rgb565();
    int tr = 7;
    fill_addressed();
    t.flags = FXL_TEXF_KEY;
    t.key = 0x0102;
    TEST_ASSERT_EQUAL_HEX16(0x0102, fxl_texture_fetch(&t, 0, 2, 1, &tr));
    TEST_ASSERT_EQUAL_INT(1, tr);
    TEST_ASSERT_EQUAL_HEX16(0x0103, fxl_texture_fetch(&t, 0, 3, 1, &tr));
    TEST_ASSERT_EQUAL_INT(0, tr);
    /* key flag off: the same value is opaque */
    t.flags = 0;
    fxl_texture_fetch(&t, 0, 2, 1, &tr);
    TEST_ASSERT_EQUAL_INT(0, tr);
}

void test_fetch_invalid_descriptor_or_level_reads_nothing(void)
{
    fxl_texture_t t = valid_rgb565();
    int tr = 7;
    fill_addressed();
    TEST_ASSERT_EQUAL_HEX16(0, fxl_texture_fetch(NULL, 0, 0, 0, &tr));
    TEST_ASSERT_EQUAL_INT(0, tr);
    /* level 4 does not exist in a 4-level chain: the texel just past the
     * chain (where a level 4 would start) is a canary it must not read */
    {
        const uint32_t past = fxl_texture_level_offset(&t, 4);
        const uint16_t saved = g_rgb[past];
        g_rgb[past] = 0xBEEFu;
        TEST_ASSERT_EQUAL_HEX16(0, fxl_texture_fetch(&t, 4, 1, 1, &tr));
        g_rgb[past] = saved;
    }
    t.wrap_u = 9;
    TEST_ASSERT_EQUAL_HEX16(0, fxl_texture_fetch(&t, 0, 1, 1, &tr));
}

/* RGB565 texels and I8 palettes are read as uint16_t: at an odd address
 * that is undefined behaviour (a HardFault on a Cortex-M0+), so the
 * descriptor is refused - by init, validate, fetch and every draw - and an
 * 8-bit format may sit anywhere. */
void test_misaligned_texels_or_palette_are_refused(void)
{
    const uint8_t *odd = (const uint8_t *)g_rgb + 1;
    static uint16_t pix[8 * 8];
    fxl_texture_t t = valid_rgb565();
    fxl_target_t tg;
    fxl_draw_t d;
    fxl_vertex_t v[3];
    int tr;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_init(&t, odd, 4, 4, FXL_TEXFMT_RGB565, 1));
    t = valid_rgb565();
    t.texels = odd;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_validate(&t));
    TEST_ASSERT_EQUAL_HEX16(0, fxl_texture_fetch(&t, 0, 1, 1, &tr));
    fxl_draw_defaults(&d);
    d.texture = &t;
    d.depth = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&tg, pix, 8, 8, 8, FXL_PIXFMT_RGB565));
    v[0] = test_vertex(0, 0, 1, 0, 0, 0xFFFF);
    v[1] = test_vertex(8, 0, 1, 1, 0, 0xFFFF);
    v[2] = test_vertex(0, 8, 1, 0, 1, 0xFFFF);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_draw_triangle(&tg, &d, v, NULL));
    /* 8-bit texels need no alignment; an I8 palette does */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, odd, 4, 4, FXL_TEXFMT_L8, 1));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_validate(&t));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&t, odd, 4, 4, FXL_TEXFMT_I8, 1));
    t.palette = (const uint16_t *)(const void *)((const uint8_t *)g_palette + 1);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_texture_validate(&t));
    t.palette = g_palette;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_validate(&t));
}

void test_fetch_every_level_stays_inside_it(void)
{
    /* 8x4 chain (32 + 8 + 2 + 1 texels): each level filled with its own
     * number; any coordinate in any mode must read that number, or in
     * border mode the border colour outside the level. */
    fxl_texture_t t = valid_rgb565();
    uint32_t lv, i;
    int mode;
    int32_t c[NPROBE];
    char msg[96];
    for (lv = 0; lv < 4; lv++)
        for (i = fxl_texture_level_offset(&t, lv); i < fxl_texture_level_offset(&t, lv + 1); i++)
            g_rgb[i] = (uint16_t)(0x10 + lv);
    t.border = 0xBEEF;
    for (mode = 0; mode <= FXL_WRAP_BORDER; mode++) {
        t.wrap_u = t.wrap_v = (uint8_t)mode;
        for (lv = 0; lv < 4; lv++) {
            const int32_t w = 8 >> lv ? 8 >> lv : 1, h = 4 >> lv ? 4 >> lv : 1;
            probes(8, c);
            for (i = 0; i < NPROBE; i++) {
                const int32_t x = c[i], y = c[NPROBE - 1 - i];
                const int inside = x >= 0 && x < w && y >= 0 && y < h;
                uint16_t got = fxl_texture_fetch(&t, lv, x, y, NULL);
                snprintf(msg, sizeof msg, "mode %d level %u coord %ld, %ld", mode, (unsigned)lv, (long)x,
                         (long)y);
                TEST_ASSERT_EQUAL_HEX32_MESSAGE(mode == FXL_WRAP_BORDER && !inside ? 0xBEEFu : 0x10u + lv, got,
                                                msg);
            }
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_init_fills_defaults_and_validates);
    RUN_TEST(test_init_rejects_bad_arguments);
    RUN_TEST(test_validate_error_paths);
    RUN_TEST(test_texfmt_bytes);
    RUN_TEST(test_levels_512x512);
    RUN_TEST(test_levels_128x32_non_square);
    RUN_TEST(test_levels_1x1_and_1x1024);
    RUN_TEST(test_level_offset_partial_chain_and_bad_input);
    RUN_TEST(test_wrap_boundaries_every_mode);
    RUN_TEST(test_wrap_matches_reference_on_a_sweep);
    RUN_TEST(test_fetch_wraps_each_axis_independently);
    RUN_TEST(test_fetch_border_reads_border_colour_never_transparent);
    RUN_TEST(test_fetch_l8_expands_grey);
    RUN_TEST(test_fetch_i8_palette_and_key_on_index);
    RUN_TEST(test_fetch_rgb565_key);
    RUN_TEST(test_fetch_invalid_descriptor_or_level_reads_nothing);
    RUN_TEST(test_fetch_every_level_stays_inside_it);
    RUN_TEST(test_misaligned_texels_or_palette_are_refused);
    return UNITY_END();
}
