/* bench_frontend.h - the set-up of the front-end benchmark (instructions per
 * vertex of fxl_pipeline_emit), shared by the host (fixel-bench frontend,
 * under callgrind) and the Cortex-M4 firmware (bench/main.c, qemu -icount)
 * so both measure the same work on the same meshes.
 *
 * Each mesh is drawn at three levels: transform only (mesh uv, material
 * colour), + lighting (per-vertex diffuse from the mesh normals), + texgen
 * (lighting and the mesh's texture-coordinate generation), each without and
 * with a vertex cache of BENCH_FE_CACHE entries (>= every mesh's vertex
 * count, so each vertex is computed once). Emitted triangles go to a
 * callback that does nothing: the figures are the front end alone
 * (transform, light, texgen, clip, project, cull), no rasterizer.
 * Header-only (static functions) because the two sides are different
 * programs; only <stdint.h> and the fixel API.
 */
#ifndef FXL_BENCH_FRONTEND_H
#define FXL_BENCH_FRONTEND_H

#include <stdint.h>
#include "fixel/pipeline.h"

#define BENCH_FE_LEVELS 3
#define BENCH_FE_CACHE 1024u

static const char *const bench_fe_level_names[BENCH_FE_LEVELS] = {"transform", "light", "texgen"};

/* Pipeline for one mesh and level: 320 x 240, 60 degree perspective, near
 * 0.1, the mesh 4 units in front of the eye, turned 20 degrees about x and
 * 30 about y so a slice of every kind of triangle faces away (culled). */
static fxl_status_t bench_fe_setup(fxl_pipeline_t *p, int level, uint8_t texgen_mode)
{
    fxl_mat4_t a, b;
    fxl_status_t st = fxl_pipeline_init(p, 320, 240);
    if (st == FXL_OK) st = fxl_pipeline_set_perspective(p, FXL_ANGLE_DEG(60), 87381 /* 4/3 */, 6554, 0);
    if (st != FXL_OK) return st;
    fxl_mat4_rotate_x(&a, FXL_ANGLE_DEG(20));
    fxl_mat4_rotate_y(&b, FXL_ANGLE_DEG(30));
    if ((st = fxl_mat4_mul(&a, &b, &a)) != FXL_OK) return st;
    fxl_mat4_translate(&b, 0, 0, -4 * FXL_Q16_ONE);
    if ((st = fxl_mat4_mul(&p->model, &b, &a)) != FXL_OK) return st;
    if (level >= 1) {
        p->lighting = 1;
        p->light.dir.x = -31457; /* (-0.48, 0.6, 0.64) */
        p->light.dir.y = 39322;
        p->light.dir.z = 41943;
    }
    if (level >= 2) {
        p->texgen.mode = texgen_mode;
        p->texgen.axis = FXL_AXIS_Y;
        p->texgen.space = FXL_TEXGEN_OBJECT;
    }
    return FXL_OK;
}

/* The emit callback of the benchmark: counts and discards. */
static fxl_status_t bench_fe_sink(void *user, const fxl_vertex_t tri[3])
{
    (void)tri;
    ++*(uint32_t *)user;
    return FXL_OK;
}

#endif
