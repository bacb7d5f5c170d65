/* fuzz_pipe.h - one fuzz case of the fixed-point 3D front end
 * (fixel/pipeline.h): decode, run, check.
 *
 * The front-end counterpart of fuzz_case.h, shared the same way (fixel-fuzz,
 * fuzz_raster, test_fuzz_regress.c; header-only, host code) and built on its
 * reader, pools, guarded memory, canaries and status oracle. An input is a
 * front-end case when bits 3..5 of its last byte are 0 (fz_input_is_pipe:
 * 1 in 8 of random inputs); every other input means what it meant before.
 *
 * A case is decoded from bytes (missing bytes read as 0): the target, depth
 * buffer, texture and draw exactly as fz_decode reads them (so every pixel
 * format, filter, origin, clip and invalid field of the raster fuzz; in half
 * the cases then the whole target as clip and a depth buffer of 0), then
 * a pipeline recipe - fxl_pipeline_init at some size (sometimes invalid),
 * fxl_pipeline_set_perspective and _set_viewport with extreme fovy, aspect,
 * near, far and viewports (limits, past them, bands of a frame), model and
 * view matrices built from rotations, axis rotations (axes on the 2^-8
 * boundary), translations, scales, look-at (eye == centre, up parallel or
 * zero) and raw entries, then fields poked directly (INT32 limits in the
 * matrices, near, far, viewport), cull, lighting, texgen and light fields
 * (sometimes invalid enums), an optional vertex cache of 1..1024 entries
 * with stale contents - and a mesh of up to 12 distinct vertices (in view,
 * across the eye plane, behind it, far away, duplicated, collinear, INT32
 * limits) with optional uv, colour and normal arrays, vert_count 0, 65535,
 * 65536 or UINT32_MAX, up to 12 triangles, some indices out of range, and
 * sometimes a NULL array.
 *
 * Checks (a finding is any violated one):
 *  P1 status: every setter and builder returns what pipeline.h documents
 *     (NULL -> FXL_ERR_ARG, ranges -> FXL_ERR_RANGE, overflow judged from a
 *     double-precision model with a 2^-30 band where it cannot tell);
 *     fxl_pipeline_emit's status is predicted the same way (ARG for NULL
 *     arrays and bad enums, RANGE for prepare, an index >= vert_count, or a
 *     vertex whose clip coordinates reach 2^52 / eye coordinates leave q16;
 *     OK otherwise), fxl_mesh_draw returns fxl_draw_check's error, else the
 *     emit's, and every status is a documented fxl_status_t.
 *  P2 memory: canaries around the pixels and depth (fz_fill), and around
 *     every caller array - positions, uv, colours, normals, indices, the
 *     vertex cache, the replay's vertices and indices - each flush against
 *     a PROT_NONE guard page on its other side; the const arrays, the
 *     pipeline, the target and the mesh are unchanged by the draws.
 *  P3 clip and determinism: the mesh drawn twice (backgrounds 0x0000 and
 *     0xFFFF, the second as two bands of the target) writes only inside
 *     the clip, the same values, nothing on a pre-vertex error
 *     (fz_check_writes).
 *  P4 differential: fxl_mesh_draw equals fxl_pipeline_emit without the
 *     cache into a recorder, then fxl_draw_indexed of what it emitted, bit
 *     for bit (pixels, depth, status, stats); emit with the cache emits the
 *     same triangles; a callback's negative return stops emission.
 *  P5 emitted triangles: inside the guard band (FXL_GUARD_PX of the
 *     viewport centre), inv_w >= 1, none culled by the cull mode's
 *     winding, at most 7 per mesh triangle, a uniform colour or uv stays
 *     uniform through clipping; a mesh triangle certainly inside every
 *     plane and certainly kept by the cull mode is emitted where a double
 *     projection of the core's matrix puts it (x, y, inv_w within derived
 *     bounds, fzp_project_d), with the mesh's uv (or exactly
 *     fxl_texgen_triangle's) and its colour: the mesh's unlit, lit the
 *     double-precision shade of the core's eye normal within its rounding.
 *  P6 the parts alone: fxl_xform_clip / _eye / _project, fxl_clip_triangle
 *     (output inside the planes, projectable), fxl_texgen_triangle,
 *     fxl_light_shade (the double-precision formula within its rounding,
 *     never brighter than the base colour),
 *     fxl_mat4_transform*, fxl_mat4_mul with aliased operands.
 *  P7 the pixels: each emitted triangle, drawn alone into the case's
 *     target with its draw, passes fz_run_case's checks 1-8 (status, memory,
 *     clip, determinism, exact coverage, stats, texel values, depth values). With P4
 *     (fxl_mesh_draw writes what fxl_draw_indexed of the emitted triangles
 *     writes, and a pixel's value depends only on its triangle) that holds
 *     every pixel the front end draws to its mode's texel or colour bound.
 */
#ifndef FXL_FUZZ_PIPE_H
#define FXL_FUZZ_PIPE_H

#include <math.h>

#include "fuzz_case.h"
#include "fixel/pipeline.h"

#define FZP_POOL 12                 /* distinct mesh vertices decoded */
#define FZP_MAX_TRIS 12
#define FZP_BIG 65536u              /* array entries of a mesh with vert_count >= 65535 */
#define FZP_MAX_EMIT (FZP_MAX_TRIS * (FXL_CLIP_MAX_VERTS - 2))
#define FZP_MAX_CACHE 1024u
#define FZP_CANARY_BYTES 64         /* canary bytes on the open side of each array */
#define FZP_BYTES 448               /* bytes fixel-fuzz gives a front-end case */
#define FZP_OK 0x10u                /* in an expectation mask: FXL_OK allowed */


/* ---- 1 in 8 inputs ------------------------------------------------------------ */

static inline int fz_input_is_pipe(const uint8_t *data, size_t n)
{
    return n > 0 && (data[n - 1] & 0x38u) == 0u;
}

/* ---- the decoded case --------------------------------------------------------- */

enum { FZP_ROT_X, FZP_ROT_Y, FZP_ROT_Z, FZP_AXIS, FZP_TRANSLATE, FZP_SCALE, FZP_LOOKAT, FZP_RAW, FZP_IDENT };

/* One matrix of a product: a builder call and its arguments. */
typedef struct fzp_op {
    uint8_t kind;                   /* FZP_* above */
    uint8_t parallel;               /* look-at: up is an exact multiple of centre - eye */
    fxl_angle_t angle;
    fxl_vec3_t a, b, c;             /* axis; translation; scale; look-at eye, centre, up */
    fxl_mat4_t raw;
} fzp_op;

/* A field written directly into the pipeline after the setters. */
typedef struct fzp_poke {
    uint8_t what;                   /* 0 model, 1 view, 2 proj entry, 3 near, 4 far, 5 vp origin, 6 vp size, 7 light */
    uint8_t rc;                     /* entry: row rc & 3, column (rc >> 2) & 3; else which of two */
    int32_t value;
} fzp_poke;

typedef struct fz_pcase {
    fz_case c;                      /* target, depth, texture, draw: fz_decode's (vertices unused) */
    /* the pipeline: fxl_pipeline_init, the setters, the products, the pokes, in this order */
    int32_t init_w, init_h;
    uint8_t has_persp, has_vp;
    fxl_angle_t fovy;
    fxl_q16_t aspect, near_q16, far_q16;
    int32_t vp[4];
    uint32_t n_model, n_view, n_poke;
    fzp_op model[3], view[3];
    fzp_poke poke[3];
    uint8_t cull, lighting;
    uint16_t material;
    fxl_light_t light;
    fxl_texgen_t texgen;
    uint8_t cache_mode;             /* 0-2 none, 3 off through the setter, 4 1..8 entries, 5 vert_count,
                                     * 6 FZP_MAX_CACHE, 7 NULL with a count (ARG), then off */
    uint8_t cache_fill;             /* byte the entries start as (stale tags) */
    uint32_t cache_count;
    /* the mesh: array entry i is pool entry i % npool */
    uint32_t vert_count, npool, tri_count;
    fxl_vec3_t pos[FZP_POOL];
    fxl_texcoord_t uv[FZP_POOL];
    uint16_t color[FZP_POOL];
    fxl_vec3_t normal[FZP_POOL];
    uint8_t has_uv, has_color, has_normal, pos_null, idx_null;
    uint16_t idx[3 * FZP_MAX_TRIS];
    /* how it runs */
    uint8_t at_start;               /* arrays after the lower guard page, canaries after them */
    uint8_t split;                  /* band split row (0: one band) */
    uint8_t stop_at;                /* the cached emit's callback stops after this many (0: never) */
    uint8_t bad_tail;               /* the replay gets a last triangle with an index out of range */
    uint8_t reverse;                /* the replay stores its vertices backwards */
    uint8_t stats_null;
} fz_pcase;

static int32_t fzp_sat(int64_t x)
{
    return x > INT32_MAX ? INT32_MAX : (x < INT32_MIN ? INT32_MIN : (int32_t)x);
}

/* An object-space q16 value: mostly a few units, otherwise extremes. */
static int32_t fzp_q16(fz_reader *r)
{
    switch (fz_u8(r) % 8u) {
    case 0: case 1: case 2:
        return ((int32_t)fz_u16(r) - 32768) * 16;   /* +-8 units in 2^-12 steps */
    case 3:
        return ((int32_t)fz_u8(r) - 128) * 65536;   /* whole units */
    case 4:
        return fz_special_i32[fz_u8(r) % FZ_NSPECIAL];
    case 5:
        return fz_i32(r);
    case 6: {
        uint32_t k = fz_u8(r);                      /* +-2^-16 .. 2^14 units */
        int32_t v = (int32_t)1 << (k % 31u);
        return (k & 0x80u) ? -v : v;
    }
    default:
        return 0;
    }
}

static const fxl_vec3_t fzp_units[] = {
    {65536, 0, 0}, {-65536, 0, 0}, {0, 65536, 0}, {0, -65536, 0}, {0, 0, 65536}, {0, 0, -65536},
    {39322, 52429, 0}, {37837, 37837, 37837}, {0, -39322, 52429}, {-46341, 0, 46341}};

/* A unit vector (normal, axis, light direction), or one just off unit
 * length (around the 2^-8 of fxl_mat4_rotate_axis), zero, or extremes. */
static void fzp_unit(fz_reader *r, fxl_vec3_t *v)
{
    static const int32_t e[] = {256, 255, 257, -256, -255, -257, 512, -512};
    uint32_t m = fz_u8(r) % 8u;
    fxl_vec3_t u = fzp_units[fz_u8(r) % 10u];
    switch (m) {
    case 0: case 1: case 2: case 3:
        *v = u;
        break;
    case 4:
        v->x = v->y = v->z = 0;
        break;
    case 5: {
        int64_t s = 65536 + e[fz_u8(r) % 8u];       /* length 1 + e / 65536 */
        v->x = (int32_t)(((int64_t)u.x * s + (u.x < 0 ? -32768 : 32768)) / 65536);
        v->y = (int32_t)(((int64_t)u.y * s + (u.y < 0 ? -32768 : 32768)) / 65536);
        v->z = (int32_t)(((int64_t)u.z * s + (u.z < 0 ? -32768 : 32768)) / 65536);
        break;
    }
    case 6:
        v->x = fzp_q16(r);
        v->y = fzp_q16(r);
        v->z = fzp_q16(r);
        break;
    default:
        v->x = (int16_t)fz_u16(r) * 2;
        v->y = (int16_t)fz_u16(r) * 2;
        v->z = (int16_t)fz_u16(r) * 2;
        break;
    }
}

static int32_t fzp_scale(fz_reader *r)
{
    static const int32_t t[] = {65536, -65536, 0, 131072, 32768, 1, INT32_MAX, INT32_MIN, 32767 * 65536, -1,
                                3 * 65536, -32768};
    uint32_t m = fz_u8(r);
    return m < 200 ? t[m % 12u] : fzp_q16(r);
}

/* Mostly within +-22.5 degrees (a mesh stays roughly in view), else
 * quarter turns and their neighbours, or any angle. */
static fxl_angle_t fzp_angle(fz_reader *r)
{
    static const fxl_angle_t t[] = {0, 1, 0x4000, 0x8000, 0xC000, 0xFFFF, 0x2000, 0x1555};
    uint32_t m = fz_u8(r) & 3u;
    return (fxl_angle_t)(m == 0u ? t[fz_u8(r) % 8u] : (m == 1u ? fz_u16(r) : ((fz_u8(r) - 128u) * 32u) & 0xFFFFu));
}

/* A mesh position: in front of the default camera (mostly in view), around
 * the eye plane, behind it, next to the previous vertex, collinear with the
 * previous two, far away in view, or extremes. */
static void fzp_pos(fz_reader *r, fxl_vec3_t *p, const fxl_vec3_t *prev, const fxl_vec3_t *prev2)
{
    static const int32_t dd[] = {0, 0, 1, -1, 0x800, -0x800, 0x10000, -0x10000};
    uint32_t m = fz_u8(r) % 16u;
    int64_t d;
    switch (m) {
    case 0: case 1: case 2: case 3: case 4: case 5: case 6:
        d = 0x4000 + (int64_t)(fz_u32(r) % (40u << 16));   /* depth 0.25 .. 40.25 */
        p->x = fzp_sat(d * ((int32_t)fz_u8(r) - 128) / 160);   /* |x| <= 0.8 depth */
        p->y = fzp_sat(d * ((int32_t)fz_u8(r) - 128) / 160);
        p->z = fzp_sat(-d);
        break;
    case 7: case 8:
        p->x = ((int32_t)fz_u8(r) - 128) * 2048;
        p->y = ((int32_t)fz_u8(r) - 128) * 2048;
        p->z = ((int32_t)fz_u16(r) - 32768) * 4;            /* +-2 units */
        break;
    case 9:
        p->x = ((int32_t)fz_u8(r) - 128) * 4096;
        p->y = ((int32_t)fz_u8(r) - 128) * 4096;
        p->z = (int32_t)fz_u16(r) * 16 + 1;                 /* behind the eye */
        break;
    case 10: case 11:
        p->x = fzp_sat((int64_t)prev->x + dd[fz_u8(r) % 8u]);
        p->y = fzp_sat((int64_t)prev->y + dd[fz_u8(r) % 8u]);
        p->z = fzp_sat((int64_t)prev->z + dd[fz_u8(r) % 8u]);
        break;
    case 12:
        p->x = fzp_q16(r);
        p->y = fzp_q16(r);
        p->z = fzp_q16(r);
        break;
    case 13:
        d = (int64_t)1 << (20u + fz_u8(r) % 11u);           /* depth 16 .. 16384 units */
        p->x = fzp_sat(d * ((int32_t)fz_u8(r) - 128) / 160);
        p->y = fzp_sat(d * ((int32_t)fz_u8(r) - 128) / 160);
        p->z = fzp_sat(-d);
        break;
    case 14: {
        static const int k[] = {-1, 2, 3, -2};
        int kk = k[fz_u8(r) % 4u];
        p->x = fzp_sat((int64_t)prev->x + kk * ((int64_t)prev->x - prev2->x));
        p->y = fzp_sat((int64_t)prev->y + kk * ((int64_t)prev->y - prev2->y));
        p->z = fzp_sat((int64_t)prev->z + kk * ((int64_t)prev->z - prev2->z));
        break;
    }
    default:
        p->x = fz_i32(r);
        p->y = fz_i32(r);
        p->z = fz_i32(r);
        break;
    }
}

