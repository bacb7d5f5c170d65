/* src/pipeline.c - 64-bit helpers, vectors and matrices, the pipeline set-up,
 * the vertex path (object -> clip -> screen) and fxl_pipeline_emit.
 *
 * Precision plan (docs/pipeline.md has the figures). Inputs are q16, but
 * view and clip space are int64 q32: view * model and proj * view * model are
 * formed in q32 (proj * (view * model), each entry rounded once to 2^-32),
 * and a position becomes clip coordinates through 96-bit products. That
 * keeps x/w and near/w accurate to ~2^-30 relative for near planes down to
 * 2^-16 and depths up to the 2^20-unit clip limit, where q16 clip space
 * would lose 1/16 px already at near = 0.05.
 */
#include "pipeline_int.h"
#include "div64.h"

/* ---- 64-bit helpers ------------------------------------------------------ */

int64_t fxl__shr_round(int64_t x, unsigned sh)
{
    uint64_t m = fxl__mag64(x);
    if (sh == 0) return x;
    m = (m + ((uint64_t)1 << (sh - 1))) >> sh;
    return fxl__apply_sign(m, x < 0, NULL);
}

int64_t fxl__asr(int64_t x, unsigned sh)
{
    return fxl__asr_i(x, sh);
}

int64_t fxl__mul_shr(int64_t a, uint32_t b, unsigned sh, int *ovf)
{
    return fxl__mul_shr_i(a, b, sh, ovf);
}

int64_t fxl__mul_shr_s(int64_t a, int32_t b, unsigned sh, int *ovf)
{
    return fxl__mul_shr_s_i(a, b, sh, ovf);
}

int64_t fxl__add_sat(int64_t a, int64_t b, int *ovf)
{
    if (b > 0 && a > INT64_MAX - b) {
        if (ovf) *ovf = 1;
        return INT64_MAX;
    }
    if (b < 0 && a < -INT64_MAX - b) {
        if (ovf) *ovf = 1;
        return -INT64_MAX;
    }
    return a + b;
}

int32_t fxl__to_i32(int64_t x, int *ovf)
{
    return fxl__to_i32_i(x, ovf);
}



/* round(num / den), ties away from zero; den != 0, |num| < 2^62. */
static int64_t div_round(int64_t num, int64_t den)
{
    uint64_t n = fxl__mag64(num), d = fxl__mag64(den);
    uint64_t q = fxl__fe_udiv64(n + d / 2u, d);
    return fxl__apply_sign(q, (num < 0) != (den < 0), NULL);
}

/* ---- matrices ------------------------------------------------------------ */

void fxl_mat4_identity(fxl_mat4_t *m)
{
    int r, c;
    if (!m) return;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) m->m[r][c] = (r == c) ? FXL_Q16_ONE : 0;
}

fxl_status_t fxl_mat4_mul(fxl_mat4_t *out, const fxl_mat4_t *a, const fxl_mat4_t *b)
{
    fxl_mat4_t t;
    int r, c, k, ovf = 0;
    if (!out || !a || !b) return FXL_ERR_ARG;
    for (r = 0; r < 4; r++) {
        for (c = 0; c < 4; c++) {
            int64_t acc = 0;
            for (k = 0; k < 4; k++) /* each product |.| <= 2^62 */
                acc = fxl__add_sat(acc, (int64_t)a->m[r][k] * b->m[k][c], &ovf);
            t.m[r][c] = fxl__to_i32(fxl__shr_round(acc, 16), &ovf);
        }
    }
    *out = t;
    return ovf ? FXL_ERR_RANGE : FXL_OK;
}

/* res[r] = row r of M times in, r < rows, rounded to nearest; returns
 * nonzero when an entry saturated. */
static int mul_rows(const fxl_mat4_t *m, const fxl_q16_t in[4], int rows, fxl_q16_t *res)
{
    int r, k, ovf = 0;
    for (r = 0; r < rows; r++) {
        int64_t acc = 0;
        for (k = 0; k < 4; k++) acc = fxl__add_sat(acc, (int64_t)m->m[r][k] * in[k], &ovf);
        res[r] = fxl__to_i32(fxl__shr_round(acc, 16), &ovf);
    }
    return ovf;
}

fxl_status_t fxl_mat4_transform(const fxl_mat4_t *m, const fxl_vec4_t *v, fxl_vec4_t *out)
{
    fxl_q16_t in[4], res[4];
    int ovf;
    if (!m || !v || !out) return FXL_ERR_ARG;
    in[0] = v->x; in[1] = v->y; in[2] = v->z; in[3] = v->w;
    ovf = mul_rows(m, in, 4, res);
    out->x = res[0]; out->y = res[1]; out->z = res[2]; out->w = res[3];
    return ovf ? FXL_ERR_RANGE : FXL_OK;
}

/* Rows 0..2 only: the fourth row is never computed, so its contents (a
 * projection's, say) cannot make a point or direction transform fail. */
static fxl_status_t transform3(const fxl_mat4_t *m, const fxl_vec3_t *p, fxl_q16_t w,
                               fxl_vec3_t *out)
{
    fxl_q16_t in[4], res[3];
    int ovf;
    if (!m || !p || !out) return FXL_ERR_ARG;
    in[0] = p->x; in[1] = p->y; in[2] = p->z; in[3] = w;
    ovf = mul_rows(m, in, 3, res);
    out->x = res[0]; out->y = res[1]; out->z = res[2];
    return ovf ? FXL_ERR_RANGE : FXL_OK;
}

