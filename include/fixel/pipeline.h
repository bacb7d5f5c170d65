/* fixel/pipeline.h - the fixed-point 3D front end: matrices, projection,
 * homogeneous clipping, back-face culling, meshes, texture-coordinate
 * generation and per-vertex lighting. It turns a mesh in object space into
 * the screen-space fxl_vertex_t triangles of raster.h.
 *
 * Number formats (see docs/pipeline.md for the derivations):
 * - Positions, matrix entries, normals: q16 (fxl_q16_t), |value| < 32768,
 *   resolution 2^-16; a result outside that saturates symmetrically, to
 *   +-INT32_MAX (not to FXL_Q16_MIN), with FXL_ERR_RANGE. Internally the pipeline keeps view and clip space in
 *   int64 q32 (value * 2^32) so small near planes and deep scenes keep their
 *   precision; only the inputs and the final screen vertices are q16.
 * - Matrices are row-major, m[row][col], and act on column vectors:
 *   p' = M p, translation in column 3. fxl_mat4_mul(o, a, b) is o = a b,
 *   i.e. b is applied first.
 * - Angles: fxl_angle_t, uint16 turns (65536 = 360 degrees), so wrapping is
 *   free. Positive angles rotate counter-clockwise looking down the axis
 *   toward the origin (right-handed).
 * - View space is right-handed, the camera looks down -z, y up. The
 *   perspective matrices give clip w = -z_view (the view depth), which is
 *   what the rasterizer's 1/w needs.
 * - Clip planes (on clip coordinates, before the divide): w >= near,
 *   w <= far (when far != 0), |x| <= G w and |y| <= G w with the guard band
 *   G = FXL_GUARD_PX / max(viewport half width, half height), capped at
 *   FXL_GUARD_MAX. So no vertex with w <= 0 reaches the rasterizer and every
 *   projected coordinate lies within about FXL_GUARD_PX pixels of the
 *   viewport centre. Clip z is not used (depth is 1/w).
 * - Screen vertices: x, y q16 frame pixels, within (|x_ndc| + 1) 2^-30 hw
 *   + 1 q16 units of the exact projection of the clip-space vertex (hw the
 *   viewport's half-width in q16, y likewise; one 31-bit reciprocal of w
 *   a vertex: 0.76 units measured on a 4096-pixel viewport; the fuzzer
 *   holds them to twice that), the rasterizer's sub-pixel snap the only
 *   other quantisation; inv_w = near / w * 2^32 within 2^-30 of it plus
 *   one unit (1.6 units measured), clamped to [1, 2^32 - 1] (u0.32);
 *   u, v q16.
 * Memory: everything is caller-owned; no function allocates. The only
 * pointer kept is the optional vertex cache of a pipeline
 * (fxl_pipeline_set_vertex_cache). Status: FXL_ERR_ARG for NULL / bad enums, FXL_ERR_RANGE for
 * numbers outside the documented ranges (matrix overflow, w == 0, ...).
 */
#ifndef FIXEL_PIPELINE_H
#define FIXEL_PIPELINE_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/status.h"
#include "fixel/fixed.h"
#include "fixel/target.h"
#include "fixel/raster.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- angles and trigonometry (src/trig.c) ------------------------------- */

typedef uint16_t fxl_angle_t;            /* turns * 65536 */
/* Whole degrees d (|d| < 32768) to an angle, truncated toward zero: off by
 * under one unit (0.0055 degrees); 60 gives 10922 (exact: 10922.67). */
#define FXL_ANGLE_DEG(d) ((fxl_angle_t)(((int32_t)(d) * 65536L / 360L) & 0xFFFF))

/* sin and cos as q16. Max error vs double over all 65536 angles:
 * <= 2^-17 + 2^-21 = 2^-16.91 (measured 2^-16.96: the final rounding
 * dominates). */
fxl_q16_t fxl_sin_q16(fxl_angle_t a);
fxl_q16_t fxl_cos_q16(fxl_angle_t a);
void fxl_sincos_q16(fxl_angle_t a, fxl_q16_t *s, fxl_q16_t *c);
/* Angle of (x, y) measured from +x toward +y, in [0, 65536) turns, rounded
 * to nearest (error <= 0.5 LSB + 2^-11 LSB, the CORDIC's 2^-27 turn).
 * atan2(0, 0) = 0. */
