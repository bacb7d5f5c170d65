/* test_determinism.c - the same input renders the same bits.
 *
 * Renders the determinism list (determinism/det_entries.h: every gallery
 * scene x 9 draw variants, then every pipeline scene x 4 front-end
 * variants, at 320x240) and checks, inside this build:
 * - a second render of the same frame is bit-identical (no dependence on
 *   uninitialised memory, addresses or earlier draws);
 * - rendering the frame as 10 bands of 24 rows (targets with origin_y = 24k,
 *   the band renderer's use) gives the same bytes as the full frame;
 * - fxl_host_crc_target equals the CRC of the raw frame bytes.
 * Then it draws the stress cases (determinism/det_stress.h: random
 * triangles with extreme inputs) and checks that none changed a pixel or a
 * depth value outside its clip rectangle, nor anything at all when its draw
 * returned an error.
 * It writes the CRC list to $FXL_TEST_OUTPUT_DIR/determinism_crcs.txt in the
 * format of determinism/det_main.c; host_sim/scripts/determinism.sh compares
 * it with gcc -O0 / -O2 / -Os, clang -O2, Cortex-M4 / M0+ and RISC-V RV32 /
 * RV64 (qemu) builds of the core. The front-end frames here come from the host's own scenes
 * (pscene_build, pscene_draw, scene_clear), det_main's from the fixed-point
 * data gen_data.c wrote: equal lists mean the two routes agree.
 * A build that leaves features out (fixel/config.h) draws without a depth
 * buffer when it has no depth (as det_main does there: its depth calls are
 * refused), except a front-end scene whose image needs the depth test
 * (anyscene_needs_depth: p_cubemap), whose buffer the core refuses as in the
 * gallery; a variant that needs a left-out feature must be refused with
 * FXL_ERR_UNSUPPORTED; its line carries that status.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crc32.h"
#include "scene.h"
#include "test_features.h"
#include "textures.h"
#include "unity.h"
#include "../determinism/det_entries.h"
#include "../determinism/det_stress.h"

#define BAND 24

void setUp(void) {}
void tearDown(void) {}

static uint16_t full[DET_W * DET_H], again[DET_W * DET_H], banded[DET_W * DET_H];
static uint16_t depth[DET_W * DET_H];

/* Frame procedure of det_entries.h into rows [y0, y0 + h) of buf, native
 * RGB565 (drawn in the byte order this build draws, left_out.h). */
static fxl_status_t render(const scene_t *s, const fxl_texture_t *tex, const det_variant_t *var, uint16_t *buf,
                           int32_t y0, int32_t h)
{
    fxl_target_t tg;
    fxl_draw_t d;
    fxl_status_t st;
    uint32_t i;

    det_draw_settings(var, &d);
    d.texture = tex;
    st = fxl_target_init(&tg, buf + (size_t)y0 * DET_W, DET_W, h, DET_W, drawable_rgb565());
    if (st == FXL_OK)
        st = fxl_target_set_origin(&tg, 0, y0);
    if (st == FXL_OK && FXL_HAVE_DEPTH)
        st = fxl_target_set_depth(&tg, depth);
    if (st != FXL_OK)
        return st;
    fxl_target_clear(&tg, 0);
    if (FXL_HAVE_DEPTH)
        fxl_target_clear_depth(&tg);
    for (i = 0; i < s->tri_count; i++) {
        st = fxl_draw_triangle(&tg, &d, &s->verts[3 * i], NULL);
        if (st != FXL_OK)
            return st;
    }
    pixels_to_native(buf + (size_t)y0 * DET_W, (size_t)h * DET_W, tg.format);
    return FXL_OK;
}

/* A front-end frame of det_entries.h into rows [y0, y0 + h) of buf, the
 * way the gallery draws it: scene_clear's sky (or the band renderer's flat
 * clear), then pscene_draw (with its vertex cache) or, for a variant
 * without the cache, every part through fxl_mesh_draw with its own
 * pipeline and pscene_part_draw's state. */