fxl_status_t fxl_mat4_transform_point(const fxl_mat4_t *m, const fxl_vec3_t *p, fxl_vec3_t *out)
{
    return transform3(m, p, FXL_Q16_ONE, out);
}

fxl_status_t fxl_mat4_transform_vector(const fxl_mat4_t *m, const fxl_vec3_t *v, fxl_vec3_t *out)
{
    return transform3(m, v, 0, out);
}

/* Rotation in the (i, j) coordinate plane: m[i][i] = c, m[i][j] = -s, ... */
static void rotate_plane(fxl_mat4_t *m, fxl_angle_t a, int i, int j)
{
    fxl_q16_t s, c;
    if (!m) return;
    fxl_mat4_identity(m);
    fxl_sincos_q16(a, &s, &c);
    m->m[i][i] = c; m->m[i][j] = -s;
    m->m[j][i] = s; m->m[j][j] = c;
}

void fxl_mat4_rotate_x(fxl_mat4_t *m, fxl_angle_t a) { rotate_plane(m, a, 1, 2); }
void fxl_mat4_rotate_y(fxl_mat4_t *m, fxl_angle_t a) { rotate_plane(m, a, 2, 0); }
void fxl_mat4_rotate_z(fxl_mat4_t *m, fxl_angle_t a) { rotate_plane(m, a, 0, 1); }

static fxl_status_t normalize_q30(const int64_t in[3], int64_t out[3]);

fxl_status_t fxl_mat4_rotate_axis(fxl_mat4_t *m, const fxl_vec3_t *axis, fxl_angle_t a)
{
    int64_t ax[3], len2, omc;
    int32_t s30, c30;
    int i, j;
    if (!m || !axis) return FXL_ERR_ARG;
    ax[0] = axis->x; ax[1] = axis->y; ax[2] = axis->z;
    /* A unit axis has |components| <= 1; refusing more than 2 keeps every
     * product below small: len2 < 3 * 2^34. */
    for (i = 0; i < 3; i++)
        if (ax[i] > 0x20000 || ax[i] < -0x20000) return FXL_ERR_RANGE;
    len2 = ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]; /* q32 */
    /* | |a| - 1 | <= 2^-8 exactly: |a| in q16 is sqrt(len2), so the test
     * is (2^16 - 2^8)^2 <= len2 <= (2^16 + 2^8)^2. */
    if (len2 < (int64_t)(65536 - 256) * (65536 - 256) || len2 > (int64_t)(65536 + 256) * (65536 + 256))
        return FXL_ERR_RANGE;
    /* The tolerance is for the q16 rounding of a unit axis, not a scale:
     * the axis is made unit length (q30) first, so the result is a rotation
     * (left unnormalised, an axis 2^-8 long would scale by up to 2^-6:
     * m[1][1] 1.0157 at 180 degrees about (0, 65792, 0)). */
    if (normalize_q30(ax, ax) != FXL_OK) return FXL_ERR_RANGE;
    fxl__sincos_q30(a, &s30, &c30);
    omc = ((int64_t)1 << 30) - c30; /* 1 - cos, q30, in [0, 2^31] */
    fxl_mat4_identity(m);
    /* R = c I + (1 - c) a a^T + s [a]x, in q30, rounded once to q16. */
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            int64_t aa = fxl__shr_round(ax[i] * ax[j], 30); /* q30, |.| <= 2^30 */
            int64_t e = fxl__mul_shr(aa, (uint32_t)omc, 30, NULL);
            if (i == j) {
                e += c30;
            } else {
                int k = 3 - i - j; /* the third axis */
                /* [a]x has -a_k at (0,1), (1,2), (2,0) and +a_k mirrored. */
                int64_t sk = fxl__shr_round((int64_t)s30 * ax[k], 30);
                e += ((i + 1) % 3 == j) ? -sk : sk;
            }
            m->m[i][j] = (fxl_q16_t)fxl__shr_round(e, 14);
        }
    }
    return FXL_OK;
}

void fxl_mat4_translate(fxl_mat4_t *m, fxl_q16_t x, fxl_q16_t y, fxl_q16_t z)
{
    if (!m) return;
    fxl_mat4_identity(m);
    m->m[0][3] = x; m->m[1][3] = y; m->m[2][3] = z;
}

void fxl_mat4_scale(fxl_mat4_t *m, fxl_q16_t x, fxl_q16_t y, fxl_q16_t z)
{
    if (!m) return;
    fxl_mat4_identity(m);
    m->m[0][0] = x; m->m[1][1] = y; m->m[2][2] = z;
}

/* Normalise an int64 vector to q30 (unit length). FXL_ERR_RANGE if zero.
 * Components are first brought below 2^30 so the squares sum below 2^62. */
