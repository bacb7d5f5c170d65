/* metrics.c - accuracy metrics against the reference (contract in metrics.h). */
#define _POSIX_C_SOURCE 200809L
#include "metrics.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "left_out.h"

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double metrics_percentile(double *x, size_t n, double p)
{
    size_t rank;
    double r;
    if (x == NULL || n == 0) {
        return 0;
    }
    qsort(x, n, sizeof(double), cmp_double);
    r = ceil(p / 100.0 * (double)n);
    rank = r < 1 ? 1 : (r > (double)n ? n : (size_t)r);
    return x[rank - 1];
}

fxl_status_t metrics_summarize(const double *x, size_t n, metrics_summary *out)
{
    double *copy, sum = 0;
    size_t i;
    if (out == NULL || (x == NULL && n > 0)) {
        return FXL_ERR_ARG;
    }
    memset(out, 0, sizeof(*out));
    out->n = n;
    if (n == 0) {
        return FXL_OK;
    }
    copy = malloc(n * sizeof(double));
    if (copy == NULL) {
        return FXL_ERR_NOMEM;
    }
    memcpy(copy, x, n * sizeof(double));
    for (i = 0; i < n; ++i) {
        sum += x[i];
    }
    out->p99 = metrics_percentile(copy, n, 99.0);
    out->max = copy[n - 1]; /* sorted by the percentile */
    out->mean = sum / (double)n;
    free(copy);
    return FXL_OK;
}

fxl_status_t metrics_coverage_compare(const uint8_t *ref_counts, const uint8_t *fxl_counts,
                                      size_t n, metrics_coverage *out)
{
    size_t i;
    if (ref_counts == NULL || fxl_counts == NULL || out == NULL) {
        return FXL_ERR_ARG;
    }
    memset(out, 0, sizeof(*out));
    for (i = 0; i < n; ++i) {
        unsigned r = ref_counts[i], f = fxl_counts[i];
        out->ref_pixels += r >= 1;
        out->drawn_pixels += f >= 1;
        out->mismatches += (r >= 1) != (f >= 1);
        out->holes += r >= 1 && f == 0;
        out->extra += r == 0 && f >= 1;
        out->twice += f >= 2;
        out->ref_twice += r >= 2;
        out->count_mismatches += r != f;
    }
    return FXL_OK;
}

static uint16_t swap16(uint16_t x)
{
    return (uint16_t)((x >> 8) | (x << 8));
}

/* Native RGB565 word of buffer pixel (x, y). */
static uint16_t target_pixel(const fxl_target_t *t, int32_t x, int32_t y)
{
    uint16_t w = t->pixels[(size_t)y * (size_t)t->stride + (size_t)x];
    return t->format == FXL_PIXFMT_RGB565_SWAP ? swap16(w) : w;
}

static int target_ok(const fxl_target_t *t)
{
    return t != NULL && t->pixels != NULL && t->width >= 1 && t->height >= 1 &&
           t->stride >= t->width &&
           (t->format == FXL_PIXFMT_RGB565 || t->format == FXL_PIXFMT_RGB565_SWAP);
}

fxl_status_t metrics_mask_from_target(const fxl_target_t *t, uint16_t sentinel, uint8_t *mask)
{
    int32_t x, y;
    if (!target_ok(t) || mask == NULL) {
        return FXL_ERR_ARG;
    }
    for (y = 0; y < t->height; ++y) {
        for (x = 0; x < t->width; ++x) {
            mask[(size_t)y * (size_t)t->width + (size_t)x] = target_pixel(t, x, y) != sentinel;
        }
    }
    return FXL_OK;
}

/* Grid units -> pixel containing them (floor, also for negatives). */
static int32_t floor_px(int32_t g)
{
    const int32_t s = (int32_t)1 << FXL_SUBPIXEL_BITS;
    int32_t q = g / s;
    return (g % s != 0 && g < 0) ? q - 1 : q;
}

