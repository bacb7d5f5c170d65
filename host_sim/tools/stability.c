/* stability.c - fixel-stability: where each perspective method fails.
 *
 *   fixel-stability [--out DIR] [--quick]
 *
 * Sweeps every method (affine, subdiv8/16/32, exact, auto) past its breaking
 * point and writes, under DIR (default docs/stability):
 *   <sweep>.csv    one row per parameter value and method (long format)
 *   <sweep>_max.dat  wide table for gnuplot: param, then max error per method
 *   summary.csv    per sweep and method: the first parameter where the max
 *                  texel error exceeds 1/64, 1/8 and 1 texel, and where
 *                  coverage first differs from the exact rule.
 * Sweeps: depth (far w / near w 1..1e4), grazing (plane angle 0..89.9 deg),
 * eyeplane (a vertex with w -> 0+), screen (vertices up to +-1e6 px, and the
 * q16 limits), texcoord (u, v offsets up to 1e5 periods, repeat / mirror /
 * clamp), sliver (aspect 1..1e4, zero-area, collinear), texsize (1x1 ..
 * 1024x1024, non-square) and lod (bias and LOD extremes).
 *
 * Measurement (per pixel): the span loops are replaced by a probe through the
 * core's hook fxl__draw_triangle_with, which records the exact level-0 q16
 * texel coordinates each pixel receives. The truth is the exact perspective
 * mapping of the *intended* triangle in long double (for inputs that fit q16
 * this is the reference renderer's ref_uv_at on the submitted vertices). The
 * error per axis is what the wrap makes visible: distance modulo the period
 * (repeat), through the triangle wave (mirror), after clamping (clamp). The
 * pixel error is the larger axis error, in level-0 texels.
 * Coverage: probe visit counts against ref_coverage_mask of the submitted
 * triangles (must match exactly), and against the intended triangle (pixels
 * that differ because a clipped vertex was snapped are reported apart).
 * Safety: each case is also drawn for real into a target with canary words
 * around pixels and depth. Exit status: 3 at once when a canary is damaged
 * or a probe leaves the target; after all sweeps, 4 when some method's
 * coverage differed from the exact rule or a draw failed (summary.csv's last
 * column says where; the deliberate counter-example variants excepted);
 * 2 on a bad command line or when an output file cannot be written; else 0.
 * Inputs beyond q16 (|x| >= 32768 px) are clipped in double to the guard
 * band +-GUARD px first (Sutherland-Hodgman in screen space; 1/w, u/w, v/w
 * are affine there, so the clipped attributes are exact) - the core itself
 * cannot represent them. The eyeplane and screen sweeps also send the same
 * geometry, in view space, through fixel's own fixed-point front end
 * (variants front_end*: near plane, guard-band clip and projection of
 * fxl_pipeline_emit, then the core), measured against the intended
 * triangle in front of the near plane.
 */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "fixel/fixel.h"
#include "fixel/pipeline.h"
#include "reference.h"
#include "../../src/raster_int.h"

#define TW 256            /* target size of every sweep */
#define TH 256
#define GUARD 30000.0     /* guard band, px (q16 holds +-32768) */
static long double guard = GUARD;
#define CAN 32            /* canary words */
#define MAXPOLY 16
#define PI 3.14159265358979323846

typedef struct dvert {
    long double x, y;     /* screen px */
    long double q;        /* 1/w, relative (nearest vertex of a scene ~ 1) */
    long double u, v;     /* normalised texture coordinates */
} dvert;

typedef struct method {
    const char *name;
    int16_t persp;
} method_t;

static const method_t methods[] = {
    {"affine", FXL_PERSP_AFFINE}, {"subdiv8", 8}, {"subdiv16", 16}, {"subdiv32", 32},
    {"exact", FXL_PERSP_EXACT}, {"auto", FXL_PERSP_AUTO}};
#define NMETH 6

/* ---- per-pixel probe ------------------------------------------------------- */

static uint16_t pix[TW * TH + 2 * CAN];
static uint16_t dep[TW * TH + 2 * CAN];
static uint8_t cnt[TW * TH];
static uint32_t pu[TW * TH], pv[TW * TH];
static int lvl_of[TW * TH];
static const fxl__tri_t *probe_tri;

static uint32_t probe(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    long k0 = (long)(s->dst - (pix + CAN));
    int32_t i;
    probe_tri = tri;
    for (i = 0; i < s->n; i++) {
        long k = k0 + i;
        if (k < 0 || k >= TW * TH) {
            fprintf(stderr, "fixel-stability: probe segment outside the target (offset %ld)\n", k);
            exit(3);
        }
        if (cnt[k] < 255)
            cnt[k]++;
        pu[k] = fxl__seg_coord(s->u, s->du, s->ddu, i);
        pv[k] = fxl__seg_coord(s->v, s->dv, s->ddv, i);
        lvl_of[k] = (int)(s->lvl - &tri->level[0]);
    }
    return (uint32_t)s->n;
}

/* ---- textures (contents do not matter for coordinates; sizes do) ---------- */

static uint16_t *tex_mem;

static void make_tex(fxl_texture_t *t, uint32_t lw, uint32_t lh, fxl_wrap_t wrap, int full_chain)
{
    uint32_t levels = full_chain ? fxl_mip_levels(1u << lw, 1u << lh) : 1u;
    uint32_t bytes = fxl_mip_size(1u << lw, 1u << lh, FXL_TEXFMT_RGB565, levels), i;
    free(tex_mem);
    tex_mem = (uint16_t *)malloc(bytes);
    if (!tex_mem) {
        fprintf(stderr, "fixel-stability: out of memory\n");
        exit(2);
    }
    for (i = 0; i < bytes / 2; i++)
        tex_mem[i] = (uint16_t)(i * 2654435761u >> 16);
    if (fxl_texture_init(t, tex_mem, 1u << lw, 1u << lh, FXL_TEXFMT_RGB565, levels) != FXL_OK) {
        fprintf(stderr, "fixel-stability: texture %ux%u refused\n", 1u << lw, 1u << lh);
        exit(2);
    }
    t->wrap_u = t->wrap_v = (uint8_t)wrap;
}

/* ---- conversion and clipping ------------------------------------------------ */

static int32_t q16_of(long double x)
{
    long double r = roundl(x * 65536.0L);
    if (r > INT32_MAX) return INT32_MAX;
    if (r < INT32_MIN) return INT32_MIN;
    return (int32_t)r;
}

static fxl_vertex_t to_vertex(const dvert *d, long double qscale)
{
    fxl_vertex_t v;
    long double q = roundl(d->q * qscale * 4294967295.0L);
    v.x = q16_of(d->x);
    v.y = q16_of(d->y);
    v.inv_w = q < 1 ? 1u : (q > 4294967295.0L ? UINT32_MAX : (uint32_t)q);
    v.u = q16_of(d->u);
    v.v = q16_of(d->v);
    v.color = 0xFFFF;
    return v;
}

static dvert lerp_dv(const dvert *a, const dvert *b, long double t)
{
    dvert r;
    /* 1/w, u/w, v/w are affine in screen space: interpolate those. */
    long double q = a->q + (b->q - a->q) * t;
    r.x = a->x + (b->x - a->x) * t;
    r.y = a->y + (b->y - a->y) * t;
    r.q = q;
    r.u = (a->u * a->q + (b->u * b->q - a->u * a->q) * t) / q;
    r.v = (a->v * a->q + (b->v * b->q - a->v * a->q) * t) / q;
    return r;
}

