/* src/texgen.c - texture coordinates from positions: planar, cylindrical,
 * spherical, cube map (the "texture map shapes"). Conventions are in
 * pipeline.h and docs/pipeline.md.
 *
 * The work is split in two: fxl__texgen_vertex() does what depends on one
 * vertex alone (the atan2 and square roots of the polar maps, the planar
 * pick), so the pipeline's vertex cache can keep it; fxl__texgen_finish()
 * does per triangle what needs the other vertices: the seam (u jumps from
 * ~1 to ~0 where theta wraps: shifting u by whole periods keeps the
 * triangle from stretching the whole texture across itself) and the poles
 * (theta is undefined on the axis). The cube map also picks one face per
 * triangle so a triangle never spans two atlas tiles.
 */
#include "pipeline_int.h"
#include "div64.h"

void fxl_texgen_defaults(fxl_texgen_t *tg)
{
    if (!tg) return;
    tg->mode = FXL_TEXGEN_NONE;
    tg->space = FXL_TEXGEN_OBJECT;
    tg->plane = FXL_PLANE_XY;
    tg->axis = FXL_AXIS_Y;
    tg->scale_u = tg->scale_v = FXL_Q16_ONE;
    tg->offset_u = tg->offset_v = 0;
}

/* (a, b, h) for an axis: X -> (y, z, x), Y -> (z, x, y), Z -> (x, y, z). */
static void axis_frame(int axis, const fxl_vec3_t *p, int64_t *a, int64_t *b, int64_t *h)
{
    if (axis == FXL_AXIS_X) { *a = p->y; *b = p->z; *h = p->x; }
    else if (axis == FXL_AXIS_Y) { *a = p->z; *b = p->x; *h = p->y; }
    else { *a = p->x; *b = p->y; *h = p->z; }
}

static int64_t mag(int64_t x) { return x < 0 ? -x : x; }

/* Cylindrical / spherical raw (u, v) in q16 plus the pole flag of one
 * vertex: u in [0, 65536], v in [0, 65536] (spherical) or h (cylindrical). */
static void polar(const fxl_texgen_t *tg, const fxl_vec3_t *pos, int32_t out[3])
{
    int64_t a, b, h, h0, r, m;
    int k = 0;
    axis_frame(tg->axis, pos, &a, &b, &h);
    h0 = h;
    out[0] = (int32_t)((fxl__atan2_q32(b, a) + 0x8000u) >> 16); /* [0, 65536] */
    /* r and phi depend only on the ratios of a, b, h: scaled up to just
     * below 2^30, r's floored square root errs by 2^-30 of the largest
     * rather than by 2^-16 of a unit (v was 31 LSB off at |p| = 0.01,
     * 1.7 at 0.25). |a|, |b| < 2^31: a^2 + b^2 < 2^63 fits in uint64. */
    m = mag(a) | mag(b) | mag(h);
    if (m != 0 && m < ((int64_t)1 << 29))
        k = fxl_clz64((uint64_t)m) - 34;   /* m 2^k in [2^29, 2^30) */
    a *= (int64_t)1 << k;
    b *= (int64_t)1 << k;
    h *= (int64_t)1 << k;
    r = (int64_t)fxl__isqrt64((uint64_t)(a * a) + (uint64_t)(b * b));
    if (tg->mode == FXL_TEXGEN_SPHERICAL) {
        /* Within 2^-10 rad of the axis, seen from the centre, theta turns
         * faster than the texture can show: a pole. */
        out[2] = r * 1024 <= mag(h);
        /* phi in [0, 2^31] q32 turns; v = phi / half turn, q16. */
        out[1] = (int32_t)((fxl__atan2_q32(r, h) + 0x4000u) >> 15);
    } else {
        /* A cylinder's theta does not depend on h: a pole is a vertex
         * within 2^-14 (|h| + 1) of the axis, where the q16 rounding of an
         * eye-space transform (entries to 2^-16) can put a point that lies
         * on it. Measured against |h| as the sphere's rule is, a tall
         * cylinder (|h| > 1024 r) lost every u to 0. In the scaled units:
         * r 2^14 <= |h| + 2^(16 + k), below 2^46. */
        out[2] = r * 16384 <= mag(h) + ((int64_t)65536 << k);
        out[1] = (int32_t)h0; /* h is a q16 input coordinate */
    }
}

/* The non-pole u's shifted by whole periods to span as little as they can
 * (the circle cut at the widest gap between them), the first of them kept
 * where it is. Shifting each to within half a period of the first
 * instead would leave 0.5, 0.75, 0 spanning 0.75 where 0.5, 0.75, 1 spans
 * 0.5 (a review). */
