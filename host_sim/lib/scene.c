/* scene.c - see scene.h. */
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crc32.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define DEG (M_PI / 180.0)

/* A view-space vertex with its texture coordinates. */
typedef struct vtx_d {
    double x, y, z, u, v;
} vtx_d;

typedef struct builder {
    fxl_vertex_t *verts;
    uint32_t tri_count, tri_cap;
    double f, aspect, near, w_px, h_px;
    double guard;             /* guard band: |ndc_x|, |ndc_y| <= guard */
    int error;                /* first SCENE_ERR_*, sticky */
    uint32_t culled, clipped, guard_clipped;
} builder_t;

static const char *const scene_names[] = {"floor",  "floor_tess", "floor_rolled", "cube",
                                          "fan",    "tunnel",     "quad_near",    "small_tris"};
#define SCENE_N (sizeof(scene_names) / sizeof(scene_names[0]))

size_t scene_count(void)
{
    return SCENE_N;
}

const char *scene_name(size_t i)
{
    return i < SCENE_N ? scene_names[i] : NULL;
}

const char *scene_strerror(int code)
{
    switch (code) {
    case SCENE_OK:
        return "ok";
    case SCENE_ERR_NAME:
        return "unknown scene name";
    case SCENE_ERR_SIZE:
        return "target size outside 1..4096";
    case SCENE_ERR_NOMEM:
        return "out of memory";
    case SCENE_ERR_RANGE:
        return "projected coordinate does not fit q16";
    default:
        return "unknown error";
    }
}

/* ---- projection and emission ---------------------------------------------- */

/* Largest magnitude we store as q16: keeps lround(x * 65536) inside int32. */
#define Q16_LIMIT 32767.0

static int to_q16(double x, fxl_q16_t *out)
{
    if (!(x > -Q16_LIMIT && x < Q16_LIMIT)) { /* also rejects NaN */
        return -1;
    }
    *out = (fxl_q16_t)lround(x * 65536.0);
    return 0;
}

static int project(builder_t *b, const vtx_d *p, fxl_vertex_t *o, double *sx, double *sy)
{
    double w = -p->z;
    double ndc_x = p->x * b->f / (b->aspect * w);
    double ndc_y = p->y * b->f / w;
    double inv = b->near / w * 4294967295.0;
    *sx = (ndc_x * 0.5 + 0.5) * b->w_px;
    *sy = (0.5 - ndc_y * 0.5) * b->h_px;
    memset(o, 0, sizeof(*o));
    if (to_q16(*sx, &o->x) || to_q16(*sy, &o->y) || to_q16(p->u, &o->u) || to_q16(p->v, &o->v)) {
        return -1;
    }
    /* w >= near after clipping, so inv <= 2^32 - 1 up to rounding; clamp. */
    inv = floor(inv + 0.5);
    if (inv < 1.0) {
        inv = 1.0;
    }
    if (inv > 4294967295.0) {
        inv = 4294967295.0;
    }
    o->inv_w = (uint32_t)inv;
    o->color = 0xFFFFu;
    return 0;
}

static int push_tri(builder_t *b, const fxl_vertex_t *a, const fxl_vertex_t *c,
                    const fxl_vertex_t *d)
{
    if (b->tri_count == b->tri_cap) {
        uint32_t cap = b->tri_cap ? b->tri_cap * 2u : 64u;
        fxl_vertex_t *n = (fxl_vertex_t *)realloc(b->verts, (size_t)cap * 3u * sizeof(*n));
        if (n == NULL) {
            b->error = SCENE_ERR_NOMEM;
            return -1;
        }
        b->verts = n;
        b->tri_cap = cap;
    }
    b->verts[3u * b->tri_count] = *a;
    b->verts[3u * b->tri_count + 1u] = *c;
    b->verts[3u * b->tri_count + 2u] = *d;
    b->tri_count++;
    return 0;
}

/* Clip planes: 0 is the near plane w >= near; 1..4 are the guard band
 * |ndc_x| <= g, |ndc_y| <= g, chosen in scene_build so that projected
 * coordinates stay inside q16 (at 320 x 240 no scene reaches it). */
static double plane_dist(const builder_t *b, int plane, const vtx_d *p)
{
    double w = -p->z;
    switch (plane) {
    case 0:
        return w - b->near;
    case 1:
        return b->guard * w - p->x * b->f / b->aspect;
    case 2:
        return b->guard * w + p->x * b->f / b->aspect;
    case 3:
        return b->guard * w - p->y * b->f;
    default:
        return b->guard * w + p->y * b->f;
    }
}

/* The point where edge (in, out) crosses a plane, interpolated from the
 * inside end so both polygons sharing the edge compute identical bits. */
static vtx_d clip_point(const builder_t *b, int plane, const vtx_d *in, const vtx_d *out)
{
    double d_in = plane_dist(b, plane, in), d_out = plane_dist(b, plane, out);
    double t = d_in / (d_in - d_out);
    vtx_d r;
    r.x = in->x + t * (out->x - in->x);
    r.y = in->y + t * (out->y - in->y);
    r.z = in->z + t * (out->z - in->z);
    r.u = in->u + t * (out->u - in->u);
    r.v = in->v + t * (out->v - in->v);
    if (plane == 0) {
        r.z = -b->near; /* exactly on the plane: inv_w is exactly 1.0 there */
    }
    return r;
}

#define POLY_MAX 16

