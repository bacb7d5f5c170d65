/* bench.c - fixel-bench: the speed-versus-accuracy benchmark (issue 4).
 *
 *   fixel-bench accuracy [--scene S] [--method M] [--filter F] [--runs N]
 *                        [--host-ir FILE] [--m4 FILE] [--m0 FILE] [--rv32 FILE]
 *                        [--m4-os FILE] [--csv FILE] [--plot-dir DIR]
 *       every scene x method x filter: coverage, texel-coordinate error,
 *       image error (all against the reference renderer), host Mpixels/s;
 *       joins the instruction counts gathered by bench.sh and writes the CSV
 *       (docs/bench/README.md documents the columns), the gnuplot data files
 *       and a summary table on stdout.
 *   fixel-bench draw [--scene S] [--method M] [--filter F] [--mip none|nearest|linear]
 *       one frame of each configuration (--mip overrides the filter's mip
 *       mode: bilinear --mip nearest is per-segment LOD on the nearest
 *       level, issue 3's figure), for callgrind: with valgrind's
 *       client requests it dumps the counters after each configuration
 *       under the name "scene/method/filter" (run with --collect-atstart=no
 *       --toggle-collect=fxl_draw_triangle so only the draw calls count).
 *   fixel-bench gen-fw OUT.c [--filters point,bilinear,trilinear] [--meshes 1]
 *                        [--mip none|nearest|linear]
 *       the scenes' triangles, textures and the configuration list as C
 *       arrays for the firmware in bench/ (both sides use the same data);
 *       --meshes 1 adds the front-end benchmark's meshes; --mip as for draw
 *       (point --mip nearest: the nearest of the texture's levels).
 *   fixel-bench ram
 *       the memory the caller provides per scene (frame, depth, bands,
 *       texture level 0 and whole chain, vertex data).
 *   fixel-bench frontend-run [--cache N]
 *       the front end alone (fxl_pipeline_emit into a callback that does
 *       nothing) on each mesh x level (transform, + light, + texgen) x vertex
 *       cache (off, on), for callgrind (--toggle-collect=fxl_pipeline_emit):
 *       counters dumped per configuration as "fe/mesh/level/cache". The
 *       set-up is bench/bench_frontend.h, shared with the firmware. --cache
 *       gives the cached runs N entries (1 .. BENCH_FE_CACHE; default all),
 *       to measure a partial cache (docs/pipeline.md).
 *   fixel-bench frontend [--host-ir FILE] [--m4 FW_OUT] [--m0 FW_OUT] [--csv FILE]
 *       joins those host counts ("mesh level cache Ir" lines) and the
 *       firmwares' "fe" lines (semihosting output, converted with its
 *       "calib" line) into instructions per unique vertex and per triangle
 *       corner; CSV (docs/bench/README.md) and a table on stdout.
 *   fixel-bench count-trace NM_FILE < trace
 *       count QEMU exec-trace instructions inside the functions listed by
 *       `arm-none-eabi-nm -S` (NM_FILE), one line per bench_begin ..
 *       bench_end segment of the firmware.
 *
 * Instruction counts are divided by *covered* pixels: the sum over the
 * scene's triangles of the pixels their coverage includes (what reaches the
 * span loops, before the depth test). Progress goes to stderr.
 * Exit status: 0 success, 1 a failure, 2 a bad command line.
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bench_lib.h"
#include "fixel/fixel.h"
#include "metrics.h"
#include "reference.h"
#include "scene.h"
#include "textures.h"
#include "timing.h"
#include "meshes.h"
#include "../../src/raster_int.h"
#include "../../bench/bench_frontend.h"

#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define BENCH_HAVE_CALLGRIND 1
#endif
#endif
#ifndef BENCH_HAVE_CALLGRIND
#define BENCH_HAVE_CALLGRIND 0
#define CALLGRIND_DUMP_STATS_AT(s) ((void)(s))
#endif

#define W SCENE_DEFAULT_WIDTH
#define H SCENE_DEFAULT_HEIGHT
#define NPIX ((size_t)W * (size_t)H)

typedef struct method {
    const char *name;
    int16_t persp;
    int seg_len;      /* pixels between exact points: 0 affine, -1 adaptive */
} method_t;

typedef struct filter {
    const char *name;
    uint8_t filter, mip;
} filter_t;

static const char *const scenes[] = {"floor", "floor_rolled", "cube", "tunnel", "small_tris", "quad_near"};
static const method_t methods[] = {{"affine", FXL_PERSP_AFFINE, 0}, {"subdiv4", 4, 4},   {"subdiv8", 8, 8},
                                   {"subdiv16", 16, 16},           {"subdiv32", 32, 32}, {"subdiv64", 64, 64},
                                   {"exact", FXL_PERSP_EXACT, 1},   {"auto", FXL_PERSP_AUTO, -1}};
/* Point and bilinear sample level 0 (the fast RGB565 loops); trilinear uses
 * the whole chain with per-segment LOD. */
static const filter_t filters[] = {{"point", FXL_FILTER_POINT, FXL_MIP_NONE},
                                   {"bilinear", FXL_FILTER_BILINEAR, FXL_MIP_NONE},
                                   {"trilinear", FXL_FILTER_BILINEAR, FXL_MIP_LINEAR}};
#define NSCENES (sizeof scenes / sizeof scenes[0])
#define NMETHODS (sizeof methods / sizeof methods[0])
#define NFILTERS (sizeof filters / sizeof filters[0])

typedef struct options {
    const char *scene, *method, *filter;
    int runs;
    const char *host_ir, *m4, *m0, *rv32, *m4_os, *csv, *plot_dir;
    const char *fw_filters;
    int fw_meshes;
    const char *mip;   /* draw, gen-fw: none|nearest|linear overrides the filter's mip mode */
    const char *tint;  /* draw: RGB565 in hex, MODULATE by that flat colour (FXL_FAST_TINT) */
    int cache;         /* frontend-run: entries of the "on" vertex cache (0: BENCH_FE_CACHE) */
} options_t;

/* The filter's mip mode, or the one --mip names (draw, gen-fw) */
static uint8_t mip_of(const options_t *o, const filter_t *f)
{
    if (!o->mip)
        return f->mip;
    return strcmp(o->mip, "nearest") == 0 ? FXL_MIP_NEAREST
                                          : (strcmp(o->mip, "linear") == 0 ? FXL_MIP_LINEAR : FXL_MIP_NONE);
}

static void usage(FILE *f)
{
    fprintf(f,
            "usage: fixel-bench COMMAND [options]   (make bench runs them all: host_sim/scripts/bench.sh)\n"
            "  accuracy [--scene S] [--method M] [--filter F] [--runs N] [--host-ir FILE]\n"
            "           [--m4 FILE] [--m0 FILE] [--rv32 FILE] [--m4-os FILE] [--csv FILE] [--plot-dir DIR]\n"
            "      every scene x method x filter against the reference: coverage, texel\n"
            "      error, PSNR, host Mpixels/s; joins instruction counts; writes the CSV\n"
            "  draw [--scene S] [--method M] [--filter F] [--mip none|nearest|linear] [--tint RGB565HEX]\n"
            "      one frame of each configuration, for callgrind:\n"
            "      valgrind --tool=callgrind --collect-atstart=no \\\n"
            "               --toggle-collect=fxl_draw_triangle fixel-bench draw --scene floor\n"
            "  gen-fw OUT.c [--filters point,bilinear,trilinear] [--meshes 1] [--mip none|nearest|linear]\n"
            "      scenes, textures and configurations as C arrays for the firmware in bench/\n"
            "  ram                     caller-provided memory per scene\n"
            "  frontend-run [--cache N]  the 3D front end alone, for callgrind; N entries\n"
            "      in the cached runs (default 1024: every mesh whole)\n"
            "  frontend [--host-ir FILE] [--m4 OUT] [--m0 OUT] [--csv FILE]\n"
            "      front-end instructions per vertex and per corner\n"
            "  count-trace NM_FILE < qemu-trace\n"
            "      count qemu exec-trace instructions inside the functions of NM_FILE\n"
            "  S: floor floor_rolled cube tunnel small_tris quad_near; M: affine subdiv4\n"
            "  subdiv8 subdiv16 subdiv32 subdiv64 exact auto; F: point bilinear trilinear\n"
            "  (details: the comment at the top of host_sim/tools/bench.c)\n");
}