/* Clip polygon against x (axis 0) or y (axis 1) <= / >= bound. */
static int clip_poly(const dvert *in, int n, dvert *out, int axis, long double bound, int keep_below)
{
    int i, m = 0;
    for (i = 0; i < n; i++) {
        const dvert *a = &in[i], *b = &in[(i + 1) % n];
        long double ca = axis ? a->y : a->x, cb = axis ? b->y : b->x;
        int ia = keep_below ? ca <= bound : ca >= bound;
        int ib = keep_below ? cb <= bound : cb >= bound;
        if (ia)
            out[m++] = *a;
        if (ia != ib)
            out[m++] = lerp_dv(a, b, (bound - ca) / (cb - ca));
    }
    return m;
}

/* Triangle -> triangles inside the guard band (fan). Returns the count. */
static int guard_clip(const dvert t[3], dvert out[][3], long double g)
{
    dvert a[MAXPOLY], b[MAXPOLY];
    int n = 3, i;
    memcpy(a, t, 3 * sizeof(dvert));
    n = clip_poly(a, n, b, 0, g, 1);
    n = clip_poly(b, n, a, 0, -g, 0);
    n = clip_poly(a, n, b, 1, g, 1);
    n = clip_poly(b, n, a, 1, -g, 0);
    for (i = 0; i + 2 < n; i++) {
        out[i][0] = a[0];
        out[i][1] = a[i + 1];
        out[i][2] = a[i + 2];
    }
    return n >= 3 ? n - 2 : 0;
}

/* ---- truth -------------------------------------------------------------------- */

typedef struct plane3 {
    long double a, b, c;   /* value = a + b x + c y */
} plane3;

typedef struct truth {
    plane3 q, uq, vq;
    long double ex[3], ey[3], ec[3];   /* edge functions, >= 0 inside */
    int valid;
} truth_t;

static plane3 plane_of(const dvert t[3], long double f0, long double f1, long double f2)
{
    long double x1 = t[1].x - t[0].x, y1 = t[1].y - t[0].y, x2 = t[2].x - t[0].x, y2 = t[2].y - t[0].y;
    long double det = x1 * y2 - x2 * y1;
    plane3 p;
    p.b = ((f1 - f0) * y2 - (f2 - f0) * y1) / det;
    p.c = ((f2 - f0) * x1 - (f1 - f0) * x2) / det;
    p.a = f0 - p.b * t[0].x - p.c * t[0].y;
    return p;
}

static void truth_init(truth_t *tr, const dvert t[3])
{
    long double q0 = t[0].q, q1 = t[1].q, q2 = t[2].q;
    long double det = (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y);
    int k;
    tr->valid = det != 0;
    if (!tr->valid)
        return;
    tr->q = plane_of(t, q0, q1, q2);
    tr->uq = plane_of(t, t[0].u * q0, t[1].u * q1, t[2].u * q2);
    tr->vq = plane_of(t, t[0].v * q0, t[1].v * q1, t[2].v * q2);
    for (k = 0; k < 3; k++) {
        const dvert *a = &t[k], *b = &t[(k + 1) % 3];
        long double s = det > 0 ? 1 : -1;
        tr->ex[k] = -(b->y - a->y) * s;
        tr->ey[k] = (b->x - a->x) * s;
        tr->ec[k] = -(tr->ex[k] * a->x + tr->ey[k] * a->y);
    }
}

static void truth_uv(const truth_t *tr, long double x, long double y, long double *u, long double *v)
{
    long double q = tr->q.a + tr->q.b * x + tr->q.c * y;
    *u = (tr->uq.a + tr->uq.b * x + tr->uq.c * y) / q;
    *v = (tr->vq.a + tr->vq.b * x + tr->vq.c * y) / q;
}

static long double truth_q(const truth_t *tr, long double x, long double y)
{
    return tr->q.a + tr->q.b * x + tr->q.c * y;
}

static int truth_inside(const truth_t *tr, long double x, long double y)
{
    int k;
    for (k = 0; k < 3; k++)
        if (tr->ex[k] * x + tr->ey[k] * y + tr->ec[k] < 0)
            return 0;
    return 1;
}

/* ---- error per axis ------------------------------------------------------------ */

static long double axis_err(uint32_t core, int is_signed, long double exact, long double n, fxl_wrap_t wrap)
{
    long double c;
    if (is_signed) {
        int32_t s = core <= INT32_MAX ? (int32_t)core : -(int32_t)(~core) - 1;
        c = (long double)s / 65536.0L;
    } else {
        c = (long double)core / 65536.0L;
    }
    if (wrap == FXL_WRAP_REPEAT) {
        long double d = fmodl(c - exact, n);
        if (d < 0) d += n;
        return d > n / 2 ? n - d : d;
    }
    if (wrap == FXL_WRAP_MIRROR) {
        long double mc = fmodl(c, 2 * n), me = fmodl(exact, 2 * n);
        if (mc < 0) mc += 2 * n;
        if (me < 0) me += 2 * n;
        mc = mc < n ? mc : 2 * n - mc;
        me = me < n ? me : 2 * n - me;
        return fabsl(mc - me);
    }
    /* clamp / border: the visible coordinate */
    c = c < 0 ? 0 : (c > n ? n : c);
    exact = exact < 0 ? 0 : (exact > n ? n : exact);
    return fabsl(c - exact);
}

/* ---- one measurement ------------------------------------------------------------ */

typedef struct result {
    fxl_status_t status;
    long pixels;            /* probe-visited pixels */
    long cov_mismatch;      /* vs the exact rule on the submitted triangles */
    long cov_intended;      /* vs the intended (unclipped, unsnapped) triangle */
    double max_err, p99_err;/* level-0 texels */
    int max_level;          /* largest level a probe segment used */
    int submitted;          /* triangles given to the core */
    int clipped;            /* 1: inputs went through the guard-band clip */
} result_t;

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}

static double *errbuf;
static uint8_t refmask[TW * TH], refcnt[TW * TH];

static void check_canaries(const char *what)
{
    int i;
    for (i = 0; i < CAN; i++)
        if (pix[i] != 0xC0DE || pix[CAN + TW * TH + i] != 0xC0DE || dep[i] != 0xD0DE ||
            dep[CAN + TW * TH + i] != 0xD0DE) {
            fprintf(stderr, "fixel-stability: canary damaged in %s\n", what);
            exit(3);
        }
}

/* Draw the intended triangle t (already in q16 range unless clip != 0) with
 * `draw`; measure against the truth. */
static result_t measure_tris(const fxl_vertex_t fv[][3], int ntri, const dvert t[3], long double q_limit,
                             fxl_draw_t draw, const fxl_texture_t *tex, int clip, const char *what);