/* Sutherland-Hodgman against one plane; returns the new vertex count. */
static int clip_poly(const builder_t *b, int plane, const vtx_d *in, int n, vtx_d *out, int *cut)
{
    int i, m = 0;
    for (i = 0; i < n; i++) {
        const vtx_d *cur = &in[i], *nxt = &in[(i + 1) % n];
        int cur_in = plane_dist(b, plane, cur) >= 0.0, nxt_in = plane_dist(b, plane, nxt) >= 0.0;
        if (cur_in) {
            out[m++] = *cur;
        } else {
            *cut = 1;
        }
        if (cur_in && !nxt_in) {
            out[m++] = clip_point(b, plane, cur, nxt);
        } else if (!cur_in && nxt_in) {
            out[m++] = clip_point(b, plane, nxt, cur);
        }
    }
    return m;
}

/* Clip a convex polygon to the near plane and the guard band, project,
 * optionally cull back faces (front = counter-clockwise seen from outside in
 * a y-up view, which is negative shoelace area in y-down screen space), and
 * emit it as a triangle fan. */
static void emit_poly(builder_t *b, const vtx_d *in, int n, int cull)
{
    vtx_d poly[POLY_MAX], tmp[POLY_MAX];
    fxl_vertex_t pv[POLY_MAX];
    double sx[POLY_MAX], sy[POLY_MAX], area = 0.0;
    int m, i, plane, cut = 0;
    if (b->error || n < 3 || n > POLY_MAX - 5) {
        return;
    }
    memcpy(poly, in, (size_t)n * sizeof(vtx_d));
    m = n;
    /* Each plane adds at most one vertex to a convex polygon: n + 5 <= POLY_MAX. */
    for (plane = 0; plane < 5 && m >= 3; plane++) {
        int cut_here = 0;
        m = clip_poly(b, plane, poly, m, tmp, &cut_here);
        memcpy(poly, tmp, (size_t)m * sizeof(vtx_d));
        if (plane == 0) {
            cut = cut_here;
        } else {
            b->guard_clipped += (uint32_t)cut_here;
        }
    }
    b->clipped += (uint32_t)cut;
    if (m < 3) {
        return;
    }
    for (i = 0; i < m; i++) {
        if (project(b, &poly[i], &pv[i], &sx[i], &sy[i]) != 0) {
            b->error = SCENE_ERR_RANGE;
            return;
        }
    }
    if (cull) {
        for (i = 0; i < m; i++) {
            int j = (i + 1) % m;
            area += sx[i] * sy[j] - sx[j] * sy[i];
        }
        if (area >= 0.0) {
            b->culled++;
            return;
        }
    }
    for (i = 1; i + 1 < m; i++) {
        if (push_tri(b, &pv[0], &pv[i], &pv[i + 1]) != 0) {
            return;
        }
    }
}

static void emit_tri(builder_t *b, vtx_d a, vtx_d c, vtx_d d)
{
    vtx_d t[3];
    t[0] = a;
    t[1] = c;
    t[2] = d;
    emit_poly(b, t, 3, 0);
}

static vtx_d vd(double x, double y, double z, double u, double v)
{
    vtx_d r;
    r.x = x;
    r.y = y;
    r.z = z;
    r.u = u;
    r.v = v;
    return r;
}

/* Deterministic xorshift32 so scenes are identical on every build. */
static double rnd01(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *s = x;
    return (double)(x >> 8) / 16777216.0;
}

/* ---- scenes --------------------------------------------------------------- */

static void scene_floor(builder_t *b, double roll_deg, int nx, int nz)
{
    const double y = -0.577, x0 = -40.0, x1 = 40.0, z0 = -1.0, z1 = -50.0;
    double c = cos(roll_deg * DEG), s = sin(roll_deg * DEG);
    int i, j, k;
    for (j = 0; j < nz; j++) {
        for (i = 0; i < nx; i++) {
            vtx_d q[4];
            double xa = x0 + (x1 - x0) * i / nx, xb = x0 + (x1 - x0) * (i + 1) / nx;
            double za = z0 + (z1 - z0) * j / nz, zb = z0 + (z1 - z0) * (j + 1) / nz;
            q[0] = vd(xa, y, za, xa / 2.0, -za / 2.0);
            q[1] = vd(xb, y, za, xb / 2.0, -za / 2.0);
            q[2] = vd(xb, y, zb, xb / 2.0, -zb / 2.0);
            q[3] = vd(xa, y, zb, xa / 2.0, -zb / 2.0);
            for (k = 0; k < 4; k++) { /* roll about the view (z) axis */
                double px = q[k].x, py = q[k].y;
                q[k].x = px * c - py * s;
                q[k].y = px * s + py * c;
            }
            emit_poly(b, q, 4, 0);
        }
    }
}

static vtx_d rot_xy(vtx_d p, double ax_deg, double ay_deg)
{
    double cx = cos(ax_deg * DEG), sx = sin(ax_deg * DEG);
    double cy = cos(ay_deg * DEG), sy = sin(ay_deg * DEG);
    double y = p.y * cx - p.z * sx, z = p.y * sx + p.z * cx; /* about x */
    double x = p.x * cy + z * sy;                            /* then about y */
    z = -p.x * sy + z * cy;
    p.x = x;
    p.y = y;
    p.z = z;
    return p;
}

static void scene_cube(builder_t *b)
{
    /* Per face: outward normal n, right r, up t with r x t = n, so the
     * corners BL, BR, TR, TL run counter-clockwise seen from outside. */
    static const double f[6][3][3] = {
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}};
    static const double corner[4][4] = {/* s_r, s_t, u, v */
                                        {-1, -1, 0, 1}, {1, -1, 1, 1}, {1, 1, 1, 0}, {-1, 1, 0, 0}};
    int i, k, a;
    for (i = 0; i < 6; i++) {
        vtx_d q[4];
        for (k = 0; k < 4; k++) {
            double p[3];
            for (a = 0; a < 3; a++) {
                p[a] = f[i][0][a] + corner[k][0] * f[i][1][a] + corner[k][1] * f[i][2][a];
            }
            q[k] = rot_xy(vd(p[0], p[1], p[2], corner[k][2], corner[k][3]), 30.0, 30.0);
            q[k].z -= 5.0;
        }
        emit_poly(b, q, 4, 1);
    }
}

