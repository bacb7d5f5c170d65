/* sim.c - fixel-sim: render the built-in scenes on the PC, write PNGs, print
 * CRCs and a timing table; animate the pipeline cube; render a scene through
 * the real panel driver and band renderer into an emulated SPI panel.
 * Run with --help for the options.
 *
 * Exit status: 0 success, 1 a render or file error, 2 a bad command line.
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

#include "crc32.h"
#include "fixel/fixel.h"
#include "panel_emu.h"
#include "pipe_scenes.h"
#include "png_io.h"
#include "scene.h"
#include "textures.h"
#include "timing.h"

#define TIMING_RUNS 5

typedef struct options {
    const char *scene;
    int16_t persp;
    uint8_t filter, mip, lod;
    int16_t lod_bias_q8;
    int32_t width, height;
    int depth;
    fxl_pixfmt_t format;
    const char *out_png;
    int crc;
    const char *gallery_dir;
    int gallery_crc;
    int list;
    int animate;             /* frames, 0 = off */
    const char *panel;       /* NULL = no panel */
    int rotation, band_rows;
    int texture;             /* texture_id_t replacing the scene's, -1 = its own */
} options_t;

typedef struct named_value {
    const char *name;
    int value;
} named_value_t;

static const named_value_t persp_names[] = {
    {"affine", FXL_PERSP_AFFINE}, {"exact", FXL_PERSP_EXACT}, {"subdiv4", 4},
    {"subdiv8", 8},               {"subdiv16", 16},           {"subdiv32", 32},
    {"subdiv64", 64},             {"auto", FXL_PERSP_AUTO},   {NULL, 0}};
static const named_value_t filter_names[] = {
    {"point", FXL_FILTER_POINT}, {"bilinear", FXL_FILTER_BILINEAR}, {NULL, 0}};
static const named_value_t mip_names[] = {
    {"none", FXL_MIP_NONE}, {"nearest", FXL_MIP_NEAREST}, {"linear", FXL_MIP_LINEAR}, {NULL, 0}};
static const named_value_t lod_names[] = {
    {"segment", FXL_LOD_SEGMENT}, {"triangle", FXL_LOD_TRIANGLE}, {NULL, 0}};
static const named_value_t onoff_names[] = {{"on", 1}, {"off", 0}, {NULL, 0}};
static const named_value_t format_names[] = {
    {"rgb565", FXL_PIXFMT_RGB565}, {"rgb565swap", FXL_PIXFMT_RGB565_SWAP}, {NULL, 0}};

static void usage(FILE *f)
{
    size_t i;
    fprintf(f,
            "usage: fixel-sim [options]\n"
            "Render a built-in scene with the fixel rasterizer. Scenes named p_* go\n"
            "entirely through the fixed-point front end (fixel/pipeline.h); the others\n"
            "are projected in double precision.\n"
            "  --scene NAME        scene to render (default floor); see --list\n"
            "  --persp MODE        affine|exact|subdiv4|subdiv8|subdiv16|subdiv32|subdiv64|auto\n"
            "                      (default subdiv16)\n"
            "  --filter F          point|bilinear|trilinear (default point; trilinear is\n"
            "                      bilinear with --mip linear)\n"
            "  --mip M             none|nearest|linear (default none)\n"
            "  --lod L             segment|triangle (default segment)\n"
            "  --lod-bias B        added to the LOD, levels, -127..127 in steps of 1/256\n"
            "                      (default 0; > 0 blurrier, < 0 sharper)\n"
            "  --texture T         replace a double-precision scene's texture: checker|crate|\n"
            "                      grid|checker_hc|cubemap|checker_hc_levels (e.g. the\n"
            "                      gallery's mip comparison: --scene floor --texture\n"
            "                      checker_hc --filter trilinear)\n"
            "  --size WxH          target size, 1..%d each (default %dx%d)\n"
            "  --depth on|off      16-bit depth buffer (default on)\n"
            "  --format F          rgb565|rgb565swap (default rgb565; rgb565swap in a build\n"
            "                      with byte-swapped walks only)\n"
            "  -o FILE.png         write the frame as a PNG (with --animate: a directory)\n"
            "  --crc               print the CRC-32 of the frame's pixel bytes\n"
            "  --animate N         render N frames of the pipeline cube (p_cube) turning\n"
            "                      once about its vertical axis into -o DIR as\n"
            "                      DIR/cube_000.png, cube_001.png, ...\n"
            "  --panel P           render the scene through the real driver and band\n"
            "                      renderer into an emulated panel: st7789 (240x320),\n"
            "                      st7789-240x240, st7789-135x240, ili9341; the frame is the\n"
            "                      panel's size in --rotation; prints the wire CRC, the CRC\n"
            "                      of the panel image and OK/MISMATCH against a direct\n"
            "                      full-frame render (exit 1 on mismatch); -o writes what\n"
            "                      the panel shows\n"
            "  --rotation R        panel rotation 0..3 (x 90 degrees, default 0)\n"
            "  --band-rows N       rows per band, 1..panel height (default 24)\n"
            "  --gallery DIR       render the gallery (scene.h: every image whose CRC the\n"
            "                      tests check, at its fixed settings) into DIR and print a\n"
            "                      table; ignores the drawing options\n"
            "  --gallery-crc       print the golden CRC list of the gallery; e.g.\n"
            "                      fixel-sim --gallery-crc > tests/golden/gallery_crc.txt\n"
            "  --list              list the scenes\n"
            "  --help              this text\n"
            "scenes:",
            FXL_TARGET_MAX_DIM, SCENE_DEFAULT_WIDTH, SCENE_DEFAULT_HEIGHT);
    for (i = 0; i < scene_count(); i++) {
        fprintf(f, " %s", scene_name(i));
    }
    for (i = 0; i < pscene_count(); i++) {
        fprintf(f, " %s", pscene_name(i));
    }
    fprintf(f, "\n");
}