static fxl_status_t normalize_q30(const int64_t in[3], int64_t out[3])
{
    uint64_t mx = 0, len;
    int64_t v[3];
    int i, top;
    for (i = 0; i < 3; i++) if (fxl__mag64(in[i]) > mx) mx = fxl__mag64(in[i]);
    if (mx == 0) return FXL_ERR_RANGE;
    top = 63 - fxl_clz64(mx);
    for (i = 0; i < 3; i++)
        v[i] = top > 29 ? fxl__shr_round(in[i], (unsigned)(top - 29))
                        : in[i] * ((int64_t)1 << (29 - top)); /* |.| < 2^30 */
    len = fxl__isqrt64((uint64_t)(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    if (len == 0) return FXL_ERR_RANGE;
    for (i = 0; i < 3; i++) out[i] = div_round(v[i] * ((int64_t)1 << 30), (int64_t)len);
    return FXL_OK;
}

/* out = a x b, each product floor-shifted by pre before the difference
 * and the difference rounded by post (fxl__shr_round). The caller keeps
 * every product below 2^63 and the shifted differences inside int64. */
static void cross_shr(const int64_t a[3], const int64_t b[3], unsigned pre, unsigned post, int64_t out[3])
{
    int i;
    for (i = 0; i < 3; i++) {
        const int j = i == 2 ? 0 : i + 1, k = i == 0 ? 2 : i - 1;
        out[i] = fxl__shr_round(fxl__asr(a[j] * b[k], pre) - fxl__asr(a[k] * b[j], pre), post);
    }
}

fxl_status_t fxl_mat4_look_at(fxl_mat4_t *m, const fxl_vec3_t *eye, const fxl_vec3_t *center,
                              const fxl_vec3_t *up)
{
    int64_t f[3], u0[3], s[3], u[3], e[3], d[3], w[3], tmp[3];
    int64_t t[3];
    uint64_t dmag = 0, wmag = 0;
    int i, ovf = 0;
    fxl_status_t st;
    if (!m || !eye || !center || !up) return FXL_ERR_ARG;
    e[0] = eye->x; e[1] = eye->y; e[2] = eye->z;
    d[0] = (int64_t)center->x - eye->x;
    d[1] = (int64_t)center->y - eye->y;
    d[2] = (int64_t)center->z - eye->z;
    w[0] = up->x; w[1] = up->y; w[2] = up->z;
    if ((st = normalize_q30(d, f)) != FXL_OK) return st;
    if ((st = normalize_q30(w, u0)) != FXL_OK) return st;
    /* Nearly parallel vectors give a short f x up (q60 products -> q30):
     * refuse below sin(angle) = 2^-16. */
    cross_shr(f, u0, 0, 30, tmp);
    if (fxl__mag64(tmp[0]) + fxl__mag64(tmp[1]) + fxl__mag64(tmp[2]) < ((uint64_t)1 << 14)) return FXL_ERR_RANGE;
    /* s from the inputs themselves, (center - eye) x up in integers: f and
     * up rounded to q30 and then crossed erred by a few 2^-30 / sin(angle)
     * (up to 10 q16 units of the rotation near the limit, and that times
     * |eye| in the translation). |d| < 2^32 and |up| <= 2^31: each product
     * is below 2^63, and a difference of two below 2^63 unless some |d| >=
     * 2^31 and some |up| >= 2^30; then the products are halved first (floor
     * shifts of integers: at most one unit of the products off, where |s| >=
     * 2^31 2^30 sin(angle) > 2^44 for the angles accepted: < 2^-44). */
    for (i = 0; i < 3; i++) {
        dmag |= fxl__mag64(d[i]);
        wmag |= fxl__mag64(w[i]);
    }
    cross_shr(d, w, (dmag >> 31) && (wmag >> 30), 0, tmp);
    if ((st = normalize_q30(tmp, s)) != FXL_OK) return st;
    cross_shr(s, f, 0, 30, u);
    /* eye q16 * unit q30: |product| < 2^61, the three-term sum < 2^63. */
    t[0] = -fxl__shr_round(s[0] * e[0] + s[1] * e[1] + s[2] * e[2], 30);
    t[1] = -fxl__shr_round(u[0] * e[0] + u[1] * e[1] + u[2] * e[2], 30);
    t[2] = fxl__shr_round(f[0] * e[0] + f[1] * e[1] + f[2] * e[2], 30);
    fxl_mat4_identity(m);
    for (i = 0; i < 3; i++) {
        m->m[0][i] = (fxl_q16_t)fxl__shr_round(s[i], 14);
        m->m[1][i] = (fxl_q16_t)fxl__shr_round(u[i], 14);
        m->m[2][i] = (fxl_q16_t)-fxl__shr_round(f[i], 14);
        m->m[i][3] = fxl__to_i32(t[i], &ovf);
    }
    return ovf ? FXL_ERR_RANGE : FXL_OK;
}

fxl_status_t fxl_mat4_perspective(fxl_mat4_t *m, fxl_angle_t fovy, fxl_q16_t aspect,
                                  fxl_q16_t near_q16, fxl_q16_t far_q16)
{
    int32_t s30, c30;
    int64_t f, fx, a, b;
    if (!m) return FXL_ERR_ARG;
    if (fovy == 0 || fovy >= 0x8000u || aspect <= 0 || near_q16 <= 0) return FXL_ERR_RANGE;
    if (far_q16 != 0 && far_q16 <= near_q16) return FXL_ERR_RANGE;
    /* fovy in 2^-17 turns is fovy / 2 in fxl_angle_t units, odd fovy too. */
    fxl__sincos_fine_q30((uint32_t)fovy, &s30, &c30);
    if (s30 <= 0) return FXL_ERR_RANGE;
    f = div_round((int64_t)c30 * 65536, s30);       /* cot(fovy / 2), q16 */
    fx = div_round(f * 65536, aspect);               /* f < 2^31: no overflow */
    if (f > INT32_MAX || fx > INT32_MAX) return FXL_ERR_RANGE;
    if (far_q16 == 0) {
        a = -FXL_Q16_ONE;
        b = -2 * (int64_t)near_q16;
    } else {
        int64_t d = (int64_t)near_q16 - far_q16;   /* < 0 */
        a = div_round(((int64_t)far_q16 + near_q16) * 65536, d);
        /* round(2 far near / d): 2 far near < 2^63. (2 round(far near / d)
         * was a unit off at times, and refused -2^31 + 0.77.) */
        b = div_round((int64_t)far_q16 * near_q16 * 2, d);
    }
    if (a < -INT32_MAX || b < -INT32_MAX) return FXL_ERR_RANGE;
    fxl_mat4_identity(m);
    m->m[0][0] = (fxl_q16_t)fx;
    m->m[1][1] = (fxl_q16_t)f;
    m->m[2][2] = (fxl_q16_t)a;
    m->m[2][3] = (fxl_q16_t)b;
    m->m[3][2] = -FXL_Q16_ONE;
    m->m[3][3] = 0;
    return FXL_OK;
}

/* ---- pipeline set-up -------------------------------------------------------- */

fxl_status_t fxl_pipeline_set_viewport(fxl_pipeline_t *p, int32_t x, int32_t y, int32_t w, int32_t h)
{
    if (!p) return FXL_ERR_ARG;
    if (w < 1 || h < 1 || w > FXL_TARGET_MAX_DIM || h > FXL_TARGET_MAX_DIM) return FXL_ERR_RANGE;
    if (x > FXL_TARGET_MAX_ORIGIN || x < -FXL_TARGET_MAX_ORIGIN ||
        y > FXL_TARGET_MAX_ORIGIN || y < -FXL_TARGET_MAX_ORIGIN)
        return FXL_ERR_RANGE;
    p->vp_x = x; p->vp_y = y; p->vp_w = w; p->vp_h = h;
    return FXL_OK;
}

fxl_status_t fxl_pipeline_set_perspective(fxl_pipeline_t *p, fxl_angle_t fovy, fxl_q16_t aspect,
                                          fxl_q16_t near_q16, fxl_q16_t far_q16)
{
    fxl_status_t st;
    if (!p) return FXL_ERR_ARG;
    st = fxl_mat4_perspective(&p->proj, fovy, aspect, near_q16, far_q16);
    if (st != FXL_OK) return st;
    p->near_q16 = near_q16;
    p->far_q16 = far_q16;
    return FXL_OK;
}

fxl_status_t fxl_pipeline_init(fxl_pipeline_t *p, int32_t width, int32_t height)
{
    fxl_status_t st;
    if (!p) return FXL_ERR_ARG;
    if ((st = fxl_pipeline_set_viewport(p, 0, 0, width, height)) != FXL_OK) return st;
    fxl_mat4_identity(&p->model);
    fxl_mat4_identity(&p->view);
    st = fxl_pipeline_set_perspective(p, FXL_ANGLE_DEG(60),
                                      (fxl_q16_t)div_round((int64_t)width * 65536, height),
                                      FXL_Q16_ONE, 0);
    if (st != FXL_OK) return st;
    p->cull = FXL_CULL_CW;
    p->lighting = 0;
    p->material = 0xFFFFu;
    p->light.dir.x = 0; p->light.dir.y = 0; p->light.dir.z = FXL_Q16_ONE;
    p->light.ambient[0] = p->light.ambient[1] = p->light.ambient[2] = 64;
    p->light.diffuse[0] = p->light.diffuse[1] = p->light.diffuse[2] = 191;
    fxl_texgen_defaults(&p->texgen);
    p->vcache = NULL;
    p->vcache_count = 0;
    return FXL_OK;
}

fxl_status_t fxl_pipeline_set_vertex_cache(fxl_pipeline_t *p, fxl_vcache_entry_t *entries,
                                           uint32_t count)
{
    if (!p || (!entries && count > 0)) return FXL_ERR_ARG;
    p->vcache = count > 0 ? entries : NULL;
    p->vcache_count = entries ? count : 0;
    return FXL_OK;
}

fxl_status_t fxl_pipeline_prepare(const fxl_pipeline_t *p, fxl_xform_t *xf)
{
    int r, c, k, ovf = 0;
    int32_t maxdim;
    int64_t g;
    if (!p || !xf) return FXL_ERR_ARG;
    if (p->near_q16 <= 0 || (p->far_q16 != 0 && p->far_q16 <= p->near_q16)) return FXL_ERR_RANGE;
    if (p->vp_w < 1 || p->vp_h < 1 || p->vp_w > FXL_TARGET_MAX_DIM || p->vp_h > FXL_TARGET_MAX_DIM ||
        p->vp_x > FXL_TARGET_MAX_ORIGIN || p->vp_x < -FXL_TARGET_MAX_ORIGIN ||
        p->vp_y > FXL_TARGET_MAX_ORIGIN || p->vp_y < -FXL_TARGET_MAX_ORIGIN)
        return FXL_ERR_RANGE;
    /* view * model exactly in q32 (q16 * q16 products, each |.| <= 2^62). */
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            int64_t acc = 0;
            for (k = 0; k < 4; k++)
                acc = fxl__add_sat(acc, (int64_t)p->view.m[r][k] * p->model.m[k][c], &ovf);
            xf->mv[r][c] = acc;
        }
    /* proj * mv: q16 * q32 through 96 bits, rounded to q32. */
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            int64_t acc = 0;
            for (k = 0; k < 4; k++)
                acc = fxl__add_sat(acc, fxl__mul_shr_s(xf->mv[k][c], p->proj.m[r][k], 16, &ovf), &ovf);
            xf->mvp[r][c] = acc;
        }
    if (ovf) return FXL_ERR_RANGE;
    xf->near_q32 = (int64_t)p->near_q16 * 65536;
    xf->far_q32 = (int64_t)p->far_q16 * 65536;
    /* G = FXL_GUARD_PX / max half size, rounded down so that G * half size
     * never exceeds FXL_GUARD_PX. */
    maxdim = p->vp_w > p->vp_h ? p->vp_w : p->vp_h;
    g = fxl__sdiv64((int64_t)FXL_GUARD_PX << 17, maxdim);
    if (g > ((int64_t)FXL_GUARD_MAX << 16)) g = (int64_t)FXL_GUARD_MAX << 16;
    xf->guard_q16 = (fxl_q16_t)g;
    xf->cx_q16 = ((int64_t)2 * p->vp_x + p->vp_w) * 32768;
    xf->cy_q16 = ((int64_t)2 * p->vp_y + p->vp_h) * 32768;
    xf->hw_q16 = (int64_t)p->vp_w * 32768;
    xf->hh_q16 = (int64_t)p->vp_h * 32768;
    return FXL_OK;
}

