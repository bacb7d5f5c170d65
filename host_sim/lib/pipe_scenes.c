/* pipe_scenes.c - see pipe_scenes.h. */
#include "pipe_scenes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "meshes.h"
#include "scene.h"

static const char *const pscene_names[] = {"p_floor", "p_cube",    "p_sphere",
                                           "p_tunnel", "p_cubemap", "p_lit"};
#define PSCENE_N (sizeof(pscene_names) / sizeof(pscene_names[0]))

size_t pscene_count(void)
{
    return PSCENE_N;
}

const char *pscene_name(size_t i)
{
    return i < PSCENE_N ? pscene_names[i] : NULL;
}

int pscene_exists(const char *name)
{
    size_t i;
    for (i = 0; name != NULL && i < PSCENE_N; i++) {
        if (strcmp(name, pscene_names[i]) == 0) {
            return 1;
        }
    }
    return 0;
}

/* Scene constants are given in double for readability and stored as q16
 * once, like constants in firmware source. */
static fxl_q16_t q16(double v)
{
    return (fxl_q16_t)lround(v * 65536.0);
}

/* out = translate(tx, ty, tz) * rot_y(ay) * rot_x(ax): rotate about x, then
 * about y, then move (the order scene.c's double cube uses). */
static void model_trs(fxl_mat4_t *out, fxl_angle_t ax, fxl_angle_t ay, double tx, double ty,
                      double tz)
{
    fxl_mat4_t rx, ry, t;
    fxl_mat4_rotate_x(&rx, ax);
    fxl_mat4_rotate_y(&ry, ay);
    fxl_mat4_translate(&t, q16(tx), q16(ty), q16(tz));
    /* Entries are rotations (|.| <= 1) and small translations: no
     * saturation possible, so the statuses are FXL_OK. */
    (void)fxl_mat4_mul(out, &ry, &rx);
    (void)fxl_mat4_mul(out, &t, out);
}

/* A "cube sphere": each cube face an n x n grid whose vertices are pushed
 * out to the sphere of radius r. Unlike a UV sphere, no triangle straddles
 * two cube faces (every vertex of face f has its major axis along f's
 * normal), so FXL_TEXGEN_CUBE, which picks one face per triangle, maps it
 * without clamped, smeared triangles along the face boundaries. Grid lines
 * are spaced by angle (tan) so the cells are of similar size. Front faces
 * are counter-clockwise from outside, like meshes.h. Released with
 * meshes_free. */
static int cube_sphere(fxl_mesh_t *m, double r, int n)
{
    static const double face[6][3][3] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}}};
    const double quarter_pi = 0.78539816339744830962;
    uint32_t row = (uint32_t)n + 1u, verts = 6u * row * row, tris = 6u * 2u * (uint32_t)(n * n);
    fxl_vec3_t *pos, *nrm;
    uint16_t *idx, *o;
    int f, i, j, k;
    memset(m, 0, sizeof(*m));
    if (n < 1 || verts > 65535u) {
        return -1;
    }
    pos = (fxl_vec3_t *)calloc(verts, sizeof(*pos));
    nrm = (fxl_vec3_t *)calloc(verts, sizeof(*nrm));
    idx = (uint16_t *)calloc((size_t)tris * 3u, sizeof(*idx));
    if (pos == NULL || nrm == NULL || idx == NULL) {
        free(pos);
        free(nrm);
        free(idx);
        return -1;
    }
    o = idx;
    for (f = 0; f < 6; f++) {
        const double *fn = face[f][0], *fr = face[f][1], *fu = face[f][2];
        uint32_t base = (uint32_t)f * row * row;
        for (j = 0; j <= n; j++) {
            for (i = 0; i <= n; i++) {
                double a = tan(quarter_pi * (2.0 * i / n - 1.0));
                double b = tan(quarter_pi * (2.0 * j / n - 1.0));
                double p[3], len = 0.0;
                uint32_t v = base + (uint32_t)j * row + (uint32_t)i;
                for (k = 0; k < 3; k++) {
                    p[k] = fn[k] + a * fr[k] + b * fu[k];
                    len += p[k] * p[k];
                }
                len = sqrt(len);
                pos[v].x = q16(r * p[0] / len);
                pos[v].y = q16(r * p[1] / len);
                pos[v].z = q16(r * p[2] / len);
                nrm[v].x = q16(p[0] / len);
                nrm[v].y = q16(p[1] / len);
                nrm[v].z = q16(p[2] / len);
            }
        }
        for (j = 0; j < n; j++) {
            for (i = 0; i < n; i++) {
                /* (i, j) -> (i+1, j) -> (i+1, j+1) -> (i, j+1) runs along
                 * right then up, counter-clockwise seen from outside. */
                uint16_t a = (uint16_t)(base + (uint32_t)j * row + (uint32_t)i);
                uint16_t b = (uint16_t)(a + 1u), c = (uint16_t)(a + row + 1u),
                         d = (uint16_t)(a + row);
                o[0] = a;
                o[1] = b;
                o[2] = c;
                o[3] = a;
                o[4] = c;
                o[5] = d;
                o += 6;
            }
        }
    }
    m->pos = pos;
    m->normal = nrm;
    m->idx = idx;
    m->vert_count = verts;
    m->tri_count = tris;
    return 0;
}