fxl_angle_t fxl_atan2_angle(fxl_q16_t y, fxl_q16_t x);
/* acos(c) in [0, 32768] (0..180 degrees) for c in q16; c outside [-1, 1]
 * is clamped. asin(s) in [-16384, 16384] as a signed value (int32). */
int32_t fxl_acos_angle(fxl_q16_t c);
int32_t fxl_asin_angle(fxl_q16_t s);

/* ---- vectors and matrices (src/pipeline.c) ------------------------------ */

typedef struct fxl_vec3 {
    fxl_q16_t x, y, z;
} fxl_vec3_t;

typedef struct fxl_vec4 {
    fxl_q16_t x, y, z, w;
} fxl_vec4_t;

typedef struct fxl_mat4 {
    fxl_q16_t m[4][4]; /* m[row][col], column vectors */
} fxl_mat4_t;

void fxl_mat4_identity(fxl_mat4_t *m);
/* out = a b (b applied first); out may alias a or b. Entries are rounded to
 * nearest; an entry outside q16 saturates and the call returns FXL_ERR_RANGE. */
fxl_status_t fxl_mat4_mul(fxl_mat4_t *out, const fxl_mat4_t *a, const fxl_mat4_t *b);
/* out = M (x, y, z, w); saturates and returns FXL_ERR_RANGE on overflow. */
fxl_status_t fxl_mat4_transform(const fxl_mat4_t *m, const fxl_vec4_t *v, fxl_vec4_t *out);
/* Point (w = 1) and direction (w = 0); the fourth row is ignored. */
fxl_status_t fxl_mat4_transform_point(const fxl_mat4_t *m, const fxl_vec3_t *p, fxl_vec3_t *out);
fxl_status_t fxl_mat4_transform_vector(const fxl_mat4_t *m, const fxl_vec3_t *v, fxl_vec3_t *out);

/* Builders overwrite *m. Rotation entries are rounded from q30 internals. */
void fxl_mat4_rotate_x(fxl_mat4_t *m, fxl_angle_t a);
void fxl_mat4_rotate_y(fxl_mat4_t *m, fxl_angle_t a);
void fxl_mat4_rotate_z(fxl_mat4_t *m, fxl_angle_t a);
/* About a unit axis (|axis| = 1 within 2^-8, else FXL_ERR_RANGE; the axis is
 * normalised, so the result is a rotation). */
fxl_status_t fxl_mat4_rotate_axis(fxl_mat4_t *m, const fxl_vec3_t *axis, fxl_angle_t a);
void fxl_mat4_translate(fxl_mat4_t *m, fxl_q16_t x, fxl_q16_t y, fxl_q16_t z);
void fxl_mat4_scale(fxl_mat4_t *m, fxl_q16_t x, fxl_q16_t y, fxl_q16_t z);
/* Right-handed view matrix (gluLookAt). FXL_ERR_RANGE when eye == center,
 * up is zero or within ~2^-16 rad of the view direction (or opposite it),
 * or the translation overflows. The side vector is (center - eye) x up,
 * computed exactly from the q16 inputs, so the rotation entries keep
 * 2^-17 + 2^-26 and the translations 2^-17 + 3 |eye| 2^-28 (eye in units)
 * at any accepted angle. */
fxl_status_t fxl_mat4_look_at(fxl_mat4_t *m, const fxl_vec3_t *eye, const fxl_vec3_t *center,
                              const fxl_vec3_t *up);
/* OpenGL-style perspective (gluPerspective): vertical field of view
 * (0 < fovy < 32768, i.e. below 180 degrees), aspect = width / height (q16,
 * > 0), 0 < near < far. Row 3 is (0, 0, -1, 0), so clip w = -z_view exactly.
 * far == 0 gives the infinite-far variant (z row (0, 0, -1, -2 near)).
 * Within those ranges FXL_ERR_RANGE still when an entry does not fit q16:
 * cot(fovy / 2) / aspect, (far + near) / (far - near) or
 * 2 far near / (far - near) of 32768 or more (a tiny aspect, far next to
 * near), or with far == 0 the -2 near of a near of 16384 or more. */
fxl_status_t fxl_mat4_perspective(fxl_mat4_t *m, fxl_angle_t fovy, fxl_q16_t aspect,
                                  fxl_q16_t near_q16, fxl_q16_t far_q16);

/* ---- meshes ------------------------------------------------------------- */

typedef struct fxl_texcoord {
    fxl_q16_t u, v;
} fxl_texcoord_t;

/* Indexed triangle list. pos is required; the others may be NULL. Front
 * faces are whichever winding the pipeline's cull mode keeps. */