static int lookup(const named_value_t *t, const char *opt, const char *s, int *out)
{
    const named_value_t *p;
    for (p = t; p->name != NULL; p++) {
        if (strcmp(p->name, s) == 0) {
            *out = p->value;
            return 0;
        }
    }
    fprintf(stderr, "fixel-sim: bad value '%s' for %s (expected:", s, opt);
    for (p = t; p->name != NULL; p++) {
        fprintf(stderr, " %s", p->name);
    }
    fprintf(stderr, ")\n");
    return -1;
}

static const char *name_of(const named_value_t *t, int v)
{
    for (; t->name != NULL; t++) {
        if (t->value == v) {
            return t->name;
        }
    }
    return "?";
}

/* "point", "bilinear", "trilinear", "point+mip", ... for the summary line. */
static const char *filter_label(const fxl_draw_t *d)
{
    if (d->mip == FXL_MIP_NONE) {
        return d->filter == FXL_FILTER_POINT ? "point" : "bilinear";
    }
    if (d->mip == FXL_MIP_LINEAR) {
        return d->filter == FXL_FILTER_POINT ? "point-mip-lin" : "trilinear";
    }
    return d->filter == FXL_FILTER_POINT ? "point-mip" : "bilinear-mip";
}

static int parse_size(const char *s, int32_t *w, int32_t *h)
{
    char *end;
    long a, b;
    errno = 0;
    a = strtol(s, &end, 10);
    if (end == s || (*end != 'x' && *end != 'X') || errno != 0) {
        return -1;
    }
    s = end + 1;
    b = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno != 0) {
        return -1;
    }
    if (a < 1 || b < 1 || a > FXL_TARGET_MAX_DIM || b > FXL_TARGET_MAX_DIM) {
        return -1;
    }
    *w = (int32_t)a;
    *h = (int32_t)b;
    return 0;
}

static int parse_long(const char *s, long lo, long hi, long *out)
{
    char *end;
    long v;
    errno = 0;
    v = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno != 0 || v < lo || v > hi) {
        return -1;
    }
    *out = v;
    return 0;
}