static void fix_seam(int64_t u[3], const int pole[3])
{
    int64_t w[3], gap = -1, lo = 65536, hi = 0;
    int idx[3], n = 0, i, j, cut = 0;
    for (i = 0; i < 3; i++)
        if (!pole[i]) {   /* u in [0, 65536] (atan2) */
            lo = u[i] < lo ? u[i] : lo;
            hi = u[i] > hi ? u[i] : hi;
        }
    /* Within half a period of each other (most triangles: away from the
     * seam) the gap across the period is the widest: nothing moves (nor
     * with fewer than two non-pole vertices: hi <= lo). The sort below,
     * for every triangle, cost the sphere's front end 7% a vertex on a
     * Cortex-M4. */
    if (hi - lo <= 32768) return;
    for (i = 0; i < 3; i++)
        if (!pole[i]) {
            /* u in [0, 65536] (atan2): one period's representative */
            w[n] = u[i] & 65535;
            idx[n++] = i;
        }
    if (n < 2) return;
    /* sorted by w (at most three: insertion) */
    for (i = 1; i < n; i++)
        for (j = i; j > 0 && w[j] < w[j - 1]; j--) {
            const int64_t tw = w[j];
            const int ti = idx[j];
            w[j] = w[j - 1]; w[j - 1] = tw;
            idx[j] = idx[j - 1]; idx[j - 1] = ti;
        }
    /* the widest gap, the one across the period (w[n-1] -> w[0] + 65536)
     * first: it leaves them as they are on ties */
    for (i = 0; i < n; i++) {
        const int64_t g = i == 0 ? w[0] + 65536 - w[n - 1] : w[i] - w[i - 1];
        if (g > gap) { gap = g; cut = i; }
    }
    /* those before the cut move up a period */
    for (i = 0; i < cut; i++) w[i] += 65536;
    /* then all by the periods that put the first non-pole vertex back */
    for (i = 0; i < n; i++)
        if (idx[i] == (pole[0] ? (pole[1] ? 2 : 1) : 0)) {
            const int64_t d = u[idx[i]] - w[i];   /* a whole number of periods */
            for (j = 0; j < n; j++) u[idx[j]] = w[j] + d;
            break;
        }
}

static void fix_seam_and_poles(int64_t u[3], const int pole[3])
{
    int i, count = 0;
    int64_t sum = 0;
    fix_seam(u, pole);
    for (i = 0; i < 3; i++)
        if (!pole[i]) { sum += u[i]; count++; }
    if (count == 0) { /* the whole triangle on the axis: any u will do */
        u[0] = u[1] = u[2] = 0;
        return;
    }
    for (i = 0; i < 3; i++) /* pole: the mean theta of the others */
        if (pole[i]) u[i] = fxl__fe_sdiv64(sum >= 0 ? sum + count / 2 : sum - count / 2, count);
}

/* Cube map faces (FXL_CUBE_POS_X .. NEG_Z): the position's components
 * that give the major axis ma and the face coordinates sc, tc, as
 * {axis, sign} (the OpenGL cube-map table). A table rather than a switch:
 * on Thumb-1 (Cortex-M0+) GCC compiles six cases at -Os into a jump table
 * and a call of libgcc's __gnu_thumb1_case_shi, outside what a
 * freestanding core may reference (scripts/check_freestanding.sh, strict). */
static const int8_t cube_face_map[6][3][2] = {
    {{0, 1}, {2, -1}, {1, -1}},  /* +x: ma = x,  sc = -z, tc = -y */
    {{0, -1}, {2, 1}, {1, -1}},  /* -x: ma = -x, sc = z,  tc = -y */
    {{1, 1}, {0, 1}, {2, 1}},    /* +y: ma = y,  sc = x,  tc = z */
    {{1, -1}, {0, 1}, {2, -1}},  /* -y: ma = -y, sc = x,  tc = -z */
    {{2, 1}, {0, 1}, {1, -1}},   /* +z: ma = z,  sc = x,  tc = -y */
    {{2, -1}, {0, -1}, {1, -1}}, /* -z: ma = -z, sc = -x, tc = -y */
};