/* fclose with the write error reported: a full disk or "--csv /dev/full"
 * used to end in exit status 0 with a truncated file. */
static int close_out(FILE *f, const char *path)
{
    int bad = ferror(f) != 0;
    if (fclose(f) != 0)
        bad = 1;
    if (bad)
        fprintf(stderr, "fixel-bench: write error on %s\n", path);
    return bad ? -1 : 0;
}

/* Remove a partial output, but only a regular file: "gen-fw /dev/full" must
 * not delete the device node (as root). */
static void remove_partial(const char *path)
{
    struct stat st;
    if (stat(path, &st) == 0 && S_ISREG(st.st_mode))
        remove(path);
}

static int selected(const char *want, const char *name)
{
    return !want || strcmp(want, name) == 0;
}

static void draw_settings(const method_t *m, const filter_t *f, const fxl_texture_t *tex, fxl_draw_t *d)
{
    fxl_draw_defaults(d);
    d->texture = tex;
    d->persp = m->persp;
    d->filter = f->filter;
    d->mip = f->mip;
    d->lod = FXL_LOD_SEGMENT;
    d->depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
}

static fxl_status_t draw_scene(const scene_t *s, const fxl_draw_t *d, fxl_target_t *t)
{
    uint32_t i;
    for (i = 0; i < s->tri_count; i++) {
        fxl_status_t st = fxl_draw_triangle(t, d, &s->verts[3u * i], NULL);
        if (st != FXL_OK)
            return st;
    }
    return FXL_OK;
}

/* ---- the probe: exact per-pixel u, v of the core ----------------------------- */

typedef struct probe {
    const uint16_t *base;
    uint8_t *count;       /* triangles whose span covered the pixel */
    int32_t *tri;         /* the one that passed the depth test last, -1 none */
    uint32_t *u, *v;      /* its level-0 q16 coordinates (modular) */
    int32_t cur;          /* triangle being drawn */
    int off_level0;       /* a segment sampled another level (its u, v are not level 0's) */
} probe_t;

/* The probe hook has no user pointer; this tool is single-threaded. */
static probe_t *g_probe;

/* Replaces the span loop: counts coverage, applies the core's depth rule
 * (draw when inv_w >> 16 > stored, then store) and records u, v. */
static uint32_t probe_seg(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    probe_t *p = g_probe;
    int32_t i;
    if (s->lvl && s->lvl != &tri->level[0])
        p->off_level0 = 1;
    for (i = 0; i < s->n; i++) {
        size_t k = (size_t)(s->dst - p->base) + (size_t)i;
        uint32_t zz = (s->z + (uint32_t)s->dz * (uint32_t)i) >> 16;
        if (p->count[k] < 255)
            p->count[k]++;
        if (s->zb) {
            if (zz <= s->zb[i])
                continue;
            s->zb[i] = (uint16_t)zz;
        }
        p->tri[k] = p->cur;
        p->u[k] = fxl__seg_coord(s->u, s->du, s->ddu, i);
        p->v[k] = fxl__seg_coord(s->v, s->dv, s->ddv, i);
    }
    return (uint32_t)s->n;
}

/* One probe pass of the scene drawn with d (its u, v must be level-0
 * texels): per pixel coverage into p->count, and the texel error against
 * the exact reference over the mask into *err, with the share of pixels
 * whose point-sampled texel differs and the covered-pixel total. */
static int probe_pass(const scene_t *s, const fxl_draw_t *d, probe_t *p, frame_t *pf, const ref_image *refs,
                      const uint8_t *mask, double *errs, uint32_t tw, uint32_t th, metrics_summary *err,
                      double *wrong_share, uint64_t *covered)
{
    size_t k, n = 0, wrong = 0;
    uint32_t i;
    memset(p->count, 0, NPIX);
    for (k = 0; k < NPIX; k++)
        p->tri[k] = -1;
    p->base = pf->target.pixels;
    p->off_level0 = 0;
    (void)fxl_target_clear_depth(&pf->target);
    g_probe = p;
    for (i = 0; i < s->tri_count; i++) {
        fxl_status_t st;
        p->cur = (int32_t)i;
        st = fxl__draw_triangle_with(&pf->target, d, &s->verts[3u * i], NULL, probe_seg);
        if (st != FXL_OK) {
            fprintf(stderr, "fixel-bench: probe pass: %s\n", fxl_status_name(st));
            return 1;
        }
    }
    *covered = 0;
    for (k = 0; k < NPIX; k++) {
        double du, dv;
        uint32_t tx, ty;
        *covered += p->count[k];
        if (!mask[k] || p->tri[k] != refs[0].tri[k])
            continue;
        du = bench_wrap_diff(p->u[k], refs[0].u[k], tw);
        dv = bench_wrap_diff(p->v[k], refs[0].v[k], th);
        errs[n++] = hypot(du, dv);
        tx = (p->u[k] >> 16) & (tw - 1u);
        ty = (p->v[k] >> 16) & (th - 1u);
        if ((int32_t)tx != refs[0].tex_x[k] || (int32_t)ty != refs[0].tex_y[k])
            wrong++;
    }
    (void)metrics_summarize(errs, n, err);
    *wrong_share = n ? (double)wrong / (double)n : 0;
    return 0;
}

/* ---- analytic bound of affine segments --------------------------------------- */

/* K such that the bound for segment length L is K * L^2: the largest
 * |(du/dx, dv/dx)| |q'| / (4 q) over the pixels the reference drew. */
static double scene_bound_k(const scene_t *s, const ref_image *ref, uint32_t tw, uint32_t th)
{
    double kmax = 0;
    int32_t x, y;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            size_t k = (size_t)y * W + (size_t)x;
            const fxl_vertex_t *t;
            double X[3], Y[3], A, db[3], b[3], q = 0, dq = 0, u, v, du[2], dv[2], px = x + 0.5, py = y + 0.5;
            int i;
            if (!ref->drawn[k] || ref->tri[k] < 0)
                continue;
            t = &s->verts[3 * (size_t)ref->tri[k]];
            for (i = 0; i < 3; i++) {
                X[i] = ref_snap(t[i].x) / (double)(1 << FXL_SUBPIXEL_BITS);
                Y[i] = ref_snap(t[i].y) / (double)(1 << FXL_SUBPIXEL_BITS);
            }
            A = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
            if (A == 0 || ref_uv_at(t, px, py, 0, &u, &v, du, dv) != 0)
                continue;
            b[1] = ((px - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (py - Y[0])) / A;
            b[2] = ((X[1] - X[0]) * (py - Y[0]) - (px - X[0]) * (Y[1] - Y[0])) / A;
            b[0] = 1 - b[1] - b[2];
            db[1] = (Y[2] - Y[0]) / A;
            db[2] = -(Y[1] - Y[0]) / A;
            db[0] = -db[1] - db[2];
            for (i = 0; i < 3; i++) {
                q += b[i] * (double)t[i].inv_w;
                dq += db[i] * (double)t[i].inv_w;
            }
            {
                double g = hypot(du[0] * tw, dv[0] * th);
                double kk = bench_affine_bound(1.0, g, q, dq);
                if (kk > kmax)
                    kmax = kk;
            }
        }
    return kmax;
}