/* A point of the fan scene's plane: (a, b) tilted 35 degrees about x. */
static vtx_d fan_plane(double a, double bb)
{
    const double tilt = 35.0 * DEG, dist = 2.6;
    return vd(a, bb * cos(tilt), bb * sin(tilt) - dist, a * 0.8 + 0.5, 0.5 - bb * 0.8);
}

static void scene_fan(builder_t *b)
{
    enum { FAN = 24, G = 16 };
    vtx_d centre = fan_plane(-0.85, 0.02), rim[FAN + 1];
    vtx_d grid[G + 1][G + 1];
    uint32_t seed = 0x2545F491u;
    int k, i, j;
    for (k = 0; k < FAN; k++) {
        double ang = 2.0 * M_PI * k / FAN + 0.13;
        double r = 0.62 * (1.0 + 0.12 * sin(3.0 * k + 1.0));
        rim[k] = fan_plane(-0.85 + r * cos(ang), 0.02 + r * sin(ang));
    }
    rim[FAN] = rim[0]; /* closes the fan with the very same vertex */
    for (k = 0; k < FAN; k++) {
        emit_tri(b, centre, rim[k], rim[k + 1]);
    }
    /* Grid on a [0.05, 1.25] x [-0.85, 0.85] patch; inner vertices jittered by
     * up to 0.3 cell so the edges take many directions. Each vertex is made
     * once and reused by every triangle that shares it. */
    for (j = 0; j <= G; j++) {
        for (i = 0; i <= G; i++) {
            double a = 0.05 + 1.2 * i / G, c = -0.85 + 1.7 * j / G;
            if (i > 0 && i < G && j > 0 && j < G) {
                a += (rnd01(&seed) - 0.5) * 0.6 * 1.2 / G;
                c += (rnd01(&seed) - 0.5) * 0.6 * 1.7 / G;
            }
            grid[j][i] = fan_plane(a, c);
        }
    }
    for (j = 0; j < G; j++) {
        for (i = 0; i < G; i++) {
            vtx_d p00 = grid[j][i], p10 = grid[j][i + 1], p01 = grid[j + 1][i],
                  p11 = grid[j + 1][i + 1];
            if ((i + j) & 1) {
                emit_tri(b, p00, p10, p11);
                emit_tri(b, p00, p11, p01);
            } else {
                emit_tri(b, p00, p10, p01);
                emit_tri(b, p10, p11, p01);
            }
        }
    }
}

static void scene_tunnel(builder_t *b)
{
    enum { AROUND = 24, ALONG = 40 };
    const double ex = 0.25, ey = 0.15; /* eye offset from the axis */
    const double turns = 4.0, vscale = 4.0 / (2.0 * M_PI);
    int i, j;
    for (j = 0; j < ALONG; j++) {
        double za = -(double)j, zb = -(double)(j + 1);
        for (i = 0; i < AROUND; i++) {
            double a0 = 2.0 * M_PI * i / AROUND, a1 = 2.0 * M_PI * (i + 1) / AROUND;
            double u0 = turns * i / AROUND, u1 = turns * (i + 1) / AROUND;
            vtx_d q[4];
            q[0] = vd(cos(a0) - ex, sin(a0) - ey, za, u0, -za * vscale);
            q[1] = vd(cos(a1) - ex, sin(a1) - ey, za, u1, -za * vscale);
            q[2] = vd(cos(a1) - ex, sin(a1) - ey, zb, u1, -zb * vscale);
            q[3] = vd(cos(a0) - ex, sin(a0) - ey, zb, u0, -zb * vscale);
            emit_poly(b, q, 4, 0);
        }
    }
}

static void scene_quad_near(builder_t *b)
{
    /* 8 x 8 quad, centre z = -2, turned 20 degrees about y: depth runs from
     * w = 0.63 to 3.37 and the far side still reaches beyond the frustum
     * (half-width 3.76 > 3.37 * tan 30 * 4/3 = 2.59; half-height 4 > 1.95). */
    static const double c[4][2] = {{-4, -4}, {4, -4}, {4, 4}, {-4, 4}};
    vtx_d q[4];
    int k;
    for (k = 0; k < 4; k++) {
        q[k] = rot_xy(vd(c[k][0], c[k][1], 0.0, (c[k][0] + 4.0) / 2.0, (4.0 - c[k][1]) / 2.0),
                      0.0, 20.0);
        q[k].z -= 2.0;
    }
    emit_poly(b, q, 4, 0);
}

static void scene_small_tris(builder_t *b)
{
    enum { COLS = 50, ROWS = 40 };
    /* Equilateral, circumradius r: area = 3 sqrt(3) / 4 r^2 = 20 px^2 at
     * r = 3.924 px of a 240-row frame. One pixel at depth w spans
     * 2 w / (f * 240) view units vertically. */
    const double r_px = sqrt(20.0 * 4.0 / (3.0 * sqrt(3.0)));
    uint32_t seed = 0x9E3779B9u;
    int i, j, k;
    for (j = 0; j < ROWS; j++) {
        for (i = 0; i < COLS; i++) {
            double ndc_x = -1.0 + 2.0 * (i + 0.5) / COLS, ndc_y = 1.0 - 2.0 * (j + 0.5) / ROWS;
            double w = 2.0 + rnd01(&seed);
            double cx = ndc_x * w * b->aspect / b->f, cy = ndc_y * w / b->f;
            double r = r_px * 2.0 * w / (b->f * 240.0);
            double phi = 2.0 * M_PI * rnd01(&seed);
            double u0 = rnd01(&seed), v0 = rnd01(&seed);
            vtx_d t[3];
            for (k = 0; k < 3; k++) {
                double a = phi + 2.0 * M_PI * k / 3.0;
                t[k] = vd(cx + r * cos(a), cy + r * sin(a), -w + 0.05 * (rnd01(&seed) - 0.5),
                          u0 + 0.06 * cos(a), v0 + 0.06 * sin(a));
            }
            emit_poly(b, t, 3, 0);
        }
    }
}