static result_t measure(const dvert t[3], fxl_draw_t draw, const fxl_texture_t *tex, int clip, const char *what)
{
    dvert tris[MAXPOLY][3];
    fxl_vertex_t fv[MAXPOLY][3];
    int ntri, k, i;
    long double maxq = 0;
    dvert tt[3];
    int clipped = 0;

    if (clip) {
        /* Vertices that fit q16 would be snapped by the core anyway; put
         * them on the grid so the clipped case shows only what clipping
         * adds (the new vertices on the guard band, snapped by the core). */
        for (i = 0; i < 3; i++) {
            tt[i] = t[i];
            if (fabsl(tt[i].x) < 32767 && fabsl(tt[i].y) < 32767) {
                tt[i].x = (long double)ref_snap(q16_of(tt[i].x)) / (1 << FXL_SUBPIXEL_BITS);
                tt[i].y = (long double)ref_snap(q16_of(tt[i].y)) / (1 << FXL_SUBPIXEL_BITS);
            }
        }
        t = tt;
        if (clip == 2) {
            /* no clipping: coordinates saturated to q16 (what not to do) */
            memcpy(tris[0], t, sizeof tris[0]);
            ntri = 1;
        } else {
            ntri = guard_clip(t, tris, guard);
        }
        clipped = clip;
    } else {
        memcpy(tris[0], t, sizeof tris[0]);
        ntri = 1;
    }
    /* one inv_w scale for all pieces: the largest q maps to UINT32_MAX */
    for (k = 0; k < ntri; k++)
        for (i = 0; i < 3; i++)
            if (tris[k][i].q > maxq)
                maxq = tris[k][i].q;
    for (k = 0; k < ntri; k++)
        for (i = 0; i < 3; i++)
            fv[k][i] = to_vertex(&tris[k][i], 1.0L / maxq);
    if (!clip) {
        /* In range: the intended triangle is exactly what the core was
         * given (snapped position, quantised 1/w, u, v), so the error is the
         * method's alone. The clipped path keeps the caller's triangle. */
        for (i = 0; i < 3; i++) {
            tt[i].x = (long double)ref_snap(fv[0][i].x) / (1 << FXL_SUBPIXEL_BITS);
            tt[i].y = (long double)ref_snap(fv[0][i].y) / (1 << FXL_SUBPIXEL_BITS);
            tt[i].q = (long double)fv[0][i].inv_w;
            tt[i].u = (long double)fv[0][i].u / 65536.0L;
            tt[i].v = (long double)fv[0][i].v / 65536.0L;
        }
        t = tt;
    }
    return measure_tris((const fxl_vertex_t(*)[3])fv, ntri, t, 0, draw, tex, clipped, what);
}

/* Draw the screen-space triangles fv[0..ntri) (for real, with canaries, and
 * through the probe) and measure them against the intended triangle t: its
 * coverage (intersected with q <= q_limit, the part in front of a near
 * plane, when q_limit > 0) and its perspective mapping. clip: 0 when fv is
 * t itself, else how t was clipped (recorded in the CSV). */
static result_t measure_tris(const fxl_vertex_t fv[][3], int ntri, const dvert t[3], long double q_limit,
                             fxl_draw_t draw, const fxl_texture_t *tex, int clip, const char *what)
{
    int k, i;
    long n = 0;
    result_t r;
    truth_t tr;
    fxl_target_t tg;

    memset(&r, 0, sizeof r);
    r.clipped = clip;
    r.submitted = ntri;
    draw.texture = tex;

    /* real draw with canaries */
    for (i = 0; i < CAN; i++) {
        pix[i] = pix[CAN + TW * TH + i] = 0xC0DE;
        dep[i] = dep[CAN + TW * TH + i] = 0xD0DE;
    }
    fxl_target_init(&tg, pix + CAN, TW, TH, TW, FXL_PIXFMT_RGB565);
    fxl_target_set_depth(&tg, dep + CAN);
    fxl_target_clear(&tg, 0);
    fxl_target_clear_depth(&tg);
    for (k = 0; k < ntri; k++) {
        fxl_status_t st = fxl_draw_triangle(&tg, &draw, fv[k], NULL);
        if (st != FXL_OK) {
            r.status = st;
            return r;
        }
    }
    check_canaries(what);

    /* probe draw */
    memset(cnt, 0, sizeof cnt);
    memset(refcnt, 0, sizeof refcnt);
    r.max_level = 0;
    draw.depth = 0;
    for (k = 0; k < ntri; k++) {
        fxl_status_t st = fxl__draw_triangle_with(&tg, &draw, fv[k], NULL, probe);
        long c;
        if (st != FXL_OK) {
            r.status = st;
            return r;
        }
        c = ref_coverage_mask(fv[k], 0, 0, TW, TH, refmask);
        if (c < 0) {
            fprintf(stderr, "fixel-stability: reference coverage failed (%s)\n", what);
            exit(3);
        }
        for (i = 0; i < TW * TH; i++)
            refcnt[i] = (uint8_t)(refcnt[i] + refmask[i]);
    }
    check_canaries(what);

    memset(&tr, 0, sizeof tr);
    truth_init(&tr, t);   /* every method against the perspective truth */
    for (i = 0; i < TW * TH; i++) {
        long double cx = (i % TW) + 0.5L, cy = (i / TW) + 0.5L;
        if (cnt[i] != refcnt[i])
            r.cov_mismatch++;
        /* (direct inputs: the intended triangle is the submitted one, whose
         * exact coverage is the line above; the open/closed edge rule only
         * matters for the clipped path, where ties are measure-zero) */
        if (clip && tr.valid &&
            ((truth_inside(&tr, cx, cy) && (q_limit <= 0 || truth_q(&tr, cx, cy) <= q_limit)) != (cnt[i] != 0)))
            r.cov_intended++;
        if (!cnt[i] || !tex || !tr.valid)
            continue;
        {
            long double u, v, w = (long double)(1u << tex->log2_w), h = (long double)(1u << tex->log2_h);
            long double eu, ev;
            int su = tex->wrap_u >= FXL_WRAP_CLAMP, sv = tex->wrap_v >= FXL_WRAP_CLAMP;
            truth_uv(&tr, cx, cy, &u, &v);
            if (lvl_of[i] > r.max_level)
                r.max_level = lvl_of[i];
            if (lvl_of[i] != 0)
                continue;   /* coordinates on a smaller level: LOD sweep only */
            eu = axis_err(pu[i], su, u * w, w, (fxl_wrap_t)tex->wrap_u);
            ev = axis_err(pv[i], sv, v * h, h, (fxl_wrap_t)tex->wrap_v);
            errbuf[n++] = (double)(eu > ev ? eu : ev);
        }
    }
    if (!clip)
        r.cov_intended = r.cov_mismatch;
    r.pixels = 0;
    for (i = 0; i < TW * TH; i++)
        r.pixels += cnt[i] != 0;
    if (n > 0) {
        qsort(errbuf, (size_t)n, sizeof(double), cmp_double);
        r.max_err = errbuf[n - 1];
        r.p99_err = errbuf[(size_t)ceil(0.99 * (double)n) - 1];
    }
    return r;
}

/* ---- through fixel's own front end --------------------------------------------- */

/* The triangles fxl_pipeline_emit hands over (a clipped triangle is a fan of
 * at most FXL_CLIP_MAX_VERTS - 2). */
typedef struct fe_out {
    fxl_vertex_t tri[MAXPOLY][3];
    int n;
} fe_out_t;

static fxl_status_t fe_collect(void *user, const fxl_vertex_t tri[3])
{
    fe_out_t *o = (fe_out_t *)user;
    if (o->n >= MAXPOLY)
        return FXL_ERR_NOMEM;
    memcpy(o->tri[o->n++], tri, sizeof o->tri[0]);
    return FXL_OK;
}

