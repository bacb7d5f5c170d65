/* test_raster.c - coverage, fill rule, watertightness, clipping, bands,
 * perspective accuracy and API errors of fxl_draw_triangle. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "unity.h"
#include "test_vertex.h"
#include "test_features.h"
#include "left_out.h"
#include "fixel/fixel.h"
#include "reference.h"
#include "../src/raster_int.h"
#include "../src/auto.h"

#define FXL_TEST_PI 3.14159265358979323846

void setUp(void) {}
void tearDown(void) {}

/* ---- helpers ------------------------------------------------------------ */

static uint32_t lcg_state = 12345u;
static uint32_t rnd(void)
{
    lcg_state = lcg_state * 1664525u + 1013904223u;
    return lcg_state >> 8;
}
static int32_t rnd_range(int32_t lo, int32_t hi) /* inclusive */
{
    return lo + (int32_t)(rnd() % (uint32_t)(hi - lo + 1));
}

#define W 64
#define H 48

/* Independent exact coverage: edge functions on the snapped grid, pixel
 * centres at 16 i + 8. With det > 0 (clockwise on a y-down screen) the
 * interior has E > 0 for every edge; a centre with E == 0 counts for a top
 * edge (dy == 0, dx > 0: interior below) or a left edge (dy < 0: interior to
 * the right). */
static int ref_covered(const fxl_vertex_t v[3], int32_t px, int32_t py)
{
    int64_t X[3], Y[3], det;
    int64_t cx = (int64_t)px * FXL__ONE + FXL__HALF, cy = (int64_t)py * FXL__ONE + FXL__HALF;
    int i;
    for (i = 0; i < 3; i++) {
        X[i] = fxl_snap_subpx(v[i].x);
        Y[i] = fxl_snap_subpx(v[i].y);
    }
    det = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
    if (det == 0)
        return 0;
    if (det < 0) {
        int64_t t = X[1]; X[1] = X[2]; X[2] = t;
        t = Y[1]; Y[1] = Y[2]; Y[2] = t;
    }
    for (i = 0; i < 3; i++) {
        int j = (i + 1) % 3;
        int64_t dx = X[j] - X[i], dy = Y[j] - Y[i];
        int64_t e = dx * (cy - Y[i]) - dy * (cx - X[i]);
        if (e < 0)
            return 0;
        if (e == 0 && !((dy == 0 && dx > 0) || dy < 0))
            return 0;
    }
    return 1;
}

/* Probe: counts writes per pixel and records u, v (level-0 q16 texels). */
static uint16_t *probe_base;
static int32_t probe_stride;
static uint8_t probe_count[1024 * 512];
static double probe_u[1024 * 512], probe_v[1024 * 512];
/* records segment s's pixels, u and v scaled from its q16 by su, sv */
static uint32_t probe_record(const fxl__seg_t *s, double su, double sv)
{
    int32_t i;
    for (i = 0; i < s->n; i++) {
        size_t k = (size_t)(s->dst - probe_base) + (size_t)i;
        probe_count[k]++;
        probe_u[k] = (double)fxl__seg_coord(s->u, s->du, s->ddu, i) * su;
        probe_v[k] = (double)fxl__seg_coord(s->v, s->dv, s->ddv, i) * sv;
    }
    return (uint32_t)s->n;
}
static uint32_t probe_seg(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    (void)tri;
    return probe_record(s, 1.0 / 65536.0, 1.0 / 65536.0);
}

static fxl_vertex_t vtx(double x, double y, double inv_w, double u, double v)
{
    return test_vertex(x, y, inv_w, u, v, 0xFFFF);
}

static uint16_t pix[W * H];

/* Untextured white; without FXL_HAVE_GENERIC (no untextured draws) a white
 * RGB565 repeat texture instead: coverage does not depend on the texture. */
static void flat_draw(fxl_draw_t *d)
{
    fxl_draw_defaults(d);
    d->depth = 0;
    d->color = 0xFFFF;
    d->texture = flat_white_texture();
}

/* Draw v on a cleared W x H target and compare with ref_covered. Returns
 * the number of mismatches and reports the first. */
static int coverage_mismatches(const fxl_vertex_t v[3], char *msg, size_t msglen)
{
    fxl_target_t t;
    fxl_draw_t d;
    int32_t x, y;
    int bad = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, pix, W, H, W, drawable_rgb565()));
    fxl_target_clear(&t, 0);
    flat_draw(&d);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, NULL));
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int got = pix[y * W + x] != 0, want = ref_covered(v, x, y);
            if (got != want) {
                if (!bad)
                    snprintf(msg, msglen, "pixel (%d,%d) drawn=%d exact=%d; tri (%d,%d) (%d,%d) (%d,%d) q16",
                             (int)x, (int)y, got, want, (int)v[0].x, (int)v[0].y, (int)v[1].x, (int)v[1].y,
                             (int)v[2].x, (int)v[2].y);
                bad++;
            }
        }
    return bad;
}

/* ---- fill rule ----------------------------------------------------------- */

void test_fill_rule_matches_exact_reference_on_random_triangles(void)
{
    char msg[200] = "";
    int k, total = 0;
    lcg_state = 1u;
    for (k = 0; k < 3000; k++) {
        fxl_vertex_t v[3];
        int i;
        for (i = 0; i < 3; i++) {
            /* Half the triangles on a coarse 1/2-px lattice, so centres fall
             * exactly on edges and vertices; the rest anywhere, off-target too. */
            if (k & 1)
                v[i] = vtx(rnd_range(-8, 2 * W + 8) * 0.5, rnd_range(-8, 2 * H + 8) * 0.5, 0.5, 0, 0);
            else
                v[i] = vtx(rnd_range(-200000, (W + 3) * 65536) / 65536.0,
                           rnd_range(-200000, (H + 3) * 65536) / 65536.0, 0.5, 0, 0);
        }
        total += coverage_mismatches(v, msg, sizeof msg);
        if (total)
            break;
    }
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, total, msg);
}

void test_fill_rule_long_edges_do_not_drift(void)
{
    /* A 16.16 slope accumulated over many rows drifts by up to rows * 2^-16
     * px; this edge puts centres within 1/16 px * k of the line on purpose.
     * Tall skinny triangles over the full height with irrational-ish slopes. */
    char msg[200] = "";
    int k, total = 0;
    lcg_state = 99u;
    for (k = 0; k < 2000 && !total; k++) {
        fxl_vertex_t v[3];
        double x0 = rnd_range(0, W * 16) / 16.0, x1 = rnd_range(0, W * 16) / 16.0;
        v[0] = vtx(x0, -0.5 + rnd_range(0, 15) / 16.0, 0.5, 0, 0);
        v[1] = vtx(x1, H + 0.5, 0.5, 0, 0);
        v[2] = vtx(rnd_range(0, W * 16) / 16.0, rnd_range(0, H * 16) / 16.0, 0.5, 0, 0);
        total += coverage_mismatches(v, msg, sizeof msg);
    }
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, total, msg);
}

/* Centres exactly on each of the eight edge directions. Each case: a
 * triangle and one pixel whose centre lies on the named edge, drawn or not. */
void test_fill_rule_centres_on_edges_all_eight_orientations(void)
{
    struct { double x[3], y[3]; int px, py, drawn; const char *what; } c[] = {
        /* horizontal top edge (y = 2.5), triangle below: drawn */
        {{1, 9, 5}, {2.5, 2.5, 8}, 4, 2, 1, "top edge"},
        /* horizontal bottom edge (y = 6.5), triangle above: not drawn */
        {{5, 9, 1}, {1, 6.5, 6.5}, 4, 6, 0, "bottom edge"},
        /* vertical left edge x = 2.5: drawn */
        {{2.5, 9, 2.5}, {1, 5, 9}, 2, 5, 1, "left vertical"},
        /* vertical right edge x = 7.5: not drawn */
        {{7.5, 7.5, 1}, {1, 9, 5}, 7, 5, 0, "right vertical"},
        /* left edge going down-right: from (1.5,0.5) to (5.5,4.5), centre (3.5,2.5) */
        {{1.5, 5.5, 9.5}, {0.5, 4.5, 0.5}, 3, 2, 1, "left diagonal \\"},
        /* left edge going down-left: (5.5,0.5)-(1.5,4.5), centre (3.5,2.5), interior to the right */
        {{5.5, 1.5, 9.5}, {0.5, 4.5, 4.5}, 3, 2, 1, "left diagonal /"},
        /* right edge going down-right: (1.5,0.5)-(5.5,4.5), interior to the left */
        {{1.5, 5.5, 0.5}, {0.5, 4.5, 4.5}, 3, 2, 0, "right diagonal \\"},
        /* right edge going down-left: (5.5,0.5)-(1.5,4.5), interior to the left */
        {{5.5, 1.5, 0.5}, {0.5, 4.5, 0.5}, 3, 2, 0, "right diagonal /"},
    };
    size_t i;
    for (i = 0; i < sizeof c / sizeof c[0]; i++) {
        fxl_vertex_t v[3];
        char msg[200];
        int k, winding;
        for (winding = 0; winding < 2; winding++) {
            for (k = 0; k < 3; k++) {
                int j = winding ? 2 - k : k;
                v[k] = vtx(c[i].x[j], c[i].y[j], 0.5, 0, 0);
            }
            TEST_ASSERT_EQUAL_INT_MESSAGE(c[i].drawn, ref_covered(v, c[i].px, c[i].py), c[i].what);
            snprintf(msg, sizeof msg, "%s (winding %d)", c[i].what, winding);
            TEST_ASSERT_EQUAL_INT_MESSAGE(0, coverage_mismatches(v, msg, sizeof msg), msg);
            TEST_ASSERT_EQUAL_INT_MESSAGE(c[i].drawn, pix[c[i].py * W + c[i].px] != 0, msg);
        }
    }
}

/* ---- watertightness --------------------------------------------------------- */

static void probe_target(fxl_target_t *t, uint16_t *buf, int32_t w, int32_t h)
{
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(t, buf, w, h, w, drawable_rgb565()));
    probe_base = buf;
    probe_stride = w;
    memset(probe_count, 0, sizeof probe_count);
}

/* Draw a jittered grid mesh (shared vertices) covering [x0,x1]x[y0,y1] and
 * check: no pixel twice, and every pixel the exact rule covers, once. */
static void check_mesh(int nx, int ny, double jitter, uint32_t seed)
{
    static uint16_t buf[W * H];
    static uint8_t ref[W * H];
    fxl_target_t t;
    fxl_draw_t d;
    fxl_vertex_t grid[40][40];
    int i, j, x, y;
    lcg_state = seed;
    for (j = 0; j <= ny; j++)
        for (i = 0; i <= nx; i++) {
            double gx = 2.0 + (W - 4.0) * i / nx, gy = 2.0 + (H - 4.0) * j / ny;
            /* jitter is a fraction of the cell. A triangle of a cell folds
             * over when a corner crosses the diagonal opposite it, 0.71 of
             * a cell away; the corner and the diagonal's two ends each move
             * at most 1.41 j along the diagonal's normal, so j < 0.25
             * never folds (0.3 did, at seed 1812), and j = 0.2 leaves 0.14
             * of a cell (> 0.38 px) for the 1/16-px snap of 3 vertices. */
            if (i > 0 && i < nx)
                gx += jitter * (W - 4.0) / nx * ((rnd() % 2001) / 1000.0 - 1.0);
            if (j > 0 && j < ny)
                gy += jitter * (H - 4.0) / ny * ((rnd() % 2001) / 1000.0 - 1.0);
            grid[j][i] = vtx(gx, gy, 0.5, 0, 0);
        }
    probe_target(&t, buf, W, H);
    memset(ref, 0, sizeof ref);
    flat_draw(&d);
    for (j = 0; j < ny; j++)
        for (i = 0; i < nx; i++) {
            fxl_vertex_t a[3] = {grid[j][i], grid[j][i + 1], grid[j + 1][i]};
            fxl_vertex_t b[3] = {grid[j][i + 1], grid[j + 1][i + 1], grid[j + 1][i]};
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, a, NULL, probe_seg));
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, b, NULL, probe_seg));
            /* the reference over the cell's bounding box (every pixel
             * centre either triangle can cover) */
            int bx0 = W, bx1 = 0, by0 = H, by1 = 0, c;
            const fxl_vertex_t *corner[4] = {&grid[j][i], &grid[j][i + 1], &grid[j + 1][i], &grid[j + 1][i + 1]};
            for (c = 0; c < 4; c++) {
                const int cx = (int)(corner[c]->x >> 16), cy = (int)(corner[c]->y >> 16);
                bx0 = cx - 1 < bx0 ? cx - 1 : bx0;
                bx1 = cx + 2 > bx1 ? cx + 2 : bx1;
                by0 = cy - 1 < by0 ? cy - 1 : by0;
                by1 = cy + 2 > by1 ? cy + 2 : by1;
            }
            for (y = by0 < 0 ? 0 : by0; y < (by1 > H ? H : by1); y++)
                for (x = bx0 < 0 ? 0 : bx0; x < (bx1 > W ? W : bx1); x++)
                    ref[y * W + x] = (uint8_t)(ref[y * W + x] + ref_covered(a, x, y) + ref_covered(b, x, y));
        }
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            char msg[120];
            int inside = x >= 3 && x < W - 3 && y >= 3 && y < H - 3;  /* strictly inside the mesh */
            snprintf(msg, sizeof msg, "pixel (%d,%d) drawn %d times, exact %d (mesh %dx%d seed %u)", x, y,
                     probe_count[y * W + x], ref[y * W + x], nx, ny, (unsigned)seed);
            TEST_ASSERT_EQUAL_INT_MESSAGE(ref[y * W + x], probe_count[y * W + x], msg);
            TEST_ASSERT_TRUE_MESSAGE(probe_count[y * W + x] <= 1, msg);
            if (inside)
                TEST_ASSERT_EQUAL_INT_MESSAGE(1, probe_count[y * W + x], msg);
        }
}

void test_watertight_grid_mesh_each_pixel_once(void)
{
    check_mesh(8, 6, 0.0, 1u);
    check_mesh(30, 22, 0.0, 2u);
}

void test_watertight_random_jittered_meshes_each_pixel_once(void)
{
    /* thousands of random meshes (the core issue's count), each checked
     * pixel by pixel */
    uint32_t s;
    for (s = 0; s < 3000; s++)
        check_mesh(3 + (int)(s % 20), 2 + (int)((s * 7) % 15), 0.2, 1000u + s);
}

void test_watertight_fan_each_pixel_once(void)
{
    static uint16_t buf[W * H];
    fxl_target_t t;
    fxl_draw_t d;
    const int n = 37;
    int i, x, y;
    double cx = 31.3, cy = 23.7, r = 60.0;
    probe_target(&t, buf, W, H);
    flat_draw(&d);
    for (i = 0; i < n; i++) {
        double a0 = 2 * FXL_TEST_PI * i / n, a1 = 2 * FXL_TEST_PI * (i + 1) / n;
        fxl_vertex_t v[3];
        v[0] = vtx(cx, cy, 0.5, 0, 0);
        v[1] = vtx(cx + r * cos(a0), cy + r * sin(a0), 0.5, 0, 0);
        v[2] = vtx(cx + r * cos(a1), cy + r * sin(a1), 0.5, 0, 0);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, v, NULL, probe_seg));
    }
    /* The fan's radius exceeds the target: every pixel exactly once. */
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            if (probe_count[y * W + x] != 1) {
                char msg[80];
                snprintf(msg, sizeof msg, "pixel (%d,%d) drawn %d times", x, y, probe_count[y * W + x]);
                TEST_FAIL_MESSAGE(msg);
            }
}

/* ---- clipping, bands, canaries ---------------------------------------------- */

static const uint16_t texels64[64 * 64] = {0};
static uint16_t tex_data[64 * 64];

static void make_texture(fxl_texture_t *tex)
{
    int i;
    for (i = 0; i < 64 * 64; i++)
        tex_data[i] = (uint16_t)(i * 2654435761u >> 16);
    (void)texels64;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(tex, tex_data, 64, 64, FXL_TEXFMT_RGB565, 1));
}

static void random_tri(fxl_vertex_t v[3], double spread)
{
    int i;
    for (i = 0; i < 3; i++)
        v[i] = vtx((rnd() % 20001) / 10000.0 * spread - spread / 2 + W / 2,
                   (rnd() % 20001) / 10000.0 * spread - spread / 2 + H / 2, 0.02 + (rnd() % 1000) / 1000.0,
                   ((int)(rnd() % 2001) - 1000) / 100.0, ((int)(rnd() % 2001) - 1000) / 100.0);
}

void test_no_write_outside_clip_rectangle_canaries(void)
{
    /* The target is the middle of a bigger buffer; everything around it
     * and outside the clip rectangle is canary. */
    enum { BW = W + 16, BH = H + 16 };
    static uint16_t big[BW * BH], zb[BW * BH];
    fxl_target_t t;
    fxl_draw_t d;
    fxl_texture_t tex;
    fxl_rect_t clip = {5, 3, W - 7, H - 4};
    int k, x, y, f;
    make_texture(&tex);
    lcg_state = 7u;
    for (f = 0; f < 2; f++) {
        for (k = 0; k < BW * BH; k++)
            big[k] = zb[k] = 0xA5A5;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, big + 8 * BW + 8, W, H, BW, (fxl_pixfmt_t)f));
        /* without FXL_HAVE_DEPTH no buffer is attached (zb stays canary) */
        TEST_ASSERT_EQUAL_INT(FXL_HAVE_DEPTH ? FXL_OK : FXL_ERR_UNSUPPORTED, fxl_target_set_depth(&t, zb + 8 * BW + 8));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_clip(&t, &clip));
        fxl_target_clear_depth(&t);
        fxl_draw_defaults(&d);
        d.texture = &tex;
        for (k = 0; k < 3000; k++) {
            fxl_vertex_t v[3];
            random_tri(v, (k % 3 == 0) ? 60000.0 : 120.0);   /* some near the q16 limit */
            d.filter = (uint8_t)(FXL_HAVE_BILINEAR ? k & 1 : FXL_FILTER_POINT);   /* the filters this build has */
            d.persp = (int16_t)((k % 4 == 0) ? 0 : (k % 4 == 1 ? 1 : 16));
            /* refused draws (left_out.h) must leave every canary too */
            TEST_ASSERT_EQUAL_INT(left_out_feature(&d, &tex, t.format, t.depth != NULL) ? FXL_ERR_UNSUPPORTED : FXL_OK,
                                  fxl_draw_triangle(&t, &d, v, NULL));
        }
        for (y = 0; y < BH; y++)
            for (x = 0; x < BW; x++) {
                int fx = x - 8, fy = y - 8;
                int in = fx >= clip.x0 && fx < clip.x1 && fy >= clip.y0 && fy < clip.y1;
                if (!in && (big[y * BW + x] != 0xA5A5 || zb[y * BW + x] != 0xA5A5)) {
                    char msg[100];
                    snprintf(msg, sizeof msg, "write outside clip at buffer (%d,%d): %04x", x, y, big[y * BW + x]);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
    }
}

/* Render random textured triangles full-frame and as bands of 7 rows and
 * with an x-clip; every drawn pixel must be bit-identical. */
/* Render n triangles into a w x h target at (x0, y0) of the frame (its own
 * buffer and depth) and compare every pixel with the full frame's. */
static void render_part_matches(const fxl_draw_t *d, fxl_vertex_t (*tris)[3], int n, uint16_t *buf, uint16_t *zbuf,
                                int x0, int y0, int w, int h, const uint16_t *full, int mode)
{
    fxl_target_t t;
    int k, x, y;
    fxl_target_init(&t, buf, w, h, w, drawable_rgb565());
    fxl_target_set_origin(&t, x0, y0);
    fxl_target_set_depth(&t, zbuf);
    fxl_target_clear(&t, 0x1234);
    fxl_target_clear_depth(&t);
    for (k = 0; k < n; k++)
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, d, tris[k], NULL));
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            if (buf[y * w + x] != full[(y0 + y) * W + x0 + x]) {
                char msg[100];
                snprintf(msg, sizeof msg, "part at (%d,%d): pixel (%d,%d) %04x != full %04x (mode %d)", x0, y0,
                         x0 + x, y0 + y, buf[y * w + x], full[(y0 + y) * W + x0 + x], mode);
                TEST_FAIL_MESSAGE(msg);
            }
}

void test_band_and_clip_renders_are_bit_identical_to_full_frame(void)
{
    static uint16_t full[W * H], zfull[W * H], band[W * 7], zband[W * 7], clipped[W * H], zclip[W * H];
    static uint16_t strip[11 * H], zstrip[11 * H];
    fxl_vertex_t tris[60][3];
    fxl_texture_t tex;
    fxl_target_t t;
    fxl_draw_t d;
    int k, y0, x0, x, y, mode, checked = 0;
    char summary[80];
    make_texture(&tex);
    lcg_state = 31u;
    for (k = 0; k < 60; k++)
        random_tri(tris[k], 90.0);
    for (mode = 0; mode < 7; mode++) {
        fxl_rect_t cr = {13, 0, 41, H};
        fxl_draw_defaults(&d);
        d.texture = &tex;
        d.filter = (uint8_t)(mode & 1);
        if (mode == 6) {
            /* Gouraud modulation: the generic walk (its own origin arithmetic) */
            d.filter = FXL_FILTER_POINT;
            d.shade = FXL_SHADE_GOURAUD;
            d.texenv = FXL_TEXENV_MODULATE;
        }
        /* subdivided, affine, adaptive (segments cut by the error bound:
         * the walk starts at the block containing the clip edge) */
        d.persp = (int16_t)(mode < 2 ? 16 : (mode < 4 ? 0 : FXL_PERSP_AUTO));
        d.auto_budget = 65536 / 16;
        /* depth is incidental (without FXL_HAVE_DEPTH the set_depth calls
         * below fail and every render is drawn without); a mode this build
         * left out is refused, not compared empty */
        if ((d.filter == FXL_FILTER_BILINEAR && !FXL_HAVE_BILINEAR) || (d.persp == FXL_PERSP_AUTO && !FXL_HAVE_AUTO) ||
            (mode == 6 && !FXL_HAVE_GENERIC)) {
            fxl_target_init(&t, full, W, H, W, drawable_rgb565());
            TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_draw_triangle(&t, &d, tris[0], NULL));
            continue;
        }
        checked++;
        fxl_target_init(&t, full, W, H, W, drawable_rgb565());
        fxl_target_set_depth(&t, zfull);
        fxl_target_clear(&t, 0x1234);
        fxl_target_clear_depth(&t);
        for (k = 0; k < 60; k++)
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, tris[k], NULL));
        fxl_target_init(&t, clipped, W, H, W, drawable_rgb565());
        fxl_target_set_depth(&t, zclip);
        fxl_target_clear(&t, 0x1234);
        fxl_target_clear_depth(&t);
        fxl_target_set_clip(&t, &cr);
        for (k = 0; k < 60; k++)
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, tris[k], NULL));
        for (y = 0; y < H; y++)
            for (x = cr.x0; x < cr.x1; x++)
                TEST_ASSERT_EQUAL_HEX16(full[y * W + x], clipped[y * W + x]);
        /* horizontal bands, then column strips (origin_x != 0) */
        for (y0 = 0; y0 < H; y0 += 7)
            render_part_matches(&d, tris, 60, band, zband, 0, y0, W, H - y0 < 7 ? H - y0 : 7, full, mode);
        for (x0 = 0; x0 < W; x0 += 11)
            render_part_matches(&d, tris, 60, strip, zstrip, x0, 0, W - x0 < 11 ? W - x0 : 11, H, full, mode);
    }
    snprintf(summary, sizeof summary, "%d of 7 modes checked, %d need features this build lacks", checked,
             7 - checked);
    TEST_MESSAGE(summary);
}

/* ---- perspective accuracy ------------------------------------------------ */

/* Exact u, v (level-0 texels) at a pixel centre from the snapped vertices. */
static void exact_uv(const fxl_vertex_t v[3], int tw, int th, int affine, int32_t px, int32_t py, double *u,
                     double *vv)
{
    double X[3], Y[3], det, b[3], q[3], sq = 0, su = 0, sv = 0;
    double cx = px + 0.5, cy = py + 0.5;
    int i;
    for (i = 0; i < 3; i++) {
        X[i] = fxl_snap_subpx(v[i].x) / (double)FXL__ONE;
        Y[i] = fxl_snap_subpx(v[i].y) / (double)FXL__ONE;
        q[i] = affine ? 1.0 : (double)v[i].inv_w;
    }
    det = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
    b[1] = ((cx - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (cy - Y[0])) / det;
    b[2] = ((X[1] - X[0]) * (cy - Y[0]) - (cx - X[0]) * (Y[1] - Y[0])) / det;
    b[0] = 1 - b[1] - b[2];
    for (i = 0; i < 3; i++) {
        sq += b[i] * q[i];
        su += b[i] * q[i] * v[i].u / 65536.0;
        sv += b[i] * q[i] * v[i].v / 65536.0;
    }
    *u = su / sq * tw;
    *vv = sv / sq * th;
}

static double wrap_err(double got, double want, double period)
{
    double e = fmod(got - want, period);
    if (e < 0)
        e += period;
    return e > period / 2 ? period - e : e;
}

/* |(u, v) - exact| in level-0 texels at pixel (x, y), as the probe recorded
 * it for a target `stride` pixels wide, of a tw x tw texture. */
static double probe_error_at(const fxl_vertex_t v[3], int tw, int affine, int stride, int x, int y)
{
    double eu, ev;
    exact_uv(v, tw, tw, affine, x, y, &eu, &ev);
    return hypot(wrap_err(probe_u[y * stride + x], eu, tw), wrap_err(probe_v[y * stride + x], ev, tw));
}

/* A draw in mode persp (default budget, no depth) of a side x side RGB565
 * texture with one level, over the caller's texels. */
static void one_level_draw(fxl_draw_t *d, fxl_texture_t *tex, uint16_t *texels, uint32_t side, int16_t persp)
{
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(tex, texels, side, side, FXL_TEXFMT_RGB565, 1));
    fxl_draw_defaults(d);
    d->texture = tex;
    d->depth = 0;
    d->persp = persp;
}

/* The same for FXL_PERSP_AUTO and a 64 x 64 texture. */
static void auto_draw_64(fxl_draw_t *d, fxl_texture_t *tex, uint16_t *texels)
{
    one_level_draw(d, tex, texels, 64, FXL_PERSP_AUTO);
}

/* The largest Euclidean (u, v) error, in texels of a 64 x 64 texture, over
 * the pixels probe_seg recorded for triangle v (320 x 240 target). */
static double probed_max_error(const fxl_vertex_t v[3])
{
    double e_max = 0;
    int x, y;
    for (y = 0; y < 240; y++)
        for (x = 0; x < 320; x++)
            if (probe_count[y * 320 + x]) {
                const double e = probe_error_at(v, 64, 0, 320, x, y);
                e_max = e > e_max ? e : e_max;
            }
    return e_max;
}

/* View-space point -> vertex, 60 degree vertical fov, 320x240, near 1. */

typedef struct { fxl_vertex_t v[3]; } tri_t;

static int floor_scene(tri_t *out)
{
    /* The core issue's floor: x = +-40, y = -0.577, z -1 .. -50; u = x / 2,
     * v = z / 2 periods of the texture. */
    fxl_vertex_t a = test_project(-40, -0.577, -1, -20, -0.5), b = test_project(40, -0.577, -1, 20, -0.5);
    fxl_vertex_t c = test_project(40, -0.577, -50, 20, -25), d = test_project(-40, -0.577, -50, -20, -25);
    out[0].v[0] = a; out[0].v[1] = b; out[0].v[2] = c;
    out[1].v[0] = a; out[1].v[1] = c; out[1].v[2] = d;
    return 2;
}

static int cube_scene(tri_t *out)
{
    static const int faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    double P[8][3], ca = cos(FXL_TEST_PI / 6), sa = sin(FXL_TEST_PI / 6);
    int i, f, n = 0;
    for (i = 0; i < 8; i++) {
        double x = (i & 1) ? 1 : -1, y = (i & 2) ? 1 : -1, z = (i & 4) ? 1 : -1, t;
        t = y * ca - z * sa; z = y * sa + z * ca; y = t;     /* about x */
        t = x * ca + z * sa; z = -x * sa + z * ca; x = t;    /* about y */
        P[i][0] = x; P[i][1] = y; P[i][2] = z - 4.5;
    }
    for (f = 0; f < 6; f++) {
        fxl_vertex_t q[4];
        static const double uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (i = 0; i < 4; i++)
            q[i] = test_project(P[faces[f][i]][0], P[faces[f][i]][1], P[faces[f][i]][2], uv[i][0], uv[i][1]);
        out[n].v[0] = q[0]; out[n].v[1] = q[1]; out[n].v[2] = q[2]; n++;
        out[n].v[0] = q[0]; out[n].v[1] = q[2]; out[n].v[2] = q[3]; n++;
    }
    return n;
}

static int rolled_floor_scene(tri_t *out, double roll_deg)
{
    double P[4][3] = {{-40, -0.577, -1}, {40, -0.577, -1}, {40, -0.577, -50}, {-40, -0.577, -50}};
    static const double uv[4][2] = {{-20, -0.5}, {20, -0.5}, {20, -25}, {-20, -25}};
    double c = cos(roll_deg * FXL_TEST_PI / 180), sn = sin(roll_deg * FXL_TEST_PI / 180);
    fxl_vertex_t q[4];
    int i;
    for (i = 0; i < 4; i++) {
        double x = P[i][0] * c - P[i][1] * sn, y = P[i][0] * sn + P[i][1] * c;
        q[i] = test_project(x, y, P[i][2], uv[i][0], uv[i][1]);
    }
    out[0].v[0] = q[0]; out[0].v[1] = q[1]; out[0].v[2] = q[2];
    out[1].v[0] = q[0]; out[1].v[1] = q[2]; out[1].v[2] = q[3];
    return 2;
}