/* ---- instruction counts gathered by bench.sh ----------------------------------- */

typedef struct counts {
    char key[NSCENES][NMETHODS][NFILTERS];
    double val[NSCENES][NMETHODS][NFILTERS];
    char src[NSCENES][NMETHODS][NFILTERS][8];
} counts_t;

static int index_of(const char *const *names, size_t n, size_t stride, const char *name)
{
    size_t i;
    for (i = 0; i < n; i++) {
        const char *s = *(const char *const *)((const char *)names + i * stride);
        if (strcmp(s, name) == 0)
            return (int)i;
    }
    return -1;
}

/* Lines "scene method filter count [source]"; '#' comments ignored. */
static int read_counts(const char *path, counts_t *c)
{
    FILE *f;
    char line[256];
    memset(c, 0, sizeof *c);
    if (!path)
        return 0;
    f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "fixel-bench: cannot read %s (its column stays empty)\n", path);
        return 0;
    }
    while (fgets(line, sizeof line, f)) {
        /* src fits the table's field (8 bytes): "trace" or "icount" */
        char sc[64], me[64], fi[64], src[8] = "";
        double v;
        int a, b, d;
        if (line[0] == '#' || sscanf(line, "%63s %63s %63s %lf %7s", sc, me, fi, &v, src) < 4)
            continue;
        a = index_of(scenes, NSCENES, sizeof scenes[0], sc);
        b = index_of(&methods[0].name, NMETHODS, sizeof methods[0], me);
        d = index_of(&filters[0].name, NFILTERS, sizeof filters[0], fi);
        if (a < 0 || b < 0 || d < 0)
            continue;
        c->key[a][b][d] = 1;
        c->val[a][b][d] = v;
        snprintf(c->src[a][b][d], sizeof c->src[a][b][d], "%s", src);
    }
    fclose(f);
    return 0;
}

/* ---- accuracy (and everything else) -------------------------------------------- */

typedef struct row {
    int valid;
    uint64_t covered;
    metrics_coverage cov;
    metrics_summary err;
    double wrong_share, psnr, max_diff, bound, mpix, host_ipp, m4_ipp, m0_ipp, rv32_ipp, m4_os_ipp;
    char m4_src[8];
} row_t;

static row_t rows[NSCENES][NMETHODS][NFILTERS];

static double time_frame(const scene_t *s, const fxl_draw_t *d, frame_t *fr, int runs)
{
    double t[15];
    int r;
    if (runs > 15)
        runs = 15;
    for (r = 0; r < runs; r++) {
        int frames = 0;
        uint64_t total = 0;
        while (total < 20000000u || frames < 2) {   /* >= 20 ms of drawing per run */
            uint64_t t0;
            (void)fxl_target_clear(&fr->target, 0);
            (void)fxl_target_clear_depth(&fr->target);
            t0 = timing_now_ns();
            (void)draw_scene(s, d, &fr->target);
            total += timing_now_ns() - t0;
            frames++;
        }
        t[r] = (double)total / 1e9 / frames;
    }
    return timing_median(t, (size_t)runs);
}

static int run_scene(size_t si, const options_t *o)
{
    scene_t s;
    host_texture_t tex;
    ref_image refs[NFILTERS];
    probe_t pr;
    frame_t fr, pf;
    uint8_t *refcount = NULL, *mask = NULL;
    double *errs = NULL, K = 0;
    size_t mi, fi, k;
    int rc = 1;

    memset(refs, 0, sizeof refs);
    memset(&pr, 0, sizeof pr);
    memset(&fr, 0, sizeof fr);
    memset(&pf, 0, sizeof pf);
    if (scene_build(scenes[si], W, H, &s) != SCENE_OK) {
        fprintf(stderr, "fixel-bench: scene %s failed\n", scenes[si]);
        return 1;
    }
    if (texture_make(&tex, s.texture) != 0) {
        scene_free(&s);
        return 1;
    }
    pr.count = calloc(NPIX, 1);
    pr.tri = malloc(NPIX * sizeof(int32_t));
    pr.u = malloc(NPIX * sizeof(uint32_t));
    pr.v = malloc(NPIX * sizeof(uint32_t));
    refcount = malloc(NPIX);
    mask = malloc(NPIX);
    errs = malloc(NPIX * sizeof(double));
    if (!pr.count || !pr.tri || !pr.u || !pr.v || !refcount || !mask || !errs ||
        frame_alloc(&fr, W, H, FXL_PIXFMT_RGB565, 1) != 0 || frame_alloc(&pf, W, H, FXL_PIXFMT_RGB565, 1) != 0)
        goto out;

    /* References: exact perspective, one per filter (u, v do not depend on it). */
    for (fi = 0; fi < NFILTERS; fi++) {
        ref_params p;
        fxl_status_t st;
        if (!selected(o->filter, filters[fi].name) && fi != 0)
            continue;
        ref_params_init(&p, W, H);
        draw_settings(&methods[6], &filters[fi], &tex.tex, &p.draw);
        p.depth_enabled = 1;
        st = ref_render(&p, s.verts, (int)s.tri_count, &refs[fi]);
        if (st != FXL_OK) {
            fprintf(stderr, "fixel-bench: reference of %s/%s: %s\n", scenes[si], filters[fi].name,
                    fxl_status_name(st));
            goto out;
        }
    }
    for (k = 0; k < NPIX; k++) {
        refcount[k] = refs[0].covered[k];
        mask[k] = (uint8_t)(refs[0].drawn[k] && !refs[0].depth_tie[k]);
    }
    K = scene_bound_k(&s, &refs[0], tex.width, tex.height);

    for (mi = 0; mi < NMETHODS; mi++) {
        fxl_draw_t d;
        metrics_coverage cov;
        metrics_summary err, err_f;
        double wrong_share = 0, wrong_share_f = 0;
        uint64_t covered = 0, covered_f = 0;
        if (!selected(o->method, methods[mi].name))
            continue;
        fprintf(stderr, "  %s %s\n", scenes[si], methods[mi].name);
        /* Probe pass: level 0 (FXL_MIP_NONE) so u, v are level-0 texels. */
        draw_settings(&methods[mi], &filters[0], &tex.tex, &d);
        if (probe_pass(&s, &d, &pr, &pf, refs, mask, errs, tex.width, tex.height, &err, &wrong_share, &covered) != 0)
            goto out;
        (void)metrics_coverage_compare(refcount, pr.count, NPIX, &cov);

        for (fi = 0; fi < NFILTERS; fi++) {
            row_t *r = &rows[si][mi][fi];
            metrics_image im;
            double sec;
            if (!selected(o->filter, filters[fi].name))
                continue;
            draw_settings(&methods[mi], &filters[fi], &tex.tex, &d);
            err_f = err;
            wrong_share_f = wrong_share;
            if (d.mip != FXL_MIP_NONE) {
                /* The filter's own u, v: with mip levels AUTO cuts its
                 * segments otherwise (capped at the LOD grid, per
                 * segment more often; auto.c). The same draw biased to
                 * level 0 everywhere segments as this one does (no
                 * choice of segments reads the LOD) and reports level-0
                 * texels. */
                fxl_draw_t d0 = d;
                d0.lod_bias_q8 = INT16_MIN;
                if (probe_pass(&s, &d0, &pr, &pf, refs, mask, errs, tex.width, tex.height, &err_f, &wrong_share_f,
                               &covered_f) != 0)
                    goto out;
                if (pr.off_level0 || covered_f != covered) {
                    fprintf(stderr, "fixel-bench: %s %s %s: level-0 probe pass off level 0\n", scenes[si],
                            methods[mi].name, filters[fi].name);
                    goto out;
                }
            }
            (void)fxl_target_clear(&fr.target, 0);
            (void)fxl_target_clear_depth(&fr.target);
            if (draw_scene(&s, &d, &fr.target) != FXL_OK)
                goto out;
            (void)metrics_image_compare(&fr.target, &refs[fi], mask, &im);
            sec = o->runs > 0 ? time_frame(&s, &d, &fr, o->runs) : 0;
            r->valid = 1;
            r->covered = covered;
            r->cov = cov;
            r->err = err_f;
            r->wrong_share = wrong_share_f;
            r->psnr = im.psnr;
            r->max_diff = im.max_diff;
            r->bound = methods[mi].seg_len > 1 ? K * methods[mi].seg_len * methods[mi].seg_len : 0;
            r->mpix = sec > 0 ? (double)covered / sec / 1e6 : NAN;
        }
    }
    rc = 0;
out:
    for (fi = 0; fi < NFILTERS; fi++)
        ref_free(&refs[fi]);
    free(pr.count);
    free(pr.tri);
    free(pr.u);
    free(pr.v);
    free(refcount);
    free(mask);
    free(errs);
    frame_free(&fr);
    frame_free(&pf);
    texture_free(&tex);
    scene_free(&s);
    return rc;
}