int scene_build(const char *name, int32_t width, int32_t height, scene_t *out)
{
    builder_t b;
    size_t i;
    const char *static_name = NULL;
    if (out == NULL) {
        return SCENE_ERR_NAME;
    }
    memset(out, 0, sizeof(*out));
    if (name == NULL) {
        return SCENE_ERR_NAME;
    }
    for (i = 0; i < SCENE_N; i++) {
        if (strcmp(name, scene_names[i]) == 0) {
            static_name = scene_names[i];
        }
    }
    if (static_name == NULL) {
        return SCENE_ERR_NAME;
    }
    if (width < 1 || height < 1 || width > FXL_TARGET_MAX_DIM || height > FXL_TARGET_MAX_DIM) {
        return SCENE_ERR_SIZE;
    }
    memset(&b, 0, sizeof(b));
    b.f = 1.0 / tan(SCENE_FOV_Y_DEG * DEG / 2.0);
    b.aspect = (double)width / (double)height;
    b.near = SCENE_NEAR;
    b.w_px = width;
    b.h_px = height;
    /* Largest |ndc| whose screen coordinate stays within +-30000 px (q16
     * holds +-32768): (g * 0.5 + 0.5) * size <= 30000. */
    b.guard = 2.0 * 30000.0 / (double)(width > height ? width : height) - 1.0;
    out->texture = TEXTURE_CHECKER;
    if (strcmp(name, "floor") == 0) {
        scene_floor(&b, 0.0, 1, 1);
    } else if (strcmp(name, "floor_tess") == 0) {
        scene_floor(&b, 0.0, 16, 32);
    } else if (strcmp(name, "floor_rolled") == 0) {
        scene_floor(&b, 40.0, 1, 1);
    } else if (strcmp(name, "cube") == 0) {
        scene_cube(&b);
        out->texture = TEXTURE_CRATE;
    } else if (strcmp(name, "fan") == 0) {
        scene_fan(&b);
        out->texture = TEXTURE_GRID;
    } else if (strcmp(name, "tunnel") == 0) {
        scene_tunnel(&b);
        out->texture = TEXTURE_GRID;
    } else if (strcmp(name, "quad_near") == 0) {
        scene_quad_near(&b);
        out->texture = TEXTURE_CRATE;
    } else {
        scene_small_tris(&b);
        out->texture = TEXTURE_GRID;
    }
    if (b.error) {
        free(b.verts);
        memset(out, 0, sizeof(*out));
        return b.error;
    }
    out->name = static_name;
    out->width = width;
    out->height = height;
    out->verts = b.verts;
    out->tri_count = b.tri_count;
    out->fov_y_deg = SCENE_FOV_Y_DEG;
    out->near = SCENE_NEAR;
    out->culled_backface = b.culled;
    out->clipped = b.clipped;
    out->guard_clipped = b.guard_clipped;
    return SCENE_OK;
}

void scene_free(scene_t *s)
{
    if (s != NULL) {
        free(s->verts);
        memset(s, 0, sizeof(*s));
    }
}

/* ---- drawing -------------------------------------------------------------- */

int frame_alloc(frame_t *f, int32_t width, int32_t height, fxl_pixfmt_t format, int with_depth)
{
    size_t n;
    fxl_status_t st;
    if (f == NULL) {
        return FXL_ERR_ARG;
    }
    memset(f, 0, sizeof(*f));
    if (width < 1 || height < 1 || width > FXL_TARGET_MAX_DIM || height > FXL_TARGET_MAX_DIM) {
        return FXL_ERR_ARG;
    }
    n = (size_t)width * (size_t)height;
    f->pixels = (uint16_t *)calloc(n, sizeof(uint16_t));
    f->depth = with_depth ? (uint16_t *)calloc(n, sizeof(uint16_t)) : NULL;
    st = (f->pixels == NULL || (with_depth && f->depth == NULL)) ? FXL_ERR_NOMEM : FXL_OK;
    if (st == FXL_OK) {
        st = fxl_target_init(&f->target, f->pixels, width, height, width, format);
    }
    if (st == FXL_OK && with_depth) {
        st = fxl_target_set_depth(&f->target, f->depth);
    }
    if (st != FXL_OK) {
        frame_free(f);
    }
    return st;
}

void frame_to_native(frame_t *f)
{
    if (f != NULL && f->pixels != NULL) {
        pixels_to_native(f->pixels, (size_t)f->target.width * (size_t)f->target.height, f->target.format);
        f->target.format = FXL_PIXFMT_RGB565;
    }
}

void frame_free(frame_t *f)
{
    if (f != NULL) {
        free(f->pixels);
        free(f->depth);
        memset(f, 0, sizeof(*f));
    }
}

void scene_clear(fxl_target_t *t, int32_t frame_height)
{
    /* Sky: light blue-grey at the top to dark blue-grey at the bottom row. */
    const int32_t top[3] = {96, 128, 176}, bot[3] = {28, 32, 44};
    int32_t x, y, den = frame_height > 1 ? frame_height - 1 : 1;
    if (t == NULL || t->pixels == NULL) {
        return;
    }
    for (y = t->clip.y0; y < t->clip.y1; y++) {
        int32_t fy = y < 0 ? 0 : (y > den ? den : y);
        uint16_t c = FXL_RGB565(top[0] + (bot[0] - top[0]) * fy / den,
                                top[1] + (bot[1] - top[1]) * fy / den,
                                top[2] + (bot[2] - top[2]) * fy / den);
        uint16_t *row = t->pixels + (size_t)(y - t->origin_y) * (size_t)t->stride;
        if (t->format == FXL_PIXFMT_RGB565_SWAP) {
            c = (uint16_t)((c >> 8) | (c << 8));
        }
        for (x = t->clip.x0; x < t->clip.x1; x++) {
            row[x - t->origin_x] = c;
        }
    }
    if (t->depth != NULL) {
        (void)fxl_target_clear_depth(t);
    }
}