/* Row r of a q32 matrix applied to (pos, 1): q32 result. */
static int64_t row_apply(const int64_t row[4], const fxl_vec3_t *pos, int *ovf)
{
    int64_t acc = row[3];
    acc = fxl__add_sat(acc, FXL__HOT_MUL_SHR_S(row[0], pos->x, 16, ovf), ovf);
    acc = fxl__add_sat(acc, FXL__HOT_MUL_SHR_S(row[1], pos->y, 16, ovf), ovf);
    acc = fxl__add_sat(acc, FXL__HOT_MUL_SHR_S(row[2], pos->z, 16, ovf), ovf);
    return acc;
}

static int beyond_limit(int64_t v)
{
    return v >= FXL_CLIP_LIMIT_Q32 || v <= -FXL_CLIP_LIMIT_Q32;
}

fxl_status_t fxl_xform_clip(const fxl_xform_t *xf, const fxl_vec3_t *pos, fxl_clipvert_t *out)
{
    int ovf = 0;
    if (!xf || !pos || !out) return FXL_ERR_ARG;
    out->x = row_apply(xf->mvp[0], pos, &ovf);
    out->y = row_apply(xf->mvp[1], pos, &ovf);
    out->w = row_apply(xf->mvp[3], pos, &ovf);
    out->u = out->v = 0;
    out->r = out->g = out->b = 0;
    if (ovf || beyond_limit(out->x) || beyond_limit(out->y) || beyond_limit(out->w))
        return FXL_ERR_RANGE;
    return FXL_OK;
}