static int parse_args(int argc, char **argv, options_t *o)
{
    static const char *const with_value[] = {
        "--scene", "--persp", "--filter", "--mip",     "--lod",      "--lod-bias", "--size",
        "--depth", "--format", "-o",      "--gallery", "--animate",  "--panel",    "--rotation",
        "--band-rows", "--texture", NULL};
    int i, v, mip_given = 0, scene_given = 0, rotation_given = 0, band_rows_given = 0;
    int format_given = 0, size_given = 0, trilinear_given = 0;
    memset(o, 0, sizeof(*o));
    o->scene = "floor";
    o->persp = 16;
    o->filter = FXL_FILTER_POINT;
    o->mip = FXL_MIP_NONE;
    o->lod = FXL_LOD_SEGMENT;
    o->width = SCENE_DEFAULT_WIDTH;
    o->height = SCENE_DEFAULT_HEIGHT;
    o->depth = 1;
    o->format = drawable_rgb565();   /* byte-swapped in a build with those walks only */
    o->band_rows = 24;
    o->texture = -1;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = NULL;
        const char *const *w;
        long n;
        for (w = with_value; *w != NULL; w++) {
            if (strcmp(a, *w) == 0) {
                /* an empty value is never meant: -o '' rendered the whole
                 * frame before the write failed */
                if (i + 1 >= argc || argv[i + 1][0] == '\0') {
                    fprintf(stderr, "fixel-sim: option %s needs a value (see --help)\n", a);
                    return -1;
                }
                val = argv[++i];
            }
        }
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            exit(0);
        } else if (strcmp(a, "--scene") == 0) {
            if (!anyscene_exists(val)) {
                fprintf(stderr, "fixel-sim: unknown scene '%s' (see --list)\n", val);
                return -1;
            }
            o->scene = val;
            scene_given = 1;
        } else if (strcmp(a, "--persp") == 0) {
            if (lookup(persp_names, a, val, &v) != 0) {
                return -1;
            }
            o->persp = (int16_t)v;
        } else if (strcmp(a, "--filter") == 0) {
            if (strcmp(val, "trilinear") == 0) {
                o->filter = FXL_FILTER_BILINEAR;
                trilinear_given = 1;
                if (!mip_given) {
                    o->mip = FXL_MIP_LINEAR;
                }
                continue;
            }
            if (lookup(filter_names, a, val, &v) != 0) {
                fprintf(stderr, "fixel-sim: (or trilinear)\n");
                return -1;
            }
            o->filter = (uint8_t)v;
            trilinear_given = 0;   /* the last --filter wins */
        } else if (strcmp(a, "--mip") == 0) {
            if (lookup(mip_names, a, val, &v) != 0) {
                return -1;
            }
            o->mip = (uint8_t)v;
            mip_given = 1;
        } else if (strcmp(a, "--lod") == 0) {
            if (lookup(lod_names, a, val, &v) != 0) {
                return -1;
            }
            o->lod = (uint8_t)v;
        } else if (strcmp(a, "--lod-bias") == 0) {
            char *end;
            double b;
            errno = 0;
            b = strtod(val, &end);
            if (end == val || *end != '\0' || errno != 0 || !(b >= -127.0 && b <= 127.0)) {
                fprintf(stderr, "fixel-sim: bad --lod-bias '%s' (expected levels, -127..127)\n",
                        val);
                return -1;
            }
            /* q8 levels: |b| <= 127 gives |b * 256| <= 32512, inside int16. */
            o->lod_bias_q8 = (int16_t)(b < 0 ? -(long)(-b * 256.0 + 0.5) : (long)(b * 256.0 + 0.5));
        } else if (strcmp(a, "--depth") == 0) {
            if (lookup(onoff_names, a, val, &v) != 0) {
                return -1;
            }
            o->depth = v;
        } else if (strcmp(a, "--format") == 0) {
            if (lookup(format_names, a, val, &v) != 0) {
                return -1;
            }
            o->format = (fxl_pixfmt_t)v;
            format_given = 1;
        } else if (strcmp(a, "--size") == 0) {
            size_given = 1;
            if (parse_size(val, &o->width, &o->height) != 0) {
                fprintf(stderr, "fixel-sim: bad --size '%s' (expected WxH, each 1..%d)\n", val,
                        FXL_TARGET_MAX_DIM);
                return -1;
            }
        } else if (strcmp(a, "-o") == 0) {
            o->out_png = val;
        } else if (strcmp(a, "--gallery") == 0) {
            o->gallery_dir = val;
        } else if (strcmp(a, "--animate") == 0) {
            if (parse_long(val, 1, 1000, &n) != 0) {
                fprintf(stderr, "fixel-sim: bad --animate '%s' (expected 1..1000 frames)\n", val);
                return -1;
            }
            o->animate = (int)n;
        } else if (strcmp(a, "--panel") == 0) {
            int pw, ph;
            if (panel_emu_frame_size(val, 0, &pw, &ph) != 0) {
                fprintf(stderr,
                        "fixel-sim: unknown panel '%s' (expected: st7789 st7789-240x320 "
                        "st7789-240x240 st7789-135x240 ili9341 ili9341-240x320)\n",
                        val);
                return -1;
            }
            o->panel = val;
        } else if (strcmp(a, "--rotation") == 0) {
            if (parse_long(val, 0, 3, &n) != 0) {
                fprintf(stderr, "fixel-sim: bad --rotation '%s' (expected 0..3)\n", val);
                return -1;
            }
            o->rotation = (int)n;
            rotation_given = 1;
        } else if (strcmp(a, "--band-rows") == 0) {
            if (parse_long(val, 1, FXL_TARGET_MAX_DIM, &n) != 0) {
                fprintf(stderr, "fixel-sim: bad --band-rows '%s'\n", val);
                return -1;
            }
            o->band_rows = (int)n;
            band_rows_given = 1;
        } else if (strcmp(a, "--texture") == 0) {
            int t;
            o->texture = -2;
            for (t = 0; t < TEXTURE_COUNT; t++) {
                if (strcmp(val, texture_name((texture_id_t)t)) == 0) {
                    o->texture = t;
                }
            }
            if (o->texture < 0) {
                fprintf(stderr, "fixel-sim: unknown texture '%s' (see --help)\n", val);
                return -1;
            }
        } else if (strcmp(a, "--crc") == 0) {
            o->crc = 1;
        } else if (strcmp(a, "--gallery-crc") == 0) {
            o->gallery_crc = 1;
        } else if (strcmp(a, "--list") == 0) {
            o->list = 1;
        } else {
            fprintf(stderr, "fixel-sim: unknown option '%s' (see --help)\n", a);
            return -1;
        }
    }
    if ((o->gallery_dir != NULL) + o->gallery_crc + (o->animate > 0) + (o->panel != NULL) > 1) {
        fprintf(stderr, "fixel-sim: --gallery, --gallery-crc, --animate and --panel are "
                        "separate runs\n");
        return -1;
    }
    if (o->animate > 0 && o->out_png == NULL) {
        fprintf(stderr, "fixel-sim: --animate needs -o DIR\n");
        return -1;
    }
    /* Options a mode would otherwise drop without a word: --panel drew the
     * scene's own texture whatever --texture said, --animate always draws
     * p_cube, and the gallery modes neither read -o nor --texture. */
    if (o->texture >= 0 && (o->panel != NULL || o->animate > 0 || o->gallery_dir != NULL ||
                            o->gallery_crc)) {
        fprintf(stderr, "fixel-sim: --texture applies to a single frame only (not with --panel, "
                        "--animate or --gallery)\n");
        return -1;
    }
    if (o->animate > 0 && scene_given && strcmp(o->scene, "p_cube") != 0) {
        fprintf(stderr, "fixel-sim: --animate always turns p_cube; drop --scene\n");
        return -1;
    }
    if ((o->gallery_dir != NULL || o->gallery_crc) && o->out_png != NULL) {
        fprintf(stderr, "fixel-sim: --gallery writes into its DIR and --gallery-crc to stdout; "
                        "drop -o\n");
        return -1;
    }
    /* trilinear with --mip none or nearest (either order) drew bilinear
     * without a word */
    if (trilinear_given && o->mip != FXL_MIP_LINEAR) {
        fprintf(stderr, "fixel-sim: --filter trilinear is bilinear with --mip linear; drop --mip or "
                        "take --filter bilinear\n");
        return -1;
    }
    /* the panel mode's size and format are the panel's, and it prints its
     * own wire and frame CRCs: these were dropped without a word */
    if (o->panel != NULL && (format_given || size_given || o->crc)) {
        fprintf(stderr, "fixel-sim: --panel draws at the panel's size in its wire format and "
                        "prints its CRCs; drop --format, --size and --crc\n");
        return -1;
    }
    if (o->panel == NULL && (rotation_given || band_rows_given)) {
        fprintf(stderr, "fixel-sim: --rotation and --band-rows need --panel\n");
        return -1;
    }
    if (o->panel != NULL) {
        int pw, ph;
        if (panel_emu_frame_size(o->panel, o->rotation, &pw, &ph) == 0 && o->band_rows > ph) {
            fprintf(stderr, "fixel-sim: --band-rows %d is more than the %d rows of %s in rotation "
                            "%d\n", o->band_rows, ph, o->panel, o->rotation);
            return -1;
        }
    }
    return 0;
}