/* Cube map: face from the summed positions, (s, t) on that face. */
static void cube(const fxl_vec3_t pos[3], int64_t u[3], int64_t v[3])
{
    int64_t sx = 0, sy = 0, sz = 0;
    int face, i;
    for (i = 0; i < 3; i++) { sx += pos[i].x; sy += pos[i].y; sz += pos[i].z; }
    if (mag(sx) >= mag(sy) && mag(sx) >= mag(sz)) face = sx >= 0 ? FXL_CUBE_POS_X : FXL_CUBE_NEG_X;
    else if (mag(sy) >= mag(sz)) face = sy >= 0 ? FXL_CUBE_POS_Y : FXL_CUBE_NEG_Y;
    else face = sz >= 0 ? FXL_CUBE_POS_Z : FXL_CUBE_NEG_Z;
    for (i = 0; i < 3; i++) {
        const int64_t c[3] = {pos[i].x, pos[i].y, pos[i].z};
        const int8_t(*const f)[2] = cube_face_map[face];
        int64_t ma = c[f[0][0]] * f[0][1], sc = c[f[1][0]] * f[1][1], tc = c[f[2][0]] * f[2][1], s, t;
        if (ma < 1) ma = 1; /* a vertex behind the face plane: clamped below */
        /* s = (sc / ma + 1) / 2 in q16; |sc| < 2^31 so sc * 2^15 < 2^46. */
        s = fxl__fe_sdiv64(sc * 32768 + (sc >= 0 ? ma / 2 : -(ma / 2)), ma) + 32768;
        t = fxl__fe_sdiv64(tc * 32768 + (tc >= 0 ? ma / 2 : -(ma / 2)), ma) + 32768;
        if (s < 0) s = 0;
        if (s > 65536) s = 65536;
        if (t < 0) t = 0;
        if (t > 65536) t = 65536;
        u[i] = fxl__fe_sdiv64((int64_t)(face % 3) * 65536 + s + 1, 3);
        v[i] = fxl__fe_sdiv64((int64_t)(face / 3) * 65536 + t + 1, 2);
    }
}

/* raw * scale + offset, clamped to +-INT32_MAX. Six a triangle: inline at
 * -O2 (FXL__HOT_*, the product's shift a constant), where the calls were
 * 16% of the firmware example's texgen sphere's front end. |raw| <= 2^31
 * here (int32 coordinates, q16 angles a period or two out): the sum is far
 * from overflow. */
static fxl_q16_t scale_offset(int64_t raw, fxl_q16_t scale, fxl_q16_t offset)
{
    return FXL__HOT_TO_I32(FXL__HOT_MUL_SHR_S(raw, scale, 16, NULL) + offset, NULL);
}

/* The modes are told apart by if-chains: on Thumb-1 (Cortex-M0+) GCC
 * compiles a switch of four or more cases at -Os into a table and a call of
 * libgcc's __gnu_thumb1_case_uqi, outside what a freestanding core may
 * reference (scripts/check_freestanding.sh, strict). */
static int texgen_polar(const fxl_texgen_t *tg)
{
    return tg->mode == FXL_TEXGEN_CYLINDRICAL || tg->mode == FXL_TEXGEN_SPHERICAL;
}

void fxl__texgen_vertex(const fxl_texgen_t *tg, const fxl_vec3_t *pos, int32_t out[3])
{
    out[0] = out[1] = out[2] = 0;
    if (tg->mode == FXL_TEXGEN_PLANAR) {
        out[0] = tg->plane == FXL_PLANE_YZ ? pos->y : pos->x;
        out[1] = tg->plane == FXL_PLANE_XY ? pos->y : pos->z;
    } else if (texgen_polar(tg)) {
        polar(tg, pos, out);
    } else if (tg->mode == FXL_TEXGEN_CUBE) {   /* the face is chosen per triangle */
        out[0] = pos->x;
        out[1] = pos->y;
        out[2] = pos->z;
    }
}

void fxl__texgen_finish(const fxl_texgen_t *tg, const int32_t vt[3][3], fxl_texcoord_t out[3])
{
    int64_t u[3], v[3];
    int pole[3], i;
    fxl_vec3_t pos[3];
    for (i = 0; i < 3; i++) {
        u[i] = vt[i][0];
        v[i] = vt[i][1];
        pole[i] = vt[i][2] != 0;
    }
    if (texgen_polar(tg)) {
        fix_seam_and_poles(u, pole);
    } else if (tg->mode == FXL_TEXGEN_CUBE) {
        for (i = 0; i < 3; i++) {
            pos[i].x = vt[i][0];
            pos[i].y = vt[i][1];
            pos[i].z = vt[i][2];
        }
        cube(pos, u, v);
    }   /* planar: per vertex already; none: zeros */
    for (i = 0; i < 3; i++) {
        out[i].u = scale_offset(u[i], tg->scale_u, tg->offset_u);
        out[i].v = scale_offset(v[i], tg->scale_v, tg->offset_v);
    }
}

fxl_status_t fxl_texgen_triangle(const fxl_texgen_t *tg, const fxl_vec3_t pos[3],
                                 fxl_texcoord_t out[3])
{
    int32_t vt[3][3];
    int i;
    if (!tg || !pos || !out) return FXL_ERR_ARG;
    if (tg->axis > FXL_AXIS_Z || tg->plane > FXL_PLANE_XZ || tg->space > FXL_TEXGEN_EYE ||
        tg->mode > FXL_TEXGEN_CUBE)
        return FXL_ERR_ARG;
    for (i = 0; i < 3; i++) fxl__texgen_vertex(tg, &pos[i], vt[i]);
    fxl__texgen_finish(tg, (const int32_t(*)[3])vt, out);
    return FXL_OK;
}
