/* fw_scenes.c - see fw_scenes.h. Integer arithmetic only. */
#include "fw_scenes.h"

#define Q(i) FXL_Q16_INT(i)

/* ---- textures ------------------------------------------------------------- */

/* Level 0 of the crate: a dark frame, two diagonal braces, planks with a
 * little grain. The values only have to be fixed, not pretty. */
static uint16_t crate_texel(int x, int y)
{
    int d = x - y, e = x + y - (FW_TEX_SIDE - 1), grain;
    if (x < 4 || x >= FW_TEX_SIDE - 4 || y < 4 || y >= FW_TEX_SIDE - 4)
        return FXL_RGB565(92, 52, 22);
    if ((d > -4 && d < 4) || (e > -4 && e < 4)) return FXL_RGB565(150, 96, 42);
    if ((y & 15) == 0) return FXL_RGB565(70, 40, 16);
    grain = ((x * 5 + (y & 15) * 3) & 7) * 4;
    return FXL_RGB565(172 + grain, 118 + grain, 56);
}

/* Globe: 8 x 8 cells, one hue per row of cells (latitude bands), light and
 * dark checker, thin grid lines, so texgen seams and poles show up. */
static uint16_t globe_texel(int x, int y)
{
    static const uint8_t band[8][3] = {{240, 90, 80},  {240, 170, 60}, {220, 220, 70},
                                       {100, 210, 90}, {70, 200, 200}, {80, 130, 240},
                                       {150, 100, 230}, {230, 100, 190}};
    const uint8_t *c = band[(y >> 3) & 7];
    if ((x & 7) == 0 || (y & 7) == 0) return FXL_RGB565(250, 250, 250);
    if (((x >> 3) + (y >> 3)) & 1) return FXL_RGB565(c[0] / 2, c[1] / 2, c[2] / 2);
    return FXL_RGB565(c[0], c[1], c[2]);
}

/* Checkerboard of 8 x 8 cells of 8 texels (one floor unit per cell). */
static uint16_t checker_texel(int x, int y)
{
    return (((x >> 3) + (y >> 3)) & 1) ? FXL_RGB565(232, 232, 220) : FXL_RGB565(40, 60, 120);
}

static fxl_status_t make_texture(uint16_t *texels, fxl_texture_t *t, uint16_t (*texel)(int, int))
{
    fxl_status_t st;
    int x, y;
    for (y = 0; y < FW_TEX_SIDE; y++)
        for (x = 0; x < FW_TEX_SIDE; x++) texels[y * FW_TEX_SIDE + x] = texel(x, y);
    /* The chain is built once here, never per frame (issue 3). */
    st = fxl_mip_build(texels, (uint32_t)(FW_TEX_TEXELS * sizeof(uint16_t)), FW_TEX_SIDE,
                       FW_TEX_SIDE, FXL_TEXFMT_RGB565, FW_TEX_LEVELS, (const uint16_t *)0,
                       FXL_MIP_SPACE_STORED);
    if (st != FXL_OK) return st;
    return fxl_texture_init(t, texels, FW_TEX_SIDE, FW_TEX_SIDE, FXL_TEXFMT_RGB565, FW_TEX_LEVELS);
}

/* ---- meshes ----------------------------------------------------------------- */