static fxl_status_t render_pipe(pscene_t *p, const det_pvariant_t *pv, uint16_t *buf, int32_t y0, int32_t h)
{
    fxl_target_t tg;
    fxl_draw_t d;
    fxl_status_t st;
    int i;

    det_draw_settings(&pv->v, &d);
    st = fxl_target_init(&tg, buf + (size_t)y0 * DET_W, DET_W, h, DET_W, drawable_rgb565());
    if (st == FXL_OK)
        st = fxl_target_set_origin(&tg, 0, y0);
    if (st == FXL_OK && (FXL_HAVE_DEPTH || anyscene_needs_depth(p->name)))
        st = fxl_target_set_depth(&tg, depth);
    if (st != FXL_OK)
        return st;
    if (pv->clear == DET_CLEAR_SKY)
        scene_clear(&tg, DET_H);
    else
        scene_clear_flat(&tg, PANEL_CLEAR_RGB565);
    if (pv->cache) {
        st = pscene_draw(p, &d, &tg, NULL);
    } else {
        for (i = 0; i < p->parts && st == FXL_OK; i++) {
            fxl_draw_t pd;
            fxl_pipeline_t pipe = p->part[i].pipe;
            pscene_part_draw(p, i, &d, &pd);
            st = fxl_mesh_draw(&pipe, &tg, &pd, &p->part[i].mesh, NULL);
        }
    }
    if (st != FXL_OK)
        return st;
    pixels_to_native(buf + (size_t)y0 * DET_W, (size_t)h * DET_W, tg.format);
    return FXL_OK;
}

/* The first feature a front-end frame needs and this build left out, or
 * NULL (gallery_missing_feature's rule for the gallery's p_* images). */
static const char *pipe_missing(const pscene_t *p, const det_pvariant_t *pv)
{
    fxl_draw_t d;
    if (!FXL_HAVE_DEPTH && anyscene_needs_depth(p->name))
        return "FXL_HAVE_DEPTH";
    det_draw_settings(&pv->v, &d);
    return pscene_missing_feature(p, &d, drawable_rgb565(), FXL_HAVE_DEPTH);
}

/* Repeat and band checks of one frame already drawn into `full`; fails the
 * test naming the first pixel that differs. */
static void check_repeat_and_bands(const char *name, const char *variant)
{
    char msg[200];
    size_t i;
    for (i = 0; i < (size_t)DET_W * DET_H; i++) {
        if (full[i] != again[i] || full[i] != banded[i]) {
            snprintf(msg, sizeof msg, "%s %s: pixel (%d,%d) full %04X, repeat %04X, banded %04X", name, variant,
                     (int)(i % DET_W), (int)(i / DET_W), full[i], again[i], banded[i]);
            TEST_FAIL_MESSAGE(msg);
        }
    }
}

static FILE *open_list(const char *mode)
{
    const char *dir = getenv("FXL_TEST_OUTPUT_DIR");
    char path[1024];
#ifdef FXL_TEST_OUTPUT_DIR
    if (!dir)
        dir = FXL_TEST_OUTPUT_DIR;
#endif
    if (!dir)
        dir = ".";
    snprintf(path, sizeof path, "%s/determinism_crcs.txt", dir);
    return fopen(path, mode);
}