fxl_status_t fxl_xform_eye(const fxl_xform_t *xf, const fxl_vec3_t *pos, fxl_vec3_t *out)
{
    int ovf = 0;
    if (!xf || !pos || !out) return FXL_ERR_ARG;
    out->x = fxl__to_i32(fxl__shr_round(row_apply(xf->mv[0], pos, &ovf), 16), &ovf);
    out->y = fxl__to_i32(fxl__shr_round(row_apply(xf->mv[1], pos, &ovf), 16), &ovf);
    out->z = fxl__to_i32(fxl__shr_round(row_apply(xf->mv[2], pos, &ovf), 16), &ovf);
    return ovf ? FXL_ERR_RANGE : FXL_OK;
}

/* A channel (0..255 in q8) as `bits` bits: round(c (2^bits - 1) / 65280),
 * c clamped to 0..65280 first. In 32 bits (< 2^22 / 65280), which the
 * compiler turns into a multiply: three 64-bit divisions a corner were
 * library calls on the Cortex-M cores. */
static uint32_t pack_channel(int32_t c, unsigned bits)
{
    const uint32_t cc = c < 0 ? 0u : (c > 65280 ? 65280u : (uint32_t)c);
    return (cc * ((1u << bits) - 1u) + 32640u) / 65280u;
}

static uint16_t pack_q8(int32_t r, int32_t g, int32_t b)
{
    return (uint16_t)((pack_channel(r, 5) << 11) | (pack_channel(g, 6) << 5) | pack_channel(b, 5));
}

/* ndc (q30) -> frame pixel q16, clamping to the guard band. */
static fxl_status_t to_screen(int64_t ndc_q30, int64_t g_q30, int64_t centre, int64_t half,
                              int flip, fxl_q16_t *out)
{
    int64_t px;
    /* The clipper leaves |ndc| <= G up to its interpolation rounding (far
     * below 2^-10 G); anything beyond that was not clipped: refuse. */
    if (ndc_q30 > g_q30 + (g_q30 >> 10) || ndc_q30 < -g_q30 - (g_q30 >> 10)) return FXL_ERR_RANGE;
    if (ndc_q30 > g_q30) ndc_q30 = g_q30;
    if (ndc_q30 < -g_q30) ndc_q30 = -g_q30;
    /* |ndc| * half <= G * half <= FXL_GUARD_PX px: fits easily. */
    px = FXL__HOT_MUL_SHR(ndc_q30, (uint32_t)half, 30, NULL);
    px = flip ? centre - px : centre + px;
    *out = (fxl_q16_t)px; /* |centre| + 8192 px < 32768 px */
    return FXL_OK;
}

/* The position part of fxl_xform_project: screen x, y and inv_w from clip
 * x, y, w alone (so the vertex cache can keep it). */