static fxl_vec3_t vec3(fxl_q16_t x, fxl_q16_t y, fxl_q16_t z)
{
    fxl_vec3_t v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

/* Cube of half-size 1: per face the outward normal n, right r and up t with
 * r x t = n, so corners BL, BR, TR, TL run counter-clockwise seen from
 * outside (front faces for FXL_CULL_CW). v = 0 at the face's top. */
static void build_cube(fw_scenes_t *s)
{
    static const int8_t f[6][3][3] = {
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}};
    static const int8_t corner[4][4] = {{-1, -1, 0, 1}, {1, -1, 1, 1}, {1, 1, 1, 0}, {-1, 1, 0, 0}};
    int i, k, a;
    for (i = 0; i < 6; i++) {
        for (k = 0; k < 4; k++) {
            int32_t p[3];
            for (a = 0; a < 3; a++) p[a] = f[i][0][a] + corner[k][0] * f[i][1][a] + corner[k][1] * f[i][2][a];
            s->cube_pos[4 * i + k] = vec3(Q(p[0]), Q(p[1]), Q(p[2]));
            s->cube_normal[4 * i + k] = vec3(Q(f[i][0][0]), Q(f[i][0][1]), Q(f[i][0][2]));
            s->cube_uv[4 * i + k].u = Q(corner[k][2]);
            s->cube_uv[4 * i + k].v = Q(corner[k][3]);
        }
        s->cube_idx[6 * i + 0] = (uint16_t)(4 * i);
        s->cube_idx[6 * i + 1] = (uint16_t)(4 * i + 1);
        s->cube_idx[6 * i + 2] = (uint16_t)(4 * i + 2);
        s->cube_idx[6 * i + 3] = (uint16_t)(4 * i);
        s->cube_idx[6 * i + 4] = (uint16_t)(4 * i + 2);
        s->cube_idx[6 * i + 5] = (uint16_t)(4 * i + 3);
    }
}

/* UV sphere about the y axis: row i at polar angle phi = 180 i / stacks
 * degrees from +y, column j at theta = 360 j / slices (x = r sin theta,
 * z = r cos theta, so j runs to the right seen from +z). The seam column is
 * duplicated (j = slices, u = 1) and each pole is a row of coincident
 * vertices with u at the middle of its quad, so the parametric uv has no
 * wrap; texgen recomputes u, v and handles the seam and the poles itself.
 * Quad (i, j) with corners a (i, j), b (i, j+1), c (i+1, j+1), d (i+1, j)
 * gives the counter-clockwise triangles (a, d, c) and (a, c, b); the one of
 * the two that has both pole corners is degenerate and left out. */
static void build_sphere(fw_scenes_t *s)
{
    const fxl_q16_t radius = 104858; /* 1.6 */
    const int n = FW_SPHERE_SLICES + 1;
    int i, j, k = 0;
    for (i = 0; i <= FW_SPHERE_STACKS; i++) {
        fxl_q16_t sp, cp;
        fxl_sincos_q16((fxl_angle_t)((uint32_t)i * 32768u / FW_SPHERE_STACKS), &sp, &cp);
        for (j = 0; j <= FW_SPHERE_SLICES; j++) {
            fxl_q16_t st, ct;
            fxl_vec3_t nrm;
            int v = i * n + j;
            fxl_sincos_q16((fxl_angle_t)((uint32_t)j * 65536u / FW_SPHERE_SLICES), &st, &ct);
            nrm = vec3(fxl_q16_mul_sat(sp, st), cp, fxl_q16_mul_sat(sp, ct));
            s->sphere_normal[v] = nrm;
            s->sphere_pos[v] = vec3(fxl_q16_mul_sat(nrm.x, radius), fxl_q16_mul_sat(nrm.y, radius),
                                    fxl_q16_mul_sat(nrm.z, radius));
            s->sphere_uv[v].u = (fxl_q16_t)((2 * j + (i == 0 || i == FW_SPHERE_STACKS)) * 32768 /
                                            FW_SPHERE_SLICES);
            s->sphere_uv[v].v = (fxl_q16_t)(i * 65536 / FW_SPHERE_STACKS);
        }
    }
    for (i = 0; i < FW_SPHERE_STACKS; i++)
        for (j = 0; j < FW_SPHERE_SLICES; j++) {
            uint16_t a = (uint16_t)(i * n + j), b = (uint16_t)(a + 1), c = (uint16_t)(a + n + 1),
                     d = (uint16_t)(a + n);
            if (i != FW_SPHERE_STACKS - 1) {
                s->sphere_idx[k++] = a;
                s->sphere_idx[k++] = d;
                s->sphere_idx[k++] = c;
            }
            if (i != 0) {
                s->sphere_idx[k++] = a;
                s->sphere_idx[k++] = c;
                s->sphere_idx[k++] = b;
            }
        }
}