void test_determinism_repeat_bands_and_crc_list(void)
{
    FILE *list = open_list("w");
    size_t si;
    int k, frames = 0, refused = 0;
    char note[100];

    TEST_ASSERT_TRUE_MESSAGE(list != NULL, "cannot write determinism_crcs.txt in FXL_TEST_OUTPUT_DIR");
    for (si = 0; si < scene_count(); si++) {
        scene_t s;
        host_texture_t ht;
        char msg[200];
        TEST_ASSERT_EQUAL_INT(SCENE_OK, scene_build(scene_name(si), DET_W, DET_H, &s));
        TEST_ASSERT_EQUAL_INT(0, texture_make(&ht, s.texture));
        for (k = 0; k < DET_NVARIANTS; k++) {
            const det_variant_t *var = &det_variants[k];
            fxl_target_t whole;
            fxl_status_t st;
            fxl_draw_t d;
            uint32_t crc_raw, crc_host;
            int32_t y;
            const char *missing;

            det_draw_settings(var, &d);
            missing = left_out_feature(&d, &ht.tex, drawable_rgb565(), FXL_HAVE_DEPTH);
            snprintf(msg, sizeof msg, "%s %s", s.name, var->name);
            st = render(&s, &ht.tex, var, full, 0, DET_H);
            if (missing != NULL) { /* never in the default configuration */
                snprintf(msg, sizeof msg, "%s %s needs %s", s.name, var->name, missing);
                TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_UNSUPPORTED, st, msg);
                fprintf(list, "%s %s %s %08lx\n", s.name, var->name, fxl_status_name(st),
                        (unsigned long)crc32_update(0, full, sizeof full));
                refused++;
                continue;
            }
            TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_OK, st, msg);
            TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_OK, render(&s, &ht.tex, var, again, 0, DET_H), msg);
            for (y = 0; y < DET_H; y += BAND)
                TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_OK, render(&s, &ht.tex, var, banded, y, BAND), msg);
            check_repeat_and_bands(s.name, var->name);
            crc_raw = crc32_update(0, full, sizeof full);
            fxl_target_init(&whole, full, DET_W, DET_H, DET_W, FXL_PIXFMT_RGB565);
            crc_host = fxl_host_crc_target(&whole);
            TEST_ASSERT_EQUAL_HEX32_MESSAGE(crc_raw, crc_host, msg);
            fprintf(list, "%s %s %s %08lx\n", s.name, var->name, fxl_status_name(st), (unsigned long)crc_raw);
            frames++;
        }
        texture_free(&ht);
        scene_free(&s);
    }
    for (si = 0; si < pscene_count(); si++) {
        pscene_t p;
        char msg[200];
        TEST_ASSERT_EQUAL_INT(SCENE_OK, pscene_build(pscene_name(si), DET_W, DET_H, 0, &p));
        for (k = 0; k < DET_NPVARIANTS; k++) {
            const det_pvariant_t *pv = &det_pvariants[k];
            const char *missing = pipe_missing(&p, pv);
            fxl_target_t whole;
            fxl_status_t st;
            uint32_t crc_raw;
            int32_t y;

            snprintf(msg, sizeof msg, "%s %s", p.name, pv->v.name);
            st = render_pipe(&p, pv, full, 0, DET_H);
            if (missing != NULL) { /* never in the default configuration */
                snprintf(msg, sizeof msg, "%s %s needs %s", p.name, pv->v.name, missing);
                TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_UNSUPPORTED, st, msg);
                fprintf(list, "%s %s %s %08lx\n", p.name, pv->v.name, fxl_status_name(st),
                        (unsigned long)crc32_update(0, full, sizeof full));
                refused++;
                continue;
            }
            TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_OK, st, msg);
            TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_OK, render_pipe(&p, pv, again, 0, DET_H), msg);
            for (y = 0; y < DET_H; y += BAND)
                TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_OK, render_pipe(&p, pv, banded, y, BAND), msg);
            check_repeat_and_bands(p.name, pv->v.name);
            crc_raw = crc32_update(0, full, sizeof full);
            fxl_target_init(&whole, full, DET_W, DET_H, DET_W, FXL_PIXFMT_RGB565);
            TEST_ASSERT_EQUAL_HEX32_MESSAGE(crc_raw, fxl_host_crc_target(&whole), msg);
            fprintf(list, "%s %s %s %08lx\n", p.name, pv->v.name, fxl_status_name(st), (unsigned long)crc_raw);
            frames++;
        }
        pscene_free(&p);
    }
    fclose(list); /* the stress test appends its lines and "done" */
    snprintf(note, sizeof note, "%d of %d frames checked, %d need features this build lacks",
             frames, frames + refused, refused);
    TEST_MESSAGE(note);
    /* 8 scenes x 9 variants + 6 pipeline scenes x 4 when this was written;
     * at least the gallery's */
    TEST_ASSERT_GREATER_OR_EQUAL(3 * 4, frames);
}