static void fmt_num(char *buf, size_t n, double v, const char *fmt)
{
    if (isnan(v))
        buf[0] = '\0';
    else
        snprintf(buf, n, fmt, v);
}

/* Cost on the chart's x axis: M4 instructions per pixel, else host. */
static double row_cost(const row_t *r)
{
    return !isnan(r->m4_ipp) ? r->m4_ipp : r->host_ipp;
}

static int write_outputs(const options_t *o)
{
    FILE *csv = stdout;
    size_t si, mi, fi;
    if (o->csv) {
        csv = fopen(o->csv, "w");
        if (!csv) {
            fprintf(stderr, "fixel-bench: cannot write %s\n", o->csv);
            return 1;
        }
    }
    fprintf(csv, "scene,method,filter,seg_len,covered_px,cov_mismatch,drawn_twice,holes,"
                 "err_max,err_mean,err_p99,wrong_texel_share,psnr_db,max_chan_diff,bound_max,"
                 "host_mpix_s,host_ipp,m4_ipp,m4_count,m0_ipp,rv32_ipp,m4_os_ipp\n");
    for (si = 0; si < NSCENES; si++)
        for (mi = 0; mi < NMETHODS; mi++)
            for (fi = 0; fi < NFILTERS; fi++) {
                const row_t *r = &rows[si][mi][fi];
                char mp[32], hi[32], m4[32], m0[32], rv[32], m4s[32];
                uint32_t twice;
                if (!r->valid)
                    continue;
                /* drawn more often than the exact rule says (overlapping
                 * scenes legitimately cover some pixels twice) */
                twice = r->cov.count_mismatches - r->cov.holes - r->cov.extra;
                fmt_num(mp, sizeof mp, r->mpix, "%.2f");
                fmt_num(hi, sizeof hi, r->host_ipp, "%.2f");
                fmt_num(m4, sizeof m4, r->m4_ipp, "%.2f");
                fmt_num(m0, sizeof m0, r->m0_ipp, "%.2f");
                fmt_num(rv, sizeof rv, r->rv32_ipp, "%.2f");
                fmt_num(m4s, sizeof m4s, r->m4_os_ipp, "%.2f");
                fprintf(csv, "%s,%s,%s,%d,%llu,%u,%u,%u,%.6f,%.6f,%.6f,%.6f,%.2f,%.2f,%.6f,%s,%s,%s,%s,%s,%s,%s\n",
                        scenes[si], methods[mi].name, filters[fi].name, methods[mi].seg_len,
                        (unsigned long long)r->covered, r->cov.mismatches, twice, r->cov.holes, r->err.max,
                        r->err.mean, r->err.p99, r->wrong_share, r->psnr, r->max_diff, r->bound, mp, hi, m4,
                        r->m4_src, m0, rv, m4s);
            }
    if (o->csv && close_out(csv, o->csv) != 0)
        return 1;

    if (o->plot_dir) {
        char path[1024];
        FILE *sp, *lp, *pp;
        /* error_len.dat rows by increasing L: exact (1), subdiv4 .. subdiv64 */
        static const size_t by_len[] = {6, 1, 2, 3, 4, 5};
        size_t k;
        snprintf(path, sizeof path, "%s/speed_error.dat", o->plot_dir);
        sp = fopen(path, "w");
        snprintf(path, sizeof path, "%s/error_len.dat", o->plot_dir);
        lp = fopen(path, "w");
        snprintf(path, sizeof path, "%s/psnr_cost.dat", o->plot_dir);
        pp = fopen(path, "w");
        if (!sp || !lp || !pp) {
            fprintf(stderr, "fixel-bench: cannot write the plot data in %s\n", o->plot_dir);
            if (sp)
                fclose(sp);
            if (lp)
                fclose(lp);
            if (pp)
                fclose(pp);
            return 1;
        }
        /* speed_error.dat: one block per scene (gnuplot `index`), point
         * filter rows: cost, err_max, err_p99, on_front(max), method. */
        for (si = 0; si < NSCENES; si++) {
            double x[NMETHODS], y[NMETHODS];
            uint8_t front[NMETHODS];
            fprintf(sp, "# %s: cost err_max err_p99 front method\n", scenes[si]);
            for (mi = 0; mi < NMETHODS; mi++) {
                const row_t *r = &rows[si][mi][0];
                x[mi] = r->valid ? row_cost(r) : NAN;
                y[mi] = r->valid ? r->err.max : NAN;
            }
            (void)bench_pareto(x, y, NMETHODS, front);
            for (mi = 0; mi < NMETHODS; mi++) {
                const row_t *r = &rows[si][mi][0];
                if (!r->valid || isnan(x[mi]))
                    continue;
                fprintf(sp, "%.3f %.6g %.6g %d %s\n", x[mi], r->err.max > 1e-6 ? r->err.max : 1e-6,
                        r->err.p99 > 1e-6 ? r->err.p99 : 1e-6, front[mi], methods[mi].name);
            }
            fprintf(sp, "\n\n");
            /* error_len.dat: L, err_max, err_p99, bound (subdivided + exact) */
            fprintf(lp, "# %s: L err_max err_p99 bound\n", scenes[si]);
            for (k = 0; k < sizeof by_len / sizeof by_len[0]; k++) {
                const row_t *r = &rows[si][by_len[k]][0];
                mi = by_len[k];
                if (!r->valid)
                    continue;
                fprintf(lp, "%d %.6g %.6g %.6g\n", methods[mi].seg_len, r->err.max > 1e-6 ? r->err.max : 1e-6,
                        r->err.p99 > 1e-6 ? r->err.p99 : 1e-6, r->bound > 0 ? r->bound : NAN);
            }
            fprintf(lp, "\n\n");
        }
        /* psnr_cost.dat: one block per filter x scene: cost psnr method */
        for (fi = 0; fi < NFILTERS; fi++)
            for (si = 0; si < NSCENES; si++) {
                fprintf(pp, "# %s %s: cost psnr method\n", filters[fi].name, scenes[si]);
                for (mi = 0; mi < NMETHODS; mi++) {
                    const row_t *r = &rows[si][mi][fi];
                    if (!r->valid || isnan(row_cost(r)))
                        continue;
                    fprintf(pp, "%.3f %.3f %s\n", row_cost(r), r->psnr, methods[mi].name);
                }
                fprintf(pp, "\n\n");
            }
        snprintf(path, sizeof path, "%s/*.dat", o->plot_dir);
        if ((close_out(sp, path) | close_out(lp, path) | close_out(pp, path)) != 0)
            return 1;
    }

    /* Summary table */
    printf("%-13s %-9s %-9s %9s %8s %8s %9s %10s %9s %9s %8s\n", "scene", "method", "filter", "host_i/px", "M4_i/px",
           "M0_i/px", "RV32_i/px", "M4-Os_i/px", "err_max", "err_p99", "PSNR");
    for (si = 0; si < NSCENES; si++)
        for (mi = 0; mi < NMETHODS; mi++)
            for (fi = 0; fi < NFILTERS; fi++) {
                const row_t *r = &rows[si][mi][fi];
                char hi[32], m4[32], m0[32], rv[32], m4s[32];
                if (!r->valid)
                    continue;
                fmt_num(hi, sizeof hi, r->host_ipp, "%.1f");
                fmt_num(m4, sizeof m4, r->m4_ipp, "%.1f");
                fmt_num(m0, sizeof m0, r->m0_ipp, "%.1f");
                fmt_num(rv, sizeof rv, r->rv32_ipp, "%.1f");
                fmt_num(m4s, sizeof m4s, r->m4_os_ipp, "%.1f");
                printf("%-13s %-9s %-9s %9s %8s %8s %9s %10s %9.4f %9.4f %8.2f\n", scenes[si], methods[mi].name,
                       filters[fi].name, hi, m4, m0, rv, m4s, r->err.max, r->err.p99, r->psnr);
            }
    return 0;
}

