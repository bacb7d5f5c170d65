/* auto.c - FXL_PERSP_AUTO: the longest segment whose affine error fits the
 * budget.
 *
 * Along a span (constant Y) u = S / q with S, q linear in x, so
 *   u'  = (S_x q - S q_x) / q^2 = N / q^2,   u'' = -2 u' q_x / q,
 * and linear interpolation between exact points L pixels apart errs by at
 * most L^2 / 8 * max|u''| = L^2 * |u'| * |q_x| / (4 q)  (the formula).
 * Over the triangle N = S_x q - S q_x is linear (S_x, q_x are constants), so
 * the texel-space vector (N_u, N_v) reaches its largest norm at a vertex
 * (a norm of a linear map is convex), and q >= q_min, the smallest vertex q.
 * Hence for every span of the triangle, at its worst point:
 *   err(L) <= L^2 / 4 * |q_x| * max_i |(N_u, N_v)_i| / q_min^3   (texels).
 * The longest power of two L with err(L) <= budget is chosen, from 1 up to
 * FXL_PERSP_MAX (a span shorter than L is then one affine segment: nearly
 * constant depth gets plain affine mapping, steep triangles short segments).
 * The bound is rigorous up to the exact-point error (< 0.003 texel measured)
 * and the q16 step truncation (L * 2^-16 texel).
 */
#include "raster_int.h"

#if FXL_HAVE_AUTO
#include "sfloat.h"

/* Largest log2(|N| / q^3) on the segment from A to B (N, q linear, q > 0):
 * at an end, or where d/dt (N_A + a t) / (q_A + b t)^3 = 0, i.e.
 * t* = (a q_A - 3 b N_A) / (2 a b), when t* lies inside (0, 1). */
static int32_t seg_max_ratio(fxl__sf_t NA, fxl__sf_t NB, fxl__sf_t qA, fxl__sf_t qB)
{
    fxl__sf_t a = fxl__sf_addsub(NB, NA, -1), b = fxl__sf_addsub(qB, qA, -1);
    int32_t best = INT32_MIN / 4, r;
    if (!fxl__sf_is_zero(NA) && (r = fxl__sf_log2_q8(NA) - 3 * fxl__sf_log2_q8(qA)) > best)
        best = r;
    if (!fxl__sf_is_zero(NB) && (r = fxl__sf_log2_q8(NB) - 3 * fxl__sf_log2_q8(qB)) > best)
        best = r;
    if (!fxl__sf_is_zero(a) && !fxl__sf_is_zero(b)) {
        fxl__sf_t num = fxl__sf_addsub(fxl__sf_mul(a, qA), fxl__sf_mul(fxl__sf_make(3 * b.m, b.e), NA), -1);
        fxl__sf_t t = fxl__sf_div(fxl__sf_div(num, fxl__sf_make(2 * a.m, a.e)), b);
        if (t.m > 0 && fxl__sf_log2_q8(t) < 0) {
            fxl__sf_t Nt = fxl__sf_addsub(NA, fxl__sf_mul(a, t), 1);
            fxl__sf_t qt = fxl__sf_addsub(qA, fxl__sf_mul(b, t), 1);
            if (!fxl__sf_is_zero(Nt) && qt.m > 0 && (r = fxl__sf_log2_q8(Nt) - 3 * fxl__sf_log2_q8(qt)) > best)
                best = r;
        }
    }
    return best;
}

/* Upper bound of log2 sqrt(2^2x + 2^2y) (q8): the u and v error bounds
 * combined as the Euclidean length the metric uses, hi + 1/2 at most
 * (a plain sum would cost a whole octave, i.e. half the segment length).
 * 2^-2d is rounded up to a power of two and the table's 1/256 rounding
 * gets one step of margin. */
static int32_t log2_hypot_bound(int32_t x, int32_t y)
{
    int32_t hi = x > y ? x : y, d2 = (x > y ? x - y : y - x) / 128;   /* floor(2 d) octaves */
    uint64_t t = d2 >= 16 ? 1u : (uint64_t)65536u >> d2;                /* >= 2^-2d in q16 */
    return hi + (fxl__log2_q8(65536u + t) - 16 * 256 + 2) / 2;
}

/* N_u, N_v (texel-scaled) and q at frame point (X, Y) in subpx. */
static void n_at(const fxl__tri_t *tri, int32_t X, int32_t Y, fxl__sf_t *nu, fxl__sf_t *nv, fxl__sf_t *q)
{
    const int eu = tri->a_shift[FXL__AU] + (int)tri->tex->log2_w - 16;
    const int ev = tri->a_shift[FXL__AV] + (int)tri->tex->log2_h - 16;
    fxl__sf_t qx = fxl__sf_make((int64_t)((uint64_t)tri->q.gx * FXL__ONE), 0);
    int64_t qi = fxl__plane_at(&tri->q, tri->X0, tri->Y0, X, Y);
    int64_t su = fxl__plane_at(&tri->a[FXL__AU], tri->X0, tri->Y0, X, Y);
    int64_t sv = fxl__plane_at(&tri->a[FXL__AV], tri->X0, tri->Y0, X, Y);
    fxl__sf_t sux = fxl__sf_make((int64_t)((uint64_t)tri->a[FXL__AU].gx * FXL__ONE), eu);
    fxl__sf_t svx = fxl__sf_make((int64_t)((uint64_t)tri->a[FXL__AV].gx * FXL__ONE), ev);
    if (qi < tri->q_min)
        qi = tri->q_min;
    *q = fxl__sf_make(qi, 0);
    *nu = fxl__sf_addsub(fxl__sf_mul(sux, *q), fxl__sf_mul(fxl__sf_make(su, eu), qx), -1);
    *nv = fxl__sf_addsub(fxl__sf_mul(svx, *q), fxl__sf_mul(fxl__sf_make(sv, ev), qx), -1);
}