/* Max |(u,v) - exact| in level-0 texels over every pixel that d, with its
 * tw x tw texture, draws of the triangles, seen through probe (probe_seg
 * or a probe that records more and calls it). */
static double draw_max_error(const tri_t *tris, int n, const fxl_draw_t *d, int tw, int affine_ref, fxl__seg_fn probe)
{
    static uint16_t buf[320 * 240];
    fxl_target_t t;
    double maxe = 0;
    int k, x, y;
    for (k = 0; k < n; k++) {
        probe_target(&t, buf, 320, 240);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, d, tris[k].v, NULL, probe));
        for (y = 0; y < 240; y++)
            for (x = 0; x < 320; x++)
                if (probe_count[y * 320 + x]) {
                    const double e = probe_error_at(tris[k].v, tw, affine_ref, 320, x, y);
                    if (e > maxe)
                        maxe = e;
                }
    }
    return maxe;
}

/* The same for the persp mode on a one-level tw x tw texture. */
static double scene_max_error_ref(const tri_t *tris, int n, int persp, int tw, int affine_ref)
{
    fxl_draw_t d;
    fxl_texture_t tex;
    static uint16_t texels[1024 * 1024];
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, (uint32_t)tw, (uint32_t)tw, FXL_TEXFMT_RGB565, 1));
    fxl_draw_defaults(&d);
    d.texture = &tex;
    d.depth = 0;
    d.persp = (int16_t)persp;
    return draw_max_error(tris, n, &d, tw, affine_ref, probe_seg);
}

/* Against the perspective-correct reference. */
static double scene_max_error(const tri_t *tris, int n, int persp, int tw)
{
    return scene_max_error_ref(tris, n, persp, tw, 0);
}

void test_exact_mode_within_one_64th_texel_on_floor_and_cube(void)
{
    tri_t tris[12];
    int n, tw;
    char msg[120];
    for (tw = 64; tw <= 1024; tw *= 16) {
        double e;
        if (!FXL_HAVE_GENERIC && tw * tw > 65536) {
            /* level 0 above 2^16 texels has no specialised walk (config.h) */
            snprintf(msg, sizeof msg, "%d-texel texture not checked: needs FXL_HAVE_GENERIC", tw);
            TEST_MESSAGE(msg);
            continue;
        }
        n = floor_scene(tris);
        e = scene_max_error(tris, n, FXL_PERSP_EXACT, tw);
        snprintf(msg, sizeof msg, "floor, %d-texel texture: max error %.6f texels", tw, e);
        TEST_MESSAGE(msg);
        TEST_ASSERT_TRUE_MESSAGE(e <= 1.0 / 64, msg);
        n = cube_scene(tris);
        e = scene_max_error(tris, n, FXL_PERSP_EXACT, tw);
        snprintf(msg, sizeof msg, "cube, %d-texel texture: max error %.6f texels", tw, e);
        TEST_MESSAGE(msg);
        TEST_ASSERT_TRUE_MESSAGE(e <= 1.0 / 64, msg);
    }
}

/* The stability issue's precision target: exact mode within 1/64 texel up to
 * a depth ratio (far w / near w) of 10^3 across one triangle, and within
 * 1/8 up to 10^4. A quad over the target with 1/w varying along its diagonal
 * (spans of varying depth), 4 periods of a 64-texel texture, at two inv_w
 * scales: nearest vertex at 2^32 - 1, and the whole quad 1000 times farther
 * (every inv_w below 2^22.1: what per-triangle scaling is for). Measured
 * here: at most 1.1e-4 texels at scale 1 and 3.9e-4 at scale 1/1000 (ratio
 * 10^4), so the test holds every case to 1/1024, stricter than the issue's
 * bounds: without the normalisation of 1/w, ratio 10^3 at scale 1/1000
 * errs 1.3e-2, inside the issue's 1/64 but caught here. */
void test_exact_mode_precision_holds_across_depth_ratios(void)
{
    static const double ratios[] = {1, 10, 100, 1000, 3000, 10000};
    static const double scales[] = {1.0, 1.0 / 1000};
    tri_t tris[2];
    char msg[160];
    size_t i, s;
    for (s = 0; s < sizeof scales / sizeof scales[0]; s++)
        for (i = 0; i < sizeof ratios / sizeof ratios[0]; i++) {
            const double R = ratios[i], k = scales[s], qf = k / R, qm = (qf + k) / 2;
            const fxl_vertex_t a = vtx(0.25, 0.5, qf, 0, 0), b = vtx(319.75, 0.5, qm, 4, 0);
            const fxl_vertex_t c = vtx(319.75, 239.5, k, 4, 4), d = vtx(0.25, 239.5, qm, 0, 4);
            double e;
            tris[0].v[0] = a; tris[0].v[1] = b; tris[0].v[2] = c;
            tris[1].v[0] = a; tris[1].v[1] = c; tris[1].v[2] = d;
            e = scene_max_error(tris, 2, FXL_PERSP_EXACT, 64);
            snprintf(msg, sizeof msg, "depth ratio %g, inv_w scale %g: max error %.2e texels", R, k, e);
            TEST_MESSAGE(msg);
            TEST_ASSERT_TRUE_MESSAGE(e <= 1.0 / 1024, msg);
        }
}

/* Exact mode's precision is that of its planes: setup keeps s = u q (u
 * rebased by whole periods, q = 1/w) as integers below 2^30 by a shift k
 * with 2^k <= 2^-29 max_i |s_i| (setup.c fit_shift), each vertex floored
 * (< 1 unit of 2^k), a correction point's mantissa floored to half a unit
 * (persp.h), the 20-bit gradients' rounding ~0.01 unit across the target:
 * < 1.51 units, i.e. 3.02 * 2^-30 max_i |s_i|. Divided by q >= q_min, plus
 * the reciprocal's 2^-28 of |u| and the q16 rounding, per axis:
 *   |du| <= 3.2 * 2^-30 max_i |u_i| q_i / q_min + 2^-27 max |u_i| + 2^-17
 *           + (range of u_i) / min_i q_i   (only when some inv_w >= 2^31)
 * texels; the last term is setup's q = inv_w >> 1 there (a floor: each
 * vertex's weight off by < 1 / q_i relative, which moves u by at most the
 * range times that). In all about 3.2 * 2^-30 U R for U texels of rebased
 * range and a depth ratio R: why exact mode reaches 1/64 between U R = 2^24
 * and 2^26 (the stability sweep range_r*). Checked on floor-like quads (rows of one depth) and
 * quads whose depth changes along the diagonal, U from 64 texels to 2^18,
 * R from 1 to 10^4; and the bound must be reached within a factor 10
 * somewhere, or it would say little. */
/* Axis `axis` (0: u, 1: v) of tr rebased by whole periods (repeat), in
 * texels of a tw-texel side: the largest |u_i| into *umax, the largest
 * |u_i| inv_w_i into *m; returns the axis's range max - min. */
static double rebased_axis(const tri_t *tr, int axis, int tw, double *umax, double *m)
{
    double mn = 1e300, mx = -1e300, base;
    int i;
    for (i = 0; i < 3; i++) {
        const double c = (axis ? tr->v[i].v : tr->v[i].u) / 65536.0;
        if (c < mn)
            mn = c;
        if (c > mx)
            mx = c;
    }
    base = floor(mn);   /* repeat: whole periods */
    *umax = *m = 0;
    for (i = 0; i < 3; i++) {
        const double a = fabs((axis ? tr->v[i].v : tr->v[i].u) / 65536.0 - base) * tw;
        if (a * tr->v[i].inv_w > *m)
            *m = a * tr->v[i].inv_w;
        if (a > *umax)
            *umax = a;
    }
    return (mx - mn) * tw;
}

static double exact_plane_bound(const tri_t *tr, int tw)
{
    double b[2], qmin = 1e300, qtrunc = 0;
    int axis, i;
    for (i = 0; i < 3; i++) {
        if (tr->v[i].inv_w < qmin)
            qmin = tr->v[i].inv_w;
        if (tr->v[i].inv_w >= 0x80000000u)
            qtrunc = 1;
    }
    if (qtrunc)
        qtrunc = 1.0 / floor(qmin / 2);   /* the smallest q_i = inv_w >> 1 */
    for (axis = 0; axis < 2; axis++) {
        double umax, m;
        const double range = rebased_axis(tr, axis, tw, &umax, &m);
        b[axis] = 3.2 * ldexp(m / qmin, -30) + ldexp(umax, -27) + ldexp(1, -17) + range * qtrunc;
    }
    return hypot(b[0], b[1]);
}

void test_exact_mode_error_within_its_plane_precision_bound(void)
{
    static const double periods[] = {1, 64, 1000, 4096};
    static const double ratios[] = {1, 10, 100, 1000, 10000};
    tri_t tris[2];
    char msg[200];
    double worst_share = 0;
    size_t p, r;
    int geo, k;
    for (geo = 0; geo < 2; geo++)
        for (p = 0; p < sizeof periods / sizeof periods[0]; p++)
            for (r = 0; r < sizeof ratios / sizeof ratios[0]; r++) {
                const double P = periods[p], qf = 1.0 / ratios[r], qm = (1.0 + qf) / 2;
                fxl_vertex_t c[4];
                if (!FXL_HAVE_GENERIC && P >= 256)
                    continue;   /* uv_wide (256 periods of 64 texels): the generic walk's */
                if (geo == 0) {   /* near edge at the bottom, rows of one depth */
                    c[0] = vtx(28, 228, 1.0, 0, 0);
                    c[1] = vtx(228, 228, 1.0, P, 0);
                    c[2] = vtx(228, 28, qf, P, P);
                    c[3] = vtx(28, 28, qf, 0, P);
                } else {          /* depth along the diagonal */
                    c[0] = vtx(28, 28, qf, 0, 0);
                    c[1] = vtx(228, 28, qm, P, 0);
                    c[2] = vtx(228, 228, 1.0, P, P);
                    c[3] = vtx(28, 228, qm, 0, P);
                }
                tris[0].v[0] = c[0]; tris[0].v[1] = c[1]; tris[0].v[2] = c[2];
                tris[1].v[0] = c[0]; tris[1].v[1] = c[2]; tris[1].v[2] = c[3];
                for (k = 0; k < 2; k++) {
                    const double e = scene_max_error(&tris[k], 1, FXL_PERSP_EXACT, 64);
                    const double bound = exact_plane_bound(&tris[k], 64);
                    snprintf(msg, sizeof msg,
                             "%s quad, %g periods of 64 texels, depth ratio %g, triangle %d: error %.3g > bound %.3g",
                             geo ? "diagonal" : "floor", P, ratios[r], k, e, bound);
                    TEST_ASSERT_TRUE_MESSAGE(e <= bound, msg);
                    if (e / bound > worst_share)
                        worst_share = e / bound;
                }
            }
    snprintf(msg, sizeof msg, "largest error / bound: %.3f", worst_share);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE_MESSAGE(worst_share >= 0.1, msg);
}

/* raster.h's term for the planes' rounded gradients, which drift with the
 * distance D from the vertex set-up starts them at (the one with the
 * smallest inv_w): 2^(S - 51) D (max_i |u_i| q_max + 2 max_i |u_i| q_i) / q
 * texels an axis, with D the largest over the target's corners (the pixels
 * lie between them) and q at its smallest. */
static double exact_drift_bound(const tri_t *tr, int tw, int w, int h)
{
    double b[2], qmin = 1e300, qmax = 0, D = 0;
    int axis, i, ref = 0, c;
    for (i = 0; i < 3; i++) {
        const double q = tr->v[i].inv_w;
        if (q < qmin) {
            qmin = q;
            ref = i;
        }
        if (q > qmax)
            qmax = q;
    }
    for (c = 0; c < 4; c++) {
        const double dx = fabs((c & 1 ? w : 0) - tr->v[ref].x / 65536.0), dy = fabs((c & 2 ? h : 0) - tr->v[ref].y / 65536.0);
        if (dx + dy > D)
            D = dx + dy;
    }
    for (axis = 0; axis < 2; axis++) {
        double umax, m;
        (void)rebased_axis(tr, axis, tw, &umax, &m);
        b[axis] = ldexp(D * (umax * qmax + 2 * m) / qmin, FXL_SUBPIXEL_BITS - 51);
    }
    return hypot(b[0], b[1]);
}

/* The six orders of a triangle's vertices: even (rotations), then odd. */
static const int vertex_order[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};

/* Exact mode on triangles with vertices far off the target (a floor's near
 * corners after clipping, 30,000 px away; a far edge 60,000 px long), a
 * depth ratio of 10^4 and 10^4 periods: within raster.h's bound in every
 * vertex order, and the same pixels in every order, as set-up starts its
 * planes from the farthest vertex whatever the order. Started from vertex
 * 0, the near-corner triangle's horizon erred by 0.45 texel, 71 times the
 * bound without its distance term. */
void test_exact_mode_far_off_target_vertices_within_bound_in_any_order(void)
{
    static uint16_t first[320 * 240], texels[64 * 64];
    const double qn = 0.49, qf = 0.49e-4, P = 10000;
    tri_t base[2];
    char msg[200];
    int b, k, i;
    for (i = 0; i < 64 * 64; i++)
        texels[i] = (uint16_t)(i * 2654435761u >> 16);
    base[0].v[0] = vtx(-30000, 30000, qn, 0, 0);   /* near corners below the target */
    base[0].v[1] = vtx(30000, 30000, qn, 0, 0);
    base[0].v[2] = vtx(160, 100, qf, 0, P);         /* the far vertex on it */
    base[1].v[0] = vtx(-30000, 100, qf, 0, P);      /* a far edge across it */
    base[1].v[1] = vtx(30000, 100, qf, P, P);
    base[1].v[2] = vtx(160, 30000, qn, 0, 0);
    for (b = 0; b < 2; b++)
        for (k = 0; k < 6; k++) {
            tri_t t;
            fxl_draw_t d;
            fxl_texture_t tex;
            fxl_target_t tg;
            static uint16_t buf[320 * 240];
            double e, bound;
            for (i = 0; i < 3; i++)
                t.v[i] = base[b].v[vertex_order[k][i]];
            e = scene_max_error(&t, 1, FXL_PERSP_EXACT, 64);
            bound = exact_plane_bound(&t, 64) + exact_drift_bound(&t, 64, 320, 240);
            snprintf(msg, sizeof msg, "triangle %d, order %d%d%d: error %.3g texel > bound %.3g", b, vertex_order[k][0],
                     vertex_order[k][1], vertex_order[k][2], e, bound);
            TEST_ASSERT_TRUE_MESSAGE(e <= bound, msg);
            if (k == 0) {
                snprintf(msg, sizeof msg, "triangle %d: error %.3g texel, bound %.3g", b, e, bound);
                TEST_MESSAGE(msg);
            }
            one_level_draw(&d, &tex, texels, 64, FXL_PERSP_EXACT);
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&tg, buf, 320, 240, 320, drawable_rgb565()));
            memset(buf, 0, sizeof buf);
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&tg, &d, t.v, NULL));
            if (k == 0)
                memcpy(first, buf, sizeof buf);
            snprintf(msg, sizeof msg, "triangle %d: order %d%d%d draws other pixels than 012", b, vertex_order[k][0],
                     vertex_order[k][1], vertex_order[k][2]);
            TEST_ASSERT_TRUE_MESSAGE(memcmp(first, buf, sizeof buf) == 0, msg);
        }
}

/* Every kind of draw gives the same pixels and depth values whichever of
 * its six orders a triangle's vertices come in: set-up starts from a
 * canonical vertex (raster.c, first_vertex), and the rest of the draw does
 * not depend on the order. Random triangles, some with equal inv_w. */
void test_vertex_order_does_not_change_the_pixels(void)
{
    static const int16_t modes[] = {FXL_PERSP_AFFINE, FXL_PERSP_EXACT, 8, 16, FXL_PERSP_AUTO};
    static uint16_t texels[64 * 64 * 2], first[W * H], zfirst[W * H], buf[W * H], zb[W * H];
    fxl_texture_t tex;
    fxl_draw_t d;
    fxl_target_t t;
    char msg[160];
    int n, k, i, drawn = 0;
    for (i = 0; i < 64 * 64 * 2; i++)
        texels[i] = (uint16_t)(i * 2654435761u >> 16);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 64, 64, FXL_TEXFMT_RGB565, FXL_HAVE_MIPMAP ? 7 : 1));
    lcg_state = 0x0D0E5u;
    for (n = 0; n < 600; n++) {
        fxl_vertex_t v[3], pv[3];
        if (n % 2) {
            random_tri(v, 90);
        } else {
            /* far off the target (up to 20,000 px), depth ratios to 10^4,
             * up to 1,000 periods: where the planes' drift shows */
            for (i = 0; i < 3; i++)
                v[i] = vtx(W / 2 + ((int)(rnd() % 40001) - 20000) * (i ? 1.0 : 0.001),
                           H / 2 + ((int)(rnd() % 40001) - 20000) * (i ? 1.0 : 0.001),
                           0.49 * pow(10.0, -4.0 * (rnd() % 1001) / 1000.0),
                           ((int)(rnd() % 2001) - 1000), ((int)(rnd() % 2001) - 1000));
        }
        if (n % 4 == 0)
            v[1].inv_w = v[0].inv_w;   /* a tie for the first vertex */
        for (i = 0; i < 3; i++)
            v[i].color = (uint16_t)rnd();
        fxl_draw_defaults(&d);
        d.texture = &tex;
        d.persp = modes[n % 5];
        d.filter = (n / 5) % 2 ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
        d.mip = (uint8_t)((n / 10) % 3 == 2 ? FXL_MIP_LINEAR : (n / 10) % 3 == 1 ? FXL_MIP_NEAREST : FXL_MIP_NONE);
        d.lod = (n / 30) % 2 ? FXL_LOD_TRIANGLE : FXL_LOD_SEGMENT;
        d.shade = (n / 60) % 2 ? FXL_SHADE_GOURAUD : FXL_SHADE_FLAT;
        d.texenv = d.shade == FXL_SHADE_GOURAUD ? FXL_TEXENV_MODULATE : d.texenv;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, buf, W, H, W, drawable_rgb565()));
        if (FXL_HAVE_DEPTH)
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zb));
        else
            d.depth = 0;
        if (fxl_draw_check(&t, &d) != FXL_OK)
            continue;   /* a kind of draw this build left out */
        drawn++;
        for (k = 0; k < 6; k++) {
            for (i = 0; i < 3; i++)
                pv[i] = v[vertex_order[k][i]];
            memset(buf, 0, sizeof buf);
            memset(zb, 0, sizeof zb);
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, pv, NULL));
            if (k == 0) {
                memcpy(first, buf, sizeof buf);
                memcpy(zfirst, zb, sizeof zb);
                continue;
            }
            snprintf(msg, sizeof msg, "triangle %d (persp %d, filter %d, mip %d, lod %d, shade %d): order %d%d%d differs",
                     n, d.persp, d.filter, d.mip, d.lod, d.shade, vertex_order[k][0], vertex_order[k][1], vertex_order[k][2]);
            TEST_ASSERT_TRUE_MESSAGE(memcmp(first, buf, sizeof buf) == 0 && memcmp(zfirst, zb, sizeof zb) == 0, msg);
        }
    }
    TEST_ASSERT_TRUE(drawn >= 100);
}

/* Subdivision error bound. Along a span u(x) = s(x) / q(x) with s, q linear,
 * u'' = -2 u' q' / q, so linear interpolation over L pixels errs by at most
 * L^2/8 max|u''| = L^2 max|u' q'| / (4 q). u' = (s' q - s q') / q^2 where
 * the numerator is linear over the triangle, so bounding |numerator| by its
 * vertex maximum and q by its vertex minimum gives a per-triangle bound
 * (ref_chord_bound, which the fuzz's check 7 uses too); plus the exact-mode
 * tolerance and one q16 step per pixel of truncation. */
static double subdiv_bound(const tri_t *tr, int L, int tw)
{
    uint32_t lg = 0;
    while ((1 << lg) < tw)
        lg++;
    return ref_chord_bound(tr->v, lg, lg, L) + 1.0 / 64;   /* (ref_chord_bound's derivation) */
}

void test_subdivided_modes_within_derived_bound_and_affine_is_worse(void)
{
    /* The floor's spans are each at one depth (q' = 0: the bound is the
     * exact-mode tolerance plus truncation); the cube's and those of a quad
     * over the target whose depth doubles along its diagonal cross depth, so
     * there the L^2 term is what is tested.
     * Its tightness is checked too: on the triangle where the bound's L^2
     * term is largest at L = 16 the error must reach a quarter of it (a
     * bound that grew loose would hide a subdivision that went wrong; at
     * L = 64 the cube's spans are shorter than a segment). */
    tri_t tris[12];
    int n, k, L, sc;
    char msg[160];
    double exact_e, affine_e;
    for (sc = 0; sc < 3; sc++) {
        static const char *const names[3] = {"floor", "cube", "slanted quad"};
        if (sc == 2) {
            const fxl_vertex_t a = vtx(0.25, 0.5, 0.5, 0, 0), b = vtx(319.75, 0.5, 0.75, 4, 0);
            const fxl_vertex_t c = vtx(319.75, 239.5, 1, 4, 4), d = vtx(0.25, 239.5, 0.75, 0, 4);
            tris[0].v[0] = a; tris[0].v[1] = b; tris[0].v[2] = c;
            tris[1].v[0] = a; tris[1].v[1] = c; tris[1].v[2] = d;
            n = 2;
        } else {
            n = sc == 0 ? floor_scene(tris) : cube_scene(tris);
        }
        for (L = 4; L <= 64; L *= 2) {
            double worst_b = 0, worst_e = 0;
            for (k = 0; k < n; k++) {
                double e = scene_max_error(&tris[k], 1, L, 64), b = subdiv_bound(&tris[k], L, 64);
                snprintf(msg, sizeof msg, "%s tri %d subdiv%d: max error %.4f texels, bound %.4f", names[sc], k, L, e,
                         b);
                TEST_ASSERT_TRUE_MESSAGE(e <= b, msg);
                if (b > worst_b && e > 0) {
                    worst_b = b;
                    worst_e = e;
                }
            }
            snprintf(msg, sizeof msg, "%s subdiv%d: largest bound %.4f texels, that triangle's max error %.4f",
                     names[sc], L, worst_b, worst_e);
            TEST_MESSAGE(msg);
            if (sc > 0 && L == 16)
                TEST_ASSERT_TRUE_MESSAGE(worst_e >= worst_b / 4, msg);
        }
    }
    n = floor_scene(tris);
    exact_e = scene_max_error(tris, n, FXL_PERSP_EXACT, 64);
    /* Affine is exact to its own (screen-linear) definition ... */
    affine_e = scene_max_error_ref(tris, n, FXL_PERSP_AFFINE, 64, 1);
    snprintf(msg, sizeof msg, "floor affine vs screen-linear reference: %.6f texels", affine_e);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE_MESSAGE(affine_e <= 1.0 / 64, msg);
    /* ... and far from perspective-correct. */
    affine_e = scene_max_error(tris, n, FXL_PERSP_AFFINE, 64);
    snprintf(msg, sizeof msg, "floor affine max error %.3f texels vs exact %.6f", affine_e, exact_e);
    TEST_MESSAGE(msg);
    /* The affine floor maps v linearly across a 50:1 depth range: errors of
     * many texels are expected; 100x the exact error is a loose floor. */
    TEST_ASSERT_TRUE_MESSAGE(affine_e > 1.0 && affine_e > 100 * exact_e, msg);
}

/* ---- adaptive perspective --------------------------------------------------- */

static int probe_seg_len_max;
static int probe_affine;   /* the last triangle was set up affine */
static uint32_t probe_seg_len(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    (void)s;
    if (tri->seg_log2 > probe_seg_len_max)
        probe_seg_len_max = tri->seg_log2;
    probe_affine = tri->affine;
    return probe_seg(tri, s);
}

/* Writes the texel index a point-sampled repeat lookup of a 256 x 256
 * texture takes (as the specialised walks index it) and counts the
 * triangles whose segments were cut by the adaptive bound. */
static int probe_auto_seg_tris, probe_auto_quad_tris, probe_row_const_tris, probe_row_const_z_tris, probe_last_quad;
static int probe_auto_rr_tris;
static const fxl__tri_t *probe_last_tri;
static uint32_t probe_texel_index(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    int32_t i;
    if (tri != probe_last_tri) {   /* the first segment of a draw */
        probe_auto_seg_tris += tri->auto_seg != 0;
        probe_auto_quad_tris += tri->auto_quad;
        probe_auto_rr_tris += tri->auto_rr;
        probe_row_const_tris += tri->gpx[FXL__PQ] == 0;
        probe_row_const_z_tris += tri->gpx[FXL__PQ] == 0 && tri->gpx[FXL__PZ] != 0;
        probe_last_tri = tri;
    }
    for (i = 0; i < s->n; i++) {
        uint32_t u = fxl__seg_coord(s->u, s->du, s->ddu, i), v = fxl__seg_coord(s->v, s->dv, s->ddv, i);
        s->dst[i] = (uint16_t)((((v >> 16) & 255u) << 8) | ((u >> 16) & 255u));
    }
    return (uint32_t)s->n;
}

/* probe_texel_index with the depth test and write of the fast loops
 * (span_loop.h): z >> 16 drawn where greater than the stored depth. */
static uint32_t probe_texel_index_z(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    uint32_t written = 0;
    int32_t i;
    uint16_t saved[1];
    if (!s->zb)
        return probe_texel_index(tri, s);
    for (i = 0; i < s->n; i++) {
        const uint16_t zz = (uint16_t)((s->z + (uint32_t)s->dz * (uint32_t)i) >> 16);
        fxl__seg_t one = *s;
        if (zz <= s->zb[i])
            continue;
        s->zb[i] = zz;
        /* the texel of pixel i alone: a segment of one pixel starting there */
        one.dst = saved;
        one.n = 1;
        one.u = fxl__seg_coord(s->u, s->du, s->ddu, i);
        one.v = fxl__seg_coord(s->v, s->dv, s->ddv, i);
        (void)probe_texel_index(tri, &one);
        s->dst[i] = saved[0];
        written++;
    }
    return written;
}

/* The specialised walks (span_fast.h) and the generic walk (span.c) cut
 * spans into the same segments and compute the same u, v: with a texture
 * whose texels hold their own index, every pixel of the fast walk equals
 * the index the generic walk computes, for fixed, exact and adaptive
 * (per-segment) lengths, with and without an x-clip. A quarter of the
 * triangles have q constant along rows (two vertices on one row at one
 * depth), where the fast walks keep the span start's 1/q. */