/* A configuration's count per covered pixel, NAN where the file had none. */
static double per_pixel(const counts_t *c, size_t si, size_t mi, size_t fi, double px)
{
    return c->key[si][mi][fi] ? c->val[si][mi][fi] / px : NAN;
}

static int cmd_accuracy(const options_t *o)
{
    static counts_t hc, m4c, m0c, rvc, m4sc;
    size_t si, mi, fi;
    (void)read_counts(o->host_ir, &hc);
    (void)read_counts(o->m4, &m4c);
    (void)read_counts(o->m0, &m0c);
    (void)read_counts(o->rv32, &rvc);
    (void)read_counts(o->m4_os, &m4sc);
    for (si = 0; si < NSCENES; si++) {
        if (!selected(o->scene, scenes[si]))
            continue;
        fprintf(stderr, "fixel-bench: %s\n", scenes[si]);
        if (run_scene(si, o) != 0)
            return 1;
    }
    for (si = 0; si < NSCENES; si++)
        for (mi = 0; mi < NMETHODS; mi++)
            for (fi = 0; fi < NFILTERS; fi++) {
                row_t *r = &rows[si][mi][fi];
                double px = r->covered ? (double)r->covered : NAN;
                r->host_ipp = per_pixel(&hc, si, mi, fi, px);
                r->m4_ipp = per_pixel(&m4c, si, mi, fi, px);
                r->m0_ipp = per_pixel(&m0c, si, mi, fi, px);
                r->rv32_ipp = per_pixel(&rvc, si, mi, fi, px);
                r->m4_os_ipp = per_pixel(&m4sc, si, mi, fi, px);
                snprintf(r->m4_src, sizeof r->m4_src, "%s", m4c.src[si][mi][fi]);
            }
    return write_outputs(o);
}

/* ---- draw: one frame per configuration under callgrind ------------------------- */

static int cmd_draw(const options_t *o)
{
    size_t si, mi, fi;
    printf("# client requests: %s\n", BENCH_HAVE_CALLGRIND ? "yes" : "no");
    for (si = 0; si < NSCENES; si++) {
        scene_t s;
        host_texture_t tex;
        frame_t fr;
        if (!selected(o->scene, scenes[si]))
            continue;
        if (scene_build(scenes[si], W, H, &s) != SCENE_OK)
            return 1;
        if (texture_make(&tex, s.texture) != 0 || frame_alloc(&fr, W, H, FXL_PIXFMT_RGB565, 1) != 0) {
            scene_free(&s);
            return 1;
        }
        for (mi = 0; mi < NMETHODS; mi++)
            for (fi = 0; fi < NFILTERS; fi++) {
                fxl_draw_t d;
                char name[128];
                if (!selected(o->method, methods[mi].name) || !selected(o->filter, filters[fi].name))
                    continue;
                draw_settings(&methods[mi], &filters[fi], &tex.tex, &d);
                d.mip = mip_of(o, &filters[fi]);
                if (o->tint) {
                    d.texenv = FXL_TEXENV_MODULATE;
                    d.color = (uint16_t)strtoul(o->tint, NULL, 16);
                }
                (void)fxl_target_clear(&fr.target, 0);
                (void)fxl_target_clear_depth(&fr.target);
                if (draw_scene(&s, &d, &fr.target) != FXL_OK)
                    return 1;
                snprintf(name, sizeof name, "%s/%s/%s", scenes[si], methods[mi].name, filters[fi].name);
                CALLGRIND_DUMP_STATS_AT(name);
                printf("%s\n", name);
            }
        frame_free(&fr);
        texture_free(&tex);
        scene_free(&s);
    }
    return 0;
}

/* ---- frontend: instructions per vertex of the 3D front end ----------------------- */

typedef struct fe_mesh {
    const char *name;
    uint8_t texgen;
} fe_mesh_t;

/* The UV sphere of the gallery (32 x 16, spherical texgen, seam column
 * and pole fans), the cube (24 vertices, cube map) and a tunnel (24 x 16
 * cylinder seen from outside, cylindrical texgen). */
static const fe_mesh_t fe_meshes[] = {{"sphere", FXL_TEXGEN_SPHERICAL},
                                      {"cube", FXL_TEXGEN_CUBE},
                                      {"tunnel", FXL_TEXGEN_CYLINDRICAL}};
#define NFE_MESHES (sizeof fe_meshes / sizeof fe_meshes[0])

static int fe_mesh_build(size_t i, fxl_mesh_t *m)
{
    switch (i) {
    case 0: return meshes_sphere(m, 1.3, 32, 16);
    case 1: return meshes_cube(m, 1.0);
    default: return meshes_cylinder(m, 1.0, -1.5, 1.5, 24, 16, 1);
    }
}