static void draw_from_options(const options_t *o, fxl_draw_t *d)
{
    fxl_draw_defaults(d);
    d->persp = o->persp;
    d->filter = o->filter;
    d->mip = o->mip;
    d->lod = o->lod;
    d->lod_bias_q8 = o->lod_bias_q8;
    d->depth = o->depth ? (FXL_DEPTH_TEST | FXL_DEPTH_WRITE) : 0;
}

/* One scene ready to draw: geometry, textures, frame, draw state. */
typedef struct job {
    anyscene_t scene;
    frame_t frame;
    fxl_draw_t draw;
} job_t;

static void job_free(job_t *j)
{
    anyscene_free(&j->scene);
    frame_free(&j->frame);
}

static int job_init(job_t *j, const char *scene, int texture, fxl_angle_t spin, int32_t w,
                    int32_t h, fxl_pixfmt_t format, const fxl_draw_t *d)
{
    int rc;
    memset(j, 0, sizeof(*j));
    rc = anyscene_build(&j->scene, scene, w, h, texture, spin);
    if (rc != SCENE_OK) {
        fprintf(stderr, "fixel-sim: scene '%s' at %ldx%ld: %s\n", scene, (long)w, (long)h,
                scene_strerror(rc));
        return -1;
    }
    if (frame_alloc(&j->frame, w, h, format, (d->depth & (FXL_DEPTH_TEST | FXL_DEPTH_WRITE)) != 0) !=
        0) {
        fprintf(stderr, "fixel-sim: out of memory for scene '%s'\n", scene);
        job_free(j);
        return -1;
    }
    j->draw = *d;
    return 0;
}