static int add_texture(pscene_t *s, texture_id_t id)
{
    if (s->texs >= PSCENE_MAX_TEX || texture_make(&s->tex[s->texs], id) != 0) {
        return -1;
    }
    return s->texs++;
}

/* A new part with the common camera; the mesh is built by the caller. */
static pscene_part_t *add_part(pscene_t *s, int tex)
{
    pscene_part_t *p;
    if (s->parts >= PSCENE_MAX_PARTS || tex < 0) {
        return NULL;
    }
    p = &s->part[s->parts++];
    memset(p, 0, sizeof(*p));
    if (fxl_pipeline_init(&p->pipe, s->width, s->height) != FXL_OK ||
        fxl_pipeline_set_perspective(&p->pipe, FXL_ANGLE_DEG(60),
                                     q16((double)s->width / (double)s->height), q16(0.1),
                                     0) != FXL_OK) {
        return NULL;
    }
    p->pipe.cull = FXL_CULL_CW;
    p->tex = tex;
    return p;
}

static void light_upper_left(fxl_pipeline_t *pp)
{
    /* Toward the light: up, left and toward the viewer, normalised. */
    const double lx = -0.5, ly = 0.6, lz = 0.62, n = sqrt(lx * lx + ly * ly + lz * lz);
    pp->lighting = 1;
    pp->light.dir.x = q16(lx / n);
    pp->light.dir.y = q16(ly / n);
    pp->light.dir.z = q16(lz / n);
    pp->light.ambient[0] = pp->light.ambient[1] = pp->light.ambient[2] = 40;
    pp->light.diffuse[0] = pp->light.diffuse[1] = pp->light.diffuse[2] = 235;
    pp->material = FXL_RGB565(255, 255, 255);
}