static fxl_status_t project_pos(const fxl_xform_t *xf, const fxl_clipvert_t *c, fxl_vertex_t *out)
{
    int s;
    uint64_t wn, rec;
    int64_t ndc_x, ndc_y, inv_w, g_q30;
    fxl_status_t st;
    if (c->w < xf->near_q32 || c->w <= 0 || beyond_limit(c->w)) return FXL_ERR_RANGE;
    /* One reciprocal per vertex: w = wn * 2^(s - 31) with wn in [2^31, 2^32),
     * rec = 2^62 / wn in (2^30, 2^31] (31 significant bits), so
     * 1/w = rec * 2^(-31 - s). */
    s = 63 - fxl_clz64((uint64_t)c->w);
    wn = s >= 31 ? (uint64_t)c->w >> (s - 31) : (uint64_t)c->w << (31 - s);
    rec = fxl__fe_udiv64(((uint64_t)1 << 62) + wn / 2u, wn);
    /* x / w in q30 = x * rec * 2^(-1 - s); s >= 16 since w >= near >= 2^-16. */
    ndc_x = FXL__HOT_MUL_SHR(c->x, (uint32_t)rec, (unsigned)(s + 1), NULL);
    ndc_y = FXL__HOT_MUL_SHR(c->y, (uint32_t)rec, (unsigned)(s + 1), NULL);
    g_q30 = (int64_t)xf->guard_q16 << 14;
    if ((st = to_screen(ndc_x, g_q30, xf->cx_q16, xf->hw_q16, 0, &out->x)) != FXL_OK) return st;
    if ((st = to_screen(ndc_y, g_q30, xf->cy_q16, xf->hh_q16, 1, &out->y)) != FXL_OK) return st;
    /* near / w * 2^32 = near_q32 * rec * 2^(1 - s). */
    inv_w = FXL__HOT_MUL_SHR(xf->near_q32, (uint32_t)rec, (unsigned)(s - 1), NULL);
    if (inv_w > (int64_t)0xFFFFFFFFu) inv_w = 0xFFFFFFFF;
    if (inv_w < 1) inv_w = 1;
    out->inv_w = (uint32_t)inv_w;
    return FXL_OK;
}

/* The attribute part: u, v as they are, colour packed. */
static void project_attr(const fxl_clipvert_t *c, fxl_vertex_t *out)
{
    out->u = c->u;
    out->v = c->v;
    out->color = pack_q8(c->r, c->g, c->b);
}

int fxl__xform_ok(const fxl_xform_t *xf)
{
    const int64_t near_max = (int64_t)INT32_MAX * 65536;
    const int64_t half_max = (int64_t)FXL_TARGET_MAX_DIM * 32768;
    const int64_t centre_max = ((int64_t)2 * FXL_TARGET_MAX_ORIGIN + FXL_TARGET_MAX_DIM) * 32768;
    int64_t half;
    if (xf->near_q32 < 65536 || xf->near_q32 > near_max) return 0;
    if (xf->far_q32 != 0 && (xf->far_q32 <= xf->near_q32 || xf->far_q32 > near_max)) return 0;
    if (xf->hw_q16 < 32768 || xf->hw_q16 > half_max || xf->hh_q16 < 32768 || xf->hh_q16 > half_max) return 0;
    if (xf->cx_q16 < -centre_max || xf->cx_q16 > centre_max || xf->cy_q16 < -centre_max ||
        xf->cy_q16 > centre_max)
        return 0;
    /* G * half <= FXL_GUARD_PX pixels (q16 * q16: < 2^24 * 2^28). G >= 1
     * (prepare gives 4 or more): the clipper's cut points are off their
     * earlier planes by a few units of the q32 clip coordinates, which is
     * below 2^-10 G w (to_screen's tolerance) only while G w >= 2^16 units
     * (w >= near >= 2^16); a hand-made G of 2^-16 .. 2^-7 left clipped
     * vertices that fxl_xform_project refused. */
    half = xf->hw_q16 > xf->hh_q16 ? xf->hw_q16 : xf->hh_q16;
    return xf->guard_q16 >= FXL_Q16_ONE && xf->guard_q16 <= ((int32_t)FXL_GUARD_MAX << 16) &&
           (int64_t)xf->guard_q16 * half <= ((int64_t)FXL_GUARD_PX << 32);
}

/* fxl_xform_project without its checks (the mesh path's prepared xf) */
static fxl_status_t project_vertex(const fxl_xform_t *xf, const fxl_clipvert_t *c, fxl_vertex_t *out)
{
    const fxl_status_t st = project_pos(xf, c, out);
    if (st == FXL_OK) project_attr(c, out);
    return st;
}

fxl_status_t fxl_xform_project(const fxl_xform_t *xf, const fxl_clipvert_t *c, fxl_vertex_t *out)
{
    if (!xf || !c || !out) return FXL_ERR_ARG;
    if (!fxl__xform_ok(xf)) return FXL_ERR_RANGE;
    return project_vertex(xf, c, out);
}

/* ---- the mesh path ------------------------------------------------------------ */

/* RGB565 -> channels 0..255 in q8: round(c * 65280 / 31) (or / 63). */
static void unpack_q8(uint16_t c, fxl_clipvert_t *v)
{
    v->r = (int32_t)((((uint32_t)c >> 11) * 65280u + 15u) / 31u);
    v->g = (int32_t)(((((uint32_t)c >> 5) & 63u) * 65280u + 31u) / 63u);
    v->b = (int32_t)((((uint32_t)c & 31u) * 65280u + 15u) / 31u);
}