fxl_status_t scene_render(const scene_t *s, const fxl_texture_t *tex, const fxl_draw_t *draw,
                          fxl_target_t *t, fxl_stats_t *stats)
{
    fxl_draw_t d;
    uint32_t i;
    if (s == NULL || draw == NULL || t == NULL) {
        return FXL_ERR_ARG;
    }
    d = *draw;
    d.texture = tex;
    scene_clear(t, s->height);
    for (i = 0; i < s->tri_count; i++) {
        fxl_status_t st = fxl_draw_triangle(t, &d, &s->verts[3u * i], stats);
        if (st != FXL_OK) {
            return st;
        }
    }
    return FXL_OK;
}

void scene_clear_flat(fxl_target_t *t, uint16_t rgb565)
{
    int32_t x, y;
    uint16_t c = rgb565;
    if (t == NULL || t->pixels == NULL) {
        return;
    }
    if (t->format == FXL_PIXFMT_RGB565_SWAP) {
        c = (uint16_t)((c >> 8) | (c << 8));
    }
    for (y = t->clip.y0; y < t->clip.y1; y++) {
        uint16_t *row = t->pixels + (size_t)(y - t->origin_y) * (size_t)t->stride;
        for (x = t->clip.x0; x < t->clip.x1; x++) {
            row[x - t->origin_x] = c;
        }
    }
    if (t->depth != NULL) {
        (void)fxl_target_clear_depth(t);
    }
}

static void put_px(fxl_target_t *t, int32_t x, int32_t y, uint16_t c)
{
    if (x < t->clip.x0 || x >= t->clip.x1 || y < t->clip.y0 || y >= t->clip.y1) {
        return;
    }
    if (t->format == FXL_PIXFMT_RGB565_SWAP) {
        c = (uint16_t)((c >> 8) | (c << 8));
    }
    t->pixels[(size_t)(y - t->origin_y) * (size_t)t->stride + (size_t)(x - t->origin_x)] = c;
}

static void text_pass(fxl_target_t *t, int32_t x, int32_t y, int32_t scale, const char *text,
                      uint16_t c)
{
    int32_t gx, gy, i, j;
    for (; *text != '\0'; text++, x += 4 * scale) {
        const uint8_t *g = texture_font_glyph(*text);
        for (gy = 0; gy < 5; gy++) {
            for (gx = 0; gx < 3; gx++) {
                if (!(g[gy] & (4u >> gx))) {
                    continue;
                }
                for (j = 0; j < scale; j++) {
                    for (i = 0; i < scale; i++) {
                        put_px(t, x + gx * scale + i, y + gy * scale + j, c);
                    }
                }
            }
        }
    }
}

void scene_draw_text(fxl_target_t *t, int32_t x, int32_t y, int32_t scale, const char *text,
                     uint16_t fg, uint16_t shadow)
{
    if (t == NULL || t->pixels == NULL || text == NULL || scale < 1) {
        return;
    }
    text_pass(t, x + scale, y + scale, scale, text, shadow);
    text_pass(t, x, y, scale, text, fg);
}

/* ---- any scene ------------------------------------------------------------ */

int anyscene_exists(const char *name)
{
    size_t i;
    if (name == NULL) {
        return 0;
    }
    for (i = 0; i < SCENE_N; i++) {
        if (strcmp(name, scene_names[i]) == 0) {
            return 1;
        }
    }
    return pscene_exists(name);
}

int anyscene_build(anyscene_t *a, const char *name, int32_t width, int32_t height, int texture,
                   fxl_angle_t spin)
{
    int rc;
    if (a == NULL) {
        return SCENE_ERR_NAME;
    }
    memset(a, 0, sizeof(*a));
    if (pscene_exists(name)) {
        rc = pscene_build(name, width, height, spin, &a->p);
        if (rc != SCENE_OK) {
            return rc;
        }
        a->is_pipe = 1;
        a->name = a->p.name;
        return SCENE_OK;
    }
    rc = scene_build(name, width, height, &a->s);
    if (rc != SCENE_OK) {
        return rc;
    }
    if (texture_make(&a->tex, texture >= 0 ? (texture_id_t)texture : a->s.texture) != 0) {
        scene_free(&a->s);
        return SCENE_ERR_NOMEM;
    }
    a->name = a->s.name;
    return SCENE_OK;
}

void anyscene_free(anyscene_t *a)
{
    if (a != NULL) {
        scene_free(&a->s);
        texture_free(&a->tex);
        pscene_free(&a->p);
        memset(a, 0, sizeof(*a));
    }
}

fxl_status_t anyscene_draw(anyscene_t *a, const fxl_draw_t *d, fxl_target_t *t,
                           fxl_stats_t *stats)
{
    fxl_draw_t dd;
    uint32_t i;
    if (a == NULL || d == NULL || t == NULL) {
        return FXL_ERR_ARG;
    }
    if (a->is_pipe) {
        return pscene_draw(&a->p, d, t, stats);
    }
    dd = *d;
    dd.texture = &a->tex.tex;
    for (i = 0; i < a->s.tri_count; i++) {
        fxl_status_t st = fxl_draw_triangle(t, &dd, &a->s.verts[3u * i], stats);
        if (st != FXL_OK) {
            return st;
        }
    }
    return FXL_OK;
}

