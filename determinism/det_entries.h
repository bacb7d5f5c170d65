/* det_entries.h - what the determinism check renders (shared by the host
 * generator gen_data.c, the bare-metal/host harness det_main.c and
 * tests/test_determinism.c, so every build renders exactly the same list).
 *
 * Two kinds of frames, all 320x240 native RGB565 with depth test + write,
 * CRC-32 (crc32.h) of the pixel rows:
 * - Screen-space frames: every double-precision gallery scene (the host's
 *   scene list, projected on the host) with each draw variant below: the
 *   gallery's own four (subdiv16 and affine, point and bilinear, no mips)
 *   plus variants that reach the other span paths (exact and auto with and
 *   without mips, subdiv32, mip nearest and linear, per-triangle LOD).
 *   Size-optimised builds draw every one of them with the generic walk, the
 *   others with the specialised ones. Pixels and depth cleared to 0, every
 *   triangle drawn in order.
 * - Front-end frames: every pipeline scene (pipe_scenes.h, the gallery's
 *   p_*) from its object-space meshes through fxl_mesh_draw, so the
 *   builds also compare trig.c, pipeline.c, clip.c, mesh.c, texgen.c and
 *   light.c. Each build runs the same fixed-point front end on the same
 *   fixed-point inputs (det_pscene_t below; no floating point on the
 *   target), with each variant of det_pvariants. Cleared like the gallery
 *   (scene_clear's sky gradient) or like the band renderer
 *   (PANEL_CLEAR_RGB565), so the CRC of a variant with a golden key must
 *   equal the gallery's golden CRC of that scene (tests/golden/
 *   gallery_crc.txt; determinism.sh checks it).
 */
#ifndef FXL_DET_ENTRIES_H
#define FXL_DET_ENTRIES_H

#include "fixel/pipeline.h"
#include "fixel/raster.h"

#define DET_W 320
#define DET_H 240

typedef struct det_variant {
    const char *name;
    int16_t persp;
    uint8_t filter, mip, lod;
} det_variant_t;

static const det_variant_t det_variants[] = {
    {"subdiv16_point", 16, FXL_FILTER_POINT, FXL_MIP_NONE, FXL_LOD_SEGMENT},
    {"affine_point", FXL_PERSP_AFFINE, FXL_FILTER_POINT, FXL_MIP_NONE, FXL_LOD_SEGMENT},
    {"subdiv16_bilinear", 16, FXL_FILTER_BILINEAR, FXL_MIP_NONE, FXL_LOD_SEGMENT},
    {"affine_bilinear", FXL_PERSP_AFFINE, FXL_FILTER_BILINEAR, FXL_MIP_NONE, FXL_LOD_SEGMENT},
    {"exact_trilinear", FXL_PERSP_EXACT, FXL_FILTER_BILINEAR, FXL_MIP_LINEAR, FXL_LOD_SEGMENT},
    {"auto_bilinear_mip", FXL_PERSP_AUTO, FXL_FILTER_BILINEAR, FXL_MIP_NEAREST, FXL_LOD_SEGMENT},
    {"subdiv32_point_mip_tri", 32, FXL_FILTER_POINT, FXL_MIP_NEAREST, FXL_LOD_TRIANGLE},
    {"exact_bilinear", FXL_PERSP_EXACT, FXL_FILTER_BILINEAR, FXL_MIP_NONE, FXL_LOD_SEGMENT},
    {"auto_point", FXL_PERSP_AUTO, FXL_FILTER_POINT, FXL_MIP_NONE, FXL_LOD_SEGMENT},
};
#define DET_NVARIANTS ((int)(sizeof det_variants / sizeof det_variants[0]))

static inline void det_draw_settings(const det_variant_t *v, fxl_draw_t *d)
{
    fxl_draw_defaults(d);
    d->persp = v->persp;
    d->filter = v->filter;
    d->mip = v->mip;
    d->lod = v->lod;
    d->depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
}

/* ---- front-end frames ------------------------------------------------------ */

/* How a front-end frame is cleared before drawing (depth to 0 in both). */
#define DET_CLEAR_SKY 0   /* scene_clear (scene.c): rows from (96, 128, 176) at the top to
                           * (28, 32, 44) at row DET_H - 1, channel = top + (bot - top) y /
                           * (DET_H - 1) in int32, truncated, packed by FXL_RGB565 */
#define DET_CLEAR_PANEL 1 /* flat DET_PANEL_CLEAR, what the band renderer clears to */
#define DET_PANEL_CLEAR FXL_RGB565(28, 32, 44) /* = PANEL_CLEAR_RGB565 (scene.h) */

typedef struct det_pvariant {
    det_variant_t v;           /* draw settings, as det_draw_settings */
    uint8_t cache;             /* 1: vertex cache of the scene's largest part's vertex count,
                                * as pscene_draw; 0: none (pipeline.h: the same pixels) */
    uint8_t clear;             /* DET_CLEAR_* */
    /* The gallery's golden line for the frame is "<golden_prefix><scene>
     * <golden_key> 0x<crc>" (gen_data.c looks it up), or none when it is
     * not in tests/golden/gallery_crc.txt (e.g. the panel image of scenes
     * other than p_cube). */
    const char *golden_prefix, *golden_key;
} det_pvariant_t;