void test_fast_and_generic_walks_agree(void)
{
    enum { NT = 120 };
    static uint16_t texels[256 * 256], fast[W * H], gen[W * H], zfast[W * H], zgen[W * H];
    /* AUTO at three budgets: at 1/4 the steepest triangles take reciprocal
     * runs, at 1/16 fewer, at 1/64 none (their error bound does not fit) */
    static const int16_t persp[6] = {16, FXL_PERSP_EXACT, FXL_PERSP_AUTO, FXL_PERSP_AUTO, 8, FXL_PERSP_AUTO};
    static const int32_t budget[6] = {0, 0, 65536 / 4, 65536 / 64, 0, 65536 / 16};
    static fxl_vertex_t tris[NT][3];
    fxl_texture_t tex;
    fxl_target_t t;
    fxl_draw_t d;
    int i, k, m, c, zd, skipped = 0;
    char msg[120];
    for (i = 0; i < 256 * 256; i++)
        texels[i] = (uint16_t)i;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 256, 256, FXL_TEXFMT_RGB565, 1));
    lcg_state = 77u;
    for (k = 0; k < NT; k++) {
        /* one far vertex: depth ratios of 10 to 33 across the triangle */
        for (i = 0; i < 3; i++)
            tris[k][i] = vtx((rnd() % 20001) / 10000.0 * 3 * W - W, (rnd() % 20001) / 10000.0 * 3 * H - H,
                             i == 0 ? 0.03 : 0.3 + (rnd() % 700) / 1000.0, ((int)(rnd() % 2001) - 1000) / 100.0,
                             ((int)(rnd() % 2001) - 1000) / 100.0);
        if (k >= NT - NT / 4) {
            /* vertex 1 on vertex 0's row at its depth: q_x == 0 */
            tris[k][1].y = tris[k][0].y;
            tris[k][1].inv_w = tris[k][0].inv_w;
            if (k & 1) {
                /* one unit of inv_w apart, with q = inv_w >> 1 (the largest
                 * inv_w >= 2^31): q_x is still 0, but z_x is not */
                tris[k][0].inv_w &= ~1u;
                tris[k][1].inv_w = tris[k][0].inv_w + 1u;
                tris[k][2].inv_w |= 0x80000000u;
            }
        }
    }
    probe_auto_seg_tris = probe_auto_quad_tris = probe_row_const_tris = probe_row_const_z_tris = 0;
    probe_auto_rr_tris = 0;
    for (zd = 0; zd < (FXL_HAVE_DEPTH ? 2 : 1); zd++)
    for (m = 0; m < 6; m++)
        for (c = 0; c < 3; c++) {
            /* a clip near the left edge, and one well inside the spans
             * (AUTO's segments start where a walk from the span's left
             * end would cut them: auto.h) */
            const fxl_rect_t cr = c == 1 ? (fxl_rect_t){11, 0, W - 9, H} : (fxl_rect_t){101, 3, 173, H - 5};
            fxl_draw_defaults(&d);
            d.texture = &tex;
            /* the second pass with the depth test and write, on a buffer
             * cleared to 0 (farthest) */
            d.depth = zd ? FXL_DEPTH_TEST | FXL_DEPTH_WRITE : 0;
            d.filter = FXL_FILTER_POINT;
            d.persp = persp[m];
            if (budget[m])
                d.auto_budget = budget[m];
            if (d.persp == FXL_PERSP_AUTO && !FXL_HAVE_AUTO) {   /* refused, not compared empty */
                fxl_target_init(&t, fast, W, H, W, drawable_rgb565());
                TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_draw_triangle(&t, &d, tris[0], NULL));
                skipped++;
                continue;
            }
            for (k = 0; k < NT; k++) {
                /* the probe writes native indices: a build drawing only
                 * byte-swapped targets has its pixels swapped back */
                fxl_target_init(&t, fast, W, H, W, drawable_rgb565());
                fxl_target_clear(&t, 0xDEAD);
                if (zd) {
                    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zfast));
                    fxl_target_clear_depth(&t);
                }
                if (c)
                    fxl_target_set_clip(&t, &cr);
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, tris[k], NULL));
                pixels_to_native(fast, W * H, t.format);
                fxl_target_init(&t, gen, W, H, W, drawable_rgb565());
                fxl_target_clear(&t, 0xDEAD);
                pixels_to_native(gen, W * H, t.format);
                if (zd) {
                    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zgen));
                    fxl_target_clear_depth(&t);
                }
                if (c)
                    fxl_target_set_clip(&t, &cr);
                probe_last_tri = NULL;
                TEST_ASSERT_EQUAL_INT(FXL_OK,
                                      fxl__draw_triangle_with(&t, &d, tris[k], NULL, probe_texel_index_z));
                for (i = 0; i < W * H; i++)
                    if (fast[i] != gen[i] || (zd && zfast[i] != zgen[i])) {
                        snprintf(msg, sizeof msg,
                                 "persp %d clip %d depth %d triangle %d pixel (%d,%d): fast %04x/%04x generic %04x/%04x",
                                 persp[m], c, zd, k, i % W, i / W, fast[i], zd ? zfast[i] : 0, gen[i],
                                 zd ? zgen[i] : 0);
                        TEST_FAIL_MESSAGE(msg);
                    }
            }
        }
    /* guard against the comparison passing vacuously: the adaptive draws
     * that reached the target did run the per-segment walk or reciprocal
     * runs, AUTO's walks for triangles whose segments vary (with this seed
     * 72 and 92 of the 2,160 of both passes with every feature; none more
     * in the inner clip, where fewer triangles show; the rest are
     * off-target or get one length; without FXL_HAVE_QUAD, where none gets one
     * quadratic length, auto_seg 2, and chords are shorter, more take
     * runs) */
    snprintf(msg, sizeof msg,
             "%d of %d adaptive draws cut per segment, %d quadratic, %d in runs; %d of %d with q_x == 0 (%d of them "
             "z_x != 0)",
             probe_auto_seg_tris, FXL_HAVE_AUTO ? 9 * NT * zd : 0, probe_auto_quad_tris, probe_auto_rr_tris,
             probe_row_const_tris, (18 * zd - skipped) * NT, probe_row_const_z_tris);
    TEST_MESSAGE(msg);
#if FXL_HAVE_DEPTH
    /* the depth pass reached a row-constant walk whose z is not constant */
    TEST_ASSERT_TRUE_MESSAGE(probe_row_const_z_tris > 0, msg);
#endif
#if FXL_HAVE_AUTO
    TEST_ASSERT_TRUE_MESSAGE(probe_auto_seg_tris + probe_auto_rr_tris >= (FXL_HAVE_QUAD ? NT / 4 : NT / 5), msg);
    TEST_ASSERT_TRUE_MESSAGE(probe_auto_seg_tris > 0, msg);
#else
    {
        char summary[80];
        snprintf(summary, sizeof summary, "%d of %d persp x clip cases checked, %d need FXL_HAVE_AUTO",
                 18 * zd - skipped, 18 * zd, skipped);
        TEST_MESSAGE(summary);
    }
#endif
    TEST_ASSERT_TRUE_MESSAGE(probe_row_const_tris >= NT / 4, msg);
#if FXL_HAVE_QUAD
    TEST_ASSERT_TRUE_MESSAGE(probe_auto_quad_tris >= NT / 4, msg);
#endif
}

/* FXL_PERSP_AUTO keeps the max texel error under its budget on the floor,
 * the 40-degree rolled floor (spans cross depth: the hard case) and the cube
 * for budgets 1/16, 1/4 and 1 texel; the unrolled floor, whose spans have
 * constant depth, gets whole-span affine (log2 length 8). Also with mip
 * levels and the per-segment LOD, where AUTO cuts its segments otherwise
 * (at most the 16-pixel LOD grid, per segment more often: auto.c, raster.c
 * and the batch walk's span test): drawn with the LOD biased to level 0
 * everywhere, which cuts the same segments and keeps u, v in level-0
 * texels. */
void test_auto_mode_within_budget_and_affine_where_depth_is_constant(void)
{
    static const int32_t budgets[3] = {65536 / 16, 65536 / 4, 65536};
    tri_t tris[12];
    int b, sc, n, mips;
    char msg[160];
    TEST_NEEDS(FXL_HAVE_AUTO);
    for (mips = 0; mips < 2; mips++) {
        if (mips && !FXL_HAVE_MIPMAP)
            continue;
        for (sc = 0; sc < 3; sc++) {
            n = sc == 0 ? floor_scene(tris) : (sc == 1 ? rolled_floor_scene(tris, 40) : cube_scene(tris));
            for (b = 0; b < 3; b++) {
                static uint16_t texels[64 * 64 * 4 / 3 + 1];
                fxl_draw_t d;
                fxl_texture_t tex;
                double maxe;
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 64, 64, FXL_TEXFMT_RGB565, mips ? 7 : 1));
                fxl_draw_defaults(&d);
                d.texture = &tex;
                d.depth = 0;
                d.persp = FXL_PERSP_AUTO;
                d.auto_budget = budgets[b];
                if (mips) {
                    /* point-mip-linear where bilinear is not built: the
                     * same segments (no segment choice reads the filter) */
                    d.filter = FXL_HAVE_BILINEAR ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
                    d.mip = FXL_MIP_LINEAR;
                    d.lod = FXL_LOD_SEGMENT;
                    d.lod_bias_q8 = INT16_MIN;
                }
                probe_seg_len_max = -1;
                maxe = draw_max_error(tris, n, &d, 64, 0, probe_seg_len);
                snprintf(msg, sizeof msg, "levels %d scene %d budget %.4f: max error %.4f texels, longest segment 2^%d",
                         mips ? 7 : 1, sc, budgets[b] / 65536.0, maxe, probe_seg_len_max);
                TEST_MESSAGE(msg);
                TEST_ASSERT_TRUE_MESSAGE(maxe <= budgets[b] / 65536.0, msg);
                if (sc == 0)
                    TEST_ASSERT_EQUAL_INT_MESSAGE(mips ? 4 : 8, probe_seg_len_max, msg);
            }
        }
    }
}

/* FXL_PERSP_AUTO's vertex test (auto.c) draws a triangle affine, with no
 * division, when (range u + range v) (q_max - q_min) / (4 q_min) is within
 * the budget less its margins (1/16 of it and 1/128 texel). Small random
 * triangles whose vertex bound lies from 1/8 to 8 times the budget: every
 * pixel stays within the budget; the test accepts every triangle whose
 * bound is clearly inside (and then draws it exactly as FXL_PERSP_AFFINE
 * does), none whose bound is over the budget, and a fair share in all. */
void test_auto_vertex_test_keeps_small_triangles_within_budget(void)
{
    static const int32_t budgets[3] = {65536 / 16, 65536 / 4, 65536};
    static uint16_t buf[320 * 240];
    static uint16_t texels[64 * 64];
    fxl_target_t t;
    fxl_draw_t d;
    fxl_texture_t tex;
    int b, i, j, x, y, accepted = 0, drawn = 0;
    double worst = 0;
    char msg[200];
    TEST_NEEDS(FXL_HAVE_AUTO);
    lcg_state = 777u;
    auto_draw_64(&d, &tex, texels);
    for (b = 0; b < 3; b++) {
        d.auto_budget = budgets[b];
        for (i = 0; i < 200; i++) {
            fxl_vertex_t v[3];
            const double cx = rnd_range(40, 280), cy = rnd_range(40, 200);
            /* vertex bound / budget from 1/8 to 8, log-uniform */
            const double rho = pow(2.0, rnd_range(-3000, 3000) / 1000.0);
            double px[3], py[3], iw[3], tu[3], tv[3], qlo = 1e9, qhi = 0, ulo = 1e9, uhi = -1e9, vlo = 1e9,
                                                     vhi = -1e9, bound, scale, e_max = 0;
            for (j = 0; j < 3; j++) {
                px[j] = cx + rnd_range(-12, 12);
                py[j] = cy + rnd_range(-12, 12);
                iw[j] = 0.3 * (1.0 + rnd_range(0, 500) / 1000.0);
                tu[j] = rnd_range(-1000, 1000) / 1000.0;
                tv[j] = rnd_range(-1000, 1000) / 1000.0;
                qlo = iw[j] < qlo ? iw[j] : qlo;
                qhi = iw[j] > qhi ? iw[j] : qhi;
                ulo = tu[j] < ulo ? tu[j] : ulo;
                uhi = tu[j] > uhi ? tu[j] : uhi;
                vlo = tv[j] < vlo ? tv[j] : vlo;
                vhi = tv[j] > vhi ? tv[j] : vhi;
            }
            bound = (uhi - ulo + vhi - vlo) * (qhi - qlo) / (4 * qlo);
            if (bound <= 0)
                continue;
            /* texel coordinates scaled to put the bound at rho * budget */
            scale = rho * budgets[b] / 65536.0 / bound;
            bound *= scale;
            for (j = 0; j < 3; j++)
                v[j] = vtx(px[j], py[j], iw[j], 0.5 + tu[j] * scale / 64, 0.5 + tv[j] * scale / 64);
            probe_target(&t, buf, 320, 240);
            probe_seg_len_max = -1;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, v, NULL, probe_seg_len));
            if (probe_seg_len_max < 0)
                continue;   /* nothing covered */
            drawn++;
            accepted += probe_affine;
            snprintf(msg, sizeof msg, "budget %.4f tri %d: vertex bound %.4f, set up affine %d", budgets[b] / 65536.0,
                     i, bound, probe_affine);
            /* the double-precision bound of the unrounded vertices, with
             * 10% for the q16 rounding of u, v and inv_w */
            if (bound <= 0.9 * (budgets[b] / 65536.0 * 15 / 16 - 1.0 / 128))
                TEST_ASSERT_TRUE_MESSAGE(probe_affine, msg);
            if (bound >= 1.1 * budgets[b] / 65536.0)
                TEST_ASSERT_TRUE_MESSAGE(!probe_affine, msg);
            if (probe_affine) {
                /* the same pixels, u and v as FXL_PERSP_AFFINE */
                static double au[320 * 240], av[320 * 240];
                memcpy(au, probe_u, sizeof au);
                memcpy(av, probe_v, sizeof av);
                d.persp = FXL_PERSP_AFFINE;
                probe_target(&t, buf, 320, 240);
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, v, NULL, probe_seg_len));
                d.persp = FXL_PERSP_AUTO;
                for (y = 0; y < 240; y++)
                    for (x = 0; x < 320; x++)
                        if (probe_count[y * 320 + x] &&
                            (au[y * 320 + x] != probe_u[y * 320 + x] || av[y * 320 + x] != probe_v[y * 320 + x]))
                            TEST_FAIL_MESSAGE(msg);
                /* redraw AUTO's for the error check below */
                probe_target(&t, buf, 320, 240);
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, v, NULL, probe_seg_len));
            }
            e_max = probed_max_error(v);
            if (e_max / (budgets[b] / 65536.0) > worst)
                worst = e_max / (budgets[b] / 65536.0);
            snprintf(msg, sizeof msg, "budget %.4f tri %d: max error %.4f texels, vertex bound %.4f, log2 length %d",
                     budgets[b] / 65536.0, i, e_max, bound, probe_seg_len_max);
            TEST_ASSERT_TRUE_MESSAGE(e_max <= budgets[b] / 65536.0, msg);
        }
    }
    snprintf(msg, sizeof msg, "%d triangles drawn, %d set up affine; worst error / budget %.3f", drawn,
             accepted, worst);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE_MESSAGE(drawn >= 450 && accepted >= drawn / 4, msg);
}

/* Counts the quadratic segments the generic walk hands to probe_seg. */
static int probe_quad_segs;
static uint32_t probe_seg_quad(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    probe_quad_segs += (s->ddu | s->ddv) != 0;
    probe_last_quad = tri->auto_quad;
    return probe_seg(tri, s);
}

/* A floor-like triangle for AUTO's reciprocal runs: two near vertices
 * 10 to 30 widths either side of the bottom of a w x h target on a line
 * rolled 20 to 60 degrees, one far vertex (depth ratio 30 to 60) in its
 * middle, texture coordinates changing by 40 to 75 repeats: what the target shows recedes steeply all over (the rolled
 * floor's shape). */
static void rr_floor_tri(fxl_vertex_t v[3], int w, int h)
{
    /* one draw from the generator a statement: C leaves the order of a
     * call's arguments open, and GCC and Clang differ */
    const double far = 1.0 / rnd_range(30, 60), su = rnd_range(25, 45), sv = rnd_range(15, 30);
    const double u0 = rnd_range(-500, 500) / 100.0, v0 = rnd_range(-500, 500) / 100.0;
    const double deg = rnd_range(20, 60), sign = (rnd() & 1) ? 1.0 : -1.0;
    const double roll = deg * 3.14159265358979 / 180 * sign;
    const double r = rnd_range(10, 30) * (double)w, cx = rnd_range(0, w), cy = h * 1.05;
    const double fx = rnd_range(w / 4, 3 * w / 4), fy = rnd_range(h / 4, h / 2), fu = rnd_range(0, 100) / 100.0;
    v[0] = vtx(cx - r * cos(roll), cy - r * sin(roll), 1.0, u0, v0);
    v[1] = vtx(cx + r * cos(roll), cy + r * sin(roll), 1.0, u0 + su, v0);
    v[2] = vtx(fx, fy, far, u0 + su * fu, v0 + sv);
}

static uint32_t probe_real_seg(const fxl__tri_t *tri, const fxl__seg_t *s);
static int probe_rr;   /* the last draw was set up with reciprocal runs */
static uint32_t probe_seg_rr(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    probe_rr = tri->auto_rr;
    return probe_seg(tri, s);
}
static uint32_t probe_real_rr(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    probe_rr = tri->auto_rr;
    return probe_real_seg(tri, s);
}
static uint32_t probe_index_rr(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    probe_rr = tri->auto_rr;
    return probe_texel_index_z(tri, s);
}

static int draw_fast_and_generic(const fxl_draw_t *d, const fxl_draw_t *dgen, const fxl_vertex_t v[3], int32_t w,
                                 int32_t h, fxl_pixfmt_t fmt, int depth, const fxl_rect_t *clip, uint16_t *fast,
                                 uint16_t *zfast, uint16_t *gen, uint16_t *zgen, const char *what);

/* probe_seg_rr for draws with levels: u, v scaled from the segment's
 * level to level 0 */
static uint32_t probe_seg_levels_rr(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    probe_rr = tri->auto_rr;
    return probe_record(s, (double)(1u << (tri->tex->log2_w - s->lvl->log2_w)) / 65536.0,
                        (double)(1u << (tri->tex->log2_h - s->lvl->log2_h)) / 65536.0);
}

/* AUTO on several levels, small steep triangles whose every segment the
 * cheap bound would make 1 to 4 pixels long throughout (the tunnel's far
 * walls): they take reciprocal runs (auto.c), where the same triangles on
 * one level keep their segments; either way every pixel the generic walk
 * gives is within the budget of the double-precision reference, and the
 * fast walk draws the generic walk's pixels. A 64-texel texture with 7
 * levels, trilinear; triangles with vertices 8 to 24 pixels from a point
 * of a 320 x 240 target, 1/w from 1/30 to 1/40 falling 10-30% across them,
 * 3 to 8 repeats. */
void test_auto_short_mip_segments_take_runs_within_budget(void)
{
    static uint16_t texels[64 * 64 * 4 / 3 + 1], buf[320 * 240], fast[320 * 240], gen[320 * 240];
    fxl_texture_t tex;
    fxl_target_t t;
    fxl_draw_t d;
    int k, i, lv, rr[2] = {0, 0};
    double worst[2] = {0, 0};
    char msg[200];
    TEST_NEEDS(FXL_HAVE_RR && FXL_HAVE_MIPMAP && FXL_HAVE_BILINEAR);
    lcg_state = 4242u;
    for (i = 0; i < 64 * 64 * 4 / 3 + 1; i++)
        texels[i] = (uint16_t)((uint32_t)i * 2654435761u >> 16);
    for (k = 0; k < 60; k++) {
        fxl_vertex_t v[3];
        const double cx = rnd_range(40, 280), cy = rnd_range(40, 200), size = rnd_range(8, 24);
        const double q0 = 1.0 / rnd_range(30, 40), fall = rnd_range(70, 90) / 100.0, rep = rnd_range(3, 8);
        const double ang = rnd_range(0, 628) / 100.0;
        for (i = 0; i < 3; i++) {
            const double a = ang + i * 2.0944;
            /* q falls along the first vertex's direction */
            v[i] = vtx(cx + size * cos(a), cy + size * sin(a), q0 * (i == 0 ? fall : 1.0), (i == 1) * rep,
                       (i == 2) * rep);
        }
        for (lv = 0; lv < 2; lv++) {
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 64, 64, FXL_TEXFMT_RGB565, lv ? 7 : 1));
            fxl_draw_defaults(&d);
            d.texture = &tex;
            d.depth = 0;
            d.persp = FXL_PERSP_AUTO;
            d.filter = FXL_FILTER_BILINEAR;
            d.mip = lv ? FXL_MIP_LINEAR : FXL_MIP_NONE;
            d.lod = FXL_LOD_SEGMENT;
            probe_target(&t, buf, 320, 240);
            probe_rr = 0;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, v, NULL, probe_seg_levels_rr));
            rr[lv] += probe_rr;
            {
                const double e = probed_max_error(v);
                snprintf(msg, sizeof msg, "tri %d levels %d (runs %d): max error %.4f texels", k, lv ? 7 : 1,
                         probe_rr, e);
                TEST_ASSERT_TRUE_MESSAGE(e <= d.auto_budget / 65536.0, msg);
                worst[lv] = e > worst[lv] ? e : worst[lv];
            }
            TEST_ASSERT_TRUE(draw_fast_and_generic(&d, NULL, v, 320, 240, drawable_rgb565(), 0, NULL, fast, NULL,
                                                   gen, NULL, msg) > 0);
        }
    }
    snprintf(msg, sizeof msg, "runs: %d of 60 with 7 levels (worst error %.4f), %d with one (worst %.4f)", rr[1],
             worst[1], rr[0], worst[0]);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE_MESSAGE(rr[1] >= 20 && rr[0] == 0, msg);
}

/* AUTO on the largest square texture this build accepts (1 <<
 * FXL_TEX_MAX_LOG2 texels a side): rolled floors, every pixel within the
 * budget. Reciprocal runs need |u| + |v| plus a
 * period an axis below 2^29 q16 units; summed in 32 bits, the periods of a
 * 2^14-texel square wrapped to 0, and with FXL_TEX_MAX_LOG2 14 such floors
 * took runs whose numerators overflowed (errors of 10^4 texels here;
 * config_tests.sh runs this in its tex14 configuration). The probe draws:
 * the one texel given is never read. */
void test_auto_on_the_largest_texture_keeps_its_budget(void)
{
    static uint8_t texel;
    static uint16_t buf[320 * 240];
    const int side = 1 << FXL_TEX_MAX_LOG2;
    fxl_texture_t tex;
    fxl_target_t t;
    fxl_draw_t d;
    int k, i, x, y, covered = 0, rr_tris = 0;
    double worst = 0;
    char msg[200];
    TEST_NEEDS(FXL_HAVE_AUTO);
    TEST_NEEDS(FXL_HAVE_GENERIC);
    lcg_state = 6161u;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, &texel, (uint32_t)side, (uint32_t)side, FXL_TEXFMT_L8, 1));
    fxl_draw_defaults(&d);
    d.texture = &tex;
    d.depth = 0;
    d.persp = FXL_PERSP_AUTO;
    for (k = 0; k < 40; k++) {
        fxl_vertex_t v[3];
        /* the runs test's floors (1,600 to 4,800 texels of range), their
         * periods scaled from a 64-texel texture to this one, then moved
         * 0.6 of a period on: coordinates past 2^13 texels, where the
         * runs' 32-bit numerators would not hold them */
        rr_floor_tri(v, 320, 240);
        for (i = 0; i < 3; i++) {
            v[i].u = (fxl_q16_t)((int64_t)v[i].u * 64 / side + 39322);
            v[i].v = (fxl_q16_t)((int64_t)v[i].v * 64 / side + 39322);
        }
        probe_target(&t, buf, 320, 240);
        probe_rr = 0;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, v, NULL, probe_seg_rr));
        rr_tris += probe_rr;
        for (y = 0; y < 240; y++)
            for (x = 0; x < 320; x++)
                if (probe_count[y * 320 + x]) {
                    const double e = probe_error_at(v, side, 0, 320, x, y);
                    worst = e > worst ? e : worst;
                    covered++;
                }
    }
    snprintf(msg, sizeof msg, "%d-texel texture: max error %.4f texels over %d pixels (budget 0.25), %d of 40 triangles took runs",
             side, worst, covered, rr_tris);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE(covered > 40 * 1000);
    TEST_ASSERT_TRUE_MESSAGE(worst <= 0.25, msg);
}

/* AUTO's reciprocal runs (recip_run.h) on floor-like triangles, whose
 * segments would all be short: every pixel within the budget (generic
 * walk, against the double-precision reference, and within the runs' own
 * bound, (|u| + |v|) 2^-18 + 260 q16 units); and on a 640-pixel-wide
 * target, where spans cross the runs' 256-pixel blocks, the fast walks
 * draw the generic walk's pixels, point and bilinear on one level and on
 * the nearest of nine, and trilinear and point-mip-linear on nine (the LOD
 * on AUTO's grid, or one for the triangle), with and without depth (the
 * depth written compared too), unclipped, behind a clip that starts in a
 * span's second block, in bands of 7 rows, and on a target whose origin is
 * left of the frame's (spans from negative x: with one LOD for the
 * triangle the walks' grid end was INT32_MAX, and xg - x overflowed into
 * a write past the row). */
void test_auto_reciprocal_runs_agree_and_stay_within_budget(void)
{
    enum { RW = 640, RH = 200, NT = 40, BAND = 7 };
    static const int32_t budgets[2] = {65536 / 4, 65536 / 16};
    static uint16_t texels[256 * 256 * 4 / 3 + 1], tex64[64 * 64], buf[320 * 240];
    static uint16_t fast[RW * RH], gen[RW * RH], zf[RW * RH], zg[RW * RH], band[RW * BAND], zband[RW * BAND];
    fxl_texture_t tex;
    fxl_target_t t;
    fxl_draw_t d;
    int b, k, i, zd, c, f, rr_tris = 0, rr_mip_tris = 0, rr_near_tris = 0, rr_agree = 0;
    double worst = 0, worst_rr = 0;
    char msg[200];
    TEST_NEEDS(FXL_HAVE_RR);
    lcg_state = 6161u;
    /* the error: 64-texel texture, 320 x 240 (probed_max_error) */
    auto_draw_64(&d, &tex, tex64);
    for (b = 0; b < 2; b++) {
        d.auto_budget = budgets[b];
        for (k = 0; k < NT; k++) {
            fxl_vertex_t v[3];
            double e;
            rr_floor_tri(v, 320, 240);
            probe_target(&t, buf, 320, 240);
            probe_rr = 0;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, v, NULL, probe_seg_rr));
            rr_tris += probe_rr;
            e = probed_max_error(v);
            if (probe_rr) {
                /* |u| + |v| within the rebased ranges plus a period each */
                double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9}, bound;
                for (i = 0; i < 3; i++) {
                    const double c[2] = {v[i].u / 65536.0, v[i].v / 65536.0};
                    int a;
                    for (a = 0; a < 2; a++) {
                        lo[a] = c[a] < lo[a] ? c[a] : lo[a];
                        hi[a] = c[a] > hi[a] ? c[a] : hi[a];
                    }
                }
                bound = (hi[0] - lo[0] + hi[1] - lo[1] + 2) * 64 / 262144.0 + 260 / 65536.0;
                snprintf(msg, sizeof msg, "budget %.4f tri %d: max error %.5f texels, runs' bound %.5f",
                         budgets[b] / 65536.0, k, e, bound);
                TEST_ASSERT_TRUE_MESSAGE(e <= bound, msg);
                worst_rr = e > worst_rr ? e : worst_rr;
            }
            worst = e / (budgets[b] / 65536.0) > worst ? e / (budgets[b] / 65536.0) : worst;
            snprintf(msg, sizeof msg, "budget %.4f tri %d (runs %d): max error %.4f texels", budgets[b] / 65536.0, k,
                     probe_rr, e);
            TEST_ASSERT_TRUE_MESSAGE(e <= budgets[b] / 65536.0, msg);
        }
    }
    snprintf(msg, sizeof msg, "%d of %d triangles took reciprocal runs (worst error %.5f texels); worst error / budget %.3f",
             rr_tris, 2 * NT, worst_rr, worst);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE_MESSAGE(rr_tris >= NT / 2, msg);   /* 42 of the 80 with this seed */

    /* fast against generic: a texture whose texels hold their index (on
     * level 0; hashed on the levels after) */
    for (i = 0; i < 256 * 256 * 4 / 3 + 1; i++)
        texels[i] = (uint16_t)(i < 256 * 256 ? (uint32_t)i : (uint32_t)i * 2654435761u >> 16);
    fxl_draw_defaults(&d);
    d.texture = &tex;
    d.persp = FXL_PERSP_AUTO;
    d.lod = FXL_LOD_SEGMENT;
    rr_tris = 0;
    for (k = 0; k < NT; k++) {
        fxl_vertex_t v[3];
        /* odd triangles: one LOD for the whole triangle */
        d.lod = k & 1 ? FXL_LOD_TRIANGLE : FXL_LOD_SEGMENT;
        rr_floor_tri(v, RW, RH);
        /* a 256-texel texture: a quarter of the repeats keeps the texel ranges of the 64-texel case */
        for (i = 0; i < 3; i++) {
            v[i].u /= 4;
            v[i].v /= 4;
        }
        for (f = 0; f < 6; f++)
        for (zd = 0; zd < (FXL_HAVE_DEPTH ? 2 : 1); zd++)
            for (c = 0; c < 4; c++) {
                const fxl_rect_t cr = {301, 0, 597, RH};
                const int bil = f == 1 || f == 2 || f == 5;
                int y0, y;
                /* f 0, point: the texel index the generic walk computes (the
                 * probe); 1 bilinear, 2 trilinear, 3 point-mip-linear, 4
                 * point and 5 bilinear on the nearest level: its own pixel
                 * loops */
                if (bil && !FXL_HAVE_BILINEAR)
                    continue;
                if (f >= 2 && !FXL_HAVE_MIPMAP)
                    continue;
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 256, 256, FXL_TEXFMT_RGB565, f >= 2 ? 9 : 1));
                d.filter = bil ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
                d.mip = f >= 4 ? FXL_MIP_NEAREST : (f >= 2 ? FXL_MIP_LINEAR : FXL_MIP_NONE);
                d.depth = zd ? FXL_DEPTH_TEST | FXL_DEPTH_WRITE : 0;
                fxl_target_init(&t, gen, RW, RH, RW, drawable_rgb565());
                fxl_target_clear(&t, 0xDEAD);
                pixels_to_native(gen, RW * RH, t.format);
                if (zd) {
                    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zg));
                    fxl_target_clear_depth(&t);
                }
                if (c == 1)
                    fxl_target_set_clip(&t, &cr);
                if (c == 3)
                    fxl_target_set_origin(&t, -64, 0);   /* spans from negative x */
                probe_last_tri = NULL;
                probe_rr = 0;
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, v, NULL,
                                                                      f ? probe_real_rr : probe_index_rr));
                if (f)
                    pixels_to_native(gen, RW * RH, t.format);
                if (c == 2) {
                    /* bands: each its own target, origin at its first row */
                    for (y0 = 0; y0 < RH; y0 += BAND) {
                        const int bh = RH - y0 < BAND ? RH - y0 : BAND;
                        fxl_target_init(&t, band, RW, bh, RW, drawable_rgb565());
                        fxl_target_set_origin(&t, 0, y0);
                        fxl_target_clear(&t, 0xDEAD);
                        if (zd) {
                            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zband));
                            fxl_target_clear_depth(&t);
                        }
                        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, NULL));
                        pixels_to_native(band, RW * bh, t.format);
                        for (y = 0; y < bh; y++)
                            memcpy(fast + (y0 + y) * RW, band + y * RW, RW * sizeof fast[0]);
                    }
                } else {
                    fxl_target_init(&t, fast, RW, RH, RW, drawable_rgb565());
                    fxl_target_clear(&t, 0xDEAD);
                    if (zd) {
                        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zf));
                        fxl_target_clear_depth(&t);
                    }
                    if (c == 1)
                        fxl_target_set_clip(&t, &cr);
                    if (c == 3)
                        fxl_target_set_origin(&t, -64, 0);
                    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, NULL));
                    pixels_to_native(fast, RW * RH, t.format);
                    /* and the depth they wrote */
                    if (zd && memcmp(zf, zg, sizeof zf) != 0) {
                        snprintf(msg, sizeof msg, "triangle %d filter %d clip %d: depth differs", k, f, c);
                        TEST_FAIL_MESSAGE(msg);
                    }
                }
                if (f == 0 && zd == 0 && c == 0)
                    rr_tris += probe_rr;
                if (f == 3 && zd == 0 && c == 0)
                    rr_mip_tris += probe_rr;   /* point-mip-linear: every build with levels */
                if (f == 4 && zd == 0 && c == 0)
                    rr_near_tris += probe_rr;   /* point, nearest level */
                for (i = 0; i < RW * RH; i++)
                    if (fast[i] != gen[i]) {
                        snprintf(msg, sizeof msg,
                                 "triangle %d filter %d depth %d clip %d pixel (%d,%d): fast %04x generic %04x", k, f,
                                 zd, c, i % RW, i / RW, fast[i], gen[i]);
                        TEST_FAIL_MESSAGE(msg);
                    }
                rr_agree++;
            }
    }
    snprintf(msg, sizeof msg,
             "%d of %d triangles took reciprocal runs (%d with nine levels blended, %d on the nearest); %d renders "
             "compared",
             rr_tris, NT, rr_mip_tris, rr_near_tris, rr_agree);
    TEST_MESSAGE(msg);
    /* 21, 27 and 27 of the 40 with this seed */
    TEST_ASSERT_TRUE_MESSAGE(rr_tris >= NT / 4 && (!FXL_HAVE_MIPMAP || (rr_mip_tris >= NT / 4 && rr_near_tris >= NT / 4)),
                             msg);
}

