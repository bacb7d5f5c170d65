/* scene.h - the simulator's built-in scenes and how they are drawn, host side.
 *
 * A scene is a list of screen-space triangles (fxl_vertex_t, three per
 * triangle, malloc'd) for one target size, plus the texture it uses. It is
 * built from view-space geometry in DOUBLE precision (the fixed-point front
 * end is a separate module):
 * - View space: eye at the origin looking down -z, y up, w = -z (> 0 in
 *   front). Perspective with vertical field of view fov_y, aspect = W / H,
 *   f = 1 / tan(fov_y / 2): ndc_x = x f / (aspect w), ndc_y = y f / w.
 * - Screen: x = (ndc_x * 0.5 + 0.5) W, y = (0.5 - ndc_y * 0.5) H, stored as
 *   q16 by lround(x * 65536) (no snapping here; the rasterizer snaps).
 * - inv_w = lround(near / w * 4294967295), clamped to [1, UINT32_MAX]: a
 *   point on the near plane has scale 1.0. u, v: normalised texture
 *   coordinates (1.0 = one texture side) as lround(u * 65536).
 * - Every polygon is clipped against the near plane w >= near in view space
 *   (attributes are linear there) before projection, so nothing behind the
 *   eye is emitted. A point on a clipped edge is always computed from the
 *   inside end towards the outside end, so two polygons sharing that edge
 *   get bit-identical new vertices (meshes stay watertight). Clipped
 *   polygons are split into triangles as a fan from their first vertex.
 * - Polygons are also clipped to a guard band |ndc_x|, |ndc_y| <= g with
 *   g = 60000 / max(W, H) - 1, which keeps every screen coordinate within
 *   +-30000 px (q16 holds +-32768). At 320 x 240 (g = 186.5) no scene
 *   reaches it; at large sizes the huge floor is cut, with the same
 *   inside-to-outside rule so shared edges stay identical.
 * - Back faces (cube only) are culled in double by screen-space winding.
 * All scenes use fov_y = 60 degrees and near = 0.1 and are defined
 * independently of the target size (any W x H works; the figures below are
 * for the default 320 x 240).
 *
 * Scenes:
 *   floor        checkerboard plane y = -0.577, x in [-40, 40], z in [-50, -1],
 *                2 triangles. Texture coordinates u = x / 2, v = -z / 2: one
 *                texture period (8 x 8 cells of the checker) per 2 world units,
 *                so cells are 0.25 x 0.25 world units, square on the plane.
 *   floor_tess   the same plane as a 16 x 32 grid of quads (1024 triangles).
 *   floor_rolled the 2-triangle floor rotated 40 degrees about the view axis.
 *   cube         cube of side 2 rotated 30 degrees about x then 30 about y,
 *                centre at z = -5 (about half the screen high); each face
 *                two triangles with u, v in 0..1 (v = 0 at the face's top),
 *                back faces culled: 3 faces, 6 triangles.
 *   fan          on a plane tilted 35 degrees: a closed 24-triangle fan
 *                (left) and a 16 x 16 jittered grid mesh with shared
 *                vertices (right, 512 triangles); all inside the screen.
 *   tunnel       inside of a cylinder of radius 1 from z = 0 to z = -40, eye
 *                off the axis by (0.25, 0.15); 24 x 40 quads, u = 4 turns of
 *                the texture around, v = -z * 4 / (2 pi) (square texels);
 *                the first ring is cut by the near plane.
 *   quad_near    one 8 x 8 quad turned 20 degrees about y, centre z = -2,
 *                covering the whole screen (fill-bound), u, v in 0..4.
 *   small_tris   2000 separate triangles of about 20 px (at 320 x 240) at
 *                depths 2..3 with random orientation (setup-bound).
 */
#ifndef FXL_HOST_SCENE_H
#define FXL_HOST_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "fixel/fixel.h"
#include "textures.h"