static int gen_fw_meshes(FILE *f)
{
    size_t mi;
    for (mi = 0; mi < NFE_MESHES; mi++) {
        fxl_mesh_t m;
        uint32_t i;
        const char *n = fe_meshes[mi].name;
        if (fe_mesh_build(mi, &m) != 0)
            return -1;
        if (m.vert_count > BENCH_FE_CACHE) {
            fprintf(stderr, "fixel-bench: mesh %s has more vertices than BENCH_FE_CACHE\n", n);
            meshes_free(&m);
            return -1;
        }
        fprintf(f, "\nstatic const fxl_vec3_t pos_%s[%u] = {", n, (unsigned)m.vert_count);
        for (i = 0; i < m.vert_count; i++)
            fprintf(f, "%s{%ld, %ld, %ld},", i % 4 ? " " : "\n    ", (long)m.pos[i].x, (long)m.pos[i].y,
                    (long)m.pos[i].z);
        fprintf(f, "\n};\nstatic const fxl_vec3_t nrm_%s[%u] = {", n, (unsigned)m.vert_count);
        for (i = 0; i < m.vert_count; i++)
            fprintf(f, "%s{%ld, %ld, %ld},", i % 4 ? " " : "\n    ", (long)m.normal[i].x, (long)m.normal[i].y,
                    (long)m.normal[i].z);
        fprintf(f, "\n};\nstatic const fxl_texcoord_t uv_%s[%u] = {", n, (unsigned)m.vert_count);
        for (i = 0; i < m.vert_count; i++)
            fprintf(f, "%s{%ld, %ld},", i % 6 ? " " : "\n    ", (long)m.uv[i].u, (long)m.uv[i].v);
        fprintf(f, "\n};\nstatic const uint16_t idx_%s[%u] = {", n, 3u * m.tri_count);
        for (i = 0; i < 3u * m.tri_count; i++)
            fprintf(f, "%s%u,", i % 16 ? " " : "\n    ", (unsigned)m.idx[i]);
        fprintf(f, "\n};\n");
        meshes_free(&m);
    }
    fprintf(f, "\nconst bench_mesh_t bench_meshes[%u] = {\n", (unsigned)NFE_MESHES);
    for (mi = 0; mi < NFE_MESHES; mi++) {
        fxl_mesh_t m;
        const char *n = fe_meshes[mi].name;
        if (fe_mesh_build(mi, &m) != 0)
            return -1;
        fprintf(f, "    {\"%s\", %u, {pos_%s, uv_%s, 0, nrm_%s, %uu, idx_%s, %uu}},\n", n,
                (unsigned)fe_meshes[mi].texgen, n, n, n, (unsigned)m.vert_count, n, (unsigned)m.tri_count);
        meshes_free(&m);
    }
    fprintf(f, "};\nconst uint32_t bench_nmeshes = %u;\n", (unsigned)NFE_MESHES);
    return 0;
}

static int cmd_frontend_run(const options_t *o)
{
    static fxl_vcache_entry_t cache[BENCH_FE_CACHE];
    const uint32_t entries = o->cache > 0 ? (uint32_t)o->cache : BENCH_FE_CACHE;
    size_t mi;
    int lv, c;
    printf("# client requests: %s\n", BENCH_HAVE_CALLGRIND ? "yes" : "no");
    for (mi = 0; mi < NFE_MESHES; mi++) {
        fxl_mesh_t m;
        if (fe_mesh_build(mi, &m) != 0 || m.vert_count > BENCH_FE_CACHE)
            return 1;
        for (lv = 0; lv < BENCH_FE_LEVELS; lv++)
            for (c = 0; c < 2; c++) {
                fxl_pipeline_t p;
                uint32_t ntri = 0;
                char name[96];
                if (bench_fe_setup(&p, lv, fe_meshes[mi].texgen) != FXL_OK ||
                    fxl_pipeline_set_vertex_cache(&p, c ? cache : NULL, c ? entries : 0) != FXL_OK ||
                    fxl_pipeline_emit(&p, &m, bench_fe_sink, &ntri, NULL) != FXL_OK) {
                    meshes_free(&m);
                    return 1;
                }
                snprintf(name, sizeof name, "fe/%s/%s/%d", fe_meshes[mi].name, bench_fe_level_names[lv], c);
                CALLGRIND_DUMP_STATS_AT(name);
                printf("%s %u\n", name, (unsigned)ntri);
            }
        meshes_free(&m);
    }
    return 0;
}

/* counts[mesh][level][cache], NAN when absent. 0, or -1 when `path` names
 * a file that cannot be read (NULL: no file). */
static int fe_read(const char *path, int fw, double counts[NFE_MESHES][BENCH_FE_LEVELS][2])
{
    FILE *f = path ? fopen(path, "r") : NULL;
    char line[256];
    double per_tick = NAN;
    if (!f) {
        if (!path)
            return 0;
        fprintf(stderr, "fixel-bench: cannot read %s\n", path);
        return -1;
    }
    while (fgets(line, sizeof line, f)) {
        char a[64], b[64], st[16];
        int c, lv;
        size_t mi;
        double v, calib_ticks, calib_instr;
        if (fw) {
            /* "calib <ticks> <instructions>", "fe <mesh> <level> <cache> <ticks> <ok|error>" */
            if (sscanf(line, "calib %lf %lf", &calib_ticks, &calib_instr) == 2 && calib_ticks > 0) {
                per_tick = calib_instr / calib_ticks;
                continue;
            }
            if (sscanf(line, "fe %63s %63s %d %lf %15s", a, b, &c, &v, st) != 5 || strcmp(st, "ok") != 0)
                continue;
            v *= per_tick;
        } else if (sscanf(line, "%63s %63s %d %lf", a, b, &c, &v) != 4) {
            continue;
        }
        for (mi = 0; mi < NFE_MESHES; mi++)
            for (lv = 0; lv < BENCH_FE_LEVELS; lv++)
                if (strcmp(a, fe_meshes[mi].name) == 0 && strcmp(b, bench_fe_level_names[lv]) == 0 &&
                    (c == 0 || c == 1))
                    counts[mi][lv][c] = v;
    }
    fclose(f);
    return 0;
}

static int cmd_frontend(const options_t *o)
{
    static double host[NFE_MESHES][BENCH_FE_LEVELS][2], m4[NFE_MESHES][BENCH_FE_LEVELS][2],
        m0[NFE_MESHES][BENCH_FE_LEVELS][2];
    FILE *csv = NULL;
    size_t mi;
    int lv, c;
    for (mi = 0; mi < NFE_MESHES; mi++)
        for (lv = 0; lv < BENCH_FE_LEVELS; lv++)
            for (c = 0; c < 2; c++)
                host[mi][lv][c] = m4[mi][lv][c] = m0[mi][lv][c] = NAN;
    /* a file named and unreadable is an error (it printed the message and
     * went on with empty columns, exit 0) */
    if (fe_read(o->host_ir, 0, host) != 0 || fe_read(o->m4, 1, m4) != 0 || fe_read(o->m0, 1, m0) != 0)
        return 1;
    if (o->csv) {
        csv = fopen(o->csv, "w");
        if (!csv) {
            fprintf(stderr, "fixel-bench: cannot write %s\n", o->csv);
            return 1;
        }
        fprintf(csv, "mesh,level,cache,vertices,corners,triangles,host_ir,host_per_vertex,host_per_corner,"
                     "m4_instr,m4_per_vertex,m4_per_corner,m0_instr,m0_per_vertex,m0_per_corner\n");
    }
    printf("front end, instructions per unique vertex (per triangle corner); cache 0 = off, 1 = on\n");
    printf("%-7s %-9s %5s %6s %7s %16s %16s %16s\n", "mesh", "level", "cache", "verts", "corners", "host x86-64",
           "Cortex-M4", "Cortex-M0+");
    for (mi = 0; mi < NFE_MESHES; mi++) {
        fxl_mesh_t m;
        if (fe_mesh_build(mi, &m) != 0) {
            if (csv)
                fclose(csv);
            return 1;
        }
        for (lv = 0; lv < BENCH_FE_LEVELS; lv++)
            for (c = 0; c < 2; c++) {
                double nv = m.vert_count, nc = 3.0 * m.tri_count, h = host[mi][lv][c], a = m4[mi][lv][c],
                       z = m0[mi][lv][c];
                char hs[32], as[32], zs[32];
                snprintf(hs, sizeof hs, "%.0f (%.0f)", h / nv, h / nc);
                snprintf(as, sizeof as, "%.0f (%.0f)", a / nv, a / nc);
                snprintf(zs, sizeof zs, "%.0f (%.0f)", z / nv, z / nc);
                printf("%-7s %-9s %5d %6u %7u %16s %16s %16s\n", fe_meshes[mi].name, bench_fe_level_names[lv], c,
                       (unsigned)m.vert_count, 3u * m.tri_count, isnan(h) ? "-" : hs, isnan(a) ? "-" : as,
                       isnan(z) ? "-" : zs);
                if (csv)
                    fprintf(csv, "%s,%s,%d,%u,%u,%u,%.0f,%.1f,%.1f,%.0f,%.1f,%.1f,%.0f,%.1f,%.1f\n",
                            fe_meshes[mi].name, bench_fe_level_names[lv], c, (unsigned)m.vert_count,
                            3u * m.tri_count, (unsigned)m.tri_count, h, h / nv, h / nc, a, a / nv, a / nc, z,
                            z / nv, z / nc);
            }
        meshes_free(&m);
    }
    if (csv && close_out(csv, o->csv) != 0)
        return 1;
    return 0;
}