/* Depth ties in the reciprocal runs (FXL_PERSP_AUTO, auto.h): the same
 * triangle drawn again with another texture has bit-for-bit the same depth,
 * and "greater is nearer" must keep the first draw. The tie test in
 * test_depth_ties_keep_the_first_draw_in_every_walk draws one-level
 * textures; the runs' mip-linear loops with depth (span_fast.h, FXL_T_MIPLIN
 * and FXL_T_DEPTH) have their own comparison, checked here for every
 * filter the runs have: point, bilinear, trilinear, point-mip-linear and the
 * nearest level. The pixels the stats count are the ones written: all of
 * the first draw's, none of the second's (the one-level run loops count
 * the rejections and subtract them). */
void test_auto_reciprocal_runs_keep_the_first_draw_on_depth_ties(void)
{
    enum { RW = 640, RH = 200, NT = 12, NTEX = 256 * 256 * 4 / 3 + 1 };
    static uint16_t tex_a[NTEX], tex_b[NTEX], px[RW * RH], zb[RW * RH], first[RW * RH], zfirst[RW * RH];
    static uint16_t scratch[RW * RH];
    fxl_texture_t ta, tb;
    fxl_target_t t, ts;
    fxl_draw_t d;
    fxl_stats_t st;
    uint32_t written;
    int i, k, f, rr_tris = 0, compared = 0;
    char msg[160];
    TEST_NEEDS(FXL_HAVE_RR);
    TEST_NEEDS(FXL_HAVE_DEPTH);
    lcg_state = 7717u;
    for (i = 0; i < NTEX; i++) {
        tex_a[i] = (uint16_t)((uint32_t)i * 2654435761u >> 16);
        tex_b[i] = (uint16_t)~tex_a[i];
    }
    for (k = 0; k < NT; k++) {
        fxl_vertex_t v[3];
        rr_floor_tri(v, RW, RH);
        for (i = 0; i < 3; i++) {
            v[i].u /= 4;   /* a 256-texel texture: as in the test above */
            v[i].v /= 4;
        }
        for (f = 0; f < 6; f++) {
            const int bil = f == 1 || f == 2 || f == 5;
            const uint32_t levels = f >= 2 ? 9u : 1u;
            if ((bil && !FXL_HAVE_BILINEAR) || (f >= 2 && !FXL_HAVE_MIPMAP))
                continue;
            fxl_draw_defaults(&d);
            d.persp = FXL_PERSP_AUTO;
            d.filter = bil ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
            d.mip = f >= 4 ? FXL_MIP_NEAREST : (f >= 2 ? FXL_MIP_LINEAR : FXL_MIP_NONE);
            d.depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&ta, tex_a, 256, 256, FXL_TEXFMT_RGB565, levels));
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tb, tex_b, 256, 256, FXL_TEXFMT_RGB565, levels));
            /* did this triangle take the runs? (the generic walk's setup) */
            d.texture = &ta;
            fxl_target_init(&ts, scratch, RW, RH, RW, drawable_rgb565());
            probe_rr = 0;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&ts, &d, v, NULL, probe_real_rr));
            if (f == 2 && probe_rr)
                rr_tris++;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, px, RW, RH, RW, drawable_rgb565()));
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zb));
            fxl_target_clear(&t, 0);
            fxl_target_clear_depth(&t);
            memset(&st, 0, sizeof st);
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, &st));
            memcpy(first, px, sizeof px);
            memcpy(zfirst, zb, sizeof zb);
            /* the pixels counted are the ones written: each wrote a depth
             * above the cleared 0 (greater is nearer) */
            for (i = 0, written = 0; i < RW * RH; i++)
                written += zfirst[i] != 0;
            snprintf(msg, sizeof msg, "triangle %d filter %d (runs %d): %lu pixels counted, %lu written", k, f,
                     probe_rr, (unsigned long)st.pixels, (unsigned long)written);
            TEST_ASSERT_TRUE_MESSAGE(st.pixels == written && written > 0, msg);
            d.texture = &tb;   /* the same geometry: every depth a tie */
            memset(&st, 0, sizeof st);
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, &st));
            snprintf(msg, sizeof msg, "triangle %d filter %d (runs %d): %lu pixels counted where every one is a tie",
                     k, f, probe_rr, (unsigned long)st.pixels);
            TEST_ASSERT_TRUE_MESSAGE(st.pixels == 0, msg);
            for (i = 0; i < RW * RH; i++)
                if (px[i] != first[i] || zb[i] != zfirst[i]) {
                    snprintf(msg, sizeof msg,
                             "triangle %d filter %d (runs %d) pixel (%d,%d): a tie overwrote %04x with %04x", k, f,
                             probe_rr, i % RW, i / RW, first[i], px[i]);
                    TEST_FAIL_MESSAGE(msg);
                }
            compared++;
        }
    }
    snprintf(msg, sizeof msg, "%d of %d triangles took reciprocal runs with levels blended; %d renders compared",
             rr_tris, NT, compared);
    TEST_MESSAGE(msg);
    /* the seed's floor triangles mostly take the runs (the test above: 27
     * of 40 with levels blended); a quarter keeps the test meaningful */
    TEST_ASSERT_TRUE_MESSAGE(!FXL_HAVE_MIPMAP || rr_tris >= NT / 4, msg);
}

/* FXL_PERSP_AUTO with quadratic segments (auto.h): random triangles with
 * one far vertex (depth ratios 3 to 30 across the triangle) and texture
 * coordinates up to +-40 repeats, seen through the generic walk: every
 * pixel stays within the budget, and quadratic segments were drawn. */
void test_auto_quadratic_segments_stay_within_budget(void)
{
    static const int32_t budgets[3] = {65536 / 16, 65536 / 4, 65536};
    static uint16_t buf[320 * 240];
    static uint16_t texels[64 * 64];
    fxl_target_t t;
    fxl_draw_t d;
    fxl_texture_t tex;
    int b, i, j, quad_tris = 0;
    double worst = 0;
    char msg[200];
    TEST_NEEDS(FXL_HAVE_AUTO);
    lcg_state = 4242u;
    auto_draw_64(&d, &tex, texels);
    probe_quad_segs = 0;
    for (b = 0; b < 3; b++) {
        d.auto_budget = budgets[b];
        for (i = 0; i < 60; i++) {
            fxl_vertex_t v[3];
            const double far = 1.0 / (3 + rnd_range(0, 27000) / 1000.0), rep = rnd_range(1, 40);
            double e_max = 0;
            for (j = 0; j < 3; j++)
                v[j] = vtx(rnd_range(0, 3200) / 10.0, rnd_range(0, 2400) / 10.0, j == 0 ? far : 1.0 - rnd_range(0, 300) / 1000.0,
                           rnd_range(-1000, 1000) / 1000.0 * rep, rnd_range(-1000, 1000) / 1000.0 * rep);
            probe_target(&t, buf, 320, 240);
            probe_last_quad = 0;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, v, NULL, probe_seg_quad));
            quad_tris += probe_last_quad;
            e_max = probed_max_error(v);
            if (e_max / (budgets[b] / 65536.0) > worst)
                worst = e_max / (budgets[b] / 65536.0);
            snprintf(msg, sizeof msg, "budget %.4f tri %d: max error %.4f texels", budgets[b] / 65536.0, i, e_max);
            TEST_ASSERT_TRUE_MESSAGE(e_max <= budgets[b] / 65536.0, msg);
        }
    }
    snprintf(msg, sizeof msg, "%d of 180 triangles quadratic, %d quadratic segments; worst error / budget %.3f",
             quad_tris, probe_quad_segs, worst);
    TEST_MESSAGE(msg);
#if FXL_HAVE_QUAD
    TEST_ASSERT_TRUE_MESSAGE(quad_tris >= 30 && probe_quad_segs >= 300, msg);
#else
    TEST_ASSERT_TRUE_MESSAGE(quad_tris == 0 && probe_quad_segs == 0, msg);   /* chords only */
#endif
}

/* Draws v with d through the probe into a w x h target over buf, with
 * stats st (may be NULL); err[] then holds each pixel's Euclidean error
 * in texels of a 128-texel texture, when ref_err is NULL, else its excess
 * over ref_err[], whose largest value is returned. */
static double probe_draw_errors(uint16_t *buf, int w, int h, const fxl_draw_t *d, const fxl_vertex_t v[3],
                                fxl_stats_t *st, double *err, const double *ref_err)
{
    fxl_target_t t;
    double worst = 0;
    int x, y;
    probe_target(&t, buf, w, h);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, d, v, st, probe_seg));
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            if (probe_count[y * w + x]) {
                const double e = probe_error_at(v, 128, 0, w, x, y) - (ref_err ? ref_err[y * w + x] : 0.0);
                if (err)
                    err[y * w + x] = e;
                worst = e > worst ? e : worst;
            }
    return worst;
}

/* AUTO's whole-span test (auto.c, the vertex ranges) on a narrow, strongly
 * receding strip whose ~200-pixel spans cross the depth change: the bound
 * holds with its margins, and a test twice as loose drew it over budget
 * (0.356 texel; found by a mutation audit: no other scene reaches it). */
/* AUTO's budget in two corners a review found:
 * - small budgets on long segments: an affine segment's q16 steps are
 *   truncated, so its pixels drift by up to one unit (2^-16 texel) a pixel
 *   and axis; the chord bound left no room for it, and a 256-pixel segment
 *   of this long sliver (a 4096-pixel target) erred 0.0046 texel against a
 *   budget of 95 q16 (0.0014). The chooser now spends the budget less
 *   1.5 * 2^-16 L on the chord.
 * - budgets above 256 texels act as 256 (raster.h): the chord bound took
 *   the raw budget, and 16384 or 32768 texels drew other pixels.
 * Each pixel's error is held to the budget plus exact mode's own error at
 * that pixel (a 128-texel texture, one level). */
void test_auto_budget_holds_for_small_and_huge_budgets(void)
{
    static const int32_t budgets[] = {95, 256, 1024, 256 * 65536, 16384 * 65536, INT32_MAX};
    static uint16_t buf[4096 * 64], texels[128 * 128], ref[4096 * 64];
    static double exact_err[4096 * 64];
    fxl_vertex_t v[3];
    fxl_texture_t tex;
    fxl_draw_t d;
    fxl_target_t t;
    char msg[200];
    size_t b;
    int k;
    const int32_t X[3] = {249886150, 179360979, 265773593}, Y[3] = {3899407, 2107052, 30407},
                  U[3] = {-6364, 19003, -9305}, Vv[3] = {-1229, -14849, 16223};
    const uint32_t Q[3] = {1871715952u, 1851342u, 1533459u};
    if (!FXL_HAVE_AUTO)
        TEST_NEEDS(FXL_HAVE_AUTO);
    for (k = 0; k < 3; k++) {
        memset(&v[k], 0, sizeof v[k]);
        v[k].x = X[k]; v[k].y = Y[k]; v[k].inv_w = Q[k]; v[k].u = U[k]; v[k].v = Vv[k]; v[k].color = 0xFFFF;
    }
    one_level_draw(&d, &tex, texels, 128, FXL_PERSP_EXACT);
    d.mip = FXL_MIP_NONE;
    (void)probe_draw_errors(buf, 4096, 64, &d, v, NULL, exact_err, NULL);
    probe_target(&t, buf, 4096, 64);   /* for the public draws below */
    d.persp = FXL_PERSP_AUTO;
    for (b = 0; b < sizeof budgets / sizeof budgets[0]; b++) {
        const double budget = (budgets[b] > 256 * 65536 ? 256 * 65536 : budgets[b]) / 65536.0;
        double worst;
        d.auto_budget = budgets[b];
        worst = probe_draw_errors(buf, 4096, 64, &d, v, NULL, NULL, exact_err);
        snprintf(msg, sizeof msg, "budget %.6g texels: error beyond exact mode's %.6g texels", budget, worst);
        TEST_MESSAGE(msg);
        TEST_ASSERT_TRUE_MESSAGE(worst <= budget + 1e-6, msg);
        /* every budget from 256 texels up draws the 256-texel image */
        if (budgets[b] == 256 * 65536) {
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_clear(&t, 0));
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, NULL));
            memcpy(ref, buf, sizeof ref);
        } else if (budgets[b] > 256 * 65536) {
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_clear(&t, 0));
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, NULL));
            TEST_ASSERT_EQUAL_MEMORY(ref, buf, sizeof ref);
        }
    }
}

/* AUTO on a triangle of constant depth along every row (two vertices on
 * one row at one inv_w, q_x = 0): u, v are affine along its rows, so the
 * chooser took 256-pixel segments whatever the budget, and their truncated
 * q16 steps drifted by up to a unit a pixel: a budget of 1 q16 drew a
 * pixel 44 units off (fuzz seed 51, case 4333147). The length is now the
 * longest whose drift fits the budget, so each pixel stays within the
 * budget of exact mode's value; from 384 q16 up the segments stay 256
 * pixels long (as many divisions as a budget of 1/4). */
void test_auto_budget_holds_on_rows_of_constant_depth(void)
{
    static const int32_t budgets[] = {1, 2, 3, 95, 256, 383, 384, 65536 / 4};
    static uint16_t buf[1024 * 128], texels[128 * 128];
    static double exact_err[1024 * 128];
    fxl_vertex_t v[3];
    fxl_texture_t tex;
    fxl_draw_t d;
    fxl_stats_t st;
    char msg[200];
    size_t b;
    uint32_t div_384 = 0;
    TEST_NEEDS(FXL_HAVE_AUTO);
    v[0] = vtx(3.3125, 2.5, 0.9, 0.0137, 0.291);
    v[1] = vtx(1020.75, 2.5, 0.9, 0.3071, 0.0127);
    v[2] = vtx(517.0625, 126.25, 0.11, -0.1913, 0.7777);
    one_level_draw(&d, &tex, texels, 128, FXL_PERSP_EXACT);
    d.mip = FXL_MIP_NONE;
    (void)probe_draw_errors(buf, 1024, 128, &d, v, NULL, exact_err, NULL);
    d.persp = FXL_PERSP_AUTO;
    for (b = 0; b < sizeof budgets / sizeof budgets[0]; b++) {
        const double budget = budgets[b] / 65536.0;
        double worst;
        d.auto_budget = budgets[b];
        memset(&st, 0, sizeof st);
        worst = probe_draw_errors(buf, 1024, 128, &d, v, &st, NULL, exact_err);
        snprintf(msg, sizeof msg, "budget %d q16: error beyond exact mode's %.3g q16, %u divisions", (int)budgets[b],
                 worst * 65536.0, (unsigned)st.divisions);
        TEST_MESSAGE(msg);
        TEST_ASSERT_TRUE_MESSAGE(worst <= budget + 1e-9, msg);
        if (budgets[b] == 384)
            div_384 = st.divisions;
        else if (budgets[b] == 65536 / 4)
            TEST_ASSERT_EQUAL_UINT32(div_384, st.divisions);   /* 256-pixel segments at both */
    }
}

void test_auto_whole_span_test_keeps_receding_strips_within_budget(void)
{
    tri_t tris[1];
    fxl_draw_t d;
    fxl_texture_t tex;
    static uint16_t texels[64 * 64];
    double e;
    char msg[100];
    TEST_NEEDS(FXL_HAVE_AUTO);
    memset(tris, 0, sizeof tris);
    tris[0].v[0].x = 1310720;  tris[0].v[0].y = 6553600; tris[0].v[0].inv_w = 858993459u;  tris[0].v[0].u = 0;
    tris[0].v[1].x = 14417920; tris[0].v[1].y = 6553600; tris[0].v[1].inv_w = 962072674u;  tris[0].v[1].u = 14388;
    tris[0].v[2].x = 7864320;  tris[0].v[2].y = 8519680; tris[0].v[2].inv_w = 2576980377u; tris[0].v[2].u = 7194;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 64, 64, FXL_TEXFMT_RGB565, 1));
    fxl_draw_defaults(&d);
    d.texture = &tex;
    d.depth = 0;
    d.persp = FXL_PERSP_AUTO;
    d.auto_budget = 65536 / 4;
    e = draw_max_error(tris, 1, &d, 64, 0, probe_seg);
    snprintf(msg, sizeof msg, "receding strip, AUTO 1/4: max error %.4f texels", e);
    TEST_ASSERT_TRUE_MESSAGE(e <= 0.25, msg);
}

/* Coordinates 2^14 texels or more from the rebased origin (uv_wide,
 * setup.c): the q16 coordinates hold u modulo 2^16 texels, so a segment's
 * change taken the short way round is wrong beyond 2^15 texels, and every
 * pixel between its ends with it. Such triangles step from the 64-bit
 * values (the generic walk, affine segments only):
 * - a quad at constant depth with 200 periods of a 1024-texel texture
 *   across 200 pixels is exact but for the step's rounding in every mode,
 *   AUTO's whole-span affine included (the error was up to 512 texels, half
 *   the texture, in segments of 64 pixels and more);
 * - AUTO keeps its budget on a receding quad whose u, v run over +-16384
 *   periods of a 64-texel texture (its quadratic segments erred by up to 32
 *   texels there, its budget 1/4). */
/* A 200-pixel square as two triangles, 1/w 1 at its top left, mid at the
 * top right and bottom left, far at the bottom right; u, v from -b to b. */
static void wide_quad(tri_t tris[2], double mid, double far, double b)
{
    const fxl_vertex_t c0 = vtx(28, 28, 1.0, -b, -b), c1 = vtx(228, 28, mid, b, -b),
                       c2 = vtx(228, 228, far, b, b), c3 = vtx(28, 228, mid, -b, b);
    tris[0].v[0] = c0; tris[0].v[1] = c1; tris[0].v[2] = c2;
    tris[1].v[0] = c0; tris[1].v[1] = c2; tris[1].v[2] = c3;
}

void test_wide_texture_ranges_step_from_64_bit_coordinates(void)
{
    static const int modes[4] = {FXL_PERSP_AFFINE, 64, FXL_PERSP_SPAN, FXL_PERSP_AUTO};
    static uint16_t texels[1024 * 1024], buf[320 * 240];
    tri_t tris[2];
    fxl_texture_t tex;
    fxl_draw_t d;
    fxl_target_t t;
    fxl_stats_t st;
    char msg[120];
    double e;
    int m, k;
    /* 1024 texels; 256 without the generic walk, whose specialised walks
     * take at most 2^16 texels (200 periods of either are wide) */
    const int tw = FXL_HAVE_GENERIC ? 1024 : 256;
    wide_quad(tris, 1.0, 1.0, 100);
    for (m = 0; m < 4; m++) {
        if (modes[m] == FXL_PERSP_AUTO && !FXL_HAVE_AUTO)
            continue;
        e = scene_max_error(tris, 2, modes[m], tw);
        snprintf(msg, sizeof msg, "constant depth, persp %d: max error %.5f texels", modes[m], e);
        TEST_ASSERT_TRUE_MESSAGE(e <= 1.0 / 64, msg);
    }
    /* the specialised walks decline them */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, (uint32_t)tw, (uint32_t)tw, FXL_TEXFMT_RGB565, 1));
    fxl_draw_defaults(&d);
    d.texture = &tex;
    d.depth = 0;
    memset(&st, 0, sizeof st);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, buf, 320, 240, 320, drawable_rgb565()));
    for (k = 0; k < 2; k++)
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, tris[k].v, &st));
    TEST_ASSERT_EQUAL_UINT32(2, st.drawn);
    TEST_ASSERT_EQUAL_UINT32(2, st.generic);

    /* A floor-like quad (rows of one depth, near edge at the bottom) over
     * 2000 periods of a 64-texel texture, depth ratio 1000: at its far tip
     * u moves ~5 * 10^5 texels a pixel. Along a row u is linear, so every
     * subdivided mode must be as exact as exact mode there: their steps
     * were saturated to 2^15 texels a pixel, 18.8 texels off. */
    {
        static const int sub[4] = {8, 16, 64, FXL_PERSP_AUTO};
        const fxl_vertex_t f0 = vtx(28, 228, 1.0, 0, 0), f1 = vtx(228, 228, 1.0, 2000, 0),
                           f2 = vtx(228, 28, 0.001, 2000, 2000), f3 = vtx(28, 28, 0.001, 0, 2000);
        double ex;
        tris[0].v[0] = f0; tris[0].v[1] = f1; tris[0].v[2] = f2;
        tris[1].v[0] = f0; tris[1].v[1] = f2; tris[1].v[2] = f3;
        ex = scene_max_error(tris, 2, FXL_PERSP_EXACT, 64);
        for (m = 0; m < 4; m++) {
            if (sub[m] == FXL_PERSP_AUTO && !FXL_HAVE_AUTO)
                continue;
            e = scene_max_error(tris, 2, sub[m], 64);
            snprintf(msg, sizeof msg, "floor over 2000 periods, ratio 1000, persp %d: max error %.5f texels (exact %.5f)",
                     sub[m], e, ex);
            TEST_ASSERT_TRUE_MESSAGE(e <= ex + 1.0 / 64, msg);
        }
    }

    if (!FXL_HAVE_AUTO)
        return;
    wide_quad(tris, 0.5, 0.25, 16384);
    e = scene_max_error(tris, 2, FXL_PERSP_AUTO, 64);
    snprintf(msg, sizeof msg, "receding, +-16384 periods, AUTO: max error %.5f texels", e);
    TEST_ASSERT_TRUE_MESSAGE(e <= 0.25, msg);
}

/* raster.h: "a triangle with a clamp or border vertex coordinate 32767
 * texels (of level 0) or more from 0 is divided at every pixel whatever
 * `persp` says". At exactly 32767 texels (2^31 - 2^16 q16 texels, setup.c's
 * rebase limit) a subdivided draw must then make exact mode's divisions;
 * a mutation run left `>=` -> `>` there alive (the limit itself went
 * unguarded). One q16 unit of the level-0 texel below, the same draw keeps
 * its 16-pixel segments (fewer divisions), so the counts tell the two
 * apart. Both signs, both clamp-type wraps, u and v. */
void test_clamp_coordinate_32767_texels_out_divides_every_pixel(void)
{
    static uint16_t texels[64 * 64], buf[W * H];   /* what the texels hold does not matter */
    const int32_t lim = (int32_t)(0x7FFF0000u >> 6);   /* 32767 texels of 64, normalised q16 */
    fxl_texture_t tex;
    fxl_target_t t;
    char msg[160];
    int wrap, sign, axis, below, checked = 0;
    for (wrap = FXL_WRAP_CLAMP; wrap <= FXL_WRAP_BORDER; wrap++)
        for (sign = -1; sign <= 1; sign += 2)
            for (axis = 0; axis < 2; axis++)
                for (below = 0; below < 2; below++) {
                    const int32_t far = sign * (lim - below);
                    fxl_vertex_t v[3] = {vtx(2.3, 1.7, 1.0, 0.25, 0.25), vtx(61.6, 9.2, 0.5, 0.25, 0.25),
                                         vtx(7.4, 45.1, 0.25, 0.25, 0.25)};
                    fxl_stats_t st[2];
                    fxl_draw_t d;
                    int m;
                    if (axis)
                        v[1].v = far;
                    else
                        v[1].u = far;
                    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 64, 64, FXL_TEXFMT_RGB565, 1));
                    tex.wrap_u = tex.wrap_v = (uint8_t)wrap;
                    fxl_draw_defaults(&d);
                    d.texture = &tex;
                    d.depth = 0;
                    if (left_out_feature(&d, &tex, FXL_PIXFMT_RGB565, 0) != NULL)
                        continue;   /* refusals: test_left_out_features_are_refused */
                    for (m = 0; m < 2; m++) {
                        d.persp = m ? FXL_PERSP_EXACT : 16;
                        memset(&st[m], 0, sizeof st[m]);
                        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, buf, W, H, W, FXL_PIXFMT_RGB565));
                        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, &st[m]));
                    }
                    snprintf(msg, sizeof msg, "wrap %d %c = %ld (%s 32767 texels): %u divisions subdivided, %u exact",
                             wrap, axis ? 'v' : 'u', (long)far, below ? "1 unit inside" : "at", (unsigned)st[0].divisions,
                             (unsigned)st[1].divisions);
                    TEST_ASSERT_TRUE_MESSAGE(st[1].pixels > 500, msg);
                    if (below)
                        TEST_ASSERT_TRUE_MESSAGE(st[0].divisions < st[1].divisions, msg);
                    else
                        TEST_ASSERT_EQUAL_UINT32_MESSAGE(st[1].divisions, st[0].divisions, msg);
                    checked++;
                }
    test_needs_draw(checked ? NULL : "FXL_HAVE_GENERIC (clamp and border wraps)");
}

/* fxl__quad_steps against the parabola it stands for: u_i (stepping
 * u += du, du += dd) within len^2/8 + 2 len + 1 q16 units of
 *   i d / len + C (i / len) (1 - i / len),  C = d len (g0 + g1) / 2 / 2^28,
 * at every pixel up to the far end, for power-of-two lengths and the
 * span's last segment (any length up to 64), d up to 2^30 and g up to
 * ~1/len (the far end's q up to twice the near one's). */
void test_quad_steps_follow_their_parabola(void)
{
#if !FXL_HAVE_QUAD
    TEST_NEEDS(FXL_HAVE_QUAD);
#else
    int n, i;
    char msg[200];
    lcg_state = 99u;
    for (n = 0; n < 20000; n++) {
        const int pow2 = (n & 1) != 0;
        const int k = pow2 ? (int)rnd_range(1, FXL__QUAD_CAP) : -1;
        const int32_t len = pow2 ? (int32_t)1 << k : rnd_range(2, 64);
        const int32_t d[2] = {rnd_range(-(1 << 29), 1 << 29) * 2 / (1 << rnd_range(0, 20)), rnd_range(-1000, 1000)};
        const int32_t g0 = rnd_range(-(1 << 28), 1 << 28) / len, g1 = g0 + rnd_range(-(1 << 20), 1 << 20) / len;
        uint32_t st[4];
        int c;
        fxl__quad_steps(d, g0, g1, len, k, st);
        for (c = 0; c < 2; c++) {
            const double C = (double)d[c] * len * (((double)g0 + g1) / 2) / 268435456.0;
            const double tol = len * len / 8.0 + 2.0 * len + 1.0;
            uint32_t u = 0, du = st[2 * c];
            for (i = 0; i <= len; i++) {
                const double t = (double)i / len, want = t * d[c] + C * t * (1 - t);
                const double got = (double)(int32_t)u;   /* |values| < 2^31 here */
                if (fabs(got - want) > tol) {
                    snprintf(msg, sizeof msg, "len %d k %d d %d g %d %d: pixel %d at %.1f, parabola %.1f (tol %.1f)",
                             (int)len, k, (int)d[c], (int)g0, (int)g1, i, got, want, tol);
                    TEST_FAIL_MESSAGE(msg);
                }
                u += du;
                du += st[2 * c + 1];
            }
        }
    }
#endif
}

/* The span's last quadratic segment (fxl__quad_axis with k < 0): its
 * first step and curvature against the formula in 64 bits,
 *   ddv = -(2 c1 / len),  du = trunc((d - ddv len (len - 1) / 2) / len),
 * for d, g anywhere in int32 (edges included) and len 2..64. The walk
 * divides in 32 bits where the numerator fits, tested on its high word;
 * the draws put the numerator on both sides of that test, on INT32_MIN
 * and INT32_MAX themselves, and within 8 of them outside. */