#define SCENE_DEFAULT_WIDTH 320
#define SCENE_DEFAULT_HEIGHT 240
#define SCENE_FOV_Y_DEG 60.0
#define SCENE_NEAR 0.1

/* scene_build() results. */
#define SCENE_OK 0
#define SCENE_ERR_NAME (-1)   /* unknown scene name (or NULL argument) */
#define SCENE_ERR_SIZE (-2)   /* width or height outside 1..FXL_TARGET_MAX_DIM */
#define SCENE_ERR_NOMEM (-3)
#define SCENE_ERR_RANGE (-4)  /* a projected value does not fit its q16 field */

typedef struct scene {
    const char *name;        /* static string */
    int32_t width, height;   /* target size the vertices were projected for */
    fxl_vertex_t *verts;     /* 3 * tri_count vertices, malloc'd */
    uint32_t tri_count;
    texture_id_t texture;
    double fov_y_deg, near;
    uint32_t culled_backface; /* polygons dropped by back-face culling */
    uint32_t clipped;         /* polygons cut (or dropped) by the near plane */
    uint32_t guard_clipped;   /* polygon cuts by the guard band (see below) */
} scene_t;

size_t scene_count(void);
/* Name of scene i (0 <= i < scene_count()), NULL past the end. */
const char *scene_name(size_t i);
/* Build scene `name` for a width x height target. On error *out is zeroed. */
int scene_build(const char *name, int32_t width, int32_t height, scene_t *out);
const char *scene_strerror(int code);
void scene_free(scene_t *s);

/* ---- drawing (needs the core library) ----------------------------------- */

/* A full-frame target with malloc'd pixels and optional depth buffer. */
typedef struct frame {
    fxl_target_t target;
    uint16_t *pixels;
    uint16_t *depth;         /* NULL without depth */
} frame_t;

int frame_alloc(frame_t *f, int32_t width, int32_t height, fxl_pixfmt_t format, int with_depth);
void frame_free(frame_t *f);

/* Clear the clip rectangle to the background, a vertical sky gradient over
 * frame rows 0 .. frame_height - 1 (so bands of one frame match a full-frame
 * clear), and the depth buffer (if any) to 0. */
void scene_clear(fxl_target_t *t, int32_t frame_height);

/* Clear, then draw every triangle of s with a copy of *draw whose texture is
 * `tex` (NULL: untextured). Stats are added to *stats (may be NULL). Returns
 * the first error of fxl_draw_triangle (drawing stops there) or FXL_OK. */
fxl_status_t scene_render(const scene_t *s, const fxl_texture_t *tex, const fxl_draw_t *draw,
                          fxl_target_t *t, fxl_stats_t *stats);

/* ---- the gallery ---------------------------------------------------------- */

/* Every scene x {subdiv16, affine} x {point, bilinear}, in that order. */
typedef struct gallery_entry {
    const char *scene;
    const char *persp_name;  /* "subdiv16", "affine" */
    int16_t persp;
    const char *filter_name; /* "point", "bilinear" */
    uint8_t filter;          /* fxl_filter_t */
} gallery_entry_t;

size_t gallery_count(void);
/* Entry i, or -1 past the end. */
int gallery_entry(size_t i, gallery_entry_t *e);
/* The draw settings of a gallery image: fxl_draw_defaults() with the entry's
 * persp and filter, FXL_MIP_NONE, depth test + write. */
void gallery_draw_settings(const gallery_entry_t *e, fxl_draw_t *d);
/* Render one gallery image the way its golden CRC is defined: 320 x 240,
 * native RGB565, depth buffer on, gallery_draw_settings(). *out is a new
 * frame (frame_free it). Returns FXL_OK, a draw error, or FXL_ERR_NOMEM /
 * FXL_ERR_ARG when the scene, texture or frame cannot be made. */
fxl_status_t gallery_render(const gallery_entry_t *e, frame_t *out, fxl_stats_t *stats);

#endif
