/* src/mesh.c - fxl_mesh_draw: the front end (fxl_pipeline_emit) feeding the
 * rasterizer. Kept apart from pipeline.c so the vertex path links without
 * the rasterizer (host tools and tests of the front end alone).
 */
#include "pipeline_int.h"
#include "raster_int.h"

typedef struct draw_ctx {
    fxl_target_t *target;
    const fxl_draw_t *draw;
    fxl_stats_t *stats;
} draw_ctx_t;

static fxl_status_t draw_one(void *user, const fxl_vertex_t tri[3])
{
    draw_ctx_t *c = (draw_ctx_t *)user;
    /* the settings were checked once by fxl_mesh_draw */
    return fxl__draw_valid(c->target, c->draw, tri, c->stats, 0);
}

fxl_status_t fxl_mesh_draw(fxl_pipeline_t *p, fxl_target_t *t, const fxl_draw_t *d,
                           const fxl_mesh_t *m, fxl_stats_t *stats)
{
    draw_ctx_t c;
    fxl_status_t st;
    if (!p || !t || !d || !m) return FXL_ERR_ARG;
    /* the settings' errors once, before the vertex work */
    if ((st = fxl_draw_check(t, d)) != FXL_OK) return st;
    c.target = t;
    c.draw = d;
    c.stats = stats;
    return fxl_pipeline_emit(p, m, draw_one, &c, stats);
}