/* ---- gen-fw: the firmware's data ---------------------------------------------- */

static int cmd_gen_fw(const char *path, const options_t *o)
{
    FILE *f = fopen(path, "w");
    size_t si, mi, fi, ncfg = 0;
    int used[TEXTURE_COUNT] = {0};
    int tex_of[NSCENES];
    int t;
    if (!f) {
        fprintf(stderr, "fixel-bench: cannot write %s\n", path);
        return 1;
    }
    fprintf(f, "/* Generated by fixel-bench gen-fw from host_sim/lib/scene.c and textures.c.\n"
               " * Do not edit; `make bench` regenerates it. */\n#include \"bench_data.h\"\n\n");
    for (si = 0; si < NSCENES; si++) {
        scene_t s;
        uint32_t i;
        if (scene_build(scenes[si], W, H, &s) != SCENE_OK) {
            fclose(f);
            return 1;
        }
        used[s.texture] = 1;
        fprintf(f, "static const fxl_vertex_t verts_%s[%u] = {\n", scenes[si], 3u * s.tri_count);
        for (i = 0; i < 3u * s.tri_count; i++) {
            const fxl_vertex_t *v = &s.verts[i];
            fprintf(f, "    {%ld, %ld, %luu, %ld, %ld, %uu},\n", (long)v->x, (long)v->y, (unsigned long)v->inv_w,
                    (long)v->u, (long)v->v, (unsigned)v->color);
        }
        fprintf(f, "};\n");
        fprintf(f, "#define NTRI_%s %uu\n\n", scenes[si], s.tri_count);
        tex_of[si] = (int)s.texture;
        scene_free(&s);
    }
    for (t = 0; t < TEXTURE_COUNT; t++) {
        host_texture_t tex;
        uint32_t i;
        if (!used[t])
            continue;
        if (texture_make(&tex, (texture_id_t)t) != 0) {
            fclose(f);
            return 1;
        }
        fprintf(f, "static const uint16_t texels_%d[%u] = {", t, tex.texel_count);
        for (i = 0; i < tex.texel_count; i++)
            fprintf(f, "%s0x%04x,", i % 12 ? " " : "\n    ", tex.texels[i]);
        fprintf(f, "\n};\n");
        fprintf(f, "static const fxl_texture_t tex_%d = {texels_%d, 0, %u, %u, %u, %u, %u, %u, %u, 0, %u, %u};\n\n", t,
                t, tex.tex.log2_w, tex.tex.log2_h, tex.tex.levels, tex.tex.format, tex.tex.wrap_u, tex.tex.wrap_v,
                tex.tex.flags, tex.tex.key, tex.tex.border);
        texture_free(&tex);
    }
    fprintf(f, "const bench_scene_t bench_scenes[%u] = {\n", (unsigned)NSCENES);
    for (si = 0; si < NSCENES; si++)
        fprintf(f, "    {\"%s\", verts_%s, NTRI_%s, &tex_%d},\n", scenes[si], scenes[si], scenes[si], tex_of[si]);
    fprintf(f, "};\n\nconst bench_cfg_t bench_cfgs[] = {\n");
    for (si = 0; si < NSCENES; si++)
        for (mi = 0; mi < NMETHODS; mi++)
            for (fi = 0; fi < NFILTERS; fi++) {
                if (!strstr(o->fw_filters, filters[fi].name) || !selected(o->scene, scenes[si]) ||
                    !selected(o->method, methods[mi].name))
                    continue;
                fprintf(f, "    {%u, %d, %u, %u, \"%s %s %s\"},\n", (unsigned)si, methods[mi].persp,
                        filters[fi].filter, mip_of(o, &filters[fi]), scenes[si], methods[mi].name, filters[fi].name);
                ncfg++;
            }
    if (ncfg == 0) {
        /* "bench_cfgs[] = {};" is not C99, and a firmware with nothing to run
         * is no benchmark: say which selection came out empty. */
        fprintf(stderr, "fixel-bench: gen-fw: no configuration matches --filters '%s'%s%s%s%s\n",
                o->fw_filters, o->scene ? " --scene " : "", o->scene ? o->scene : "",
                o->method ? " --method " : "", o->method ? o->method : "");
        fclose(f);
        remove_partial(path);
        return 1;
    }
    fprintf(f, "};\nconst uint32_t bench_ncfg = %u;\n", (unsigned)ncfg);
    if (o->fw_meshes) {
        if (gen_fw_meshes(f) != 0) {
            fclose(f);
            return 1;
        }
    } else {
        fprintf(f, "\nconst bench_mesh_t bench_meshes[1] = {{0}};\nconst uint32_t bench_nmeshes = 0;\n");
    }
    if (close_out(f, path) != 0) {
        remove_partial(path);
        return 1;
    }
    return 0;
}

static int cmd_count_trace(const char *nm)
{
    static bench_range_t ranges[4096];
    static uint64_t counts[4096];
    uint32_t begin = 0xFFFFFFFFu, end = 0xFFFFFFFFu;
    uint64_t unclosed = 0;
    long n = bench_read_nm(nm, ranges, 4096, "bench_begin", &begin, "bench_end", &end);
    size_t seg, i;
    if (n < 0) {
        fprintf(stderr, "fixel-bench: cannot read %s\n", nm);
        return 1;
    }
    if (n == 0) {
        fprintf(stderr, "fixel-bench: no function ranges in %s\n", nm);
        return 1;
    }
    if (begin == 0xFFFFFFFFu || end == 0xFFFFFFFFu) {
        fprintf(stderr, "fixel-bench: bench_begin / bench_end not in %s\n", nm);
        return 1;
    }
    seg = bench_trace_count(stdin, ranges, (size_t)n, begin, end, counts, 4096, &unclosed);
    for (i = 0; i < seg && i < 4096; i++)
        printf("%llu\n", (unsigned long long)counts[i]);
    if (unclosed)
        fprintf(stderr, "fixel-bench: the trace ended inside a measurement\n");
    return 0;
}

/* ---- ram: what the caller provides per scene ------------------------------------ */