static int report(fxl_status_t st, const char *what)
{
    if (st != FXL_OK) {
        fprintf(stderr, "fixel-sim: %s: %s\n", what, fxl_status_name(st));
        return -1;
    }
    return 0;
}

/* Render once for the stats, then `runs` more for the median time. The last
 * render stays in the frame. */
static int job_run(job_t *j, int runs, fxl_stats_t *stats, double *ms)
{
    double t[TIMING_RUNS];
    int r;
    memset(stats, 0, sizeof(*stats));
    if (report(anyscene_render(&j->scene, &j->draw, &j->frame.target, stats), j->scene.name)) {
        return -1;
    }
    if (runs > TIMING_RUNS) {
        runs = TIMING_RUNS;
    }
    for (r = 0; r < runs; r++) {
        uint64_t t0 = timing_now_ns();
        (void)anyscene_render(&j->scene, &j->draw, &j->frame.target, NULL);
        t[r] = timing_seconds(t0, timing_now_ns()) * 1e3;
    }
    *ms = runs > 0 ? timing_median(t, (size_t)runs) : 0.0;
    return 0;
}

static int write_png(const char *path, const fxl_target_t *t)
{
    char err[512];
    if (pngio_write_target(path, t, err, sizeof(err)) != 0) {
        fprintf(stderr, "fixel-sim: %s\n", err);
        return -1;
    }
    return 0;
}

static int make_dir(const char *dir)
{
    struct stat st;
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "fixel-sim: cannot create directory '%s': %s\n", dir, strerror(errno));
        return -1;
    }
    /* EEXIST may be a file: frames went to DIR/cube_000.png and failed */
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        fprintf(stderr, "fixel-sim: '%s' exists and is not a directory\n", dir);
        return -1;
    }
    return 0;
}

static void table_header(void)
{
    printf("%-22s %-9s %-10s %5s %7s %9s %8s  %-10s\n", "scene", "mode", "filter", "drawn",
           "pixels", "ms/frame", "Mpix/s", "crc32");
}

static void table_row(const char *scene, const char *mode, const char *filter,
                      const fxl_stats_t *s, double ms, uint32_t crc)
{
    printf("%-22s %-9s %-10s %5lu %7lu %9.3f %8.2f  0x%08lX\n", scene, mode, filter,
           (unsigned long)s->drawn, (unsigned long)s->pixels, ms,
           ms > 0.0 ? (double)s->pixels / (ms * 1e3) : 0.0, (unsigned long)crc);
}

