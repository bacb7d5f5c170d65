/* sim.c - fixel-sim: render the built-in scenes on the PC, write PNGs, print
 * CRCs and a timing table. Run with --help for the options.
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
#include "png_io.h"
#include "scene.h"
#include "textures.h"
#include "timing.h"

#define TIMING_RUNS 5

typedef struct options {
    const char *scene;
    int16_t persp;
    uint8_t filter, mip, lod;
    int32_t width, height;
    int depth;
    fxl_pixfmt_t format;
    const char *out_png;
    int crc;
    const char *gallery_dir;
    int gallery_crc;
    int list;
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
            "Render a built-in scene with the fixel rasterizer (double-precision projection).\n"
            "  --scene NAME        scene to render (default floor); see --list\n"
            "  --persp MODE        affine|exact|subdiv4|subdiv8|subdiv16|subdiv32|subdiv64|auto\n"
            "                      (default subdiv16)\n"
            "  --filter F          point|bilinear (default point)\n"
            "  --mip M             none|nearest|linear (default none)\n"
            "  --lod L             segment|triangle (default segment)\n"
            "  --size WxH          target size, 1..%d each (default %dx%d)\n"
            "  --depth on|off      16-bit depth buffer (default on)\n"
            "  --format F          rgb565|rgb565swap (default rgb565)\n"
            "  -o FILE.png         write the frame as a PNG\n"
            "  --crc               print the CRC-32 of the frame's pixel bytes\n"
            "  --gallery DIR       render every scene x {subdiv16, affine} x {point, bilinear}\n"
            "                      into DIR/<scene>_<persp>_<filter>.png and print a table\n"
            "                      (honours --size, --depth, --format, --mip, --lod)\n"
            "  --gallery-crc       print the golden CRC list of the gallery at its fixed\n"
            "                      settings (320x240, rgb565, depth on, mip none); e.g.\n"
            "                      fixel-sim --gallery-crc > tests/golden/gallery_crc.txt\n"
            "  --list              list the scenes\n"
            "  --help              this text\n"
            "scenes:",
            FXL_TARGET_MAX_DIM, SCENE_DEFAULT_WIDTH, SCENE_DEFAULT_HEIGHT);
    for (i = 0; i < scene_count(); i++) {
        fprintf(f, " %s", scene_name(i));
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

static int parse_args(int argc, char **argv, options_t *o)
{
    int i, v;
    memset(o, 0, sizeof(*o));
    o->scene = "floor";
    o->persp = 16;
    o->filter = FXL_FILTER_POINT;
    o->mip = FXL_MIP_NONE;
    o->lod = FXL_LOD_SEGMENT;
    o->width = SCENE_DEFAULT_WIDTH;
    o->height = SCENE_DEFAULT_HEIGHT;
    o->depth = 1;
    o->format = FXL_PIXFMT_RGB565;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = NULL;
        int takes_value = strcmp(a, "--scene") == 0 || strcmp(a, "--persp") == 0 ||
                          strcmp(a, "--filter") == 0 || strcmp(a, "--mip") == 0 ||
                          strcmp(a, "--lod") == 0 || strcmp(a, "--size") == 0 ||
                          strcmp(a, "--depth") == 0 || strcmp(a, "--format") == 0 ||
                          strcmp(a, "-o") == 0 || strcmp(a, "--gallery") == 0;
        if (takes_value) {
            if (i + 1 >= argc) {
                fprintf(stderr, "fixel-sim: option %s needs a value (see --help)\n", a);
                return -1;
            }
            val = argv[++i];
        }
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            exit(0);
        } else if (strcmp(a, "--scene") == 0) {
            size_t k;
            int found = 0;
            for (k = 0; k < scene_count(); k++) {
                found |= strcmp(scene_name(k), val) == 0;
            }
            if (!found) {
                fprintf(stderr, "fixel-sim: unknown scene '%s' (see --list)\n", val);
                return -1;
            }
            o->scene = val;
        } else if (strcmp(a, "--persp") == 0) {
            if (lookup(persp_names, a, val, &v) != 0) {
                return -1;
            }
            o->persp = (int16_t)v;
        } else if (strcmp(a, "--filter") == 0) {
            if (lookup(filter_names, a, val, &v) != 0) {
                return -1;
            }
            o->filter = (uint8_t)v;
        } else if (strcmp(a, "--mip") == 0) {
            if (lookup(mip_names, a, val, &v) != 0) {
                return -1;
            }
            o->mip = (uint8_t)v;
        } else if (strcmp(a, "--lod") == 0) {
            if (lookup(lod_names, a, val, &v) != 0) {
                return -1;
            }
            o->lod = (uint8_t)v;
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
        } else if (strcmp(a, "--size") == 0) {
            if (parse_size(val, &o->width, &o->height) != 0) {
                fprintf(stderr, "fixel-sim: bad --size '%s' (expected WxH, each 1..%d)\n", val,
                        FXL_TARGET_MAX_DIM);
                return -1;
            }
        } else if (strcmp(a, "-o") == 0) {
            o->out_png = val;
        } else if (strcmp(a, "--gallery") == 0) {
            o->gallery_dir = val;
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
    if (o->gallery_dir != NULL && o->gallery_crc) {
        fprintf(stderr, "fixel-sim: --gallery and --gallery-crc are separate runs\n");
        return -1;
    }
    return 0;
}

/* One scene ready to draw: geometry, texture, frame, draw state. */
typedef struct job {
    scene_t scene;
    host_texture_t tex;
    frame_t frame;
    fxl_draw_t draw;
} job_t;