typedef struct fxl_mesh {
    const fxl_vec3_t *pos;         /* object space, q16 */
    const fxl_texcoord_t *uv;      /* q16 normalised texture coordinates */
    const uint16_t *color;         /* native RGB565 */
    const fxl_vec3_t *normal;      /* object space unit vectors, q16; transformed by view *
                                    * model's 3x3 and renormalised: right for rotations and
                                    * uniform scale, not for non-uniform scale or shear */
    uint32_t vert_count;
    const uint16_t *idx;           /* 3 * tri_count indices < vert_count */
    uint32_t tri_count;
} fxl_mesh_t;

/* Culling by the winding of the snapped screen vertices as seen on the
 * display (x right, y down in memory). With the usual counter-clockwise
 * front faces (OpenGL) use FXL_CULL_CW. Zero-area triangles are left to the
 * rasterizer (counted as degenerate there). */
typedef enum fxl_cull {
    FXL_CULL_NONE = 0,
    FXL_CULL_CW = 1,               /* drop triangles that appear clockwise */
    FXL_CULL_CCW = 2               /* drop triangles that appear counter-clockwise */
} fxl_cull_t;

/* ---- texture-coordinate generation (src/texgen.c) ----------------------- */

typedef enum fxl_texgen_mode {
    FXL_TEXGEN_NONE = 0,           /* use the mesh's uv (or 0, 0) */
    FXL_TEXGEN_PLANAR = 1,         /* u, v = two coordinates (plane) */
    FXL_TEXGEN_CYLINDRICAL = 2,    /* u = theta / 360 deg, v = height along axis */
    FXL_TEXGEN_SPHERICAL = 3,      /* u = theta / 360 deg, v = phi / 180 deg */
    FXL_TEXGEN_CUBE = 4            /* six faces in a 3x2 atlas */
} fxl_texgen_mode_t;

typedef enum fxl_texgen_space {
    FXL_TEXGEN_OBJECT = 0,         /* mesh positions as given */
    FXL_TEXGEN_EYE = 1             /* positions after model and view: each
                                    * mesh vertex's must be within q16
                                    * (+-32768 units), culled or not, else
                                    * FXL_ERR_RANGE (fxl_xform_eye) */
} fxl_texgen_space_t;

/* Planar: which two coordinates become (u, v). */
typedef enum fxl_plane {
    FXL_PLANE_XY = 0,              /* u = x, v = y */
    FXL_PLANE_YZ = 1,              /* u = y, v = z */
    FXL_PLANE_XZ = 2               /* u = x, v = z */
} fxl_plane_t;

/* Cylindrical and spherical: the axis. With (a, b, h) = (y, z, x) for X,
 * (z, x, y) for Y, (x, y, z) for Z: theta = atan2(b, a) in [0, 1) turns,
 * phi = angle from +h in [0, 0.5] turns (v = 2 phi: 0 at +h, 1 at -h). */
typedef enum fxl_axis {
    FXL_AXIS_X = 0,
    FXL_AXIS_Y = 1,
    FXL_AXIS_Z = 2
} fxl_axis_t;

/* Cube faces (major axis of the triangle's summed positions), in this
 * order; face f is tile (f % 3, f / 3) of a 3x2 atlas:
 *   row 0: +X -X +Y    row 1: -Y +Z -Z
 * Within a face, s, t in [0, 1] follow the OpenGL cube-map table
 * (+X: s=-z t=-y, -X: s=+z t=-y, +Y: s=+x t=+z, -Y: s=+x t=-z, +Z: s=+x
 * t=-y, -Z: s=-x t=-y, divided by the vertex's major coordinate and
 * mapped from [-1,1]); then u = (col + s) / 3, v = (row + t) / 2, with s,
 * t clamped to [0, 1]. A vertex on or behind its face's plane (major
 * coordinate <= 0: the face is the triangle's, not the vertex's) divides
 * by 2^-16 instead: its s and t clamp to the tile's edges (a coordinate
 * of exactly 0 stays at 1/2). */
#define FXL_CUBE_POS_X 0
#define FXL_CUBE_NEG_X 1
#define FXL_CUBE_POS_Y 2
#define FXL_CUBE_NEG_Y 3
#define FXL_CUBE_POS_Z 4
#define FXL_CUBE_NEG_Z 5