/* One gallery image drawn by a job at the golden settings: timed, and kept
 * in *keep (when not NULL) for composing. */
static int gallery_single(const gallery_entry_t *e, const char *dir, frame_t *keep)
{
    job_t j;
    fxl_draw_t d;
    fxl_stats_t s;
    double ms;
    char name[256], path[4096];
    uint32_t crc;
    gallery_draw_settings(e, &d);
    if (job_init(&j, e->scene, e->texture, 0, SCENE_DEFAULT_WIDTH, SCENE_DEFAULT_HEIGHT,
                 drawable_rgb565(), &d) != 0) {
        return -1;
    }
    if (job_run(&j, TIMING_RUNS, &s, &ms) != 0) {
        job_free(&j);
        return -1;
    }
    frame_to_native(&j.frame);   /* the goldens' byte order */
    crc = fxl_host_crc_target(&j.frame.target);
    table_row(e->kind == GALLERY_PIPE ? e->id : e->id, e->persp_name, e->filter_name, &s, ms,
              crc);
    if (keep != NULL) {
        *keep = j.frame; /* hand the frame over */
        memset(&j.frame, 0, sizeof(j.frame));
        job_free(&j);
        return 0;
    }
    gallery_file_name(e, name, sizeof(name));
    snprintf(path, sizeof(path), "%s/%s", dir, name);
    if (write_png(path, &j.frame.target) != 0) {
        job_free(&j);
        return -1;
    }
    job_free(&j);
    return 0;
}

static int gallery_mips(const gallery_entry_t *e, const char *dir)
{
    frame_t p[GALLERY_MIPS_PANELS], out;
    char name[256], path[4096];
    size_t i;
    int rc = 0;
    memset(p, 0, sizeof(p));
    for (i = 0; i < GALLERY_MIPS_PANELS && rc == 0; i++) {
        gallery_entry_t pe;
        (void)gallery_mips_panel(i, &pe);
        rc = gallery_single(&pe, dir, &p[i]);
    }
    if (rc == 0 && gallery_mips_compose(p, &out) == 0) {
        gallery_file_name(e, name, sizeof(name));
        snprintf(path, sizeof(path), "%s/%s", dir, name);
        printf("%-22s %-9s %-10s composite %dx%d of the 6 rows above -> %s  0x%08lX\n", e->id,
               e->persp_name, e->filter_name, (int)out.target.width, (int)out.target.height,
               name, (unsigned long)fxl_host_crc_target(&out.target));
        rc = write_png(path, &out.target);
        frame_free(&out);
    } else if (rc == 0) {
        fprintf(stderr, "fixel-sim: cannot compose floor_mips\n");
        rc = -1;
    }
    for (i = 0; i < GALLERY_MIPS_PANELS; i++) {
        frame_free(&p[i]);
    }
    return rc;
}

static void print_panel_check(const char *panel, int rotation, int band_rows,
                              const panel_check_t *c)
{
    printf("  panel %s rotation %d, %dx%d, %d bands of %d rows, %lu transfers, %llu wire "
           "bytes, protocol errors %d\n",
           panel, rotation, c->res.width, c->res.height, c->res.bands, band_rows,
           c->res.transfers, (unsigned long long)c->res.wire_bytes, c->res.protocol_errors);
    printf("  wire CRC 0x%08lX (frame only 0x%08lX), panel image CRC 0x%08lX, direct render "
           "CRC 0x%08lX: %s",
           (unsigned long)c->res.wire_crc, (unsigned long)c->res.frame_crc,
           (unsigned long)c->panel_crc, (unsigned long)c->direct_crc,
           c->diff_pixels == 0 ? "OK" : "MISMATCH");
    if (c->diff_pixels != 0) {
        printf(" (%ld pixels differ, first at x %ld, y %ld)", c->diff_pixels,
               c->first_diff % c->res.width, c->first_diff / c->res.width);
    }
    printf("\n");
}