static void job_free(job_t *j)
{
    scene_free(&j->scene);
    texture_free(&j->tex);
    frame_free(&j->frame);
}

static int job_init(job_t *j, const options_t *o, const char *scene, int16_t persp,
                    uint8_t filter)
{
    int rc;
    memset(j, 0, sizeof(*j));
    rc = scene_build(scene, o->width, o->height, &j->scene);
    if (rc != SCENE_OK) {
        fprintf(stderr, "fixel-sim: scene '%s' at %ldx%ld: %s\n", scene, (long)o->width,
                (long)o->height, scene_strerror(rc));
        return -1;
    }
    if (texture_make(&j->tex, j->scene.texture) != 0 ||
        frame_alloc(&j->frame, o->width, o->height, o->format, o->depth) != 0) {
        fprintf(stderr, "fixel-sim: out of memory for scene '%s'\n", scene);
        job_free(j);
        return -1;
    }
    fxl_draw_defaults(&j->draw);
    j->draw.persp = persp;
    j->draw.filter = filter;
    j->draw.mip = o->mip;
    j->draw.lod = o->lod;
    j->draw.depth = o->depth ? (FXL_DEPTH_TEST | FXL_DEPTH_WRITE) : 0;
    return 0;
}

/* Render once for the stats, then TIMING_RUNS more for the median time. */
static int job_run(job_t *j, fxl_stats_t *stats, double *ms)
{
    double t[TIMING_RUNS];
    int r;
    fxl_status_t st;
    memset(stats, 0, sizeof(*stats));
    st = scene_render(&j->scene, &j->tex.tex, &j->draw, &j->frame.target, stats);
    if (st != FXL_OK) {
        fprintf(stderr, "fixel-sim: scene '%s': fxl_draw_triangle failed: %s\n",
                j->scene.name, fxl_status_name(st));
        return -1;
    }
    for (r = 0; r < TIMING_RUNS; r++) {
        uint64_t t0 = timing_now_ns();
        (void)scene_render(&j->scene, &j->tex.tex, &j->draw, &j->frame.target, NULL);
        t[r] = timing_seconds(t0, timing_now_ns()) * 1e3;
    }
    *ms = timing_median(t, TIMING_RUNS);
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

static void table_header(void)
{
    printf("%-13s %-9s %-9s %5s %9s %9s %9s\n", "scene", "mode", "filter", "drawn", "pixels",
           "ms/frame", "Mpix/s");
}

static void table_row(const job_t *j, const fxl_stats_t *s, double ms)
{
    printf("%-13s %-9s %-9s %5lu %9lu %9.3f %9.2f\n", j->scene.name,
           name_of(persp_names, j->draw.persp), name_of(filter_names, j->draw.filter),
           (unsigned long)s->drawn, (unsigned long)s->pixels, ms,
           ms > 0.0 ? (double)s->pixels / (ms * 1e3) : 0.0);
}

static int run_gallery(const options_t *o)
{
    size_t i;
    int failed = 0;
    if (mkdir(o->gallery_dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "fixel-sim: cannot create directory '%s': %s\n", o->gallery_dir,
                strerror(errno));
        return 1;
    }
    table_header();
    for (i = 0; i < gallery_count(); i++) {
        gallery_entry_t e;
        job_t j;
        fxl_stats_t s;
        double ms;
        char path[4096];
        (void)gallery_entry(i, &e);
        if (job_init(&j, o, e.scene, e.persp, e.filter) != 0) {
            return 1;
        }
        if (job_run(&j, &s, &ms) != 0) {
            job_free(&j);
            return 1;
        }
        snprintf(path, sizeof(path), "%s/%s_%s_%s.png", o->gallery_dir, e.scene, e.persp_name,
                 e.filter_name);
        table_row(&j, &s, ms);
        if (write_png(path, &j.frame.target) != 0) {
            failed = 1;
        }
        job_free(&j);
    }
    return failed;
}

static int run_gallery_crc(void)
{
    size_t i;
    printf("# fixel gallery CRC-32 (pixel bytes, 320x240 native RGB565, depth on, mip none)\n");
    printf("# regenerate: fixel-sim --gallery-crc > tests/golden/gallery_crc.txt\n");
    printf("# scene persp filter crc32\n");
    for (i = 0; i < gallery_count(); i++) {
        gallery_entry_t e;
        frame_t f;
        fxl_status_t st;
        (void)gallery_entry(i, &e);
        st = gallery_render(&e, &f, NULL);
        if (st != FXL_OK) {
            fprintf(stderr, "fixel-sim: gallery %s %s %s: %s\n", e.scene, e.persp_name,
                    e.filter_name, fxl_status_name(st));
            frame_free(&f);
            return 1;
        }
        printf("%s %s %s 0x%08lX\n", e.scene, e.persp_name, e.filter_name,
               (unsigned long)fxl_host_crc_target(&f.target));
        frame_free(&f);
    }
    return 0;
}

int main(int argc, char **argv)
{
    options_t o;
    job_t j;
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
        return 0;
    }
    if (o.gallery_crc) {
        return run_gallery_crc();
    }
    if (o.gallery_dir != NULL) {
        return run_gallery(&o);
    }
    if (job_init(&j, &o, o.scene, o.persp, o.filter) != 0) {
        return 1;
    }
    if (job_run(&j, &s, &ms) != 0) {
        job_free(&j);
        return 1;
    }
    /* The summary goes to stderr so that stdout carries only the CRC. */
    fprintf(stderr, "%s %s %s %dx%d: %lu triangles, %lu drawn, %lu pixels, %.3f ms/frame\n",
            j.scene.name, name_of(persp_names, j.draw.persp), name_of(filter_names, j.draw.filter),
            (int)o.width, (int)o.height, (unsigned long)s.triangles, (unsigned long)s.drawn,
            (unsigned long)s.pixels, ms);
    if (o.crc) {
        printf("0x%08lX\n", (unsigned long)fxl_host_crc_target(&j.frame.target));
    }
    if (o.out_png != NULL && write_png(o.out_png, &j.frame.target) != 0) {
        rc = 1;
    }
    job_free(&j);
    return rc;
}