fxl_status_t metrics_coverage_count(const fxl_vertex_t *tris, int ntri, int32_t width,
                                    int32_t height, uint8_t *counts)
{
    fxl_target_t tg;
    fxl_draw_t d;
    uint16_t *px;
    fxl_status_t st;
    int n;
    if (counts == NULL || ntri < 0 || (tris == NULL && ntri > 0) || width < 1 || height < 1 ||
        width > FXL_TARGET_MAX_DIM || height > FXL_TARGET_MAX_DIM) {
        return FXL_ERR_ARG;
    }
    memset(counts, 0, (size_t)width * (size_t)height);
    px = calloc((size_t)width * (size_t)height, sizeof(uint16_t));
    if (px == NULL) {
        return FXL_ERR_NOMEM;
    }
    st = fxl_target_init(&tg, px, width, height, width, drawable_rgb565());
    fxl_draw_defaults(&d);
    d.texture = flat_white_texture();   /* untextured, or white where a build has no such draws */
    d.depth = 0;
    d.shade = FXL_SHADE_FLAT;
    d.color = 0xFFFFu;
    for (n = 0; n < ntri && st == FXL_OK; ++n) {
        const fxl_vertex_t *v = &tris[3 * n];
        /* Bounding box of the snapped vertices, widened by a pixel: every
         * pixel the triangle can cover has its centre inside. */
        int32_t gx[3], gy[3], k, x, y;
        fxl_rect_t r;
        for (k = 0; k < 3; ++k) {
            gx[k] = floor_px(ref_snap(v[k].x));
            gy[k] = floor_px(ref_snap(v[k].y));
        }
        r.x0 = gx[0] < gx[1] ? gx[0] : gx[1];
        r.x0 = (r.x0 < gx[2] ? r.x0 : gx[2]) - 1;
        r.y0 = gy[0] < gy[1] ? gy[0] : gy[1];
        r.y0 = (r.y0 < gy[2] ? r.y0 : gy[2]) - 1;
        r.x1 = gx[0] > gx[1] ? gx[0] : gx[1];
        r.x1 = (r.x1 > gx[2] ? r.x1 : gx[2]) + 2;
        r.y1 = gy[0] > gy[1] ? gy[0] : gy[1];
        r.y1 = (r.y1 > gy[2] ? r.y1 : gy[2]) + 2;
        st = fxl_target_set_clip(&tg, &r);
        if (st == FXL_OK) st = fxl_target_clear(&tg, 0);
        if (st == FXL_OK) st = fxl_draw_triangle(&tg, &d, v, NULL);
        for (y = tg.clip.y0; st == FXL_OK && y < tg.clip.y1; ++y) {
            for (x = tg.clip.x0; x < tg.clip.x1; ++x) {
                size_t i = (size_t)y * (size_t)width + (size_t)x;
                if (px[i] != 0 && counts[i] < 255) {
                    counts[i]++;
                }
            }
        }
    }
    free(px);
    return st;
}

fxl_status_t metrics_image_compare(const fxl_target_t *t, const ref_image *ref,
                                   const uint8_t *mask, metrics_image *out)
{
    static const double lsb[3] = {255.0 / 31.0, 255.0 / 63.0, 255.0 / 31.0};
    double sum = 0;
    int32_t x, y;
    int k;
    if (!target_ok(t) || ref == NULL || ref->rgb == NULL || out == NULL) {
        return FXL_ERR_ARG;
    }
    if (t->width != ref->width || t->height != ref->height || t->origin_x != ref->origin_x ||
        t->origin_y != ref->origin_y) {
        return FXL_ERR_ARG;
    }
    memset(out, 0, sizeof(*out));
    out->max_x = out->max_y = -1;
    for (y = 0; y < t->height; ++y) {
        for (x = 0; x < t->width; ++x) {
            size_t i = (size_t)y * (size_t)t->width + (size_t)x;
            double c[3];
            if (mask != NULL && mask[i] == 0) {
                continue;
            }
            ref_rgb565_to_rgb(target_pixel(t, x, y), c);
            for (k = 0; k < 3; ++k) {
                double dlt = fabs(c[k] - ref->rgb[3 * i + (size_t)k]);
                sum += dlt * dlt;
                if (dlt > out->max_diff) {
                    out->max_diff = dlt;
                    out->max_x = x;
                    out->max_y = y;
                }
                if (dlt / lsb[k] > out->max_diff_lsb) {
                    out->max_diff_lsb = dlt / lsb[k];
                }
            }
            out->pixels++;
        }
    }
    out->mse = out->pixels ? sum / (3.0 * (double)out->pixels) : 0;
    out->psnr = METRICS_PSNR_CAP;
    if (out->mse > 0) {
        double p = 10.0 * log10(255.0 * 255.0 / out->mse);
        out->psnr = p < METRICS_PSNR_CAP ? p : METRICS_PSNR_CAP;
    }
    return FXL_OK;
}

static int pow2_ok(uint32_t n)
{
    return n >= 1 && n <= 65536u && (n & (n - 1)) == 0;
}

fxl_status_t metrics_probe_fill(uint16_t *texels, uint32_t w, uint32_t h, int pass)
{
    uint32_t x, y, shift;
    if (texels == NULL || !pow2_ok(w) || !pow2_ok(h) || pass < 0 || pass > 1) {
        return FXL_ERR_ARG;
    }
    shift = (uint32_t)pass * METRICS_PROBE_BITS;
    for (y = 0; y < h; ++y) {
        for (x = 0; x < w; ++x) {
            texels[(size_t)y * w + x] = (uint16_t)((((y >> shift) & 0xFFu) << 8) | ((x >> shift) & 0xFFu));
        }
    }
    return FXL_OK;
}