typedef struct fxl_texgen {
    uint8_t mode;                  /* fxl_texgen_mode_t */
    uint8_t space;                 /* fxl_texgen_space_t */
    uint8_t plane;                 /* fxl_plane_t (planar) */
    uint8_t axis;                  /* fxl_axis_t (cylindrical, spherical) */
    /* Final u = raw_u * scale_u + offset_u (q16), v likewise. */
    fxl_q16_t scale_u, scale_v, offset_u, offset_v;
} fxl_texgen_t;

/* Scale 1, offset 0, planar XY, axis Y, object space, mode NONE. */
void fxl_texgen_defaults(fxl_texgen_t *tg);
/* Generate (u, v) for the three vertices of one triangle from positions in
 * the chosen space. Seams: for cylindrical and spherical u, vertices are
 * shifted by whole periods so that together they span as little as they can,
 * the first keeping its own u (others may leave [0, 1]; repeat wrap makes
 * that right). Poles (a vertex on the axis, where theta is undefined:
 * spherical within 2^-10 rad of it seen from the centre, cylindrical within
 * 2^-14 (|h| + 1) of it) take the mean theta of the other vertices.
 * Cube: one face per triangle. */
fxl_status_t fxl_texgen_triangle(const fxl_texgen_t *tg, const fxl_vec3_t pos[3],
                                 fxl_texcoord_t out[3]);

/* ---- lighting (src/light.c) ---------------------------------------------- */

/* One directional light plus ambient. Channel intensities are k / 255. For
 * a vertex of base colour c (RGB565) and eye-space unit normal n:
 *   I = min(1, ambient + diffuse * max(0, n . dir)),   out = round(c * I)
 * per channel (5, 6, 5 bits), exact except within 0.004 of a rounding tie
 * (n . dir and I are q16), where it may be the other neighbour. */
typedef struct fxl_light {
    fxl_vec3_t dir;                /* unit vector toward the light, eye space, q16 */
    uint8_t ambient[3];            /* r, g, b */
    uint8_t diffuse[3];
} fxl_light_t;

/* Shade one vertex; n need not be exactly unit (n . dir is clamped to 1).
 * A NULL l or n_eye returns base_rgb565 unchanged. */
uint16_t fxl_light_shade(const fxl_light_t *l, const fxl_vec3_t *n_eye, uint16_t base_rgb565);

/* ---- the pipeline (src/pipeline.c, clip.c, mesh.c) ---------------------- */

#define FXL_GUARD_PX 8192          /* guard band half-size, pixels */
#define FXL_GUARD_MAX 256          /* cap of G (for viewports below 64 px) */
#define FXL_CLIP_MAX_VERTS 9       /* a triangle clipped by 6 planes */
/* Clip coordinates are int64 q32 and must stay below 2^52 (2^20 units). */
#define FXL_CLIP_LIMIT_Q32 ((int64_t)1 << 52)

/* Vertex cache: caller-owned scratch memory that lets a draw transform,
 * light and texgen each mesh vertex once instead of once per triangle
 * corner (a closed mesh has about 6 corners per vertex). One entry holds a
 * vertex's clip position, lit colour, the per-vertex part of texgen and,
 * once a triangle using it passed the clipper untouched, its projected
 * screen position; what depends on the whole triangle (seams, poles, cube
 * face, clipping, culling) stays per triangle, so the output is bit-identical
 * with and without the cache. Direct-mapped: vertex i uses entry i % count,
 * so count >= vert_count makes every vertex computed exactly once; fewer
 * entries still work (a vertex evicted by another is recomputed), and
 * meshes whose triangles use nearby indices (rings, grids) keep most of the
 * saving with count of about two rings. Contents are private; the cache
 * holds nothing between draws (each draw starts by emptying the entries it
 * can use), so it may be shared by pipelines drawn one after another, never
 * by two draws running at the same time. */
typedef struct fxl_vcache_entry {
    int64_t x, y, w;               /* clip space, q32 */
    int32_t tex[3];                /* per-vertex texgen data */
    fxl_q16_t sx, sy;              /* screen position, once projected */
    uint32_t inv_w;
    uint32_t tag;                  /* mesh vertex held, FXL_VCACHE_EMPTY if none */
    uint16_t color;                /* lit RGB565 */
    uint8_t projected;             /* sx, sy, inv_w are valid */
    uint8_t outcode;               /* clip planes it lies outside (in the padding) */
} fxl_vcache_entry_t;