/* One stress case after its draw: nothing outside the clip rectangle
 * changed (pixels, and depth where the target took the buffer, in the whole
 * buffer, not only the case's rows). A failed triangle draw changes nothing
 * at all; a failed mesh draw (mesh) may have drawn the triangles before its
 * error (pipeline.h). px0, dp0 hold the buffers as the draw found them (a
 * depth band the case cleared is 0 inside its clip). Returns the pixels the
 * draw changed. */
static uint32_t check_stress_case(uint32_t k, const det_stress_case_t *c, fxl_status_t st, int mesh,
                                  const uint16_t *px0, const uint16_t *dp0)
{
    uint32_t changed = 0;
    int32_t i;
    for (i = 0; i < DET_STRESS_BUF; i++) {
        /* the buffer's geometry as the case made it, not as tg says */
        const int32_t col = i % c->stride, row = i / c->stride;
        const int32_t fx = c->origin_x + col, fy = c->origin_y + row;
        const int inside = (st == FXL_OK || mesh) && i < c->buf_len && fx >= c->clip.x0 && fx < c->clip.x1 &&
                           fy >= c->clip.y0 && fy < c->clip.y1;
        char msg[120];
        if (inside) {
            changed += c->pixels[i] != px0[i];
            continue;
        }
        if (c->pixels[i] == px0[i] && c->depth[i] == dp0[i])
            continue; /* the message only for a failure: 20,000 cases x 7,168 elements */
        snprintf(msg, sizeof msg, "%s case %lu (%s): buffer element %ld (row %ld, column %ld)",
                 mesh ? "front-end stress" : "stress",
                 (unsigned long)k, fxl_status_name(st), (long)i, (long)row, (long)col);
        TEST_ASSERT_EQUAL_HEX32_MESSAGE(px0[i], c->pixels[i], msg);
        TEST_ASSERT_EQUAL_HEX32_MESSAGE(dp0[i], c->depth[i], msg);
    }
    return changed;
}

#define STRESS_LINES (DET_STRESS_ALL / DET_STRESS_LINE)
#define STRESS_GOLDEN "golden/stress_hash.txt"

/* The stress lines must equal tests/golden/stress_hash.txt (comments
 * skipped) line for line: the builds agree with each other (determinism.sh)
 * and, here, with what the core printed when the file was written, so a
 * change of its output on extreme inputs is a decision, not an accident. */
static void check_stress_golden(char got[][64])
{
    char path[1024], line[256], msg[2048];
    FILE *f;
    int n = 0;
#ifdef FXL_TEST_SOURCE_DIR
    snprintf(path, sizeof path, "%s/%s", FXL_TEST_SOURCE_DIR, STRESS_GOLDEN);
#else
    snprintf(path, sizeof path, "%s", STRESS_GOLDEN); /* cwd is tests/ */
#endif
    f = fopen(path, "r");
    snprintf(msg, sizeof msg, "cannot read %s", path);
    TEST_ASSERT_TRUE_MESSAGE(f != NULL, msg);
    while (fgets(line, sizeof line, f) != NULL) {
        line[strcspn(line, "\r\n")] = '\0';
        if (line[0] == '#' || line[0] == '\0')
            continue;
        if (n < STRESS_LINES && strcmp(line, got[n]) != 0) {
            fclose(f);
            snprintf(msg, sizeof msg,
                     "stress line %d is \"%s\", %s says \"%s\": the core's output on extreme inputs "
                     "changed; once that is understood, regenerate the file as its header says",
                     n + 1, got[n], path, line);
            TEST_FAIL_MESSAGE(msg);
        }
        n++;
    }
    fclose(f);
    snprintf(msg, sizeof msg, "%s has %d stress lines, the list %d", path, n, STRESS_LINES);
    TEST_ASSERT_EQUAL_INT_MESSAGE(STRESS_LINES, n, msg);
}