/* Object-space normal -> unit eye-space normal (view * model's 3x3, then
 * renormalised: right for rotations and uniform scales). */
static void eye_normal(const fxl_xform_t *xf, const fxl_vec3_t *n, fxl_vec3_t *out)
{
    int64_t e[3], u[3];
    int r;
    for (r = 0; r < 3; r++) {
        int64_t acc = FXL__HOT_MUL_SHR_S(xf->mv[r][0], n->x, 16, NULL);
        acc = fxl__add_sat(acc, FXL__HOT_MUL_SHR_S(xf->mv[r][1], n->y, 16, NULL), NULL);
        e[r] = fxl__add_sat(acc, FXL__HOT_MUL_SHR_S(xf->mv[r][2], n->z, 16, NULL), NULL);
    }
    if (normalize_q30(e, u) != FXL_OK) {
        out->x = out->y = out->z = 0; /* no normal: ambient only */
        return;
    }
    out->x = (fxl_q16_t)fxl__shr_round(u[0], 14);
    out->y = (fxl_q16_t)fxl__shr_round(u[1], 14);
    out->z = (fxl_q16_t)fxl__shr_round(u[2], 14);
}

static int32_t snap(fxl_q16_t x)
{
    /* raster.h: round to the sub-pixel grid, ties toward +inf */
    return (int32_t)fxl__asr((int64_t)x + ((int64_t)1 << (15 - FXL_SUBPIXEL_BITS)),
                             16 - FXL_SUBPIXEL_BITS);
}

/* Winding of the snapped triangle as seen on the display: > 0 clockwise
 * (x right, y down), < 0 counter-clockwise. */
static int64_t snapped_area2(const fxl_vertex_t *a, const fxl_vertex_t *b, const fxl_vertex_t *c)
{
    int64_t ax = snap(a->x), ay = snap(a->y);
    int64_t bx = snap(b->x) - ax, by = snap(b->y) - ay, cx = snap(c->x) - ax, cy = snap(c->y) - ay;
    return bx * cy - cx * by; /* |coords| < 2^20 grid units: products < 2^42 */
}

/* Everything about mesh vertex i that does not depend on the triangle:
 * clip position, lit colour, per-vertex texgen data. e->tag is left alone. */
static fxl_status_t vertex_compute(const fxl_pipeline_t *p, const fxl_xform_t *xf,
                                   const fxl_mesh_t *m, uint32_t i, fxl_vcache_entry_t *e)
{
    fxl_clipvert_t c;
    fxl_status_t st;
    uint16_t colour;
    if ((st = fxl_xform_clip(xf, &m->pos[i], &c)) != FXL_OK) return st;
    e->x = c.x;
    e->y = c.y;
    e->w = c.w;
    e->outcode = (uint8_t)fxl__clip_outcode(xf, c.x, c.y, c.w);
    colour = m->color ? m->color[i] : p->material;
    if (p->lighting && m->normal) {
        fxl_vec3_t ne;
        eye_normal(xf, &m->normal[i], &ne);
        colour = fxl_light_shade(&p->light, &ne, colour);
    }
    e->color = colour;
    if (p->texgen.mode != FXL_TEXGEN_NONE) {
        fxl_vec3_t tp;
        if (p->texgen.space == FXL_TEXGEN_EYE) {
            if ((st = fxl_xform_eye(xf, &m->pos[i], &tp)) != FXL_OK) return st;
        } else {
            tp = m->pos[i];
        }
        fxl__texgen_vertex(&p->texgen, &tp, e->tex);
    } else {
        e->tex[0] = e->tex[1] = e->tex[2] = 0;
    }
    e->projected = 0;
    return FXL_OK;
}

/* Screen vertex of a triangle inside every clip plane (so its x, y, inv_w
 * depend on the mesh vertex alone): from the cache entry when it still
 * holds vertex idx and was projected, else projected now and kept. The
 * attributes are the corner's: u, v from c, and the colour as it is
 * (packing it from q8 channels as the clipper's path does gives back every
 * RGB565 value unchanged: test_pipeline checks all 65,536). */
static fxl_status_t project_inside(const fxl_xform_t *xf, fxl_vcache_entry_t *cache, uint32_t ncache,
                                   uint32_t idx, const fxl_clipvert_t *c, uint16_t colour, fxl_vertex_t *out)
{
    fxl_status_t st;
    if (ncache) {
        fxl_vcache_entry_t *e = &cache[idx < ncache ? idx : idx % ncache];
        if (e->tag == idx && e->projected) {
            out->x = e->sx;
            out->y = e->sy;
            out->inv_w = e->inv_w;
        } else {
            if ((st = project_pos(xf, c, out)) != FXL_OK) return st;
            if (e->tag == idx) { /* not evicted by another corner meanwhile */
                e->sx = out->x;
                e->sy = out->y;
                e->inv_w = out->inv_w;
                e->projected = 1;
            }
        }
    } else if ((st = project_pos(xf, c, out)) != FXL_OK) {
        return st;
    }
    out->u = c->u;
    out->v = c->v;
    out->color = colour;
    return FXL_OK;
}

