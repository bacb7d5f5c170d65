/* bench_data.h - the data fixel-bench gen-fw bakes for the firmware: the
 * scenes' screen-space triangles (the same fxl_vertex_t values the host
 * benchmark draws), their textures (full mip chains) and the list of
 * configurations to measure; optionally the meshes of the front-end
 * benchmark. */
#ifndef FXL_BENCH_DATA_H
#define FXL_BENCH_DATA_H

#include <stdint.h>
#include "fixel/fixel.h"
#include "fixel/pipeline.h"

typedef struct bench_scene {
    const char *name;
    const fxl_vertex_t *verts;   /* 3 per triangle */
    uint32_t ntri;
    const fxl_texture_t *tex;
} bench_scene_t;

typedef struct bench_cfg {
    uint8_t scene;               /* index into bench_scenes */
    int16_t persp;               /* fxl_draw_t.persp */
    uint8_t filter, mip;         /* fxl_draw_t.filter, .mip */
    const char *name;            /* "scene method filter" */
} bench_cfg_t;

/* The front-end benchmark's meshes (bench_frontend.h); bench_nmeshes is 0
 * unless gen-fw ran with --meshes 1. */
typedef struct bench_mesh {
    const char *name;
    uint8_t texgen;              /* fxl_texgen_mode_t of the texgen level */
    fxl_mesh_t mesh;
} bench_mesh_t;

extern const bench_scene_t bench_scenes[];
extern const bench_mesh_t bench_meshes[];
extern const uint32_t bench_nmeshes;
extern const bench_cfg_t bench_cfgs[];
extern const uint32_t bench_ncfg;

#endif