#define FE_FOVY 10923    /* fxl_angle_t: 60 degrees (65536 / 6, rounded) */

/* A view-space triangle (q16, camera at the origin looking down -z) drawn
 * the way a firmware draws it: fxl_pipeline_emit (near plane, guard-band
 * clip, projection into the TW x TH viewport, all fixed point) into
 * fxl_draw_triangle. The intended triangle is the same q16 positions
 * projected in long double with the pipeline's own q32 matrix and viewport,
 * so the error is what the front end's clipping and quantisation add to the
 * method's; coverage is compared with the part in front of the near plane. */
static result_t measure_front(const fxl_vec3_t pos[3], const fxl_texcoord_t uv[3], fxl_q16_t near_q16,
                              fxl_draw_t draw, const fxl_texture_t *tex, const char *what)
{
    static const uint16_t idx[3] = {0, 1, 2};
    fxl_pipeline_t p;
    fxl_xform_t xf;
    fxl_mesh_t m;
    fxl_status_t st;
    fe_out_t o;
    dvert t[3];
    result_t r;
    int i, j;

    memset(&r, 0, sizeof r);
    r.clipped = 3;
    if ((st = fxl_pipeline_init(&p, TW, TH)) != FXL_OK ||
        (st = fxl_pipeline_set_perspective(&p, FE_FOVY, 1 << 16, near_q16, 0)) != FXL_OK ||
        (st = fxl_pipeline_prepare(&p, &xf)) != FXL_OK) {
        r.status = st;
        return r;
    }
    p.cull = FXL_CULL_NONE;
    memset(&m, 0, sizeof m);
    m.pos = pos;
    m.uv = uv;
    m.vert_count = 3;
    m.idx = idx;
    m.tri_count = 1;
    o.n = 0;
    if ((st = fxl_pipeline_emit(&p, &m, fe_collect, &o, NULL)) != FXL_OK) {
        r.status = st;
        return r;
    }
    for (i = 0; i < 3; i++) {
        const long double P[4] = {pos[i].x / 65536.0L, pos[i].y / 65536.0L, pos[i].z / 65536.0L, 1};
        long double c[4] = {0, 0, 0, 0};
        int row;
        for (row = 0; row < 4; row++)
            for (j = 0; j < 4; j++)
                c[row] += (long double)xf.mvp[row][j] / 4294967296.0L * P[j];
        fxl_clipvert_t cv;
        fxl_vertex_t sv;
        t[i].x = xf.cx_q16 / 65536.0L + c[0] / c[3] * (xf.hw_q16 / 65536.0L);
        t[i].y = xf.cy_q16 / 65536.0L - c[1] / c[3] * (xf.hh_q16 / 65536.0L);
        t[i].q = 1.0L / c[3];
        /* A vertex the front end projects itself (in front of the near
         * plane, inside the guard band) reaches the core snapped to the
         * 1/16-px grid: put the intended one there too, as the clipped
         * path of measure() does, so that what is measured is the
         * clipping and 1/w's precision, not the grid. */
        if (fxl_xform_clip(&xf, &pos[i], &cv) == FXL_OK && fxl_xform_project(&xf, &cv, &sv) == FXL_OK) {
            t[i].x = (long double)ref_snap(sv.x) / (1 << FXL_SUBPIXEL_BITS);
            t[i].y = (long double)ref_snap(sv.y) / (1 << FXL_SUBPIXEL_BITS);
        }
        t[i].u = uv[i].u / 65536.0L;
        t[i].v = uv[i].v / 65536.0L;
    }
    return measure_tris((const fxl_vertex_t(*)[3])o.tri, o.n, t, 65536.0L / near_q16, draw, tex, 3, what);
}

static fxl_vec3_t vec3_q16(double x, double y, double z)
{
    fxl_vec3_t v;
    v.x = (fxl_q16_t)lround(x * 65536.0);
    v.y = (fxl_q16_t)lround(y * 65536.0);
    v.z = (fxl_q16_t)lround(z * 65536.0);
    return v;
}

static fxl_texcoord_t uv_q16(double u, double v)
{
    fxl_texcoord_t t;
    t.u = (fxl_q16_t)lround(u * 65536.0);
    t.v = (fxl_q16_t)lround(v * 65536.0);
    return t;
}

/* ---- output ----------------------------------------------------------------------- */

static const char *outdir = "docs/stability";
static FILE *csv_all, *summary;

typedef struct sweep_out {
    FILE *csv, *dat;
    const char *name;
    /* breaking points per method: first param above 1/64, 1/8, 1 texel, coverage */
    double brk[NMETH][4];
    int have[NMETH][4];
} sweep_out_t;

static FILE *open_out(const char *name, const char *ext)
{
    char path[4096];
    FILE *f;
    /* A longer --out was cut short here, so sweeps wrote to clipped names
     * ("depth_max.da") and overwrote each other, with exit status 0. */
    if (snprintf(path, sizeof path, "%s/%s%s", outdir, name, ext) >= (int)sizeof path) {
        fprintf(stderr, "fixel-stability: --out '%s' is too long\n", outdir);
        exit(2);
    }
    f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "fixel-stability: cannot write %s: %s\n", path, strerror(errno));
        exit(2);
    }
    return f;
}

/* fclose, and stop on a write error (a full disk used to end in status 0). */
static void close_out(FILE *f, const char *name)
{
    int bad = ferror(f) != 0;
    if (fclose(f) != 0)
        bad = 1;
    if (bad) {
        fprintf(stderr, "fixel-stability: write error on %s/%s*\n", outdir, name);
        exit(2);
    }
}

static void sweep_begin(sweep_out_t *s, const char *name, const char *param)
{
    int m;
    memset(s, 0, sizeof *s);
    s->name = name;
    s->csv = open_out(name, ".csv");
    s->dat = open_out(name, "_max.dat");
    fprintf(s->csv, "sweep,variant,param,method,status,clipped,triangles,pixels,cov_mismatch,cov_vs_intended,"
                    "max_err,p99_err,max_level\n");
    fprintf(s->dat, "# %s", param);
    for (m = 0; m < NMETH; m++)
        fprintf(s->dat, " %s_max %s_p99", methods[m].name, methods[m].name);
    fprintf(s->dat, "\n");
    fprintf(stderr, "fixel-stability: sweep %s\n", name);
}

/* Sweep and method pairs whose coverage or status broke (exit status 4). */
static int broken;

static void emit(sweep_out_t *s, const char *variant, double param, int m, const result_t *r)
{
    static const double lim[3] = {1.0 / 64, 1.0 / 8, 1.0};
    int j;
    const char *line = "%s,%s,%.6g,%s,%s,%d,%d,%ld,%ld,%ld,%.6g,%.6g,%d\n";
    fprintf(s->csv, line, s->name, variant, param, methods[m].name, fxl_status_name(r->status), r->clipped,
            r->submitted, r->pixels, r->cov_mismatch, r->cov_intended, r->max_err, r->p99_err, r->max_level);
    fprintf(csv_all, line, s->name, variant, param, methods[m].name, fxl_status_name(r->status), r->clipped,
            r->submitted, r->pixels, r->cov_mismatch, r->cov_intended, r->max_err, r->p99_err, r->max_level);
    /* Side variants (a tight guard band, the unclipped counter-example)
     * are in the CSV but do not define the method's breaking point; nor do
     * the front end's (a different path to the core), whose coverage and
     * status must still be right. */
    if (!strcmp(variant, "saturated_no_clip") || !strcmp(variant, "clipped_guard1024"))
        return;
    for (j = 0; j < 3; j++)
        if (strncmp(variant, "front_end", 9) != 0 && !s->have[m][j] && r->max_err > lim[j]) {
            s->have[m][j] = 1;
            s->brk[m][j] = param;
        }
    if (!s->have[m][3] && (r->cov_mismatch || r->status != FXL_OK)) {
        s->have[m][3] = 1;
        s->brk[m][3] = param;
        broken++;
        fprintf(stderr, "fixel-stability: %s %s %s at %g: %s, %ld coverage mismatches\n", s->name, variant,
                methods[m].name, param, fxl_status_name(r->status), r->cov_mismatch);
    }
}

