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
#include "left_out.h"
#include "panel_emu.h"
#include "pipe_scenes.h"
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

/* Returns 0 (FXL_OK) or, with *f empty, the fxl_status_t of the failure:
 * FXL_ERR_ARG (NULL, size outside 1..FXL_TARGET_MAX_DIM), FXL_ERR_NOMEM, or
 * the core's (FXL_ERR_UNSUPPORTED for a depth buffer in a build without
 * FXL_HAVE_DEPTH). */
int frame_alloc(frame_t *f, int32_t width, int32_t height, fxl_pixfmt_t format, int with_depth);
/* Convert f's pixels to native RGB565 in place and mark its target so:
 * for frames drawn in drawable_rgb565()'s order (left_out.h). */
void frame_to_native(frame_t *f);
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

/* Fill the clip rectangle with one native RGB565 colour and clear the
 * depth buffer (if any) to 0: what the band renderer does per band. */
void scene_clear_flat(fxl_target_t *t, uint16_t rgb565);

/* Draw `text` (texture_font_glyph's 3x5 font, `scale` px per font pixel,
 * 4 * scale advance) with its top-left at frame pixel (x, y), in colour fg
 * over a one-font-pixel drop shadow in `shadow`. Clipped to the target. */
void scene_draw_text(fxl_target_t *t, int32_t x, int32_t y, int32_t scale, const char *text,
                     uint16_t fg, uint16_t shadow);

/* ---- any scene: double-precision (above) or pipeline (pipe_scenes.h) ---- */

typedef struct anyscene {
    const char *name;
    int is_pipe;
    scene_t s;              /* double-precision scene ... */
    host_texture_t tex;     /* ... and its texture */
    pscene_t p;             /* pipeline scene (textures inside) */
} anyscene_t;

/* 1 when name is a scene of either kind. */
int anyscene_exists(const char *name);
/* Build scene `name` for width x height. texture >= 0 replaces a
 * double-precision scene's texture (texture_id_t; ignored for pipeline
 * scenes); spin turns pipeline scenes' models (pipe_scenes.h). Returns
 * SCENE_OK or a SCENE_ERR_* code; *a is then empty. */
int anyscene_build(anyscene_t *a, const char *name, int32_t width, int32_t height, int texture,
                   fxl_angle_t spin);
void anyscene_free(anyscene_t *a);
/* Draw without clearing (texture and per-part settings from the scene, the
 * rest from *d). Stats are added to (may be NULL). */
fxl_status_t anyscene_draw(anyscene_t *a, const fxl_draw_t *d, fxl_target_t *t,
                           fxl_stats_t *stats);
/* scene_clear (the sky gradient), then anyscene_draw. */
fxl_status_t anyscene_render(anyscene_t *a, const fxl_draw_t *d, fxl_target_t *t,
                             fxl_stats_t *stats);
/* The screen triangles in draw order, each pointing at its draw state in
 * draws[] (filled here); *tris is malloc'd. */
fxl_status_t anyscene_collect(anyscene_t *a, const fxl_draw_t *d,
                              fxl_draw_t draws[PSCENE_MAX_PARTS], fxl_band_tri_t **tris,
                              size_t *count);

/* ---- what a draw needs of the build (fixel/config.h) ---------------------- */

/* One draw: left_out_feature (left_out.h, included above). A scene whose
 * image needs a depth buffer: anyscene_needs_depth. */
/* left_out_feature for a built scene drawn by anyscene_draw with *d (its
 * own textures, all with mip chains; each part's state for pipeline
 * scenes) onto a target of that format, with or without a depth buffer. */
const char *anyscene_missing_feature(const anyscene_t *a, const fxl_draw_t *d, fxl_pixfmt_t format,
                                     int depth_buffer);
/* 1 when the image of scene `name` (either kind, any size) depends on the
 * depth test, i.e. some of its triangles cover the same pixel: small_tris
 * (random triangles in space) and p_cubemap (its cube sphere's split quads
 * are not planar, so the mesh is not quite convex). 0 for the others, which
 * therefore draw the same pixels without a depth buffer: one plane of
 * triangles that do not overlap (floors, fan, quad_near), convex meshes
 * with back faces culled (cube, p_cube, p_sphere's UV sphere, p_lit's two,
 * whose bounding spheres are apart on screen), or the inside of a cylinder
 * seen from within it (tunnels: a view ray meets the wall once). Measured
 * in the default build: bit-identical at 320 x 240 with every gallery
 * setting. 1 for an unknown name. */
int anyscene_needs_depth(const char *name);

/* ---- a scene on an emulated SPI panel (panel_emu.h) ---------------------- */

#define PANEL_CLEAR_RGB565 FXL_RGB565(28, 32, 44) /* the band renderer's flat clear */

typedef struct panel_check {
    panel_emu_result_t res;  /* wire CRC, bands, protocol errors, stats */
    uint32_t panel_crc;      /* CRC-32 of the panel image (native RGB565 bytes) */
    uint32_t direct_crc;     /* the same of the direct full-frame render */
    long diff_pixels;        /* pixels where the two differ (0 = bit-identical) */
    long first_diff;         /* index of the first such pixel, -1 if none */
} panel_check_t;

/* Render scene `scene` (either kind, its own texture) for the frame size of
 * `panel` in `rotation` through the real driver and band renderer into the
 * emulated panel (panel_emu_render_scene, `band_rows` rows per band, 0 =
 * 24), and directly into a full-frame native RGB565 target with depth,
 * cleared to PANEL_CLEAR_RGB565 like the bands, with the same draw state.
 * *panel_img (frame_free it) receives what the panel shows; *chk (may be
 * NULL) the CRCs and the comparison. Returns the first error (FXL_ERR_ARG
 * for an unknown panel or scene, FXL_ERR_IO for protocol errors). */