static void fzp_raw_matrix(fz_reader *r, fxl_mat4_t *m)
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            uint32_t b = fz_u8(r);
            m->m[i][j] = b < 64 ? (i == j ? FXL_Q16_ONE : 0)
                                : (b < 160 ? ((int32_t)b - 112) * 4096
                                           : (b < 224 ? fz_special_i32[fz_u8(r) % FZ_NSPECIAL] : fz_i32(r)));
        }
}

static void fzp_decode_op(fz_reader *r, fzp_op *op)
{
    memset(op, 0, sizeof *op);
    op->kind = (uint8_t)(fz_u8(r) % 9u);
    switch (op->kind) {
    case FZP_ROT_X: case FZP_ROT_Y: case FZP_ROT_Z:
        op->angle = fzp_angle(r);
        break;
    case FZP_AXIS:
        fzp_unit(r, &op->a);
        op->angle = fzp_angle(r);
        break;
    case FZP_TRANSLATE:
        op->a.x = fzp_q16(r);
        op->a.y = fzp_q16(r);
        op->a.z = fzp_q16(r);
        break;
    case FZP_SCALE:
        op->a.x = fzp_scale(r);
        op->a.y = fzp_scale(r);
        op->a.z = fzp_scale(r);
        break;
    case FZP_LOOKAT: {
        uint32_t m = fz_u8(r) % 4u;
        /* eye */
        if (m == 1) {
            op->a.x = fzp_q16(r);
            op->a.y = fzp_q16(r);
            op->a.z = fzp_q16(r);
        } else if (m == 2) {
            op->a.z = (int32_t)fz_u8(r) * 65536;
        } else if (m == 3) {
            op->a.x = fz_special_i32[fz_u8(r) % FZ_NSPECIAL];
            op->a.y = fz_special_i32[fz_u8(r) % FZ_NSPECIAL];
            op->a.z = fz_special_i32[fz_u8(r) % FZ_NSPECIAL];
        }
        /* centre */
        m = fz_u8(r) % 4u;
        if (m == 0) {
            op->b = op->a;
            op->b.z = fzp_sat((int64_t)op->a.z - 65536);
        } else if (m == 1) {
            op->b = op->a;                                   /* eye == centre: RANGE */
        } else if (m == 2) {
            op->b.x = fzp_q16(r);
            op->b.y = fzp_q16(r);
            op->b.z = fzp_q16(r);
        }
        /* up */
        m = fz_u8(r) % 6u;
        if (m <= 1) {
            op->c.y = FXL_Q16_ONE;
        } else if (m == 3) {
            /* an exact multiple of the view direction, where it fits */
            int64_t k = (fz_u8(r) & 1u) ? 1 : -1;
            int64_t x = k * ((int64_t)op->b.x - op->a.x), y = k * ((int64_t)op->b.y - op->a.y),
                    z = k * ((int64_t)op->b.z - op->a.z);
            if (x == fzp_sat(x) && y == fzp_sat(y) && z == fzp_sat(z)) {
                op->c.x = (int32_t)x;
                op->c.y = (int32_t)y;
                op->c.z = (int32_t)z;
                op->parallel = 1;
            }
        } else if (m == 4) {
            fzp_unit(r, &op->c);
        } else if (m == 5) {
            op->c.x = fzp_q16(r);
            op->c.y = fzp_q16(r);
            op->c.z = fzp_q16(r);
        } /* 2: zero */
        break;
    }
    case FZP_RAW:
        fzp_raw_matrix(r, &op->raw);
        break;
    default:
        break;
    }
}

static void fzp_decode_pipeline(fz_reader *r, fz_pcase *pc)
{
    static const int32_t bad_size[] = {0, -1, 4097, INT32_MIN, INT32_MAX, 1, 4096, 4095};
    const fz_case *c = &pc->c;
    uint32_t m, i;

    m = fz_u8(r);
    if (m < 200) {
        pc->init_w = c->w;
        pc->init_h = c->h;
    } else if (m < 230) {
        pc->init_w = 1 + (int32_t)(fz_u16(r) % 4096u);
        pc->init_h = 1 + (int32_t)(fz_u16(r) % 4096u);
    } else {
        pc->init_w = bad_size[fz_u8(r) % 8u];
        pc->init_h = bad_size[fz_u8(r) % 8u];
    }

    /* perspective */
    m = fz_u8(r) % 8u;
    pc->has_persp = m < 6;
    if (m < 4) {
        static const fxl_angle_t fov[] = {FXL_ANGLE_DEG(60), FXL_ANGLE_DEG(30), FXL_ANGLE_DEG(90),
                                          FXL_ANGLE_DEG(120), FXL_ANGLE_DEG(170), FXL_ANGLE_DEG(5)};
        static const int32_t nearv[] = {65536, 32768, 6554, 1, 256, 655360};
        uint32_t a = fz_u8(r);
        pc->fovy = fov[fz_u8(r) % 6u];
        pc->aspect = a < 128 ? (int32_t)(((int64_t)c->w << 16) / c->h)
                             : (a < 192 ? FXL_Q16_ONE : (int32_t)(0x2000u + fz_u32(r) % 0x80000u));
        pc->near_q16 = nearv[fz_u8(r) % 6u];
        m = fz_u8(r) % 6u;
        pc->far_q16 = m < 2 ? 0 : (m == 2 ? 100 * 65536 : (m == 3 ? pc->near_q16 + 1
                                  : (m == 4 ? fzp_sat((int64_t)pc->near_q16 * 2) : INT32_MAX)));
    } else if (m == 4) {
        static const int32_t nearv[] = {1, 2, 0x100, INT32_MAX, INT32_MAX - 1, 0, -1, INT32_MIN, 0x7FFF0000};
        pc->fovy = FXL_ANGLE_DEG(60);
        pc->aspect = FXL_Q16_ONE;
        pc->near_q16 = nearv[fz_u8(r) % 9u];
        m = fz_u8(r) % 8u;
        pc->far_q16 = m == 0 ? 0 : (m == 1 ? fzp_sat((int64_t)pc->near_q16 + 1) : (m == 2 ? INT32_MAX
                      : (m == 3 ? pc->near_q16 : (m == 4 ? fzp_sat((int64_t)pc->near_q16 - 1)
                      : (m == 5 ? 1 : (m == 6 ? -1 : INT32_MIN))))));
    } else if (m == 5) {
        static const fxl_angle_t fov[] = {0, 1, 2, 3, 0x7FFF, 0x8000, 0xFFFF, 0x7FFE};
        static const int32_t asp[] = {0, -1, 1, 2, INT32_MAX, 65536, INT32_MIN, 16};
        pc->fovy = fov[fz_u8(r) % 8u];
        pc->aspect = asp[fz_u8(r) % 8u];
        pc->near_q16 = FXL_Q16_ONE;
        pc->far_q16 = (fz_u8(r) & 1u) ? 100 * 65536 : 0;
    }

    /* viewport, frame pixels: mostly the target (so meshes land on it) */
    m = fz_u8(r) % 16u;
    pc->has_vp = m < 14;
    m = m < 8 ? 0u : (m < 10 ? 3u : (m < 14 ? m - 7u : 7u));
    if (m < 3) {
        pc->vp[0] = c->origin_x;
        pc->vp[1] = c->origin_y;
        pc->vp[2] = c->w;
        pc->vp[3] = c->h;
    } else if (m == 3) {
        /* a frame the target is one band of */
        pc->vp[0] = c->origin_x - (int32_t)(fz_u8(r) % 8u);
        pc->vp[1] = c->origin_y - (int32_t)(fz_u8(r) % 4u) * c->h;
        pc->vp[2] = c->w + (int32_t)(fz_u8(r) % 16u);
        pc->vp[3] = c->h * (1 + (int32_t)(fz_u8(r) % 4u));
    } else if (m == 4) {
        pc->vp[0] = c->origin_x + (int32_t)(fz_u8(r) % (uint32_t)c->w);
        pc->vp[1] = c->origin_y + (int32_t)(fz_u8(r) % (uint32_t)c->h);
        pc->vp[2] = 1 + (int32_t)(fz_u8(r) % 2u);
        pc->vp[3] = 1 + (int32_t)(fz_u8(r) % 2u);
    } else if (m == 5) {
        pc->vp[2] = FXL_TARGET_MAX_DIM;
        pc->vp[3] = (fz_u8(r) & 1u) ? FXL_TARGET_MAX_DIM : c->h;
        pc->vp[0] = c->origin_x - (int32_t)(fz_u16(r) % 4096u);
        pc->vp[1] = c->origin_y - (int32_t)(fz_u16(r) % (uint32_t)pc->vp[3]);
    } else if (m == 6) {
        static const int32_t org[] = {FXL_TARGET_MAX_ORIGIN, -FXL_TARGET_MAX_ORIGIN, FXL_TARGET_MAX_ORIGIN + 1,
                                      -FXL_TARGET_MAX_ORIGIN - 1, 0, INT32_MIN};
        static const int32_t dim[] = {1, FXL_TARGET_MAX_DIM, FXL_TARGET_MAX_DIM + 1, 0, -5, 2};
        pc->vp[0] = org[fz_u8(r) % 6u];
        pc->vp[1] = org[fz_u8(r) % 6u];
        pc->vp[2] = dim[fz_u8(r) % 6u];
        pc->vp[3] = dim[fz_u8(r) % 6u];
    }

    /* model and view products */
    m = fz_u8(r);
    pc->n_model = m < 160 ? 0u : 1u + m % 3u;
    for (i = 0; i < pc->n_model; i++)
        fzp_decode_op(r, &pc->model[i]);
    m = fz_u8(r);
    pc->n_view = m < 160 ? 0u : 1u + m % 3u;
    for (i = 0; i < pc->n_view; i++)
        fzp_decode_op(r, &pc->view[i]);

    /* pokes */
    m = fz_u8(r);
    pc->n_poke = m < 224 ? 0u : 1u + m % 3u;
    for (i = 0; i < pc->n_poke; i++) {
        fzp_poke *k = &pc->poke[i];
        k->what = (uint8_t)(fz_u8(r) % 8u);
        k->rc = (uint8_t)fz_u8(r);
        m = fz_u8(r) % 4u;
        k->value = m < 2 ? fz_special_i32[fz_u8(r) % FZ_NSPECIAL]
                         : (m == 2 ? fz_i32(r) : ((int32_t)fz_u16(r) - 32768) * 64);
    }

    /* cull, lighting, texgen */
    m = fz_u8(r);
    pc->cull = (uint8_t)(m < 252 ? m % 3u : m);
    m = fz_u8(r);
    pc->lighting = (uint8_t)(m < 96 ? 0u : (m < 250 ? 1u : m));
    pc->material = (uint16_t)fz_u16(r);
    fzp_unit(r, &pc->light.dir);
    m = fz_u8(r) % 4u;
    for (i = 0; i < 3; i++) {
        pc->light.ambient[i] = (uint8_t)(m == 0 ? 64u : (m == 1 ? fz_u8(r) : (m == 2 ? 255u : 0u)));
        pc->light.diffuse[i] = (uint8_t)(m == 0 ? 191u : (m == 1 ? fz_u8(r) : (m == 2 ? 0u : 255u)));
    }
    fxl_texgen_defaults(&pc->texgen);
    m = fz_u8(r);
    pc->texgen.mode = (uint8_t)(m < 96 ? 0u : (m < 248 ? 1u + m % 4u : m));
    m = fz_u8(r);
    pc->texgen.space = (uint8_t)(m < 253 ? m % 2u : m);
    m = fz_u8(r);
    pc->texgen.plane = (uint8_t)(m < 253 ? m % 3u : m);
    m = fz_u8(r);
    pc->texgen.axis = (uint8_t)(m < 253 ? m % 3u : m);
    m = fz_u8(r) % 4u;
    if (m == 1) {
        pc->texgen.scale_u = fzp_scale(r);
        pc->texgen.scale_v = fzp_scale(r);
        pc->texgen.offset_u = fzp_q16(r);
        pc->texgen.offset_v = fzp_q16(r);
    } else if (m >= 2) {
        pc->texgen.scale_u = fz_special_i32[fz_u8(r) % FZ_NSPECIAL];
        pc->texgen.scale_v = fz_special_i32[fz_u8(r) % FZ_NSPECIAL];
        pc->texgen.offset_u = m == 2 ? fz_special_i32[fz_u8(r) % FZ_NSPECIAL] : fz_i32(r);
        pc->texgen.offset_v = m == 2 ? fz_special_i32[fz_u8(r) % FZ_NSPECIAL] : fz_i32(r);
    }

    /* vertex cache */
    pc->cache_mode = (uint8_t)(fz_u8(r) % 8u);
    pc->cache_count = fz_u8(r);
    m = fz_u8(r) % 4u;
    pc->cache_fill = (uint8_t)(m == 0 ? 0x00u : (m == 1 ? 0xFFu : (m == 2 ? 0xA5u : fz_u8(r))));
}