#if FXL_HAVE_QUAD
static int32_t rnd_i32_any_scale(void)   /* |x| < 2^31, log-uniform-ish magnitude, either sign */
{
    const int32_t m = (int32_t)((((rnd() << 8) ^ rnd()) >> 1) >> (rnd() % 31u));
    return (rnd() & 1u) ? -m : m;
}

void test_quad_last_segment_step_matches_64bit(void)
{
    static const int32_t edges[] = {INT32_MIN, INT32_MIN + 1, -(1 << 28), -1, 0, 1, 1 << 28, INT32_MAX - 1, INT32_MAX};
    const int ne = (int)(sizeof edges / sizeof edges[0]);
    long fits = 0, wide = 0, at_min = 0, at_max = 0, near_edge = 0;
    int n;
    char msg[200];
    lcg_state = 4242u;
    for (n = 0; n < 300000; n++) {
        const int32_t d = (n & 3) == 0 ? edges[n % ne] : rnd_i32_any_scale();
        const int32_t g = (n & 3) == 1 ? edges[(n / 4) % ne] : rnd_i32_any_scale();
        const int32_t len = (n & 16) ? 2 : rnd_range(2, 64);
        const int32_t c1 = fxl__quad_c1(d, g);
        const int64_t ddv = -((2 * (int64_t)c1) / len);
        const int64_t num = (int64_t)d - ddv * ((int64_t)len * (len - 1) / 2);
        const uint32_t want = (uint32_t)(uint64_t)(num / len);
        uint32_t dd;
        const uint32_t got = fxl__quad_axis(d, g, len, -1, &dd);
        if (got != want || dd != (uint32_t)(uint64_t)ddv) {
            snprintf(msg, sizeof msg, "d %ld g %ld len %ld: du %lu dd %lu, want %lu %lu", (long)d, (long)g, (long)len,
                     (unsigned long)got, (unsigned long)dd, (unsigned long)want, (unsigned long)(uint32_t)(uint64_t)ddv);
            TEST_FAIL_MESSAGE(msg);
        }
        if (num >= INT32_MIN && num <= INT32_MAX)
            fits++;
        else
            wide++;
        at_min += num == INT32_MIN;
        at_max += num == INT32_MAX;
        near_edge += (num < INT32_MIN && num >= (int64_t)INT32_MIN - 8) || (num > INT32_MAX && num <= (int64_t)INT32_MAX + 8);
    }
    snprintf(msg, sizeof msg, "numerator fits 32 bits %ld, wider %ld; at INT32_MIN %ld, INT32_MAX %ld; within 8 outside %ld",
             fits, wide, at_min, at_max, near_edge);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE_MESSAGE(fits > 1000 && wide > 1000 && at_min > 0 && at_max > 0 && near_edge > 0, msg);
}
#else
void test_quad_last_segment_step_matches_64bit(void)
{
    TEST_NEEDS(FXL_HAVE_QUAD);
}
#endif

/* The generic walk with the variant's own pixel loops (a probe that is not
 * the picked seg function gets the generic walk). */
static uint32_t probe_real_seg(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    return fxl__pick_seg_fn(tri)(tri, s);
}

/* Draw v with d on a w x h target of format fmt (with a depth buffer when
 * depth, the clip rectangle clip when not NULL) twice: by the walk the
 * core picks into fast/zfast, and into gen/zgen by the generic walk with
 * the same pixel loops (dgen NULL) or as dgen draws it; fail at the first
 * pixel or depth value that differs, the message starting with `what`.
 * Returns the pixels drawn. */
static int draw_fast_and_generic(const fxl_draw_t *d, const fxl_draw_t *dgen, const fxl_vertex_t v[3], int32_t w,
                                 int32_t h,
                                 fxl_pixfmt_t fmt, int depth, const fxl_rect_t *clip, uint16_t *fast,
                                 uint16_t *zfast, uint16_t *gen, uint16_t *zgen, const char *what)
{
    char msg[200];
    fxl_target_t t;
    int pass, i, covered = 0;
    for (pass = 0; pass < 2; pass++) {
        uint16_t *px = pass ? gen : fast, *zb = pass ? zgen : zfast;
        fxl_target_init(&t, px, w, h, w, fmt);
        fxl_target_clear(&t, 0xDEAD);
        if (depth) {
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zb));
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_clear_depth(&t));
        }
        if (clip)
            fxl_target_set_clip(&t, clip);
        if (pass && dgen)
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, dgen, v, NULL));
        else
            TEST_ASSERT_EQUAL_INT(FXL_OK, pass ? fxl__draw_triangle_with(&t, d, v, NULL, probe_real_seg)
                                               : fxl_draw_triangle(&t, d, v, NULL));
    }
    for (i = 0; i < w * h; i++) {
        if (fast[i] != gen[i] || (depth && zfast[i] != zgen[i])) {
            snprintf(msg, sizeof msg, "%.120s pixel (%d,%d): fast %04x/%04x generic %04x/%04x", what, (int)(i % w),
                     (int)(i / w), fast[i], depth ? zfast[i] : 0u, gen[i], depth ? zgen[i] : 0u);
            TEST_FAIL_MESSAGE(msg);
        }
        covered += gen[i] != 0xDEAD;
    }
    return covered;
}

/* Rows of constant q with fixed segment lengths take their own walk
 * (FXL_T_ROWC: the span's 1/q kept, each correction a multiply and a
 * shift): every pixel and depth value equals the generic walk's, for
 * every fast variant (point, bilinear; depth or not; native or swapped
 * RGB565), lengths 2 to 32 (2 has no whole-segment runs), with and
 * without an x-clip on both sides, and for textures and UV ranges whose
 * shifts fall on both sides of 32 (one ASR, or two words). */
void test_row_const_walk_matches_generic(void)
{
    enum { NT = 60 };
    static uint16_t tex_big[256 * 256], tex_small[16 * 4];
    static uint16_t fast[W * H], gen[W * H], zfast[W * H], zgen[W * H];
    static const int16_t persp[4] = {2, 4, 16, 32};
    static fxl_vertex_t tris[NT][3];
    fxl_texture_t tex[2];
    fxl_target_t t;
    fxl_draw_t d;
    char msg[160];
    int i, k, cfg, compared = 0;
    for (i = 0; i < 256 * 256; i++)
        tex_big[i] = (uint16_t)(i * 2654435761u >> 16);
    for (i = 0; i < 16 * 4; i++)
        tex_small[i] = (uint16_t)(i * 40503u);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex[0], tex_big, 256, 256, FXL_TEXFMT_RGB565, 1));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex[1], tex_small, 16, 4, FXL_TEXFMT_RGB565, 1));
    lcg_state = 2024u;
    for (k = 0; k < NT; k++) {
        /* UV ranges from 0.01 to 10^4 texture periods; vertex 1 on vertex
         * 0's row at its depth (q_x == 0) */
        const double uvs = k % 3 == 0 ? 0.01 : k % 3 == 1 ? 10.0 : 10000.0;
        for (i = 0; i < 3; i++)
            tris[k][i] = vtx((rnd() % 20001) / 10000.0 * 3 * W - W, (rnd() % 20001) / 10000.0 * 3 * H - H,
                             0.02 + (rnd() % 1000) / 1000.0, ((int)(rnd() % 2001) - 1000) / 1000.0 * uvs,
                             ((int)(rnd() % 2001) - 1000) / 1000.0 * uvs);
        tris[k][1].y = tris[k][0].y;
        tris[k][1].inv_w = tris[k][0].inv_w;
    }
    for (cfg = 0; cfg < 8 * 4 * 2; cfg++) {
        const int bil = cfg & 1, depth = (cfg >> 1) & 1, swap = (cfg >> 2) & 1;
        const int pm = (cfg >> 3) & 3, clip = cfg >> 5;
        const fxl_rect_t cr = {7, 0, W - 5, H};
        fxl_draw_defaults(&d);
        d.filter = bil ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
        d.persp = persp[pm];
        d.texture = &tex[0];
        if (left_out_feature(&d, &tex[0], swap ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565, depth) != NULL) {
            /* a variant this build left out: refused where it is asked for */
            fxl_target_init(&t, fast, W, H, W, swap ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565);
            if (depth && !FXL_HAVE_DEPTH) {
                TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_target_set_depth(&t, zfast));
            } else {
                if (depth)
                    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zfast));
                TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_draw_triangle(&t, &d, tris[0], NULL));
            }
            continue;
        }
        for (k = 0; k < NT; k++) {
            d.texture = &tex[k & 1];
            snprintf(msg, sizeof msg, "bilinear %d depth %d swap %d persp %d clip %d triangle %d", bil, depth, swap,
                     persp[pm], clip, k);
            draw_fast_and_generic(&d, NULL, tris[k], W, H, swap ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565, depth,
                                  clip ? &cr : NULL, fast, zfast, gen, zgen, msg);
            compared++;
        }
    }
    snprintf(msg, sizeof msg, "%d of 64 variants x lengths x clips checked, %d need features this build lacks",
             compared / NT, 64 - compared / NT);
    TEST_MESSAGE(msg);
    if (FXL_HAVE_GENERIC) /* then only the features themselves are refused */
        TEST_ASSERT_EQUAL_INT(8 * 4 * 2 * NT / (FXL_HAVE_BILINEAR ? 1 : 2) / (FXL_HAVE_DEPTH ? 1 : 2), compared);
}

/* n texels none of which is 0x0001, and keyed: tex with that colour key,
 * which no texel matches, so its draws take the generic loop (seg_generic)
 * and leave every pixel as it is. */
static void fill_unkeyed(uint16_t *texels, int n)
{
    int i;
    for (i = 0; i < n; i++)
        texels[i] = (uint16_t)((i * 2654435761u >> 16) | 0x0802u);
}

static void keyed_twin_texture(const fxl_texture_t *tex, fxl_texture_t *keyed)
{
    *keyed = *tex;
    keyed->flags |= FXL_TEXF_KEY;
    keyed->key = 0x0001u;
}

/* d with tex (and no depth buffer unless depth), and dg the same draw
 * through keyed. 0 when the build left out something either needs
 * (refusals: test_left_out_features_are_refused). */
static int keyed_twin_draws(fxl_draw_t *d, fxl_draw_t *dg, const fxl_texture_t *tex, const fxl_texture_t *keyed,
                            fxl_pixfmt_t fmt, int depth)
{
    d->texture = tex;
    if (!depth)
        d->depth = 0;
    *dg = *d;
    dg->texture = keyed;
    return left_out_feature(d, tex, fmt, depth) == NULL && left_out_feature(dg, keyed, fmt, depth) == NULL;
}

/* The pixel loops of the specialised walks against the generic loop
 * (seg_generic with fxl__bilerp565; reached here through a colour key no
 * texel has, which leaves every pixel as it is). Two kinds of triangle:
 * - level-floor ones (vertices 0 and 1 on one row with one depth and one
 *   v): v does not change along a row, so whole segments go to the row
 *   loops (span.c's bl_row_t for bilinear, whose footprint cache moves one
 *   column left or right on most misses; the point run loop's one texel
 *   row), and the rowc walk computes v once a row; u runs either way,
 *   magnified 8x to minified 4x;
 * - random ones, whose segments step v too (bl_sample).
 * Every pixel and depth value must be the generic loop's, in every walk:
 * affine, subdivided, exact and AUTO, point and bilinear, with depth or
 * without, both byte orders, with and without a clip rectangle. */
void test_fast_loops_match_generic_loop(void)
{
    enum { NT = 48 };
    static uint16_t texels[32 * 16], fast[W * H], gen[W * H], zfast[W * H], zgen[W * H];
    static const int16_t persp[6] = {FXL_PERSP_AFFINE, 4, 16, 32, FXL_PERSP_EXACT, FXL_PERSP_AUTO};
    static fxl_vertex_t tris[NT][3];
    fxl_texture_t tex, keyed;
    fxl_draw_t d, dg;
    char msg[200];
    int i, j, k, cfg, compared = 0;
    TEST_NEEDS(FXL_HAVE_GENERIC);
    fill_unkeyed(texels, 32 * 16);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 32, 16, FXL_TEXFMT_RGB565, 1));
    keyed_twin_texture(&tex, &keyed);
    lcg_state = 777u;
    for (k = 0; k < NT; k++) {
        const double scale = k % 4 == 0 ? 0.125 : k % 4 == 1 ? 0.5 : k % 4 == 2 ? 2.0 : 4.0; /* texels a pixel */
        const double dir = (k >> 2) % 2 ? -1.0 : 1.0;
        const double y0 = rnd_range(-4, H / 2), y2 = y0 + rnd_range(8, H), x0 = rnd_range(-8, 8) + 0.3;
        const double w = rnd_range(W / 2, W + 16), q0 = 0.2 + (rnd() % 800) / 1000.0;
        const double q2 = k % 3 == 0 ? q0 : 0.05 + (rnd() % 950) / 1000.0;
        /* u, v in texels here, in texture periods (32 x 16) in the vertices */
        const double u0 = (rnd() % 64) / 2.0 - 16.0, v0 = (rnd() % 64) / 8.0 - 4.0;
        for (i = 0; i < 3; i++) {
            /* even k: level floor; odd k past NT / 2: random */
            if (k < NT / 2 || (k & 1) == 0) {
                tris[k][0] = vtx(x0, y0, q0, u0 / 32, v0 / 16);
                tris[k][1] = vtx(x0 + w, y0, q0, (u0 + dir * scale * w) / 32, v0 / 16);
                tris[k][2] = vtx(x0 + rnd_range(0, W), y2, q2, (u0 + rnd_range(-20, 20)) / 32,
                                 (v0 + rnd_range(-12, 12)) / 16);
            } else {
                tris[k][i] = vtx(rnd_range(-W / 2, W + W / 2) + 0.1 * i, rnd_range(-H / 2, H + H / 2),
                                 0.05 + (rnd() % 950) / 1000.0, rnd_range(-40, 40) / 96.0, rnd_range(-40, 40) / 48.0);
            }
        }
        if (k & 8) {   /* the floor's far edge on top instead */
            for (j = 0; j < 3; j++)
                tris[k][j].y = (fxl_q16_t)(H * 65536 - tris[k][j].y);
        }
    }
    for (cfg = 0; cfg < 6 * 2 * 2 * 2 * 2; cfg++) {
        const int pm = cfg % 6, depth = (cfg / 6) & 1, swap = (cfg / 12) & 1, clip = (cfg / 24) & 1;
        const int bil = cfg / 48;
        const fxl_pixfmt_t fmt = swap ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
        const fxl_rect_t cr = {5, 3, W - 7, H - 2};
        fxl_draw_defaults(&d);
        d.filter = bil ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
        d.persp = persp[pm];
        if (!keyed_twin_draws(&d, &dg, &tex, &keyed, fmt, depth))
            continue;
        for (k = 0; k < NT; k++) {
            snprintf(msg, sizeof msg, "bilinear %d persp %d depth %d swap %d clip %d triangle %d", bil, persp[pm],
                     depth, swap, clip, k);
            draw_fast_and_generic(&d, &dg, tris[k], W, H, fmt, depth, clip ? &cr : NULL, fast, zfast, gen, zgen, msg);
            compared++;
        }
    }
    snprintf(msg, sizeof msg, "%d draws compared", compared);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE(compared > 0);
}

/* The perspective modes of the keyed-twin comparisons: affine, subdivided,
 * exact and AUTO (quadratic segments) */
static const int16_t twin_persp[4] = {FXL_PERSP_AFFINE, 16, FXL_PERSP_EXACT, FXL_PERSP_AUTO};

/* A comparison's count of draws and covered pixels, reported, and checked
 * to have compared something: every draw covers over 100 pixels on average */
static void report_draws_compared(int compared, int covered)
{
    char msg[80];
    snprintf(msg, sizeof msg, "%d draws compared, %d pixels", compared, covered);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE(compared > 0);
    TEST_ASSERT_TRUE(covered > 100 * compared);
}

/* An RGB565 texture of tw x th texels (mips where built) over texels, its
 * keyed twin (test_fast_loops_match_generic_loop), and nt random triangles
 * from seed: texels a pixel from ~1/4 (even ones) to ~4 (odd ones, u and v
 * within +-far), vertex colours anywhere. */
static void twin_textures_and_triangles(uint16_t *texels, int ntex, int tw, int th, fxl_texture_t *tex,
                                        fxl_texture_t *keyed, fxl_vertex_t (*tris)[3], int nt, uint32_t seed,
                                        double far)
{
    int i, k;
    fill_unkeyed(texels, ntex);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(tex, texels, tw, th, FXL_TEXFMT_RGB565,
                                                   FXL_HAVE_MIPMAP ? 6u : 1u));
    keyed_twin_texture(tex, keyed);
    lcg_state = seed;
    for (k = 0; k < nt; k++)
        for (i = 0; i < 3; i++) {
            const double span = k % 2 ? far : 0.3;
            tris[k][i] = test_vertex(rnd_range(-W / 2, W + W / 2) + 0.1 * i, rnd_range(-H / 2, H + H / 2),
                                     0.05 + (rnd() % 950) / 1000.0, rnd_range(-span, span),
                                     rnd_range(-span, span), (uint16_t)(rnd() & 0xFFFFu));
        }
}

/* MODULATE draws of RGB565 repeat textures take their own pixel loop in
 * speed builds (span.c, seg_modulate) inside the generic walk; every pixel
 * and depth value must be seg_generic's (reached through a colour key no
 * texel has): flat and Gouraud colours, point and bilinear, no mips, the
 * nearest level and two levels blended, affine, subdivided, exact and
 * AUTO (its quadratic segments step du, dv), with depth or without, both
 * byte orders, with and without a clip rectangle. In size builds both
 * passes are seg_generic. */
void test_modulate_loop_matches_generic_loop(void)
{
    enum { NT = 16, TW = 32, TH = 16, NTEX = TW * TH * 4 / 3 + 1 };
    static uint16_t texels[NTEX], fast[W * H], gen[W * H], zfast[W * H], zgen[W * H];
    static fxl_vertex_t tris[NT][3];
    fxl_texture_t tex, keyed;
    fxl_draw_t d, dg;
    char msg[200];
    int k, cfg, compared = 0, covered = 0;
    TEST_NEEDS(FXL_HAVE_GENERIC);
    twin_textures_and_triangles(texels, NTEX, TW, TH, &tex, &keyed, tris, NT, 4242u, 4.0);
    for (cfg = 0; cfg < 4 * 2 * 2 * 2 * 2 * 3 * 2; cfg++) {
        const int pm = cfg % 4, depth = (cfg / 4) & 1, swap = (cfg / 8) & 1, clip = (cfg / 16) & 1;
        const int bil = (cfg / 32) & 1, mip = (cfg / 64) % 3, gouraud = cfg / 192;
        const fxl_pixfmt_t fmt = swap ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
        const fxl_rect_t cr = {5, 3, W - 7, H - 2};
        fxl_draw_defaults(&d);
        d.filter = bil ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
        d.persp = twin_persp[pm];
        d.mip = (uint8_t)(mip == 2 ? FXL_MIP_LINEAR : mip == 1 ? FXL_MIP_NEAREST : FXL_MIP_NONE);
        d.texenv = FXL_TEXENV_MODULATE;
        d.shade = (uint8_t)(gouraud ? FXL_SHADE_GOURAUD : FXL_SHADE_FLAT);
        /* flat white (drawn as REPLACE) on one configuration in seven
         * (7 is coprime with the 4 modes: every mode gets some) */
        d.color = cfg % 7 == 3 && !gouraud ? 0xFFFFu : 0xB5D3u;
        if (!keyed_twin_draws(&d, &dg, &tex, &keyed, fmt, depth))
            continue;
        for (k = 0; k < NT; k++) {
            snprintf(msg, sizeof msg, "bilinear %d mip %d gouraud %d persp %d depth %d swap %d clip %d triangle %d",
                     bil, mip, gouraud, twin_persp[pm], depth, swap, clip, k);
            covered += draw_fast_and_generic(&d, &dg, tris[k], W, H, fmt, depth, clip ? &cr : NULL, fast, zfast,
                                             gen, zgen, msg);
            compared++;
        }
    }
    report_draws_compared(compared, covered);
}

/* seg_generic's plain taps (RGB565 repeat textures without a key: a mask
 * and a read a tap) against its wrapped ones (fxl__wrap and
 * fxl__texel_rgb565 a tap, reached through a colour key no texel has), on
 * draws no specialised loop takes in any build: DECAL, and REPLACE with a
 * depth test that does not write. Flat and Gouraud colours, point and
 * bilinear, no mips, the nearest level and two levels blended, affine,
 * subdivided, exact and AUTO (quadratic segments), both byte orders, with
 * and without a clip rectangle. Both passes share seg_generic's values of
 * a pixel (its steps, the quadratic term): the fast-against-generic tests
 * and determinism.sh hold those. */
void test_generic_plain_taps_match_wrapped_taps(void)
{
    enum { NT = 10, TW = 32, TH = 16, NTEX = TW * TH * 4 / 3 + 1 };
    static uint16_t texels[NTEX], plain[W * H], wrapped[W * H], zplain[W * H], zwrapped[W * H];
    static fxl_vertex_t tris[NT][3];
    fxl_texture_t tex, keyed;
    fxl_draw_t d, dg;
    char msg[200];
    int k, cfg, compared = 0, covered = 0;
    TEST_NEEDS(FXL_HAVE_GENERIC);
    twin_textures_and_triangles(texels, NTEX, TW, TH, &tex, &keyed, tris, NT, 9090u, 5.0);
    for (cfg = 0; cfg < 4 * 2 * 2 * 2 * 3 * 2; cfg++) {
        const int pm = cfg % 4, swap = (cfg / 4) & 1, clip = (cfg / 8) & 1, bil = (cfg / 16) & 1;
        const int mip = (cfg / 32) % 3, decal = cfg / 96;
        const fxl_pixfmt_t fmt = swap ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
        const fxl_rect_t cr = {5, 3, W - 7, H - 2};
        fxl_draw_defaults(&d);
        d.filter = bil ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
        d.persp = twin_persp[pm];
        d.mip = (uint8_t)(mip == 2 ? FXL_MIP_LINEAR : mip == 1 ? FXL_MIP_NEAREST : FXL_MIP_NONE);
        d.texenv = decal ? FXL_TEXENV_DECAL : FXL_TEXENV_REPLACE;
        d.shade = (uint8_t)(decal ? FXL_SHADE_GOURAUD : FXL_SHADE_FLAT);
        d.depth = decal ? 0 : FXL_DEPTH_TEST;
        if (!keyed_twin_draws(&d, &dg, &tex, &keyed, fmt, !decal))
            continue;
        for (k = 0; k < NT; k++) {
            snprintf(msg, sizeof msg, "decal %d bilinear %d mip %d persp %d swap %d clip %d triangle %d", decal, bil,
                     mip, twin_persp[pm], swap, clip, k);
            covered += draw_fast_and_generic(&d, &dg, tris[k], W, H, fmt, !decal, clip ? &cr : NULL, plain, zplain,
                                             wrapped, zwrapped, msg);
            compared++;
        }
    }
    report_draws_compared(compared, covered);
}

/* The MODULATE loop's depth modes against the generic loop: test and
 * write, test only, write only, over a depth buffer filled with hashed
 * values (so the test rejects part of each triangle), each triangle drawn
 * twice with two flat colours or two colour sets, so the second draw meets
 * its own depths: ties keep the first draw. Point and bilinear, flat and
 * Gouraud, both byte orders. Every pixel and depth value must be the
 * generic loop's (a >= in place of the > of the test fails it). */
void test_modulate_depth_modes_match_generic_loop(void)
{
    enum { NT = 12, TW = 32, TH = 16, NTEX = TW * TH };
    static uint16_t texels[NTEX], px[2][W * H], zb[2][W * H];
    static const uint8_t modes[3] = {FXL_DEPTH_TEST | FXL_DEPTH_WRITE, FXL_DEPTH_TEST, FXL_DEPTH_WRITE};
    static fxl_vertex_t tris[NT][3];
    fxl_texture_t tex, keyed;
    fxl_draw_t d, dg;
    char msg[160];
    int i, k, cfg, pass, compared = 0;
    uint32_t drawn[3] = {0, 0, 0};   /* pixels drawn, by depth mode */
    TEST_NEEDS(FXL_HAVE_GENERIC && FXL_HAVE_DEPTH);
    fill_unkeyed(texels, NTEX);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, TW, TH, FXL_TEXFMT_RGB565, 1));
    keyed_twin_texture(&tex, &keyed);
    lcg_state = 777u;
    for (k = 0; k < NT; k++)
        for (i = 0; i < 3; i++)
            tris[k][i] = test_vertex(rnd_range(-W / 4, W + W / 4) + 0.1 * i, rnd_range(-H / 4, H + H / 4),
                                     0.05 + (rnd() % 950) / 1000.0, rnd_range(-3.0, 3.0), rnd_range(-3.0, 3.0),
                                     (uint16_t)(rnd() & 0xFFFFu));
    for (cfg = 0; cfg < 3 * 2 * 2 * 2; cfg++) {
        const int mode = cfg % 3, bil = (cfg / 3) & 1, gouraud = (cfg / 6) & 1, swap = cfg / 12;
        const fxl_pixfmt_t fmt = swap ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
        fxl_draw_defaults(&d);
        d.filter = bil ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
        d.mip = FXL_MIP_NONE;
        d.texenv = FXL_TEXENV_MODULATE;
        d.shade = (uint8_t)(gouraud ? FXL_SHADE_GOURAUD : FXL_SHADE_FLAT);
        d.depth = modes[mode];
        if (!keyed_twin_draws(&d, &dg, &tex, &keyed, fmt, 1))
            continue;
        for (k = 0; k < NT; k++) {
            for (pass = 0; pass < 2; pass++) {
                fxl_target_t t;
                fxl_draw_t twice[2];
                fxl_vertex_t v[3];
                int rep;
                fxl_target_init(&t, px[pass], W, H, W, fmt);
                fxl_target_clear(&t, 0xDEAD);
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zb[pass]));
                for (i = 0; i < W * H; i++)
                    zb[pass][i] = (uint16_t)(((uint32_t)i * 2654435761u) >> 16);
                twice[0] = twice[1] = pass ? dg : d;
                twice[0].color = 0xB5D3u;
                twice[1].color = 0x4A2Cu;
                for (rep = 0; rep < 2; rep++) {
                    for (i = 0; i < 3; i++) {
                        v[i] = tris[k][i];
                        if (rep)
                            v[i].color = (uint16_t)~v[i].color;   /* other Gouraud colours */
                    }
                    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &twice[rep], v, NULL));
                }
            }
            for (i = 0; i < W * H; i++) {
                if (px[0][i] != px[1][i] || zb[0][i] != zb[1][i]) {
                    snprintf(msg, sizeof msg,
                             "depth mode %d bilinear %d gouraud %d swap %d triangle %d pixel (%d,%d): %04x/%04x, "
                             "generic %04x/%04x",
                             d.depth, bil, gouraud, swap, k, i % W, i / W, px[0][i], zb[0][i], px[1][i], zb[1][i]);
                    TEST_FAIL_MESSAGE(msg);
                }
                drawn[mode] += px[1][i] != 0xDEAD;
            }
            compared++;
        }
    }
    snprintf(msg, sizeof msg, "%d draw pairs compared; pixels drawn with test and write %lu, test %lu, write %lu",
             compared, (unsigned long)drawn[0], (unsigned long)drawn[1], (unsigned long)drawn[2]);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE(compared > 0);
    /* the hashed depths hide part of every tested draw, and write-only
     * draws everything they cover */
    TEST_ASSERT_TRUE(drawn[2] > 50u * (uint32_t)compared);
    TEST_ASSERT_TRUE(drawn[0] > 0u && drawn[0] < drawn[2] && drawn[1] < drawn[2]);
}

/* Spans on one texel row (q and v constant along every row: span_fast.h's
 * FXL_T_LROW) against the generic walk, pixel, depth value and the pixels
 * the stats count: wide spans (up to 300 pixels) for many segments of
 * every length the walk takes (4 to 64; affine and AUTO with depth), u
 * magnified 8x to minified 8x in both directions, textures 256 wide and
 * 1 wide (a column of constant index), a clip rectangle cutting both ends
 * at odd pixels, and with depth an occluder drawn first, so the depth
 * test rejects part of each span (all of it where the occluder is the
 * triangle itself, at equal depths). */