/* The benchmark floor (issue 2): view-space quad, counter-clockwise seen
 * from above; u = x / 8, v = z / 8 (one texture per 8 units, 1-unit cells). */
static void build_floor(fw_scenes_t *s)
{
    static const int8_t xz[4][2] = {{-40, -1}, {40, -1}, {40, -50}, {-40, -50}};
    static const uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
    const fxl_q16_t y = -37815; /* -0.577: tan 30 deg, the near edge meets the bottom row */
    int k;
    for (k = 0; k < 4; k++) {
        s->floor_pos[k] = vec3(Q(xz[k][0]), y, Q(xz[k][1]));
        s->floor_uv[k].u = Q(xz[k][0]) / 8;
        s->floor_uv[k].v = Q(xz[k][1]) / 8;
    }
    for (k = 0; k < 6; k++) s->floor_idx[k] = idx[k];
}

fxl_status_t fw_scenes_init(fw_scenes_t *s)
{
    fxl_status_t st;
    if (s == (fw_scenes_t *)0) return FXL_ERR_ARG;
    st = make_texture(s->crate, &s->crate_tex, crate_texel);
    if (st == FXL_OK) st = make_texture(s->globe, &s->globe_tex, globe_texel);
    if (st == FXL_OK) st = make_texture(s->checker, &s->checker_tex, checker_texel);
    if (st != FXL_OK) return st;
    build_cube(s);
    build_sphere(s);
    build_floor(s);
    return FXL_OK;
}

/* ---- per-frame set-up ------------------------------------------------------- */

const char *fw_scene_name(int scene)
{
    static const char *const names[FW_SCENE_COUNT] = {"cube",  "sphere",     "lit",
                                                             "floor", "cube_point", "floor_point"};
    return scene >= 0 && scene < FW_SCENE_COUNT ? names[scene] : "?";
}

/* model = translate(0, 0, -5) * rotate_b * rotate_a (rotate_a applied first). */
static fxl_status_t place(fxl_mat4_t *model, const fxl_mat4_t *rot_a, const fxl_mat4_t *rot_b)
{
    fxl_mat4_t t;
    fxl_status_t st = fxl_mat4_mul(model, rot_b, rot_a);
    fxl_mat4_translate(&t, 0, 0, Q(-5));
    if (st == FXL_OK) st = fxl_mat4_mul(model, &t, model);
    return st;
}

static void set_mesh(fxl_mesh_t *m, const fxl_vec3_t *pos, const fxl_texcoord_t *uv,
                     const fxl_vec3_t *normal, uint32_t verts, const uint16_t *idx, uint32_t tris)
{
    m->pos = pos;
    m->uv = uv;
    m->color = (const uint16_t *)0;
    m->normal = normal;
    m->vert_count = verts;
    m->idx = idx;
    m->tri_count = tris;
}