fxl_status_t fxl_pipeline_emit(const fxl_pipeline_t *p, const fxl_mesh_t *m, fxl_emit_fn fn,
                               void *user, fxl_stats_t *stats)
{
    fxl_xform_t xf;
    fxl_status_t st;
    fxl_vcache_entry_t *cache = p ? p->vcache : NULL;
    uint32_t t, ncache = 0;
    if (!p || !m || !fn || !m->pos || (!m->idx && m->tri_count)) return FXL_ERR_ARG;
    if (p->cull > FXL_CULL_CCW || p->texgen.mode > FXL_TEXGEN_CUBE) return FXL_ERR_ARG;
    if (p->texgen.mode != FXL_TEXGEN_NONE && m->tri_count > 0 &&
        (p->texgen.axis > FXL_AXIS_Z || p->texgen.plane > FXL_PLANE_XZ ||
         p->texgen.space > FXL_TEXGEN_EYE))
        return FXL_ERR_ARG;
    if ((st = fxl_pipeline_prepare(p, &xf)) != FXL_OK) return st;
    if (cache && p->vcache_count > 0) {
        /* Only entries 0 .. min(count, vert_count) - 1 can be used: empty
         * those, whatever an earlier draw left there. */
        ncache = p->vcache_count;
        for (t = 0; t < ncache && t < m->vert_count; t++) cache[t].tag = FXL_VCACHE_EMPTY;
    }
    for (t = 0; t < m->tri_count; t++) {
        /* the corners in poly[0..2]: the clipper reads them before it
         * writes its polygon there (one array less in this frame, which
         * lies under every draw of fxl_mesh_draw) */
        fxl_clipvert_t poly[FXL_CLIP_MAX_VERTS];
        fxl_vertex_t scr[FXL_CLIP_MAX_VERTS];
        int32_t vt[3][3];
        uint32_t n, k, idx3[3];
        uint16_t colour[3];
        unsigned out_all = 0xFFu, out_any = 0u; /* clip planes all / any corner lies outside */
        for (k = 0; k < 3; k++) {
            /* size_t: 3 t wraps 32 bits past 1.4 x 10^9 triangles (as in
             * fxl_draw_indexed) */
            uint32_t idx = idx3[k] = m->idx[(size_t)3 * t + k];
            fxl_vcache_entry_t local, *e = &local;
            if (idx >= m->vert_count) return FXL_ERR_RANGE;
            if (ncache) {
                /* Direct-mapped; the division only when the cache is
                 * smaller than the mesh. */
                e = &cache[idx < ncache ? idx : idx % ncache];
                if (e->tag != idx) {
                    e->tag = FXL_VCACHE_EMPTY; /* stays empty if this fails */
                    if ((st = vertex_compute(p, &xf, m, idx, e)) != FXL_OK) return st;
                    e->tag = idx;
                }
            } else if ((st = vertex_compute(p, &xf, m, idx, e)) != FXL_OK) {
                return st;
            }
            /* Copy out now: a later corner may evict this entry. */
            poly[k].x = e->x;
            poly[k].y = e->y;
            poly[k].w = e->w;
            colour[k] = e->color;
            out_all &= e->outcode;
            out_any |= e->outcode;
            if (m->uv && p->texgen.mode == FXL_TEXGEN_NONE) {
                poly[k].u = m->uv[idx].u;
                poly[k].v = m->uv[idx].v;
            } else {
                poly[k].u = poly[k].v = 0;
            }
            vt[k][0] = e->tex[0];
            vt[k][1] = e->tex[1];
            vt[k][2] = e->tex[2];
        }
        if (p->texgen.mode != FXL_TEXGEN_NONE) {
            fxl_texcoord_t tc[3];
            fxl__texgen_finish(&p->texgen, (const int32_t(*)[3])vt, tc);
            for (k = 0; k < 3; k++) { poly[k].u = tc[k].u; poly[k].v = tc[k].v; }
        }
        if (out_any == 0u) {
            /* Inside every plane: the clipper would return the corners as
             * they are. Most triangles of a scene take this path, without
             * the clipper's copies, q8 colour channels and outcodes. */
            n = 3;
            for (k = 0; k < 3; k++)
                if ((st = project_inside(&xf, cache, ncache, idx3[k], &poly[k], colour[k], &scr[k])) != FXL_OK)
                    return st;
        } else {
            if (out_all == 0u) {
                /* cut by some plane (xf is fxl_pipeline_prepare's: the
                 * unchecked forms); the cut vertices are new, so the
                 * corners' cached projections do not apply */
                for (k = 0; k < 3; k++) unpack_q8(colour[k], &poly[k]);
                if ((st = fxl__clip_triangle(&xf, poly, poly, &n)) != FXL_OK) return st;
            } else {
                n = 0; /* all three outside one plane */
            }
            if (n < 3) {
                if (stats) { stats->triangles++; stats->culled_outside++; }
                continue;
            }
            for (k = 0; k < n; k++)
                if ((st = project_vertex(&xf, &poly[k], &scr[k])) != FXL_OK) return st;
        }
        for (k = 1; k + 1 < n; k++) {
            /* The fan's triangle (0, k, k + 1) as three consecutive
             * vertices in place: scr[k - 1] is done with (the triangle
             * before used it last), so it takes scr[0]'s copy. */
            fxl_vertex_t *tri = &scr[k - 1];
            int64_t area;
            if (k > 1) tri[0] = scr[0];
            area = snapped_area2(&tri[0], &tri[1], &tri[2]);
            if ((p->cull == FXL_CULL_CW && area > 0) || (p->cull == FXL_CULL_CCW && area < 0)) {
                if (stats) { stats->triangles++; stats->culled_backface++; }
                continue;
            }
            if ((st = fn(user, tri)) < 0) return st;
        }
    }
    return FXL_OK;
}