void test_level_row_walk_matches_generic(void)
{
    enum { LW = 300, LH = 24, NT = 40 };
    static uint16_t tex_wide[256 * 8], tex_col[1 * 64];
    static uint16_t fast[LW * LH], gen[LW * LH], zfast[LW * LH], zgen[LW * LH];
    static uint16_t scratch[LW * LH], zscratch[LW * LH];
    static const int16_t persp[7] = {4, 8, 16, 32, 64, FXL_PERSP_AFFINE, FXL_PERSP_AUTO};
    static fxl_vertex_t tris[NT][3], occ[3];
    fxl_texture_t tex[2], keyed[2];
    fxl_draw_t d, dg, dflat;
    char msg[200];
    int i, k, cfg, compared = 0;
    uint32_t hidden = 0, drawn_z = 0;
    TEST_NEEDS(FXL_HAVE_GENERIC);
    fill_unkeyed(tex_wide, 256 * 8);
    for (i = 0; i < 64; i++)
        tex_col[i] = (uint16_t)((i * 40503u) | 0x0802u);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex[0], tex_wide, 256, 8, FXL_TEXFMT_RGB565, 1));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex[1], tex_col, 1, 64, FXL_TEXFMT_RGB565, 1));
    for (i = 0; i < 2; i++)
        keyed_twin_texture(&tex[i], &keyed[i]);
    lcg_state = 4242u;
    for (k = 0; k < NT; k++) {
        /* texels a pixel along u, either direction */
        static const double scales[5] = {0.125, 0.7, 1.0, 3.3, 8.0};
        const double scale = scales[k % 5] * ((k / 5) % 2 ? -1.0 : 1.0);
        const double x0 = rnd_range(-40, 20) + 0.37, w = rnd_range(LW / 2, LW + 60);
        const double y0 = rnd_range(-4, 4) + 0.21, q0 = 0.1 + (rnd() % 900) / 1000.0;
        const double q2 = 0.05 + (rnd() % 950) / 1000.0, u0 = rnd_range(-500, 500) / 3.0;
        const double v0 = rnd_range(-64, 64) / 7.0;
        /* u, v in texels here, in periods of the 256 x 8 texture in the vertices */
        tris[k][0] = vtx(x0, y0, q0, u0 / 256, v0 / 8);
        tris[k][1] = vtx(x0 + w, y0, q0, (u0 + scale * w) / 256, v0 / 8);
        tris[k][2] = vtx(x0 + rnd_range(0, LW), y0 + rnd_range(LH / 2, 2 * LH), q2, rnd_range(-99, 99) / 256.0,
                         (v0 + rnd_range(-30, 30)) / 8);
        if (k & 2) {   /* the far edge on top instead */
            for (i = 0; i < 3; i++)
                tris[k][i].y = (fxl_q16_t)(LH * 65536 - tris[k][i].y);
        }
    }
    /* the occluder: nearer than some of each span, farther than the rest */
    occ[0] = vtx(LW * 0.2, -5, 0.4, 0, 0);
    occ[1] = vtx(LW * 0.7, LH + 5, 0.9, 0, 0);
    occ[2] = vtx(LW * 0.1, LH + 5, 0.1, 0, 0);
    flat_draw(&dflat);
    dflat.depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
    for (cfg = 0; cfg < 7 * 2 * 2 * 2 * 3; cfg++) {
        const int pm = cfg % 7, depth = (cfg / 7) & 1, swap = (cfg / 14) & 1, clip = (cfg / 28) & 1;
        /* REPLACE, then MODULATE by a flat colour (the tinted walks with
         * FXL_FAST_TINT, else the generic one) and by white (REPLACE's) */
        const int tint = cfg / 56;
        const fxl_pixfmt_t fmt = swap ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
        const fxl_rect_t cr = {13, 1, LW - 29, LH - 1};
        fxl_draw_defaults(&d);
        d.filter = FXL_FILTER_POINT;
        d.persp = persp[pm];
        if (tint) {
            d.texenv = FXL_TEXENV_MODULATE;
            d.color = tint == 1 ? 0xB5D3u : 0xFFFFu;
        }
        if (!depth)
            d.depth = 0;
        for (k = 0; k < NT; k++) {
            fxl_stats_t st[2];
            int pass;
            d.texture = &tex[k % 7 == 3];
            dg = d;
            dg.texture = &keyed[k % 7 == 3];
            if (left_out_feature(&d, d.texture, fmt, depth) != NULL ||
                left_out_feature(&dg, dg.texture, fmt, depth) != NULL)
                break;   /* refusals: test_left_out_features_are_refused */
            /* pass 2 (with depth): without the occluder, to count what it hides */
            for (pass = 0; pass < (depth ? 3 : 2); pass++) {
                fxl_target_t tg;
                fxl_target_init(&tg, pass == 0 ? fast : pass == 1 ? gen : scratch, LW, LH, LW, fmt);
                fxl_target_clear(&tg, 0xDEAD);
                if (depth) {
                    TEST_ASSERT_EQUAL_INT(FXL_OK,
                                          fxl_target_set_depth(&tg, pass == 0 ? zfast : pass == 1 ? zgen : zscratch));
                    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_clear_depth(&tg));
                    /* every fourth triangle is its own occluder: equal depths, all rejected */
                    if (pass < 2)
                        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&tg, &dflat, k % 4 == 1 ? tris[k] : occ, NULL));
                }
                if (pass == 2) {
                    fxl_stats_t all;
                    memset(&all, 0, sizeof all);
                    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&tg, &d, tris[k], &all));
                    hidden += all.pixels - st[0].pixels;
                    break;
                }
                if (clip)
                    fxl_target_set_clip(&tg, &cr);
                memset(&st[pass], 0, sizeof st[pass]);
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&tg, pass ? &dg : &d, tris[k], &st[pass]));
            }
            snprintf(msg, sizeof msg, "persp %d depth %d swap %d clip %d tint %d triangle %d", persp[pm], depth, swap,
                     clip, tint, k);
            for (i = 0; i < LW * LH; i++) {
                if (fast[i] != gen[i] || (depth && zfast[i] != zgen[i])) {
                    char m2[260];
                    snprintf(m2, sizeof m2, "%s pixel (%d,%d): fast %04x/%04x generic %04x/%04x", msg, i % LW,
                             i / LW, fast[i], zfast[i], gen[i], zgen[i]);
                    TEST_FAIL_MESSAGE(m2);
                }
            }
            TEST_ASSERT_EQUAL_UINT32_MESSAGE(st[1].pixels, st[0].pixels, msg);
            /* the walk under test where this build has it (none at -Os) */
            TEST_ASSERT_EQUAL_UINT32_MESSAGE(FXL__FAST_SPANS && (swap ? FXL_FAST_SWAPPED : FXL_FAST_NATIVE) &&
                                                     FXL_FAST_POINT && (depth ? FXL_FAST_DEPTH : FXL_FAST_NO_DEPTH) &&
                                                     (tint != 1 || FXL_FAST_TINT)
                                                 ? 0u
                                                 : 1u,
                                             st[0].generic, msg);
            TEST_ASSERT_EQUAL_UINT32_MESSAGE(1u, st[1].generic, msg);
            if (depth)
                drawn_z += st[0].pixels;
            compared++;
        }
    }
    snprintf(msg, sizeof msg, "%d draws compared; with depth %lu pixels drawn, %lu hidden by the occluder", compared,
             (unsigned long)drawn_z, (unsigned long)hidden);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE(compared > 0);
    if (FXL_HAVE_DEPTH)
        TEST_ASSERT_TRUE_MESSAGE(hidden > drawn_z / 8 && drawn_z > hidden / 8, msg);
}

/* The walk along rows of constant q declines a span whose correction points
 * fall outside the range its one shift serves (span_fast.h: FXL_T_ROWC
 * returns 0, having drawn nothing) and the lean walk draws it. These
 * triangles reach that path: their constant-q row is the top edge at a depth
 * 10^7 to 10^9 times the far vertex's. Found by a counter at the decline (one
 * declined span each; 10 in 905,475 random triangles with inv_w from 1 to
 * 2^32, not a hook the core keeps). Every variant this build has must draw
 * them as the generic walk does, pixel and depth value. */
void test_row_const_walk_declined_spans_match_generic(void)
{
    static const struct {
        int lw, lh, persp;
        fxl_vertex_t v[3];
    } cases[] = {
        {1, 6, 8, {{-18234151, 4161680, 1u, -20068, 13380, 0}, {41418381, 4161680, 1u, -1967, 1880, 0},
                   {-8073391, 20421899, 2427099573u, 41643550, 125737166, 0}}},
        {8, 0, 32, {{16450791, 1538371, 10u, -93852118, -33495858, 0}, {40452838, 1538371, 10u, 603, -680, 0},
                    {31608853, 29299344, 1503346949u, 13792, -50012, 0}}},
        {0, 6, 8, {{11329030, 4292931, 1u, 53712755, 38584277, 0}, {-20480963, 4292931, 1u, 150849701, -127605684, 0},
                   {3923511, 15621026, 1047668216u, 6363, 527, 0}}},
        {7, 3, 2, {{23001737, 10320867, 1u, -14571, 15185, 0}, {13558078, 10320867, 1u, -210953, 332201, 0},
                   {22872887, 17399910, 1614403555u, -188060404, 434582704, 0}}},
        {0, 6, 32, {{25298293, 7505729, 3u, -150071480, -177734709, 0}, {14370928, 7505729, 3u, 111178714, 49210177, 0},
                    {2795368, 9833081, 2495497870u, -2942840, -2737389, 0}}},
        {7, 6, 2, {{12305331, 7241505, 8u, 16609, 20035, 0}, {-13344837, 7241505, 8u, 1402396, 3085048, 0},
                   {-11233403, 13903103, 2328082652u, 83092818, -33924347, 0}}},
        {6, 4, 16, {{22944126, 5146317, 2u, 10315, 15004, 0}, {-14310357, 5146317, 2u, 314, -1353, 0},
                    {1871132, 27055329, 2348976272u, -109915722, 167258605, 0}}},
        {5, 7, 4, {{8273458, 490186, 45u, 153359, 205229, 0}, {5964771, 490186, 45u, 4375, -4017, 0},
                   {30763603, 29068120, 3562605630u, -160688530, 251450062, 0}}},
        {3, 8, 8, {{12053965, 5012194, 1u, 76409651, -64979740, 0}, {15662811, 5012194, 1u, 1140197, 166365, 0},
                   {38941787, 18733808, 3128880183u, -1632, -2801, 0}}},
        {5, 4, 16, {{6724783, 12549340, 1u, -8622659, -15753782, 0}, {35115516, 12549340, 1u, 5183, -8243, 0},
                    {-13799652, 30909720, 4123818727u, 38976848, -20599080, 0}}},
    };
    static uint16_t texels[256 * 256];
    enum { FW = 320, FH = 240 };   /* the frame they were found in */
    static uint16_t fast[FW * FH], gen[FW * FH], zfast[FW * FH], zgen[FW * FH];
    char msg[160];
    size_t c;
    int i, cfg, drawn = 0, refused = 0;
    for (i = 0; i < 256 * 256; i++)
        texels[i] = (uint16_t)(i * 2654435761u >> 16);
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++)
        for (cfg = 0; cfg < 8; cfg++) {
            const int bil = cfg & 1, depth = (cfg >> 1) & 1, swap = cfg >> 2;
            const fxl_pixfmt_t fmt = swap ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
            int covered;
            fxl_texture_t tex;
            fxl_draw_t d;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 1u << cases[c].lw, 1u << cases[c].lh,
                                                           FXL_TEXFMT_RGB565, 1));
            fxl_draw_defaults(&d);
            d.texture = &tex;
            d.persp = (int16_t)cases[c].persp;
            d.filter = bil ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
            if (!depth)
                d.depth = 0;
            if (left_out_feature(&d, &tex, fmt, depth) != NULL) {
                refused++;   /* checked by test_left_out_features_are_refused */
                continue;
            }
            snprintf(msg, sizeof msg, "case %d bilinear %d depth %d swap %d", (int)c, bil, depth, swap);
            covered = draw_fast_and_generic(&d, NULL, cases[c].v, FW, FH, fmt, depth, NULL, fast, zfast, gen, zgen, msg);
            snprintf(msg, sizeof msg, "case %d draws nothing", (int)c);
            TEST_ASSERT_TRUE_MESSAGE(covered > 0, msg);
            drawn++;
        }
    snprintf(msg, sizeof msg, "%d draws equal to the generic walk's, %d need features this build lacks", drawn,
             refused);
    TEST_MESSAGE(msg);
    if (FXL_HAVE_GENERIC && FXL_HAVE_BILINEAR && FXL_HAVE_DEPTH)
        TEST_ASSERT_EQUAL_INT(80, drawn);
}

/* The walk along rows of constant q steps z too: q's plane is flat along
 * x, z's need not be, where vertices of inv_w 2^31 or more are halved
 * into q (inv_w 2k and 2k + 1 give one q, so a top edge of one q has z
 * rising a unit). A first segment that starts left of the clip must
 * advance z by its steps to the first pixel drawn, as the generic walk
 * does; without it (a mutation run left that step out alive) a span's last
 * two pixels, one segment clipped to the second, stored the first one's
 * depth where inv_w crosses a multiple of 2^16 between them. Found by a
 * search over such triangles (inv_w within a few units of m 2^16, the clip
 * at a row's last pixel where the generic walk's stored depth changes
 * there; 1,070 of 20,000 random ones qualified, every one of them drew
 * the wrong depth with the step left out). Every variant with depth this
 * build has must draw them as the generic walk does. */
void test_row_const_walk_clipped_first_segment_steps_depth(void)
{
    static const struct {
        int persp;
        fxl_rect_t clip;
        fxl_vertex_t v[3];
    } cases[] = {
        {8, {59, 35, 160, 36}, {{5953970, 2646571, 2751201276u, 28913, 25912, 0}, {4689863, 2646571, 2751201277u, 64278, 4854, 0},
                               {1839718, 1993980, 2751201284u, 15232, 29612, 0}}},
        {4, {75, 71, 160, 72}, {{5055776, 4458170, 2275999744u, 11212, 19730, 0}, {5247276, 4458170, 2275999745u, 12587, 19512, 0},
                               {2654102, 6801260, 2275999740u, 9666, 6842, 0}}},
        {2, {23, 69, 160, 70}, {{1194822, 3168449, 3389784062u, 2444, 46155, 0}, {823649, 3168449, 3389784063u, 21522, 41012, 0},
                               {2417779, 7691328, 3389784068u, 54651, 47899, 0}}},
    };
    enum { FW = 160, FH = 120 };   /* the frame they were found in */
    static uint16_t texels[64 * 64], fast[FW * FH], gen[FW * FH], zfast[FW * FH], zgen[FW * FH];
    char msg[160];
    size_t c;
    int i, cfg, covered, drawn = 0;
    for (i = 0; i < 64 * 64; i++)
        texels[i] = (uint16_t)(i * 2654435761u >> 16);
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++)
        for (cfg = 0; cfg < 4; cfg++) {
            const int bil = cfg & 1, swap = cfg >> 1;
            const fxl_pixfmt_t fmt = swap ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
            fxl_texture_t tex;
            fxl_draw_t d;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 64, 64, FXL_TEXFMT_RGB565, 1));
            fxl_draw_defaults(&d);
            d.texture = &tex;
            d.persp = (int16_t)cases[c].persp;
            d.filter = bil ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
            if (left_out_feature(&d, &tex, fmt, 1) != NULL)
                continue;   /* refusals: test_left_out_features_are_refused */
            snprintf(msg, sizeof msg, "case %d bilinear %d swap %d", (int)c, bil, swap);
            covered = draw_fast_and_generic(&d, NULL, cases[c].v, FW, FH, fmt, 1, &cases[c].clip, fast, zfast, gen,
                                            zgen, msg);
            /* found on the 1/16 px grid: on another one the clipped row may
             * hold no pixel (the comparison holds all the same) */
            snprintf(msg, sizeof msg, "case %d draws nothing", (int)c);
            TEST_ASSERT_TRUE_MESSAGE(covered > 0 || !FXL_TEST_DEFAULT_GRID, msg);
            drawn++;
        }
    test_needs_draw(drawn ? NULL : "FXL_HAVE_DEPTH (textured draws with depth)");
}

/* The one-texel-row walk (FXL_T_LROW) runs whole segments only up to the
 * span's last pixel, which ends the last segment (span_fast.h: the bound
 * min(cr, xr - 1)), as the generic walk does. Ending a run on the
 * correction point one past the last pixel instead gives the same line of
 * u with other truncations, so it shows only where a step's rounding moves
 * a pixel across a texel boundary: this triangle (found by a search over
 * random ones) has such a pixel inside a clip of x 13 to 124. One inv_w
 * on every vertex (q constant) and v 0.5, subdiv 4, point; every variant
 * this build has must draw it as the generic walk does. */
void test_level_row_walk_ends_whole_segments_before_the_last_pixel(void)
{
    enum { LW = 128, LH = 64 };
    static uint16_t fast[LW * LH], gen[LW * LH], zfast[LW * LH], zgen[LW * LH];
    static const fxl_rect_t clip = {13, 0, 124, LH};
    fxl_vertex_t v[3];
    fxl_texture_t tex;
    fxl_draw_t d;
    char msg[120];
    int k, cfg, drawn = 0;
    static const int32_t xyu[3][3] = {{0x0045a95a, 0x0034493c, 0x0006a333},
                                      {0x004d4f34, 0x000350a9, 0x00058d61},
                                      {0x003d7881, -0x0000c34c, -0x00082dfe}};
    TEST_NEEDS(FXL_HAVE_GENERIC);
    make_texture(&tex);
    memset(v, 0, sizeof v);
    for (k = 0; k < 3; k++) {
        v[k].x = xyu[k][0];
        v[k].y = xyu[k][1];
        v[k].u = xyu[k][2];
        v[k].v = 32768;
        v[k].inv_w = 0x40019097u;
        v[k].color = 0xFFFF;
    }
    for (cfg = 0; cfg < 4; cfg++) {
        const int depth = cfg & 1, swap = cfg >> 1;
        const fxl_pixfmt_t fmt = swap ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
        fxl_draw_defaults(&d);
        d.texture = &tex;
        d.persp = 4;
        d.filter = FXL_FILTER_POINT;
        if (!depth)
            d.depth = 0;
        if (left_out_feature(&d, &tex, fmt, depth) != NULL)
            continue;
        snprintf(msg, sizeof msg, "depth %d swap %d", depth, swap);
        TEST_ASSERT_TRUE_MESSAGE(draw_fast_and_generic(&d, NULL, v, LW, LH, fmt, depth, &clip, fast, zfast, gen, zgen, msg) > 0,
                                 msg);
        drawn++;
    }
    TEST_ASSERT_TRUE(drawn > 0);
}

/* ---- which walk drew a triangle (fxl_stats_t.generic) ------------------------- */

/* A triangle drawn with the given target format, depth buffer and texture
 * settings, where fast says whether this build has specialised code for
 * it. Checks drawn and stats.generic; a draw without specialised code in a
 * build without the generic walk must be FXL_ERR_UNSUPPORTED instead. */
static void check_walk(fxl_pixfmt_t fmt, int with_depth, fxl_filter_t filter, fxl_wrap_t wrap, int mip_linear,
                       int fast)
{
    static uint16_t zbuf[W * H];
    static uint16_t chain[64 * 64 * 4 / 3 + 1];   /* 64x64 RGB565 with all 7 levels */
    fxl_target_t t;
    fxl_draw_t d;
    fxl_texture_t tex;
    fxl_vertex_t v[3];
    fxl_stats_t st;
    fxl_status_t status;
    memset(&st, 0, sizeof st);
    v[0] = vtx(1, 1, 0.5, 0, 0);
    v[1] = vtx(40, 3, 0.25, 9, 0);
    v[2] = vtx(5, 40, 0.75, 0, 7);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, pix, W, H, W, fmt));
    if (with_depth) {
        fxl_target_set_depth(&t, zbuf);
        fxl_target_clear_depth(&t);
    }
    make_texture(&tex);
    fxl_draw_defaults(&d);
    if (mip_linear) {
        /* the same level 0 with its chain: two levels blended a pixel */
        TEST_ASSERT_TRUE(fxl_mip_size(64, 64, FXL_TEXFMT_RGB565, 7) <= sizeof chain);
        memcpy(chain, tex_data, 64 * 64 * sizeof(uint16_t));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build(chain, (uint32_t)sizeof chain, 64, 64, FXL_TEXFMT_RGB565, 7, NULL,
                                                    FXL_MIP_SPACE_STORED));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, chain, 64, 64, FXL_TEXFMT_RGB565, 7));
        d.mip = FXL_MIP_LINEAR;
    }
    tex.wrap_u = (uint8_t)wrap;
    d.texture = &tex;
    d.filter = (uint8_t)filter;
    status = fxl_draw_triangle(&t, &d, v, &st);
    if (!fast && !FXL_HAVE_GENERIC) {
        TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, status);
        return;
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, status);
    TEST_ASSERT_EQUAL_UINT32(1, st.drawn);
    TEST_ASSERT_TRUE(st.pixels > 0);
    TEST_ASSERT_EQUAL_UINT32(fast ? 0u : 1u, st.generic);
}

void test_stats_count_generic_draws(void)
{
    /* The kinds of draw with specialised code in this build (config.h,
     * FXL_FAST_*; none at -Os) count 0, everything else 1. */
    const int nat = FXL__FAST_SPANS && FXL_FAST_NATIVE, swp = FXL__FAST_SPANS && FXL_FAST_SWAPPED;
    const int pt = FXL_FAST_POINT, bl = FXL_HAVE_BILINEAR && FXL_FAST_BILINEAR;
    const int noz = FXL_FAST_NO_DEPTH, z = FXL_HAVE_DEPTH && FXL_FAST_DEPTH;
    check_walk(FXL_PIXFMT_RGB565, 0, FXL_FILTER_POINT, FXL_WRAP_REPEAT, 0, nat && pt && noz);
    check_walk(FXL_PIXFMT_RGB565_SWAP, 0, FXL_FILTER_POINT, FXL_WRAP_REPEAT, 0, swp && pt && noz);
#if FXL_HAVE_DEPTH
    check_walk(FXL_PIXFMT_RGB565, 1, FXL_FILTER_POINT, FXL_WRAP_REPEAT, 0, nat && pt && z);
#else
    (void)z;
#endif
#if FXL_HAVE_BILINEAR
    check_walk(FXL_PIXFMT_RGB565_SWAP, 0, FXL_FILTER_BILINEAR, FXL_WRAP_REPEAT, 0, swp && bl && noz);
#if FXL_HAVE_MIPMAP
    /* trilinear: the two-level variants (FXL_FAST_MIP) */
    check_walk(FXL_PIXFMT_RGB565, 0, FXL_FILTER_BILINEAR, FXL_WRAP_REPEAT, 1, nat && bl && noz && FXL_FAST_MIP);
#endif
#else
    (void)bl;
#endif
    /* clamp has no specialised walk anywhere */
    check_walk(FXL_PIXFMT_RGB565, 0, FXL_FILTER_POINT, FXL_WRAP_CLAMP, 0, 0);
}

/* fxl_stats_t.divisions in the fixed-length modes: the correction points
 * of each clipped span [cl, cr) of a span [xl, xr), counted once each.
 * Segments of N = 2^k pixels (affine: FXL_PERSP_MAX) start at x0 = xl +
 * N floor((cl - xl) / N), the first that reaches the clip, and the last
 * one ends on the span's last pixel xr - 1: 1 + ceil((cr - x0) / N)
 * points. A last segment of one pixel (it starts on xr - 1, and the span
 * reaches cr = xr) ends where it starts: every walk these one-level draws
 * take counts that point once (the generic walk divided there twice until
 * it took the segment's start as its end; in exact mode every span's last
 * segment is one pixel; the batch walk of mipmapped draws, not drawn here,
 * still divides there twice and counts it once, raster.h, which
 * test_divisions_match_between_walks holds it to). In exact mode a clip's
 * right edge cr < xr ends the span the same way: its last pixel's
 * segment needs no end past cr, so exact mode counts one point a drawn
 * pixel in every walk (the generic walk divided at cr too until it did
 * what exact mode's runs do). The spans come from the same triangle drawn
 * unclipped; half the triangles have a top edge of one depth (the walk
 * along rows of constant q). A mutation run left the counts unguarded:
 * the generic walk counting from xl (the segments left of the clip too),
 * the lean walk counting floor + 1 segments and the constant-q row walk
 * counting the one-pixel end twice all survived. A third of the triangles
 * are lit (Gouraud MODULATE), which speed builds draw with the generic
 * walk's own copy (draw_span_mod). AUTO and mip levels: the next test. */
static uint32_t expected_divisions(const uint16_t *full, int32_t w, const fxl_rect_t *c, int k)
{
    const int32_t N = (int32_t)1 << k;
    uint32_t n = 0;
    int32_t x, y;
    for (y = c->y0; y < c->y1; y++) {
        int32_t xl = -1, xr = -1, cl, cr, x0;
        for (x = 0; x < w; x++)
            if (full[y * w + x] != 0xDEAD) {
                if (xl < 0)
                    xl = x;
                xr = x + 1;
            }
        cl = xl > c->x0 ? xl : c->x0;
        cr = xr < c->x1 ? xr : c->x1;
        if (xl < 0 || cl >= cr)
            continue;   /* no span, or none left by the clip: no walk */
        x0 = xl + ((cl - xl) >> k << k);
        n += 1u + (uint32_t)((cr - x0 + N - 1) >> k);
        if ((cr == xr || k == 0) && ((cr - 1 - x0) & (N - 1)) == 0)
            n--;
    }
    return n;
}

void test_divisions_count_each_correction_point_once(void)
{
    enum { TW = 200, TH = 150, NT = 400 };
    static uint16_t texels[64 * 64], full[TW * TH], buf[TW * TH], zbuf[TW * TH];
    static const int16_t persp[7] = {FXL_PERSP_AFFINE, FXL_PERSP_EXACT, 2, 4, 16, 32, 256};
    static const int log2_len[7] = {8, 0, 1, 2, 4, 5, 8};
    fxl_texture_t tex, keyed;
    fxl_target_t t;
    char msg[200];
    int n, drawable = 0, checked = 0;
    TEST_NEEDS(FXL_HAVE_GENERIC);   /* the spans come from a keyed draw */
    fill_unkeyed(texels, 64 * 64);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 64, 64, FXL_TEXFMT_RGB565, 1));
    keyed_twin_texture(&tex, &keyed);
    lcg_state = 6061u;
    for (n = 0; n < NT; n++) {
        const int pm = n % 7, depth = (n / 7) & 1;
        fxl_rect_t c = {0, 0, TW, TH};
        fxl_vertex_t v[3];
        fxl_draw_t d, dg;
        int i, pass;
        for (i = 0; i < 3; i++)
            v[i] = vtx(rnd() % (TW * 100u) / 100.0, rnd() % (TH * 100u) / 100.0, 0.01 + rnd() % 1000 / 1000.0,
                       rnd() % 5000 / 1000.0, rnd() % 5000 / 1000.0);
        if (n & 16) {   /* a top or bottom edge of one depth */
            v[1].y = v[0].y;
            v[1].inv_w = v[0].inv_w;
        }
        if (n % 4 != 3) {   /* a clip rectangle of any size inside the target */
            c.x0 = (int32_t)(rnd() % (TW / 2));
            c.y0 = (int32_t)(rnd() % (TH / 2));
            c.x1 = c.x0 + 1 + (int32_t)(rnd() % (uint32_t)(TW - c.x0));
            c.y1 = c.y0 + 1 + (int32_t)(rnd() % (uint32_t)(TH - c.y0));
        }
        fxl_draw_defaults(&d);
        d.persp = persp[pm];
        d.filter = (n / 14) & 1 ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
        if (n % 3 == 2) {   /* lit: speed builds draw it with the walk's Gouraud copy */
            d.shade = FXL_SHADE_GOURAUD;
            d.texenv = FXL_TEXENV_MODULATE;
            for (i = 0; i < 3; i++)
                v[i].color = (uint16_t)(0x3A5Bu * (uint32_t)(i + 1) + (uint32_t)n);
        }
        if (!keyed_twin_draws(&d, &dg, &tex, &keyed, FXL_PIXFMT_RGB565, depth))
            continue;   /* refusals: test_left_out_features_are_refused */
        drawable++;
        fxl_target_init(&t, full, TW, TH, TW, FXL_PIXFMT_RGB565);
        fxl_target_clear(&t, 0xDEAD);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &dg, v, NULL));
        for (pass = 0; pass < 2; pass++) {
            fxl_stats_t st;
            uint32_t want;
            memset(&st, 0, sizeof st);
            fxl_target_init(&t, buf, TW, TH, TW, FXL_PIXFMT_RGB565);
            fxl_target_clear(&t, 0xDEAD);
            if (depth) {
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zbuf));
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_clear_depth(&t));
            }
            fxl_target_set_clip(&t, &c);
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, pass ? &dg : &d, v, &st));
            if (st.drawn == 0)
                continue;
            want = expected_divisions(full, TW, &c, log2_len[pm]);
            snprintf(msg, sizeof msg, "triangle %d persp %d depth %d clip (%d,%d)-(%d,%d), %s walk: %u divisions, want %u",
                     n, d.persp, depth, (int)c.x0, (int)c.y0, (int)c.x1, (int)c.y1,
                     st.generic ? "generic" : "specialised", (unsigned)st.divisions, (unsigned)want);
            TEST_ASSERT_EQUAL_UINT32_MESSAGE(want, st.divisions, msg);
            checked++;
        }
    }
    /* two draws a triangle; some miss the clip, and exact mode's
     * specialised draws are not counted: still most */
    snprintf(msg, sizeof msg, "%d draws' divisions checked, of %d triangles this build draws", checked, drawable);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE_MESSAGE(drawable > 0 && checked > drawable, msg);
}

/* Every walk counts the same points (raster.h), so each draw's count is
 * held to the generic walk's (its keyed twin): AUTO, whose lengths depend
 * on the triangle; the batch walk of mipmapped draws (speed builds), which
 * divides at a one-pixel end twice; the fixed modes with mip levels.
 * Depth ratios up to 2^30 and up to 8 periods make segments of every
 * length, one pixel too, and the clip rectangles put them at its right
 * edge, where the generic walk divided once more than exact mode's runs
 * until it took such a one-pixel segment as a last one, and the batch walk
 * counted its one-pixel ends twice. Without specialised walks (-Os) both
 * draws are generic; there the sum of the counts, held to the speed
 * build's (FXL_TEST_DIVISIONS_TOTAL), is what checks them. */