static void fzp_decode_mesh(fz_reader *r, fz_pcase *pc)
{
    uint32_t m, i, flags, bad, patch;
    int64_t cz;

    m = fz_u8(r);
    pc->npool = 1u + fz_u8(r) % FZP_POOL;
    if (pc->npool < 3u && (m & 1u))
        pc->npool += 3u;   /* fewer one- and two-vertex pools: those are all degenerate */
    pc->vert_count = m < 200 ? pc->npool : (m < 212 ? 0u : (m < 228 ? FZP_BIG : (m < 242 ? FZP_BIG - 1u : UINT32_MAX)));
    flags = fz_u8(r);
    pc->has_uv = (uint8_t)(flags & 1u);
    pc->has_color = (uint8_t)((flags >> 1) & 1u);
    pc->has_normal = (uint8_t)((flags >> 2) & 1u);
    m = fz_u8(r);
    pc->pos_null = m >= 254;
    pc->idx_null = m >= 252 && m < 254;
    /* 5 in 8 meshes are a patch around (0, 0, -cz), 1.5 .. 20 units away,
     * most of whose vertices the default camera sees (a fifth of them
     * still from fzp_pos); the rest take every vertex from fzp_pos */
    patch = fz_u8(r) % 8u < 5u;
    cz = 0x18000 + (int64_t)fz_u16(r) * 18;
    for (i = 0; i < pc->npool; i++) {
        static const fxl_vec3_t start = {0, 0, -4 * 65536};
        const fxl_vec3_t *p1 = i ? &pc->pos[i - 1] : &start, *p2 = i > 1 ? &pc->pos[i - 2] : &start;
        if (patch && fz_u8(r) % 5u != 0u) {
            pc->pos[i].x = fzp_sat(cz * ((int32_t)fz_u8(r) - 128) / 213);   /* |x| <= 0.6 cz */
            pc->pos[i].y = fzp_sat(cz * ((int32_t)fz_u8(r) - 128) / 213);
            pc->pos[i].z = fzp_sat(-cz + cz * ((int32_t)fz_u8(r) - 128) / 512);
        } else {
            fzp_pos(r, &pc->pos[i], p1, p2);
        }
        if (pc->has_uv) {
            /* uniform (flags bit 4): a uv that stays one value through clipping */
            pc->uv[i].u = (flags & 0x10u) && i ? pc->uv[0].u : fz_uv(r, i ? pc->uv[i - 1].u : 0);
            pc->uv[i].v = (flags & 0x10u) && i ? pc->uv[0].v : fz_uv(r, i ? pc->uv[i - 1].v : 0);
        }
        if (pc->has_color)
            pc->color[i] = (flags & 0x08u) && i ? pc->color[0] : (uint16_t)fz_u16(r);
        if (pc->has_normal)
            fzp_unit(r, &pc->normal[i]);
    }
    m = fz_u8(r);
    pc->tri_count = m < 200 ? 1u + m % 8u : (m < 216 ? 0u : 9u + m % 4u);
    m = fz_u8(r);
    bad = m < 32;                 /* this mesh may have indices out of range */
    for (i = 0; i < 3u * pc->tri_count; i++) {
        uint32_t b = fz_u8(r), ix, n = pc->vert_count;
        if (n == 0) {
            ix = b;
        } else if (n <= FZP_POOL) {
            ix = b % n;
            if ((m & 0x40u) && n >= 3u && i % 3u != 0u) {
                /* three different corners (a mesh's usual triangle) */
                uint32_t i0 = pc->idx[i - i % 3u], i1 = i % 3u == 2u ? pc->idx[i - 1] : i0;
                ix = (i0 + 1u + b % (n - 1u)) % n;
                while (ix == i0 || ix == i1)
                    ix = (ix + 1u) % n;
            }
            if (bad && b >= 240)
                ix = n + (b - 240);
        } else {
            /* low and high indices, any 16-bit one (65535 is out of range at vert_count 65535) */
            ix = b < 128 ? b % pc->npool : (b < 192 ? 65535u - b % pc->npool : fz_u16(r));
        }
        pc->idx[i] = (uint16_t)ix;
    }
    m = fz_u8(r);
    pc->at_start = (uint8_t)(m & 1u);
    pc->reverse = (uint8_t)((m >> 1) & 1u);
    pc->stats_null = (m >> 2) < 6;
    pc->split = (uint8_t)fz_u8(r);
    m = fz_u8(r);
    pc->stop_at = (uint8_t)(m < 40 ? 1u + m % 4u : 0u);
    pc->bad_tail = fz_u8(r) < 48;
}

/* Decode a front-end case (any bytes are one). */
static void fz_pipe_decode(const uint8_t *data, size_t n, fz_pcase *pc)
{
    fz_reader rd = {data, n, 0};

    memset(pc, 0, sizeof *pc);
    fz_decode_target(&rd, &pc->c);
    fz_decode_texture(&rd, &pc->c);
    fz_decode_draw(&rd, &pc->c);
    if (fz_u8(&rd) < 128) {
        /* half the cases keep the whole target and a depth buffer that
         * passes every test, so more of what the front end emits is drawn */
        pc->c.clip.x0 = pc->c.origin_x;
        pc->c.clip.y0 = pc->c.origin_y;
        pc->c.clip.x1 = pc->c.origin_x + pc->c.w;
        pc->c.clip.y1 = pc->c.origin_y + pc->c.h;
        pc->c.depth_init = 0;
        pc->c.depth_rand = 0;
    }
    fzp_decode_pipeline(&rd, pc);
    fzp_decode_mesh(&rd, pc);
}

/* As fz_prepare: the settings fitted to the build in 7 of 8 inputs. */
static inline void fz_pipe_prepare(const uint8_t *data, size_t n, fz_pcase *pc)
{
    fz_pipe_decode(data, n, pc);
    if (n > 0 && (data[n - 1] & 7u) != 0u)
        fz_fit_build(&pc->c);
}

/* ---- the oracle: overflow judged in double precision ------------------------------ */

/* Whether first + t[0] + ... + t[n-1], added in that order, stays in range:
 * 0 certainly (every term and partial sum below 2^63 - as fxl__add_sat
 * and fxl__mul_shr saturate - and the result below lim), 2 certainly not,
 * 1 too close to tell. The terms are exact values rounded to double: a
 * band of 2^-30 of their magnitude covers that rounding and the core's
 * own (half a unit per term). */
static int fzp_verdict(double first, const double *t, int n, double lim)
{
    double mag = fabs(first), s = first, tol_p, tol_f;
    int k, maybe = 0;

    for (k = 0; k < n; k++)
        mag += fabs(t[k]);
    tol_p = 0x1p-30 * (mag + 0x1p63);
    tol_f = 0x1p-30 * (mag + lim) + 4.0;
    for (k = -1; k < n; k++) {
        double a = k < 0 ? first : t[k];
        if (k >= 0)
            s += a;
        if (fabs(a) > 0x1p63 + tol_p || fabs(s) > 0x1p63 + tol_p)
            return 2;
        if (fabs(a) > 0x1p63 - tol_p || fabs(s) > 0x1p63 - tol_p)
            maybe = 1;
    }
    if (fabs(s) > lim + tol_f)
        return 2;
    return maybe || fabs(s) > lim - tol_f ? 1 : 0;
}

/* q16 rounded to int32 as fxl__to_i32 clamps it: the q32 sum must stay
 * below (INT32_MAX + 1/2) * 2^16. */
#define FZP_LIM_I32_Q32 (((double)INT32_MAX + 0.5) * 65536.0)

/* fxl_mat4_mul(a, b) (entries: q32 sums rounded to q16). */
static int fzp_mul_verdict(const fxl_mat4_t *a, const fxl_mat4_t *b)
{
    int r, c, k, v = 0, x;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            double t[4];
            for (k = 0; k < 4; k++)
                t[k] = (double)a->m[r][k] * (double)b->m[k][c];
            x = fzp_verdict(0.0, t, 4, FZP_LIM_I32_Q32);
            v = x > v ? x : v;
        }
    return v;
}

/* fxl_mat4_transform of (x, y, z, w) q16, rows r0 .. r1. */
static int fzp_transform_verdict(const fxl_mat4_t *m, const int32_t in[4], int r0, int r1)
{
    int r, k, v = 0, x;
    for (r = r0; r <= r1; r++) {
        double t[4];
        for (k = 0; k < 4; k++)
            t[k] = (double)m->m[r][k] * (double)in[k];
        x = fzp_verdict(0.0, t, 4, FZP_LIM_I32_Q32);
        v = x > v ? x : v;
    }
    return v;
}

/* fxl_pipeline_prepare: 2 for a documented range error, else whether
 * view * model (exact q32) and proj * (view * model) (q32 through 96-bit
 * products) overflow int64; mv, mvp get the model's values, tol their
 * error bounds (the terms' magnitudes times 2^-40: the double sums round
 * relative to those, not to the result). */
static int fzp_prepare_verdict(const fxl_pipeline_t *p, double mv[4][4], double mvp[4][4], double tol[2][4][4])
{
    int r, c, k, v = 0, x;
    if (p->near_q16 <= 0 || (p->far_q16 != 0 && p->far_q16 <= p->near_q16) || p->vp_w < 1 || p->vp_h < 1 ||
        p->vp_w > FXL_TARGET_MAX_DIM || p->vp_h > FXL_TARGET_MAX_DIM || p->vp_x > FXL_TARGET_MAX_ORIGIN ||
        p->vp_x < -FXL_TARGET_MAX_ORIGIN || p->vp_y > FXL_TARGET_MAX_ORIGIN || p->vp_y < -FXL_TARGET_MAX_ORIGIN)
        return 2;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            double t[4];
            for (k = 0; k < 4; k++)
                t[k] = (double)p->view.m[r][k] * (double)p->model.m[k][c];
            x = fzp_verdict(0.0, t, 4, 0x1p63);
            v = x > v ? x : v;
            mv[r][c] = t[0] + t[1] + t[2] + t[3];
            tol[0][r][c] = (fabs(t[0]) + fabs(t[1]) + fabs(t[2]) + fabs(t[3])) * 0x1p-40 + 1.0;
        }
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            double t[4];
            for (k = 0; k < 4; k++)
                t[k] = mv[k][c] * (double)p->proj.m[r][k] / 65536.0;
            x = fzp_verdict(0.0, t, 4, 0x1p63);
            v = x > v ? x : v;
            mvp[r][c] = t[0] + t[1] + t[2] + t[3];
            tol[1][r][c] = 4.0;   /* the core rounds each of the four products */
            for (k = 0; k < 4; k++)
                tol[1][r][c] += (fabs(mv[k][c]) + tol[0][k][c]) * fabs((double)p->proj.m[r][k]) / 65536.0 * 0x1p-40 +
                                tol[0][k][c] * fabs((double)p->proj.m[r][k]) / 65536.0;
        }
    return v;
}

/* Row `row` (q32) of a prepared matrix applied to (pos, 1): verdict
 * against lim (q32). */
static int fzp_row_verdict(const int64_t row[4], const fxl_vec3_t *pos, double lim)
{
    double t[3];
    t[0] = (double)row[0] * pos->x / 65536.0;
    t[1] = (double)row[1] * pos->y / 65536.0;
    t[2] = (double)row[2] * pos->z / 65536.0;
    return fzp_verdict((double)row[3], t, 3, lim);
}

/* fxl_xform_clip (rows x, y, w below FXL_CLIP_LIMIT_Q32) and, when eye,
 * fxl_xform_eye (eye coordinates in q16) of one position. */
static int fzp_vertex_verdict(const fxl_xform_t *xf, const fxl_vec3_t *pos, int eye)
{
    static const int clip_rows[3] = {0, 1, 3};
    int k, v = 0, x;
    for (k = 0; k < 3; k++) {
        x = fzp_row_verdict(xf->mvp[clip_rows[k]], pos, (double)FXL_CLIP_LIMIT_Q32);
        v = x > v ? x : v;
    }
    for (k = 0; eye && k < 3; k++) {
        x = fzp_row_verdict(xf->mv[k], pos, FZP_LIM_I32_Q32);
        v = x > v ? x : v;
    }
    return v;
}

/* fxl_mat4_perspective: 2 outside the documented ranges, else whether
 * cot(fovy / 2), cot / aspect and the z row fit q16. */
static int fzp_persp_verdict(fxl_angle_t fovy, fxl_q16_t aspect, fxl_q16_t near_q16, fxl_q16_t far_q16)
{
    double f, e[3], lim = (double)INT32_MAX;
    int k, v = 0;
    if (fovy == 0 || fovy >= 0x8000u || aspect <= 0 || near_q16 <= 0 || (far_q16 != 0 && far_q16 <= near_q16))
        return 2;
    if (far_q16 == 0)
        e[2] = 2.0 * (double)near_q16;
    else
        e[2] = fmax(((double)far_q16 + near_q16) * 65536.0 / ((double)far_q16 - near_q16),
                    2.0 * (double)far_q16 * near_q16 / ((double)far_q16 - near_q16));
    /* cot of fovy / 2, odd fovy included */
    f = 65536.0 / tan(fovy * 3.14159265358979323846 / 65536.0);
    e[0] = f;
    e[1] = f * 65536.0 / (double)aspect;
    for (k = 0; k < 3; k++) {
        double tol = e[k] * 0x1p-24 + 2.0;
        if (e[k] > lim + tol)
            v = 2;
        else if (e[k] > lim - tol && v == 0)
            v = 1;
    }
    return v;
}

/* fxl_mat4_rotate_axis: OK exactly when | |a| - 1 | <= 2^-8. */
static int fzp_axis_verdict(const fxl_vec3_t *a)
{
    const int64_t one = (int64_t)1 << 32;
    int64_t len2, lo = one - ((int64_t)1 << 25) + ((int64_t)1 << 16), hi = one + ((int64_t)1 << 25) + ((int64_t)1 << 16);
    if (a->x > 0x20000 || a->x < -0x20000 || a->y > 0x20000 || a->y < -0x20000 || a->z > 0x20000 ||
        a->z < -0x20000)
        return 2;   /* |a| >= 2 */
    len2 = (int64_t)a->x * a->x + (int64_t)a->y * a->y + (int64_t)a->z * a->z;   /* q32 */
    return (len2 >= lo && len2 <= hi) ? 0 : 2;
}

/* fxl_mat4_look_at: 2 for eye == centre, up == 0 or up an exact multiple
 * of the view direction, or a translation certainly outside q16; 0 when
 * up is clearly off the view direction and the translation fits. */
static int fzp_lookat_verdict(const fzp_op *op)
{
    double f[3], u[3], s[3], uu[3], e[3], lf, lu, ls, t[3];
    int k, v = 0;
    if (op->a.x == op->b.x && op->a.y == op->b.y && op->a.z == op->b.z)
        return 2;
    if ((op->c.x == 0 && op->c.y == 0 && op->c.z == 0) || op->parallel)
        return 2;
    e[0] = op->a.x / 65536.0;
    e[1] = op->a.y / 65536.0;
    e[2] = op->a.z / 65536.0;
    f[0] = ((double)op->b.x - op->a.x) / 65536.0;
    f[1] = ((double)op->b.y - op->a.y) / 65536.0;
    f[2] = ((double)op->b.z - op->a.z) / 65536.0;
    u[0] = op->c.x / 65536.0;
    u[1] = op->c.y / 65536.0;
    u[2] = op->c.z / 65536.0;
    lf = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    lu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (k = 0; k < 3; k++) {
        f[k] /= lf;
        u[k] /= lu;
    }
    s[0] = f[1] * u[2] - f[2] * u[1];
    s[1] = f[2] * u[0] - f[0] * u[2];
    s[2] = f[0] * u[1] - f[1] * u[0];
    ls = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    if (ls < 0x1p-14)
        v = 1;   /* nearly parallel: the core's threshold is its own */
    if (ls == 0.0)
        return 1;
    for (k = 0; k < 3; k++)
        s[k] /= ls;
    uu[0] = s[1] * f[2] - s[2] * f[1];
    uu[1] = s[2] * f[0] - s[0] * f[2];
    uu[2] = s[0] * f[1] - s[1] * f[0];
    t[0] = -(s[0] * e[0] + s[1] * e[1] + s[2] * e[2]);
    t[1] = -(uu[0] * e[0] + uu[1] * e[1] + uu[2] * e[2]);
    t[2] = f[0] * e[0] + f[1] * e[1] + f[2] * e[2];
    for (k = 0; k < 3; k++) {
        /* the core's q30 unit vectors: 2^-24 of |eye| covers them */
        double q = fabs(t[k]) * 65536.0, tol = 256.0 + (fabs(e[0]) + fabs(e[1]) + fabs(e[2])) * 65536.0 * 0x1p-24;
        if (q > (double)INT32_MAX + tol && v == 0)
            return 2;
        if (q > (double)INT32_MAX - tol)
            v = 1;
    }
    return v;
}