fxl_status_t anyscene_render(anyscene_t *a, const fxl_draw_t *d, fxl_target_t *t,
                             fxl_stats_t *stats)
{
    if (a == NULL || d == NULL || t == NULL) {
        return FXL_ERR_ARG;
    }
    scene_clear(t, a->is_pipe ? a->p.height : a->s.height);
    return anyscene_draw(a, d, t, stats);
}

fxl_status_t anyscene_collect(anyscene_t *a, const fxl_draw_t *d,
                              fxl_draw_t draws[PSCENE_MAX_PARTS], fxl_band_tri_t **tris,
                              size_t *count)
{
    uint32_t i;
    if (a == NULL || d == NULL || draws == NULL || tris == NULL || count == NULL) {
        return FXL_ERR_ARG;
    }
    if (a->is_pipe) {
        return pscene_collect(&a->p, d, draws, tris, count);
    }
    draws[0] = *d;
    draws[0].texture = &a->tex.tex;
    *count = 0;
    *tris = (fxl_band_tri_t *)calloc(a->s.tri_count ? a->s.tri_count : 1u, sizeof(**tris));
    if (*tris == NULL) {
        return FXL_ERR_NOMEM;
    }
    for (i = 0; i < a->s.tri_count; i++) {
        memcpy((*tris)[i].v, &a->s.verts[3u * i], 3u * sizeof(fxl_vertex_t));
        (*tris)[i].draw = &draws[0];
    }
    *count = a->s.tri_count;
    return FXL_OK;
}

/* ---- what a draw needs of the build --------------------------------------- */

const char *anyscene_missing_feature(const anyscene_t *a, const fxl_draw_t *d, fxl_pixfmt_t format,
                                     int depth_buffer)
{
    return a->is_pipe ? pscene_missing_feature(&a->p, d, format, depth_buffer)
                      : left_out_feature(d, &a->tex.tex, format, depth_buffer);
}

int anyscene_needs_depth(const char *name)
{
    /* See scene.h for why the others do not. */
    return !anyscene_exists(name) || strcmp(name, "small_tris") == 0 ||
           strcmp(name, "p_cubemap") == 0;
}

/* FXL_HAVE_DEPTH for a scene whose image needs depth in a build without,
 * else anyscene_missing_feature of scene `name` built for the query; NULL
 * when it cannot be built (the render reports that). */
static const char *named_missing_feature(const char *name, int texture, const fxl_draw_t *d,
                                         fxl_pixfmt_t format, int depth_buffer)
{
    anyscene_t a;
    const char *m;
    if (!FXL_HAVE_DEPTH && anyscene_needs_depth(name)) {
        return "FXL_HAVE_DEPTH";
    }
    if (anyscene_build(&a, name, SCENE_DEFAULT_WIDTH, SCENE_DEFAULT_HEIGHT, texture, 0) !=
        SCENE_OK) {
        return NULL;
    }
    m = anyscene_missing_feature(&a, d, format, depth_buffer);
    anyscene_free(&a);
    return m;
}

/* ---- panel ---------------------------------------------------------------- */

const char *panel_scene_missing_feature(const char *scene, const fxl_draw_t *d)
{
    const char *m;
    /* the bands in the emulated HAL's format, and the direct render it is
     * checked against (in the order this build draws), both with depth
     * where the build has it */
    m = named_missing_feature(scene, -1, d, panel_band_format(), FXL_HAVE_DEPTH);
    return m != NULL ? m : named_missing_feature(scene, -1, d, drawable_rgb565(), FXL_HAVE_DEPTH);
}

fxl_status_t panel_scene_render(const char *panel, int rotation, int band_rows,
                                const char *scene, const fxl_draw_t *d, frame_t *panel_img,
                                panel_check_t *chk)
{
    anyscene_t a;
    frame_t direct;
    fxl_draw_t draws[PSCENE_MAX_PARTS];
    fxl_band_tri_t *tris = NULL;
    size_t count = 0, n, k;
    panel_check_t c;
    fxl_status_t st;
    int w, h;
    memset(&c, 0, sizeof(c));
    c.first_diff = -1;
    if (panel_img == NULL || d == NULL) {
        return FXL_ERR_ARG;
    }
    memset(panel_img, 0, sizeof(*panel_img));
    if (panel_emu_frame_size(panel, rotation, &w, &h) != 0) {
        return FXL_ERR_ARG;
    }
    if (anyscene_build(&a, scene, w, h, -1, 0) != SCENE_OK) {
        return FXL_ERR_ARG;
    }
    /* The reference has a depth buffer like the bands, when the build has
     * depth at all; a scene that needs one in a build without is refused
     * here, where the core refuses the buffer (FXL_ERR_UNSUPPORTED). */
    st = (fxl_status_t)frame_alloc(panel_img, w, h, FXL_PIXFMT_RGB565, 0);
    if (st == FXL_OK) {
        st = (fxl_status_t)frame_alloc(&direct, w, h, drawable_rgb565(),
                                       FXL_HAVE_DEPTH || anyscene_needs_depth(scene));
        if (st != FXL_OK) {
            frame_free(panel_img);
        }
    }
    if (st != FXL_OK) {
        anyscene_free(&a);
        return st;
    }
    st = anyscene_collect(&a, d, draws, &tris, &count);
    if (st == FXL_OK) {
        n = (size_t)w * (size_t)h;
        st = panel_emu_render_scene(panel, rotation, band_rows, tris, count, PANEL_CLEAR_RGB565,
                                    panel_img->pixels, n, &c.res);
        /* The reference: the same triangles, the same draw state, one
         * full-frame target cleared like every band. */
        scene_clear_flat(&direct.target, PANEL_CLEAR_RGB565);
        if (st == FXL_OK) {
            st = anyscene_draw(&a, d, &direct.target, NULL);
        }
        frame_to_native(&direct);
        c.panel_crc = fxl_host_crc_target(&panel_img->target);
        c.direct_crc = fxl_host_crc_target(&direct.target);
        for (k = 0; k < n; k++) {
            if (panel_img->pixels[k] != direct.pixels[k]) {
                if (c.first_diff < 0) {
                    c.first_diff = (long)k;
                }
                c.diff_pixels++;
            }
        }
    }
    free(tris);
    frame_free(&direct);
    anyscene_free(&a);
    if (chk != NULL) {
        *chk = c;
    }
    return st;
}