/* Every stress case, triangles and then meshes through the front end,
 * held to check_stress_case; its line appended to the list as det_main
 * prints it, and with every feature compared with the golden lines. */
void test_determinism_stress_cases_write_only_inside_their_clip(void)
{
    static det_stress_assets_t assets;
    static det_stress_fe_case_t mesh_case;
    static uint16_t px[DET_STRESS_BUF], dp[DET_STRESS_BUF], px0[DET_STRESS_BUF], dp0[DET_STRESS_BUF];
    static char lines[STRESS_LINES][64];
    FILE *list = open_list("a");
    uint32_t k, drawn[2] = {0, 0}, pixels[2] = {0, 0}; /* [0] triangles, [1] meshes */
    char note[160];

    TEST_ASSERT_TRUE_MESSAGE(list != NULL, "cannot append to determinism_crcs.txt in FXL_TEST_OUTPUT_DIR");
    det_stress_assets_init(&assets);
    for (k = 0; k < DET_STRESS_ALL; k += DET_STRESS_LINE) {
        uint32_t j, first, hash = 0, ok = 0;
        const int mesh = det_stress_is_mesh(k, &first);
        for (j = k; j < k + DET_STRESS_LINE; j++) {
            det_stress_case_t tri_case;
            const det_stress_case_t *c = det_stress_prepare(j, &assets, px, dp, &tri_case, &mesh_case);
            fxl_status_t st;
            uint32_t index;
            memcpy(px0, px, sizeof px);
            memcpy(dp0, dp, sizeof dp);
            hash = det_stress_run(j, &tri_case, &mesh_case, hash, &st);
            ok += st == FXL_OK;
            (void)det_stress_is_mesh(j, &index);
            pixels[mesh] += check_stress_case(index, c, st, mesh, px0, dp0);
        }
        drawn[mesh] += ok;
        snprintf(lines[k / DET_STRESS_LINE], sizeof lines[0], "%s %lu ok %lu %08lx", det_stress_line_name(k),
                 (unsigned long)first, (unsigned long)ok, (unsigned long)hash);
        fprintf(list, "%s\n", lines[k / DET_STRESS_LINE]);
    }
    fprintf(list, "done\n");
    fclose(list);
    snprintf(note, sizeof note,
             "%lu triangle cases: %lu drawn, %lu pixels changed; %lu mesh cases: %lu drawn, %lu pixels changed",
             (unsigned long)DET_STRESS_CASES, (unsigned long)drawn[0], (unsigned long)pixels[0],
             (unsigned long)DET_STRESS_FE_CASES, (unsigned long)drawn[1], (unsigned long)pixels[1]);
    TEST_MESSAGE(note);
    /* The cases must reach the span loops, or the list compares nothing.
     * With every feature: 13,174 triangle cases draw and change 1,689,308
     * pixels, 2,773 mesh cases draw and change 190,357 (min builds without
     * the generic walk refuse all but a few). */
    TEST_ASSERT_GREATER_OR_EQUAL(1, drawn[0]);
    if (FXL_HAVE_DEPTH && FXL_HAVE_BILINEAR && FXL_HAVE_MIPMAP && FXL_HAVE_AUTO && FXL_HAVE_GENERIC) {
        TEST_ASSERT_GREATER_OR_EQUAL(12500, drawn[0]);
        TEST_ASSERT_GREATER_OR_EQUAL(1400000, pixels[0]);
        TEST_ASSERT_GREATER_OR_EQUAL(2500, drawn[1]);
        TEST_ASSERT_GREATER_OR_EQUAL(150000, pixels[1]);
        /* AUTO's quadratic segments and reciprocal runs choose other
         * pixels within the budget: the golden lines are every feature's */
        if (FXL_HAVE_QUAD && FXL_HAVE_RR && FXL_TEST_DEFAULT_GRID)
            check_stress_golden(lines);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_determinism_repeat_bands_and_crc_list);
    RUN_TEST(test_determinism_stress_cases_write_only_inside_their_clip);
    return UNITY_END();
}