fxl_status_t metrics_probe_decode(const fxl_target_t *t, int pass, int32_t *tx, int32_t *ty)
{
    int32_t x, y;
    int shift = pass * METRICS_PROBE_BITS;
    if (!target_ok(t) || tx == NULL || ty == NULL || pass < 0 || pass > 1) {
        return FXL_ERR_ARG;
    }
    for (y = 0; y < t->height; ++y) {
        for (x = 0; x < t->width; ++x) {
            size_t i = (size_t)y * (size_t)t->width + (size_t)x;
            uint16_t w = target_pixel(t, x, y);
            int32_t lx = (int32_t)(w & 0xFFu) << shift, ly = (int32_t)(w >> 8) << shift;
            if (pass == 0) {
                tx[i] = lx;
                ty[i] = ly;
            } else {
                tx[i] |= lx;
                ty[i] |= ly;
            }
        }
    }
    return FXL_OK;
}

/* Distances from e to [lo, hi) (lower) and to its centre; hi may be +inf and
 * lo -inf (clamped edge texels), the centre is then that of the edge texel. */
static void interval_dist(double e, double lo, double hi, double mid, double *lower,
                          double *centre)
{
    double l = e < lo ? lo - e : (e >= hi ? e - hi : 0);
    double c = fabs(e - mid);
    if (l < *lower) *lower = l;
    if (c < *centre) *centre = c;
}

void metrics_axis_error(double e, int32_t f, int32_t n, fxl_wrap_t wrap, double *lower,
                        double *centre)
{
    double lo = HUGE_VAL, ce = HUGE_VAL;
    if (wrap == FXL_WRAP_CLAMP) {
        double a = f == 0 ? -HUGE_VAL : (double)f;
        double b = f == n - 1 ? HUGE_VAL : (double)f + 1;
        interval_dist(e, a, b, (double)f + 0.5, &lo, &ce);
    } else {
        /* repeat: images f + k n; mirror: f + 2 k n and 2n - 1 - f + 2 k n */
        double period = wrap == FXL_WRAP_MIRROR ? 2.0 * n : (double)n;
        int images = wrap == FXL_WRAP_MIRROR ? 2 : 1;
        int m, dk;
        for (m = 0; m < images; ++m) {
            double base = m == 0 ? (double)f : 2.0 * n - 1.0 - f;
            double k = floor((e - base) / period);
            for (dk = -1; dk <= 2; ++dk) {
                double a = base + (k + dk) * period;
                interval_dist(e, a, a + 1, a + 0.5, &lo, &ce);
            }
        }
    }
    if (lower) *lower = lo;
    if (centre) *centre = ce;
}

fxl_status_t metrics_texcoord_compare(const ref_image *ref, const int32_t *tx, const int32_t *ty,
                                      const uint8_t *mask, uint32_t tex_w, uint32_t tex_h,
                                      fxl_wrap_t wrap_u, fxl_wrap_t wrap_v,
                                      metrics_texcoord *out)
{
    size_t n, i, m = 0;
    double *lb, *cd;
    fxl_status_t st;
    if (ref == NULL || tx == NULL || ty == NULL || out == NULL || ref->drawn == NULL ||
        tex_w < 1 || tex_h < 1 || tex_w > 65536u || tex_h > 65536u ||
        wrap_u > FXL_WRAP_CLAMP || wrap_v > FXL_WRAP_CLAMP) {
        return FXL_ERR_ARG;
    }
    memset(out, 0, sizeof(*out));
    n = (size_t)ref->width * (size_t)ref->height;
    lb = malloc((n ? n : 1) * sizeof(double));
    cd = malloc((n ? n : 1) * sizeof(double));
    if (lb == NULL || cd == NULL) {
        free(lb);
        free(cd);
        return FXL_ERR_NOMEM;
    }
    for (i = 0; i < n; ++i) {
        double lu, cu, lv, cv;
        if (!ref->drawn[i] || ref->depth_tie[i] || (mask != NULL && mask[i] == 0)) {
            continue;
        }
        if (tx[i] < 0 || ty[i] < 0 || (uint32_t)tx[i] >= tex_w || (uint32_t)ty[i] >= tex_h) {
            continue;
        }
        metrics_axis_error(ref->u[i], tx[i], (int32_t)tex_w, wrap_u, &lu, &cu);
        metrics_axis_error(ref->v[i], ty[i], (int32_t)tex_h, wrap_v, &lv, &cv);
        lb[m] = hypot(lu, lv);
        cd[m] = hypot(cu, cv);
        out->wrong_texel += tx[i] != ref->tex_x[i] || ty[i] != ref->tex_y[i];
        ++m;
    }
    out->pixels = m;
    out->wrong_share = m ? (double)out->wrong_texel / (double)m : 0;
    st = metrics_summarize(lb, m, &out->lower);
    if (st == FXL_OK) {
        st = metrics_summarize(cd, m, &out->centre);
    }
    free(lb);
    free(cd);
    return st;
}