#define FXL_TEST_DIVISIONS_TOTAL 180670u
void test_divisions_match_between_walks(void)
{
    enum { TW = 200, TH = 150, NT = 900 };
    static uint16_t chain[64 * 64 * 2], buf[TW * TH], zbuf[TW * TH];
    static const int16_t persp[5] = {FXL_PERSP_AUTO, FXL_PERSP_EXACT, 16, FXL_PERSP_AFFINE, 2};
    fxl_texture_t tex, keyed;
    fxl_target_t t;
    char msg[200];
    int n, drawable = 0, compared = 0, specialised = 0;
    uint32_t total = 0;
    TEST_NEEDS(FXL_HAVE_GENERIC);
    fill_unkeyed(chain, 64 * 64);
#if FXL_HAVE_MIPMAP
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build(chain, (uint32_t)sizeof chain, 64, 64, FXL_TEXFMT_RGB565, 7, NULL,
                                                FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, chain, 64, 64, FXL_TEXFMT_RGB565, 7));
#else
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, chain, 64, 64, FXL_TEXFMT_RGB565, 1));
#endif
    keyed_twin_texture(&tex, &keyed);
    lcg_state = 7919u;
    for (n = 0; n < NT; n++) {
        const int depth = n & 1;
        fxl_rect_t c;
        fxl_vertex_t v[3];
        fxl_draw_t d, dg;
        fxl_stats_t st[2];
        int i, pass;
        for (i = 0; i < 3; i++) {
            /* one rnd() a declarator, in order: the sum below is a golden
             * value, and C leaves the order of calls in one expression
             * (function arguments too) open */
            const uint32_t rx = rnd(), ry = rnd(), ru = rnd(), rv = rnd(), rs = rnd(), rw = rnd();
            v[i] = vtx(rx % (TW * 100u) / 100.0, ry % (TH * 100u) / 100.0, 1.0, ru % 16000 / 1000.0 - 8.0,
                       rv % 16000 / 1000.0 - 8.0);
            v[i].inv_w = 1u + rw % (1u << (7u + rs % 24u));
        }
        c.x0 = (int32_t)(rnd() % (TW / 2));
        c.y0 = (int32_t)(rnd() % (TH / 2));
        c.x1 = c.x0 + 1 + (int32_t)(rnd() % (uint32_t)(TW - c.x0));
        c.y1 = c.y0 + 1 + (int32_t)(rnd() % (uint32_t)(TH - c.y0));
        fxl_draw_defaults(&d);
        d.persp = persp[(n / 2) % 5];
        d.filter = (n / 10) & 1 ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
        d.mip = (uint8_t)((n / 20) % 3);   /* none, nearest, linear */
        if (!keyed_twin_draws(&d, &dg, &tex, &keyed, FXL_PIXFMT_RGB565, depth))
            continue;   /* refusals: test_left_out_features_are_refused */
        drawable++;
        for (pass = 0; pass < 2; pass++) {
            memset(&st[pass], 0, sizeof st[pass]);
            fxl_target_init(&t, buf, TW, TH, TW, FXL_PIXFMT_RGB565);
            if (depth) {
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zbuf));
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_clear_depth(&t));
            }
            fxl_target_set_clip(&t, &c);
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, pass ? &dg : &d, v, &st[pass]));
        }
        if (st[0].spans == 0)
            continue;
        snprintf(msg, sizeof msg, "triangle %d persp %d mip %d depth %d clip (%d,%d)-(%d,%d): %u, generic walk %u", n,
                 d.persp, d.mip, depth, (int)c.x0, (int)c.y0, (int)c.x1, (int)c.y1, (unsigned)st[0].divisions,
                 (unsigned)st[1].divisions);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(st[0].spans, st[1].spans, msg);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(st[0].divisions, st[1].divisions, msg);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(st[1].drawn, st[1].generic, msg);   /* the twin is generic */
        total += st[0].divisions;
        compared++;
        specialised += !st[0].generic;
    }
    snprintf(msg, sizeof msg, "%d draws compared, %d of them specialised, of %d this build draws", compared,
             specialised, drawable);
    TEST_MESSAGE(msg);
    /* most triangles reach the clip rectangle */
    TEST_ASSERT_TRUE_MESSAGE(drawable > 0 && compared > drawable / 2, msg);
    /* Where every draw is made (every feature, the 1/16 px grid) the
     * counts' sum is the speed build's: a size build compares the generic
     * walk with itself, and this holds its AUTO draws to that build. */
    if (drawable == NT && FXL_TEST_DEFAULT_GRID)
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(FXL_TEST_DIVISIONS_TOTAL, total, msg);
}

/* ---- errors ------------------------------------------------------------------ */

void test_draw_api_errors(void)
{
    fxl_target_t t;
    fxl_draw_t d;
    fxl_texture_t tex;
    fxl_vertex_t v[3];
    fxl_stats_t st;
    /* the draw each check starts from: untextured, or without
     * FXL_HAVE_GENERIC (no untextured draws) an RGB565 repeat texture */
    const fxl_texture_t *base = flat_white_texture();
    memset(&st, 0, sizeof st);
    v[0] = vtx(1, 1, 0.5, 0, 0);
    v[1] = vtx(20, 2, 0.5, 1, 0);
    v[2] = vtx(3, 20, 0.5, 0, 1);
    fxl_target_init(&t, pix, W, H, W, drawable_rgb565());
    fxl_draw_defaults(&d);
    d.texture = base;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_draw_triangle(NULL, &d, v, NULL));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_draw_triangle(&t, NULL, v, NULL));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_draw_triangle(&t, &d, NULL, NULL));
    d.persp = 12;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_draw_triangle(&t, &d, v, NULL));
    d.persp = 512;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_draw_triangle(&t, &d, v, NULL));
    d.persp = FXL_PERSP_AUTO;
    d.auto_budget = 0;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_draw_triangle(&t, &d, v, NULL));
    fxl_draw_defaults(&d);
    d.texture = base;
    d.filter = 7;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_draw_triangle(&t, &d, v, NULL));
    fxl_draw_defaults(&d);
    d.texture = base;
    d.texenv = 9;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_draw_triangle(&t, &d, v, NULL));
    /* One past the last value of each mode is refused too (a limit
     * compared with > instead of >= would take it). */
    {
        int field;
        for (field = 0; field < 5; field++) {
            fxl_draw_defaults(&d);
            d.texture = base;
            if (field == 0)
                d.texenv = FXL_TEXENV_DECAL + 1;
            else if (field == 1)
                d.filter = FXL_FILTER_BILINEAR + 1;
            else if (field == 2)
                d.mip = FXL_MIP_LINEAR + 1;
            else if (field == 3)
                d.lod = FXL_LOD_TRIANGLE + 1;
            else
                d.shade = FXL_SHADE_GOURAUD + 1;
            TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_ARG, fxl_draw_triangle(&t, &d, v, NULL), "one past a mode");
        }
    }
    fxl_draw_defaults(&d);
    d.texture = base;
    v[1].inv_w = 0;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_draw_triangle(&t, &d, v, NULL));
    v[1].inv_w = 5;
    /* A texture descriptor edited into nonsense is refused, not read. */
    make_texture(&tex);
    tex.log2_w = 30;
    d.texture = &tex;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_draw_triangle(&t, &d, v, NULL));
    d.texture = base;
    fxl_draw_defaults(&d);
    d.texture = base;
    d.lod = 2;   /* no such LOD mode */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_draw_triangle(&t, &d, v, NULL));
    fxl_draw_defaults(&d);
    d.texture = base;
    /* A clip rectangle edited to exceed the buffer is refused, on every
     * side, before any pixel: the triangle covers the whole target and
     * beyond, and the row after the buffer is a canary. */
    {
        static uint16_t guarded[W * (H + 1)];
        const fxl_vertex_t big[3] = {vtx(-40, -40, 0.5, 0, 0), vtx(4 * W, -40, 0.5, 1, 0),
                                     vtx(-40, 4 * H, 0.5, 0, 1)};
        int side, k;
        for (side = 0; side < 6; side++) {
            for (k = 0; k < W * (H + 1); k++)
                guarded[k] = 0x5A5Au;
            fxl_target_init(&t, guarded, W, H, W, drawable_rgb565());
            if (side == 0)
                t.clip.x0 = -1;
            else if (side == 1)
                t.clip.y0 = -1;
            else if (side == 2)
                t.clip.x1 = W + 1;
            else if (side == 3)
                t.clip.y1 = H + 1;
            else if (side == 4)
                t.stride = FXL_TARGET_MAX_DIM * 4 + 1;   /* past the documented limit */
            else
                t.stride = W - 1;   /* rows would overlap */
            TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_ARG, fxl_draw_triangle(&t, &d, big, NULL), "edited target");
            for (k = 0; k < W * (H + 1); k++)
                TEST_ASSERT_EQUAL_HEX16(0x5A5Au, guarded[k]);
        }
    }
    fxl_target_init(&t, pix, W, H, W, drawable_rgb565());
    t.pixels = NULL;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_draw_triangle(&t, &d, v, NULL));
    /* Pixel or depth pointers edited to an odd address: every uint16_t
     * store would be misaligned (a HardFault on a Cortex-M0+); refused
     * like fxl_target_init refuses them, before any pixel. */
    {
        static uint16_t words[W * H + 1];
        uint16_t *odd = (uint16_t *)(void *)((unsigned char *)words + 1);
        int k;
        for (k = 0; k < W * H + 1; k++)
            words[k] = 0x5A5Au;
        fxl_target_init(&t, pix, W, H, W, drawable_rgb565());
        t.pixels = odd;
        TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_ARG, fxl_draw_check(&t, &d), "odd pixels");
        TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_ARG, fxl_draw_triangle(&t, &d, v, NULL), "odd pixels");
        fxl_target_init(&t, pix, W, H, W, drawable_rgb565());
        t.depth = odd;
        TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_ARG, fxl_draw_triangle(&t, &d, v, NULL), "odd depth");
        for (k = 0; k < W * H + 1; k++)
            TEST_ASSERT_EQUAL_HEX16(0x5A5Au, words[k]);
    }
    fxl_target_init(&t, pix, W, H, W, drawable_rgb565());
    /* Degenerate and off-target triangles are culled and counted. */
    v[2] = v[1];
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, &st));
    TEST_ASSERT_EQUAL_UINT32(1, st.culled_degenerate);
    v[0] = vtx(-50, -50, 0.5, 0, 0);
    v[1] = vtx(-10, -50, 0.5, 0, 0);
    v[2] = vtx(-30, -5, 0.5, 0, 0);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, &st));
    TEST_ASSERT_EQUAL_UINT32(1, st.culled_outside);
    TEST_ASSERT_EQUAL_UINT32(2, st.triangles);
    TEST_ASSERT_EQUAL_UINT32(0, st.pixels);
    /* Indexed draws refuse out-of-range indices, the first one past the
     * array included. */
    {
        static const uint16_t idx[3] = {0, 1, 7}, idx3[3] = {0, 1, 3};
        TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_draw_indexed(&t, &d, v, 3, idx, 1, NULL));
        TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_draw_indexed(&t, &d, v, 3, idx3, 1, NULL));
        TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_draw_indexed(&t, &d, v, 3, NULL, 1, NULL));
    }
    /* A triangle whose rightmost vertex is exactly on the clip's left edge
     * covers no pixel centre inside it: culled as outside, not drawn. */
    memset(&st, 0, sizeof st);
    t.clip.x0 = 10;
    v[0] = vtx(0, 0, 0.5, 0, 0);
    v[1] = vtx(10, 0, 0.5, 1, 0);
    v[2] = vtx(0, 10, 0.5, 0, 1);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, &st));
    TEST_ASSERT_EQUAL_UINT32(1, st.culled_outside);
    TEST_ASSERT_EQUAL_UINT32(0, st.drawn);
}

/* The core's depth rule (not only the reference renderer's): a pixel is
 * drawn where the new depth is greater (nearer) than the stored one, so
 * of two draws at one depth the first stays. A quad at one inv_w drawn
 * twice with two textures keeps the first everywhere, and its depth; a
 * nearer third draw replaces both. Point and bilinear on subdivided,
 * exact and adaptive walks, and a Gouraud draw (the generic walk). */
void test_depth_ties_keep_the_first_draw_in_every_walk(void)
{
    static uint16_t px[W * H], zb[W * H], first[W * H], zfirst[W * H], tex_a[64 * 64], tex_b[64 * 64];
    static const int16_t persp[3] = {16, FXL_PERSP_EXACT, FXL_PERSP_AUTO};
    fxl_texture_t ta, tb;
    fxl_target_t t;
    fxl_draw_t d;
    fxl_vertex_t q[4], t0[3], t1[3];
    int i, m, f, pass, drawn = 0;
    char msg[80];
    TEST_NEEDS(FXL_HAVE_DEPTH);
    for (i = 0; i < 64 * 64; i++) {
        tex_a[i] = (uint16_t)(0x0841u * (uint32_t)(i & 31));
        tex_b[i] = (uint16_t)~tex_a[i];
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&ta, tex_a, 64, 64, FXL_TEXFMT_RGB565, 1));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tb, tex_b, 64, 64, FXL_TEXFMT_RGB565, 1));
    for (m = 0; m < 4; m++)
        for (f = 0; f < 2; f++) {
            const double w0 = 0.4;
            fxl_draw_defaults(&d);
            d.depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
            d.filter = (uint8_t)f;
            if (m == 3) {
                if (f || !FXL_HAVE_GENERIC)
                    continue;
                d.shade = FXL_SHADE_GOURAUD;   /* untextured: the generic walk */
            } else {
                d.persp = persp[m];
                if ((f && !FXL_HAVE_BILINEAR) || (d.persp == FXL_PERSP_AUTO && !FXL_HAVE_AUTO))
                    continue;
            }
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, px, W, H, W, drawable_rgb565()));
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zb));
            fxl_target_clear(&t, 0);
            fxl_target_clear_depth(&t);
            for (pass = 0; pass < 3; pass++) {
                /* a receding quad (depth varies along x and y), the same
                 * inv_w in passes 0 and 1, nearer in pass 2 */
                const double s = pass == 2 ? 1.05 : 1.0;   /* inv_w stays below 1 */
                const uint16_t col = pass == 1 ? 0x07E0u : 0xF800u;
                q[0] = test_vertex(2, 3, w0 * s, 0, 0, col);
                q[1] = test_vertex(W - 3, 1, 0.9 * s, 3, 0, col);
                q[2] = test_vertex(W - 2, H - 2, 0.7 * s, 3, 2, col);
                q[3] = test_vertex(1, H - 4, w0 * s, 0, 2, col);
                t0[0] = q[0]; t0[1] = q[1]; t0[2] = q[2];
                t1[0] = q[0]; t1[1] = q[2]; t1[2] = q[3];
                d.texture = m == 3 ? NULL : (pass == 1 ? &tb : &ta);
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, t0, NULL));
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, t1, NULL));
                if (pass == 0) {
                    memcpy(first, px, sizeof px);
                    memcpy(zfirst, zb, sizeof zb);
                } else if (pass == 1) {
                    snprintf(msg, sizeof msg, "walk %d filter %d: a tie overwrote the first draw", m, f);
                    TEST_ASSERT_TRUE_MESSAGE(memcmp(first, px, sizeof px) == 0, msg);
                    TEST_ASSERT_TRUE_MESSAGE(memcmp(zfirst, zb, sizeof zb) == 0, msg);
                }
            }
            /* the nearer draw replaced every pixel of the quad's interior */
            for (i = 0; i < W * H; i++)
                if (zfirst[i]) {
                    snprintf(msg, sizeof msg, "walk %d filter %d: pixel %d not nearer", m, f, i);
                    TEST_ASSERT_TRUE_MESSAGE(zb[i] > zfirst[i], msg);
                }
            drawn++;
        }
    TEST_ASSERT_TRUE(drawn > 0);
}

/* The depth value a pixel stores (raster.h): its interpolated inv_w >> 16,
 * floored, one step off the exact value's at most. The exact value is the
 * reference renderer's (reference.h: the screen-linear exact inv_w through
 * the snapped vertices, floored >> 16), drawn with depth write only so it
 * stores every covered pixel. Random triangles with inv_w log-uniform over
 * [2^17, 2^32) (a depth ratio up to 2^15), and a pair whose depth falls by
 * more than 2^31 in one pixel: (0,0) and (0,8) at 2^32 - 1, (1.75,0) at 1.
 * There a one-pixel segment's step does not fit an int32; a saturated step
 * stored 0x36DB for the second pixel, whose value is 0x2492 (z steps wrap
 * modulo 2^32: z0 + step lands on z1). Every walk: subdivided 16 and 8,
 * exact, adaptive, affine and Gouraud (generic), point and bilinear; depth
 * tested against a cleared buffer, so a pixel whose exact inv_w >> 16 is 2
 * or more must be drawn. */
void test_depth_values_stay_within_one_step_of_the_exact_plane(void)
{
    static uint16_t px[W * H], zb[W * H];
    static const int16_t persp[6] = {16, 8, FXL_PERSP_EXACT, FXL_PERSP_AUTO, FXL_PERSP_AFFINE, 16};
    fxl_texture_t tex;
    fxl_target_t t;
    fxl_draw_t d;
    char msg[200];
    int m, f, k, i, checked = 0;
    long values = 0;
    TEST_NEEDS(FXL_HAVE_DEPTH);
    make_texture(&tex);
    lcg_state = 61u;
    for (m = 0; m < 6; m++)
        for (f = 0; f < 2; f++) {
            fxl_draw_defaults(&d);
            d.depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
            d.filter = (uint8_t)f;
            d.persp = persp[m];
            d.texture = &tex;
            if (m == 5) {   /* untextured Gouraud: the generic walk */
                d.texture = NULL;
                d.shade = FXL_SHADE_GOURAUD;
            }
            if (left_out_feature(&d, d.texture, drawable_rgb565(), 1) != NULL)
                continue;
            for (k = 0; k < 200; k++) {
                fxl_vertex_t v[3];
                ref_params rp;
                ref_image ri;
                if (k == 0) {
                    v[0] = vtx(0, 0, 0.5, 0, 0);
                    v[1] = vtx(1.75, 0, 0.5, 1, 0);
                    v[2] = vtx(0, 8, 0.5, 0, 1);
                    v[0].inv_w = v[2].inv_w = 0xFFFFFFFFu;
                    v[1].inv_w = 1u;
                } else {
                    random_tri(v, k % 2 ? 40.0 : 12.0);
                    for (i = 0; i < 3; i++)   /* 2^(17 + 15 r), r in [0, 1) */
                        v[i].inv_w = (uint32_t)(exp2(17.0 + 15.0 * (rnd() % 65536) / 65536.0));
                }
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, px, W, H, W, drawable_rgb565()));
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zb));
                fxl_target_clear_depth(&t);
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, NULL));
                ref_params_init(&rp, W, H);
                rp.draw = d;
                rp.draw.depth = FXL_DEPTH_WRITE;
                rp.depth_enabled = 1;
                TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&rp, v, 1, &ri));
                for (i = 0; i < W * H; i++) {
                    const int got = zb[i], want = ri.depth[i];
                    if (!ri.covered[i]) {
                        if (got != 0) {
                            snprintf(msg, sizeof msg, "walk %d filter %d triangle %d: (%d,%d) not covered, depth %04X",
                                     m, f, k, i % W, i / W, (unsigned)got);
                            TEST_FAIL_MESSAGE(msg);
                        }
                        continue;
                    }
                    if (got == 0 && want < 2)
                        continue;   /* may fail the test against 0 */
                    if (abs(got - want) > 1) {
                        snprintf(msg, sizeof msg, "walk %d filter %d triangle %d: (%d,%d) stores %04X, exact inv_w >> 16 %04X",
                                 m, f, k, i % W, i / W, (unsigned)got, (unsigned)want);
                        TEST_FAIL_MESSAGE(msg);
                    }
                    values++;
                }
                ref_free(&ri);
            }
            checked++;
        }
    snprintf(msg, sizeof msg, "%d walks, %ld depth values checked", checked, values);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE(checked > 0 && values > 1000);
}

/* Byte-swapped targets get the native pixels byte-swapped, in every walk:
 * point and bilinear, subdivided, exact (whose one-pixel segments have
 * their own code, span_fast.h FXL_T_PIX1) and adaptive, with and without
 * depth. */
void test_swapped_target_is_the_native_image_byte_swapped(void)
{
    static uint16_t nat[W * H], swp[W * H], zn[W * H], zs[W * H], texels[64 * 64];
    static const int16_t persp[4] = {16, FXL_PERSP_EXACT, FXL_PERSP_AUTO, 8};
    fxl_vertex_t tris[12][3];
    fxl_texture_t tex;
    fxl_target_t tn, ts;
    fxl_draw_t d;
    int i, k, m, f, zd, compared = 0;
    char msg[80];
    for (i = 0; i < 64 * 64; i++)
        texels[i] = (uint16_t)(i * 2654435761u >> 13);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 64, 64, FXL_TEXFMT_RGB565, 1));
    lcg_state = 5u;
    for (k = 0; k < 12; k++)
        random_tri(tris[k], 70.0);
    for (zd = 0; zd < (FXL_HAVE_DEPTH ? 2 : 1); zd++)
        for (m = 0; m < 4; m++)
            for (f = 0; f < 2; f++) {
                fxl_status_t sn, ss;
                fxl_draw_defaults(&d);
                d.texture = &tex;
                d.depth = zd ? FXL_DEPTH_TEST | FXL_DEPTH_WRITE : 0;
                d.filter = (uint8_t)f;
                d.persp = persp[m];
                fxl_target_init(&tn, nat, W, H, W, FXL_PIXFMT_RGB565);
                fxl_target_init(&ts, swp, W, H, W, FXL_PIXFMT_RGB565_SWAP);
                if (zd) {
                    fxl_target_set_depth(&tn, zn);
                    fxl_target_set_depth(&ts, zs);
                    fxl_target_clear_depth(&tn);
                    fxl_target_clear_depth(&ts);
                }
                fxl_target_clear(&tn, 0x1234);
                fxl_target_clear(&ts, 0x1234);
                sn = fxl_draw_check(&tn, &d);
                ss = fxl_draw_check(&ts, &d);
                if (sn != FXL_OK || ss != FXL_OK)
                    continue;   /* a kind of draw this build left out */
                for (k = 0; k < 12; k++) {
                    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&tn, &d, tris[k], NULL));
                    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&ts, &d, tris[k], NULL));
                }
                for (i = 0; i < W * H; i++)
                    if ((uint16_t)((nat[i] >> 8) | (nat[i] << 8)) != swp[i]) {
                        snprintf(msg, sizeof msg, "persp %d filter %d depth %d: pixel %d %04x vs %04x", persp[m], f,
                                 zd, i, nat[i], swp[i]);
                        TEST_FAIL_MESSAGE(msg);
                    }
                compared++;
            }
    snprintf(msg, sizeof msg, "%d of %d kinds of draw compared", compared, (FXL_HAVE_DEPTH ? 2 : 1) * 8);
    TEST_MESSAGE(msg);
}


/* fxl_draw_indexed checks the settings once for the list (fxl_draw_check)
 * and then draws each triangle as fxl_draw_triangle would: the same pixels
 * and counts as one call a triangle, and a settings error returned before
 * any pixel is written. */
void test_indexed_draw_matches_single_draws(void)
{
    static uint16_t a[W * H], b[W * H];
    enum { GX = 5, GY = 3, NV = (GX + 1) * (GY + 1), NT = 2 * GX * GY };
    fxl_vertex_t vs[NV], tv[3];
    uint16_t idx[3 * NT];
    fxl_target_t ta, tb;
    fxl_draw_t d;
    fxl_texture_t tex;
    fxl_stats_t sa, sb;
    int i, j, k, n = 0;
    make_texture(&tex);
    for (j = 0; j <= GY; j++)
        for (i = 0; i <= GX; i++)
            vs[j * (GX + 1) + i] = vtx(-3.3 + i * 17.7, -2.6 + j * 18.1, 0.2 + 0.15 * i + 0.05 * j, i * 9.5, j * 7.25);
    for (j = 0; j < GY; j++)
        for (i = 0; i < GX; i++) {
            const uint16_t c = (uint16_t)(j * (GX + 1) + i);
            const uint16_t q[6] = {c, (uint16_t)(c + 1), (uint16_t)(c + GX + 1),
                                   (uint16_t)(c + 1), (uint16_t)(c + GX + 2), (uint16_t)(c + GX + 1)};
            for (k = 0; k < 6; k++)
                idx[n++] = q[k];
        }
    fxl_draw_defaults(&d);
    d.texture = &tex;
    d.depth = 0;
    d.filter = FXL_HAVE_BILINEAR ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
    memset(a, 0, sizeof a);
    memset(b, 0, sizeof b);
    memset(&sa, 0, sizeof sa);
    memset(&sb, 0, sizeof sb);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&ta, a, W, H, W, drawable_rgb565()));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&tb, b, W, H, W, drawable_rgb565()));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_indexed(&ta, &d, vs, NV, idx, NT, &sa));
    for (i = 0; i < NT; i++) {
        for (k = 0; k < 3; k++)
            tv[k] = vs[idx[3 * i + k]];
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&tb, &d, tv, &sb));
    }
    TEST_ASSERT_EQUAL_MEMORY(b, a, sizeof a);
    TEST_ASSERT_EQUAL_UINT32(NT, sa.triangles);
    TEST_ASSERT_EQUAL_UINT32(sb.drawn, sa.drawn);
    TEST_ASSERT_EQUAL_UINT32(sb.pixels, sa.pixels);
    TEST_ASSERT_EQUAL_UINT32(sb.culled_outside, sa.culled_outside);
    TEST_ASSERT_TRUE(sa.pixels > 0u && sa.culled_outside > 0u);   /* its last column lies right of the target */

    /* Settings errors: returned before any triangle is drawn or counted. */
    memset(a, 0, sizeof a);
    memset(&sa, 0, sizeof sa);
    ta.clip.x1 = W + 1;   /* edited past the buffer */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_draw_indexed(&ta, &d, vs, NV, idx, NT, &sa));
    fxl_target_init(&ta, a, W, H, W, drawable_rgb565());
    d.persp = 12;   /* not a power of two */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_draw_indexed(&ta, &d, vs, NV, idx, NT, &sa));
    for (i = 0; i < W * H; i++)
        TEST_ASSERT_EQUAL_HEX16(0, a[i]);
    TEST_ASSERT_EQUAL_UINT32(0, sa.triangles);
    /* An empty list draws nothing, but its settings are checked as a culled
     * triangle's are: the same error, and none once they are valid. */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_draw_indexed(&ta, &d, vs, NV, idx, 0, &sa));
    d.persp = FXL_PERSP_SPAN;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_indexed(&ta, &d, vs, NV, NULL, 0, &sa));
    TEST_ASSERT_EQUAL_UINT32(0, sa.triangles);
    /* A bad vertex stops the list there, after the triangles before it. */
    vs[NV - 1].inv_w = 0;   /* the bottom-right corner: the last triangle only */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_draw_indexed(&ta, &d, vs, NV, idx, NT, &sa));
    TEST_ASSERT_EQUAL_UINT32(NT - 1, sa.triangles);
}

/* A depth buffer that is attached but neither tested nor written changes
 * nothing: the same pixels as without one (set-up then skips the depth
 * plane), the buffer untouched. With only the test on, the buffer is read
 * and still not written. Every persp mode, both filters. */
void test_depth_buffer_unused_without_test_or_write(void)
{
    static uint16_t a[W * H], b[W * H], zb[W * H];
    fxl_target_t ta, tb;
    fxl_draw_t d;
    fxl_texture_t tex;
    int k, i;
    TEST_NEEDS(FXL_HAVE_DEPTH);
    make_texture(&tex);
    lcg_state = 31u;
    for (i = 0; i < W * H; i++) {
        a[i] = b[i] = 0;
        zb[i] = (uint16_t)(0x1357u * (uint32_t)i);
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&ta, a, W, H, W, drawable_rgb565()));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&tb, b, W, H, W, drawable_rgb565()));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&tb, zb));
    fxl_draw_defaults(&d);
    d.texture = &tex;
    for (k = 0; k < 400; k++) {
        /* the modes and filters this build has: 4 for AUTO, point for bilinear */
        static const int16_t persp[5] = {FXL_PERSP_AFFINE, FXL_PERSP_EXACT, 8, 16, FXL_HAVE_AUTO ? FXL_PERSP_AUTO : 4};
        fxl_vertex_t v[3];
        random_tri(v, 120.0);
        d.filter = (uint8_t)(FXL_HAVE_BILINEAR ? k & 1 : FXL_FILTER_POINT);
        d.persp = persp[k % 5];
        d.depth = 0;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&ta, &d, v, NULL));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&tb, &d, v, NULL));
    }
    TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a);
    for (i = 0; i < W * H; i++)
        TEST_ASSERT_EQUAL_UINT16((uint16_t)(0x1357u * (uint32_t)i), zb[i]);
    /* Test without write against a buffer of zeros (the farthest depth):
     * every pixel passes, so the pixels are again those drawn without a
     * buffer (which needs the depth plane), and the buffer stays zero. */
    for (i = 0; i < W * H; i++) {
        a[i] = b[i] = 0;
        zb[i] = 0;
    }
    d.depth = FXL_DEPTH_TEST;
    if (left_out_feature(&d, d.texture, tb.format, 1) != NULL) {
        /* without the generic walk: no walk tests without writing */
        TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_draw_check(&tb, &d));
        TEST_MESSAGE("depth test without write not checked: needs FXL_HAVE_GENERIC");
        return;
    }
    for (k = 0; k < 100; k++) {
        fxl_vertex_t v[3];
        random_tri(v, 120.0);
        d.depth = 0;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&ta, &d, v, NULL));
        d.depth = FXL_DEPTH_TEST;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&tb, &d, v, NULL));
    }
    TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a);
    for (i = 0; i < W * H; i++)
        TEST_ASSERT_EQUAL_UINT16(0, zb[i]);
}