fxl_status_t panel_scene_render(const char *panel, int rotation, int band_rows,
                                const char *scene, const fxl_draw_t *d, frame_t *panel_img,
                                panel_check_t *chk);
/* The first feature panel_scene_render of `scene` with *d needs and this
 * build left out, or NULL: FXL_HAVE_DEPTH for a scene whose image depends
 * on the depth test (anyscene_needs_depth), then the draw settings' on the
 * bands (panel_band_format, left_out.h) and on the direct render (native), each with
 * depth where the build has it (anyscene_missing_feature). A render needing
 * a left-out feature returns FXL_ERR_UNSUPPORTED. */
const char *panel_scene_missing_feature(const char *scene, const fxl_draw_t *d);

/* ---- the gallery ---------------------------------------------------------- */

/* Gallery images, in this order:
 * 1. GALLERY_SCENE: every double-precision scene x {subdiv16, affine} x
 *    {point, bilinear}, mip none (the core issue's gallery);
 * 2. GALLERY_MIPS: "floor_mips", the floor with TEXTURE_CHECKER_HC in six
 *    320x240 panels side by side (3 x 2, 960 x 480, labelled), subdiv16:
 *    point without mips, bilinear without mips, per-triangle LOD (mip
 *    nearest, bilinear), per-segment LOD (mip nearest, bilinear), trilinear
 *    (mip linear, bilinear, per-segment LOD), and the level chosen per
 *    segment (TEXTURE_CHECKER_HC_LEVELS, point, mip nearest);
 * 3. GALLERY_PIPE: every pipeline scene (pipe_scenes.h) x {point (mip none),
 *    trilinear (bilinear, mip linear, per-segment LOD)}, subdiv16;
 * 4. GALLERY_PANEL: p_cube (subdiv16, bilinear) on the emulated ST7789
 *    240x320 in rotation 1, 24-row bands (panel_scene_render).
 * All at 320 x 240 unless stated, native RGB565, depth test + write. */
typedef enum gallery_kind {
    GALLERY_SCENE = 0,
    GALLERY_MIPS = 1,
    GALLERY_PIPE = 2,
    GALLERY_PANEL = 3
} gallery_kind_t;

typedef struct gallery_entry {
    gallery_kind_t kind;
    const char *id;          /* first token of the golden line, file name stem */
    const char *scene;       /* scene drawn (GALLERY_MIPS: "floor") */
    int texture;             /* texture_id_t replacing the scene's, or -1 */
    const char *persp_name;  /* "subdiv16", "affine" */
    int16_t persp;
    const char *filter_name; /* "point", "bilinear", "trilinear", "compare", ... */
    uint8_t filter;          /* fxl_filter_t */
    uint8_t mip;             /* fxl_mipmode_t */
    uint8_t lod;             /* fxl_lodmode_t */
    const char *label;       /* text on a floor_mips panel, else NULL */
    const char *panel;       /* GALLERY_PANEL: panel name, else NULL */
    int rotation, band_rows; /* GALLERY_PANEL */
} gallery_entry_t;

size_t gallery_count(void);
/* Entry i, or -1 past the end. */
int gallery_entry(size_t i, gallery_entry_t *e);
/* File name of an entry's PNG: "<id>_<persp>_<filter>.png" for scenes,
 * "floor_mips.png", "<id>.png" for the panel. */
void gallery_file_name(const gallery_entry_t *e, char *buf, size_t n);
/* The draw settings of an entry: fxl_draw_defaults() with the entry's
 * persp, filter, mip and lod, depth test + write. */
void gallery_draw_settings(const gallery_entry_t *e, fxl_draw_t *d);

/* The six panels of floor_mips, each a GALLERY_SCENE-like entry. */
#define GALLERY_MIPS_PANELS 6
int gallery_mips_panel(size_t i, gallery_entry_t *e);
/* Compose the six 320 x 240 panel frames into *out (new 960 x 480 frame,
 * 3 columns x 2 rows, labels drawn, 2-px dark gutters). Returns 0 or -1. */
int gallery_mips_compose(const frame_t panels[GALLERY_MIPS_PANELS], frame_t *out);

/* The first FXL_HAVE_ flag that entry e needs and this build left out (its
 * name), or NULL: FXL_HAVE_DEPTH for a scene whose image depends on the
 * depth test (anyscene_needs_depth), then those of its draw settings
 * (anyscene_missing_feature; for GALLERY_MIPS of every panel;
 * panel_scene_missing_feature for GALLERY_PANEL).
 * gallery_render of such an entry is refused by the core: it returns
 * FXL_ERR_UNSUPPORTED. Every other entry draws the pixels of its golden CRC;
 * without FXL_HAVE_DEPTH a scene that does not need the depth test is drawn
 * without a depth buffer. */
const char *gallery_missing_feature(const gallery_entry_t *e);

/* Render one gallery image the way its golden CRC is defined (settings
 * above). *out is a new frame (frame_free it). Returns FXL_OK, a draw error
 * (FXL_ERR_UNSUPPORTED: gallery_missing_feature), or FXL_ERR_NOMEM /
 * FXL_ERR_ARG when the scene, texture or frame cannot be made. For
 * GALLERY_PANEL the image is what the emulated panel shows; chk (may be
 * NULL) receives the panel check, otherwise it is untouched. */
fxl_status_t gallery_render(const gallery_entry_t *e, frame_t *out, fxl_stats_t *stats,
                            panel_check_t *chk);

#endif