/* The mask (FZ_E_* and FZP_OK) a verdict allows. */
static uint32_t fzp_allow(int verdict)
{
    return verdict == 0 ? FZP_OK : (verdict == 1 ? FZP_OK | FZ_E_RANGE : FZ_E_RANGE);
}

static uint32_t fzp_bit(fxl_status_t st)
{
    return st == FXL_OK ? FZP_OK : fz_status_bit(st);
}

static const char *fzp_mask_str(uint32_t mask, char *buf)
{
    snprintf(buf, 64, "%s%s%s%s", (mask & FZP_OK) ? " OK" : "", (mask & FZ_E_ARG) ? " ARG" : "",
             (mask & FZ_E_RANGE) ? " RANGE" : "", (mask & FZ_E_UNSUP) ? " UNSUPPORTED" : "");
    return buf;
}

/* A status against a mask (documented values only). */
#define FZP_EXPECT(st, mask, ...)                                                                            \
    do {                                                                                                     \
        char mb_[64], w_[160];                                                                               \
        if ((fzp_bit(st) & (mask)) == 0u) {                                                                  \
            snprintf(w_, sizeof w_, __VA_ARGS__);                                                            \
            FZ_FAIL("%s: status %s (%d), expected%s", w_, fxl_status_name(st), (int)(st),                    \
                    fzp_mask_str((mask), mb_));                                                              \
        }                                                                                                    \
    } while (0)

/* ---- running a case --------------------------------------------------------------- */

typedef struct fzp_rec {
    fxl_vertex_t *tri;              /* 3 per triangle */
    uint32_t n, cap, stop_at;
    fxl_status_t stop_status;
    int over, stopped, after_stop, null_tri;
} fzp_rec;

typedef struct fz_pstate {
    fz_state *s;                    /* the raster state: pixels, depth, texture memory */
    fz_guard pos, uv, color, normal, idx, cache, rverts, ridx;
    uint16_t *pix_c, *dep_c;        /* the replay */
    fxl_vertex_t *rec1, *rec2;      /* FZP_MAX_EMIT triangles each */
} fz_pstate;

static int fz_pstate_init(fz_pstate *ps, fz_state *s)
{
    size_t cb = FZP_CANARY_BYTES;
    memset(ps, 0, sizeof *ps);
    ps->s = s;
    if (fz_guard_alloc(&ps->pos, FZP_BIG * sizeof(fxl_vec3_t) + cb) ||
        fz_guard_alloc(&ps->uv, FZP_BIG * sizeof(fxl_texcoord_t) + cb) ||
        fz_guard_alloc(&ps->color, FZP_BIG * sizeof(uint16_t) + cb) ||
        fz_guard_alloc(&ps->normal, FZP_BIG * sizeof(fxl_vec3_t) + cb) ||
        fz_guard_alloc(&ps->idx, 3u * FZP_MAX_TRIS * sizeof(uint16_t) + cb) ||
        fz_guard_alloc(&ps->cache, FXL_VCACHE_BYTES(FZP_MAX_CACHE) + cb) ||
        fz_guard_alloc(&ps->rverts, 3u * FZP_MAX_EMIT * sizeof(fxl_vertex_t) + cb) ||
        fz_guard_alloc(&ps->ridx, 3u * (FZP_MAX_EMIT + 1u) * sizeof(uint16_t) + cb))
        return -1;
    ps->pix_c = (uint16_t *)malloc(s->cap * 2u);
    ps->dep_c = (uint16_t *)malloc(s->cap * 2u);
    ps->rec1 = (fxl_vertex_t *)malloc(3u * FZP_MAX_EMIT * sizeof(fxl_vertex_t));
    ps->rec2 = (fxl_vertex_t *)malloc(3u * FZP_MAX_EMIT * sizeof(fxl_vertex_t));
    return ps->pix_c && ps->dep_c && ps->rec1 && ps->rec2 ? 0 : -1;
}

static uint8_t fzp_canary_byte(size_t i)
{
    return (uint8_t)(0x5Au ^ (uint8_t)(i * 37u));
}

/* An array of `bytes` in g: flush against the guard page after it, with
 * canary bytes before it, or (at_start) the other way round. */
static uint8_t *fzp_place(const fz_guard *g, size_t bytes, int at_start)
{
    uint8_t *p = at_start ? g->base : g->base + g->bytes - bytes;
    uint8_t *cn = at_start ? p + bytes : p - FZP_CANARY_BYTES;
    size_t i;
    for (i = 0; i < FZP_CANARY_BYTES; i++)
        cn[i] = fzp_canary_byte(i);
    return p;
}

static int fzp_canary_ok(const fz_guard *g, size_t bytes, int at_start)
{
    const uint8_t *cn = at_start ? g->base + bytes : g->base + g->bytes - bytes - FZP_CANARY_BYTES;
    size_t i;
    for (i = 0; i < FZP_CANARY_BYTES; i++)
        if (cn[i] != fzp_canary_byte(i))
            return 0;
    return 1;
}

/* Entries the arrays hold: vert_count, at most FZP_BIG (indices are 16-bit). */
static uint32_t fzp_entries(const fz_pcase *pc)
{
    return pc->vert_count < FZP_BIG ? pc->vert_count : FZP_BIG;
}

/* Put the mesh into guarded memory; m gets the caller's view of it. */
static void fzp_place_mesh(fz_pstate *ps, const fz_pcase *pc, fxl_mesh_t *m)
{
    uint32_t ne = fzp_entries(pc), i, k;
    fxl_vec3_t *pos = (fxl_vec3_t *)fzp_place(&ps->pos, ne * sizeof(fxl_vec3_t), pc->at_start);
    fxl_texcoord_t *uv = (fxl_texcoord_t *)fzp_place(&ps->uv, ne * sizeof(fxl_texcoord_t), pc->at_start);
    uint16_t *col = (uint16_t *)fzp_place(&ps->color, ne * sizeof(uint16_t), pc->at_start);
    fxl_vec3_t *nrm = (fxl_vec3_t *)fzp_place(&ps->normal, ne * sizeof(fxl_vec3_t), pc->at_start);
    uint16_t *idx = (uint16_t *)fzp_place(&ps->idx, 3u * pc->tri_count * sizeof(uint16_t), pc->at_start);

    for (k = 0; k < (pc->vert_count <= FZP_POOL ? ne : 3u * pc->tri_count); k++) {
        i = pc->vert_count <= FZP_POOL ? k : pc->idx[k];
        if (i >= ne)
            continue;
        pos[i] = pc->pos[i % pc->npool];
        uv[i] = pc->uv[i % pc->npool];
        col[i] = pc->color[i % pc->npool];
        nrm[i] = pc->normal[i % pc->npool];
    }
    memcpy(idx, pc->idx, 3u * pc->tri_count * sizeof(uint16_t));
    memset(m, 0, sizeof *m);
    m->pos = pc->pos_null ? NULL : pos;
    m->uv = pc->has_uv ? uv : NULL;
    m->color = pc->has_color ? col : NULL;
    m->normal = pc->has_normal ? nrm : NULL;
    m->vert_count = pc->vert_count;
    m->idx = pc->idx_null ? NULL : idx;
    m->tri_count = pc->tri_count;
}

/* P2 for the mesh arrays: canaries intact and every filled entry unchanged. */
static int fzp_check_mesh(const fz_pstate *ps, const fz_pcase *pc, char *msg)
{
    uint32_t ne = fzp_entries(pc), i, k;
    const fxl_vec3_t *pos = (const fxl_vec3_t *)(pc->at_start ? ps->pos.base
                                                               : ps->pos.base + ps->pos.bytes - ne * sizeof(fxl_vec3_t));
    const fxl_texcoord_t *uv = (const fxl_texcoord_t *)(pc->at_start ? ps->uv.base
                                                                      : ps->uv.base + ps->uv.bytes - ne * sizeof(fxl_texcoord_t));
    const uint16_t *col = (const uint16_t *)(pc->at_start ? ps->color.base
                                                          : ps->color.base + ps->color.bytes - ne * sizeof(uint16_t));
    const fxl_vec3_t *nrm = (const fxl_vec3_t *)(pc->at_start ? ps->normal.base
                                                               : ps->normal.base + ps->normal.bytes - ne * sizeof(fxl_vec3_t));
    const uint16_t *idx = (const uint16_t *)(pc->at_start ? ps->idx.base
                                                          : ps->idx.base + ps->idx.bytes - 3u * pc->tri_count * 2u);
    if (!fzp_canary_ok(&ps->pos, ne * sizeof(fxl_vec3_t), pc->at_start) ||
        !fzp_canary_ok(&ps->uv, ne * sizeof(fxl_texcoord_t), pc->at_start) ||
        !fzp_canary_ok(&ps->color, ne * sizeof(uint16_t), pc->at_start) ||
        !fzp_canary_ok(&ps->normal, ne * sizeof(fxl_vec3_t), pc->at_start) ||
        !fzp_canary_ok(&ps->idx, 3u * pc->tri_count * sizeof(uint16_t), pc->at_start))
        FZ_FAIL("canary next to a mesh array overwritten");
    if (memcmp(idx, pc->idx, 3u * pc->tri_count * sizeof(uint16_t)) != 0)
        FZ_FAIL("mesh indices changed");
    /* the entries fzp_place_mesh filled in */
    for (k = 0; k < (pc->vert_count <= FZP_POOL ? ne : 3u * pc->tri_count); k++) {
        i = pc->vert_count <= FZP_POOL ? k : pc->idx[k];
        if (i < ne && (memcmp(&pos[i], &pc->pos[i % pc->npool], sizeof *pos) != 0 ||
                       memcmp(&uv[i], &pc->uv[i % pc->npool], sizeof *uv) != 0 ||
                       col[i] != pc->color[i % pc->npool] ||
                       memcmp(&nrm[i], &pc->normal[i % pc->npool], sizeof *nrm) != 0))
            FZ_FAIL("mesh vertex %u changed", (unsigned)i);
    }
    return 0;
}

static fxl_status_t fzp_record(void *user, const fxl_vertex_t tri[3])
{
    fzp_rec *r = (fzp_rec *)user;
    if (r->stopped) {
        r->after_stop = 1;
        return r->stop_status;
    }
    if (!tri) {
        r->null_tri = 1;
        return FXL_OK;
    }
    if (r->n >= r->cap) {
        r->over = 1;
        return FXL_OK;
    }
    memcpy(&r->tri[3u * r->n], tri, 3u * sizeof *tri);
    r->n++;
    if (r->stop_at != 0 && r->n == r->stop_at) {
        r->stopped = 1;
        return r->stop_status;
    }
    return FXL_OK;
}

/* Band `row0 .. row0 + rows` of the case's target over buf, clip cut to it. */
static void fzp_band(const fz_case *c, fxl_target_t *t, uint16_t *buf, uint16_t *depth, int32_t row0, int32_t rows)
{
    int32_t y0 = c->origin_y + row0, y1 = y0 + rows;
    fz_make_target(c, t, buf, depth);
    t->pixels += (size_t)row0 * (size_t)c->stride;
    if (t->depth)
        t->depth += (size_t)row0 * (size_t)c->stride;
    t->height = rows;
    t->origin_y = y0;
    t->clip.y0 = c->clip.y0 < y0 ? y0 : (c->clip.y0 > y1 ? y1 : c->clip.y0);
    t->clip.y1 = c->clip.y1 < y0 ? y0 : (c->clip.y1 > y1 ? y1 : c->clip.y1);
}

/* Apply one product factor: *acc = *acc * M, checking the builder's and the
 * product's status, and that fxl_mat4_mul gives the same with out aliasing
 * a or b. */
static int fzp_apply(fxl_mat4_t *acc, const fzp_op *op, char *msg)
{
    fxl_mat4_t m, o1, o2, o3;
    fxl_status_t st, s1, s2, s3;
    uint32_t allow;

    fxl_mat4_identity(&m);
    switch (op->kind) {
    case FZP_ROT_X: fxl_mat4_rotate_x(&m, op->angle); break;
    case FZP_ROT_Y: fxl_mat4_rotate_y(&m, op->angle); break;
    case FZP_ROT_Z: fxl_mat4_rotate_z(&m, op->angle); break;
    case FZP_AXIS:
        st = fxl_mat4_rotate_axis(&m, &op->a, op->angle);
        FZP_EXPECT(st, fzp_allow(fzp_axis_verdict(&op->a)), "fxl_mat4_rotate_axis(%d, %d, %d)", op->a.x, op->a.y,
                   op->a.z);
        if (st != FXL_OK)
            fxl_mat4_identity(&m);
        break;
    case FZP_TRANSLATE: fxl_mat4_translate(&m, op->a.x, op->a.y, op->a.z); break;
    case FZP_SCALE: fxl_mat4_scale(&m, op->a.x, op->a.y, op->a.z); break;
    case FZP_LOOKAT:
        st = fxl_mat4_look_at(&m, &op->a, &op->b, &op->c);
        FZP_EXPECT(st, fzp_allow(fzp_lookat_verdict(op)), "fxl_mat4_look_at");
        if (st != FXL_OK)
            fxl_mat4_identity(&m);
        break;
    case FZP_RAW: m = op->raw; break;
    default: break;
    }
    if (op->kind <= FZP_ROT_Z && (m.m[3][3] != FXL_Q16_ONE || m.m[0][3] != 0 || m.m[1][3] != 0 || m.m[2][3] != 0 ||
                                  m.m[3][0] != 0 || m.m[3][1] != 0 || m.m[3][2] != 0))
        FZ_FAIL("rotation matrix with a translation or a fourth row");
    allow = fzp_allow(fzp_mul_verdict(acc, &m));
    s1 = fxl_mat4_mul(&o1, acc, &m);
    o2 = *acc;
    s2 = fxl_mat4_mul(&o2, &o2, &m);
    o3 = m;
    s3 = fxl_mat4_mul(&o3, acc, &o3);
    FZP_EXPECT(s1, allow, "fxl_mat4_mul");
    if (s2 != s1 || s3 != s1 || memcmp(&o1, &o2, sizeof o1) != 0 || memcmp(&o1, &o3, sizeof o1) != 0)
        FZ_FAIL("fxl_mat4_mul differs when out aliases an operand");
    *acc = o1;
    return 0;
}