/* Each optional feature either works or, left out by the configuration, is
 * refused with FXL_ERR_UNSUPPORTED and draws nothing: never drawn some
 * other way. Which is expected comes from left_out.h (config.h's rules,
 * not the core's code), so in the full build every draw below must give
 * pixels; CI runs this file in reduced configurations too. fxl_draw_check
 * must give the draw's status, and a refused draw is refused for a
 * zero-area triangle as well (before culling). */
static void expect_feature(fxl_target_t *t, const fxl_draw_t *d, const fxl_vertex_t v[3], const char *what)
{
    const fxl_vertex_t flat[3] = {vtx(1, 1, 0.5, 0, 0), vtx(11, 1, 0.5, 1, 0), vtx(21, 1, 0.5, 2, 0)};
    const char *need = left_out_feature(d, d->texture, t->format, t->depth != NULL);
    fxl_stats_t st;
    char msg[160];
    fxl_status_t got;
    memset(&st, 0, sizeof st);
    memset(pix, 0, sizeof pix);
    got = fxl_draw_triangle(t, d, v, &st);
    snprintf(msg, sizeof msg, "%s: status %d, %lu pixels, %s%s", what, (int)got, (unsigned long)st.pixels,
             need ? "needs " : "every feature it needs is in", need ? need : "");
    TEST_ASSERT_EQUAL_INT_MESSAGE(need ? FXL_ERR_UNSUPPORTED : FXL_OK, got, msg);
    TEST_ASSERT_TRUE_MESSAGE(need ? st.pixels == 0 : st.pixels > 0, msg);
    TEST_ASSERT_EQUAL_INT_MESSAGE(got, fxl_draw_check(t, d), msg);
    TEST_ASSERT_EQUAL_INT_MESSAGE(got, fxl_draw_triangle(t, d, flat, NULL), msg);
}

void test_left_out_features_are_refused(void)
{
    static uint16_t chain[64 * 64 * 4 / 3 + 8];
    static uint16_t big[512 * 256];
    static uint16_t zbuf[W * H];
    fxl_target_t t;
    fxl_draw_t d;
    fxl_texture_t tex, mip, lum, wide;
    fxl_vertex_t v[3];
    v[0] = vtx(1, 1, 0.5, 0, 0);
    v[1] = vtx(40, 2, 0.25, 8, 0);
    v[2] = vtx(3, 40, 0.5, 0, 8);
    fxl_target_init(&t, pix, W, H, W, FXL_PIXFMT_RGB565);
    make_texture(&tex);
    fxl_draw_defaults(&d);
    d.texture = &tex;
    expect_feature(&t, &d, v, "point, subdivided, RGB565 repeat");
    d.filter = FXL_FILTER_BILINEAR;
    expect_feature(&t, &d, v, "FXL_FILTER_BILINEAR");
    fxl_draw_defaults(&d);
    d.texture = &tex;
    d.persp = FXL_PERSP_AUTO;
    expect_feature(&t, &d, v, "FXL_PERSP_AUTO");
    /* A chain of levels: selection needs FXL_HAVE_MIPMAP; FXL_MIP_NONE (level
     * 0) and a one-level texture need nothing. */
    memset(chain, 0x5A, sizeof chain);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&mip, chain, 64, 64, FXL_TEXFMT_RGB565, 7));
    fxl_draw_defaults(&d);
    d.texture = &mip;
    expect_feature(&t, &d, v, "FXL_MIP_NEAREST on 7 levels");
    d.mip = FXL_MIP_LINEAR;
    expect_feature(&t, &d, v, "FXL_MIP_LINEAR on 7 levels");
    d.mip = FXL_MIP_NONE;
    expect_feature(&t, &d, v, "FXL_MIP_NONE on 7 levels");
    d.texture = &tex;
    d.mip = FXL_MIP_LINEAR;
    expect_feature(&t, &d, v, "FXL_MIP_LINEAR on one level");
    /* The generic walk's kinds of draw */
    fxl_draw_defaults(&d);
    expect_feature(&t, &d, v, "untextured");
    d.texture = &tex;
    d.texenv = FXL_TEXENV_MODULATE;
    expect_feature(&t, &d, v, "FXL_TEXENV_MODULATE");
    d.texenv = FXL_TEXENV_REPLACE;
    d.shade = FXL_SHADE_GOURAUD;
    expect_feature(&t, &d, v, "FXL_SHADE_GOURAUD");
    d.shade = FXL_SHADE_FLAT;
    tex.wrap_u = FXL_WRAP_CLAMP;
    expect_feature(&t, &d, v, "FXL_WRAP_CLAMP");
    tex.wrap_u = FXL_WRAP_REPEAT;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&lum, tex_data, 64, 64, FXL_TEXFMT_L8, 1));
    d.texture = &lum;
    expect_feature(&t, &d, v, "FXL_TEXFMT_L8");
    /* level 0 above 2^16 texels: only the generic walk */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&wide, big, 512, 256, FXL_TEXFMT_RGB565, 1));
    d.texture = &wide;
    expect_feature(&t, &d, v, "512 x 256 texture");
    /* The specialised walks of each kind of target */
    d.texture = &tex;
    d.filter = FXL_FILTER_BILINEAR;
    expect_feature(&t, &d, v, "bilinear, native target");
    t.format = FXL_PIXFMT_RGB565_SWAP;
    expect_feature(&t, &d, v, "bilinear, byte-swapped target");
    d.filter = FXL_FILTER_POINT;
    expect_feature(&t, &d, v, "point, byte-swapped target");
    t.format = FXL_PIXFMT_RGB565;
    /* The depth buffer is refused where it is attached: by
     * fxl_target_set_depth, and by the draw for one put in the struct. */
    TEST_ASSERT_EQUAL_INT(FXL_HAVE_DEPTH ? FXL_OK : FXL_ERR_UNSUPPORTED, fxl_target_set_depth(&t, zbuf));
    t.depth = zbuf;
    memset(zbuf, 0, sizeof zbuf);
    expect_feature(&t, &d, v, "depth test and write");
    d.depth = FXL_DEPTH_TEST;
    memset(zbuf, 0, sizeof zbuf);   /* farthest: every pixel passes */
    expect_feature(&t, &d, v, "depth test only");
    d.depth = FXL_DEPTH_WRITE;
    memset(zbuf, 0, sizeof zbuf);
    expect_feature(&t, &d, v, "depth write only");
    d.depth = 0;
    expect_feature(&t, &d, v, "depth buffer, neither test nor write");
}


/* Needles: a triangle whose far vertex lies 8000-30000 px away almost on
 * the line of its 1-4 px short edge (1-3 sub-pixels off it), so that a
 * whole attribute range changes within ~10^-5 px across it near that
 * edge. Its x (or, turned, y) gradients are then up to ~2^13 times what
 * 64 bits hold at the planes' scale; they are kept modulo 2^64, which the
 * planes' evaluation is, so every covered pixel still gets its
 * interpolated value (such a triangle divides at every pixel: the
 * gradients' size, which segment bounds read, is lost). The gradients
 * were saturated instead: on the fuzz's needle (seed 30, case 1890225)
 * affine mode read texel row 128+ instead of 111, and its Gouraud green
 * was 63 instead of 39 (0 instead of 56 in every perspective mode). Every
 * mode, u, v from the probe within 1/256 texel of the exact map (affine:
 * the screen-linear one) plus the mode's own bound (AUTO: its budget; a
 * length L: the chord bound), Gouraud channels within 10^-3 of theirs
 * plus their chord bound (untextured AUTO: 16-pixel segments). */
static int needle(fxl_vertex_t v[3])
{
    /* sub-pixel units; direction: the 4 axes, 4 diagonals or random */
    const int k = (int)(rnd() % 12u);
    const double ang = k < 8 ? k * 0.7853981633974483 : (rnd() % 62832u) / 10000.0;
    const double dx = cos(ang), dy = sin(ang), F = 8000 + rnd() % 22000u, h = 1 + rnd() % 4u;
    const int off = (int)(rnd() % 6u) - 3;
    int32_t X1 = 64 + (int32_t)(rnd() % (56u * 16u)), Y1 = 64 + (int32_t)(rnd() % (40u * 16u));
    int32_t X[3], Y[3], i;
    if (k == 2 || k == 6)
        X1 = X1 / 16 * 16 + 8;   /* vertical: the short edge through pixel centres */
    if (k == 0 || k == 4)
        Y1 = Y1 / 16 * 16 + 8;
    X[1] = X1;
    Y[1] = Y1;
    X[2] = X1 + (int32_t)lround(h * 16 * dx);
    Y[2] = Y1 + (int32_t)lround(h * 16 * dy);
    X[0] = X1 + (int32_t)lround(F * 16 * dx - (off ? off : 1) * dy);
    Y[0] = Y1 + (int32_t)lround(F * 16 * dy + (off ? off : 1) * dx);
    for (i = 0; i < 3; i++) {
        v[i].x = X[i] * 4096;
        v[i].y = Y[i] * 4096;
        /* depth ratios up to 2^3; u, v within 2 periods of 0 */
        v[i].inv_w = (rnd() % 2u ? 0x80000000u : 0x10000000u) + (rnd() << 4);
        v[i].u = (int32_t)(rnd() % 262144u) - 131072;
        v[i].v = (int32_t)(rnd() % 262144u) - 131072;
        v[i].color = (uint16_t)(rnd() >> 8);
    }
    return k;
}

void test_needle_slivers_interpolate_their_attributes_in_every_mode(void)
{
    static const int16_t modes[] = {FXL_PERSP_AFFINE, FXL_PERSP_EXACT, FXL_PERSP_AUTO, 8, 16, 256};
    static uint16_t texels[64 * 64], buf[W * H];
    static const int sh[3] = {11, 5, 0}, top[3] = {31, 63, 31};
    fxl_texture_t tex;
    fxl_target_t t;
    char msg[200];
    long uv_px = 0, col_px = 0;
    int n;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 64, 64, FXL_TEXFMT_RGB565, 1));
    for (n = 0; n < 3000; n++) {
        fxl_vertex_t v[3];
        size_t mi;
        needle(v);
        for (mi = 0; mi < sizeof modes / sizeof modes[0]; mi++) {
            const int affine = modes[mi] == FXL_PERSP_AFFINE, L = modes[mi] > 1 ? modes[mi] : 0;
            const double uv_tol = 1.0 / 256 + (modes[mi] == FXL_PERSP_AUTO ? 0.25 : (L ? ref_chord_bound(v, 6, 6, L) : 0));
            fxl_draw_t d;
            int x, y, ch;
            fxl_draw_defaults(&d);
            d.texture = &tex;
            d.depth = 0;
            d.persp = modes[mi];
            if (left_out_feature(&d, &tex, drawable_rgb565(), 0) == NULL) {
                probe_target(&t, buf, W, H);
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, v, NULL, probe_seg));
                for (y = 0; y < H; y++)
                    for (x = 0; x < W; x++)
                        if (probe_count[y * W + x]) {
                            const double e = probe_error_at(v, 64, affine, W, x, y);
                            snprintf(msg, sizeof msg, "needle %d persp %d: pixel (%d,%d) %.4g texels off", n,
                                     modes[mi], x, y, e);
                            TEST_ASSERT_TRUE_MESSAGE(e <= uv_tol, msg);
                            uv_px++;
                        }
            }
            /* untextured Gouraud: each channel against its own exact map */
            d.texture = NULL;
            d.shade = FXL_SHADE_GOURAUD;
            if (left_out_feature(&d, NULL, drawable_rgb565(), 0) != NULL)
                continue;
            memset(buf, 0, sizeof buf);
            probe_target(&t, buf, W, H);   /* native: Gouraud needs the generic walk */
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, v, NULL, probe_seg));
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, NULL));
            for (y = 0; y < H; y++)
                for (x = 0; x < W; x++)
                    if (probe_count[y * W + x])
                        for (ch = 0; ch < 3; ch++) {
                            fxl_vertex_t c[3];
                            double want, unused, tol;
                            int i, got = (buf[y * W + x] >> sh[ch]) & top[ch];
                            for (i = 0; i < 3; i++) {
                                c[i] = v[i];
                                c[i].u = (int32_t)(((uint32_t)v[i].color >> sh[ch]) & (uint32_t)top[ch]) << 16;
                                c[i].v = 0;
                            }
                            exact_uv(c, 1, 1, affine, x, y, &want, &unused);
                            tol = 1e-3 + (modes[mi] == FXL_PERSP_AUTO ? ref_chord_bound(c, 0, 0, 16)
                                                                       : (L ? ref_chord_bound(c, 0, 0, L) : 0));
                            snprintf(msg, sizeof msg, "needle %d persp %d: pixel (%d,%d) channel %d is %d, exact %.5f tol %g",
                                     n, modes[mi], x, y, ch, got, want, tol);
                            TEST_ASSERT_TRUE_MESSAGE(got >= floor(want - tol) && got <= floor(want + tol),
                                                     msg);
                            col_px++;
                        }
        }
    }
    /* most needles miss every pixel centre; enough do not */
    snprintf(msg, sizeof msg, "%ld textured and %ld Gouraud pixel values checked", uv_px, col_px / 3);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE_MESSAGE(uv_px > 1000, msg);
    TEST_ASSERT_TRUE_MESSAGE(col_px > 1000 || !FXL_HAVE_GENERIC, msg);
}

/* Plane gradients round half away from zero (setup.c, gradient: sign(N)
 * round_half_up(|N| 2^PF / den)). A tie needs |det| to hold 2^(PF + 1):
 * det = 2048 * 1024 = 2^21 grid units with an odd dY1 gives the depth
 * plane gx = (dz1 * 1024 - dz2) 2^20 / 2^21, a half exactly when dz2 is
 * odd. Checked against the exact quotient for both signs and windings.
 * The second shape, det = 512 * 4096 = 2^21 too, makes gx's numerator
 * dz1 * 4096 - dz2 with |dz1| near 2^31: |N| 2^PF passes 2^62, so the
 * quotient takes setup's chunked path (div_frac's long division of the
 * remainder), whose tie rule must be the same (a mutation run left a
 * `>` there alive: its ties rounded toward zero, one unit off). */
static fxl__plane_t probe_zplane;
static uint32_t probe_depth_plane(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    probe_zplane = tri->z;
    return (uint32_t)s->n;
}

/* round(num 2^PF / den), ties away from zero, for den > 0 below 2^41 and
 * any num: the whole quotient and the remainder's fraction apart, so
 * nothing passes 2^62 (num 2^PF itself would, for the second shape) */
static int64_t round_half_away_pf(int64_t num, int64_t den)
{
    const int64_t m = num < 0 ? -num : num;
    const int64_t q = (m / den) * ((int64_t)1 << FXL__PF) + ((m % den) * ((int64_t)1 << FXL__PF) + den / 2) / den;
    return num < 0 ? -q : q;
}

void test_gradient_ties_round_half_away_from_zero(void)
{
    enum { TW = 160, TH = 120 };
    static uint16_t px[TW * TH], zb[TW * TH];
    /* per shape: X1 - X0, Y1 - Y0, Y2 - Y0 (X2 = X0) and four (dz1, dz2) */
    static const struct {
        int32_t dx1, dy1, dy2;
        int32_t dz[4][2];
    } shapes[2] = {{2048, 1, 1024, {{1001, 3}, {1001, -3}, {-7, 5}, {-7, -5}}},
                   {512, 1, 4096, {{0x7FFFFFF1, 3}, {0x7FFFFFF1, -3}, {-0x7FFFFFF1, 5}, {-0x7FFFFFF1, -5}}}};
    const int32_t X0 = 8 << FXL__S, Y0 = 8 << FXL__S;
    fxl_target_t t;
    fxl_draw_t d;
    char msg[160];
    int sh, k, w;
    TEST_NEEDS(FXL_HAVE_DEPTH && FXL_HAVE_GENERIC);
    for (sh = 0; sh < 2; sh++)
        for (k = 0; k < 4; k++)
            for (w = 0; w < 2; w++) {
                const int32_t X[3] = {X0, X0 + shapes[sh].dx1, X0}, Y[3] = {Y0, Y0 + shapes[sh].dy1, Y0 + shapes[sh].dy2};
                const int32_t *dz = shapes[sh].dz[k];
                fxl_vertex_t v[3];
                /* room for dz of either sign within uint32 */
                const uint32_t z0 = sh == 0 ? 0x40000000u : dz[0] < 0 || dz[1] < 0 ? 0x80000000u : 0x100u;
                const uint32_t z[3] = {z0, z0 + (uint32_t)dz[0], z0 + (uint32_t)dz[1]};
                int64_t det, nx, ny;
                int i;
                memset(v, 0, sizeof v);
                for (i = 0; i < 3; i++) {
                    const int j = w && i ? 3 - i : i;   /* w: the other winding */
                    v[j].x = X[i] * (1 << (16 - FXL__S));
                    v[j].y = Y[i] * (1 << (16 - FXL__S));
                    v[j].inv_w = z[i];
                    v[j].color = 0xFFFFu;
                }
                fxl_draw_defaults(&d);
                d.shade = FXL_SHADE_FLAT;
                d.depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, px, TW, TH, TW, drawable_rgb565()));
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, zb));
                fxl_target_clear_depth(&t);
                memset(&probe_zplane, 0, sizeof probe_zplane);
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, v, NULL, probe_depth_plane));
                /* the plane's reference vertex is v[0] = (X0, Y0) in both windings */
                det = ((int64_t)X[1] - X[0]) * ((int64_t)Y[2] - Y[0]) - ((int64_t)X[2] - X[0]) * ((int64_t)Y[1] - Y[0]);
                nx = ((int64_t)z[1] - z[0]) * ((int64_t)Y[2] - Y[0]) - ((int64_t)z[2] - z[0]) * ((int64_t)Y[1] - Y[0]);
                ny = ((int64_t)z[2] - z[0]) * ((int64_t)X[1] - X[0]) - ((int64_t)z[1] - z[0]) * ((int64_t)X[2] - X[0]);
                snprintf(msg, sizeof msg, "shape %d dz (%ld, %ld) winding %d: gx %lld, want %lld", sh, (long)dz[0],
                         (long)dz[1], w, (long long)probe_zplane.gx, (long long)round_half_away_pf(nx, det));
                TEST_ASSERT_TRUE_MESSAGE(probe_zplane.gx == round_half_away_pf(nx, det), msg);
                TEST_ASSERT_TRUE_MESSAGE(probe_zplane.gy == round_half_away_pf(ny, det), msg);
            }
}

/* The needle threshold (setup.c, gradient): a triangle without uv_wide
 * bit 2 must have every plane gradient within 2^42 plane units a pixel,
 * the size the segment bounds and the per-segment LOD read 16 pixels'
 * worth of in int64 (auto.c, auto.h, span.c lod_setup). Oblique needles on
 * the build's own sub-pixel grid, a few sub-pixels across their long edge,
 * give gradients of every size up to ~2^50 units a sub-pixel. Until the
 * forty-third session the threshold was 2^38 units a sub-pixel on every
 * grid: 2^44 a pixel on the 1/64 grid (FXL_SUBPIXEL_BITS 6), which this
 * test catches there (the sub6 configuration of config_tests.sh); on the
 * 1/16 grid the two thresholds are the same. */
static uint64_t probe_grad_max;   /* largest |gradient| of the draw, plane units a sub-pixel (FXL__PF bits) */
static int probe_grad_flagged, probe_grad_seen;
static uint64_t grad_abs(int64_t g)
{
    return g < 0 ? (uint64_t)0 - (uint64_t)g : (uint64_t)g;
}

static uint32_t probe_gradients(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    const fxl__plane_t *pl[4] = {&tri->q, &tri->z, &tri->a[FXL__AU], &tri->a[FXL__AV]};
    int i;
    probe_grad_seen = 1;
    probe_grad_flagged = (tri->uv_wide & 4u) != 0;
    probe_grad_max = 0;
    for (i = 0; i < 4; i++) {
        if (grad_abs(pl[i]->gx) > probe_grad_max)
            probe_grad_max = grad_abs(pl[i]->gx);
        if (grad_abs(pl[i]->gy) > probe_grad_max)
            probe_grad_max = grad_abs(pl[i]->gy);
    }
    return (uint32_t)s->n;
}

void test_needles_flag_gradients_beyond_what_a_pixel_holds(void)
{
    static uint16_t texels[64 * 64], buf[W * H], zbuf[W * H];
    /* 2^42 units a pixel, and the rounding of one gradient (half a unit
     * of its FXL__PF fraction bits, a sub-pixel) on top */
    const uint64_t limit = ((uint64_t)1 << (42 + FXL__PF)) + ((uint64_t)1 << (FXL__PF + FXL__S));
    fxl_texture_t tex;
    fxl_target_t t;
    fxl_draw_t d;
    char msg[160];
    int n, flagged = 0, near_limit = 0, drawn = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 64, 64, FXL_TEXFMT_RGB565, 1));
    fxl_draw_defaults(&d);
    d.texture = &tex;
    d.persp = 16;
    d.depth = FXL_HAVE_DEPTH ? FXL_DEPTH_TEST | FXL_DEPTH_WRITE : 0;   /* the z plane too */
    if (left_out_feature(&d, &tex, drawable_rgb565(), 0) != NULL)
        d.depth = 0;
    if (left_out_feature(&d, &tex, drawable_rgb565(), 0) != NULL)
        TEST_IGNORE_MESSAGE("textured draws left out of this build");
    for (n = 0; n < 20000; n++) {
        /* sub-pixel units, along the lattice direction (1, b) (or (b, 1)):
         * the short edge P1 P2, m steps, passes through the pixel centre C
         * (j steps from P1; it covers C when the fill rule takes that
         * edge), the far vertex P0 is K steps along and off units across:
         * the area is m off / 2 sub-pixels squared, the long edge up to
         * 2^14 px */
        const int32_t b = (int32_t)(rnd() % 41u) - 20, m = 2 + (int32_t)(rnd() % 4u);
        const int32_t j = 1 + (int32_t)(rnd() % (uint32_t)(m - 1));
        const int32_t K = (int32_t)(rnd() % ((16384u * FXL__ONE) / (uint32_t)(abs(b) + 1))) + 2 * FXL__ONE;
        const int32_t off = 1 + (int32_t)(rnd() % (1u << (rnd() % (13u + FXL__S))));
        const int steep = (int)(rnd() & 1u), sx = rnd() & 1u ? 1 : -1, sy = rnd() & 1u ? 1 : -1;
        const int32_t CX = (20 + (int32_t)(rnd() % 24u)) * FXL__ONE + FXL__ONE / 2;
        const int32_t CY = (16 + (int32_t)(rnd() % 16u)) * FXL__ONE + FXL__ONE / 2;
        const int32_t along[3] = {K - j, -j, m - j}, across[3] = {(K - j) * b + off, -j * b, (m - j) * b};
        int32_t X[3], Y[3];
        fxl_vertex_t v[3];
        int i;
        for (i = 0; i < 3; i++) {
            X[i] = CX + sx * (steep ? across[i] : along[i]);
            Y[i] = CY + sy * (steep ? along[i] : across[i]);
        }
        for (i = 0; i < 3; i++) {
            v[i].x = X[i] * (1 << (16 - FXL__S));
            v[i].y = Y[i] * (1 << (16 - FXL__S));
            v[i].inv_w = 0x10000000u + (rnd() << 5);
            v[i].u = ((int32_t)(rnd() % 16777216u) - 8388608) * 32;   /* +-4096 texels */
            v[i].v = ((int32_t)(rnd() % 16777216u) - 8388608) * 32;
            v[i].color = 0xFFFF;
        }
        probe_target(&t, buf, W, H);
        if (d.depth) {
            t.depth = zbuf;
            memset(zbuf, 0, sizeof zbuf);
        }
        probe_grad_seen = 0;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl__draw_triangle_with(&t, &d, v, NULL, probe_gradients));
        if (!probe_grad_seen)
            continue;   /* no pixel centre covered */
        drawn++;
        if (probe_grad_flagged) {
            flagged++;
            continue;
        }
        snprintf(msg, sizeof msg, "needle %d: a gradient of 2^%.2f units a pixel is not flagged", n,
                 log2((double)probe_grad_max) - FXL__PF + FXL__S);
        TEST_ASSERT_TRUE_MESSAGE(probe_grad_max <= limit >> FXL__S, msg);
        near_limit += probe_grad_max >= limit >> (FXL__S + 4);
    }
    /* both sides of the threshold are reached, the unflagged side within
     * 16x of its limit */
    snprintf(msg, sizeof msg, "%d needles drawn: %d flagged, %d unflagged within 16x of the limit", drawn, flagged,
             near_limit);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE_MESSAGE(flagged >= 20 && near_limit >= 20, msg);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_fill_rule_matches_exact_reference_on_random_triangles);
    RUN_TEST(test_depth_buffer_unused_without_test_or_write);
    RUN_TEST(test_fill_rule_long_edges_do_not_drift);
    RUN_TEST(test_fill_rule_centres_on_edges_all_eight_orientations);
    RUN_TEST(test_watertight_grid_mesh_each_pixel_once);
    RUN_TEST(test_watertight_random_jittered_meshes_each_pixel_once);
    RUN_TEST(test_watertight_fan_each_pixel_once);
    RUN_TEST(test_no_write_outside_clip_rectangle_canaries);
    RUN_TEST(test_band_and_clip_renders_are_bit_identical_to_full_frame);
    RUN_TEST(test_exact_mode_within_one_64th_texel_on_floor_and_cube);
    RUN_TEST(test_exact_mode_precision_holds_across_depth_ratios);
    RUN_TEST(test_exact_mode_error_within_its_plane_precision_bound);
    RUN_TEST(test_exact_mode_far_off_target_vertices_within_bound_in_any_order);
    RUN_TEST(test_vertex_order_does_not_change_the_pixels);
    RUN_TEST(test_subdivided_modes_within_derived_bound_and_affine_is_worse);
    RUN_TEST(test_auto_mode_within_budget_and_affine_where_depth_is_constant);
    RUN_TEST(test_auto_vertex_test_keeps_small_triangles_within_budget);
    RUN_TEST(test_auto_quadratic_segments_stay_within_budget);
    RUN_TEST(test_auto_reciprocal_runs_agree_and_stay_within_budget);
    RUN_TEST(test_auto_reciprocal_runs_keep_the_first_draw_on_depth_ties);
    RUN_TEST(test_auto_on_the_largest_texture_keeps_its_budget);
    RUN_TEST(test_auto_short_mip_segments_take_runs_within_budget);
    RUN_TEST(test_wide_texture_ranges_step_from_64_bit_coordinates);
    RUN_TEST(test_clamp_coordinate_32767_texels_out_divides_every_pixel);
    RUN_TEST(test_needle_slivers_interpolate_their_attributes_in_every_mode);
    RUN_TEST(test_needles_flag_gradients_beyond_what_a_pixel_holds);
    RUN_TEST(test_gradient_ties_round_half_away_from_zero);
    RUN_TEST(test_auto_whole_span_test_keeps_receding_strips_within_budget);
    RUN_TEST(test_auto_budget_holds_for_small_and_huge_budgets);
    RUN_TEST(test_auto_budget_holds_on_rows_of_constant_depth);
    RUN_TEST(test_quad_steps_follow_their_parabola);
    RUN_TEST(test_quad_last_segment_step_matches_64bit);
    RUN_TEST(test_fast_and_generic_walks_agree);
    RUN_TEST(test_row_const_walk_matches_generic);
    RUN_TEST(test_row_const_walk_declined_spans_match_generic);
    RUN_TEST(test_row_const_walk_clipped_first_segment_steps_depth);
    RUN_TEST(test_level_row_walk_ends_whole_segments_before_the_last_pixel);
    RUN_TEST(test_stats_count_generic_draws);
    RUN_TEST(test_divisions_count_each_correction_point_once);
    RUN_TEST(test_divisions_match_between_walks);
    RUN_TEST(test_draw_api_errors);
    RUN_TEST(test_indexed_draw_matches_single_draws);
    RUN_TEST(test_depth_ties_keep_the_first_draw_in_every_walk);
    RUN_TEST(test_depth_values_stay_within_one_step_of_the_exact_plane);
    RUN_TEST(test_swapped_target_is_the_native_image_byte_swapped);
    RUN_TEST(test_fast_loops_match_generic_loop);
    RUN_TEST(test_modulate_loop_matches_generic_loop);
    RUN_TEST(test_modulate_depth_modes_match_generic_loop);
    RUN_TEST(test_generic_plain_taps_match_wrapped_taps);
    RUN_TEST(test_level_row_walk_matches_generic);
    RUN_TEST(test_left_out_features_are_refused);
    return UNITY_END();
}
