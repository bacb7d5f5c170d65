/* pipe_scenes.h - simulator scenes drawn entirely by the fixed-point front
 * end (fixel/pipeline.h), host side.
 *
 * A scene is up to PSCENE_MAX_PARTS meshes (host_sim/lib/meshes.h builders,
 * computed once in double and stored as q16 like any firmware asset), each
 * with its own fxl_pipeline_t (matrices, texgen, lighting) and texture. From
 * there on everything is the core's integer code: model/view/projection,
 * homogeneous clipping, projection, culling, texgen and lighting in
 * fxl_pipeline_emit, rasterization in fxl_draw_triangle. No projection is
 * done in double here.
 *
 * Common camera: eye at the origin looking down -z (identity view), 60
 * degree vertical field of view, aspect = width / height, near 0.1, no far
 * plane; viewport = the whole width x height target; cull CW (meshes are
 * counter-clockwise from the front).
 *
 * Scenes (`spin` turns every model about its vertical axis; 0 for stills):
 *   p_floor    the floor of scene.h ("floor") as a 1x1 mesh: y = -0.577,
 *              x in [-40, 40], z in [-50, -1], u = x / 2, v = z / 2,
 *              checker texture.
 *   p_cube     the cube of scene.h ("cube"): side 2, rotated 30 degrees about
 *              x then 30 about y (+ spin), centre z = -5, crate texture with
 *              the mesh's per-face uv.
 *   p_sphere   sphere r = 1.3 (32 slices, 16 stacks) at z = -4, tilted 40
 *              degrees toward the viewer so the north pole shows, seam turned
 *              20 degrees off centre; spherical texgen (object space, axis
 *              y, u scaled x2) on the numbered grid texture: shows the seam
 *              fix and the poles.
 *   p_tunnel   inside of a cylinder r = 1 (24 x 40 quads, 40 long) along -z,
 *              eye inside, off the axis by (0.25, 0.15); cylindrical texgen
 *              about the mesh axis, 4 turns of the grid texture around,
 *              v scaled for square texels; near-clipped first ring.
 *   p_cubemap  a sphere (left) and a cube (right) with cube-map texgen in
 *              object space on the six-face atlas (textures.h), turned so
 *              three faces of each show. The sphere is a "cube sphere" (each
 *              cube face an 8 x 8 grid pushed out to the sphere): texgen
 *              picks one face per triangle, so on a UV sphere the triangles
 *              straddling a face boundary would show clamped, smeared texels
 *              and a zigzag boundary; here every triangle lies in one face.
 *   p_lit      Gouraud-lit textured meshes: a sphere with the grid texture
 *              (mesh uv) and a crate cube, per-vertex diffuse light from the
 *              upper left front plus ambient, FXL_SHADE_GOURAUD and
 *              FXL_TEXENV_MODULATE (the caller's draw is overridden for
 *              those two fields only).
 */
#ifndef FXL_HOST_PIPE_SCENES_H
#define FXL_HOST_PIPE_SCENES_H

#include <stddef.h>
#include <stdint.h>

#include "fixel/fixel.h"
#include "fixel/pipeline.h"
#include "fixel/port.h"
#include "textures.h"

#define PSCENE_MAX_PARTS 4
#define PSCENE_MAX_TEX 2

typedef struct pscene_part {
    fxl_mesh_t mesh;           /* malloc'd by meshes.h */
    fxl_pipeline_t pipe;
    int tex;                   /* index into pscene_t.tex */
    int lit;                   /* 1: FXL_SHADE_GOURAUD + FXL_TEXENV_MODULATE */
} pscene_part_t;

typedef struct pscene {
    const char *name;          /* static string */
    int32_t width, height;
    pscene_part_t part[PSCENE_MAX_PARTS];
    int parts;
    host_texture_t tex[PSCENE_MAX_TEX];
    int texs;
} pscene_t;

size_t pscene_count(void);
/* Name of scene i, NULL past the end. */
const char *pscene_name(size_t i);
/* 1 when `name` is a pipeline scene. */
int pscene_exists(const char *name);
/* Build scene `name` for a width x height target. Returns 0, or a SCENE_ERR_*
 * code of scene.h (name, size, out of memory); *out is then empty. */
int pscene_build(const char *name, int32_t width, int32_t height, fxl_angle_t spin,
                 pscene_t *out);
void pscene_free(pscene_t *s);

/* The draw state of part i: *base with the part's texture (and, for lit
 * parts, Gouraud shading and modulate). */
void pscene_part_draw(const pscene_t *s, int i, const fxl_draw_t *base, fxl_draw_t *out);

/* The first feature a draw of s with *base onto a target of that format,
 * with or without a depth buffer, needs and this build left out
 * (left_out_feature of left_out.h on every part's state), or NULL. */
const char *pscene_missing_feature(const pscene_t *s, const fxl_draw_t *base, fxl_pixfmt_t format,
                                   int depth_buffer);

/* Draw every part with fxl_mesh_draw (no clear). Stats are added to. */
fxl_status_t pscene_draw(pscene_t *s, const fxl_draw_t *base, fxl_target_t *t,
                         fxl_stats_t *stats);

/* The screen-space triangles the front end emits, in draw order, each with
 * its part's draw state: draws[i] is filled for part i and must live as long
 * as the triangles are used. *tris is malloc'd (free it); *count triangles.
 * For the band renderer (port.h), which takes triangles, not meshes. */
fxl_status_t pscene_collect(pscene_t *s, const fxl_draw_t *base,
                            fxl_draw_t draws[PSCENE_MAX_PARTS], fxl_band_tri_t **tris,
                            size_t *count);

#endif