static int gallery_panel(const gallery_entry_t *e, const char *dir)
{
    frame_t img;
    panel_check_t c;
    fxl_draw_t d;
    fxl_stats_t s;
    char name[256], path[4096];
    double t[3];
    int r, rc;
    gallery_draw_settings(e, &d);
    for (r = 0; r < 3; r++) { /* the whole path: front end, bands, driver, emulator */
        uint64_t t0 = timing_now_ns();
        fxl_status_t st = panel_scene_render(e->panel, e->rotation, e->band_rows, e->scene, &d,
                                             &img, &c);
        t[r] = timing_seconds(t0, timing_now_ns()) * 1e3;
        if (report(st, e->id) != 0) {
            frame_free(&img);
            return -1;
        }
        if (r < 2) {
            frame_free(&img);
        }
    }
    memset(&s, 0, sizeof(s));
    s.drawn = c.res.stats.drawn;
    s.pixels = c.res.stats.pixels;
    table_row(e->id, e->persp_name, e->filter_name, &s, timing_median(t, 3), c.panel_crc);
    print_panel_check(e->panel, e->rotation, e->band_rows, &c);
    gallery_file_name(e, name, sizeof(name));
    snprintf(path, sizeof(path), "%s/%s", dir, name);
    rc = write_png(path, &img.target);
    frame_free(&img);
    return (rc != 0 || c.diff_pixels != 0) ? -1 : 0;
}

static int run_gallery(const options_t *o)
{
    size_t i;
    int failed = 0;
    uint64_t t0 = timing_now_ns();
    if (make_dir(o->gallery_dir) != 0) {
        return 1;
    }
    printf("fixel gallery: 320x240 native RGB565, depth on, subdiv16 unless stated; ms/frame is\n"
           "the median of %d renders (clear + draw; panel: front end + bands + driver +\n"
           "emulator); crc32 of the frame's pixels, golden where tests/golden/gallery_crc.txt\n"
           "lists the image (the mip comparison's panels are checked as one composite)\n",
           TIMING_RUNS);
    table_header();
    for (i = 0; i < gallery_count(); i++) {
        gallery_entry_t e;
        int rc;
        (void)gallery_entry(i, &e);
        if (e.kind == GALLERY_MIPS) {
            rc = gallery_mips(&e, o->gallery_dir);
        } else if (e.kind == GALLERY_PANEL) {
            rc = gallery_panel(&e, o->gallery_dir);
        } else {
            rc = gallery_single(&e, o->gallery_dir, NULL);
        }
        failed |= rc != 0;
    }
    printf("%lu images in %s/ in %.2f s%s\n", (unsigned long)gallery_count(), o->gallery_dir,
           timing_seconds(t0, timing_now_ns()), failed ? " (with ERRORS, see above)" : "");
    return failed;
}

static int run_gallery_crc(void)
{
    size_t i;
    printf("# fixel gallery CRC-32 (pixel bytes, native RGB565, depth on; scene.h lists the\n"
           "# images and their settings)\n");
    printf("# regenerate: fixel-sim --gallery-crc > tests/golden/gallery_crc.txt\n");
    printf("# image persp filter crc32\n");
    for (i = 0; i < gallery_count(); i++) {
        gallery_entry_t e;
        frame_t f;
        fxl_status_t st;
        (void)gallery_entry(i, &e);
        st = gallery_render(&e, &f, NULL, NULL);
        if (st != FXL_OK) {
            fprintf(stderr, "fixel-sim: gallery %s %s %s: %s\n", e.id, e.persp_name,
                    e.filter_name, fxl_status_name(st));
            frame_free(&f);
            return 1;
        }
        printf("%s %s %s 0x%08lX\n", e.id, e.persp_name, e.filter_name,
               (unsigned long)fxl_host_crc_target(&f.target));
        frame_free(&f);
    }
    return 0;
}