#define FXL_VCACHE_EMPTY 0xFFFFFFFFu
/* Bytes for n entries (56 per entry with 8-byte aligned int64). */
#define FXL_VCACHE_BYTES(n) ((size_t)(n) * sizeof(fxl_vcache_entry_t))

/* Plain data; start from fxl_pipeline_init(). */
typedef struct fxl_pipeline {
    fxl_mat4_t model;              /* object -> world */
    fxl_mat4_t view;               /* world -> eye */
    fxl_mat4_t proj;               /* eye -> clip, must give w = view depth */
    fxl_q16_t near_q16;            /* clip plane w >= near (> 0) */
    fxl_q16_t far_q16;             /* w <= far; 0 = no far plane */
    int32_t vp_x, vp_y, vp_w, vp_h;/* viewport, frame pixels */
    uint8_t cull;                  /* fxl_cull_t */
    uint8_t lighting;              /* 1: per-vertex diffuse from mesh normals */
    uint16_t material;             /* RGB565 base colour when the mesh has none */
    fxl_light_t light;
    fxl_texgen_t texgen;
    fxl_vcache_entry_t *vcache;    /* optional, see fxl_pipeline_set_vertex_cache */
    uint32_t vcache_count;
} fxl_pipeline_t;

/* Identity matrices, 60 degree perspective with near 1 and infinite far,
 * viewport (0, 0, width, height), cull CW, no lighting, white material,
 * texgen off, no vertex cache. The light (used once `lighting` is set)
 * shines along +z in eye space, toward the camera, with ambient 64 and
 * diffuse 191 in every channel: a face toward it is lit fully (255), one
 * edge-on or facing away at 1/4. */
fxl_status_t fxl_pipeline_init(fxl_pipeline_t *p, int32_t width, int32_t height);
/* proj = fxl_mat4_perspective(...) and the clip planes near, far. */
fxl_status_t fxl_pipeline_set_perspective(fxl_pipeline_t *p, fxl_angle_t fovy, fxl_q16_t aspect,
                                          fxl_q16_t near_q16, fxl_q16_t far_q16);
/* Use `count` caller-owned entries as the vertex cache of the draws of p
 * (fxl_pipeline_emit, fxl_mesh_draw); entries == NULL with count == 0
 * turns the cache off (the default). The memory must stay valid while p
 * draws with it; its previous contents do not matter. FXL_ERR_ARG for
 * p == NULL or entries == NULL with count > 0. */
fxl_status_t fxl_pipeline_set_vertex_cache(fxl_pipeline_t *p, fxl_vcache_entry_t *entries,
                                           uint32_t count);
/* 1 <= w, h <= FXL_TARGET_MAX_DIM, |x|, |y| <= FXL_TARGET_MAX_ORIGIN. */
fxl_status_t fxl_pipeline_set_viewport(fxl_pipeline_t *p, int32_t x, int32_t y, int32_t w, int32_t h);

/* A clip-space vertex with its attributes, as the clipper sees it. */
typedef struct fxl_clipvert {
    int64_t x, y, w;               /* clip space, q32 */
    fxl_q16_t u, v;
    int32_t r, g, b;               /* colour channels, 0..255 in q8 (0..65280;
                                    * projected as RGB565 rounded, clamped to that range) */
} fxl_clipvert_t;

/* Everything a draw derives from the pipeline once: the combined matrices
 * in q32 and the viewport mapping. */
typedef struct fxl_xform {
    int64_t mvp[4][4];             /* proj * view * model, q32 */
    int64_t mv[4][4];              /* view * model, q32 */
    int64_t near_q32, far_q32;
    fxl_q16_t guard_q16;           /* G */
    int64_t cx_q16, cy_q16;        /* viewport centre, frame pixels */
    int64_t hw_q16, hh_q16;        /* viewport half size */
} fxl_xform_t;

/* Errors: FXL_ERR_ARG (NULL), FXL_ERR_RANGE (near <= 0, far not beyond near
 * (far 0: none), a viewport outside 1..FXL_TARGET_MAX_DIM or its origin past
 * FXL_TARGET_MAX_ORIGIN, or a product of the matrices that overflows). */
fxl_status_t fxl_pipeline_prepare(const fxl_pipeline_t *p, fxl_xform_t *xf);
/* Clip coordinates of an object-space position (attributes zeroed).
 * FXL_ERR_RANGE when a coordinate reaches FXL_CLIP_LIMIT_Q32. */
