/* reference.c - double-precision reference renderer (contract in reference.h).
 *
 * Written for clarity, not speed: every covered pixel evaluates its three
 * edge functions in int64 and its attributes in long double from scratch, so
 * no error accumulates along a span.
 */
#define _POSIX_C_SOURCE 200809L
#include "reference.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Grid units per pixel, and the doubled grid (pixel centres become the
 * integers 2*S*i + S). */
#define REF_S ((int64_t)1 << FXL_SUBPIXEL_BITS)
#define REF_S2 (2 * REF_S)

/* A triangle after snapping, oriented so that the doubled signed area is
 * positive (vertices 1 and 2 swapped when it was negative). */
typedef struct ref_tri {
    int64_t x[3], y[3];        /* doubled grid coordinates */
    int64_t area;              /* E_k(V_k), the same for every k, > 0 */
    int incl[3];               /* edge k (V[k+1] -> V[k+2]) owns centres on it */
    const fxl_vertex_t *v[3];  /* attributes, in the same (possibly swapped) order */
} ref_tri;

static int64_t floor_div64(int64_t a, int64_t b) /* b > 0 */
{
    int64_t q = a / b;
    if ((a % b) != 0 && a < 0) {
        q -= 1;
    }
    return q;
}

int32_t ref_snap(fxl_q16_t x)
{
    /* round(x * 2^B / 2^16), ties toward +inf == floor((x + half) / 2^(16-B)).
     * Done in int64 so x near INT32_MAX cannot overflow. */
    const int64_t step = (int64_t)1 << (16 - FXL_SUBPIXEL_BITS);
    return (int32_t)floor_div64((int64_t)x + step / 2, step);
}

/* Edge function of edge a -> b at point (px, py), doubled grid units.
 * Ranges: coordinates are below 2^20 in magnitude (2 * 2^19 grid units of an
 * int32 q16 position), differences below 2^21, products below 2^42. */