fxl_status_t fw_scene_setup(const fw_scenes_t *s, int scene, uint32_t frame, int32_t width,
                            int32_t height, fw_view_t *out)
{
    fxl_mat4_t ra, rb;
    fxl_status_t st;
    /* Frame angles repeat after 36 frames; keeping f < 36 also keeps
     * FXL_ANGLE_DEG's d * 65536 below 2^31 (d <= 30 + 40 * 35 = 1430). */
    const int32_t f = (int32_t)(frame % 36u);
    if (s == (const fw_scenes_t *)0 || out == (fw_view_t *)0 || scene < 0 || scene >= FW_SCENE_COUNT ||
        height <= 0)
        return FXL_ERR_ARG;
    st = fxl_pipeline_init(&out->pipe, width, height);
    if (st != FXL_OK) return st;
    /* aspect = width / height in q16; width <= FXL_TARGET_MAX_DIM keeps the
     * shifted value far inside int32 (checked by fxl_pipeline_init). */
    st = fxl_pipeline_set_perspective(&out->pipe, FXL_ANGLE_DEG(60), (fxl_q16_t)(width * 65536 / height),
                                      FXL_Q16_HALF, 0);
    if (st != FXL_OK) return st;
    out->pipe.cull = FXL_CULL_CW;
    fxl_draw_defaults(&out->draw);
    out->draw.filter = FXL_FILTER_BILINEAR;
    out->clear_rgb565 = FXL_RGB565(24, 28, 40);

    switch (scene) {
    case FW_SCENE_CUBE:
    case FW_SCENE_CUBE_POINT:
        fxl_mat4_rotate_x(&ra, FXL_ANGLE_DEG(30 + 8 * f));
        fxl_mat4_rotate_y(&rb, FXL_ANGLE_DEG(30 + 12 * f));
        st = place(&out->pipe.model, &ra, &rb);
        set_mesh(&out->mesh, s->cube_pos, s->cube_uv, s->cube_normal, 24, s->cube_idx, 12);
        out->draw.texture = &s->crate_tex;
        if (scene == FW_SCENE_CUBE_POINT) {
            out->draw.filter = FXL_FILTER_POINT;
            out->draw.mip = FXL_MIP_NONE;
        }
        break;
    case FW_SCENE_SPHERE:
        fxl_mat4_rotate_y(&ra, FXL_ANGLE_DEG(40 * f));
        fxl_mat4_rotate_x(&rb, FXL_ANGLE_DEG(20));
        st = place(&out->pipe.model, &ra, &rb);
        set_mesh(&out->mesh, s->sphere_pos, (const fxl_texcoord_t *)0, (const fxl_vec3_t *)0,
                 FW_SPHERE_VERTS, s->sphere_idx, FW_SPHERE_TRIS);
        fxl_texgen_defaults(&out->pipe.texgen);
        out->pipe.texgen.mode = FXL_TEXGEN_SPHERICAL;
        out->pipe.texgen.space = FXL_TEXGEN_OBJECT;
        out->pipe.texgen.axis = FXL_AXIS_Y;
        out->pipe.texgen.scale_u = Q(2);
        out->draw.texture = &s->globe_tex;
        break;
    case FW_SCENE_LIT:
        fxl_mat4_rotate_y(&ra, FXL_ANGLE_DEG(30 + 40 * f));
        fxl_mat4_rotate_x(&rb, FXL_ANGLE_DEG(-15));
        st = place(&out->pipe.model, &ra, &rb);
        set_mesh(&out->mesh, s->sphere_pos, s->sphere_uv, s->sphere_normal, FW_SPHERE_VERTS,
                 s->sphere_idx, FW_SPHERE_TRIS);
        out->pipe.lighting = 1;
        /* (0.48, 0.64, 0.60) is exactly unit: 0.2304 + 0.4096 + 0.36 = 1. */
        out->pipe.light.dir = vec3(31457, 41943, 39322);
        out->pipe.light.ambient[0] = out->pipe.light.ambient[1] = out->pipe.light.ambient[2] = 40;
        out->pipe.light.diffuse[0] = 235;
        out->pipe.light.diffuse[1] = 225;
        out->pipe.light.diffuse[2] = 210;
        out->draw.texture = &s->globe_tex;
        out->draw.shade = FXL_SHADE_GOURAUD;
        out->draw.texenv = FXL_TEXENV_MODULATE;
        break;
    default: /* FW_SCENE_FLOOR(_POINT): static, the frame number does not move it */
        set_mesh(&out->mesh, s->floor_pos, s->floor_uv, (const fxl_vec3_t *)0, 4, s->floor_idx, 2);
        out->draw.texture = &s->checker_tex;
        if (scene == FW_SCENE_FLOOR_POINT) {
            out->draw.filter = FXL_FILTER_POINT;
            out->draw.mip = FXL_MIP_NONE;
        }
        out->clear_rgb565 = FXL_RGB565(150, 190, 230);
        break;
    }
    return st;
}