static int run_animate(const options_t *o)
{
    fxl_draw_t d;
    int i, failed = 0, written = 0;
    unsigned long pixels = 0;
    double total_ms = 0.0;
    if (make_dir(o->out_png) != 0) {
        return 1;
    }
    draw_from_options(o, &d);
    for (i = 0; i < o->animate && !failed; i++) {
        /* One full turn over the N frames: frame i at i / N turns. */
        fxl_angle_t spin = (fxl_angle_t)(((uint32_t)i * 65536u) / (uint32_t)o->animate);
        job_t j;
        fxl_stats_t s;
        double ms;
        char path[4096];
        if (job_init(&j, "p_cube", -1, spin, o->width, o->height, o->format, &d) != 0) {
            return 1;
        }
        if (job_run(&j, 1, &s, &ms) != 0) {
            job_free(&j);
            return 1;
        }
        snprintf(path, sizeof(path), "%s/cube_%03d.png", o->out_png, i);
        failed |= write_png(path, &j.frame.target) != 0;
        if (o->crc) {
            printf("%s 0x%08lX\n", path, (unsigned long)fxl_host_crc_target(&j.frame.target));
        }
        if (!failed) {
            written++;
            pixels += s.pixels;
            total_ms += ms;
        }
        job_free(&j);
    }
    /* the frames written: a failed write stops the loop early */
    if (written > 0)
        fprintf(stderr, "p_cube: %d of %d frames (%s %s) in %s/cube_000.png .. cube_%03d.png, %.0f "
                        "pixels/frame, %.3f ms/frame\n",
                written, o->animate, name_of(persp_names, d.persp), filter_label(&d), o->out_png,
                written - 1, (double)pixels / written, total_ms / written);
    return failed;
}

static int run_panel(const options_t *o)
{
    frame_t img;
    panel_check_t c;
    fxl_draw_t d;
    fxl_status_t st;
    int rc = 0;
    draw_from_options(o, &d);
    /* The band renderer always keeps a depth band; the direct reference has
     * a depth buffer too, so depth settings act the same in both. */
    st = panel_scene_render(o->panel, o->rotation, o->band_rows, o->scene, &d, &img, &c);
    if (report(st, "panel render") != 0) {
        frame_free(&img);
        return 1;
    }
    fprintf(stderr, "%s on %s: %s %s, %lu triangles, %lu drawn, %lu pixels\n", o->scene,
            o->panel, name_of(persp_names, d.persp), filter_label(&d),
            (unsigned long)c.res.stats.triangles, (unsigned long)c.res.stats.drawn,
            (unsigned long)c.res.stats.pixels);
    print_panel_check(o->panel, o->rotation, o->band_rows, &c);
    if (o->out_png != NULL && write_png(o->out_png, &img.target) != 0) {
        rc = 1;
    }
    frame_free(&img);
    return (rc != 0 || c.diff_pixels != 0) ? 1 : 0;
}

int main(int argc, char **argv)
{
    options_t o;
    job_t j;
    fxl_draw_t d;
    fxl_stats_t s;
    double ms;
    int rc = 0;
    if (parse_args(argc, argv, &o) != 0) {
        return 2;
    }
    if (o.list) {
        size_t i;
        for (i = 0; i < scene_count(); i++) {
            printf("%s\n", scene_name(i));
        }
        for (i = 0; i < pscene_count(); i++) {
            printf("%s\n", pscene_name(i));
        }
        return 0;
    }
    if (o.gallery_crc) {
        return run_gallery_crc();
    }
    if (o.gallery_dir != NULL) {
        return run_gallery(&o);
    }
    if (o.animate > 0) {
        return run_animate(&o);
    }
    if (o.panel != NULL) {
        return run_panel(&o);
    }
    draw_from_options(&o, &d);
    if (o.texture >= 0 && pscene_exists(o.scene)) {
        fprintf(stderr, "fixel-sim: --texture applies to the double-precision scenes only\n");
        return 2;
    }
    if (job_init(&j, o.scene, o.texture, 0, o.width, o.height, o.format, &d) != 0) {
        return 1;
    }
    if (job_run(&j, TIMING_RUNS, &s, &ms) != 0) {
        job_free(&j);
        return 1;
    }
    /* The summary goes to stderr so that stdout carries only the CRC. */
    fprintf(stderr,
            "%s %s %s %dx%d: %lu triangles, %lu drawn (%lu by the generic walk), %lu pixels, "
            "%lu divisions, %.3f ms/frame\n",
            j.scene.name, name_of(persp_names, d.persp), filter_label(&d), (int)o.width,
            (int)o.height, (unsigned long)s.triangles, (unsigned long)s.drawn, (unsigned long)s.generic,
            (unsigned long)s.pixels, (unsigned long)s.divisions, ms);
    if (o.crc) {
        printf("0x%08lX\n", (unsigned long)fxl_host_crc_target(&j.frame.target));
    }
    if (o.out_png != NULL && write_png(o.out_png, &j.frame.target) != 0) {
        rc = 1;
    }
    job_free(&j);
    return rc;
}