static int build_parts(pscene_t *s, const char *name, fxl_angle_t spin)
{
    pscene_part_t *p;
    int t0, t1;
    if (strcmp(name, "p_floor") == 0) {
        if ((p = add_part(s, add_texture(s, TEXTURE_CHECKER))) == NULL ||
            meshes_floor(&p->mesh, -0.577, -40.0, 40.0, -50.0, -1.0, 1, 1, 2.0) != 0) {
            return -1;
        }
        model_trs(&p->pipe.model, 0, spin, 0.0, 0.0, 0.0);
    } else if (strcmp(name, "p_cube") == 0) {
        if ((p = add_part(s, add_texture(s, TEXTURE_CRATE))) == NULL ||
            meshes_cube(&p->mesh, 1.0) != 0) {
            return -1;
        }
        model_trs(&p->pipe.model, FXL_ANGLE_DEG(30), (fxl_angle_t)(FXL_ANGLE_DEG(30) + spin), 0.0,
                  0.0, -5.0);
    } else if (strcmp(name, "p_sphere") == 0) {
        if ((p = add_part(s, add_texture(s, TEXTURE_GRID))) == NULL ||
            meshes_sphere(&p->mesh, 1.3, 32, 16) != 0) {
            return -1;
        }
        model_trs(&p->pipe.model, FXL_ANGLE_DEG(40), (fxl_angle_t)(FXL_ANGLE_DEG(20) + spin), 0.0,
                  0.0, -4.0);
        p->pipe.texgen.mode = FXL_TEXGEN_SPHERICAL;
        p->pipe.texgen.space = FXL_TEXGEN_OBJECT;
        p->pipe.texgen.axis = FXL_AXIS_Y;
        p->pipe.texgen.scale_u = FXL_Q16_INT(2); /* the equator is twice a meridian */
    } else if (strcmp(name, "p_tunnel") == 0) {
        /* Cylinder about +y from 0 to 40, turned so +y runs down -z
         * (rotate_x(-90): y -> -z), then offset from the eye. */
        if ((p = add_part(s, add_texture(s, TEXTURE_GRID))) == NULL ||
            meshes_cylinder(&p->mesh, 1.0, 0.0, 40.0, 24, 40, 1) != 0) {
            return -1;
        }
        model_trs(&p->pipe.model, FXL_ANGLE_DEG(-90), spin, -0.25, -0.15, 0.0);
        p->pipe.texgen.mode = FXL_TEXGEN_CYLINDRICAL;
        p->pipe.texgen.space = FXL_TEXGEN_OBJECT;
        p->pipe.texgen.axis = FXL_AXIS_Y;
        /* 4 texture widths around a circumference of 2 pi: one width is
         * pi / 2 units, so v = y / (pi / 2) keeps texels square. */
        p->pipe.texgen.scale_u = FXL_Q16_INT(4);
        p->pipe.texgen.scale_v = q16(2.0 / 3.14159265358979323846);
    } else if (strcmp(name, "p_cubemap") == 0) {
        t0 = add_texture(s, TEXTURE_CUBEMAP);
        if ((p = add_part(s, t0)) == NULL || cube_sphere(&p->mesh, 1.0, 8) != 0) {
            return -1;
        }
        model_trs(&p->pipe.model, FXL_ANGLE_DEG(25), (fxl_angle_t)(FXL_ANGLE_DEG(-35) + spin),
                  -1.25, 0.0, -4.5);
        p->pipe.texgen.mode = FXL_TEXGEN_CUBE;
        p->pipe.texgen.space = FXL_TEXGEN_OBJECT;
        if ((p = add_part(s, t0)) == NULL || meshes_cube(&p->mesh, 0.75) != 0) {
            return -1;
        }
        model_trs(&p->pipe.model, FXL_ANGLE_DEG(25), (fxl_angle_t)(FXL_ANGLE_DEG(-35) + spin),
                  1.3, 0.0, -4.5);
        p->pipe.texgen.mode = FXL_TEXGEN_CUBE;
        p->pipe.texgen.space = FXL_TEXGEN_OBJECT;
    } else if (strcmp(name, "p_lit") == 0) {
        t0 = add_texture(s, TEXTURE_GRID);
        t1 = add_texture(s, TEXTURE_CRATE);
        if ((p = add_part(s, t0)) == NULL || meshes_sphere(&p->mesh, 1.0, 32, 16) != 0) {
            return -1;
        }
        model_trs(&p->pipe.model, FXL_ANGLE_DEG(15), (fxl_angle_t)(FXL_ANGLE_DEG(30) + spin),
                  -1.15, 0.0, -4.2);
        light_upper_left(&p->pipe);
        p->lit = 1;
        if ((p = add_part(s, t1)) == NULL || meshes_cube(&p->mesh, 0.7) != 0) {
            return -1;
        }
        model_trs(&p->pipe.model, FXL_ANGLE_DEG(30), (fxl_angle_t)(FXL_ANGLE_DEG(30) + spin),
                  1.25, 0.0, -4.2);
        light_upper_left(&p->pipe);
        p->lit = 1;
    } else {
        return -1;
    }
    return 0;
}

int pscene_build(const char *name, int32_t width, int32_t height, fxl_angle_t spin,
                 pscene_t *out)
{
    size_t i;
    if (out == NULL) {
        return SCENE_ERR_NAME;
    }
    memset(out, 0, sizeof(*out));
    for (i = 0; name != NULL && i < PSCENE_N; i++) {
        if (strcmp(name, pscene_names[i]) == 0) {
            out->name = pscene_names[i];
        }
    }
    if (out->name == NULL) {
        return SCENE_ERR_NAME;
    }
    if (width < 1 || height < 1 || width > FXL_TARGET_MAX_DIM || height > FXL_TARGET_MAX_DIM) {
        memset(out, 0, sizeof(*out));
        return SCENE_ERR_SIZE;
    }
    out->width = width;
    out->height = height;
    if (build_parts(out, name, spin) != 0) {
        pscene_free(out);
        return SCENE_ERR_NOMEM;
    }
    return SCENE_OK;
}

void pscene_free(pscene_t *s)
{
    int i;
    if (s == NULL) {
        return;
    }
    for (i = 0; i < PSCENE_MAX_PARTS; i++) {
        meshes_free(&s->part[i].mesh);
    }
    for (i = 0; i < s->texs; i++) {
        texture_free(&s->tex[i]);
    }
    memset(s, 0, sizeof(*s));
}

void pscene_part_draw(const pscene_t *s, int i, const fxl_draw_t *base, fxl_draw_t *out)
{
    *out = *base;
    out->texture = &s->tex[s->part[i].tex].tex;
    if (s->part[i].lit) {
        out->shade = FXL_SHADE_GOURAUD;
        out->texenv = FXL_TEXENV_MODULATE;
    }
}