static void sweep_end(sweep_out_t *s, const char *variant)
{
    int m, j;
    for (m = 0; m < NMETH; m++) {
        fprintf(summary, "%s,%s,%s", s->name, variant, methods[m].name);
        for (j = 0; j < 4; j++) {
            if (s->have[m][j])
                fprintf(summary, ",%.6g", s->brk[m][j]);
            else
                fprintf(summary, ",none");
        }
        fprintf(summary, "\n");
    }
    close_out(s->csv, s->name);
    close_out(s->dat, s->name);
}

static void dat_row(sweep_out_t *s, double param, const result_t r[NMETH])
{
    int m;
    fprintf(s->dat, "%.6g", param);
    for (m = 0; m < NMETH; m++)
        fprintf(s->dat, " %.6g %.6g", r[m].max_err > 1e-9 ? r[m].max_err : 1e-9,
                r[m].p99_err > 1e-9 ? r[m].p99_err : 1e-9);
    fprintf(s->dat, "\n");
}

static void run_all_methods(sweep_out_t *s, const char *variant, double param, const dvert t[3],
                            const fxl_texture_t *tex, int clip, result_t r[NMETH])
{
    int m;
    char what[128];
    for (m = 0; m < NMETH; m++) {
        fxl_draw_t d;
        fxl_draw_defaults(&d);
        d.persp = methods[m].persp;
        d.mip = FXL_MIP_NONE;
        snprintf(what, sizeof what, "%s %s %g %s", s->name, variant, param, methods[m].name);
        r[m] = measure(t, d, tex, clip, what);
        emit(s, variant, param, m, &r[m]);
    }
}

/* run_all_methods through the front end (measure_front) */
static void run_all_methods_front(sweep_out_t *s, const char *variant, double param, const fxl_vec3_t pos[3],
                                  const fxl_texcoord_t uv[3], fxl_q16_t near_q16, const fxl_texture_t *tex)
{
    int m;
    char what[128];
    for (m = 0; m < NMETH; m++) {
        fxl_draw_t d;
        result_t r;
        fxl_draw_defaults(&d);
        d.persp = methods[m].persp;
        d.mip = FXL_MIP_NONE;
        snprintf(what, sizeof what, "%s %s %g %s", s->name, variant, param, methods[m].name);
        r = measure_front(pos, uv, near_q16, d, tex, what);
        emit(s, variant, param, m, &r);
    }
}

static dvert dv(long double x, long double y, long double q, long double u, long double v)
{
    dvert d;
    d.x = x;
    d.y = y;
    d.q = q;
    d.u = u;
    d.v = v;
    return d;
}

/* A quad as two triangles sharing the diagonal; measure both, merge (max). */
static void quad_all_methods(sweep_out_t *s, const char *variant, double param, const dvert c[4],
                             const fxl_texture_t *tex, int clip, result_t r[NMETH])
{
    dvert a[3] = {c[0], c[1], c[2]}, b[3] = {c[0], c[2], c[3]};
    result_t ra[NMETH], rb[NMETH];
    int m;
    char what[128];
    for (m = 0; m < NMETH; m++) {
        fxl_draw_t d;
        fxl_draw_defaults(&d);
        d.persp = methods[m].persp;
        d.mip = FXL_MIP_NONE;
        snprintf(what, sizeof what, "%s %s %g %s", s->name, variant, param, methods[m].name);
        ra[m] = measure(a, d, tex, clip, what);
        rb[m] = measure(b, d, tex, clip, what);
        r[m] = ra[m];
        r[m].pixels += rb[m].pixels;
        r[m].cov_mismatch += rb[m].cov_mismatch;
        r[m].cov_intended += rb[m].cov_intended;
        r[m].submitted += rb[m].submitted;
        if (rb[m].max_err > r[m].max_err) r[m].max_err = rb[m].max_err;
        if (rb[m].p99_err > r[m].p99_err) r[m].p99_err = rb[m].p99_err;
        if (rb[m].status != FXL_OK) r[m].status = rb[m].status;
        emit(s, variant, param, m, &r[m]);
    }
}

/* ---- sweeps ---------------------------------------------------------------------------- */

static int quick;

/* 1. depth ratio R = far w / near w across a 256x256 quad; 1/w varies along
 * the diagonal so spans are not of constant depth. 64x64 texture, 4 periods. */
static void sweep_depth(void)
{
    sweep_out_t s;
    fxl_texture_t tex;
    int k, kmax = quick ? 8 : 32;
    sweep_begin(&s, "depth", "ratio");
    make_tex(&tex, 6, 6, FXL_WRAP_REPEAT, 0);
    for (k = 0; k <= kmax; k++) {
        double R = pow(10.0, 4.0 * k / kmax);
        long double qf = 1.0L / R, qm = (qf + 1) / 2;
        dvert c[4];
        result_t r[NMETH];
        c[0] = dv(0, 0, qf, 0, 0);
        c[1] = dv(TW, 0, qm, 4, 0);
        c[2] = dv(TW, TH, 1, 4, 4);
        c[3] = dv(0, TH, qm, 0, 4);
        quad_all_methods(&s, "diagonal", R, c, &tex, 0, r);
        dat_row(&s, R, r);
    }
    sweep_end(&s, "diagonal");
}

/* 3D helpers for the grazing sweep: project view-space (x, y, z), z < 0. */
static dvert project(double x, double y, double z, double u, double v)
{
    double f = 1.0 / tan(30.0 * PI / 180.0), w = -z;
    return dv(TW * 0.5 + x * f / w * TW * 0.5, TH * 0.5 - y * f / w * TH * 0.5, 1.0 / w, u, v);
}

/* 2. A 2x2 plane at distance 3 turned by theta about a diagonal axis in the
 * view plane; 8 periods of a 64x64 texture across it. */
