/* fw_scenes.h - the scenes of the firmware example, shared by the Cortex-M4
 * firmware (examples/m4_band) and the host test (tests/test_firmware_scene.c)
 * so both feed the rasterizer the same triangles and must send the same
 * bytes to the panel.
 *
 * Freestanding C99, integers only: meshes and textures are generated once by
 * fw_scenes_init() into caller-owned memory (the sphere from fxl_sincos_q16,
 * the cube and floor from small integer tables), and every frame goes through
 * the fixed-point front end (fxl_pipeline_t). No float, no libc, no globals
 * that change.
 *
 * Scenes (all 60 degree vertical field of view, near 0.5, infinite far):
 *   cube    textured crate of half-size 1 at z = -5, rotated about x then y
 *           by (30 + 8 f, 30 + 12 f) degrees in frame f; bilinear, mips
 *   sphere  UV sphere (16 x 10) of radius 1.6, spherical texgen about y in
 *           object space, tilted 20 degrees, spun 40 f degrees about y
 *   lit     the same sphere with its parametric uv, per-vertex diffuse light
 *           plus ambient, Gouraud colour modulating the texture
 *   floor   the benchmark floor: view-space quad x = +-40, y = -0.577,
 *           z = -1 .. -50, checkerboard of 1-unit cells, bilinear, mips
 *   cube_point, floor_point   the same with point sampling and no mip
 *           levels: the rasterizer's fast span loops, for the frame-time
 *           model (examples/frame_time.py, docs/porting.md)
 */
#ifndef FW_SCENES_H
#define FW_SCENES_H

#include "fixel/pipeline.h"

enum {
    FW_SCENE_CUBE = 0,
    FW_SCENE_SPHERE = 1,
    FW_SCENE_LIT = 2,
    FW_SCENE_FLOOR = 3,
    FW_SCENE_CUBE_POINT = 4,
    FW_SCENE_FLOOR_POINT = 5,
    FW_SCENE_COUNT = 6
};

#define FW_TEX_SIDE 64                       /* every texture is 64 x 64 RGB565 */
#define FW_TEX_LEVELS 7                      /* 64, 32, ..., 1 */
#define FW_TEX_TEXELS 5461                   /* (4^7 - 1) / 3 texels of the chain */

#define FW_SPHERE_SLICES 16
#define FW_SPHERE_STACKS 10
#define FW_SPHERE_VERTS ((FW_SPHERE_STACKS + 1) * (FW_SPHERE_SLICES + 1))
/* Two triangles per quad, minus the degenerate one of each pole quad. */
#define FW_SPHERE_TRIS (FW_SPHERE_SLICES * (2 * FW_SPHERE_STACKS - 2))

/* Largest number of screen triangles one frame of any scene emits (the
 * front end may split a clipped triangle into a fan): size the band
 * renderer's store with it. The sphere emits at most FW_SPHERE_TRIS (no
 * clipping: it lies inside the view), the others far fewer. */
#define FW_MAX_SCREEN_TRIS FW_SPHERE_TRIS

typedef struct fw_scenes {
    uint16_t crate[FW_TEX_TEXELS], globe[FW_TEX_TEXELS], checker[FW_TEX_TEXELS];
    fxl_texture_t crate_tex, globe_tex, checker_tex;

    fxl_vec3_t cube_pos[24], cube_normal[24];
    fxl_texcoord_t cube_uv[24];
    uint16_t cube_idx[36];

    fxl_vec3_t sphere_pos[FW_SPHERE_VERTS], sphere_normal[FW_SPHERE_VERTS];
    fxl_texcoord_t sphere_uv[FW_SPHERE_VERTS];
    uint16_t sphere_idx[3 * FW_SPHERE_TRIS];

    fxl_vec3_t floor_pos[4];
    fxl_texcoord_t floor_uv[4];
    uint16_t floor_idx[6];
} fw_scenes_t;

/* What one frame of a scene needs: the front end's state, the mesh (whose
 * arrays point into fw_scenes_t), the draw state and the background. */
typedef struct fw_view {
    fxl_pipeline_t pipe;
    fxl_mesh_t mesh;
    fxl_draw_t draw;
    uint16_t clear_rgb565;                   /* native RGB565 */
} fw_view_t;

/* Build the textures (with their mip chains) and meshes. FXL_ERR_ARG on
 * NULL; otherwise the status of the core calls (FXL_OK). */
fxl_status_t fw_scenes_init(fw_scenes_t *s);

/* Set up frame `frame` of scene `scene` for a width x height frame. The view
 * refers to s, which must outlive it. FXL_ERR_ARG on NULL or an unknown
 * scene. */
fxl_status_t fw_scene_setup(const fw_scenes_t *s, int scene, uint32_t frame, int32_t width,
                            int32_t height, fw_view_t *out);

/* Short lower-case name ("cube", ...), or "?" for an unknown scene. */
const char *fw_scene_name(int scene);

#endif