/* ---- gallery -------------------------------------------------------------- */

#define GALLERY_N_SCENE (SCENE_N * 4u)
#define GALLERY_N_PIPE (2u * 6u)

static const gallery_entry_t mips_panels[GALLERY_MIPS_PANELS] = {
    {GALLERY_SCENE, "floor_mips", "floor", TEXTURE_CHECKER_HC, "subdiv16", 16, "point",
     FXL_FILTER_POINT, FXL_MIP_NONE, FXL_LOD_SEGMENT, "POINT, NO MIPS", NULL, 0, 0},
    {GALLERY_SCENE, "floor_mips", "floor", TEXTURE_CHECKER_HC, "subdiv16", 16, "bilinear",
     FXL_FILTER_BILINEAR, FXL_MIP_NONE, FXL_LOD_SEGMENT, "BILINEAR, NO MIPS", NULL, 0, 0},
    {GALLERY_SCENE, "floor_mips", "floor", TEXTURE_CHECKER_HC, "subdiv16", 16, "lod-tri",
     FXL_FILTER_BILINEAR, FXL_MIP_NEAREST, FXL_LOD_TRIANGLE, "PER-TRIANGLE LOD", NULL, 0, 0},
    {GALLERY_SCENE, "floor_mips", "floor", TEXTURE_CHECKER_HC, "subdiv16", 16, "lod-seg",
     FXL_FILTER_BILINEAR, FXL_MIP_NEAREST, FXL_LOD_SEGMENT, "PER-SEGMENT LOD", NULL, 0, 0},
    {GALLERY_SCENE, "floor_mips", "floor", TEXTURE_CHECKER_HC, "subdiv16", 16, "trilinear",
     FXL_FILTER_BILINEAR, FXL_MIP_LINEAR, FXL_LOD_SEGMENT, "TRILINEAR", NULL, 0, 0},
    {GALLERY_SCENE, "floor_mips", "floor", TEXTURE_CHECKER_HC_LEVELS, "subdiv16", 16, "levels",
     FXL_FILTER_POINT, FXL_MIP_NEAREST, FXL_LOD_SEGMENT, "LEVEL PER SEGMENT", NULL, 0, 0}};

size_t gallery_count(void)
{
    return GALLERY_N_SCENE + 1u + GALLERY_N_PIPE + 1u;
}

int gallery_entry(size_t i, gallery_entry_t *e)
{
    if (e == NULL || i >= gallery_count()) {
        return -1;
    }
    memset(e, 0, sizeof(*e));
    e->texture = -1;
    e->persp_name = "subdiv16";
    e->persp = 16;
    e->lod = FXL_LOD_SEGMENT;
    e->mip = FXL_MIP_NONE;
    if (i < GALLERY_N_SCENE) {
        e->kind = GALLERY_SCENE;
        e->scene = e->id = scene_names[i / 4u];
        if ((i / 2u) % 2u != 0) {
            e->persp_name = "affine";
            e->persp = FXL_PERSP_AFFINE;
        }
        e->filter_name = i % 2u == 0 ? "point" : "bilinear";
        e->filter = (uint8_t)(i % 2u == 0 ? FXL_FILTER_POINT : FXL_FILTER_BILINEAR);
        return 0;
    }
    i -= GALLERY_N_SCENE;
    if (i == 0) {
        e->kind = GALLERY_MIPS;
        e->id = "floor_mips";
        e->scene = "floor";
        e->texture = TEXTURE_CHECKER_HC;
        e->filter_name = "compare";
        return 0;
    }
    i -= 1u;
    if (i < GALLERY_N_PIPE) {
        e->kind = GALLERY_PIPE;
        e->scene = e->id = pscene_name(i / 2u);
        if (i % 2u == 0) {
            e->filter_name = "point";
            e->filter = FXL_FILTER_POINT;
        } else {
            e->filter_name = "trilinear";
            e->filter = FXL_FILTER_BILINEAR;
            e->mip = FXL_MIP_LINEAR;
        }
        return 0;
    }
    e->kind = GALLERY_PANEL;
    e->id = "panel_st7789_r1_p_cube";
    e->scene = "p_cube";
    e->filter_name = "bilinear";
    e->filter = FXL_FILTER_BILINEAR;
    e->panel = "st7789";
    e->rotation = 1;
    e->band_rows = 24;
    return 0;
}

void gallery_file_name(const gallery_entry_t *e, char *buf, size_t n)
{
    if (e->kind == GALLERY_SCENE || e->kind == GALLERY_PIPE) {
        snprintf(buf, n, "%s_%s_%s.png", e->id, e->persp_name, e->filter_name);
    } else {
        snprintf(buf, n, "%s.png", e->id);
    }
}

void gallery_draw_settings(const gallery_entry_t *e, fxl_draw_t *d)
{
    fxl_draw_defaults(d);
    d->persp = e->persp;
    d->filter = e->filter;
    d->mip = e->mip;
    d->lod = e->lod;
    d->depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
}