static void sweep_grazing(void)
{
    static const double th[] = {0, 10, 20, 30, 40, 50, 60, 70, 75, 80, 85, 87, 88, 89, 89.5, 89.8, 89.9};
    int n = (int)(sizeof th / sizeof th[0]), k;
    sweep_out_t s;
    fxl_texture_t tex;
    sweep_begin(&s, "grazing", "angle_deg");
    make_tex(&tex, 6, 6, FXL_WRAP_REPEAT, 0);
    for (k = 0; k < n; k++) {
        double a = th[k] * PI / 180.0, ax = cos(PI / 6), ay = sin(PI / 6);
        /* Rodrigues rotation of the plane's corners about (ax, ay, 0). */
        double P[4][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
        double UV[4][2] = {{0, 0}, {8, 0}, {8, 8}, {0, 8}};
        dvert c[4];
        result_t r[NMETH];
        int i;
        for (i = 0; i < 4; i++) {
            double px = P[i][0], py = P[i][1], pz = P[i][2];
            double dot = ax * px + ay * py;
            double cx = ay * pz * 1 - 0 * py, cy = 0 * px - ax * pz, cz = ax * py - ay * px;
            double rx = px * cos(a) + cx * sin(a) + ax * dot * (1 - cos(a));
            double ry = py * cos(a) + cy * sin(a) + ay * dot * (1 - cos(a));
            double rz = pz * cos(a) + cz * sin(a);
            c[i] = project(rx * 0.9, ry * 0.9, rz * 0.9 - 3.0, UV[i][0], UV[i][1]);
        }
        quad_all_methods(&s, "plane", th[k], c, &tex, 0, r);
        dat_row(&s, th[k], r);
    }
    sweep_end(&s, "plane");
}

/* 3. A vertex approaching the eye plane: view-space triangle with two
 * vertices at w = 2 and the third at w = e -> 0+ (its screen position grows
 * like 1/e). Beyond q16 the inputs are clipped to the guard band. */
static void sweep_eyeplane(void)
{
    sweep_out_t s;
    fxl_texture_t tex;
    int k, kmax = quick ? 6 : 28;
    sweep_begin(&s, "eyeplane", "w_min");
    make_tex(&tex, 6, 6, FXL_WRAP_REPEAT, 0);
    for (k = 0; k <= kmax; k++) {
        double e = pow(10.0, -7.0 * k / kmax) * 2.0;
        dvert t[3];
        result_t r[NMETH];
        int clip;
        t[0] = project(-0.9, -0.7, -2.0, 0, 0);
        t[1] = project(0.9, -0.6, -2.0, 4, 0);
        /* (0.3, 0.25) off the view axis: the projection grows like 1/e */
        t[2] = project(0.3, 0.25, -e, 2, 4);
        clip = fabsl(t[2].x) >= 32000.0L || fabsl(t[2].y) >= 32000.0L;
        run_all_methods(&s, clip ? "clipped" : "direct", 2.0 / e, t, &tex, clip, r);
        dat_row(&s, 2.0 / e, r);
        if (clip) {
            /* the same with a tight guard band: does the lever arm matter? */
            guard = 1024;
            run_all_methods(&s, "clipped_guard1024", 2.0 / e, t, &tex, clip, r);
            guard = GUARD;
            run_all_methods(&s, "saturated_no_clip", 2.0 / e, t, &tex, 2, r);
        }
        {
            /* The same triangle through fixel's front end, 4096 times
             * larger so that q16 positions resolve the third vertex's depth
             * (4096 e >= 8e-4). With a near plane at w = 0.1 (scaled) the
             * front end cuts off what is nearer: the part of the triangle
             * left must be drawn right. With the near plane just in front
             * of the third vertex nothing is near-clipped and the guard
             * band alone bounds the coordinates, but 1/w is u0.32 scaled to
             * near: at a w ratio of 10^7 the far vertices keep ~9 bits. */
            const double S = 4096;
            const fxl_vec3_t pos[3] = {vec3_q16(-0.9 * S, -0.7 * S, -2.0 * S), vec3_q16(0.9 * S, -0.6 * S, -2.0 * S),
                                       vec3_q16(0.3 * S, 0.25 * S, -e * S)};
            const fxl_texcoord_t uv[3] = {uv_q16(0, 0), uv_q16(4, 0), uv_q16(2, 4)};
            const long near_below = (long)(0.9 * -pos[2].z);
            run_all_methods_front(&s, "front_end_near0.1", 2.0 / e, pos, uv, (fxl_q16_t)lround(0.1 * S * 65536), &tex);
            run_all_methods_front(&s, "front_end_no_near_clip", 2.0 / e, pos, uv,
                                  (fxl_q16_t)(near_below > 0 ? near_below : 1), &tex);
        }
    }
    sweep_end(&s, "w_ratio");
}

/* 4. Screen coordinates up to +-1e6 px: a triangle containing the target.
 * Up to the q16 limit it goes to the core directly; beyond, through the
 * guard-band clip. Plus the limits themselves: vertices at +-32767 px. */
static void sweep_screen(void)
{
    sweep_out_t s;
    fxl_texture_t tex;
    int k, kmax = quick ? 6 : 16;
    sweep_begin(&s, "screen", "extent_px");
    make_tex(&tex, 6, 6, FXL_WRAP_REPEAT, 0);
    for (k = 0; k <= kmax; k++) {
        double S = pow(10.0, 2.0 + 4.0 * k / kmax);
        dvert t[3];
        result_t r[NMETH];
        int clip = S >= 32767.0;
        double P = S / 256.0;   /* texture periods across: ~1 texel per 4 px at the target */
        t[0] = dv(128 - S, 128 - 0.37 * S, 1.0, 0, 0);
        t[1] = dv(128 + 0.93 * S, 128 - 0.51 * S, 0.5, P, 0);
        t[2] = dv(128 + 0.11 * S, 128 + S, 0.25, 0, P);
        /* snap the in-range case to the sub-pixel grid: only the method counts */
        if (!clip) {
            int i;
            for (i = 0; i < 3; i++) {
                t[i].x = roundl(t[i].x * 16) / 16;
                t[i].y = roundl(t[i].y * 16) / 16;
            }
        }
        run_all_methods(&s, clip ? "clipped" : "direct", S, t, &tex, clip, r);
        dat_row(&s, S, r);
        {
            /* The same triangle through fixel's front end: view-space
             * vertices at w = 1, 2, 4 that project onto t (the front end's
             * own matrix gives the intended triangle, within 1e-5 of t), its
             * guard-band clip in fixed point, then the core. */
            const double f = 1.0 / tan(30.0 * PI / 180.0);
            fxl_vec3_t pos[3];
            fxl_texcoord_t uv[3];
            int i;
            for (i = 0; i < 3; i++) {
                const double w = 1.0 / (double)t[i].q;
                pos[i] = vec3_q16(((double)t[i].x - TW * 0.5) / (TW * 0.5) * w / f,
                                  -((double)t[i].y - TH * 0.5) / (TH * 0.5) * w / f, -w);
                uv[i] = uv_q16((double)t[i].u, (double)t[i].v);
            }
            run_all_methods_front(&s, "front_end", S, pos, uv, 1 << 15, &tex);
        }
    }
    sweep_end(&s, "extent");
    {
        /* the q16 limits, fed directly: the visible part must be right */
        sweep_out_t l;
        dvert t[3];
        result_t r[NMETH];
        sweep_begin(&l, "screen_limits", "case");
        t[0] = dv(-32767, -32767, 1.0, 0, 0);
        t[1] = dv(32767, -32767, 0.5, 128, 0);
        t[2] = dv(0, 32767, 0.25, 0, 128);
        run_all_methods(&l, "pm32767", 1, t, &tex, 0, r);
        dat_row(&l, 1, r);
        t[0] = dv(-32768, 32767.99998474, 1.0, 0, 0);
        t[1] = dv(32767.99998474, 32767.99998474, 1.0, 256, 0);
        t[2] = dv(0, -32768, 1.0, 0, 256);
        run_all_methods(&l, "int32_extremes", 2, t, &tex, 0, r);
        dat_row(&l, 2, r);
        t[0] = dv(100.3, 40.1, 1.0, 0, 0);
        t[1] = dv(32767, 80.7, 0.001, 1000, 0);
        t[2] = dv(120.9, 250.2, 0.9, 0, 1);
        run_all_methods(&l, "far_vertex_depth1000", 3, t, &tex, 0, r);
        dat_row(&l, 3, r);
        sweep_end(&l, "limits");
    }
}

/* 5. Texture coordinates: offset B periods (narrow range, 2 periods across a
 * 200 px quad with depth ratio 4), and a wide range -B..B across it. */
static void sweep_texcoord(void)
{
    static const double base[] = {0, 1, 10, 100, 1000, 4096, 10000, 16384, 30000, 32760, 1e5};
    static const fxl_wrap_t wraps[] = {FXL_WRAP_REPEAT, FXL_WRAP_MIRROR, FXL_WRAP_CLAMP};
    static const char *wname[] = {"repeat", "mirror", "clamp"};
    int nb = (int)(sizeof base / sizeof base[0]), k, w;
    sweep_out_t s;
    fxl_texture_t tex;
    for (w = 0; w < 3; w++) {
        char name[64], var[64];
        snprintf(name, sizeof name, "texcoord_%s", wname[w]);
        sweep_begin(&s, name, "offset_periods");
        make_tex(&tex, 6, 6, wraps[w], 0);
        for (k = 0; k < nb; k++) {
            double B = base[k];
            double Bin = B;
            dvert c[4];
            result_t r[NMETH];
            /* Beyond +-32767 periods q16 cannot hold u: the caller rebases by
             * whole periods (repeat) or pairs (mirror) before converting;
             * for clamp every such u is past the edge, so it is clamped. */
            if (B + 2 >= 32767.0) {
                if (wraps[w] == FXL_WRAP_REPEAT)
                    Bin = fmod(B, 1.0);
                else if (wraps[w] == FXL_WRAP_MIRROR)
                    Bin = fmod(B, 2.0);
                else
                    Bin = 32765.0;
            }
            snprintf(var, sizeof var, "%s", B + 2 >= 32767.0 ? "rebased_by_caller" : "direct");
            c[0] = dv(28, 28, 1.0, Bin, Bin);
            c[1] = dv(228, 28, 0.5, Bin + 2, Bin);
            c[2] = dv(228, 228, 0.25, Bin + 2, Bin + 2);
            c[3] = dv(28, 228, 0.5, Bin, Bin + 2);
            quad_all_methods(&s, var, B, c, &tex, 0, r);
            dat_row(&s, B, r);
        }
        sweep_end(&s, "offset");
        snprintf(name, sizeof name, "texcoord_wide_%s", wname[w]);
        sweep_begin(&s, name, "range_periods");
        for (k = 0; k < nb - 1; k++) {
            double B = base[k] > 0 ? base[k] : 0.5;
            dvert c[4];
            result_t r[NMETH];
            c[0] = dv(28, 28, 1.0, -B, -B);
            c[1] = dv(228, 28, 0.5, B, -B);
            c[2] = dv(228, 228, 0.25, B, B);
            c[3] = dv(28, 228, 0.5, -B, B);
            quad_all_methods(&s, "wide", B, c, &tex, 0, r);
            dat_row(&s, B, r);
        }
        sweep_end(&s, "wide");
    }
}

/* 5b. Texel range times depth ratio. Exact mode keeps u/w and v/w as 30-bit
 * mantissas of their largest vertex value (setup.c, persp.h: one 32 x 32
 * product a correction), so its error at a pixel of depth q grows as
 * 2^-30 * max_i(|u_i| q_i) / q: about 2^-30 U R for U texels of (rebased)
 * coordinate range across a triangle and a depth ratio R. The depth sweep
 * holds U at 256 texels, the wide sweep R at 4; this one moves both. A
 * 64x64 texture on a floor-like quad (rows of one depth), near edge at the
 * bottom, u and v from 0 to B periods; one sweep per R, param U * R. */
static void sweep_range_ratio(void)
{
    static const double ratios[] = {10, 100, 1000, 10000};
    sweep_out_t s;
    fxl_texture_t tex;
    size_t i;
    int k, step = quick ? 2 : 1;
    make_tex(&tex, 6, 6, FXL_WRAP_REPEAT, 0);
    for (i = 0; i < sizeof ratios / sizeof ratios[0]; i++) {
        const double R = ratios[i];
        char name[32];
        snprintf(name, sizeof name, "range_r%g", R);
        sweep_begin(&s, name, "texels_times_ratio");
        for (k = 10; k <= 38; k += step) {
            const double UR = ldexp(1.0, k), B = UR / R / 64.0;
            dvert c[4];
            result_t r[NMETH];
            if (B < 1.0 || B > 32000.0)
                continue;
            c[0] = dv(28, 228, 1.0, 0, 0);
            c[1] = dv(228, 228, 1.0, B, 0);
            c[2] = dv(228, 28, 1.0 / R, B, B);
            c[3] = dv(28, 28, 1.0 / R, 0, B);
            quad_all_methods(&s, "floor", UR, c, &tex, 0, r);
            dat_row(&s, UR, r);
        }
        sweep_end(&s, "floor");
    }
}

/* 6. Slivers: 200 px long, 200 / aspect px wide, at 30 degrees; u along,
 * v across (1 period each: the steepest gradient is across). */
static void sweep_sliver(void)
{
    sweep_out_t s;
    fxl_texture_t tex;
    int k, kmax = quick ? 8 : 32;
    sweep_begin(&s, "sliver", "aspect");
    make_tex(&tex, 6, 6, FXL_WRAP_REPEAT, 0);
    for (k = 0; k <= kmax; k++) {
        double A = pow(10.0, 4.0 * k / kmax), L = 200, Wd = L / A;
        double ca = cos(PI / 6), sa = sin(PI / 6);
        dvert t[3];
        result_t r[NMETH];
        t[0] = dv(28, 28, 1.0, 0, 0);
        t[1] = dv(28 + L * ca, 28 + L * sa, 0.3, 1, 0);
        t[2] = dv(28 + L * ca * 0.5 - Wd * sa, 28 + L * sa * 0.5 + Wd * ca, 0.6, 0.5, 1);
        run_all_methods(&s, "sliver", A, t, &tex, 0, r);
        dat_row(&s, A, r);
    }
    sweep_end(&s, "sliver");
    {
        /* zero-area and collinear: culled, nothing drawn */
        sweep_out_t z;
        dvert t[3];
        result_t r[NMETH];
        sweep_begin(&z, "degenerate", "case");
        t[0] = dv(10, 10, 1, 0, 0);
        t[1] = dv(200, 100, 0.5, 1, 0);
        t[2] = dv(10, 10, 0.5, 0, 1);
        run_all_methods(&z, "two_equal", 1, t, &tex, 0, r);
        dat_row(&z, 1, r);
        t[2] = dv(105, 55, 0.7, 0.5, 1);
        run_all_methods(&z, "collinear", 2, t, &tex, 0, r);
        dat_row(&z, 2, r);
        t[2] = dv(105.01, 55, 0.7, 0.5, 1);   /* collinear after the 1/16 px snap */
        run_all_methods(&z, "collinear_after_snap", 3, t, &tex, 0, r);
        dat_row(&z, 3, r);
        t[0] = dv(-32768, -32768, 1, 0, 0);
        t[1] = dv(32767, 32767, 1, 1, 0);
        t[2] = dv(0, 0, 1, 0, 1);
        run_all_methods(&z, "collinear_huge", 4, t, &tex, 0, r);
        dat_row(&z, 4, r);
        sweep_end(&z, "degenerate");
    }
}

/* 7. Texture sizes: a 200 px quad with depth ratio 8, u, v 0..1. */
static void sweep_texsize(void)
{
    static const int sz[][2] = {{0, 0}, {0, 10}, {10, 0}, {1, 3}, {4, 4}, {6, 8}, {8, 6}, {9, 9}, {10, 10}, {10, 1}};
    int n = (int)(sizeof sz / sizeof sz[0]), k;
    sweep_out_t s;
    sweep_begin(&s, "texsize", "texels_log2_sum");
    for (k = 0; k < n; k++) {
        fxl_texture_t tex;
        dvert c[4];
        result_t r[NMETH];
        char var[32];
        make_tex(&tex, (uint32_t)sz[k][0], (uint32_t)sz[k][1], FXL_WRAP_REPEAT, 0);
        snprintf(var, sizeof var, "%dx%d", 1 << sz[k][0], 1 << sz[k][1]);
        c[0] = dv(28, 28, 0.125, 0, 0);
        c[1] = dv(228, 28, 0.3, 1, 0);
        c[2] = dv(228, 228, 1.0, 1, 1);
        c[3] = dv(28, 228, 0.3, 0, 1);
        quad_all_methods(&s, var, k, c, &tex, 0, r);
        dat_row(&s, k, r);
    }
    sweep_end(&s, "size");
}

/* 8. LOD extremes: 1024x1024 with a full chain, magnified (u, v 0..1/16
 * periods over the quad: LOD -2.9, 7.6x, at its near edge) and minified
 * (u, v 0..4096 and 30000 periods: LOD > 10), with
 * bias -32768 / +32767 q8; per-segment and per-triangle LOD, nearest and
 * linear. Records the level range used; levels beyond the chain would read
 * outside it (caught by ASan / canaries). */
static void sweep_lod(void)
{
    static const double span[] = {1.0 / 16, 1, 64, 4096, 30000};
    static const int16_t bias[] = {INT16_MIN, -256, 0, 256, INT16_MAX};
    sweep_out_t s;
    fxl_texture_t tex;
    int a, b, m, lodm, mipm;
    FILE *f = open_out("lod", ".csv");
    fprintf(f, "periods,bias_q8,lod_mode,mip,method,status,pixels,max_level,levels,ref_lod_min,ref_lod_max\n");
    (void)s;
    make_tex(&tex, 10, 10, FXL_WRAP_REPEAT, 1);
    for (a = 0; a < 5; a++)
        for (b = 0; b < 5; b++)
            for (lodm = 0; lodm < 2; lodm++)
                for (mipm = 1; mipm <= 2; mipm++)
                    for (m = 0; m < NMETH; m++) {
                        fxl_draw_t d;
                        dvert t[3];
                        result_t r;
                        fxl_vertex_t fv[3];
                        double dun[2], dvn[2], lmin = 1e9, lmax = -1e9;
                        int i;
                        fxl_draw_defaults(&d);
                        d.persp = methods[m].persp;
                        d.mip = (uint8_t)mipm;
                        d.lod = (uint8_t)lodm;
                        d.lod_bias_q8 = bias[b];
                        t[0] = dv(0, 0, 1.0, 0, 0);
                        t[1] = dv(256, 0, 0.5, span[a], 0);
                        t[2] = dv(0, 256, 0.25, 0, span[a]);
                        r = measure(t, d, &tex, 0, "lod");
                        for (i = 0; i < 3; i++)
                            fv[i] = to_vertex(&t[i], 1.0L);
                        for (i = 0; i < 16; i++) {
                            double uu, vv, l;
                            if (ref_uv_at(fv, 8 + 15 * i, 8 + 7 * i, 0, &uu, &vv, dun, dvn) == 0) {
                                l = ref_lod_pixel(&tex, dun, dvn) + bias[b] / 256.0;
                                if (l < lmin) lmin = l;
                                if (l > lmax) lmax = l;
                            }
                        }
                        fprintf(f, "%g,%d,%s,%s,%s,%s,%ld,%d,%d,%.3f,%.3f\n", span[a], bias[b],
                                lodm ? "triangle" : "segment", mipm == 1 ? "nearest" : "linear",
                                methods[m].name, fxl_status_name(r.status), r.pixels, r.max_level, tex.levels,
                                lmin, lmax);
                        if (r.max_level > tex.levels - 1) {
                            fprintf(stderr, "fixel-stability: level %d beyond the chain\n", r.max_level);
                            exit(3);
                        }
                    }
    close_out(f, "lod");
    fprintf(stderr, "fixel-stability: sweep lod\n");
}

int main(int argc, char **argv)
{
    int a;
    for (a = 1; a < argc; a++) {
        /* the empty test first: --out '' wrote every file into / */
        if (!strcmp(argv[a], "--out") && (a + 1 >= argc || argv[a + 1][0] == '\0')) {
            fprintf(stderr, "fixel-stability: --out needs a directory\n");
            return 2;
        } else if (!strcmp(argv[a], "--out"))
            outdir = argv[++a];
        else if (!strcmp(argv[a], "--quick"))
            quick = 1;
        else {
            const int help = !strcmp(argv[a], "--help") || !strcmp(argv[a], "-h");
            fprintf(help ? stdout : stderr,
                    "usage: fixel-stability [--out DIR] [--quick]\n"
                    "  Sweeps every method past its breaking point against the reference\n"
                    "  renderer (depth ratio, grazing angle, eye plane, screen extent and\n"
                    "  limits, texture offsets and ranges, range times depth ratio,\n"
                    "  slivers, texture sizes, LOD) and\n"
                    "  writes CSVs and gnuplot data to DIR (default docs/stability; charts:\n"
                    "  make stability). --quick: fewer points per sweep.\n");
            return help ? 0 : 2;
        }
    }
    if (mkdir(outdir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "fixel-stability: cannot create '%s': %s\n", outdir, strerror(errno));
        return 2;
    }
    errbuf = (double *)malloc(sizeof(double) * TW * TH);
    if (!errbuf)
        return 2;
    csv_all = open_out("all", ".csv");
    summary = open_out("summary", ".csv");
    fprintf(csv_all, "sweep,variant,param,method,status,clipped,triangles,pixels,cov_mismatch,cov_vs_intended,"
                     "max_err,p99_err,max_level\n");
    fprintf(summary, "sweep,variant,method,first_above_1_64,first_above_1_8,first_above_1,first_coverage_or_status_fail\n");
    sweep_depth();
    sweep_grazing();
    sweep_eyeplane();
    sweep_screen();
    sweep_texcoord();
    sweep_range_ratio();
    sweep_sliver();
    sweep_texsize();
    sweep_lod();
    close_out(csv_all, "all");
    close_out(summary, "summary");
    free(errbuf);
    free(tex_mem);
    fprintf(stderr, "fixel-stability: wrote %s/*.csv\n", outdir);
    if (broken) {
        fprintf(stderr, "fixel-stability: %d sweep/method pairs lost exact coverage or a valid draw failed\n",
                broken);
        return 4;
    }
    return 0;
}