/* Build the pipeline from the recipe, checking every setter's status. */
static int fzp_build(fz_pstate *ps, const fz_pcase *pc, fxl_pipeline_t *p, char *msg)
{
    fxl_status_t st;
    uint32_t i, want;
    int32_t w = pc->init_w, h = pc->init_h;

    memset(p, 0, sizeof *p);
    st = fxl_pipeline_init(p, w, h);
    want = (w < 1 || h < 1 || w > FXL_TARGET_MAX_DIM || h > FXL_TARGET_MAX_DIM) ? FZ_E_RANGE : FZP_OK;
    FZP_EXPECT(st, want, "fxl_pipeline_init(%d, %d)", w, h);
    if (st != FXL_OK) {
        w = pc->c.w;
        h = pc->c.h;
        memset(p, 0, sizeof *p);
        if ((st = fxl_pipeline_init(p, w, h)) != FXL_OK)
            FZ_FAIL("fxl_pipeline_init(%d, %d): %s", w, h, fxl_status_name(st));
    }
    /* pipeline.h: viewport (0, 0, w, h), near 1, infinite far, w = depth, cull CW, ... */
    if (p->vp_x != 0 || p->vp_y != 0 || p->vp_w != w || p->vp_h != h || p->near_q16 != FXL_Q16_ONE ||
        p->far_q16 != 0 || p->proj.m[3][2] != -FXL_Q16_ONE || p->proj.m[3][3] != 0 || p->cull != FXL_CULL_CW ||
        p->lighting != 0 || p->material != 0xFFFFu || p->texgen.mode != FXL_TEXGEN_NONE || p->vcache != NULL ||
        p->vcache_count != 0 || p->model.m[0][0] != FXL_Q16_ONE || p->view.m[2][2] != FXL_Q16_ONE)
        FZ_FAIL("fxl_pipeline_init(%d, %d) is not the documented default", w, h);

    if (pc->has_persp) {
        st = fxl_pipeline_set_perspective(p, pc->fovy, pc->aspect, pc->near_q16, pc->far_q16);
        FZP_EXPECT(st, fzp_allow(fzp_persp_verdict(pc->fovy, pc->aspect, pc->near_q16, pc->far_q16)),
                   "fxl_pipeline_set_perspective(%u, %d, %d, %d)", (unsigned)pc->fovy, pc->aspect, pc->near_q16,
                   pc->far_q16);
        if (st == FXL_OK && (p->near_q16 != pc->near_q16 || p->far_q16 != pc->far_q16 ||
                             p->proj.m[3][2] != -FXL_Q16_ONE || p->proj.m[3][3] != 0 || p->proj.m[3][0] != 0))
            FZ_FAIL("fxl_pipeline_set_perspective: planes or w row not as documented");
    }
    if (pc->has_vp) {
        const int32_t *v = pc->vp;
        want = (v[2] < 1 || v[3] < 1 || v[2] > FXL_TARGET_MAX_DIM || v[3] > FXL_TARGET_MAX_DIM ||
                v[0] > FXL_TARGET_MAX_ORIGIN || v[0] < -FXL_TARGET_MAX_ORIGIN || v[1] > FXL_TARGET_MAX_ORIGIN ||
                v[1] < -FXL_TARGET_MAX_ORIGIN) ? FZ_E_RANGE : FZP_OK;
        st = fxl_pipeline_set_viewport(p, v[0], v[1], v[2], v[3]);
        FZP_EXPECT(st, want, "fxl_pipeline_set_viewport(%d, %d, %d, %d)", v[0], v[1], v[2], v[3]);
        if (st == FXL_OK && (p->vp_x != v[0] || p->vp_y != v[1] || p->vp_w != v[2] || p->vp_h != v[3]))
            FZ_FAIL("fxl_pipeline_set_viewport did not set the viewport");
    }
    for (i = 0; i < pc->n_model; i++)
        if (fzp_apply(&p->model, &pc->model[i], msg))
            return 1;
    for (i = 0; i < pc->n_view; i++)
        if (fzp_apply(&p->view, &pc->view[i], msg))
            return 1;
    for (i = 0; i < pc->n_poke; i++) {
        const fzp_poke *k = &pc->poke[i];
        int32_t row = k->rc & 3, col = (k->rc >> 2) & 3;
        switch (k->what) {
        case 0: p->model.m[row][col] = k->value; break;
        case 1: p->view.m[row][col] = k->value; break;
        case 2: p->proj.m[row][col] = k->value; break;
        case 3: p->near_q16 = k->value; break;
        case 4: p->far_q16 = k->value; break;
        case 5: if (k->rc & 1u) p->vp_x = k->value; else p->vp_y = k->value; break;
        case 6: if (k->rc & 1u) p->vp_w = k->value; else p->vp_h = k->value; break;
        default: if (k->rc & 1u) p->light.dir.x = k->value; else p->light.dir.z = k->value; break;
        }
    }
    p->cull = pc->cull;
    p->lighting = pc->lighting;
    p->material = pc->material;
    p->light = pc->light;
    p->texgen = pc->texgen;

    /* the vertex cache, stale contents and all */
    if (pc->cache_mode >= 3) {
        uint32_t n = 0;
        fxl_vcache_entry_t *e = NULL;
        if (pc->cache_mode == 4)
            n = 1u + pc->cache_count % 8u;
        else if (pc->cache_mode == 5)
            n = pc->vert_count == 0 ? 1u : (pc->vert_count < FZP_MAX_CACHE ? pc->vert_count : FZP_MAX_CACHE);
        else if (pc->cache_mode == 6)
            n = FZP_MAX_CACHE;
        if (n) {
            e = (fxl_vcache_entry_t *)fzp_place(&ps->cache, FXL_VCACHE_BYTES(n), pc->at_start);
            memset(e, pc->cache_fill, FXL_VCACHE_BYTES(n));
        }
        if (pc->cache_mode == 7) {
            st = fxl_pipeline_set_vertex_cache(p, NULL, 1u + pc->cache_count);
            FZP_EXPECT(st, FZ_E_ARG, "fxl_pipeline_set_vertex_cache(NULL, %u)", 1u + pc->cache_count);
            e = (fxl_vcache_entry_t *)ps->cache.base;
        }
        st = fxl_pipeline_set_vertex_cache(p, e, n);
        FZP_EXPECT(st, FZP_OK, "fxl_pipeline_set_vertex_cache(%p, %u)", (void *)e, (unsigned)n);
        if (p->vcache != (n ? e : NULL) || p->vcache_count != n)
            FZ_FAIL("fxl_pipeline_set_vertex_cache did not set the cache");
    }
    return 0;
}

/* NULL arguments where the API checks them: FXL_ERR_ARG, nothing else. */
static int fzp_null_calls(fxl_pipeline_t *p, fxl_target_t *t, const fxl_draw_t *d, const fxl_mesh_t *m, char *msg)
{
    fxl_xform_t xf;
    fxl_mat4_t a;
    fxl_vec3_t v3 = {0, 0, 0}, p3[3];
    fxl_vec4_t v4 = {0, 0, 0, 0};
    fxl_clipvert_t cv[3], out[FXL_CLIP_MAX_VERTS];
    fxl_vertex_t vx[3];
    fxl_texcoord_t tc[3];
    fxl_texgen_t tg;
    uint16_t ix[3] = {0, 0, 0};
    uint32_t n;
    fxl_status_t st[40];
    int k = 0, i;

    memset(cv, 0, sizeof cv);
    memset(vx, 0, sizeof vx);
    memset(&xf, 0, sizeof xf);
    memset(p3, 0, sizeof p3);
    fxl_mat4_identity(&a);
    fxl_texgen_defaults(&tg);
    st[k++] = fxl_mesh_draw(NULL, t, d, m, NULL);
    st[k++] = fxl_mesh_draw(p, NULL, d, m, NULL);
    st[k++] = fxl_mesh_draw(p, t, NULL, m, NULL);
    st[k++] = fxl_mesh_draw(p, t, d, NULL, NULL);
    st[k++] = fxl_pipeline_emit(NULL, m, fzp_record, NULL, NULL);
    st[k++] = fxl_pipeline_emit(p, NULL, fzp_record, NULL, NULL);
    st[k++] = fxl_pipeline_emit(p, m, NULL, NULL, NULL);
    st[k++] = fxl_pipeline_prepare(NULL, &xf);
    st[k++] = fxl_pipeline_prepare(p, NULL);
    st[k++] = fxl_pipeline_init(NULL, 16, 16);
    st[k++] = fxl_pipeline_set_perspective(NULL, FXL_ANGLE_DEG(60), FXL_Q16_ONE, FXL_Q16_ONE, 0);
    st[k++] = fxl_pipeline_set_viewport(NULL, 0, 0, 16, 16);
    st[k++] = fxl_pipeline_set_vertex_cache(NULL, NULL, 0);
    st[k++] = fxl_draw_indexed(NULL, d, vx, 3, ix, 1, NULL);
    st[k++] = fxl_draw_indexed(t, NULL, vx, 3, ix, 1, NULL);
    st[k++] = fxl_draw_indexed(t, d, NULL, 3, ix, 1, NULL);
    st[k++] = fxl_draw_indexed(t, d, vx, 3, NULL, 1, NULL);
    st[k++] = fxl_mat4_mul(NULL, &a, &a);
    st[k++] = fxl_mat4_mul(&a, NULL, &a);
    st[k++] = fxl_mat4_mul(&a, &a, NULL);
    st[k++] = fxl_mat4_transform(NULL, &v4, &v4);
    st[k++] = fxl_mat4_transform(&a, NULL, &v4);
    st[k++] = fxl_mat4_transform(&a, &v4, NULL);
    st[k++] = fxl_mat4_transform_point(&a, NULL, &v3);
    st[k++] = fxl_mat4_transform_vector(&a, &v3, NULL);
    st[k++] = fxl_mat4_rotate_axis(NULL, &v3, 0);
    st[k++] = fxl_mat4_rotate_axis(&a, NULL, 0);
    st[k++] = fxl_mat4_look_at(NULL, &v3, &v3, &v3);
    st[k++] = fxl_mat4_look_at(&a, &v3, NULL, &v3);
    st[k++] = fxl_mat4_perspective(NULL, FXL_ANGLE_DEG(60), FXL_Q16_ONE, FXL_Q16_ONE, 0);
    st[k++] = fxl_xform_clip(NULL, &v3, cv);
    st[k++] = fxl_xform_eye(&xf, NULL, &v3);
    st[k++] = fxl_xform_project(&xf, cv, NULL);
    st[k++] = fxl_clip_triangle(NULL, cv, out, &n);
    st[k++] = fxl_clip_triangle(&xf, cv, out, NULL);
    st[k++] = fxl_texgen_triangle(NULL, p3, tc);
    st[k++] = fxl_texgen_triangle(&tg, NULL, tc);
    st[k++] = fxl_texgen_triangle(&tg, p3, NULL);
    for (i = 0; i < k; i++)
        if (st[i] != FXL_ERR_ARG)
            FZ_FAIL("NULL argument call %d: status %s, expected FXL_ERR_ARG", i, fxl_status_name(st[i]));
    return 0;
}

static int64_t fzp_area2(const fxl_vertex_t *t)
{
    int64_t ax = ref_snap(t[0].x), ay = ref_snap(t[0].y);
    int64_t bx = ref_snap(t[1].x) - ax, by = ref_snap(t[1].y) - ay, cx = ref_snap(t[2].x) - ax,
            cy = ref_snap(t[2].y) - ay;
    return bx * cy - cx * by;   /* > 0: clockwise on the display (y down) */
}

/* A clip-space row of xf (q32) applied to pos in double, and a bound on
 * how far the core's row_apply may be from it: three products rounded to
 * q32 (1.5 units) plus the double sum's own error (2^-52 of the terms). */
static double fzp_row_d(const int64_t row[4], const fxl_vec3_t *pos, double *err)
{
    double t0 = (double)row[0] * pos->x / 65536.0, t1 = (double)row[1] * pos->y / 65536.0,
           t2 = (double)row[2] * pos->z / 65536.0, r3 = (double)row[3];
    *err = 1.5 + (fabs(t0) + fabs(t1) + fabs(t2) + fabs(r3)) * 0x1p-52;
    return r3 + t0 + t1 + t2;
}

/* fxl_xform_project in double, for clip x, y, w (q32) known within ex, ew:
 * screen x, y (q16, clamped to the guard band like the core) and inv_w,
 * with tolerances: the input error carried through x / w, plus the core's
 * own (a 31-bit reciprocal, 2^-31 relative, and the q30 and q16 roundings),
 * both doubled. */
typedef struct fzp_proj {
    double sx, sy, iw;
    double tx, ty, tw;
} fzp_proj;

static void fzp_project_d(const fxl_xform_t *xf, double x, double y, double w, double ex, double ey, double ew,
                          fzp_proj *o)
{
    double g = xf->guard_q16 / 65536.0, nx = x / w, ny = y / w, wl = w - ew;
    double hw = (double)xf->hw_q16, hh = (double)xf->hh_q16;
    o->tx = 2.0 * ((ex + fabs(nx) * ew) / wl * hw + (fabs(nx) + 1.0) * 0x1p-30 * hw + 1.0);
    o->ty = 2.0 * ((ey + fabs(ny) * ew) / wl * hh + (fabs(ny) + 1.0) * 0x1p-30 * hh + 1.0);
    nx = nx > g ? g : (nx < -g ? -g : nx);
    ny = ny > g ? g : (ny < -g ? -g : ny);
    o->sx = (double)xf->cx_q16 + nx * hw;
    o->sy = (double)xf->cy_q16 - ny * hh;
    o->iw = (double)xf->near_q32 / w * 4294967296.0;
    o->tw = 2.0 * (o->iw * ew / wl + o->iw * 0x1p-30 + 1.0);
    o->iw = o->iw > 4294967295.0 ? 4294967295.0 : (o->iw < 1.0 ? 1.0 : o->iw);
}

static int fzp_proj_match(const fzp_proj *r, const fxl_vertex_t *v)
{
    return fabs((double)v->x - r->sx) <= r->tx && fabs((double)v->y - r->sy) <= r->ty &&
           fabs((double)v->inv_w - r->iw) <= r->tw;
}

/* Lighting in double. fxl_light_shade rounds n . dir to q16 and clamps it
 * to [0, 1], truncates I = (ambient + diffuse n . dir) / 255 to q16 (within
 * 2^-16 below, 2^-17 above), clamps it to 1 and rounds base * I half up per
 * channel. Given that the n . dir it uses lies in [ndl - tol, ndl + tol],
 * does `got` have, in every channel, a value that chain can give? */