static int64_t edge_fn(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px, int64_t py)
{
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

/* Returns 0 for a zero-area triangle. */
static int tri_setup(ref_tri *t, const fxl_vertex_t src[3])
{
    int k;
    for (k = 0; k < 3; ++k) {
        t->v[k] = &src[k];
        t->x[k] = 2 * (int64_t)ref_snap(src[k].x);
        t->y[k] = 2 * (int64_t)ref_snap(src[k].y);
    }
    t->area = edge_fn(t->x[0], t->y[0], t->x[1], t->y[1], t->x[2], t->y[2]);
    if (t->area == 0) {
        return 0;
    }
    if (t->area < 0) {
        int64_t sx = t->x[1], sy = t->y[1];
        const fxl_vertex_t *sv = t->v[1];
        t->x[1] = t->x[2];
        t->y[1] = t->y[2];
        t->v[1] = t->v[2];
        t->x[2] = sx;
        t->y[2] = sy;
        t->v[2] = sv;
        t->area = -t->area;
    }
    for (k = 0; k < 3; ++k) {
        int a = (k + 1) % 3, b = (k + 2) % 3;
        int64_t dx = t->x[b] - t->x[a];
        int64_t dy = t->y[b] - t->y[a];
        /* Inside is where E grows: along the gradient (-dy, dx). A top edge is
         * horizontal with the inside below (dx > 0, y grows downward); a left
         * edge is not horizontal and has the inside to its right (-dy > 0). */
        t->incl[k] = (dy == 0 && dx > 0) || dy < 0;
    }
    return 1;
}

static int64_t tri_edge(const ref_tri *t, int k, int64_t px, int64_t py)
{
    int a = (k + 1) % 3, b = (k + 2) % 3;
    return edge_fn(t->x[a], t->y[a], t->x[b], t->y[b], px, py);
}

/* Covered test at doubled-grid point (px, py); e[] receives the edge values. */
static int tri_covers(const ref_tri *t, int64_t px, int64_t py, int64_t e[3])
{
    int k;
    for (k = 0; k < 3; ++k) {
        e[k] = tri_edge(t, k, px, py);
        if (e[k] < 0 || (e[k] == 0 && !t->incl[k])) {
            return 0;
        }
    }
    return 1;
}

static int64_t centre_of(int32_t i)
{
    return REF_S2 * (int64_t)i + REF_S;
}

int ref_pixel_covered(const fxl_vertex_t tri[3], int32_t i, int32_t j)
{
    ref_tri t;
    int64_t e[3];
    if (tri == NULL || !tri_setup(&t, tri)) {
        return 0;
    }
    return tri_covers(&t, centre_of(i), centre_of(j), e);
}

/* Pixel index range whose centres lie in [lo, hi] (doubled grid). */
static void centre_range(int64_t lo, int64_t hi, int64_t *first, int64_t *last)
{
    *first = -floor_div64(-(lo - REF_S), REF_S2); /* ceil */
    *last = floor_div64(hi - REF_S, REF_S2);
}

static int64_t min3(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a < b ? a : b;
    return m < c ? m : c;
}

static int64_t max3(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a > b ? a : b;
    return m > c ? m : c;
}

/* Pixel bounding box of t intersected with [x0, x0+w) x [y0, y0+h);
 * returns 0 when empty. */
static int tri_bbox(const ref_tri *t, int32_t x0, int32_t y0, int32_t w, int32_t h,
                    int64_t *i0, int64_t *i1, int64_t *j0, int64_t *j1)
{
    centre_range(min3(t->x[0], t->x[1], t->x[2]), max3(t->x[0], t->x[1], t->x[2]), i0, i1);
    centre_range(min3(t->y[0], t->y[1], t->y[2]), max3(t->y[0], t->y[1], t->y[2]), j0, j1);
    if (*i0 < x0) *i0 = x0;
    if (*j0 < y0) *j0 = y0;
    if (*i1 > (int64_t)x0 + w - 1) *i1 = (int64_t)x0 + w - 1;
    if (*j1 > (int64_t)y0 + h - 1) *j1 = (int64_t)y0 + h - 1;
    return *i0 <= *i1 && *j0 <= *j1;
}

long ref_coverage_mask(const fxl_vertex_t tri[3], int32_t x0, int32_t y0, int32_t w,
                       int32_t h, uint8_t *mask)
{
    ref_tri t;
    int64_t i0, i1, j0, j1, i, j, e[3];
    long n = 0;
    if (tri == NULL || mask == NULL || w <= 0 || h <= 0) {
        return -1;
    }
    memset(mask, 0, (size_t)w * (size_t)h);
    if (!tri_setup(&t, tri) || !tri_bbox(&t, x0, y0, w, h, &i0, &i1, &j0, &j1)) {
        return 0;
    }
    for (j = j0; j <= j1; ++j) {
        for (i = i0; i <= i1; ++i) {
            if (tri_covers(&t, centre_of((int32_t)i), centre_of((int32_t)j), e)) {
                mask[(size_t)(j - y0) * (size_t)w + (size_t)(i - x0)] = 1;
                ++n;
            }
        }
    }
    return n;
}

/* ---- attributes ------------------------------------------------------------ */

/* Exact attribute evaluation at doubled-grid point (px, py) given as long
 * double edge values e[k] (b_k = e[k] / area). */
typedef struct ref_attr {
    long double u, v;          /* normalised */
    long double du[2], dv[2];  /* d/dx, d/dy per pixel, normalised */
    long double q;             /* inv_w, screen-linear */
} ref_attr;

static void attr_eval(const ref_tri *t, const long double e[3], int affine, ref_attr *a)
{
    long double n_u = 0, n_v = 0, d = 0;
    long double n_ux = 0, n_uy = 0, n_vx = 0, n_vy = 0, d_x = 0, d_y = 0;
    long double area = (long double)t->area;
    int k;
    for (k = 0; k < 3; ++k) {
        int ia = (k + 1) % 3, ib = (k + 2) % 3;
        /* dE_k/dx and dE_k/dy per pixel (doubled grid: REF_S2 units per px) */
        long double ex = -(long double)(t->y[ib] - t->y[ia]) * (long double)REF_S2;
        long double ey = (long double)(t->x[ib] - t->x[ia]) * (long double)REF_S2;
        long double uk = (long double)t->v[k]->u / 65536.0L;
        long double vk = (long double)t->v[k]->v / 65536.0L;
        long double qk = affine ? 1.0L : (long double)t->v[k]->inv_w;
        n_u += e[k] * uk * qk;
        n_v += e[k] * vk * qk;
        d += e[k] * qk;
        n_ux += ex * uk * qk;
        n_uy += ey * uk * qk;
        n_vx += ex * vk * qk;
        n_vy += ey * vk * qk;
        d_x += ex * qk;
        d_y += ey * qk;
    }
    a->u = n_u / d;
    a->v = n_v / d;
    /* quotient rule: (N/D)' = (N' D - N D') / D^2 */
    a->du[0] = (n_ux * d - n_u * d_x) / (d * d);
    a->du[1] = (n_uy * d - n_u * d_y) / (d * d);
    a->dv[0] = (n_vx * d - n_v * d_x) / (d * d);
    a->dv[1] = (n_vy * d - n_v * d_y) / (d * d);
    {
        long double q = 0;
        for (k = 0; k < 3; ++k) {
            q += e[k] * (long double)t->v[k]->inv_w;
        }
        a->q = q / area;
    }
}

int ref_uv_at(const fxl_vertex_t tri[3], double px, double py, int affine, double *u,
              double *v, double du[2], double dv[2])
{
    ref_tri t;
    long double e[3];
    long double gx = (long double)px * (long double)REF_S2;
    long double gy = (long double)py * (long double)REF_S2;
    ref_attr a;
    int k;
    if (tri == NULL || !tri_setup(&t, tri)) {
        return -1;
    }
    for (k = 0; k < 3; ++k) {
        int ia = (k + 1) % 3, ib = (k + 2) % 3;
        e[k] = (long double)(t.x[ib] - t.x[ia]) * (gy - (long double)t.y[ia]) -
               (long double)(t.y[ib] - t.y[ia]) * (gx - (long double)t.x[ia]);
    }
    attr_eval(&t, e, affine, &a);
    if (u) *u = (double)a.u;
    if (v) *v = (double)a.v;
    if (du) {
        du[0] = (double)a.du[0];
        du[1] = (double)a.du[1];
    }
    if (dv) {
        dv[0] = (double)a.dv[0];
        dv[1] = (double)a.dv[1];
    }
    return 0;
}

/* ---- textures ---------------------------------------------------------------- */

static uint32_t level_w(const fxl_texture_t *t, uint32_t level)
{
    uint32_t s = level < t->log2_w ? t->log2_w - level : 0;
    return 1u << s;
}

static uint32_t level_h(const fxl_texture_t *t, uint32_t level)
{
    uint32_t s = level < t->log2_h ? t->log2_h - level : 0;
    return 1u << s;
}

static int tex_ok(const fxl_texture_t *t)
{
    uint32_t maxl = t->log2_w > t->log2_h ? t->log2_w : t->log2_h;
    if (t->texels == NULL || t->log2_w > FXL_TEX_MAX_LOG2 || t->log2_h > FXL_TEX_MAX_LOG2) {
        return 0;
    }
    if (t->levels < 1 || t->levels > maxl + 1 || t->format > FXL_TEXFMT_I8) {
        return 0;
    }
    if (t->format == FXL_TEXFMT_I8 && t->palette == NULL) {
        return 0;
    }
    return t->wrap_u <= FXL_WRAP_BORDER && t->wrap_v <= FXL_WRAP_BORDER;
}

int32_t ref_wrap(fxl_wrap_t mode, int64_t x, int32_t n)
{
    int64_t m;
    switch (mode) {
    case FXL_WRAP_MIRROR:
        m = x % (2 * (int64_t)n);
        if (m < 0) m += 2 * (int64_t)n;
        return (int32_t)(m < n ? m : 2 * (int64_t)n - 1 - m);
    case FXL_WRAP_CLAMP:
        return (int32_t)(x < 0 ? 0 : (x >= n ? n - 1 : x));
    case FXL_WRAP_BORDER:
        return (x < 0 || x >= n) ? -1 : (int32_t)x;
    case FXL_WRAP_REPEAT:
    default:
        m = x % n;
        return (int32_t)(m < 0 ? m + n : m);
    }
}

void ref_rgb565_to_rgb(uint16_t c, double rgb[3])
{
    rgb[0] = (double)((c >> 11) & 31u) * 255.0 / 31.0;
    rgb[1] = (double)((c >> 5) & 63u) * 255.0 / 63.0;
    rgb[2] = (double)(c & 31u) * 255.0 / 31.0;
}

int ref_texel(const fxl_texture_t *t, uint32_t level, int64_t x, int64_t y, double rgb[3])
{
    uint32_t w = level_w(t, level), h = level_h(t, level);
    int32_t tx = ref_wrap((fxl_wrap_t)t->wrap_u, x, (int32_t)w);
    int32_t ty = ref_wrap((fxl_wrap_t)t->wrap_v, y, (int32_t)h);
    size_t off = 0, idx;
    uint32_t l;
    uint16_t stored, c;
    if (tx < 0 || ty < 0) {
        ref_rgb565_to_rgb(t->border, rgb);
        return 0; /* border colour is never keyed */
    }
    for (l = 0; l < level; ++l) {
        off += (size_t)level_w(t, l) * level_h(t, l);
    }
    idx = off + (size_t)ty * w + (size_t)tx;
    if (t->format == FXL_TEXFMT_RGB565) {
        stored = ((const uint16_t *)t->texels)[idx];
        c = stored;
    } else {
        stored = ((const uint8_t *)t->texels)[idx];
        c = t->format == FXL_TEXFMT_L8 ? FXL_RGB565(stored, stored, stored) : t->palette[stored];
    }
    ref_rgb565_to_rgb(c, rgb);
    return (t->flags & FXL_TEXF_KEY) && stored == t->key;
}

int ref_sample_level(const fxl_texture_t *t, uint32_t level, fxl_filter_t filter, double ut,
                     double vt, double rgb[3])
{
    int64_t nx = (int64_t)floor(ut), ny = (int64_t)floor(vt);
    double c[3], wsum = 0;
    int64_t x0, y0;
    double fx, fy;
    int dx, dy, k;
    if (filter == FXL_FILTER_POINT) {
        return ref_texel(t, level, nx, ny, rgb);
    }
    /* The nearest texel decides transparency (texture.h). */
    if (ref_texel(t, level, nx, ny, c)) {
        rgb[0] = rgb[1] = rgb[2] = 0;
        return 1;
    }
    x0 = (int64_t)floor(ut - 0.5);
    y0 = (int64_t)floor(vt - 0.5);
    fx = (ut - 0.5) - (double)x0;
    fy = (vt - 0.5) - (double)y0;
    rgb[0] = rgb[1] = rgb[2] = 0;
    /* A key texel in the footprint takes the nearest texel's colour
     * (texture.h), so keys never bleed and the weights stay bilinear. */
    for (dy = 0; dy < 2; ++dy) {
        for (dx = 0; dx < 2; ++dx) {
            double w = (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy), cc[3];
            if (ref_texel(t, level, x0 + dx, y0 + dy, cc)) {
                cc[0] = c[0];
                cc[1] = c[1];
                cc[2] = c[2];
            }
            for (k = 0; k < 3; ++k) {
                rgb[k] += w * cc[k];
            }
            wsum += w;
        }
    }
    (void)wsum;
    return 0;
}

double ref_lod_triangle(const fxl_texture_t *t, const fxl_vertex_t tri[3])
{
    ref_tri s;
    double w0 = (double)(1u << t->log2_w), h0 = (double)(1u << t->log2_h);
    double du1 = ((double)tri[1].u - tri[0].u) / 65536.0 * w0;
    double dv1 = ((double)tri[1].v - tri[0].v) / 65536.0 * h0;
    double du2 = ((double)tri[2].u - tri[0].u) / 65536.0 * w0;
    double dv2 = ((double)tri[2].v - tri[0].v) / 65536.0 * h0;
    double texel_area = fabs(du1 * dv2 - du2 * dv1) / 2;
    double pixel_area;
    if (!tri_setup(&s, tri)) {
        return HUGE_VAL;
    }
    /* area is doubled-area in doubled grid units: (2S)^2 per px^2, times 2 */
    pixel_area = (double)s.area / ((double)REF_S2 * (double)REF_S2) / 2;
    if (texel_area == 0) {
        return -HUGE_VAL;
    }
    return log2(texel_area / pixel_area) / 2;
}

double ref_chord_bound(const fxl_vertex_t tri[3], uint32_t log2_w, uint32_t log2_h, int L)
{
    double X[3], Y[3], q[3], su[3], sv[3], det, qx, sux, svx, nu = 0, nv = 0, qmin = 1e300;
    int i;
    for (i = 0; i < 3; i++) {
        X[i] = ref_snap(tri[i].x) / (double)REF_S;
        Y[i] = ref_snap(tri[i].y) / (double)REF_S;
        q[i] = (double)tri[i].inv_w;
        su[i] = tri[i].u / 65536.0 * ldexp(1.0, (int)log2_w) * q[i];
        sv[i] = tri[i].v / 65536.0 * ldexp(1.0, (int)log2_h) * q[i];
        qmin = q[i] < qmin ? q[i] : qmin;
    }
    det = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
#define REF_GX(a) (((a[1] - a[0]) * (Y[2] - Y[0]) - (a[2] - a[0]) * (Y[1] - Y[0])) / det)
    qx = REF_GX(q);
    sux = REF_GX(su);
    svx = REF_GX(sv);
#undef REF_GX
    for (i = 0; i < 3; i++) {
        const double a = fabs(sux * q[i] - su[i] * qx), b = fabs(svx * q[i] - sv[i] * qx);
        nu = a > nu ? a : nu;
        nv = b > nv ? b : nv;
    }
    return (double)L * L / 4.0 * fabs(qx) * hypot(nu, nv) / (qmin * qmin * qmin) + L / 65536.0;
}

double ref_lod_pixel(const fxl_texture_t *t, const double du[2], const double dv[2])
{
    double w0 = (double)(1u << t->log2_w), h0 = (double)(1u << t->log2_h);
    double lx = hypot(du[0] * w0, dv[0] * h0);
    double ly = hypot(du[1] * w0, dv[1] * h0);
    double m = lx > ly ? lx : ly;
    return m > 0 ? log2(m) : -HUGE_VAL;
}

/* ---- the renderer -------------------------------------------------------------- */

void ref_params_init(ref_params *p, int32_t width, int32_t height)
{
    memset(p, 0, sizeof(*p));
    p->width = width;
    p->height = height;
    /* The same defaults as fxl_draw_defaults (raster.h), written out so the
     * reference does not need the core library. */
    p->draw.texture = NULL;
    p->draw.persp = FXL_PERSP_SPAN;
    p->draw.filter = FXL_FILTER_POINT;
    p->draw.mip = FXL_MIP_NEAREST;
    p->draw.lod = FXL_LOD_SEGMENT;
    p->draw.texenv = FXL_TEXENV_REPLACE;
    p->draw.shade = FXL_SHADE_FLAT;
    p->draw.depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
    p->draw.color = 0xFFFFu;
    p->draw.lod_bias_q8 = 0;
    p->draw.auto_budget = FXL_Q16_ONE / 4;
    p->depth_enabled = 0;
    p->depth_tie_margin = 1;
    p->clear_color = 0;
}

void ref_free(ref_image *img)
{
    if (img == NULL) {
        return;
    }
    free(img->covered);
    free(img->drawn);
    free(img->depth_tie);
    free(img->tri);
    free(img->u);
    free(img->v);
    free(img->lod);
    free(img->tex_x);
    free(img->tex_y);
    free(img->rgb);
    free(img->depth);
    memset(img, 0, sizeof(*img));
}

static fxl_status_t image_alloc(ref_image *img, const ref_params *p)
{
    size_t n = (size_t)p->width * (size_t)p->height, i;
    memset(img, 0, sizeof(*img));
    img->width = p->width;
    img->height = p->height;
    img->origin_x = p->origin_x;
    img->origin_y = p->origin_y;
    img->covered = calloc(n, 1);
    img->drawn = calloc(n, 1);
    img->depth_tie = calloc(n, 1);
    img->tri = malloc(n * sizeof(int32_t));
    img->u = calloc(n, sizeof(double));
    img->v = calloc(n, sizeof(double));
    img->lod = calloc(n, sizeof(double));
    img->tex_x = malloc(n * sizeof(int32_t));
    img->tex_y = malloc(n * sizeof(int32_t));
    img->rgb = malloc(3 * n * sizeof(double));
    img->depth = calloc(n, sizeof(uint16_t));
    if (!img->covered || !img->drawn || !img->depth_tie || !img->tri || !img->u || !img->v ||
        !img->lod || !img->tex_x || !img->tex_y || !img->rgb || !img->depth) {
        ref_free(img);
        return FXL_ERR_NOMEM;
    }
    for (i = 0; i < n; ++i) {
        img->tri[i] = -1;
        img->tex_x[i] = REF_NO_TEXEL;
        img->tex_y[i] = REF_NO_TEXEL;
        ref_rgb565_to_rgb(p->clear_color, &img->rgb[3 * i]);
    }
    return FXL_OK;
}

static fxl_status_t params_check(const ref_params *p)
{
    const fxl_draw_t *d = &p->draw;
    if (p->width < 1 || p->height < 1 || p->width > 16384 || p->height > 16384) {
        return FXL_ERR_ARG;
    }
    if (d->filter > FXL_FILTER_BILINEAR || d->mip > FXL_MIP_LINEAR ||
        d->lod > FXL_LOD_TRIANGLE || d->texenv > FXL_TEXENV_DECAL ||
        d->shade > FXL_SHADE_GOURAUD) {
        return FXL_ERR_ARG;
    }
    if (d->texture != NULL) {
        if (!tex_ok(d->texture)) {
            return FXL_ERR_UNSUPPORTED;
        }
        if (d->texenv != FXL_TEXENV_REPLACE || d->shade != FXL_SHADE_FLAT) {
            return FXL_ERR_UNSUPPORTED;
        }
    }
    return FXL_OK;
}

/* Colour of one pixel of a textured triangle; returns 1 if transparent. */
static int shade_textured(const fxl_draw_t *d, double lod, double ut0, double vt0,
                          double rgb[3])
{
    const fxl_texture_t *t = d->texture;
    fxl_filter_t f = (fxl_filter_t)d->filter;
    uint32_t l0;
    double frac, c0[3], c1[3];
    int tr0, tr1, k;
    if (d->mip == FXL_MIP_NONE) {
        return ref_sample_level(t, 0, f, ut0, vt0, rgb);
    }
    if (d->mip == FXL_MIP_NEAREST) {
        l0 = (uint32_t)floor(lod + 0.5);
        if (l0 > (uint32_t)t->levels - 1) l0 = (uint32_t)t->levels - 1;
        return ref_sample_level(t, l0, f, ut0 * level_w(t, l0) / level_w(t, 0),
                                vt0 * level_h(t, l0) / level_h(t, 0), rgb);
    }
    l0 = (uint32_t)floor(lod);
    frac = lod - (double)l0;
    tr0 = ref_sample_level(t, l0, f, ut0 * level_w(t, l0) / level_w(t, 0),
                           vt0 * level_h(t, l0) / level_h(t, 0), c0);
    if (l0 + 1 >= t->levels || frac == 0) {
        memcpy(rgb, c0, sizeof(c0));
        return tr0;
    }
    tr1 = ref_sample_level(t, l0 + 1, f, ut0 * level_w(t, l0 + 1) / level_w(t, 0),
                           vt0 * level_h(t, l0 + 1) / level_h(t, 0), c1);
    /* The finer level decides transparency; a transparent coarser level
     * drops out (reference.h). */
    if (tr0) {
        return 1;
    }
    if (tr1) {
        memcpy(rgb, c0, sizeof(c0));
        return 0;
    }
    for (k = 0; k < 3; ++k) {
        rgb[k] = (1 - frac) * c0[k] + frac * c1[k];
    }
    return 0;
}

fxl_status_t ref_render(const ref_params *p, const fxl_vertex_t *tri_list, int ntri,
                        ref_image *out)
{
    const fxl_draw_t *d;
    const fxl_texture_t *tex;
    uint8_t *depth_set;
    fxl_status_t st;
    int n;
    if (out != NULL) {
        memset(out, 0, sizeof(*out));
    }
    if (p == NULL || out == NULL || ntri < 0 || (tri_list == NULL && ntri > 0)) {
        return FXL_ERR_ARG;
    }
    st = params_check(p);
    if (st != FXL_OK) {
        return st;
    }
    st = image_alloc(out, p);
    if (st != FXL_OK) {
        return st;
    }
    depth_set = calloc((size_t)p->width * (size_t)p->height, 1);
    if (depth_set == NULL) {
        ref_free(out);
        return FXL_ERR_NOMEM;
    }
    d = &p->draw;
    tex = d->texture;
    for (n = 0; n < ntri; ++n) {
        const fxl_vertex_t *src = &tri_list[3 * n];
        ref_tri t;
        int64_t i0, i1, j0, j1, i, j;
        int affine = d->persp == FXL_PERSP_AFFINE;
        double w0 = tex ? (double)level_w(tex, 0) : 1.0;
        double h0 = tex ? (double)level_h(tex, 0) : 1.0;
        double lod_tri = 0, bias = (double)d->lod_bias_q8 / 256.0;
        if (!tri_setup(&t, src) ||
            !tri_bbox(&t, p->origin_x, p->origin_y, p->width, p->height, &i0, &i1, &j0, &j1)) {
            continue;
        }
        if (tex && d->lod == FXL_LOD_TRIANGLE) {
            lod_tri = ref_lod_triangle(tex, src);
        }
        for (j = j0; j <= j1; ++j) {
            for (i = i0; i <= i1; ++i) {
                size_t idx = (size_t)(j - p->origin_y) * (size_t)p->width + (size_t)(i - p->origin_x);
                int64_t e[3];
                long double el[3];
                ref_attr a;
                double rgb[3], lod = 0, ut, vt;
                int k;
                if (!tri_covers(&t, centre_of((int32_t)i), centre_of((int32_t)j), e)) {
                    continue;
                }
                if (out->covered[idx] < 255) {
                    out->covered[idx]++;
                }
                for (k = 0; k < 3; ++k) {
                    el[k] = (long double)e[k]; /* |e| < 2^43: exact */
                }
                attr_eval(&t, el, affine, &a);
                ut = (double)(a.u * w0);
                vt = (double)(a.v * h0);
                if (tex) {
                    double du[2] = {(double)a.du[0], (double)a.du[1]};
                    double dv[2] = {(double)a.dv[0], (double)a.dv[1]};
                    lod = (d->lod == FXL_LOD_TRIANGLE ? lod_tri : ref_lod_pixel(tex, du, dv)) + bias;
                    if (!(lod > 0)) lod = 0; /* also -inf */
                    if (lod > (double)(tex->levels - 1)) lod = (double)(tex->levels - 1);
                    if (shade_textured(d, lod, ut, vt, rgb)) {
                        continue; /* key: no colour, no depth */
                    }
                } else if (d->shade == FXL_SHADE_GOURAUD) {
                    /* perspective-correct, like u and v */
                    long double num[3] = {0, 0, 0}, den = 0;
                    int c;
                    for (k = 0; k < 3; ++k) {
                        double ck[3];
                        long double w = el[k] * (long double)t.v[k]->inv_w;
                        ref_rgb565_to_rgb(t.v[k]->color, ck);
                        for (c = 0; c < 3; ++c) num[c] += w * ck[c];
                        den += w;
                    }
                    for (c = 0; c < 3; ++c) rgb[c] = (double)(num[c] / den);
                } else {
                    ref_rgb565_to_rgb(d->color, rgb);
                }
                if (p->depth_enabled && d->depth != 0) {
                    long double dz = floorl(a.q / 65536.0L);
                    uint16_t dq = (uint16_t)(dz < 0 ? 0 : (dz > 65535 ? 65535 : dz));
                    if (d->depth & FXL_DEPTH_TEST) {
                        int32_t diff = (int32_t)dq - (int32_t)out->depth[idx];
                        if (depth_set[idx] && diff <= p->depth_tie_margin &&
                            diff >= -p->depth_tie_margin) {
                            out->depth_tie[idx] = 1;
                        }
                        if (!(dq > out->depth[idx])) {
                            continue;
                        }
                    }
                    if (d->depth & FXL_DEPTH_WRITE) {
                        out->depth[idx] = dq;
                        depth_set[idx] = 1;
                    }
                }
                out->drawn[idx] = 1;
                out->tri[idx] = n;
                out->u[idx] = ut;
                out->v[idx] = vt;
                out->lod[idx] = lod;
                for (k = 0; k < 3; ++k) {
                    out->rgb[3 * idx + (size_t)k] = rgb[k];
                }
                if (tex) {
                    int32_t tx = ref_wrap((fxl_wrap_t)tex->wrap_u, (int64_t)floor(ut), (int32_t)w0);
                    int32_t ty = ref_wrap((fxl_wrap_t)tex->wrap_v, (int64_t)floor(vt), (int32_t)h0);
                    out->tex_x[idx] = tx < 0 ? REF_NO_TEXEL : tx;
                    out->tex_y[idx] = ty < 0 ? REF_NO_TEXEL : ty;
                }
            }
        }
    }
    free(depth_set);
    return FXL_OK;
}