static int cmd_ram(void)
{
    size_t si;
    const uint32_t band_rows = 24;
    printf("# RAM/flash the caller provides per scene at %dx%d RGB565 (bytes). frame: full framebuffer;\n"
           "# depth: full depth buffer; bands: two %u-row colour bands + one depth band (issue 6);\n"
           "# tex0: level 0 (point/bilinear); chain: all levels (trilinear); verts: fxl_vertex_t data\n",
           W, H, (unsigned)band_rows);
    printf("%-13s %-8s %8s %8s %8s %8s %8s %8s\n", "scene", "texture", "frame", "depth", "bands", "tex0", "chain",
           "verts");
    for (si = 0; si < NSCENES; si++) {
        scene_t s;
        host_texture_t tex;
        if (scene_build(scenes[si], W, H, &s) != SCENE_OK)
            return 1;
        if (texture_make(&tex, s.texture) != 0) {
            scene_free(&s);
            return 1;
        }
        printf("%-13s %-8s %8u %8u %8u %8u %8u %8u\n", scenes[si], texture_name(s.texture),
               (unsigned)FXL_TARGET_BYTES(W, H), (unsigned)FXL_TARGET_BYTES(W, H),
               (unsigned)(3u * FXL_TARGET_BYTES(W, band_rows)), (unsigned)(tex.width * tex.height * 2u),
               (unsigned)(tex.texel_count * 2u), (unsigned)(3u * s.tri_count * sizeof(fxl_vertex_t)));
        texture_free(&tex);
        scene_free(&s);
    }
    return 0;
}

/* A misspelt --scene, --method, --filter or --filters selected nothing, and
 * accuracy, draw and gen-fw ran empty with exit status 0; a bad --mip drew
 * without mip maps. */
static int check_names(const options_t *o)
{
    const char *bad = NULL, *what = NULL;
    size_t k;
    if (o->scene && index_of(scenes, NSCENES, sizeof scenes[0], o->scene) < 0)
        bad = o->scene, what = "--scene";
    else if (o->method && index_of(&methods[0].name, NMETHODS, sizeof methods[0], o->method) < 0)
        bad = o->method, what = "--method";
    else if (o->filter && index_of(&filters[0].name, NFILTERS, sizeof filters[0], o->filter) < 0)
        bad = o->filter, what = "--filter";
    else if (o->mip && strcmp(o->mip, "none") != 0 && strcmp(o->mip, "nearest") != 0 &&
             strcmp(o->mip, "linear") != 0)
        bad = o->mip, what = "--mip";
    else if (o->tint && (strlen(o->tint) != 4 || strspn(o->tint, "0123456789abcdefABCDEF") != 4))
        bad = o->tint, what = "--tint (4 hex digits of RGB565)";
    if (bad == NULL) {
        /* --filters: a comma-separated list of filter names */
        const char *p = o->fw_filters;
        while (*p != '\0') {
            size_t n = strcspn(p, ",");
            int found = 0;
            for (k = 0; k < NFILTERS; k++)
                if (strlen(filters[k].name) == n && strncmp(p, filters[k].name, n) == 0)
                    found = 1;
            if (!found) {
                bad = o->fw_filters, what = "--filters";
                break;
            }
            p += n;
            if (*p == ',')
                p++;
        }
    }
    if (bad != NULL) {
        fprintf(stderr, "fixel-bench: unknown %s '%s' (see --help for the names)\n", what, bad);
        return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    options_t o;
    int i;
    const char *cmd;
    memset(&o, 0, sizeof o);
    o.runs = 5;
    o.fw_filters = "point,bilinear,trilinear";
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    cmd = argv[1];
    for (i = 1; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            usage(stdout);
            return 0;
        }
    if (strcmp(cmd, "count-trace") == 0) {
        if (argc != 3) {
            usage(stderr);
            return 2;
        }
        return cmd_count_trace(argv[2]);
    }
    /* gen-fw's output file comes first: an option there was taken for it
     * (gen-fw --meshes 3 wrote a file named --meshes) */
    if (strcmp(cmd, "gen-fw") == 0 && (argc < 3 || argv[2][0] == '-' || argv[2][0] == '\0')) {
        fprintf(stderr, "fixel-bench: gen-fw needs OUT.c before its options\n");
        return 2;
    }
    /* options come in pairs: name, value */
    for (i = (strcmp(cmd, "gen-fw") == 0 ? 3 : 2); i < argc; i += 2) {
        const char *a = argv[i];
        const char **dst = NULL;
        /* an empty value is never meant: --plot-dir '' wrote into / */
        if (i + 1 >= argc || argv[i + 1][0] == '\0') {
            fprintf(stderr, "fixel-bench: %s needs a value\n", a);
            return 2;
        }
        if (strcmp(a, "--scene") == 0)
            dst = &o.scene;
        else if (strcmp(a, "--method") == 0)
            dst = &o.method;
        else if (strcmp(a, "--filter") == 0)
            dst = &o.filter;
        else if (strcmp(a, "--host-ir") == 0)
            dst = &o.host_ir;
        else if (strcmp(a, "--m4") == 0)
            dst = &o.m4;
        else if (strcmp(a, "--m0") == 0)
            dst = &o.m0;
        else if (strcmp(a, "--rv32") == 0)
            dst = &o.rv32;
        else if (strcmp(a, "--m4-os") == 0)
            dst = &o.m4_os;
        else if (strcmp(a, "--csv") == 0)
            dst = &o.csv;
        else if (strcmp(a, "--plot-dir") == 0)
            dst = &o.plot_dir;
        else if (strcmp(a, "--filters") == 0)
            dst = &o.fw_filters;
        else if (strcmp(a, "--mip") == 0)
            dst = &o.mip;
        else if (strcmp(a, "--tint") == 0)
            dst = &o.tint;
        else if (strcmp(a, "--meshes") == 0 || strcmp(a, "--runs") == 0 || strcmp(a, "--cache") == 0) {
            /* atoi took "abc" and "-5" for 0 timing runs without a word */
            char *end;
            long v = strtol(argv[i + 1], &end, 10);
            /* --runs: time_frame keeps at most 15 (it capped more silently) */
            const long least = a[2] == 'c' ? 1 : 0;
            const long most = a[2] == 'm' ? 1000000 : a[2] == 'c' ? (long)BENCH_FE_CACHE : 15;
            if (end == argv[i + 1] || *end != '\0' || v < least || v > most) {
                fprintf(stderr, "fixel-bench: %s wants a whole number %ld..%ld, got '%s'\n", a, least, most,
                        argv[i + 1]);
                return 2;
            }
            if (a[2] == 'm')
                o.fw_meshes = (int)v;
            else if (a[2] == 'c')
                o.cache = (int)v;
            else
                o.runs = (int)v;
        } else {
            fprintf(stderr, "fixel-bench: unknown option %s\n", a);
            usage(stderr);
            return 2;
        }
        if (dst)
            *dst = argv[i + 1];
    }
    if (check_names(&o) != 0)
        return 2;
    if (strcmp(cmd, "accuracy") == 0)
        return cmd_accuracy(&o);
    if (strcmp(cmd, "ram") == 0)
        return cmd_ram();
    if (strcmp(cmd, "draw") == 0)
        return cmd_draw(&o);
    if (strcmp(cmd, "frontend-run") == 0)
        return cmd_frontend_run(&o);
    if (strcmp(cmd, "frontend") == 0)
        return cmd_frontend(&o);
    if (strcmp(cmd, "gen-fw") == 0)
        return cmd_gen_fw(argv[2], &o);
    fprintf(stderr, "fixel-bench: unknown command '%s'\n", cmd);
    usage(stderr);
    return 2;
}