static int fzp_shade_allows(const fxl_light_t *l, double ndl, double tol, uint16_t base, uint16_t got)
{
    static const unsigned sh[3] = {11, 5, 0}, mx[3] = {31, 63, 31};
    double lo = fmin(1.0, fmax(0.0, ndl - tol)), hi = fmin(1.0, fmax(0.0, ndl + tol));
    int c;
    for (c = 0; c < 3; c++) {
        double bc = (double)(((unsigned)base >> sh[c]) & mx[c]);
        double ilo = fmin(1.0, (l->ambient[c] + l->diffuse[c] * lo) / 255.0 - 0x1p-16);
        double ihi = fmin(1.0, (l->ambient[c] + l->diffuse[c] * hi) / 255.0 + 0x1p-16);
        double oc = (double)(((unsigned)got >> sh[c]) & mx[c]);
        if (oc < floor(bc * ilo + 0.5 - 1e-9) || oc > floor(bc * ihi + 0.5 + 1e-9))
            return 0;
    }
    return 1;
}

/* n . dir of a q16 normal as fxl_light_shade forms it, exactly but for the
 * q16 rounding (2^-17, in *tol with the double sum's error). */
static double fzp_ndotl_d(const fxl_light_t *l, const fxl_vec3_t *n, double *tol)
{
    double t0 = (double)n->x * l->dir.x, t1 = (double)n->y * l->dir.y, t2 = (double)n->z * l->dir.z;
    *tol = 0x1p-17 + (fabs(t0) + fabs(t1) + fabs(t2)) * 0x1p-52 * 0x1p-32;
    return (t0 + t1 + t2) * 0x1p-32;
}

/* n . dir for a mesh normal taken to eye space by the core's view * model
 * (eye_normal in pipeline.c): e = mv's 3x3 applied to n (three products
 * rounded to q32 units, so within 1.5 of the double e per component),
 * normalised to q30 (2^-27 relative) and rounded to q16 (2^-17), so each
 * component of the core's unit normal is within 2^-17 + 2^-27 + 2 |de| / |e|
 * of e / |e|. Returns 0 where that cannot be told: a product that could
 * saturate. */
static int fzp_eye_ndotl_d(const fxl_xform_t *xf, const fxl_light_t *l, const fxl_vec3_t *n, double *ndl,
                           double *tol)
{
    double e[3], len = 0, eps;
    int r;
    for (r = 0; r < 3; r++) {
        double t0 = (double)xf->mv[r][0] * n->x / 65536.0, t1 = (double)xf->mv[r][1] * n->y / 65536.0,
               t2 = (double)xf->mv[r][2] * n->z / 65536.0;
        if (fabs(t0) >= 0x1p61 || fabs(t1) >= 0x1p61 || fabs(t2) >= 0x1p61)
            return 0;
        e[r] = t0 + t1 + t2;
        len += e[r] * e[r];
    }
    len = sqrt(len);
    eps = len < 8.0 ? 2.0 : 0x1p-17 + 0x1p-27 + 2.0 * (1.5 * sqrt(3.0) + len * 0x1p-50) / len;
    *ndl = len < 8.0 ? 0.0 : (e[0] * l->dir.x + e[1] * l->dir.y + e[2] * l->dir.z) / len / 65536.0;
    *tol = (fabs((double)l->dir.x) + fabs((double)l->dir.y) + fabs((double)l->dir.z)) / 65536.0 * eps + 0x1p-17 +
           0x1p-40;
    return 1;
}

/* P5, geometry: a mesh triangle whose three vertices are certainly inside
 * near, far and the guard band (by more than the error bounds above) is
 * emitted unclipped, so unless the cull mode might drop it, some emitted
 * triangle carries its three projected vertices, in order. Returns the
 * number of mesh triangles so checked in *checked. */
static int fzp_check_emitted_geometry(const fz_pcase *pc, const fxl_pipeline_t *p, const fxl_xform_t *xf,
                                      const fzp_rec *rec, uint32_t *checked, char *msg)
{
    double g = xf->guard_q16 / 65536.0;
    int unlit = !p->lighting || !pc->has_normal;
    uint32_t t, k, j;
    *checked = 0;
    for (t = 0; t < pc->tri_count; t++) {
        fzp_proj pr[3];
        fxl_texcoord_t want[3];
        fxl_vec3_t tpos[3];
        uint16_t want_col[3];
        double ndl[3], ndl_tol[3];
        int col_check[3];           /* 0 none, 1 want_col exactly, 2 lit from want_col */
        double area, l1 = 0, e = 0, d, margin;
        int inside = 1, tg_ok = 1, placed = 0;
        for (k = 0; k < 3 && inside; k++) {
            const fxl_vec3_t *pos = &pc->pos[pc->idx[3u * t + k] % pc->npool];
            double ex, ey, ew, x, y, w, m;
            x = fzp_row_d(xf->mvp[0], pos, &ex);
            y = fzp_row_d(xf->mvp[1], pos, &ey);
            w = fzp_row_d(xf->mvp[3], pos, &ew);
            m = g * ew + 4.0;
            if (w - ew < (double)xf->near_q32 + 2.0 || (xf->far_q32 != 0 && w + ew > (double)xf->far_q32 - 2.0) ||
                fabs(x) + ex > g * w - m || fabs(y) + ey > g * w - m)
                inside = 0;
            else
                fzp_project_d(xf, x, y, w, ex, ey, ew, &pr[k]);
        }
        if (!inside)
            continue;
        /* twice the signed area in pixels (y down), and how far moving each
         * vertex by d (snapping, half a sub-pixel, plus the tolerance) can change it */
        area = ((pr[1].sx - pr[0].sx) * (pr[2].sy - pr[0].sy) - (pr[2].sx - pr[0].sx) * (pr[1].sy - pr[0].sy)) /
               (65536.0 * 65536.0);
        for (k = 0; k < 3; k++) {
            e = fmax(e, fmax(pr[k].tx, pr[k].ty) / 65536.0);
            l1 += (fabs(pr[(k + 1) % 3].sx - pr[k].sx) + fabs(pr[(k + 1) % 3].sy - pr[k].sy)) / 65536.0;
        }
        d = e + ldexp(1.0, -(FXL_SUBPIXEL_BITS + 1));
        margin = 4.0 * d * l1 + 16.0 * d * d;
        if (p->cull == FXL_CULL_CW ? area > -margin : p->cull == FXL_CULL_CCW && area < margin)
            continue; /* culled, or too close to tell */
        /* unclipped, its attributes pass unchanged: the mesh's uv (0, 0
         * without them) when texgen is off (else those of texgen, below),
         * the mesh colour or material when unlit, lit within the rounding
         * fzp_eye_ndotl_d and fzp_shade_allows derive. Pools repeat positions
         * with other attributes, so another mesh triangle may be emitted at
         * the same place: any emitted triangle with both is this one. */
        for (k = 0; k < 3; k++) {
            uint32_t ix = pc->idx[3u * t + k] % pc->npool;
            want[k].u = want[k].v = 0;
            if (pc->has_uv)
                want[k] = pc->uv[ix];
            want_col[k] = pc->has_color ? pc->color[ix] : p->material;
            col_check[k] = unlit ? 1 : 2 * fzp_eye_ndotl_d(xf, &p->light, &pc->normal[ix], &ndl[k], &ndl_tol[k]);
            tpos[k] = pc->pos[ix];
            if (p->texgen.space == FXL_TEXGEN_EYE && fxl_xform_eye(xf, &pc->pos[ix], &tpos[k]) != FXL_OK)
                tg_ok = 0;
        }
        /* with texgen on, the uv of fxl_texgen_triangle on the same
         * positions, bit for bit (the emit path splits it per vertex and
         * per triangle; pipeline.h says the two are the same) */
        if (p->texgen.mode != FXL_TEXGEN_NONE)
            tg_ok = tg_ok && fxl_texgen_triangle(&p->texgen, tpos, want) == FXL_OK;
        for (j = 0; j < rec->n; j++) {
            const fxl_vertex_t *v = &rec->tri[3u * j];
            int attr = 1;
            if (!fzp_proj_match(&pr[0], &v[0]) || !fzp_proj_match(&pr[1], &v[1]) || !fzp_proj_match(&pr[2], &v[2]))
                continue;
            placed = 1;
            for (k = 0; k < 3; k++)
                if ((tg_ok && (v[k].u != want[k].u || v[k].v != want[k].v)) ||
                    (col_check[k] == 1 && v[k].color != want_col[k]) ||
                    (col_check[k] == 2 && !fzp_shade_allows(&p->light, ndl[k], ndl_tol[k], want_col[k], v[k].color)))
                    attr = 0;
            if (attr)
                break;
        }
        if (j == rec->n && placed)
            FZ_FAIL("mesh triangle %u emitted unclipped at its place, but not with its uv (%ld, %ld) (%ld, %ld) "
                    "(%ld, %ld) or colours (%s) %04X %04X %04X",
                    (unsigned)t, (long)want[0].u, (long)want[0].v, (long)want[1].u, (long)want[1].v,
                    (long)want[2].u, (long)want[2].v, unlit ? "unlit" : "lit from", want_col[0], want_col[1],
                    want_col[2]);
        if (j == rec->n)
            FZ_FAIL("mesh triangle %u lies inside every plane, projects to (%.1f, %.1f) (%.1f, %.1f) (%.1f, %.1f) px "
                    "(tolerance %.3g px), but no emitted triangle is there",
                    (unsigned)t, pr[0].sx / 65536.0, pr[0].sy / 65536.0, pr[1].sx / 65536.0, pr[1].sy / 65536.0,
                    pr[2].sx / 65536.0, pr[2].sy / 65536.0, pr[0].tx / 65536.0);
        (*checked)++;
    }
    return 0;
}

/* P5 on the emitted triangles. */
static int fzp_check_emitted(const fz_pcase *pc, const fxl_pipeline_t *p, const fxl_xform_t *xf, const fzp_rec *rec,
                             char *msg)
{
    const int64_t band = (int64_t)FXL_GUARD_PX * 65536 + 2;
    int uni_col = !p->lighting || !pc->has_normal;
    int uni_uv = p->texgen.mode == FXL_TEXGEN_NONE;
    uint16_t col = pc->has_color ? pc->color[0] : p->material;
    fxl_texcoord_t uv = {0, 0};
    uint32_t t, k, i;

    if (pc->has_uv) {
        uv = pc->uv[0];
        for (i = 1; i < pc->npool; i++)
            if (pc->uv[i].u != uv.u || pc->uv[i].v != uv.v)
                uni_uv = 0;
    }
    for (i = 1; pc->has_color && i < pc->npool; i++)
        if (pc->color[i] != col)
            uni_col = 0;
    if (rec->over || rec->n > (FXL_CLIP_MAX_VERTS - 2u) * pc->tri_count)
        FZ_FAIL("%u screen triangles from %u mesh triangles (at most %u each)", (unsigned)rec->n,
                (unsigned)pc->tri_count, FXL_CLIP_MAX_VERTS - 2u);
    if (rec->null_tri || rec->after_stop)
        FZ_FAIL("emit callback %s", rec->null_tri ? "given NULL" : "called after it returned an error");
    for (t = 0; t < rec->n; t++) {
        const fxl_vertex_t *v = &rec->tri[3u * t];
        int64_t a = fzp_area2(v);
        if ((p->cull == FXL_CULL_CW && a > 0) || (p->cull == FXL_CULL_CCW && a < 0))
            FZ_FAIL("screen triangle %u has the winding cull mode %u drops (area2 %lld)", (unsigned)t, p->cull,
                    (long long)a);
        for (k = 0; k < 3; k++) {
            int64_t dx = (int64_t)v[k].x - xf->cx_q16, dy = (int64_t)v[k].y - xf->cy_q16;
            if (dx > band || dx < -band || dy > band || dy < -band)
                FZ_FAIL("screen triangle %u vertex %u at (%ld, %ld) q16, outside the guard band of the viewport centre",
                        (unsigned)t, (unsigned)k, (long)v[k].x, (long)v[k].y);
            if (v[k].inv_w == 0)
                FZ_FAIL("screen triangle %u vertex %u has inv_w 0", (unsigned)t, (unsigned)k);
            if (uni_col && v[k].color != col)
                FZ_FAIL("screen triangle %u vertex %u colour %04X, the mesh's is uniformly %04X", (unsigned)t,
                        (unsigned)k, v[k].color, col);
            if (uni_uv && (v[k].u != uv.u || v[k].v != uv.v))
                FZ_FAIL("screen triangle %u vertex %u uv (%ld, %ld), the mesh's is uniformly (%ld, %ld)", (unsigned)t,
                        (unsigned)k, (long)v[k].u, (long)v[k].v, (long)uv.u, (long)uv.v);
        }
    }
    return 0;
}