int gallery_mips_panel(size_t i, gallery_entry_t *e)
{
    if (e == NULL || i >= GALLERY_MIPS_PANELS) {
        return -1;
    }
    *e = mips_panels[i];
    return 0;
}

int gallery_mips_compose(const frame_t panels[GALLERY_MIPS_PANELS], frame_t *out)
{
    const int32_t pw = SCENE_DEFAULT_WIDTH, ph = SCENE_DEFAULT_HEIGHT;
    const uint16_t gutter = FXL_RGB565(10, 10, 12);
    int32_t x, y;
    size_t i;
    if (panels == NULL || out == NULL ||
        frame_alloc(out, 3 * pw, 2 * ph, FXL_PIXFMT_RGB565, 0) != 0) {
        return -1;
    }
    for (i = 0; i < GALLERY_MIPS_PANELS; i++) {
        int32_t ox = (int32_t)(i % 3u) * pw, oy = (int32_t)(i / 3u) * ph;
        const fxl_target_t *src = &panels[i].target;
        if (src->width != pw || src->height != ph || src->format != FXL_PIXFMT_RGB565) {
            frame_free(out);
            return -1;
        }
        for (y = 0; y < ph; y++) {
            memcpy(out->pixels + (size_t)(oy + y) * (size_t)(3 * pw) + (size_t)ox,
                   src->pixels + (size_t)y * (size_t)src->stride, (size_t)pw * sizeof(uint16_t));
        }
        scene_draw_text(&out->target, ox + 8, oy + 8, 2, mips_panels[i].label,
                        FXL_RGB565(255, 255, 255), FXL_RGB565(0, 0, 0));
    }
    /* 2-px gutters on the panel boundaries (drawn over the panels' edges). */
    for (y = 0; y < 2 * ph; y++) {
        for (x = 0; x < 3 * pw; x++) {
            int32_t mx = x % pw, my = y % ph;
            if ((mx == 0 && x > 0) || (mx == pw - 1 && x < 3 * pw - 1) || (my == 0 && y > 0) ||
                (my == ph - 1 && y < 2 * ph - 1)) {
                out->pixels[(size_t)y * (size_t)(3 * pw) + (size_t)x] = gutter;
            }
        }
    }
    return 0;
}

const char *gallery_missing_feature(const gallery_entry_t *e)
{
    fxl_draw_t d;
    const char *m = NULL;
    size_t i;
    if (e->kind == GALLERY_MIPS) {
        for (i = 0; i < GALLERY_MIPS_PANELS && m == NULL; i++) {
            m = gallery_missing_feature(&mips_panels[i]);
        }
        return m;
    }
    gallery_draw_settings(e, &d);
    if (e->kind == GALLERY_PANEL) {
        return panel_scene_missing_feature(e->scene, &d);
    }
    /* render_single's frame, with depth where the build has it */
    return named_missing_feature(e->scene, e->texture, &d, drawable_rgb565(), FXL_HAVE_DEPTH);
}

static fxl_status_t render_single(const gallery_entry_t *e, frame_t *out, fxl_stats_t *stats)
{
    anyscene_t a;
    fxl_draw_t d;
    fxl_status_t st;
    memset(out, 0, sizeof(*out));
    if (anyscene_build(&a, e->scene, SCENE_DEFAULT_WIDTH, SCENE_DEFAULT_HEIGHT, e->texture, 0) !=
        SCENE_OK) {
        return FXL_ERR_ARG;
    }
    /* With depth, as the goldens were drawn. A build without FXL_HAVE_DEPTH
     * draws a scene that does not need it without a depth buffer (the same
     * pixels, scene.h); for the others the core refuses the buffer. Drawn
     * in the byte order the build draws, returned native. */
    st = (fxl_status_t)frame_alloc(out, SCENE_DEFAULT_WIDTH, SCENE_DEFAULT_HEIGHT,
                                   drawable_rgb565(),
                                   FXL_HAVE_DEPTH || anyscene_needs_depth(e->scene));
    if (st != FXL_OK) {
        anyscene_free(&a);
        return st;
    }
    gallery_draw_settings(e, &d);
    st = anyscene_render(&a, &d, &out->target, stats);
    frame_to_native(out);
    anyscene_free(&a);
    return st;
}

fxl_status_t gallery_render(const gallery_entry_t *e, frame_t *out, fxl_stats_t *stats,
                            panel_check_t *chk)
{
    if (e == NULL || out == NULL) {
        return FXL_ERR_ARG;
    }
    memset(out, 0, sizeof(*out));
    if (e->kind == GALLERY_MIPS) {
        frame_t p[GALLERY_MIPS_PANELS];
        fxl_status_t st = FXL_OK;
        size_t i;
        memset(p, 0, sizeof(p));
        for (i = 0; i < GALLERY_MIPS_PANELS && st == FXL_OK; i++) {
            st = render_single(&mips_panels[i], &p[i], stats);
        }
        if (st == FXL_OK && gallery_mips_compose(p, out) != 0) {
            st = FXL_ERR_NOMEM;
        }
        for (i = 0; i < GALLERY_MIPS_PANELS; i++) {
            frame_free(&p[i]);
        }
        return st;
    }
    if (e->kind == GALLERY_PANEL) {
        fxl_draw_t d;
        panel_check_t c;
        fxl_status_t st;
        gallery_draw_settings(e, &d);
        st = panel_scene_render(e->panel, e->rotation, e->band_rows, e->scene, &d, out, &c);
        if (stats != NULL) {
            stats->triangles += c.res.stats.triangles;
            stats->drawn += c.res.stats.drawn;
            stats->generic += c.res.stats.generic;
            stats->pixels += c.res.stats.pixels;
        }
        if (chk != NULL) {
            *chk = c;
        }
        return st;
    }
    return render_single(e, out, stats);
}