/* Longest log2 L <= cap with L^2 / 4 * 2^lg <= budget. */
static int fit_log2(int32_t lg, int32_t lb, int cap)
{
    /* log2 L <= (log2 budget + 2 - log2 G) / 2; the log2 table rounds to
     * 1/256, one step of margin keeps it an upper bound. */
    int32_t k = (lb + 2 * 256 - lg - 2) / 2;
    if (k < 0)
        return 0;
    k >>= 8;
    return k > cap ? cap : (int)k;
}

int fxl__auto_seg_log2(const fxl__tri_t *tri, const int32_t X[3], const int32_t Y[3])
{
    const int64_t qx_g = (int64_t)((uint64_t)tri->q.gx * FXL__ONE);
    const int64_t sux_g = (int64_t)((uint64_t)tri->a[FXL__AU].gx * FXL__ONE);
    const int64_t svx_g = (int64_t)((uint64_t)tri->a[FXL__AV].gx * FXL__ONE);
    /* Plane value units cancel in N / q^3 (both carry 2^PF per factor);
     * u in texels = (S / q) * 2^(shift_u + log2_w - 16). */
    const int eu = tri->a_shift[FXL__AU] + (int)tri->tex->log2_w - 16;
    const int ev = tri->a_shift[FXL__AV] + (int)tri->tex->log2_h - 16;
    fxl__sf_t qx = fxl__sf_make(qx_g, 0), nmax = fxl__sf_make(0, 0);
    int32_t lg, lb, minx = X[0], maxx = X[0], w;
    int i, cap = 0, k;

    if (!tri->has_uv || qx_g == 0)
        return 8;   /* constant depth along every span: affine is exact */
    /* No span is longer than the bounding box: a longer L changes nothing. */
    for (i = 1; i < 3; i++) {
        minx = X[i] < minx ? X[i] : minx;
        maxx = X[i] > maxx ? X[i] : maxx;
    }
    w = (int32_t)(((int64_t)maxx - minx) >> FXL__S) + 1;   /* widest span, px */
    while (cap < 8 && ((int32_t)1 << cap) < w)
        cap++;
    lb = fxl__log2_q8((uint64_t)tri->draw->auto_budget) - 16 * 256;
    for (i = 0; i < 3; i++) {
        int64_t qi = fxl__plane_at(&tri->q, tri->X0, tri->Y0, X[i], Y[i]);
        int64_t su = fxl__plane_at(&tri->a[FXL__AU], tri->X0, tri->Y0, X[i], Y[i]);
        int64_t sv = fxl__plane_at(&tri->a[FXL__AV], tri->X0, tri->Y0, X[i], Y[i]);
        fxl__sf_t fq = fxl__sf_make(qi, 0);
        fxl__sf_t nu = fxl__sf_addsub(fxl__sf_mul(fxl__sf_make(sux_g, eu), fq),
                                      fxl__sf_mul(fxl__sf_make(su, eu), qx), -1);
        fxl__sf_t nv = fxl__sf_addsub(fxl__sf_mul(fxl__sf_make(svx_g, ev), fq),
                                      fxl__sf_mul(fxl__sf_make(sv, ev), qx), -1);
        /* |(nu, nv)|^2, compared as squares */
        fxl__sf_t n2 = fxl__sf_addsub(fxl__sf_mul(nu, nu), fxl__sf_mul(nv, nv), 1);
        if (fxl__sf_log2_q8(n2) > fxl__sf_log2_q8(nmax))
            nmax = n2;
    }
    if (nmax.m == 0)
        return 8;
    {
        /* Cheap bound first: max |N| with min q, each over the vertices. */
        fxl__sf_t qmin = fxl__sf_make(tri->q_min, 0);
        lg = fxl__sf_log2_q8(qx) + fxl__sf_log2_q8(nmax) / 2 - 3 * fxl__sf_log2_q8(qmin);
    }
    k = fit_log2(lg, lb, cap);
    if (k >= cap)
        return k;
    /* Exact bound over the whole triangle: the max of |N_u| / q^3 and
     * |N_v| / q^3 lies at a vertex or an edge's critical point (no interior
     * maximum unless grad N is parallel to grad q). Once per triangle. */
    {
        fxl__sf_t Nu[3], Nv[3], Q[3];
        int32_t ru = INT32_MIN / 4, rv = INT32_MIN / 4;
        for (i = 0; i < 3; i++)
            n_at(tri, X[i], Y[i], &Nu[i], &Nv[i], &Q[i]);
        for (i = 0; i < 3; i++) {
            int j = (i + 1) % 3;
            int32_t a = seg_max_ratio(Nu[i], Nu[j], Q[i], Q[j]), b = seg_max_ratio(Nv[i], Nv[j], Q[i], Q[j]);
            ru = a > ru ? a : ru;
            rv = b > rv ? b : rv;
        }
        lg = fxl__sf_log2_q8(qx) + log2_hypot_bound(ru, rv);
        k = fit_log2(lg, lb, cap);
    }
    /* Refining span by span (128-pixel chunks, each with its own exact
     * bound) was tried and removed: a chunk's bound costs ~4,000 Cortex-M4
     * instructions, more than the correction points it saved once those
     * became cheap (40-degree rolled floor: 186.6 instr/px with it, 169.3
     * without). */
    return k;
}
#endif /* FXL_HAVE_AUTO */