/* P6: the stages called one by one on the first triangle's positions. */
static int fzp_parts(const fz_pcase *pc, const fxl_pipeline_t *p, const fxl_xform_t *xf, int xf_ok, char *msg)
{
    fxl_vec3_t pos[3], o3;
    fxl_vec4_t o4, in4;
    fxl_clipvert_t cv[3], out[FXL_CLIP_MAX_VERTS];
    fxl_texcoord_t tc[3];
    fxl_status_t st;
    uint32_t k, n, allow, i;
    int ok3 = 1;
    int32_t in[4];
    const fxl_texgen_t *tg = &p->texgen;

    for (k = 0; k < 3; k++)
        pos[k] = pc->pos[(pc->tri_count && pc->idx[k] < pc->vert_count ? pc->idx[k] : k) % pc->npool];

    /* transforms of the model matrix (the fourth row is ignored for points
     * and directions, pipeline.h) */
    in[0] = pos[0].x; in[1] = pos[0].y; in[2] = pos[0].z; in[3] = FXL_Q16_ONE;
    allow = fzp_allow(fzp_transform_verdict(&p->model, in, 0, 2));
    st = fxl_mat4_transform_point(&p->model, &pos[0], &o3);
    FZP_EXPECT(st, allow, "fxl_mat4_transform_point");
    in[3] = 0;
    allow = fzp_allow(fzp_transform_verdict(&p->model, in, 0, 2));
    st = fxl_mat4_transform_vector(&p->model, &pos[0], &o3);
    FZP_EXPECT(st, allow, "fxl_mat4_transform_vector");
    in[3] = pos[1].x;
    in4.x = in[0]; in4.y = in[1]; in4.z = in[2]; in4.w = in[3];
    st = fxl_mat4_transform(&p->view, &in4, &o4);
    FZP_EXPECT(st, fzp_allow(fzp_transform_verdict(&p->view, in, 0, 3)), "fxl_mat4_transform");

    /* texgen alone: FXL_ERR_ARG for a bad enum, else OK; mode none gives the offsets */
    st = fxl_texgen_triangle(tg, pos, tc);
    FZP_EXPECT(st, (tg->mode > FXL_TEXGEN_CUBE || tg->axis > FXL_AXIS_Z || tg->plane > FXL_PLANE_XZ ||
                    tg->space > FXL_TEXGEN_EYE) ? FZ_E_ARG : FZP_OK, "fxl_texgen_triangle");
    if (st == FXL_OK && tg->mode == FXL_TEXGEN_NONE)
        for (k = 0; k < 3; k++)
            /* (INT32_MIN, outside q16's documented range, saturates) */
            if (tc[k].u != (tg->offset_u == INT32_MIN ? -INT32_MAX : tg->offset_u) ||
                tc[k].v != (tg->offset_v == INT32_MIN ? -INT32_MAX : tg->offset_v))
                FZ_FAIL("fxl_texgen_triangle mode none: (%ld, %ld), not the offsets", (long)tc[k].u, (long)tc[k].v);

    /* lighting never brightens, full ambient keeps the base colour, and
     * each channel is what the double-precision formula rounds to */
    for (i = 0; i < pc->npool; i++) {
        static const unsigned sh[3] = {11, 5, 0}, mx[3] = {31, 63, 31};
        uint16_t base = pc->has_color ? pc->color[i] : p->material;
        uint16_t lit = fxl_light_shade(&p->light, &pc->normal[i], base);
        double tol, ndl = fzp_ndotl_d(&p->light, &pc->normal[i], &tol);
        for (k = 0; k < 3; k++) {
            unsigned b = ((unsigned)base >> sh[k]) & mx[k], l = ((unsigned)lit >> sh[k]) & mx[k];
            if (l > b || (p->light.ambient[k] == 255 && l != b))
                FZ_FAIL("fxl_light_shade(%04X) = %04X: channel %u %u from %u", base, lit, (unsigned)k, l, b);
        }
        if (!fzp_shade_allows(&p->light, ndl, tol, base, lit))
            FZ_FAIL("fxl_light_shade(%04X, normal (%ld, %ld, %ld)) = %04X, n . dir = %.9f: not the rounded formula",
                    base, (long)pc->normal[i].x, (long)pc->normal[i].y, (long)pc->normal[i].z, lit, ndl);
    }

    if (!xf_ok)
        return 0;
    for (k = 0; k < 3; k++) {
        st = fxl_xform_clip(xf, &pos[k], &cv[k]);
        FZP_EXPECT(st, fzp_allow(fzp_vertex_verdict(xf, &pos[k], 0)), "fxl_xform_clip(%d, %d, %d)", pos[k].x,
                   pos[k].y, pos[k].z);
        if (st != FXL_OK)
            ok3 = 0;
        else if (cv[k].u || cv[k].v || cv[k].r || cv[k].g || cv[k].b)
            FZ_FAIL("fxl_xform_clip: attributes not zeroed");
        else {
            double ex, ey, ew, x = fzp_row_d(xf->mvp[0], &pos[k], &ex), y = fzp_row_d(xf->mvp[1], &pos[k], &ey),
                               w = fzp_row_d(xf->mvp[3], &pos[k], &ew);
            if (fabs((double)cv[k].x - x) > ex || fabs((double)cv[k].y - y) > ey || fabs((double)cv[k].w - w) > ew)
                FZ_FAIL("fxl_xform_clip: (%lld, %lld, w %lld) q32, the double product (%.1f, %.1f, w %.1f)",
                        (long long)cv[k].x, (long long)cv[k].y, (long long)cv[k].w, x, y, w);
        }
        st = fxl_xform_eye(xf, &pos[k], &o3);
        {
            int v0 = fzp_row_verdict(xf->mv[0], &pos[k], FZP_LIM_I32_Q32),
                v1 = fzp_row_verdict(xf->mv[1], &pos[k], FZP_LIM_I32_Q32),
                v2 = fzp_row_verdict(xf->mv[2], &pos[k], FZP_LIM_I32_Q32);
            int vm = v0 > v1 ? v0 : v1;
            FZP_EXPECT(st, fzp_allow(v2 > vm ? v2 : vm), "fxl_xform_eye(%d, %d, %d)", pos[k].x, pos[k].y, pos[k].z);
        }
    }
    if (!ok3)
        return 0;
    /* in range: the clipper answers OK, its output lies on the inside of
     * every plane (up to the rounding fxl_xform_project allows: 2^-10 G)
     * and every output vertex projects */
    st = fxl_clip_triangle(xf, cv, out, &n);
    FZP_EXPECT(st, FZP_OK, "fxl_clip_triangle");
    if (n == 1 || n == 2 || n > FXL_CLIP_MAX_VERTS)
        FZ_FAIL("fxl_clip_triangle: %u vertices", (unsigned)n);
    for (k = 0; k < n; k++) {
        fxl_vertex_t sv;
        double g = xf->guard_q16 / 65536.0, w = (double)out[k].w, lim = g * w * (1.0 + 1.0 / 1024) + 2.0;
        if (out[k].w < xf->near_q32 || (xf->far_q32 != 0 && out[k].w > xf->far_q32 + (xf->far_q32 >> 20) + 2) ||
            fabs((double)out[k].x) > lim || fabs((double)out[k].y) > lim)
            FZ_FAIL("fxl_clip_triangle: vertex %u (%lld, %lld, w %lld) q32 outside the planes", (unsigned)k,
                    (long long)out[k].x, (long long)out[k].y, (long long)out[k].w);
        st = fxl_xform_project(xf, &out[k], &sv);
        FZP_EXPECT(st, FZP_OK, "fxl_xform_project of clipped vertex %u (%lld, %lld, w %lld) q32", (unsigned)k,
                   (long long)out[k].x, (long long)out[k].y, (long long)out[k].w);
        if (sv.inv_w == 0)
            FZ_FAIL("fxl_xform_project: inv_w 0");
        if (st == FXL_OK) {
            fzp_proj r;
            fzp_project_d(xf, (double)out[k].x, (double)out[k].y, w, 0.0, 0.0, 0.0, &r);
            if (!fzp_proj_match(&r, &sv))
                FZ_FAIL("fxl_xform_project of clipped vertex %u: (%ld, %ld) q16 inv_w %lu, double (%.1f, %.1f) "
                        "inv_w %.1f", (unsigned)k, (long)sv.x, (long)sv.y, (unsigned long)sv.inv_w, r.sx, r.sy, r.iw);
        }
    }
    return 0;
}

/* The statuses fxl_pipeline_emit may return (P1), from the documented
 * rules; xf, *xf_ok: fxl_pipeline_prepare's result, checked against the
 * double model. */
static int fzp_expect_emit(const fz_pcase *pc, const fxl_pipeline_t *p, const fxl_mesh_t *m, fxl_xform_t *xf,
                           int *xf_ok, uint32_t *mask, char *msg)
{
    double mv[4][4], mvp[4][4], tol[2][4][4];
    int pv, vv = 0, r, c;
    int bad_sub = p->texgen.axis > FXL_AXIS_Z || p->texgen.plane > FXL_PLANE_XZ || p->texgen.space > FXL_TEXGEN_EYE;
    int arg = !m->pos || (!m->idx && m->tri_count) || p->cull > FXL_CULL_CCW || p->texgen.mode > FXL_TEXGEN_CUBE ||
              (p->texgen.mode != FXL_TEXGEN_NONE && m->tri_count > 0 && bad_sub);
    /* fields that are no enum in use: refusing them is allowed */
    uint32_t maybe_arg = (bad_sub || p->lighting > 1) ? FZ_E_ARG : 0u;
    uint32_t t, k;
    fxl_status_t st;

    pv = fzp_prepare_verdict(p, mv, mvp, tol);
    st = fxl_pipeline_prepare(p, xf);
    FZP_EXPECT(st, fzp_allow(pv), "fxl_pipeline_prepare");
    *xf_ok = st == FXL_OK;
    if (*xf_ok) {
        int32_t maxdim = p->vp_w > p->vp_h ? p->vp_w : p->vp_h;
        int64_t g = ((int64_t)FXL_GUARD_PX << 17) / maxdim;
        if (g > ((int64_t)FXL_GUARD_MAX << 16))
            g = (int64_t)FXL_GUARD_MAX << 16;
        if (xf->guard_q16 != g || xf->near_q32 != (int64_t)p->near_q16 * 65536 ||
            xf->far_q32 != (int64_t)p->far_q16 * 65536 || xf->cx_q16 != ((int64_t)2 * p->vp_x + p->vp_w) * 32768 ||
            xf->cy_q16 != ((int64_t)2 * p->vp_y + p->vp_h) * 32768 || xf->hw_q16 != (int64_t)p->vp_w * 32768 ||
            xf->hh_q16 != (int64_t)p->vp_h * 32768)
            FZ_FAIL("fxl_pipeline_prepare: planes, guard band or viewport mapping not as documented");
        for (r = 0; r < 4; r++)
            for (c = 0; c < 4; c++) {
                if (fabs((double)xf->mv[r][c] - mv[r][c]) > tol[0][r][c] ||
                    fabs((double)xf->mvp[r][c] - mvp[r][c]) > tol[1][r][c])
                    FZ_FAIL("fxl_pipeline_prepare: entry (%d,%d) mv %lld / mvp %lld, the model says %.6g / %.6g", r,
                            c, (long long)xf->mv[r][c], (long long)xf->mvp[r][c], mv[r][c], mvp[r][c]);
            }
    }
    if (arg) {
        *mask = FZ_E_ARG | (*xf_ok ? 0u : FZ_E_RANGE);
        return 0;
    }
    if (!*xf_ok) {
        *mask = FZ_E_RANGE | maybe_arg;
        return 0;
    }
    /* the triangles in order: an index out of range or a vertex out of
     * range stops with FXL_ERR_RANGE (every error from here on is RANGE) */
    for (t = 0; t < m->tri_count && vv < 2; t++)
        for (k = 0; k < 3 && vv < 2; k++) {
            uint32_t ix = m->idx[3u * t + k];
            int x;
            if (ix >= m->vert_count) {
                vv = 2;
                break;
            }
            x = fzp_vertex_verdict(xf, &pc->pos[ix % pc->npool],
                                   p->texgen.mode != FXL_TEXGEN_NONE && p->texgen.space == FXL_TEXGEN_EYE);
            vv = x > vv ? x : vv;
        }
    *mask = fzp_allow(vv) | maybe_arg;
    return 0;
}

/* Field by field: padding bytes need not match. */
static int fzp_vert_equal(const fxl_vertex_t *a, const fxl_vertex_t *b)
{
    return a->x == b->x && a->y == b->y && a->inv_w == b->inv_w && a->u == b->u && a->v == b->v &&
           a->color == b->color;
}

static int fzp_stats_equal(const fxl_stats_t *a, const fxl_stats_t *b)
{
    return a->triangles == b->triangles && a->drawn == b->drawn && a->culled_degenerate == b->culled_degenerate &&
           a->culled_outside == b->culled_outside && a->culled_backface == b->culled_backface &&
           a->pixels == b->pixels && a->spans == b->spans && a->divisions == b->divisions &&
           a->generic == b->generic;
}

/* P7: every emitted triangle as a raster case of its own (the case's
 * target, texture and draw), so check 7 sees the front end's triangles:
 * guard-band and near-plane vertices, clipped fans, lit colours. */
static int fzp_alone(fz_pstate *ps, const fz_pcase *pc, const fzp_rec *rec, fz_outcome *out, char *msg)
{
    uint32_t t;
    for (t = 0; t < rec->n; t++) {
        fz_case ct = pc->c;
        fz_outcome o;
        memcpy(ct.v, &rec->tri[3u * t], sizeof ct.v);
        if (fz_run_case(ps->s, &ct, &o, msg)) {
            char why[FZ_MSG];
            memcpy(why, msg, FZ_MSG);
            why[FZ_MSG - 1] = 0;
            snprintf(msg, FZ_MSG, "emitted triangle %u of %u drawn alone: %.400s", (unsigned)t, (unsigned)rec->n, why);
            return 1;
        }
        out->alone_tris++;
        out->alone_written += o.written;
        out->alone_checked += o.texel_checked;
    }
    return 0;
}

/* Run one decoded front-end case. Returns 0 when every check holds, 1 with
 * a message in msg (FZ_MSG bytes) otherwise. */