/* The gallery's two pipeline images (scene.h: GALLERY_PIPE, subdiv16
 * point and trilinear), the point one again without the vertex cache, and
 * the direct render behind the emulated ST7789 panel image (GALLERY_PANEL:
 * bilinear, flat clear; test_gallery checks the panel shows exactly it). */
static const det_pvariant_t det_pvariants[] = {
    {{"subdiv16_point", 16, FXL_FILTER_POINT, FXL_MIP_NONE, FXL_LOD_SEGMENT}, 1, DET_CLEAR_SKY, "",
     "subdiv16 point"},
    {{"subdiv16_trilinear", 16, FXL_FILTER_BILINEAR, FXL_MIP_LINEAR, FXL_LOD_SEGMENT}, 1, DET_CLEAR_SKY, "",
     "subdiv16 trilinear"},
    {{"subdiv16_point_nocache", 16, FXL_FILTER_POINT, FXL_MIP_NONE, FXL_LOD_SEGMENT}, 0, DET_CLEAR_SKY, "",
     "subdiv16 point"},
    {{"subdiv16_bilinear_panel", 16, FXL_FILTER_BILINEAR, FXL_MIP_NONE, FXL_LOD_SEGMENT}, 1, DET_CLEAR_PANEL,
     "panel_st7789_r1_", "subdiv16 bilinear"},
};
#define DET_NPVARIANTS ((int)(sizeof det_pvariants / sizeof det_pvariants[0]))

/* One part of a pipeline scene as fixed-point data, read off the host's
 * pscene_build by gen_data.c (which checks that det_pipe_build gives the
 * host's pipeline bit for bit). */
typedef struct det_ppart {
    fxl_mesh_t mesh;           /* object space, q16 (arrays in det_data.h) */
    fxl_angle_t rot_x, rot_y;  /* model = translate(t) rot_y(rot_y) rot_x(rot_x) */
    fxl_vec3_t t;              /* q16 */
    fxl_texgen_t texgen;
    uint8_t cull, lighting;    /* fxl_pipeline_t's */
    uint16_t material;         /* RGB565 */
    fxl_light_t light;
    int tex;                   /* texture_id_t of the part's texture */
    int lit;                   /* 1: FXL_SHADE_GOURAUD + FXL_TEXENV_MODULATE (pscene_part_draw) */
} det_ppart_t;

typedef struct det_pscene {
    const char *name;
    fxl_angle_t fovy;          /* fxl_pipeline_set_perspective's arguments: turns * 65536, */
    fxl_q16_t aspect, near_q16, far_q16; /* q16 width / height, q16 planes (far 0: none) */
    const det_ppart_t *parts;
    int nparts;
    uint32_t cache_entries;    /* vertex count of the largest part */
} det_pscene_t;

/* The pipeline of part pt of scene s: fxl_pipeline_init for DET_W x DET_H
 * (identity view, whole-frame viewport), s's perspective, the model matrix
 * built like pipe_scenes.c's model_trs (rot_x first, then rot_y, then the
 * translation; every product rounded to nearest by fxl_mat4_mul), the
 * part's plain fields. No vertex cache. */
static inline fxl_status_t det_pipe_build(const det_pscene_t *s, const det_ppart_t *pt,
                                          fxl_pipeline_t *p)
{
    fxl_mat4_t rx, ry, tr;
    fxl_status_t st = fxl_pipeline_init(p, DET_W, DET_H);
    if (st == FXL_OK)
        st = fxl_pipeline_set_perspective(p, s->fovy, s->aspect, s->near_q16, s->far_q16);
    if (st != FXL_OK)
        return st;
    fxl_mat4_rotate_x(&rx, pt->rot_x);
    fxl_mat4_rotate_y(&ry, pt->rot_y);
    fxl_mat4_translate(&tr, pt->t.x, pt->t.y, pt->t.z);
    st = fxl_mat4_mul(&p->model, &ry, &rx);
    if (st == FXL_OK)
        st = fxl_mat4_mul(&p->model, &tr, &p->model);
    p->texgen = pt->texgen;
    p->cull = pt->cull;
    p->lighting = pt->lighting;
    p->material = pt->material;
    p->light = pt->light;
    return st;
}

/* The draw state of a part: the variant's settings, the part's texture,
 * and for lit parts Gouraud shading modulating it (pscene_part_draw). */
static inline void det_part_draw_settings(const det_pvariant_t *pv, const det_ppart_t *pt,
                                          const fxl_texture_t *tex, fxl_draw_t *d)
{
    det_draw_settings(&pv->v, d);
    d->texture = tex;
    if (pt->lit) {
        d->shade = FXL_SHADE_GOURAUD;
        d->texenv = FXL_TEXENV_MODULATE;
    }
}

#endif