const char *pscene_missing_feature(const pscene_t *s, const fxl_draw_t *base, fxl_pixfmt_t format,
                                   int depth_buffer)
{
    const char *m = NULL;
    int i;
    for (i = 0; i < s->parts && m == NULL; i++) {
        fxl_draw_t d;
        pscene_part_draw(s, i, base, &d);
        m = left_out_feature(&d, d.texture, format, depth_buffer);
    }
    return m;
}

/* A vertex cache for the largest part (pipeline.h), so every mesh vertex
 * is transformed, lit and texgen'd once per draw; the output is
 * bit-identical to drawing without it. NULL (no cache) when out of
 * memory. Released with free(). */
static fxl_vcache_entry_t *part_cache(const pscene_t *s, uint32_t *count)
{
    uint32_t n = 0;
    int i;
    for (i = 0; i < s->parts; i++) {
        if (s->part[i].mesh.vert_count > n) {
            n = s->part[i].mesh.vert_count;
        }
    }
    *count = n;
    return n ? (fxl_vcache_entry_t *)malloc(FXL_VCACHE_BYTES(n)) : NULL;
}

/* The part's pipeline with the cache set (a copy: the stored pipeline never
 * keeps a pointer to the temporary cache). */
static void part_pipe(const pscene_t *s, int i, fxl_vcache_entry_t *cache, uint32_t count,
                      fxl_pipeline_t *out)
{
    *out = s->part[i].pipe;
    (void)fxl_pipeline_set_vertex_cache(out, cache, cache ? count : 0);
}

fxl_status_t pscene_draw(pscene_t *s, const fxl_draw_t *base, fxl_target_t *t,
                         fxl_stats_t *stats)
{
    fxl_vcache_entry_t *cache;
    uint32_t count;
    int i;
    if (s == NULL || base == NULL || t == NULL) {
        return FXL_ERR_ARG;
    }
    cache = part_cache(s, &count);
    for (i = 0; i < s->parts; i++) {
        fxl_draw_t d;
        fxl_pipeline_t pipe;
        fxl_status_t st;
        pscene_part_draw(s, i, base, &d);
        part_pipe(s, i, cache, count, &pipe);
        st = fxl_mesh_draw(&pipe, t, &d, &s->part[i].mesh, stats);
        if (st != FXL_OK) {
            free(cache);
            return st;
        }
    }
    free(cache);
    return FXL_OK;
}

typedef struct collector {
    fxl_band_tri_t *tris;
    size_t count, cap;
    const fxl_draw_t *draw;
} collector_t;

static fxl_status_t collect_one(void *user, const fxl_vertex_t tri[3])
{
    collector_t *c = (collector_t *)user;
    if (c->count == c->cap) {
        size_t cap = c->cap ? 2u * c->cap : 256u;
        fxl_band_tri_t *n = (fxl_band_tri_t *)realloc(c->tris, cap * sizeof(*n));
        if (n == NULL) {
            return FXL_ERR_NOMEM;
        }
        c->tris = n;
        c->cap = cap;
    }
    memset(&c->tris[c->count], 0, sizeof(c->tris[0]));
    memcpy(c->tris[c->count].v, tri, 3u * sizeof(fxl_vertex_t));
    c->tris[c->count].draw = c->draw;
    c->count++;
    return FXL_OK;
}

fxl_status_t pscene_collect(pscene_t *s, const fxl_draw_t *base,
                            fxl_draw_t draws[PSCENE_MAX_PARTS], fxl_band_tri_t **tris,
                            size_t *count)
{
    collector_t c;
    fxl_vcache_entry_t *cache;
    uint32_t ncache;
    int i;
    if (s == NULL || base == NULL || draws == NULL || tris == NULL || count == NULL) {
        return FXL_ERR_ARG;
    }
    memset(&c, 0, sizeof(c));
    cache = part_cache(s, &ncache);
    for (i = 0; i < s->parts; i++) {
        fxl_pipeline_t pipe;
        fxl_status_t st;
        pscene_part_draw(s, i, base, &draws[i]);
        c.draw = &draws[i];
        part_pipe(s, i, cache, ncache, &pipe);
        st = fxl_pipeline_emit(&pipe, &s->part[i].mesh, collect_one, &c, NULL);
        if (st != FXL_OK) {
            free(cache);
            free(c.tris);
            *tris = NULL;
            *count = 0;
            return st;
        }
    }
    free(cache);
    *tris = c.tris;
    *count = c.count;
    return FXL_OK;
}