static int fz_pipe_run(fz_pstate *ps, fz_pcase *pc, fz_outcome *out, char *msg)
{
    fz_state *s = ps->s;
    fz_case *c = &pc->c;
    size_t nw = (size_t)c->stride * (size_t)c->h + 2u * FZ_CANARY;
    uint16_t *dep_a = c->has_depth ? s->dep_a : NULL, *dep_b = c->has_depth ? s->dep_b : NULL;
    uint16_t *dep_c = c->has_depth ? ps->dep_c : NULL;
    fxl_pipeline_t p, p_keep, pn;
    fxl_target_t ta, ta_keep, tb[2], tc;
    fxl_mesh_t mesh, mesh_keep;
    fxl_draw_t draw_keep;
    fxl_stats_t sa, e1s, e2s, rs, sum;
    fxl_status_t st_a, st_b[2], e1, e2 = FXL_OK, chk, st_r;
    fxl_xform_t xf;
    fzp_rec rec1, rec2;
    uint32_t setting, mask, written = 0, nb = 1, i, count, cache_n;
    int32_t row = 0;
    int xf_ok, may_write, banded;

    msg[0] = 0;
    memset(out, 0, sizeof *out);
    memset(&e2s, 0, sizeof e2s);
    memset(&xf, 0, sizeof xf);
    out->pipe = 1;
    if (c->has_tex)
        fz_place_texture(s, c);
    if (c->has_depth)
        fz_init_depth(s, c);
    if (fzp_build(ps, pc, &p, msg))
        return 1;
    cache_n = p.vcache_count;
    fzp_place_mesh(ps, pc, &mesh);
    fz_fill(c, s, s->pix_a, 0x0000u, dep_a);
    fz_fill(c, s, s->pix_b, 0xFFFFu, dep_b);
    fz_fill(c, s, ps->pix_c, 0x0000u, dep_c);
    fz_make_target(c, &ta, s->pix_a, dep_a);
    if (fzp_null_calls(&p, &ta, &c->draw, &mesh, msg))
        return 1;

    /* A: the whole target */
    /* memcpy: the memcmp below must see the padding bytes too */
    memcpy(&p_keep, &p, sizeof p);
    memcpy(&ta_keep, &ta, sizeof ta);
    memcpy(&mesh_keep, &mesh, sizeof mesh);
    memcpy(&draw_keep, &c->draw, sizeof draw_keep);
    memset(&sa, 0, sizeof sa);
    st_a = fxl_mesh_draw(&p, &ta, &c->draw, &mesh, pc->stats_null ? NULL : &sa);
    out->status = st_a;
    if (memcmp(&p, &p_keep, sizeof p) != 0 || memcmp(&ta, &ta_keep, sizeof ta) != 0 ||
        memcmp(&mesh, &mesh_keep, sizeof mesh) != 0 || memcmp(&c->draw, &draw_keep, sizeof draw_keep) != 0)
        FZ_FAIL("fxl_mesh_draw changed the pipeline, target, mesh or draw");

    /* B: the same as two bands (a valid target whose clip lies in the buffer) */
    banded = fz_target_valid(c) && c->h >= 2 && pc->split != 0 && c->clip.x0 >= c->origin_x &&
             c->clip.y0 >= c->origin_y && c->clip.x1 <= c->origin_x + c->w && c->clip.y1 <= c->origin_y + c->h;
    if (banded) {
        row = 1 + (int32_t)(pc->split % (uint32_t)(c->h - 1));
        if (c->origin_y + row > FXL_TARGET_MAX_ORIGIN)   /* the lower band's origin must stay valid */
            row = FXL_TARGET_MAX_ORIGIN - c->origin_y;
    }
    if (row >= 1) {
        fzp_band(c, &tb[0], s->pix_b, dep_b, 0, row);
        fzp_band(c, &tb[1], s->pix_b, dep_b, row, c->h - row);
        nb = 2;
    } else {
        fz_make_target(c, &tb[0], s->pix_b, dep_b);
    }
    for (i = 0; i < nb; i++)
        st_b[i] = fxl_mesh_draw(&p, &tb[i], &c->draw, &mesh, NULL);

    /* the emitted triangles: without the cache, then with it (and stopped) */
    pn = p;
    pn.vcache = NULL;
    pn.vcache_count = 0;
    memset(&rec1, 0, sizeof rec1);
    rec1.tri = ps->rec1;
    rec1.cap = FZP_MAX_EMIT;
    memset(&e1s, 0, sizeof e1s);
    e1 = fxl_pipeline_emit(&pn, &mesh, fzp_record, &rec1, &e1s);
    memset(&rec2, 0, sizeof rec2);
    if (cache_n || pc->stop_at) {
        rec2.tri = ps->rec2;
        rec2.cap = FZP_MAX_EMIT;
        rec2.stop_at = pc->stop_at;
        rec2.stop_status = (pc->stop_at & 1u) ? FXL_ERR_IO : FXL_ERR_BUSY;
        memset(&e2s, 0, sizeof e2s);
        e2 = fxl_pipeline_emit(&p, &mesh, fzp_record, &rec2, &e2s);
    }
    if (cache_n && !fzp_canary_ok(&ps->cache, FXL_VCACHE_BYTES(cache_n), pc->at_start))
        FZ_FAIL("canary next to the vertex cache (%u entries) overwritten", (unsigned)cache_n);
    out->emitted = rec1.n;

    /* P2, P1 */
    if (fz_check_canaries(c, s, s->pix_a, dep_a, msg) || fz_check_canaries(c, s, s->pix_b, dep_b, msg) ||
        fzp_check_mesh(ps, pc, msg))
        return 1;
    chk = fxl_draw_check(&ta, &c->draw);
    setting = fz_setting_errors(c);
    if (setting == 0 ? chk != FXL_OK : (chk == FXL_OK || (fz_status_bit(chk) & setting) == 0))
        FZ_FAIL("fxl_draw_check says %s for these settings", fxl_status_name(chk));
    if (fzp_expect_emit(pc, &p, &mesh, &xf, &xf_ok, &mask, msg))
        return 1;
    FZP_EXPECT(e1, mask, "fxl_pipeline_emit (%u triangles emitted)", (unsigned)rec1.n);
    if (st_a != (chk != FXL_OK ? chk : e1))
        FZ_FAIL("fxl_mesh_draw %s, but fxl_draw_check %s and fxl_pipeline_emit %s", fxl_status_name(st_a),
                fxl_status_name(chk), fxl_status_name(e1));
    for (i = 0; i < nb; i++)
        if (st_b[i] != st_a)
            FZ_FAIL("band %u of the target: status %s, the whole target %s", (unsigned)i, fxl_status_name(st_b[i]),
                    fxl_status_name(st_a));
    if (rec2.tri) {
        uint32_t want_n = rec2.stopped ? rec2.stop_at : rec1.n;
        if (rec2.stopped ? e2 != rec2.stop_status : e2 != e1)
            FZ_FAIL("emit with the cache: %s, without %s%s", fxl_status_name(e2), fxl_status_name(e1),
                    rec2.stopped ? " (stopped by the callback)" : "");
        for (i = 0; i < 3u * rec2.n && i < 3u * rec1.n && fzp_vert_equal(&rec2.tri[i], &rec1.tri[i]); i++) {
        }
        if (rec2.n != want_n || i != 3u * rec2.n)
            FZ_FAIL("emit with the cache (%u entries): %u triangles, not the %u without it", (unsigned)cache_n,
                    (unsigned)rec2.n, (unsigned)want_n);
        if (!rec2.stopped && !fzp_stats_equal(&e1s, &e2s))
            FZ_FAIL("emit with the cache counts differently");
        if (rec2.after_stop)
            FZ_FAIL("emit called the callback after it returned an error");
    }
    if (e1s.triangles != e1s.culled_outside + e1s.culled_backface || e1s.drawn || e1s.pixels ||
        e1s.culled_degenerate || e1s.culled_outside > pc->tri_count)
        FZ_FAIL("emit stats: %u triangles, %u outside, %u back faces, %u drawn", (unsigned)e1s.triangles,
                (unsigned)e1s.culled_outside, (unsigned)e1s.culled_backface, (unsigned)e1s.drawn);
    if (xf_ok && fzp_check_emitted(pc, &p, &xf, &rec1, msg))
        return 1;
    if (xf_ok && e1 == FXL_OK && !pc->pos_null && !pc->idx_null &&
        fzp_check_emitted_geometry(pc, &p, &xf, &rec1, &out->placed, msg))
        return 1;

    /* P3 */
    may_write = chk == FXL_OK && (st_a == FXL_OK || rec1.n > 0);
    if (fz_check_writes(c, s, s->pix_a, s->pix_b, dep_a, dep_b, st_a, may_write, &written, msg))
        return 1;
    out->written = written;

    /* P4: what emit gave, drawn as an indexed list, is what fxl_mesh_draw drew */
    {
        fxl_vertex_t *rv = (fxl_vertex_t *)fzp_place(&ps->rverts, 3u * rec1.n * sizeof(fxl_vertex_t), pc->at_start);
        uint16_t *ri;
        uint32_t nv = 3u * rec1.n;
        count = rec1.n + (pc->bad_tail ? 1u : 0u);
        ri = (uint16_t *)fzp_place(&ps->ridx, 3u * count * sizeof(uint16_t), pc->at_start);
        for (i = 0; i < nv; i++) {
            uint32_t at = pc->reverse ? nv - 1u - i : i;
            rv[at] = rec1.tri[i];
            ri[i] = (uint16_t)at;
        }
        if (pc->bad_tail) {
            ri[nv] = 0;
            ri[nv + 1] = (uint16_t)(nv + (pc->split & 3u));
            ri[nv + 2] = 0xFFFFu;
        }
        fz_make_target(c, &tc, ps->pix_c, dep_c);
        memset(&rs, 0, sizeof rs);
        st_r = fxl_draw_indexed(&tc, &c->draw, rv, nv, ri, count, &rs);
        if (count == 0)
            FZP_EXPECT(st_r, FZP_OK | fzp_bit(chk), "fxl_draw_indexed of nothing");
        else
            FZP_EXPECT(st_r, chk != FXL_OK ? fzp_bit(chk) : (pc->bad_tail ? FZ_E_RANGE : FZP_OK),
                       "fxl_draw_indexed of %u emitted triangles%s", (unsigned)rec1.n,
                       pc->bad_tail ? " and one out of range" : "");
        if (!fzp_canary_ok(&ps->rverts, 3u * rec1.n * sizeof(fxl_vertex_t), pc->at_start) ||
            !fzp_canary_ok(&ps->ridx, 3u * count * sizeof(uint16_t), pc->at_start))
            FZ_FAIL("canary next to the indexed list overwritten");
        for (i = 0; i < nv; i++)
            if (!fzp_vert_equal(&rv[pc->reverse ? nv - 1u - i : i], &rec1.tri[i]) ||
                ri[i] != (pc->reverse ? nv - 1u - i : i))
                FZ_FAIL("fxl_draw_indexed changed its vertices or indices");
    }
    if (memcmp(ps->pix_c, s->pix_a, nw * 2u) != 0 || (dep_c && memcmp(dep_c, dep_a, nw * 2u) != 0)) {
        for (i = 0; i < nw && ps->pix_c[i] == s->pix_a[i] && (!dep_c || dep_c[i] == dep_a[i]); i++) {
        }
        FZ_FAIL("fxl_mesh_draw and fxl_draw_indexed of the emitted triangles differ at word %ld: %04X vs %04X",
                (long)i - FZ_CANARY, s->pix_a[i], ps->pix_c[i]);
    }

    /* stats: the front end's counts plus the rasterizer's */
    if (!pc->stats_null) {
        static const fxl_stats_t zero = {0, 0, 0, 0, 0, 0, 0, 0, 0};
        sum = rs;
        sum.triangles += e1s.triangles;
        sum.culled_outside += e1s.culled_outside;
        sum.culled_backface += e1s.culled_backface;
        if (chk != FXL_OK ? !fzp_stats_equal(&sa, &zero) : !fzp_stats_equal(&sa, &sum))
            FZ_FAIL("fxl_mesh_draw stats: %u triangles, %u pixels; emit + indexed: %u, %u", (unsigned)sa.triangles,
                    (unsigned)sa.pixels, (unsigned)sum.triangles, (unsigned)sum.pixels);
    }

    /* P6, then P7 (which redraws the buffers) */
    if (fzp_parts(pc, &p, &xf, xf_ok, msg))
        return 1;
    return chk == FXL_OK ? fzp_alone(ps, pc, &rec1, out, msg) : 0;
}

/* ---- printing ---------------------------------------------------------------------- */

static void fzp_print_vec(FILE *f, const char *name, const fxl_vec3_t *v)
{
    fprintf(f, " %s (%ld, %ld, %ld)", name, (long)v->x, (long)v->y, (long)v->z);
}

static void fz_pipe_print(FILE *f, const fz_pcase *pc)
{
    static const char *const ops[] = {"rotate_x", "rotate_y", "rotate_z", "rotate_axis", "translate", "scale",
                                      "look_at", "raw", "identity"};
    uint32_t i, k;
    fz_print_settings(f, &pc->c);
    fprintf(f, "  pipeline init %dx%d", pc->init_w, pc->init_h);
    if (pc->has_persp)
        fprintf(f, ", perspective fovy %u aspect %d near %d far %d", (unsigned)pc->fovy, pc->aspect, pc->near_q16,
                pc->far_q16);
    if (pc->has_vp)
        fprintf(f, ", viewport (%d, %d) %dx%d", pc->vp[0], pc->vp[1], pc->vp[2], pc->vp[3]);
    fprintf(f, "\n");
    for (k = 0; k < 2; k++)
        for (i = 0; i < (k ? pc->n_view : pc->n_model); i++) {
            const fzp_op *op = k ? &pc->view[i] : &pc->model[i];
            int r, q;
            fprintf(f, "  %s *= %s angle %u", k ? "view" : "model", ops[op->kind], (unsigned)op->angle);
            fzp_print_vec(f, "a", &op->a);
            fzp_print_vec(f, "b", &op->b);
            fzp_print_vec(f, "c", &op->c);
            if (op->kind == FZP_RAW)
                for (r = 0; r < 4; r++)
                    for (q = 0; q < 4; q++)
                        fprintf(f, "%s%ld", r + q ? " " : " raw ", (long)op->raw.m[r][q]);
            fprintf(f, "\n");
        }
    for (i = 0; i < pc->n_poke; i++)
        fprintf(f, "  poke what %u rc %u value %ld\n", pc->poke[i].what, pc->poke[i].rc, (long)pc->poke[i].value);
    fprintf(f, "  cull %u lighting %u material %04X light", pc->cull, pc->lighting, pc->material);
    fzp_print_vec(f, "dir", &pc->light.dir);
    fprintf(f, " ambient %u %u %u diffuse %u %u %u\n", pc->light.ambient[0], pc->light.ambient[1],
            pc->light.ambient[2], pc->light.diffuse[0], pc->light.diffuse[1], pc->light.diffuse[2]);
    fprintf(f, "  texgen mode %u space %u plane %u axis %u scale %ld %ld offset %ld %ld; cache mode %u count %u fill %02X\n",
            pc->texgen.mode, pc->texgen.space, pc->texgen.plane, pc->texgen.axis, (long)pc->texgen.scale_u,
            (long)pc->texgen.scale_v, (long)pc->texgen.offset_u, (long)pc->texgen.offset_v, pc->cache_mode,
            (unsigned)pc->cache_count, pc->cache_fill);
    fprintf(f, "  mesh vert_count %lu (pool %u)%s%s%s%s%s, %u triangles:", (unsigned long)pc->vert_count,
            (unsigned)pc->npool, pc->has_uv ? " uv" : "", pc->has_color ? " colour" : "",
            pc->has_normal ? " normals" : "", pc->pos_null ? " pos NULL" : "", pc->idx_null ? " idx NULL" : "",
            (unsigned)pc->tri_count);
    for (i = 0; i < 3u * pc->tri_count; i++)
        fprintf(f, "%s%u", i % 3u ? "," : " ", pc->idx[i]);
    fprintf(f, "\n");
    for (i = 0; i < pc->npool; i++) {
        fprintf(f, "  p%u", (unsigned)i);
        fzp_print_vec(f, "pos", &pc->pos[i]);
        if (pc->has_uv)
            fprintf(f, " uv (%ld, %ld)", (long)pc->uv[i].u, (long)pc->uv[i].v);
        if (pc->has_color)
            fprintf(f, " colour %04X", pc->color[i]);
        if (pc->has_normal)
            fzp_print_vec(f, "normal", &pc->normal[i]);
        fprintf(f, "  /* %.4f %.4f %.4f */\n", pc->pos[i].x / 65536.0, pc->pos[i].y / 65536.0,
                pc->pos[i].z / 65536.0);
    }
    fprintf(f, "  run: arrays %s, split %u, stop after %u, bad tail %u, reverse %u, stats %s\n",
            pc->at_start ? "at start" : "at end", pc->split, pc->stop_at, pc->bad_tail, pc->reverse,
            pc->stats_null ? "NULL" : "kept");
}

/* ---- either kind of input ------------------------------------------------------------ */

/* Decode (fitted to the build) and run any input as fixel-fuzz and the
 * libFuzzer target do. Returns 1 for a finding (message in msg). The
 * decoded case goes to f (if not NULL) after the run, on a finding only
 * unless always. */
static inline int fz_input_run(fz_pstate *ps, const uint8_t *data, size_t n, fz_outcome *o, char *msg, FILE *f,
                               int always)
{
    int bad;
    if (fz_input_is_pipe(data, n)) {
        fz_pcase pc;
        fz_pipe_prepare(data, n, &pc);
        bad = fz_pipe_run(ps, &pc, o, msg);
        if (f && (bad || always))
            fz_pipe_print(f, &pc);
    } else {
        fz_case c;
        fz_prepare(data, n, &c);
        bad = fz_run_case(ps->s, &c, o, msg);
        if (f && (bad || always))
            fz_print_case(f, &c);
    }
    return bad;
}

#endif