fxl_status_t fxl_xform_clip(const fxl_xform_t *xf, const fxl_vec3_t *pos, fxl_clipvert_t *out);
/* Eye-space position (q16, saturating; FXL_ERR_RANGE when it saturated). */
fxl_status_t fxl_xform_eye(const fxl_xform_t *xf, const fxl_vec3_t *pos, fxl_vec3_t *out);
/* Perspective divide and viewport mapping of a vertex with w >= near.
 * FXL_ERR_RANGE for w < near (including w <= 0) or |x|, |y| beyond the
 * guard band by more than 2^-10 G (the clipper's rounding leaves far
 * less); a vertex beyond it by less is clamped to the guard band, which
 * moves it by up to 2^-10 FXL_GUARD_PX = 8 px (the accuracy bound in the
 * header's comment holds within the guard band); for w at
 * FXL_CLIP_LIMIT_Q32 or beyond, and for an xf (filled by hand) outside the
 * ranges fxl_pipeline_prepare gives: near in [2^-16, 2^15 - 2^-16] (q32:
 * [2^16, 2^47 - 2^16]), far 0 or beyond near and at most 2^15 - 2^-16, half
 * sizes in [0.5, FXL_TARGET_MAX_DIM / 2] px, centres within
 * FXL_TARGET_MAX_ORIGIN + FXL_TARGET_MAX_DIM / 2 px, 1 <= G <= FXL_GUARD_MAX
 * with G times the larger half size <= FXL_GUARD_PX (prepare gives G >= 4). */
fxl_status_t fxl_xform_project(const fxl_xform_t *xf, const fxl_clipvert_t *c, fxl_vertex_t *out);
/* Sutherland-Hodgman against near, far (if set) and the guard band, in that
 * order; attributes interpolated linearly in clip space. Each intersection
 * is interpolated from the edge's end nearer the plane (the inside one on
 * a tie), a choice made from the two plane distances alone, so an edge
 * shared by two triangles is cut at the same point in both (watertight).
 * *n = 0 when nothing is left. in may overlap out (in[0..2] = out[0..2] is fine): it is read first. out
 * is also the clipper's work space: whatever the result, out[*n..] (all of
 * out when *n = 0, after an error too) holds no defined values.
 * A polygon that the cut points' rounding made non-convex and longer than
 * FXL_CLIP_MAX_VERTS at some plane (a triangle close to two planes at
 * once) loses the vertices nearest their neighbours, within that rounding.
 * FXL_ERR_RANGE for a vertex coordinate at FXL_CLIP_LIMIT_Q32 or beyond,
 * and for an xf outside fxl_pipeline_prepare's ranges (fxl_xform_project). */
fxl_status_t fxl_clip_triangle(const fxl_xform_t *xf, const fxl_clipvert_t in[3],
                               fxl_clipvert_t out[FXL_CLIP_MAX_VERTS], uint32_t *n);

/* Receives each screen-space triangle; a negative return stops emission.
 * tri points into fxl_pipeline_emit's own working vertices (the fan's
 * triangles are passed in place): valid during the call only, and not to
 * be written through (later triangles of the fan share its vertices). */
typedef fxl_status_t (*fxl_emit_fn)(void *user, const fxl_vertex_t tri[3]);

/* Transform, light, texgen, clip, project, cull a mesh and hand each
 * surviving triangle (a clipped polygon becomes a fan) to fn. stats (may be
 * NULL): culled_outside counts mesh triangles rejected whole by the clip
 * planes, culled_backface the fan triangles culled here, and triangles
 * both (the triangles handed to fn are counted by whoever draws them). With a
 * vertex cache set, writes p->vcache (the pipeline itself is not changed). */
fxl_status_t fxl_pipeline_emit(const fxl_pipeline_t *p, const fxl_mesh_t *m, fxl_emit_fn fn,
                               void *user, fxl_stats_t *stats);
/* fxl_pipeline_emit into fxl_draw_triangle(t, d, ...). A target or draw
 * setting every triangle would be refused for (fxl_draw_check) is returned
 * before any vertex is transformed, even when every triangle is culled.
 * Any other error (an index past the mesh, a vertex or clipped corner out
 * of range, a triangle the rasterizer refuses) stops the draw at that
 * triangle and is returned: the triangles before it stay drawn, as
 * fxl_pipeline_emit has handed them on. */
fxl_status_t fxl_mesh_draw(fxl_pipeline_t *p, fxl_target_t *t, const fxl_draw_t *d,
                           const fxl_mesh_t *m, fxl_stats_t *stats);

#ifdef __cplusplus
}
#endif
#endif
