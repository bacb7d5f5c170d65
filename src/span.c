/* span.c - spans: correction points, level selection and the pixel loops.
 *
 * A span [xl, xr) of one row is cut into segments of N = 2^seg_log2 pixels
 * anchored at xl (not at the clip edge, so a pixel's value never depends on
 * the clip rectangle: bands and full frames agree bit for bit). At each
 * segment boundary u, v (and Gouraud colour, depth) are computed exactly
 * from the planes; inside a segment they are stepped linearly. The last
 * segment ends on the last pixel of the span, which is inside the triangle,
 * so no correction point is ever extrapolated outside it.
 */
#include <stddef.h>
#include "raster_int.h"
#include "texel.h"
#include "persp.h"
#include "sfloat.h"
#include "div64.h"
#include "auto.h"
#include "recip_run.h"

/* The variants (config.h, FXL_FAST_*): FXL__V(bilinear, depth, swap) is 1
 * where that one-level variant is built. A two-level (mip-linear) variant
 * also needs FXL__V_MIP and reuses the one-level pixel loop of its filter,
 * depth and format. */
#define FXL__V_NAT FXL_FAST_NATIVE
#define FXL__V_SWP FXL_FAST_SWAPPED
#define FXL__V_NOZ FXL_FAST_NO_DEPTH
#define FXL__V_Z (FXL_FAST_DEPTH && FXL_HAVE_DEPTH)
#define FXL__V_PT FXL_FAST_POINT
#define FXL__V_BL (FXL_FAST_BILINEAR && FXL_HAVE_BILINEAR)
#define FXL__V_MIP (FXL_FAST_MIP && FXL_HAVE_MIPMAP && FXL__FAST_SPANS)
/* tinted copies of the one-level variants (FXL_FAST_TINT; speed builds) */
#define FXL__V_TINT (FXL_FAST_TINT && FXL__FAST_SPANS && FXL_HAVE_GENERIC)
#define FXL__V(bil, z, sw)                                                                                  \
    (((bil) ? FXL__V_BL : FXL__V_PT) && ((z) ? FXL__V_Z : FXL__V_NOZ) && ((sw) ? FXL__V_SWP : FXL__V_NAT))
/* Size-optimised builds (no fast spans) keep one pixel loop a filter and
 * depth for both target formats, the store swapping by the target's shift
 * (fl_t, bl_t: osh), and one bilinear loop for draws with depth and
 * without, where both are kept: a NULL depth row skips the test
 * (FXL_T_DEPTH 2; its branch is small beside a bilinear sample, where the
 * point loop's registers spilled). That costs ~2 Cortex-M4 instructions a
 * pixel and saves ~700 and ~160 bytes (issue 4's -Os budget).
 * FXL__VB(bil, z): a variant of that filter and depth is kept, in either
 * format. */
#define FXL__FMT_RUNTIME (!FXL__FAST_SPANS)
#define FXL__VB(bil, z) (FXL__V(bil, z, 0) || FXL__V(bil, z, 1))
/* FXL_T_SWAP of the native variants, FXL_T_DEPTH of bilinear's with depth
 * (plain numbers: clang warns of a constant ?: in a condition) */
#if FXL__FMT_RUNTIME
#define FXL__SWAP_NAT 2
#else
#define FXL__SWAP_NAT 0
#endif
#if FXL__FMT_RUNTIME && FXL__VB(1, 0)
#define FXL__DEPTH_BL 2
#else
#define FXL__DEPTH_BL 1
#endif
/* from fxl__fast_id's value: its depth bit, and the store's byte shift
 * (8 on byte-swapped targets, else 0) */
#define FXL__FAST_ID_DEPTH(id) ((((id) - 1) >> 1) & 1)
#define FXL__FAST_ID_OSH(id) ((uint32_t)(((id) - 1) & 4) << 1)
/* What the shared helpers are built for: a one-level variant of the
 * filter (FXL__V_ANY_PT, _BL); any specialised walk (FXL__V_ANY), one
 * without depth (_NOZ) and one with (_Z). */
#define FXL__V_ANY1 ((FXL__V_PT || FXL__V_BL) && (FXL__V_NAT || FXL__V_SWP))
#define FXL__V_ANY_PT (FXL__V_PT && (FXL__V_NAT || FXL__V_SWP) && (FXL__V_NOZ || FXL__V_Z))
#define FXL__V_ANY_BL (FXL__V_BL && (FXL__V_NAT || FXL__V_SWP) && (FXL__V_NOZ || FXL__V_Z))
#define FXL__V_ANY (FXL__FAST_SPANS && FXL__V_ANY1 && (FXL__V_NOZ || FXL__V_Z))
#define FXL__V_ANY_NOZ (FXL__FAST_SPANS && FXL__V_ANY1 && FXL__V_NOZ)
#define FXL__V_ANY_Z (FXL__FAST_SPANS && FXL__V_ANY1 && FXL__V_Z)

/* Small helpers of the pixel loops and walks that GCC's inlining left out
 * of line, or compiled worse, in some builds: forced where speed counts. */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
#define FXL__HOT_INLINE inline __attribute__((always_inline))
#else
#define FXL__HOT_INLINE inline
#endif

/* The batch walk's copy for triangles of constant depth along rows
 * (FXL_T_WALK##_z0, span_walk.h) on 64-bit hosts only: on the Cortex-M4
 * (-O2) its eight copies added ~34 KB and exhausted GCC's inlining budget
 * for this file, which then left fast_correct_rc and recip_at out of line
 * in every walk, with depth or without (tunnel subdiv16 trilinear +1.4%,
 * AUTO +2.2%). */
#if FXL__FAST_SPANS && UINTPTR_MAX > 0xFFFFFFFFu
#define FXL__ZROW_WALK 1
#else
#define FXL__ZROW_WALK 0
#endif

#if defined(__GNUC__)
#define FXL__NOINLINE __attribute__((noinline))
#else
#define FXL__NOINLINE
#endif

/* ---- RGB565 arithmetic without unpacking ---------------------------------
 * expand() spreads r5 g6 b5 into 0x07E0F81F lanes (g in bits 21..26, r in
 * 11..15, b in 0..4) leaving >= 5 zero bits above each channel, so one
 * 32-bit multiply by a 5-bit weight (<= 32) scales all three at once:
 * 31 * 32 + 16 < 2^10 and 63 * 32 + 16 < 2^11 never reach the next lane. */
#if FXL_HAVE_GENERIC || FXL__V_ANY_BL
static inline uint32_t expand565(uint32_t c)
{
    return (c | (c << 16)) & 0x07E0F81Fu;
}

static inline uint32_t compact565(uint32_t x)
{
    x &= 0x07E0F81Fu;
    return (x | (x >> 16)) & 0xFFFFu;
}
#endif

#if FXL__V_TINT
/* A flat tint's factors: each channel of the colour + 1 (1..32, 1..64,
 * 1..32), as modulate565 below multiplies by them. */
typedef struct fxl__tint {
    uint32_t r, g, b;
} fxl__tint_t;
#endif

#if FXL__V_TINT && FXL__V_ANY && FXL__V_SWP
/* a byte swap (the tinted variants' stores: FXL_T_OUT names its argument
 * once; only where byte-swapped walks are built: clang warns of an unused
 * static inline function) */
static inline uint16_t fxl__swap16(uint32_t c)
{
    return (uint16_t)((c >> 8) | (c << 8));
}
#endif

#if FXL__V_TINT && FXL__V_ANY
static inline void tint_init(fxl__tint_t *k, uint32_t c)
{
    k->r = ((c >> 11) & 31u) + 1u;
    k->g = ((c >> 5) & 63u) + 1u;
    k->b = (c & 31u) + 1u;
}

/* modulate565(t, colour) for t <= 0xFFFF with each channel left in place:
 * (t & 0xF800) * r1 >> 5 is r * r1 << 6, whose bits 11..15 are those of
 * (r * r1 >> 5) << 11 because r * r1 <= 31 * 32 < 2^10 (green: 63 * 64 <
 * 2^12; blue needs no mask). Three multiplies, no unpacking. */
static inline uint32_t tint565(uint32_t t, const fxl__tint_t *k)
{
    return ((((t & 0xF800u) * k->r) >> 5) & 0xF800u) | ((((t & 0x07E0u) * k->g) >> 6) & 0x07E0u) |
           (((t & 0x001Fu) * k->b) >> 5);
}
#endif

#if FXL_HAVE_GENERIC
/* a + (b - a) * f / 32 per channel, rounded to nearest (0x02008010 adds
 * 16 to every lane), f in 0..31 (the generic loop and the mip-linear
 * variants, which need FXL_HAVE_MIPMAP and so FXL_HAVE_GENERIC). That is
 * (a (32 - f) + b f + R) >> 5 per lane; computed as (32 a + R + (b - a) f)
 * >> 5 in uint32, the same integer modulo 2^32 (see bl_sample below): one
 * multiply, and no 32 - f to keep (Cortex-M4 trilinear: floor -0.6%,
 * tunnel -0.3%; x86-64 within 0.2% either way). */
static inline uint32_t lerp565x(uint32_t a, uint32_t b, uint32_t f)
{
    return (((a << 5) + 0x02008010u + (b - a) * f) >> 5) & 0x07E0F81Fu;
}
#endif

#if FXL_HAVE_GENERIC && FXL_HAVE_BILINEAR
static inline uint32_t fxl__bilerp565(uint32_t c00, uint32_t c10, uint32_t c01, uint32_t c11, uint32_t fu,
                               uint32_t fv)
{
    /* columns first (v), then the row (u): see bl_sample below */
    uint32_t left = lerp565x(expand565(c00), expand565(c01), fv);
    uint32_t right = lerp565x(expand565(c10), expand565(c11), fv);
    return compact565(lerp565x(left, right, fu));
}
#endif

#if FXL__V_ANY
/* 1 when a segment goes to the row loops (FXL_T_ROWLOOP in span_loop.h):
 * v does not change along it (dv == 0: every pixel has one texel row and,
 * bilinear, one v weight), and it has at least 4 pixels (bilinear: the row
 * cache is separate from bl_sample's, so a shorter segment would refill it
 * for too few pixels; point: the call would cost what it saves). A wider
 * test, vv's bits 11..31 equal at both ends for |dv| < 2^16, found no more
 * such segments on the benchmark scenes and cost the others ~1 Cortex-M4
 * instruction a segment. */
static FXL__HOT_INLINE int row_fits(uint32_t dv, int32_t n)
{
    return dv == 0u && n >= 4;
}
#endif

#if FXL__V_ANY_BL
/* ---- bilinear footprint of the fast loops -----------------------------------
 * bl_sample returns the filtered colour in expanded form, equal bit for bit
 * to fxl__bilerp565 before its compact565:
 * - lerp565x(a, b, f) = (a (32 - f) + b f + R) >> 5 is computed as
 *   (32 a + R + (b - a) f) >> 5 in uint32: the same integer modulo 2^32,
 *   and the true value of every lane sum is below 2^32 (63 * 32 + 16 < 2^11
 *   at bit 21), so the bits are identical; per row it is one multiply-add
 *   with 32 a + R and b - a computed once per footprint.
 * - the 2x2 footprint is fetched and expanded only when its key changes;
 *   on a magnified texture neighbouring pixels mostly share it (4 loads and
 *   4 expansions saved). The key holds the integer parts of uu and vv,
 *   unmasked: texture sides divide 2^14, so equal keys mean the same
 *   footprint (a key that differs only by whole texture periods costs a
 *   needless fetch, nothing else). Two layouts:
 *   - with the DSP extension (Cortex-M4/M7/M33), uu's in bits 16..31 and
 *     vv's in 0..15: one PKHTB (inline assembly: GCC 12 does not form it
 *     from C). The portable form took three instructions and a register
 *     for the mask that the Cortex-M4 loops lack: it was reloaded every
 *     pixel, with spills around it (floor subdiv16 bilinear 46.0 -> 41.8
 *     instructions a pixel, trilinear -4.5%, tunnel -1.5%). Every 32-bit
 *     value is a key, so there is no "none": bl_init fetches the footprint
 *     where the first sample will be, which that sample would have
 *     fetched anyway.
 *   - elsewhere, vv's mod 2^15 in bits 16..30 and uu's in 0..15: two
 *     instructions and a constant. Bit 31 is always 0, so bl_init sets ~0,
 *     "none", and the first sample fetches.
 * Coordinates uu = u - 1/2 texel, vv = v - 1/2 texel (q16): the weights are
 * bits 11..15 (constant shifts: UBFX on a Cortex-M4), row and column the
 * bits from 16 (the row times the width only on a new footprint). */
#define FXL_RND565 0x02008010u    /* 16 in every lane: round to nearest */

/* On 64-bit cores the two columns of a footprint share one register:
 * column 1's lanes sit 32 bits above column 0's, so one multiply-add steps
 * both vertical lerps. The same identity as above holds across the halves
 * (column 0's lane sum is below 2^32, so it never reaches column 1), and
 * after the shift column 1's low bits land in bits 27..31, which the mask
 * clears: the halves are bit for bit the two 32-bit lerps. Two values a
 * footprint instead of four, and on x86-64 fewer of them spilled. */
#if UINTPTR_MAX > 0xFFFFFFFFu
#define FXL__BL64 1
#define FXL_MASK565_2 UINT64_C(0x07E0F81F07E0F81F)
#define FXL_RND565_2 UINT64_C(0x0200801002008010)
#else
#define FXL__BL64 0
#endif

typedef struct bl {
    const uint16_t *tex;
    uint32_t mu, mv, lw;          /* mask_u, mask_v, log2 width */
    uint32_t key;
#if FXL__BL64
    uint64_t a, d;                /* 32 e0 + R, e1 - e0 for row 0 and 1, column 1 in the high half */
#else
    uint32_t a0, d0, a1, d1;      /* 32 e00 + R, e01 - e00; the same for column 1 */
#endif
#if FXL__FAST_SPANS
    /* the row loop's state (bl_row_t below), kept across segments: the v
     * bucket hv (vv >> 11, ~0 none) whose texel rows ht0, ht1 and weight
     * hfv these are, and the footprint hkey (uu >> 16), ha, hd in it */
    const uint16_t *ht0, *ht1;
    uint32_t hv, hfv, hkey, ha, hd;
#endif
#if FXL__FMT_RUNTIME
    uint32_t osh;   /* as fl_t's */
#endif
#if FXL__V_TINT
    fxl__tint_t tint;   /* the tinted variants' factors (FXL_T_TINT) */
#endif
} bl_t;

#if defined(__GNUC__) && defined(__ARM_FEATURE_DSP) && defined(__thumb2__)
#define FXL__BL_PKH 1
#else
#define FXL__BL_PKH 0
#endif

static inline uint32_t bl_key(uint32_t uu, uint32_t vv)
{
#if FXL__BL_PKH
    uint32_t key;   /* (uu & 0xFFFF0000) | (vv >> 16) */
    __asm__("pkhtb %0, %1, %2, asr #16" : "=r"(key) : "r"(uu), "r"(vv));
    return key;
#else
    return (vv & 0x7FFF0000u) | (uu >> 16);
#endif
}

/* The footprint of key `key` at uu, vv: the cache's fetch. */
static FXL__HOT_INLINE void bl_refill(bl_t *b, uint32_t key, uint32_t uu, uint32_t vv)
{
    const uint32_t c0 = (uu >> 16) & b->mu, c1 = (c0 + 1u) & b->mu;
    const uint32_t rv = (vv >> 16) & b->mv;
    const uint16_t *t0 = b->tex + (rv << b->lw), *t1 = b->tex + (((rv + 1u) & b->mv) << b->lw);
#if FXL__BL64
    const uint64_t e0 = expand565(t0[c0]) | (uint64_t)expand565(t0[c1]) << 32;
    const uint64_t e1 = expand565(t1[c0]) | (uint64_t)expand565(t1[c1]) << 32;
    b->key = key;
    b->a = (e0 << 5) + FXL_RND565_2;
    b->d = e1 - e0;
#else
    const uint32_t e00 = expand565(t0[c0]), e10 = expand565(t0[c1]);
    b->key = key;
    b->a0 = (e00 << 5) + FXL_RND565;
    b->d0 = expand565(t1[c0]) - e00;
    b->a1 = (e10 << 5) + FXL_RND565;
    b->d1 = expand565(t1[c1]) - e10;
#endif
}

/* Level lv, with u, v (q16 texels) where the first sample will be: with
 * PKHTB keys the footprint there is fetched now (its first sample would
 * have fetched it), which makes the key valid; any u, v are correct. */
static inline void bl_init(bl_t *b, const fxl__level_t *lv, uint32_t u, uint32_t v)
{
    b->tex = (const uint16_t *)lv->texels;
    b->mu = lv->mask_u;
    b->mv = lv->mask_v;
    b->lw = lv->log2_w;
#if FXL__BL_PKH
    bl_refill(b, bl_key(u - 0x8000u, v - 0x8000u), u - 0x8000u, v - 0x8000u);
#else
    (void)u;
    (void)v;
    b->key = 0xFFFFFFFFu;
#if FXL__BL64
    b->a = b->d = 0;
#else
    b->a0 = b->d0 = b->a1 = b->d1 = 0;
#endif
#endif
#if FXL__FAST_SPANS
    b->hv = 0xFFFFFFFFu;     /* none: bl_row_begin sets the rest */
#endif
}

static inline uint32_t bl_sample(bl_t *b, uint32_t uu, uint32_t vv)
{
    const uint32_t key = bl_key(uu, vv);
    const uint32_t fu = (uu >> 11) & 31u, fv = (vv >> 11) & 31u;
    uint32_t left, right;

    if (key != b->key)
        bl_refill(b, key, uu, vv);
#if FXL__BL64
    {
        const uint64_t lr = ((b->a + b->d * fv) >> 5) & FXL_MASK565_2;
        left = (uint32_t)lr;
        right = (uint32_t)(lr >> 32);
    }
#else
    left = ((b->a0 + b->d0 * fv) >> 5) & 0x07E0F81Fu;
    right = ((b->a1 + b->d1 * fv) >> 5) & 0x07E0F81Fu;
#endif
    return (((left << 5) + FXL_RND565 + (right - left) * fu) >> 5) & 0x07E0F81Fu;
}

#if FXL__FAST_SPANS
/* ---- segments on one row of texels with one v weight ----------------------
 * Where v does not change over a whole segment (dv == 0, row_fits: a level
 * floor's rows), every pixel of it reads the same two texel rows with the
 * same fv, so the vertical lerps depend on the column alone: bl_row_refill does
 * them once a footprint, and a pixel is one lerp in u. The bits are those
 * of bl_sample, which lerps the columns first for this reason: the same
 * three lerps, in the same order. The key is uu >> 16 alone. */
/* no footprint: no uu >> 16 (< 2^16) is this or one off it */
#define FXL__ROW_NONE 0x80000000u

typedef struct bl_row {
    const uint16_t *t0, *t1;      /* the two texel rows */
    uint32_t mu, fv;              /* mask_u; the segment's v weight */
    uint32_t key, a, d;           /* uu >> 16 of the footprint (FXL__ROW_NONE: none);
                                   * 32 left + R, right - left */
} bl_row_t;

/* A span's segments on one row share its bucket: the rows are found once. */
static FXL__HOT_INLINE void bl_row_begin(bl_t *b, bl_row_t *r, uint32_t vv)
{
    if (b->hv != vv >> 11) {
        const uint32_t rv = (vv >> 16) & b->mv;
        b->ht0 = b->tex + (rv << b->lw);
        b->ht1 = b->tex + (((rv + 1u) & b->mv) << b->lw);
        b->hfv = (vv >> 11) & 31u;
        b->hv = vv >> 11;
        b->hkey = FXL__ROW_NONE;
        b->ha = b->hd = 0;
    }
    r->t0 = b->ht0;
    r->t1 = b->ht1;
    r->mu = b->mu;
    r->fv = b->hfv;
    r->key = b->hkey;
    r->a = b->ha;
    r->d = b->hd;
}

static FXL__HOT_INLINE void bl_row_end(bl_t *b, const bl_row_t *r)
{
    b->hkey = r->key;
    b->ha = r->a;
    b->hd = r->d;
}

/* Column c of the footprint, lerped in v: 32 e0 + R + (e1 - e0) fv, >> 5. */
static FXL__HOT_INLINE uint32_t bl_row_col(const bl_row_t *r, uint32_t c)
{
    const uint32_t e0 = expand565(r->t0[c]);
    return (((e0 << 5) + FXL_RND565 + (expand565(r->t1[c]) - e0) * r->fv) >> 5) & 0x07E0F81Fu;
}

/* The footprint of key `key`. On 64-bit hosts a key one column right (left)
 * of the cached one reuses its right (left) column, which a = 32 left + R,
 * d = right - left give back exactly: on the level floor most misses are one
 * column over, and they fetch 2 texels instead of 4 (x86-64 floor subdiv16
 * bilinear with depth 53.8 -> 50.4 instructions a pixel). On the Cortex-M4,
 * where a column is ~10 instructions, the two tests cost what they saved
 * (floor 31.2 -> 32.1). */
static FXL__HOT_INLINE void bl_row_refill(bl_row_t *r, uint32_t key)
{
    const uint32_t c0 = key & r->mu;
    uint32_t left, right;
#if FXL__BL64
    if (key == r->key + 1u) {
        left = ((r->a - FXL_RND565) >> 5) + r->d;
        right = bl_row_col(r, (c0 + 1u) & r->mu);
    } else if (key == r->key - 1u) {
        right = (r->a - FXL_RND565) >> 5;
        left = bl_row_col(r, c0);
    } else
#endif
    {
        left = bl_row_col(r, c0);
        right = bl_row_col(r, (c0 + 1u) & r->mu);
    }
    r->key = key;
    r->a = (left << 5) + FXL_RND565;
    r->d = right - left;
}

static FXL__HOT_INLINE uint32_t bl_row_sample(bl_row_t *r, uint32_t uu)
{
    const uint32_t key = uu >> 16;
    if (key != r->key)
        bl_row_refill(r, key);
    return ((r->a + r->d * ((uu >> 11) & 31u)) >> 5) & 0x07E0F81Fu;
}
#endif
#endif

/* The textures the fast pixel loops read directly: RGB565, repeat on both
 * axes, no colour key (fxl__fast_id's walks, seg_modulate, and
 * seg_generic's plain taps). */
static int tex_repeat565(const fxl_texture_t *t)
{
    return t->format == FXL_TEXFMT_RGB565 && t->wrap_u == FXL_WRAP_REPEAT && t->wrap_v == FXL_WRAP_REPEAT &&
           !(t->flags & FXL_TEXF_KEY);
}

#if FXL_HAVE_GENERIC
/* ---- the generic loop: any format, wrap, key, mip blend, texenv, shade --- */

/* Integer texel coordinate of a q16 value: repeat/mirror axes are modular
 * uint32, clamp/border axes hold a saturated int32 (floor shift). */
static int32_t texel_coord(uint32_t u, int is_signed)
{
    if (is_signed) {
        int32_t s = u <= INT32_MAX ? (int32_t)u : -(int32_t)(~u) - 1;
        return s < 0 ? -(int32_t)(((uint32_t)~s) >> 16) - 1 : s >> 16;
    }
    return (int32_t)(u >> 16);
}

/* Texel (wx, wy) of a level, the coordinates already wrapped (fxl__wrap:
 * -1 on a border axis reads the border colour) */
static uint32_t fetch(const fxl_texture_t *t, const fxl__level_t *lv, int32_t wx, int32_t wy, int *key)
{
    if (wx < 0 || wy < 0) {
        *key = 0;
        return t->border;
    }
    return fxl__texel_rgb565(t, lv->texels, ((uint32_t)wy << lv->log2_w) + (uint32_t)wx, key);
}

/* Filtered texel of one level; returns 0x10000 for "transparent". plain
 * (tex_repeat565, from seg_generic) reads the taps directly; otherwise
 * each coordinate is wrapped once, a bilinear footprint's two columns and
 * two rows, not its four taps' (at -Os, where fxl__wrap and fetch are out
 * of line, the eight calls and four fetches with their cases were ~340
 * Cortex-M4 instructions a pixel of the firmware example's lit sphere;
 * ~80 with the plain taps, fxl__bilerp565 included). */
static uint32_t sample(const fxl__tri_t *tri, const fxl__level_t *lv, uint32_t u, uint32_t v, int plain)
{
    const fxl_texture_t *t = tri->tex;
    const fxl_wrap_t wu = (fxl_wrap_t)t->wrap_u, wv = (fxl_wrap_t)t->wrap_v;
    /* plain: a tap is a mask and a read, fxl__wrap's REPEAT and
     * fxl__texel_rgb565's RGB565 without their cases or a key (the
     * texels are read as uint16_t only then: an L8 or I8 level may start
     * at an odd address) */
    const uint32_t mw = lv->mask_u, mh = lv->mask_v;
    int key;
#if FXL_HAVE_BILINEAR
    if (tri->draw->filter == FXL_FILTER_BILINEAR) {
        /* (no wrap on clamp/border axes: correct() keeps them >= INT32_MIN + 1/2 texel) */
        uint32_t uu = u - 0x8000u, vv = v - 0x8000u;
        uint32_t fu = (uu >> 11) & 31u, fv = (vv >> 11) & 31u;
        if (plain) {
            /* repeat axes: texel_coord is the plain shift */
            const uint16_t *const tx = (const uint16_t *)lv->texels;
            const uint32_t xa = (uu >> 16) & mw, xb = ((uu >> 16) + 1u) & mw;
            const uint32_t ya = ((vv >> 16) & mh) << lv->log2_w, yb = (((vv >> 16) + 1u) & mh) << lv->log2_w;
            return fxl__bilerp565(tx[ya + xa], tx[ya + xb], tx[yb + xa], tx[yb + xb], fu, fv);
        }
        int32_t x0 = texel_coord(uu, fxl__signed_u(tri)), y0 = texel_coord(vv, fxl__signed_v(tri));
        uint32_t c[4];
        int k[4], i, nearest = (fu >= 16u ? 1 : 0) + (fv >= 16u ? 2 : 0);
        /* x0 + 1 cannot overflow: |x0| <= 2^15 after the q16 shift. */
        const int32_t xw[2] = {fxl__wrap(x0, lv->log2_w, wu), fxl__wrap(x0 + 1, lv->log2_w, wu)};
        const int32_t yw[2] = {fxl__wrap(y0, lv->log2_h, wv), fxl__wrap(y0 + 1, lv->log2_h, wv)};

        for (i = 0; i < 4; i++)
            c[i] = fetch(t, lv, xw[i & 1], yw[i >> 1], &k[i]);
        if (k[nearest])
            return 0x10000u;
        /* Key texels never bleed: they take the nearest (opaque) colour. */
        for (i = 0; i < 4; i++)
            if (k[i])
                c[i] = c[nearest];
        return fxl__bilerp565(c[0], c[1], c[2], c[3], fu, fv);
    }
#endif
    if (plain)
        return ((const uint16_t *)lv->texels)[(((v >> 16) & mh) << lv->log2_w) + ((u >> 16) & mw)];
    {
        uint32_t c = fetch(t, lv, fxl__wrap(texel_coord(u, fxl__signed_u(tri)), lv->log2_w, wu),
                           fxl__wrap(texel_coord(v, fxl__signed_v(tri)), lv->log2_h, wv), &key);
        return key ? 0x10000u : c;
    }
}

/* Texel channels r5, g6, b5 times factors r1, g1, b1 (a colour channel
 * + 1, 1..32 or 1..64), >> 5 or 6, as RGB565. */
static FXL__HOT_INLINE uint32_t modulate_ch(uint32_t r, uint32_t g, uint32_t b, uint32_t r1, uint32_t g1,
                                            uint32_t b1)
{
    return (((r * r1) >> 5) << 11) | (((g * g1) >> 6) << 5) | ((b * b1) >> 5);
}

/* Per-channel t * (c + 1) >> bits: white leaves the texel unchanged. */
static FXL__HOT_INLINE uint32_t modulate565(uint32_t t, uint32_t c)
{
    return modulate_ch((t >> 11) & 31u, (t >> 5) & 63u, t & 31u, ((c >> 11) & 31u) + 1u, ((c >> 5) & 63u) + 1u,
                       (c & 31u) + 1u);
}

/* A segment loop's running values (seg_modulate_full), from the segment
 * s, and its depth modes. */
#define SEG_LOCALS()                                                                                        \
    uint32_t u = s->u, v = s->v, u2 = s->u2, v2 = s->v2, z = s->z;                                        \
    uint32_t du = (uint32_t)s->du, dv = (uint32_t)s->dv;                                                  \
    uint32_t c0 = s->c[0], c1 = s->c[1], c2 = s->c[2];                                                    \
    uint32_t written = 0;                                                                                 \
    const int ztest = s->zb && tri->depth_test, zwrite = s->zb && tri->depth_write

/* One pixel's steps in a segment loop (seg_modulate_full): u, v
 * (whose steps change in quadratic segments), the second level's u2, v2,
 * z and the Gouraud channels, from the segment s. */
#if FXL_HAVE_QUAD
#define SEG_ADVANCE()                                                                                       \
    (u += du, v += dv, du += (uint32_t)s->ddu, dv += (uint32_t)s->ddv, u2 += (uint32_t)s->du2,            \
     v2 += (uint32_t)s->dv2, z += (uint32_t)s->dz, c0 += (uint32_t)s->dc[0], c1 += (uint32_t)s->dc[1],    \
     c2 += (uint32_t)s->dc[2])
#else
#define SEG_ADVANCE()                                                                                       \
    (u += du, v += dv, u2 += (uint32_t)s->du2, v2 += (uint32_t)s->dv2, z += (uint32_t)s->dz,              \
     c0 += (uint32_t)s->dc[0], c1 += (uint32_t)s->dc[1], c2 += (uint32_t)s->dc[2])
#endif

/* seg_generic's values at pixel i of the segment, from its start and steps
 * (modulo 2^32, the values stepping gives bit for bit: fxl__seg_coord). No
 * running state: the loop keeps nothing live across pixels, and a pixel
 * computes only what it uses (stepping every value, ten loads and adds a
 * pixel, was ~40 Cortex-M4 instructions a pixel at -Os). */
#define SEG_AT(c, d) ((c) + (uint32_t)(d) * (uint32_t)i)

static uint32_t seg_generic(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    const fxl_draw_t *d = tri->draw;
    const int ztest = s->zb && tri->depth_test, zwrite = s->zb && tri->depth_write;
    const int plain = fxl__has_uv(tri) && tex_repeat565(tri->tex);
    uint32_t written = 0, ti = 0;   /* ti = i (i - 1) / 2, quadratic steps' factor (fxl__seg_coord) */
    int32_t i;

    for (i = 0; i < s->n; ti += (uint32_t)i, i++) {
        uint32_t zz = SEG_AT(s->z, s->dz) >> 16, out, col;

        if (ztest && zz <= s->zb[i])
            continue;
        col = fxl__has_color(tri) ? ((SEG_AT(s->c[0], s->dc[0]) >> 16) << 11 | (SEG_AT(s->c[1], s->dc[1]) >> 16) << 5 |
                                     SEG_AT(s->c[2], s->dc[2]) >> 16)
                                  : d->color;
        if (fxl__has_uv(tri)) {
#if FXL_HAVE_QUAD
            const uint32_t u = SEG_AT(s->u, s->du) + (uint32_t)s->ddu * ti, v = SEG_AT(s->v, s->dv) + (uint32_t)s->ddv * ti;
#else
            const uint32_t u = SEG_AT(s->u, s->du), v = SEG_AT(s->v, s->dv);
            (void)ti;
#endif
            uint32_t t = sample(tri, s->lvl, u, v, plain);
            if (s->lvl2 && t != 0x10000u && s->lod_frac_q8 != 0u) {
                uint32_t t2 = sample(tri, s->lvl2, SEG_AT(s->u2, s->du2), SEG_AT(s->v2, s->dv2), plain);
                if (t2 != 0x10000u)
                    t = compact565(lerp565x(expand565(t), expand565(t2), s->lod_frac_q8 >> 3));
            }
            if (t == 0x10000u)
                out = d->texenv == FXL_TEXENV_DECAL ? col : 0x10000u;
            else if (d->texenv == FXL_TEXENV_MODULATE)
                out = modulate565(t, col);
            else
                out = t;
        } else {
            out = col;
        }
        if (out != 0x10000u) {
            s->dst[i] = (uint16_t)(tri->swap ? ((out >> 8) | (out << 8)) : out);
            if (zwrite)
                s->zb[i] = (uint16_t)zz;
            written++;
        }
    }
    return written;
}
#undef SEG_AT

#if FXL__FAST_SPANS
/* ---- MODULATE draws of RGB565 repeat textures ---------------------------------
 * The specialised walks are for REPLACE draws (fast_id); a texture
 * modulated by a flat colour or by Gouraud colours took seg_generic, whose
 * pixel runs sample() and four fetch() calls with their format, wrap and
 * key cases: ~400 Cortex-M4 instructions a pixel of the firmware example's
 * lit sphere (bilinear, nearest level, -O2), ~160 in seg_modulate's first
 * form (the frame 11.5 M -> 7.2 M), ~87 in its specialised copies below
 * (seg_modulate_plain; 160 with bl_sample forced inline, which spilled the
 * steps). seg_modulate is seg_generic for the draws fxl__pick_seg_fn
 * gives it (RGB565, no key, repeat on both axes, MODULATE), with the texel
 * read the fast loops' way (a mask, no function); the same arithmetic
 * otherwise, so the same pixels (test_raster compares it with
 * seg_generic on the same draws through an unused colour key). Speed
 * builds only: it is flash a size build would rather keep. */
static FXL__HOT_INLINE uint32_t texel_repeat(const fxl__level_t *lv, int32_t x, int32_t y)
{
    const uint32_t xm = (uint32_t)fxl__wrap(x, lv->log2_w, FXL_WRAP_REPEAT);
    const uint32_t ym = (uint32_t)fxl__wrap(y, lv->log2_h, FXL_WRAP_REPEAT);
    return ((const uint16_t *)lv->texels)[(ym << lv->log2_w) + xm];
}

static FXL__HOT_INLINE uint32_t sample_repeat(const fxl__level_t *lv, uint32_t u, uint32_t v, int bilinear)
{
#if FXL_HAVE_BILINEAR
    if (bilinear) {
        const uint32_t uu = u - 0x8000u, vv = v - 0x8000u;
        const int32_t x0 = (int32_t)(uu >> 16), y0 = (int32_t)(vv >> 16);
        return fxl__bilerp565(texel_repeat(lv, x0, y0), texel_repeat(lv, x0 + 1, y0), texel_repeat(lv, x0, y0 + 1),
                              texel_repeat(lv, x0 + 1, y0 + 1), (uu >> 11) & 31u, (vv >> 11) & 31u);
    }
#else
    (void)bilinear;
#endif
    return texel_repeat(lv, (int32_t)(u >> 16), (int32_t)(v >> 16));
}

/* The common segment of seg_modulate, with the filter, the shading and
 * the depth mode constant: one level, affine steps (no level blend, no
 * quadratic segment), depth tested and written or not used, so the loop
 * steps u, v, z and the colours alone and keeps them in registers.
 * - Bilinear samples go through the fast loops' footprint cache where
 *   those are built (bl_sample, the fxl__bilerp565 bits in expanded form):
 *   the 2x2 footprint is fetched once for the pixels that share it, not
 *   four wrapped fetches a pixel; the channels are modulated from the
 *   expanded form (the same bits compact565 would gather).
 * - A Gouraud channel at a pixel is c >> 16 exactly as seg_generic packs
 *   it: the corrections clamp each channel to its vertex range (within 31
 *   << 16 or 63 << 16) and the steps, truncated toward zero, never pass the
 *   segment's end, so no channel reaches the next one's bits. The
 *   channels are stepped with the + 1 of modulate565 already added. */
static FXL__HOT_INLINE uint32_t seg_modulate_plain(const fxl__tri_t *tri, const fxl__seg_t *s, const int bilinear,
                                                   const int gouraud, const int depth)
{
    const fxl__level_t *lv = s->lvl;
    const uint32_t one = 0x10000u;   /* modulate565's + 1, in q16 */
    uint32_t u = s->u, v = s->v, z = s->z, c0 = s->c[0] + one, c1 = s->c[1] + one, c2 = s->c[2] + one;
    const uint32_t du = (uint32_t)s->du, dv = (uint32_t)s->dv, dz = (uint32_t)s->dz;
    const uint32_t dc0 = (uint32_t)s->dc[0], dc1 = (uint32_t)s->dc[1], dc2 = (uint32_t)s->dc[2];
    const uint32_t flat = tri->draw->color;
    const uint32_t fr = ((flat >> 11) & 31u) + 1u, fg = ((flat >> 5) & 63u) + 1u, fb = (flat & 31u) + 1u;
    uint16_t *const dst = s->dst, *const zb = s->zb;
    const unsigned osh = tri->swap ? 8u : 0u;
    uint32_t written = 0;
    int32_t i;
#if FXL__V_ANY_BL
    bl_t L;
    if (bilinear)
        bl_init(&L, lv, u, v);
#endif

    for (i = 0; i < s->n; i++) {
        const uint32_t zz = z >> 16;
        if (!depth || zz > zb[i]) {
            const uint32_t r1 = gouraud ? c0 >> 16 : fr, g1 = gouraud ? c1 >> 16 : fg, b1 = gouraud ? c2 >> 16 : fb;
            uint32_t out;
#if FXL__V_ANY_BL
            if (bilinear) {
                const uint32_t e = bl_sample(&L, u - 0x8000u, v - 0x8000u);
                out = modulate_ch((e >> 11) & 31u, (e >> 21) & 63u, e & 31u, r1, g1, b1);
            } else
#endif
            {
                const uint32_t t = sample_repeat(lv, u, v, bilinear);
                out = modulate_ch((t >> 11) & 31u, (t >> 5) & 63u, t & 31u, r1, g1, b1);
            }
            dst[i] = (uint16_t)((out >> osh) | (out << osh));
            if (depth)
                zb[i] = (uint16_t)zz;
            written++;
        }
        u += du;
        v += dv;
        z += dz;
        if (gouraud) {
            c0 += dc0;
            c1 += dc1;
            c2 += dc2;
        }
    }
    return written;
}

/* The other segments (a level blend, quadratic steps): seg_generic's
 * pixel loop for these textures. */
static FXL__NOINLINE uint32_t seg_modulate_full(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    const fxl_draw_t *d = tri->draw;
    SEG_LOCALS();
    int32_t i;
    const int bilinear = d->filter == FXL_FILTER_BILINEAR, gouraud = fxl__has_color(tri);
    const int blend = s->lvl2 && s->lod_frac_q8 != 0u;
    const unsigned osh = tri->swap ? 8u : 0u;

    for (i = 0; i < s->n; i++) {
        const uint32_t zz = z >> 16;
        if (!ztest || zz > s->zb[i]) {
            const uint32_t col = gouraud ? (((c0 >> 16) << 11) | ((c1 >> 16) << 5) | (c2 >> 16)) : d->color;
            uint32_t t = sample_repeat(s->lvl, u, v, bilinear), out;
            if (blend)
                t = compact565(lerp565x(expand565(t), expand565(sample_repeat(s->lvl2, u2, v2, bilinear)),
                                        s->lod_frac_q8 >> 3));
            out = modulate565(t, col);
            s->dst[i] = (uint16_t)((out >> osh) | (out << osh));
            if (zwrite)
                s->zb[i] = (uint16_t)zz;
            written++;
        }
        SEG_ADVANCE();
    }
    return written;
}

#define FXL__SEG_MOD 1   /* seg_modulate exists: draw_span_mod is its walk */
static uint32_t seg_modulate(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    const int gouraud = fxl__has_color(tri);
    const int ztest = s->zb && tri->depth_test, zwrite = s->zb && tri->depth_write;
#define FXL_T_MOD(bil, z)                                                                                   \
    (gouraud ? seg_modulate_plain(tri, s, bil, 1, z) : seg_modulate_plain(tri, s, bil, 0, z))
    if ((s->lvl2 && s->lod_frac_q8 != 0u) || s->ddu || s->ddv || ztest != zwrite)
        return seg_modulate_full(tri, s);
    if (tri->draw->filter == FXL_FILTER_BILINEAR)
        return ztest ? FXL_T_MOD(1, 1) : FXL_T_MOD(1, 0);
    return ztest ? FXL_T_MOD(0, 1) : FXL_T_MOD(0, 0);
#undef FXL_T_MOD
}

#endif
#endif /* FXL_HAVE_GENERIC */
#ifndef FXL__SEG_MOD
#define FXL__SEG_MOD 0
#endif

/* ---- correction points ------------------------------------------------------ */

#define PQ FXL__PQ
#define PZ FXL__PZ
#define PA FXL__PA
#define NPLANES FXL__NPLANES

typedef struct point {
    uint32_t a[FXL__NATTR];  /* u, v: level-0 texel q16; colours: channel q16 */
    uint32_t z;              /* inv_w, u0.32 */
    int64_t u64, v64;        /* u, v before wrapping (rebased), for derivatives */
    int32_t g;               /* q_x / q, q28 (quadratic segments only) */
} point_t;

/* Every field of p 0, as plain stores: `= {0}` on the generic walk's two
 * points and its planes was three memset calls a span (GCC's choice at -O2
 * and -Os; one for the reciprocal-run walk's segment), ~150 bytes that a
 * byte-wise memset (the firmware examples') took ~700 instructions over:
 * Cortex-M4 -Os cube bilinear 182.95 -> 163.18 instructions a pixel in the
 * bench firmware. */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__)
__attribute__((noinline))   /* one copy at -Os: 34 B less with seg_zero's */
#endif
static void point_zero(point_t *p)
{
    p->a[FXL__AU] = p->a[FXL__AV] = 0u;
    p->a[FXL__AR] = p->a[FXL__AG] = p->a[FXL__AB] = 0u;
    p->z = 0u;
    p->u64 = p->v64 = 0;
    p->g = 0;
}

/* Every field of seg 0 (the same plain stores for the walks' segments) */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__)
__attribute__((noinline))
#endif
static void seg_zero(fxl__seg_t *seg)
{
    seg->dst = seg->zb = 0;
    seg->n = 0;
    seg->u = seg->v = 0u;
    seg->du = seg->dv = seg->ddu = seg->ddv = 0;
    seg->z = 0u;
    seg->dz = 0;
    seg->c[0] = seg->c[1] = seg->c[2] = 0u;
    seg->dc[0] = seg->dc[1] = seg->dc[2] = 0;
    seg->lvl = seg->lvl2 = 0;
    seg->u2 = seg->v2 = 0u;
    seg->du2 = seg->dv2 = 0;
    seg->lod_frac_q8 = 0u;
    seg->lod_q8 = 0;
}

static inline uint32_t sat_u32(int64_t x)
{
    return x < 0 ? 0u : (x > (int64_t)UINT32_MAX ? UINT32_MAX : (uint32_t)x);
}

/* A clamp/border axis's coordinate saturated to [INT32_MIN + 2^15, INT32_MAX]
 * (q16 texels: -32767.5 .. 32768), as its two's-complement bit pattern.
 * Bilinear takes half a texel off for its left tap: from INT32_MIN that
 * wrapped to +32767.5 texels, the far edge (any u below -8 periods of a
 * 4096-texel texture). Steps between two such values stay inside them
 * (truncated toward zero), and every coordinate below -1 texel clamps to
 * the same edge texel or border. */
static inline uint32_t sat_i32_bits(int64_t x)
{
    if (x > INT32_MAX)
        x = INT32_MAX;
    if (x < (int64_t)INT32_MIN + 0x8000)
        x = (int64_t)INT32_MIN + 0x8000;
    return (uint32_t)(x < 0 ? (uint64_t)x + ((uint64_t)1 << 32) : (uint64_t)x);
}

/* 1/q at a correction point, q clamped below at q_min: inside the triangle
 * q >= q_min, and the clamp keeps a rounding overshoot at a sliver's tip
 * from reaching zero. A constant q takes the reciprocal set-up computed
 * (the same value: the clamp makes it q_min's), which spares affine mode
 * and faces parallel to the screen the division. */
static FXL__ALWAYS_INLINE void recip_at(const fxl__tri_t *tri, int64_t q, fxl__recip_t *rc)
{
    if (q <= tri->q_min) {
        if (tri->q_const) {
            *rc = tri->rc_qmin;
            return;
        }
        q = tri->q_min;
    }
    fxl__recip(q, rc);
}

/* What the generic walk's triangle draws (correct_t, generic_walk); in its
 * copy for seg_modulate's Gouraud draws (mod: draw_span_mod, correct_mod)
 * the answers those draws give, constants. */
#define GW_UV (mod || fxl__has_uv(tri))
#define GW_COLOR (mod || fxl__has_color(tri))
#define GW_SIGNED_U (!mod && fxl__signed_u(tri))
#define GW_SIGNED_V (!mod && fxl__signed_v(tri))
#define GW_AUTO_ROWS (!mod && tri->auto_seg == 1)
#define GW_LOD_GRID (!mod && tri->lod_grid)
#define GW_CORRECT(p) (mod ? correct_mod(tri, pv, (p)) : correct(tri, pv, (p)))

/* A correction point: z, and u, v and the colours at pv. mod: a Gouraud
 * seg_modulate draw in the generic walk's copy draw_span_mod (repeat axes,
 * no AUTO), whose tests fold away. */
static FXL__HOT_INLINE void correct_t(const fxl__tri_t *tri, const int64_t pv[NPLANES], point_t *pt, const int mod)
{
    fxl__recip_t rc;
    int64_t q = pv[PQ];
    int i;

    /* pv[PZ] >= 0 inside the triangle */
    pt->z = FXL_HAVE_DEPTH ? sat_u32(pv[PZ] >> FXL__PF) : 0u;
    if (!mod && tri->np <= PA)
        return;
    recip_at(tri, q, &rc);
    if (tri->stats)
        tri->stats->divisions++;
#if FXL_HAVE_AUTO
    pt->g = !mod && fxl__auto_quad(tri) ? fxl__quad_g(tri, &rc) : 0;
#endif
    if (GW_UV) {
        int64_t u = fxl__persp(pv[PA + FXL__AU], &rc, tri->a_shift[FXL__AU] + (int)tri->tex->log2_w);
        int64_t v = fxl__persp(pv[PA + FXL__AV], &rc, tri->a_shift[FXL__AV] + (int)tri->tex->log2_h);
        /* Repeat/mirror: modulo 2^32 is exact (the period divides it). */
        pt->a[FXL__AU] = GW_SIGNED_U ? sat_i32_bits(u) : (uint32_t)(uint64_t)u;
        pt->a[FXL__AV] = GW_SIGNED_V ? sat_i32_bits(v) : (uint32_t)(uint64_t)v;
        pt->u64 = u;
        pt->v64 = v;
    }
    if (GW_COLOR) {
        /* each channel within its vertex range (a constant colour exactly) */
        for (i = 0; i < 3; i++) {
            const int32_t lo = tri->color_lo[i], hi = tri->color_hi[i];
            if (mod && FXL__WORD32) {
                /* a channel (below 2^23) is nearly always in fxl__persp's
                 * 32-bit case: there the value and its clamp in one word
                 * (the lit sphere's corrections ~24 Cortex-M4 instructions
                 * shorter) */
                const int e = rc.n + fxl__persp_eb(tri->a_shift[FXL__AR + i]);
                if (e <= -33 && e >= -62) {
                    const int32_t c = fxl__persp_w32(fxl__persp_prod(pv[PA + FXL__AR + i], &rc), e);
                    pt->a[FXL__AR + i] = (uint32_t)(c < lo ? lo : (c > hi ? hi : c));
                    continue;
                }
            }
            {
                const int64_t c = fxl__persp(pv[PA + FXL__AR + i], &rc, tri->a_shift[FXL__AR + i]);
                pt->a[FXL__AR + i] = (uint32_t)(c < lo ? lo : (c > hi ? hi : c));
            }
        }
    }
}

static inline void correct(const fxl__tri_t *tri, const int64_t pv[NPLANES], point_t *pt)
{
    correct_t(tri, pv, pt, 0);
}

#if FXL__SEG_MOD
static FXL__NOINLINE void correct_mod(const fxl__tri_t *tri, const int64_t pv[NPLANES], point_t *pt)
{
    correct_t(tri, pv, pt, 1);
}
#else
#define correct_mod correct   /* never called: draw_span_mod is a speed-build copy */
#endif

/* p1 - p0 of coordinate u (axis 0) or v (1) as a signed step numerator:
 * for clamp axes from the saturated int32 values, for repeat and mirror
 * axes from the 64-bit ones (not the uint32 ones, which hold them modulo
 * 2^16 texels: their short-way difference is the same number while the
 * triangle is not uv_wide, and the wrong one where it is). Modular, as the
 * planes (raster_int.h): only a saturated coordinate, garbage anyway,
 * wraps. Out of line at -Os (inlined twice it was ~180 bytes of the
 * Cortex-M4 core), with pointers so the call stays small. */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__)
__attribute__((noinline))
#endif
static int64_t coord_diff(const point_t *p1, const point_t *p0, int axis, int is_signed)
{
    if (is_signed) {
        const uint32_t b = p1->a[axis], a = p0->a[axis];
        int64_t sb = b <= INT32_MAX ? (int64_t)b : (int64_t)b - ((int64_t)1 << 32);
        int64_t sa = a <= INT32_MAX ? (int64_t)a : (int64_t)a - ((int64_t)1 << 32);
        return sb - sa;
    }
    return axis ? (int64_t)((uint64_t)p1->v64 - (uint64_t)p0->v64) : (int64_t)((uint64_t)p1->u64 - (uint64_t)p0->u64);
}

static inline int32_t sat_i32(int64_t s)
{
    return s > INT32_MAX ? INT32_MAX : (s < INT32_MIN ? INT32_MIN : (int32_t)s);
}

/* diff / 2^k truncated toward zero (stepping never passes the endpoint).
 * Kept in 64 bits: a level-0 step beyond 2^31 (over 32768 texels per pixel)
 * is still exact after the shift to a smaller mip level. */
static inline int64_t step_pow2(int64_t diff, int k)
{
    /* the magnitude in uint64 and k >= 1 before negating: defined for
     * INT64_MIN too */
    if (k == 0)
        return diff;
    return diff < 0 ? -(int64_t)((0u - (uint64_t)diff) >> k) : (int64_t)((uint64_t)diff >> k);
}

static inline int64_t step_of(int64_t diff, int32_t div)
{
    if (div <= 0)
        return 0;
#if FXL__DIV32_HW
    /* a difference fitting 32 bits (almost every one): one 32-bit
     * division, truncated toward zero too (div > 0; `diff == (int32_t)diff`
     * takes the conversion as modular, as GCC and Clang define it). At -Os the 64-bit
     * loop's ~20 iterations a step were ~1 M of the firmware example's lit
     * frame on a Cortex-M4. */
    if (diff == (int32_t)diff)
        return (int32_t)diff / div;
#endif
    return fxl__sdiv64_small(diff, div);   /* truncation: stepping never overshoots the endpoint */
}

/* sat_i32 of step_pow2 (full) or step_of for a difference that fits in
 * int32, in 32-bit arithmetic: the Gouraud channels, each within [0, 63 <<
 * 16] at a correction point. C's / truncates toward zero too. */
static inline int32_t step_i32(int32_t diff, int full, int k, int32_t div)
{
    if (full)
        return diff < 0 ? -(int32_t)((0u - (uint32_t)diff) >> k) : diff >> k;
    return div > 0 ? diff / div : 0;
}

static inline uint32_t shift_coord(uint32_t c, int level, int is_signed)
{
    if (is_signed) {
        int32_t s = c <= INT32_MAX ? (int32_t)c : -(int32_t)(~c) - 1;
        s = s < 0 ? -(int32_t)(((uint32_t)~s) >> level) - 1 : s >> level;
        return (uint32_t)(s < 0 ? (uint64_t)(int64_t)s + ((uint64_t)1 << 32) : (uint64_t)s);
    }
    return c >> level;
}

/* Floor shift of a 64-bit step to `level`. A clamp/border axis saturates it
 * to int32 (its coordinates are saturated too). A repeat/mirror axis keeps
 * it modulo 2^32, like its coordinates: the period divides 2^32, so u0 + k
 * du is then exact modulo the period however large the step. Saturating
 * one of 2^15 texels a pixel or more (a uv_wide triangle's far tip, where
 * a pixel spans thousands of periods) put the pixels after a segment's
 * first at the wrong texels. */
static inline int32_t shift_step(int64_t d, int level, int is_signed)
{
    /* level 0 without the 64-bit shift by a variable (a long sequence on
     * 32-bit cores) */
    const int64_t f = level == 0 ? d : d < 0 ? ~(int64_t)((uint64_t)~d >> level) : (int64_t)((uint64_t)d >> level);
    return is_signed ? sat_i32(f) : fxl__i32_of_bits((uint32_t)(uint64_t)f);
}

#if FXL_HAVE_MIPMAP
/* ---- level of detail from the plane gradients ----------------------------
 * u = S / q with S, q planes, so du/dg = (S_g - u q_g) / q for g = x, y
 * (likewise v) and, in texels of level 0 (u in q16),
 *   LOD = log2 max_g |(S_ug - u q_g, S_vg - v q_g)| - log2 q - 16.
 * lod_setup puts each direction's three gradients on one integer scale, so
 * a correction point pays four 32 x 32-bit products, two squared lengths
 * of 15 significant bits and three table logarithms. The 1/q of the
 * derivatives becomes the subtracted log2 q: no division. (Carried as
 * soft floats with a reciprocal, the same LOD cost ~360 x86-64 and ~460
 * Cortex-M4 instructions a correction point.) */

/* s as an integer in units of 2^e: exact when s.e >= e (the caller keeps
 * s.e - e <= 30 for s != 0, so |result| <= 2^61), else floor-shifted. */
static int64_t lod_fix(fxl__sf_t s, int e)
{
    const int d = s.e - e;
    if (s.m == 0)
        return 0;   /* a zero's exponent is arbitrary */
    if (d >= 0)
        return (int64_t)s.m * ((int64_t)1 << d);
    return fxl__asr32(s.m, d < -31 ? 31 : -d);
}

/* The numerators' common scale for direction g: S_u, S_v and q's gradient
 * (soft floats, |m| <= 2^31) and the shift ash that brings u, v into int32.
 * e is the smallest exponent at which S_u, S_v are below 2^61, given that
 * the product u' m_q (|u'| <= 2^31) is in units of 2^(ash + q's exponent)
 * or coarser: every numerator fits int64, and a term the shifts cut short
 * is below 2^-30 of the one that dominates. */
static void lod_scale(fxl__tri_t *tri, int g, const fxl__sf_t s[2], fxl__sf_t qg, int ash)
{
    int e = ash + qg.e, i;

    for (i = 0; i < 2; i++)
        if (s[i].m != 0 && s[i].e - 30 > e)
            e = s[i].e - 30;
    tri->lod_mq[g] = (int32_t)lod_fix(qg, e - ash);
    for (i = 0; i < 2; i++)
        tri->lod_s[g][i] = lod_fix(s[i], e);
    tri->lod_e512[g] = 512 * e;
}

/* 2 log2 |(a, b)| in q8 for int64 a, b (INT32_MIN / 4 for (0, 0)): the top
 * 15 bits of the larger magnitude and the same bits of the other squared
 * in 32 bits, i.e. within 2^-13 relative before the table. */
static FXL__SF_INLINE int32_t lod_len2_q8(int64_t a, int64_t b)
{
    const uint64_t aa = a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a;
    const uint64_t ab = b < 0 ? (uint64_t)0 - (uint64_t)b : (uint64_t)b;
    const uint64_t m = aa | ab;
    uint32_t x, y, l;
    int s;

    if (m == 0)
        return INT32_MIN / 4;
    s = 64 - fxl__clz64_inline(m) - 15;
    if (s >= 0) {
        x = (uint32_t)(aa >> s);
        y = (uint32_t)(ab >> s);
    } else {
        x = (uint32_t)aa << -s;
        y = (uint32_t)ab << -s;
    }
    l = x * x + y * y;   /* [2^28, 2^31) */
    return fxl__log2_q8_u32(l) + 512 * s;
}

/* x >> k (floor) saturated to int32, on 32-bit words: u, v lie within the
 * vertices' range, so the saturation only guards against a broken bound. */
#if defined(__OPTIMIZE_SIZE__)
/* one copy for u and v: 72 B less, which keeps the core within 16 KiB */
static FXL__NOINLINE int32_t lod_coord(int64_t x, int k)
#else
static FXL__SF_INLINE int32_t lod_coord(int64_t x, int k)
#endif
{
    const int64_t y = k ? fxl__asr64(x, k) : x;   /* k is mostly 0: ~9 Cortex-M4 instructions less */
    const uint32_t lo = (uint32_t)(uint64_t)y;
    const int32_t hi = fxl__i32_of_bits((uint32_t)((uint64_t)y >> 32));
    if (hi != fxl__asr32(fxl__i32_of_bits(lo), 31))
        return hi < 0 ? INT32_MIN : INT32_MAX;
    return fxl__i32_of_bits(lo);
}

/* 2 log2 of direction g's numerator length, q8, scale included. */
static FXL__SF_INLINE int32_t lod_dir(const fxl__tri_t *tri, int g, int32_t u, int32_t v)
{
    /* |s| <= 2^61 and |u m_q| <= 2^62: no overflow */
    return lod_len2_q8(tri->lod_s[g][0] - fxl__mul_s32(u, tri->lod_mq[g]),
                       tri->lod_s[g][1] - fxl__mul_s32(v, tri->lod_mq[g])) +
           tri->lod_e512[g];
}

/* log2 q in q8 (q_min <= q <= q_max): fxl__log2_q8's value. On 32-bit
 * cores from q >> (PF - 1), which fits 32 bits (q_max < 2^(31 + PF),
 * setup.c) and holds the same top 9 bits whenever it is >= 256. */
static FXL__SF_INLINE int32_t lod_log2_q(int64_t q)
{
#if defined(__OPTIMIZE_SIZE__)
    return fxl__log2_q8((uint64_t)q);
#else
    if (FXL__WORD32) {
        const uint32_t q32 = (uint32_t)((uint64_t)q >> (FXL__PF - 1));
        if (q32 >= 256u)
            return fxl__log2_q8_u32(q32) + (FXL__PF - 1) * 256;
    }
    return fxl__log2_q8_inline((uint64_t)q);
#endif
}

/* The LOD's log2 q term at a correction point, q8. */
static FXL__SF_INLINE int32_t lod_lq(const fxl__tri_t *tri, int64_t qv)
{
    /* inside the triangle q_min <= q <= q_max; the clamps catch rounding
     * at a sliver's tips */
    if (qv < tri->q_min)
        qv = tri->q_min;
    if (qv > tri->q_max)
        qv = tri->q_max;
    return lod_log2_q(qv);
}

/* The LOD at a correction point from its log2 q term lq; xc, yc (constants
 * in each copy): direction x, y has lod_mq 0, so its length is lod_dirc's. */
static FXL__SF_INLINE int32_t lod_at_with(const fxl__tri_t *tri, int32_t lq, int64_t u64, int64_t v64, const int xc,
                                          const int yc)
{
    const int32_t u = lod_coord(u64, tri->lod_ash), v = lod_coord(v64, tri->lod_ash);
    const int32_t lx = xc ? tri->lod_dirc[0] : lod_dir(tri, 0, u, v);
    const int32_t ly = yc ? tri->lod_dirc[1] : lod_dir(tri, 1, u, v);
    return fxl__asr32(lx > ly ? lx : ly, 1) - lq - 16 * 256;
}

/* Out of line: once per segment, from every walk with mip levels. */
static FXL__NOINLINE int32_t lod_at(const fxl__tri_t *tri, int64_t qv, int64_t u64, int64_t v64)
{
    return lod_at_with(tri, lod_lq(tri, qv), u64, v64, 0, 0);
}

#if !defined(__OPTIMIZE_SIZE__)   /* the copies that skip a constant direction */
static FXL__NOINLINE int32_t lod_at_xc(const fxl__tri_t *tri, int64_t qv, int64_t u64, int64_t v64)
{
    return lod_at_with(tri, lod_lq(tri, qv), u64, v64, 1, 0);
}

static FXL__NOINLINE int32_t lod_at_yc(const fxl__tri_t *tri, int64_t qv, int64_t u64, int64_t v64)
{
    return lod_at_with(tri, lod_lq(tri, qv), u64, v64, 0, 1);
}

static FXL__NOINLINE int32_t lod_at_xyc(const fxl__tri_t *tri, int64_t qv, int64_t u64, int64_t v64)
{
    return lod_at_with(tri, lod_lq(tri, qv), u64, v64, 1, 1);
}

/* On rows of constant q (a level floor) the constant-depth walk takes
 * lod_lq once a span and these per correction point (x86-64 floor
 * subdiv16 trilinear with depth -0.8%). */
static FXL__NOINLINE int32_t lod_at_lq_xc(const fxl__tri_t *tri, int32_t lq, int64_t u64, int64_t v64)
{
    return lod_at_with(tri, lq, u64, v64, 1, 0);
}

static FXL__NOINLINE int32_t lod_at_lq_xyc(const fxl__tri_t *tri, int32_t lq, int64_t u64, int64_t v64)
{
    return lod_at_with(tri, lq, u64, v64, 1, 1);
}
#endif

/* The largest LOD lod_at gives inside the triangle: at any q (lod_lq
 * clamps it into [q_min, q_max]) and any u, v in the vertices' range
 * (setup.c, rebase), where u, v of every point of the triangle lie. lod_at
 * is monotonic in what it computes from them: it falls as log2 q rises
 * (fxl__log2_q8 is non-decreasing), and each direction's lod_len2_q8 does
 * not fall when either magnitude rises (within one shift s the truncated
 * x, y cannot fall; where the larger magnitude reaches 2^(15 + s + 1),
 * x = 2^15 - 1 becomes 2^14 and y becomes y >> 1: 4 (x'^2 + y'^2) >=
 * x^2 + y^2 + 2^16 - 2 y > x^2 + y^2, and log2_q8 of 4 l is log2_q8 of l
 * plus 512). The magnitudes |S - u' m_q| and |S - v' m_q| are linear in
 * u' and v' inside the absolute value, so each is largest at an end of
 * its range: each direction's length is largest at a corner of the range,
 * and lod_at, the larger of the two, is largest at one of the four
 * corners at q_min. That is lod_at's own arithmetic with no margin
 * (tests/test_lod.c checks it against lod_at at random points, and
 * against lod_at at the corners). */
#if defined(__OPTIMIZE_SIZE__)
/* Size builds: lod_at at the four corners, no code of its own; it stops at
 * the first above limit (the triangle cannot stay at level 0: a minified
 * one mostly stops at the first corner), returning that one. */
static int32_t lod_bound_hi(const fxl__tri_t *tri, int32_t limit)
{
    int32_t hi = INT32_MIN;
    int i;
    for (i = 0; i < 4 && hi <= limit; i++) {
        const int32_t l = tri->lod_at(tri, tri->q_min, tri->lod_a[0][i & 1], tri->lod_a[1][i >> 1]);
        if (l > hi)
            hi = l;
    }
    return hi;
}
#else
/* |S - c m| at its largest for c in [lo, hi]: at an end. (|S| <= 2^61,
 * |c m| <= 2^62: no overflow.) */
static int64_t lod_num_max(int64_t s, int32_t m, int32_t lo, int32_t hi)
{
    const int64_t a = s - fxl__mul_s32(lo, m), b = s - fxl__mul_s32(hi, m);
    const int64_t ma = a < 0 ? -a : a, mb = b < 0 ? -b : b;
    return ma > mb ? ma : mb;
}

/* Speed builds: the same largest value from each direction's largest
 * magnitudes, one length each (lod_at at four corners is ~2.4 times the
 * work); it too stops once above limit (after direction x). */
static int32_t lod_bound_hi(const fxl__tri_t *tri, int32_t limit)
{
    const int32_t lq = lod_lq(tri, tri->q_min) + 16 * 256;
    int32_t c[4], hi = INT32_MIN;
    int i, g;
    for (i = 0; i < 4; i++)   /* u low, high; v low, high, as lod_at's u', v' */
        c[i] = lod_coord(tri->lod_a[i >> 1][i & 1], tri->lod_ash);
    for (g = 0; g < 2 && hi <= limit; g++) {
        const int32_t d = lod_len2_q8(lod_num_max(tri->lod_s[g][0], tri->lod_mq[g], c[0], c[1]),
                                      lod_num_max(tri->lod_s[g][1], tri->lod_mq[g], c[2], c[3])) +
                          tri->lod_e512[g];
        /* lod_at's max(lx, ly) / 2, one direction at a time (the floor
         * shift is monotonic) */
        const int32_t l = fxl__asr32(d, 1) - lq;
        if (l > hi)
            hi = l;
    }
    return hi;
}
#endif

/* lod_at of a triangle whose LOD stays at or below level 0 with its bias
 * (lod_bound_hi): lod_hi, which seg_lod takes to 0 as it would every value
 * of lod_at there. ~140 x86-64 instructions a segment less. */
static FXL__NOINLINE int32_t lod_at_const(const fxl__tri_t *tri, int64_t qv, int64_t u64, int64_t v64)
{
    (void)qv;
    (void)u64;
    (void)v64;
    return tri->lod_hi;
}

/* lod_at's per-triangle factors (fxl__span_setup). */
static void lod_setup(fxl__tri_t *tri)
{
    const int shu = tri->a_shift[FXL__AU] + (int)tri->tex->log2_w;
    const int shv = tri->a_shift[FXL__AV] + (int)tri->tex->log2_h;
    /* u, v at a correction point lie between the vertices' values (convex
     * combinations): the shift that keeps those below 2^30 (one bit of
     * margin for rounding; the conversion saturates beyond it) */
    int ash = tri->uv_len[0] + (int)tri->tex->log2_w + 1 - 30;
    const int ashv = tri->uv_len[1] + (int)tri->tex->log2_h + 1 - 30;
    fxl__sf_t s[2];
    int g;

    if (ashv > ash)
        ash = ashv;
    if (ash < 0)
        ash = 0;
    tri->lod_ash = (uint8_t)ash;
    for (g = 0; g < 2; g++) {
        /* direction g's gradients of the u, v and q planes: a pixel (x), a row (y) */
        const int64_t gu = g ? (int64_t)((uint64_t)tri->a[FXL__AU].gy * FXL__ONE) : tri->gpx[PA + FXL__AU];
        const int64_t gv = g ? (int64_t)((uint64_t)tri->a[FXL__AV].gy * FXL__ONE) : tri->gpx[PA + FXL__AV];
        const int64_t gq = g ? (int64_t)((uint64_t)tri->q.gy * FXL__ONE) : tri->gpx[PQ];
        s[0] = fxl__sf_make(gu, shu);
        s[1] = fxl__sf_make(gv, shv);
        lod_scale(tri, g, s, fxl__sf_make(gq, 0), ash);
    }
    /* A direction in which q does not change (lod_mq 0: a level floor's
     * rows, an upright wall's columns) has a derivative length that does
     * not depend on u, v: lod_at reads it instead of measuring it per
     * segment (the same value). */
#if defined(__OPTIMIZE_SIZE__)
    tri->lod_at = lod_at;   /* one copy: the same values */
    tri->lod_at_lq = 0;
#else
    {
        static int32_t (*const pick[4])(const fxl__tri_t *, int64_t, int64_t, int64_t) = {lod_at, lod_at_xc,
                                                                                         lod_at_yc, lod_at_xyc};
        int c = 0;
        if (tri->lod_mq[0] == 0) {
            tri->lod_dirc[0] = lod_dir(tri, 0, 0, 0);
            c = 1;
        }
        if (tri->lod_mq[1] == 0) {
            tri->lod_dirc[1] = lod_dir(tri, 1, 0, 0);
            c += 2;
        }
        tri->lod_at = pick[c];
        /* q constant along rows: then lod_mq[0] is 0 too (c is 1 or 3) */
        tri->lod_at_lq = tri->gpx[PQ] != 0 || !(c & 1) ? 0 : c == 3 ? lod_at_lq_xyc : lod_at_lq_xc;
    }
#endif
    /* A triangle whose LOD stays at or below level 0 with its bias (a
     * magnified texture: 1,696 of the firmware example's lit sphere's
     * 1,982 per-segment LODs) takes level 0 at every segment, with no LOD
     * to compute. Every build decides so, alike: a correction point whose
     * rounding stepped past the vertex range, where lod_at could give
     * more, takes level 0 too (one determinism stress case changed). */
    tri->lod_hi = lod_bound_hi(tri, -tri->draw->lod_bias_q8);   /* above the limit: maybe not the largest */
    if (tri->lod_hi + tri->draw->lod_bias_q8 <= 0) {
        tri->lod_at = lod_at_const;
#if !defined(__OPTIMIZE_SIZE__)
        tri->lod_at_lq = 0;   /* (always 0 at -Os) */
#endif
    }
}

#endif

/* ---- the fast path ----------------------------------------------------------
 * RGB565, repeat on both axes, no key, REPLACE (fxl__fast_id). The walk is the
 * generic one (fxl__draw_span below) with everything that cannot occur
 * there removed; every value is bit-identical to it:
 * - coordinates are modular uint32 (repeat), and no uv_wide triangle comes
 *   here, so coord_diff's 64-bit difference is the uint32 difference read
 *   as int32, and a step is its magnitude shifted or divided (truncation
 *   toward zero), all in 32 bits: the last segment's division
 *   is one UDIV on a Cortex-M4 instead of a 64-bit library division;
 * - the steps of repeat coordinates lie in [-2^31, 2^31), so the int32
 *   saturation of shift_step never acts and a level shift is a floor shift
 *   of the int32 bit pattern;
 * - the exponents of the two divisions are precomputed per triangle.
 * The specialised walks are built where FXL__FAST_SPANS (raster_int.h). */

/* A level prepared for the point loops. The texel index has two
 * formulations (FXL__IDX); with v carried as V = v << lw, row * width and
 * the column sit in disjoint bit fields above bit 16 (lw + lh <= 16):
 * - masks: ((V & mv16) | (U & mu16)) >> 16 with U = u. Best where a shift
 *   by a register is not free (x86-64: CL only, and the depth loop needs
 *   every register; Thumb-1: two-operand).
 * - top: (U >> shu) + ((V & mv16) >> 16) with U = u << (16 - lw), whose
 *   top lw bits are the column already wrapped. On Thumb-2 that is LSR, AND
 *   and ADD with LSR #16: one instruction less per pixel. A 1-texel-wide
 *   level has column 0: U = 0 (and shu any valid shift). */
#define FXL__IDX_MASKS(U, V, mu16, mv16) ((((V) & (mv16)) | ((U) & (mu16))) >> 16)   /* U = u */
#if defined(__ARM_ARCH_ISA_THUMB) && __ARM_ARCH_ISA_THUMB >= 2
#define FXL__IDX_TOPU 1
#define FXL__IDX(U, V, shu, mu16, mv16) (((U) >> (shu)) + (((V) & (mv16)) >> 16))
#define FXL__TEXEL(tex, U, V, shu, mu16, mv16) ((tex)[FXL__IDX(U, V, shu, mu16, mv16)])
#else
#define FXL__IDX_TOPU 0
#define FXL__IDX(U, V, shu, mu16, mv16) FXL__IDX_MASKS(U, V, mu16, mv16)
/* The masks leave bit 15 clear, so >> 15 is the texel's byte offset: one
 * shift where the index takes two on Thumb-1 (a register offset is not
 * scaled there). Written out, because GCC found it only in some builds
 * (a change elsewhere in span.c cost the Cortex-M0+ floor point loop one
 * instruction a pixel). */
#define FXL__TEXEL(tex, U, V, shu, mu16, mv16)                                                               \
    (*(const uint16_t *)(const void *)((const uint8_t *)(tex) + ((((V) & (mv16)) | ((U) & (mu16))) >> 15)))
#endif

/* The column of a point sample on one texel row (v constant): FXL__IDX
 * without its v part. */
#if FXL__IDX_TOPU
#define FXL__RCOL(U, shu, mu16) ((U) >> (shu))
#else
#define FXL__RCOL(U, shu, mu16) (((U) & (mu16)) >> 16)
#endif

typedef struct fl {
    const uint16_t *tex;
    uint32_t lw, shu;
    uint32_t mu16, mv16;
#if FXL__FMT_RUNTIME
    uint32_t osh;   /* the store's byte shift: 8 on swapped targets, else 0 */
#endif
#if FXL__V_TINT
    fxl__tint_t tint;   /* the tinted variants' factors (FXL_T_TINT) */
#endif
} fl_t;

#if FXL__V_ANY_PT
/* forced inline: once a segment in some walks, and GCC left it out of line
 * in some Cortex-M0+ builds */
static FXL__HOT_INLINE void fl_init(fl_t *f, const fxl__level_t *lv)
{
    f->tex = (const uint16_t *)lv->texels;
    f->lw = lv->log2_w;
    f->shu = f->lw ? 32u - f->lw : 31u;
    f->mu16 = lv->mask_u << 16;
    f->mv16 = (lv->mask_v << f->lw) << 16;
}
#endif

typedef struct fxl__pt {
    uint32_t u, v;               /* level-0 texel q16, modular */
    uint32_t z;                  /* inv_w, u0.32 (set by the walk) */
#if FXL_HAVE_MIPMAP
    int64_t u64, v64;            /* before wrapping, for the LOD */
#endif
} fxl__pt_t;

/* The walk's position in plane space: q, u, v (and z) plane values, modular
 * int64, at the latest correction point, and its u, v. */
typedef struct fxl__walk {
    uint64_t sq, su, sv, sz;
    fxl__pt_t pt;
} fxl__walk_t;

/* Forced inline where code size allows: a function called twice with a
 * constant argument becomes two copies specialised for it. */
#define FXL__UNSWITCH FXL__HOT_INLINE

/* Segments per batch of the specialised walks (span_fast.h): its arrays
 * take 12 bytes a segment on the stack (16 with depth). */
#ifndef FXL__BATCH
#define FXL__BATCH 16
#endif

#if FXL__V_ANY
/* u, v at a correction point from the q, u, v plane values: correct() for
 * the fast case, inline (it is most of a segment's cost). The walk counts
 * the divisions and computes z (fast_z) only where it has a depth buffer.
 * fast_correct_rc is its part after 1/q. fast_correct_batch is the copy
 * the batch loops use, forced inline where code size allows (the adaptive
 * batch is out of line: a call there cost ~25 Cortex-M4 instructions a
 * segment); it clamps q without recip_at's test for a constant q, which
 * cost the fixed-length walks, where it was inlined, ~6 instructions a
 * segment in spills. */
static FXL__ALWAYS_INLINE void fast_correct_rc(const fxl__tri_t *tri, const fxl__recip_t *rc, int64_t su, int64_t sv,
                                               fxl__pt_t *pt)
{
    const int64_t u = fxl__persp_e(su, rc, tri->persp_eb[0]);
    const int64_t v = fxl__persp_e(sv, rc, tri->persp_eb[1]);
    pt->u = (uint32_t)(uint64_t)u;
    pt->v = (uint32_t)(uint64_t)v;
#if FXL_HAVE_MIPMAP
    pt->u64 = u;
    pt->v64 = v;
#endif
}

/* 1/q at a batch loop's correction point, q clamped below; also the
 * constant-depth walk's one 1/q for a row of constant q (span_walk.h). */
static FXL__HOT_INLINE void recip_batch(const fxl__tri_t *tri, int64_t q, fxl__recip_t *rc)
{
    if (q < tri->q_min)
        q = tri->q_min;
    fxl__recip(q, rc);
}

static FXL__UNSWITCH void fast_correct_batch(const fxl__tri_t *tri, int64_t q, int64_t su, int64_t sv,
                                             fxl__pt_t *pt)
{
    fxl__recip_t rc;
    recip_batch(tri, q, &rc);
    fast_correct_rc(tri, &rc, su, sv, pt);
}

/* The same values with recip_at: for the out-of-line starts and ends of
 * the lean walks' segments, where a constant q (affine mode) is common. */
static FXL__ALWAYS_INLINE void fast_correct(const fxl__tri_t *tri, int64_t q, int64_t su, int64_t sv,
                                            fxl__pt_t *pt)
{
    fxl__recip_t rc;
    recip_at(tri, q, &rc);
    fast_correct_rc(tri, &rc, su, sv, pt);
}

/* sat_u32(z >> PF) of correct(): a negative value (rounding at a sliver)
 * gives 0. */
static inline uint32_t fast_z(int64_t sz)
{
    return sz < 0 ? 0u : sat_u32((int64_t)((uint64_t)sz >> FXL__PF));
}

/* The one-level runs' depth pixels in the out-of-line run loop
 * (span_fast.h, FXL_T_RRLOOP). Not on the Cortex-M0+: there the eight
 * depth loops took enough of GCC's inlining budget for span.c that
 * fxl__persp_e stopped being inlined into lean_start and the corrections,
 * and every draw without depth cost 0.3-0.9% more. */
#ifndef FXL__RR_ZLOOP
#if defined(__ARM_ARCH_6M__)
#define FXL__RR_ZLOOP 0
#else
#define FXL__RR_ZLOOP 1
#endif
#endif

#if FXL_HAVE_RR && FXL__V_ANY_Z && FXL__RR_ZLOOP
/* Whether the depth values of n >= 1 pixels of a run, the modular int64
 * plane values sz + i·gz, all lie in [0, 2^52): then fast_z's clamps
 * cannot act and each is sz >> FXL__PF (the run loops' z). With
 * |gz| <= 2^52 and n <= 2^10 the last value's true magnitude is below
 * 2^63, so its modular value is the true one, and the values between lie
 * between the two ends. Saves the clamps' ~5 x86-64 instructions a pixel
 * (a run's chunk is at most 256 pixels; a sliver's steep depth falls back
 * to the clamped loop). */
static inline int rr_z_fits(uint64_t sz, uint64_t gz, int32_t n)
{
    const uint64_t lim = (uint64_t)1 << 52;
    return n <= 1024 && gz + lim <= 2u * lim && sz < lim && sz + gz * (uint32_t)(n - 1) < lim;
}
#endif

/* The lean walks' position: plane values (modular int64) at the latest
 * correction point, and u, v, z there. */
typedef struct fxl__lean {
    uint64_t sq, su, sv, sz;
    uint32_t u, v, z;
    fxl__recip_t rc;   /* 1/q there (lean_start) */
    int32_t g;         /* q_x / q there, fxl__quad_g (the quadratic walks' corrections) */
    int32_t run_to;    /* exact_run: the span's tests hold up to this x (lean_start: none) */
} fxl__lean_t;


#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
#define FXL__FLATTEN __attribute__((flatten))
#else
#define FXL__FLATTEN
#endif

/* q the same along every row (its plane has no x gradient, exactly): each
 * correction point of a span can keep the span start's 1/q */
static inline int q_row_const(const fxl__tri_t *tri)
{
    return tri->gpx[FXL__PQ] == 0;
}

/* The lean walks' correction point: the planes advanced by 2^k pixels
 * (mult == 0) or by mult pixels, and u, v (and z when with_z) there, as the
 * batch walk computes them. One copy out of line serves every variant: the
 * division and its 64-bit arithmetic (flattened in) get all the registers,
 * and the span functions keep theirs for the pixel loop. */
static FXL__UNSWITCH void lean_next(const fxl__tri_t *tri, fxl__lean_t *s, uint32_t mult, const int with_z,
                                    const int with_g, const int row_const)
{
    fxl__pt_t pt;
    fxl__recip_t rc;

    if (row_const) {
        /* s->sq stays (q_row_const) */
    } else if (mult == 0u) {
        s->sq += (uint64_t)tri->gpxN[FXL__PQ];
    } else {
        /* a 64 x 32 multiply: cheaper than a 64-bit shift by a variable on
         * 32-bit cores */
        s->sq += (uint64_t)tri->gpx[FXL__PQ] * mult;
    }
    if (mult == 0u) {
        s->su += (uint64_t)tri->gpxN[FXL__PA + FXL__AU];
        s->sv += (uint64_t)tri->gpxN[FXL__PA + FXL__AV];
        if (with_z)
            s->sz += (uint64_t)tri->gpxN[FXL__PZ];
    } else {
        s->su += (uint64_t)tri->gpx[FXL__PA + FXL__AU] * mult;
        s->sv += (uint64_t)tri->gpx[FXL__PA + FXL__AV] * mult;
        if (with_z)
            s->sz += (uint64_t)tri->gpx[FXL__PZ] * mult;
    }
    /* the batch walk's correction; its 64-bit copies for the LOD are
     * dead here and optimised away. Where q does not change along a row
     * (row_const) 1/q is lean_start's: on the floor that is ~35 of a
     * correction's ~100 Cortex-M4 instructions. */
    if (row_const)
        rc = s->rc;
    else
        recip_at(tri, (int64_t)s->sq, &rc);
    fast_correct_rc(tri, &rc, (int64_t)s->su, (int64_t)s->sv, &pt);
    s->u = pt.u;
    s->v = pt.v;
#if FXL_HAVE_QUAD
    if (with_g)
        s->g = fxl__quad_g(tri, &rc);   /* here, where 1/q is in registers */
#else
    (void)with_g;
#endif
    if (with_z)
        s->z = fast_z((int64_t)s->sz);
}

#if FXL__V_ANY_NOZ
static FXL__NOINLINE FXL__FLATTEN void lean_next_uv(const fxl__tri_t *tri, fxl__lean_t *s, uint32_t mult)
{
    lean_next(tri, s, mult, 0, 0, 0);
}

/* The copies for triangles whose q is the same along every row (1/q is
 * lean_start's: the same q). The walks call through tri->lean_next, set
 * with the walk (FXL_T_SPAN##_pick): one load more than a direct call; a
 * test in the one copy cost the tunnel's corrections 3 Cortex-M4
 * instructions each, a pointer chosen in the walk ~7 a span. */
static FXL__NOINLINE FXL__FLATTEN void lean_next_uv_rowc(const fxl__tri_t *tri, fxl__lean_t *s, uint32_t mult)
{
    lean_next(tri, s, mult, 0, 0, 1);
}
#endif

#if FXL__V_ANY_Z
static FXL__NOINLINE FXL__FLATTEN void lean_next_uvz(const fxl__tri_t *tri, fxl__lean_t *s, uint32_t mult)
{
    lean_next(tri, s, mult, 1, 0, 0);
}

static FXL__NOINLINE FXL__FLATTEN void lean_next_uvz_rowc(const fxl__tri_t *tri, fxl__lean_t *s, uint32_t mult)
{
    lean_next(tri, s, mult, 1, 0, 1);
}
#endif

#if FXL_HAVE_QUAD
/* The quadratic walks' copies: they also give q_x / q (s->g). */
#if FXL__V_ANY_NOZ
static FXL__NOINLINE FXL__FLATTEN void lean_next_uv_g(const fxl__tri_t *tri, fxl__lean_t *s, uint32_t mult)
{
    lean_next(tri, s, mult, 0, 1, 0);
}
#endif

#if FXL__V_ANY_Z
static FXL__NOINLINE FXL__FLATTEN void lean_next_uvz_g(const fxl__tri_t *tri, fxl__lean_t *s, uint32_t mult)
{
    lean_next(tri, s, mult, 1, 1, 0);
}
#endif
#endif

/* The lean walks' start of a span, out of line (one copy for every
 * variant, ~10 instructions a span for the call): planes at pixel x of the
 * row dY below the reference vertex, and u, v (and z) there. */
static FXL__NOINLINE void lean_start(const fxl__tri_t *tri, int32_t x, int32_t dY, fxl__lean_t *s, const int with_z)
{
    const int32_t dX = x * FXL__ONE + FXL__HALF - tri->X0;
    fxl__pt_t pt;
    s->sq = (uint64_t)fxl__plane_eval(&tri->q, dX, dY);
    s->su = (uint64_t)fxl__plane_eval(&tri->a[FXL__AU], dX, dY);
    s->sv = (uint64_t)fxl__plane_eval(&tri->a[FXL__AV], dX, dY);
    s->sz = with_z ? (uint64_t)fxl__plane_eval(&tri->z, dX, dY) : 0u;
    s->z = with_z ? fast_z((int64_t)s->sz) : 0u;
    recip_at(tri, (int64_t)s->sq, &s->rc);
    fast_correct_rc(tri, &s->rc, (int64_t)s->su, (int64_t)s->sv, &pt);
    s->u = pt.u;
    s->v = pt.v;
    s->run_to = INT32_MIN;
}

/* Runs of 1-pixel segments (exact mode, AUTO's steepest stretches): up to
 * FXL__BATCH pixels from x (s holds its planes and u, v, z), each pixel's
 * u, v into puv (pairs) and z into pz. The planes step one pixel at a time and
 * every pixel is a correction point, with the walk state in registers and
 * none of the segment bookkeeping of the lean walk: the same values as its
 * 1-pixel segments (plane steps gpx, which is gpxN for k = 0, and the same
 * correction), bit for bit. One copy out of line serves every variant;
 * their pixel loops read the arrays (FXL_T_RUN).
 * The chunk ends at cr (without the correction there, which no pixel
 * uses), after FXL__BATCH pixels, or (autoseg) before the first pixel whose
 * segment is longer than 1; at an odd offset from xl alignment caps the
 * length to 1, so fxl__auto_next runs only at even ones. s is left at the
 * pixel after the chunk. Returns the chunk's pixel count m >= 1; *more
 * says whether the run goes on after it; *ndiv counts the corrections. */
static FXL__UNSWITCH int32_t lean_run(const fxl__tri_t *tri, const int autoseg, const int32_t t_row,
                                      fxl__lean_t *s, const int32_t x0, const int32_t xl, const int32_t xr,
                                      const int32_t cr, uint32_t *puv, uint32_t *pz, int *more,
                                      uint32_t *ndiv, const int with_z, const int row_const)
{
    const uint64_t gq = (uint64_t)tri->gpx[FXL__PQ];
    const uint64_t gu = (uint64_t)tri->gpx[FXL__PA + FXL__AU];
    const uint64_t gv = (uint64_t)tri->gpx[FXL__PA + FXL__AV];
    const uint64_t gz = with_z ? (uint64_t)tri->gpx[FXL__PZ] : 0u;
    uint64_t sq = s->sq, su = s->su, sv = s->sv, sz = s->sz;
    int32_t m = 0;
    int go_on = 0;

    (void)autoseg;
    (void)t_row;
    (void)xl;
    (void)xr;
    puv[0] = s->u;
    puv[1] = s->v;
    if (with_z)
        pz[0] = s->z;
    for (;;) {
        fxl__pt_t pt;
        int32_t x;
        int longer = 0;   /* a segment longer than 1 starts at x */
        m++;
        x = x0 + m;
        if (x >= cr)
            break;   /* the span's end: no correction */
        sq += gq;
        su += gu;
        sv += gv;
        if (row_const)
            fast_correct_rc(tri, &s->rc, (int64_t)su, (int64_t)sv, &pt);   /* q is s->sq's */
        else
            fast_correct_batch(tri, (int64_t)sq, (int64_t)su, (int64_t)sv, &pt);
        if (with_z)
            sz += gz;
#if FXL_HAVE_AUTO
        longer = autoseg && !((uint32_t)(x - xl) & 1u) && fxl__auto_next_tri(tri, t_row, x, xl, xr, (int64_t)sq) != 0;
#endif
        if (longer || m == FXL__BATCH) {
            /* the run ends at x, or (a full chunk) goes on there */
            s->u = pt.u;
            s->v = pt.v;
#if FXL_HAVE_AUTO
            /* the quadratic walk's next segment needs q_x / q here: 1/q computed
             * again (once a run) rather than kept through the loop, which
             * cost exact mode ~10 Cortex-M4 instructions a pixel in spills */
            if (autoseg && fxl__auto_quad(tri)) {
                fxl__recip_t rc;
                recip_at(tri, (int64_t)sq, &rc);
                s->g = fxl__quad_g(tri, &rc);
            }
#endif
            go_on = !longer;
            break;
        }
        puv[2 * m] = pt.u;
        puv[2 * m + 1] = pt.v;
        if (with_z)
            pz[m] = fast_z((int64_t)sz);
    }
    /* corrections: one a pixel after the first, none at cr */
    *ndiv += (uint32_t)m - (x0 + m >= cr ? 1u : 0u);
    s->sq = sq;
    s->su = su;
    s->sv = sv;
    if (with_z) {
        s->sz = sz;
        s->z = fast_z((int64_t)sz);
    }
    *more = go_on;
    return m;
}

/* ---- Exact mode's runs with the division's range work done once a span ----
 *
 * lean_run's correction (fast_correct_batch) normalises q with a 64-bit CLZ
 * and shift, clamps it, range-checks each attribute's mantissa and picks a
 * rounding by the exponent, at every pixel: ~100 Cortex-M4 instructions a
 * pixel of the rolled floor. Along a span the planes are linear, so where
 * the first and last corrections of its rest pass those tests, every
 * point between passes them the same way:
 * - q (between q_min and 2^62 at both ends) is never clamped;
 * - an attribute within fxl__persp_m_ok's interval at both ends is within
 *   it everywhere, and its mantissa (bits PF-1..PF+30) is the high word of
 *   the plane shifted left by 33 - PF, which steps modulo 2^64 like the
 *   plane itself;
 * - z within [0, 2^52) needs no clamp: fast_z is the high word of z << 12.
 * Ends below 2^62, gradients below 2^54 over at most 2^8 steps (2^46 over
 * 2^16) keep the int64 values from wrapping between them. The tests run once a
 * span, over its rest (exact_run_check), and cover every chunk after.
 * The chunk is walked from its larger-q end, so q only falls: q << n with
 * n = clz(q) there never overflows, its high word is fxl__recip's
 * normalised q while its top bit is set, and where q falls past a power of
 * two (40% of the rolled floor's chunks) one more CLZ renormalises it;
 * from there each exponent is larger by that shift.
 * The walk is three passes, each with few enough live values for a
 * Cortex-M4's registers (one pass spilled ~25 instructions a pixel): the
 * reciprocals (into the v slots of puv), then u, then v, each a product
 * and a rounding with a shift that is constant between renormalisations.
 * fast_correct_batch's values bit for bit (test_fast_and_generic_walks_agree).
 * A chunk outside these conditions returns 0 and takes lean_run. */
#define FXL__RUN_MANT_SHIFT (33 - FXL__PF)   /* plane << this: mantissa in the high word */
#define FXL__RUN_EVENTS 4                    /* renormalisations a chunk, at most */
/* exact_run's chunk: twice lean_run's, for half the chunks' set-up (the
 * callers' arrays take FXL__RUN_BATCH + 1 pairs) */
#define FXL__RUN_BATCH (2 * FXL__BATCH)
/* Chunks of fewer corrections take lean_run: below 6 exact_run's set-up
 * (~300 Cortex-M4 instructions a span) costs more than it saves; small_tris'
 * spans average ~4 pixels. */
#define FXL__RUN_MIN 6

/* g below 2^(32 + b) in magnitude, as a signed bit pattern (on its high
 * word: in 32-bit operations) */
static inline int exact_run_step_ok(uint64_t g, int b)
{
    return (uint32_t)(g >> 32) + ((uint32_t)1 << b) < ((uint32_t)2 << b);
}

/* lo <= v < hi for the signed value whose bit pattern is v (lo, hi signed) */
static inline int exact_run_in(uint64_t v, int64_t lo, int64_t hi)
{
    const uint64_t off = (uint64_t)0 - (uint64_t)lo;   /* v - lo, modulo 2^64 */
    return v + off < (uint64_t)hi + off;
}

/* One coordinate's pass over cnt points from o (stride 2 dj words): the
 * mantissa w stepped by g, the reciprocal read from o[roff], and
 * fxl__persp_e's low 32 bits for a shift of k written to o[0]. On 32-bit
 * cores persp.h's one-word roundings, chosen here once a stretch: the
 * high word's (k >= 33), the two words' for k = 32, and for k <= 31 (the
 * rolled floor's far half, where u and v reach 2^13 texels). Returns w
 * after the last point. */
#define FXL__RUN_AXIS_LOOP(ROUNDED)                                                                         \
    do {                                                                                                    \
        const int64_t p = fxl__mul_s32(fxl__i32_of_bits((uint32_t)(w >> 32)), (int32_t)o[roff]);           \
        o[0] = (ROUNDED);                                                                                   \
        o += stride;                                                                                        \
        w += g;                                                                                             \
    } while (--cnt)

static FXL__UNSWITCH uint64_t exact_run_axis(uint32_t *o, const int32_t stride, int32_t cnt, uint64_t w,
                                             const uint64_t g, const int k, const int roff)
{
    if (FXL__WORD32 && k >= 33) {
        FXL__RUN_AXIS_LOOP(fxl__persp_lo32_hi(p, k));
    } else if (FXL__WORD32 && k == 32) {
        FXL__RUN_AXIS_LOOP(fxl__persp_lo32_words(p, 32, (uint64_t)1 << 31));
    } else if (FXL__WORD32) {
        const uint32_t half = (uint32_t)1 << (k - 1);   /* k <= 31 */
        FXL__RUN_AXIS_LOOP(fxl__bits32_at((uint64_t)p + half, k));
    } else {
        const uint64_t half = (uint64_t)1 << (k - 1);
        FXL__RUN_AXIS_LOOP(fxl__persp_lo32(p, k, half));
    }
    return w;
}
#undef FXL__RUN_AXIS_LOOP

/* The planes at the corrections x0 + 1 and x0 + last (x0 is s's pixel) */
typedef struct exact_run_ends {
    uint64_t q1, q_end, u1, u_end, v1, v_end, z1, z_end;
} exact_run_ends_t;

static FXL__UNSWITCH void exact_run_ends(const fxl__tri_t *tri, const fxl__lean_t *s, const int32_t last,
                                         exact_run_ends_t *e, const int with_z)
{
    const uint64_t steps = (uint64_t)(last - 1);
    e->q1 = s->sq + (uint64_t)tri->gpx[FXL__PQ];
    e->q_end = e->q1 + (uint64_t)tri->gpx[FXL__PQ] * steps;
    e->u1 = s->su + (uint64_t)tri->gpx[FXL__PA + FXL__AU];
    e->u_end = e->u1 + (uint64_t)tri->gpx[FXL__PA + FXL__AU] * steps;
    e->v1 = s->sv + (uint64_t)tri->gpx[FXL__PA + FXL__AV];
    e->v_end = e->v1 + (uint64_t)tri->gpx[FXL__PA + FXL__AV] * steps;
    e->z1 = with_z ? s->sz + (uint64_t)tri->gpx[FXL__PZ] : 0u;
    e->z_end = with_z ? e->z1 + (uint64_t)tri->gpx[FXL__PZ] * steps : 0u;
}

/* The tests above for the corrections at x0 + 1 .. x0 + last, whose
 * planes are e: 1 if they hold there. */
static FXL__UNSWITCH int exact_run_check(const fxl__tri_t *tri, const exact_run_ends_t *e, const int32_t last,
                                         const int with_z)
{
    const int64_t mant_lo = -((int64_t)1 << (FXL__PF + 30)) + ((int64_t)1 << (FXL__PF - 1));
    const int64_t mant_hi = (int64_t)1 << (FXL__PF + 30);
    const int64_t q_lo = tri->q_min > 1 ? tri->q_min : 1;
    const int eb_lo = tri->persp_eb[0] < tri->persp_eb[1] ? tri->persp_eb[0] : tri->persp_eb[1];
    const int eb_hi = tri->persp_eb[0] < tri->persp_eb[1] ? tri->persp_eb[1] : tri->persp_eb[0];
    /* |g| < 2^54 and at most 2^8 steps, or 2^46 and 2^16, and |ends| <
     * 2^62: the int64 values do not wrap between the ends */
    const int b = last <= 0x100 ? 22 : 14;
    int n_lo, n_hi;

    if (last > 0xFFFF || !exact_run_step_ok((uint64_t)tri->gpx[FXL__PQ], b) ||
        !exact_run_step_ok((uint64_t)tri->gpx[FXL__PA + FXL__AU], b) ||
        !exact_run_step_ok((uint64_t)tri->gpx[FXL__PA + FXL__AV], b) ||
        (with_z && !exact_run_step_ok((uint64_t)tri->gpx[FXL__PZ], b)))
        return 0;
    if (!exact_run_in(e->q1, q_lo, (int64_t)1 << 62) || !exact_run_in(e->q_end, q_lo, (int64_t)1 << 62) ||
        !exact_run_in(e->u1, mant_lo, mant_hi) || !exact_run_in(e->u_end, mant_lo, mant_hi) ||
        !exact_run_in(e->v1, mant_lo, mant_hi) || !exact_run_in(e->v_end, mant_lo, mant_hi))
        return 0;
    if (with_z &&
        (!exact_run_in(e->z1, 0, (int64_t)1 << 52) || !exact_run_in(e->z_end, 0, (int64_t)1 << 52)))
        return 0;
    /* every shift k = -(n + eb) within 1..62 (n = clz(q), monotonic in q) */
    n_lo = fxl__clz64_inline(e->q1);
    n_hi = fxl__clz64_inline(e->q_end);
    if (n_lo > n_hi) {
        const int t = n_lo;
        n_lo = n_hi;
        n_hi = t;
    }
    return n_lo + eb_lo >= -62 && n_hi + eb_hi <= -1;
}

/* Returns the chunk's pixel count (lean_run's contract) or 0: not taken.
 * The caller passes at least FXL__RUN_MIN corrections (cr - 1 - x0); puv
 * has room for FXL__RUN_BATCH + 1 pairs, pz for FXL__RUN_BATCH + 1
 * values. The tests run once a span (s->run_to), over the rest of it. */
static FXL__UNSWITCH int32_t exact_run(const fxl__tri_t *tri, fxl__lean_t *s, const int32_t x0, const int32_t cr,
                                       uint32_t *puv, uint32_t *pz, int *more, uint32_t *ndiv, const int with_z)
{
    /* corrections at x0 + 1 .. x0 + nc (none at cr); the one at
     * x0 + RUN_BATCH starts the next chunk */
    const int32_t nc = cr - 1 - x0 < FXL__RUN_BATCH ? cr - 1 - x0 : FXL__RUN_BATCH;
    uint64_t gq = (uint64_t)tri->gpx[FXL__PQ];
    uint64_t gu = (uint64_t)tri->gpx[FXL__PA + FXL__AU];
    uint64_t gv = (uint64_t)tri->gpx[FXL__PA + FXL__AV];
    uint64_t gz = with_z ? (uint64_t)tri->gpx[FXL__PZ] : 0u;
    const int eb_u = tri->persp_eb[0], eb_v = tri->persp_eb[1];
    exact_run_ends_t en;
    uint64_t qw, gqw, uw, vw, zw;
    int32_t ev_at[FXL__RUN_EVENTS + 2], i, j0, dj, nev = 0, at;
    int ev_n[FXL__RUN_EVENTS + 1], n, e;
    uint32_t *o;

    if (x0 + nc > s->run_to) {
        /* the tests, over the span's rest: in one chunk, its ends */
        const int32_t rest = cr - 1 - x0;
        exact_run_ends(tri, s, rest, &en, with_z);
        if (!exact_run_check(tri, &en, rest, with_z))
            return 0;
        s->run_to = cr - 1;
        if (rest != nc)
            exact_run_ends(tri, s, nc, &en, with_z);
    } else {
        exact_run_ends(tri, s, nc, &en, with_z);
    }
    /* walk from the larger q: from the last correction when q rises */
    if (gq & (UINT64_C(1) << 63)) {
        j0 = 1;
        dj = 1;
        qw = en.q1;
        uw = en.u1;
        vw = en.v1;
        zw = en.z1;
    } else {
        j0 = nc;
        dj = -1;
        qw = en.q_end;
        uw = en.u_end;
        vw = en.v_end;
        zw = en.z_end;
        gq = 0u - gq;
        gu = 0u - gu;
        gv = 0u - gv;
        gz = 0u - gz;
    }
    n = fxl__clz64_inline(qw);

    /* pass 1: the reciprocals, into the v slots; ev_at[] / ev_n[] are the
     * walk's stretches of one n */
    qw <<= n;
    gqw = gq << n;
    ev_at[0] = 0;
    ev_n[0] = n;
    o = puv + 2 * j0 + 1;
    for (i = 0;; i++) {
        uint32_t qn = (uint32_t)(qw >> 32);
        if (!(qn & 0x80000000u)) {
            /* q fell past a power of two */
            const int sh = fxl__clz64_inline(qw);
            if (nev == FXL__RUN_EVENTS)
                return 0;
            qw <<= sh;
            gqw <<= sh;
            n += sh;
            nev++;
            ev_at[nev] = i;
            ev_n[nev] = n;
            qn = (uint32_t)(qw >> 32);
        }
        *o = fxl__recip_qn(qn);
        if (i == nc - 1)
            break;
        o += 2 * dj;
        qw += gqw;
    }
    /* passes 2 and 3: u, then v over the reciprocals, one stretch of
     * constant shifts at a time */
    ev_at[nev + 1] = nc;
    uw <<= FXL__RUN_MANT_SHIFT;
    gu <<= FXL__RUN_MANT_SHIFT;
    vw <<= FXL__RUN_MANT_SHIFT;
    gv <<= FXL__RUN_MANT_SHIFT;
    for (e = 0; e <= nev; e++) {
        const int32_t cnt = ev_at[e + 1] - ev_at[e];
        if (cnt == 0)
            continue;
        at = 2 * (j0 + dj * ev_at[e]);
        uw = exact_run_axis(puv + at, 2 * dj, cnt, uw, gu, -(ev_n[e] + eb_u), 1);
        vw = exact_run_axis(puv + at + 1, 2 * dj, cnt, vw, gv, -(ev_n[e] + eb_v), 0);
    }
    if (with_z) {
        uint32_t *oz = pz + j0;
        zw <<= 32 - FXL__PF;
        gz <<= 32 - FXL__PF;
        for (i = 0; i < nc; i++) {
            *oz = (uint32_t)(zw >> 32);
            oz += dj;
            zw += gz;
        }
    }
    puv[0] = s->u;
    puv[1] = s->v;
    if (with_z)
        pz[0] = s->z;
    if (nc == FXL__RUN_BATCH) {
        /* a full chunk's last correction starts the next chunk */
        s->u = puv[2 * FXL__RUN_BATCH];
        s->v = puv[2 * FXL__RUN_BATCH + 1];
    }
    /* the planes at the last correction, as lean_run leaves them */
    s->sq = en.q_end;
    s->su = en.u_end;
    s->sv = en.v_end;
    if (with_z) {
        s->sz = en.z_end;
        s->z = (uint32_t)(en.z_end >> FXL__PF);
    }
    *ndiv += (uint32_t)nc;
    *more = nc == FXL__RUN_BATCH;
    return nc == FXL__RUN_BATCH ? FXL__RUN_BATCH : nc + 1;
}

/* One copy for exact mode and one for AUTO's runs: with the adaptive
 * chooser in the same loop, exact mode spilled ~7 Cortex-M4 instructions
 * a pixel. Exact mode's chunks go to exact_run, or where its tests fail to
 * lean_run (_plain); triangles whose q is the same along every row
 * (gpx[PQ] == 0) to a copy that keeps lean_start's 1/q (~30% of an exact
 * floor pixel on a Cortex-M4). Each is out of line (in one function the
 * others' loops spilled ~2.6 instructions a pixel), and the dispatch
 * calls them one after the other, so their stack frames do not nest.
 * AUTO draws row-constant triangles affine. */
#if FXL__V_ANY_NOZ
static FXL__NOINLINE FXL__FLATTEN int32_t lean_run_uv_rowc(const fxl__tri_t *tri, fxl__lean_t *s, const int32_t x0,
                                                           const int32_t xl, const int32_t xr, const int32_t cr,
                                                           uint32_t *puv, int *more, uint32_t *ndiv)
{
    return lean_run(tri, 0, 0, s, x0, xl, xr, cr, puv, 0, more, ndiv, 0, 1);
}

/* lean_run for the chunks exact_run does not take */
static FXL__NOINLINE FXL__FLATTEN int32_t lean_run_uv_plain(const fxl__tri_t *tri, fxl__lean_t *s, const int32_t x0,
                                                            const int32_t xl, const int32_t xr, const int32_t cr,
                                                            uint32_t *puv, int *more, uint32_t *ndiv)
{
    return lean_run(tri, 0, 0, s, x0, xl, xr, cr, puv, 0, more, ndiv, 0, 0);
}

static FXL__NOINLINE FXL__FLATTEN int32_t lean_run_uv_exact(const fxl__tri_t *tri, fxl__lean_t *s, const int32_t x0,
                                                            const int32_t cr, uint32_t *puv, int *more,
                                                            uint32_t *ndiv)
{
    return exact_run(tri, s, x0, cr, puv, 0, more, ndiv, 0);
}

static FXL__NOINLINE FXL__FLATTEN int32_t lean_run_uv_auto(const fxl__tri_t *tri, const int32_t t_row, fxl__lean_t *s,
                                                           const int32_t x0, const int32_t xl, const int32_t xr,
                                                           const int32_t cr, uint32_t *puv, int *more, uint32_t *ndiv)
{
    return lean_run(tri, 1, t_row, s, x0, xl, xr, cr, puv, 0, more, ndiv, 0, 0);
}

static FXL__UNSWITCH int32_t lean_run_uv(const fxl__tri_t *tri, const int autoseg, const int32_t t_row,
                                         fxl__lean_t *s, const int32_t x0, const int32_t xl, const int32_t xr,
                                         const int32_t cr, uint32_t *puv, int *more, uint32_t *ndiv)
{
    if (autoseg)
        return lean_run_uv_auto(tri, t_row, s, x0, xl, xr, cr, puv, more, ndiv);
    if (q_row_const(tri))
        return lean_run_uv_rowc(tri, s, x0, xl, xr, cr, puv, more, ndiv);
    if (cr - 1 - x0 >= FXL__RUN_MIN) {
        /* called one after the other, not nested: their frames do not add up */
        const int32_t m = lean_run_uv_exact(tri, s, x0, cr, puv, more, ndiv);
        if (m)
            return m;
    }
    return lean_run_uv_plain(tri, s, x0, xl, xr, cr, puv, more, ndiv);
}
#endif

#if FXL__V_ANY_Z
static FXL__NOINLINE FXL__FLATTEN int32_t lean_run_uvz_rowc(const fxl__tri_t *tri, fxl__lean_t *s, const int32_t x0,
                                                            const int32_t xl, const int32_t xr, const int32_t cr,
                                                            uint32_t *puv, uint32_t *pz, int *more, uint32_t *ndiv)
{
    return lean_run(tri, 0, 0, s, x0, xl, xr, cr, puv, pz, more, ndiv, 1, 1);
}

static FXL__NOINLINE FXL__FLATTEN int32_t lean_run_uvz_plain(const fxl__tri_t *tri, fxl__lean_t *s, const int32_t x0,
                                                             const int32_t xl, const int32_t xr, const int32_t cr,
                                                             uint32_t *puv, uint32_t *pz, int *more, uint32_t *ndiv)
{
    return lean_run(tri, 0, 0, s, x0, xl, xr, cr, puv, pz, more, ndiv, 1, 0);
}

static FXL__NOINLINE FXL__FLATTEN int32_t lean_run_uvz_exact(const fxl__tri_t *tri, fxl__lean_t *s, const int32_t x0,
                                                            const int32_t cr, uint32_t *puv, uint32_t *pz, int *more,
                                                            uint32_t *ndiv)
{
    return exact_run(tri, s, x0, cr, puv, pz, more, ndiv, 1);
}

static FXL__NOINLINE FXL__FLATTEN int32_t lean_run_uvz_auto(const fxl__tri_t *tri, const int32_t t_row,
                                                            fxl__lean_t *s, const int32_t x0, const int32_t xl,
                                                            const int32_t xr, const int32_t cr, uint32_t *puv,
                                                            uint32_t *pz, int *more, uint32_t *ndiv)
{
    return lean_run(tri, 1, t_row, s, x0, xl, xr, cr, puv, pz, more, ndiv, 1, 0);
}

static FXL__UNSWITCH int32_t lean_run_uvz(const fxl__tri_t *tri, const int autoseg, const int32_t t_row,
                                          fxl__lean_t *s, const int32_t x0, const int32_t xl, const int32_t xr,
                                          const int32_t cr, uint32_t *puv, uint32_t *pz, int *more, uint32_t *ndiv)
{
    if (autoseg)
        return lean_run_uvz_auto(tri, t_row, s, x0, xl, xr, cr, puv, pz, more, ndiv);
    if (q_row_const(tri))
        return lean_run_uvz_rowc(tri, s, x0, xl, xr, cr, puv, pz, more, ndiv);
    if (cr - 1 - x0 >= FXL__RUN_MIN) {
        /* called one after the other, not nested: their frames do not add up */
        const int32_t m = lean_run_uvz_exact(tri, s, x0, cr, puv, pz, more, ndiv);
        if (m)
            return m;
    }
    return lean_run_uvz_plain(tri, s, x0, xl, xr, cr, puv, pz, more, ndiv);
}
#endif
#endif /* FXL__V_ANY */

#if FXL__V_ANY
/* step_pow2 of coord_diff for repeat axes, from d = b - a as uint32; the
 * result is the int32 bit pattern. A negative d has magnitude 0 - d <= 2^31. */
static inline uint32_t step_pow2_u32(uint32_t d, int k)
{
    return (d & 0x80000000u) ? 0u - ((0u - d) >> k) : d >> k;
}

/* Thumb-1 (Cortex-M0+: eight low registers, no shifted operands) keeps
 * rowc_run's plain loop: the branchless step and two points an iteration
 * cost it 5% on the floor (subdiv16 point 32.1 -> 33.8 a pixel), where
 * the Cortex-M4 and x86-64 gain 1-3%. It also keeps the pixel loop per
 * segment in the rowc walk: the run loop (FXL_T_LOOP##_segs) spilled
 * there (floor subdiv16 point 33.1 -> 34.4). */
#if defined(__ARM_ARCH_ISA_THUMB) && __ARM_ARCH_ISA_THUMB < 2
#define FXL__ROWC_LEAN 1
#else
#define FXL__ROWC_LEAN 0
#endif

#if !FXL__ROWC_LEAN
/* The same as a floor shift of d biased by bias = 2^k - 1 when negative:
 * no branch (a Cortex-M4 AND with ASR #31, ADD, ASR), for loops that keep
 * bias in a register (elsewhere the two-way form was as cheap). */
static inline uint32_t step_pow2_u32_b(uint32_t d, int k, uint32_t bias)
{
    const uint32_t neg = 0u - (d >> 31);
    return (uint32_t)fxl__asr32(fxl__i32_of_bits(d + (neg & bias)), k);
}
#endif

/* A coordinate's value at a correction point of a row of constant q (the
 * rowc walk): its plane value s times the span's 1/q r, shifted by k with
 * half = 2^(k-1): fxl__persp_e's low 32 bits. hi (a constant): the form
 * for k >= 33 on 32-bit cores, one ASR of the product's high word (the
 * same value). */
static FXL__HOT_INLINE uint32_t rowc_value(uint64_t s, int32_t r, int k, uint64_t half, const int hi)
{
    const int64_t prod = fxl__mul_s32(fxl__persp_mant((int64_t)s), r);
    return hi ? fxl__persp_lo32_hi(prod, k) : fxl__persp_lo32(prod, k, half);
}

/* step_of of coord_diff, div, likewise; div = 0 gives 0. */
static inline uint32_t step_div_u32(uint32_t d, uint32_t div)
{
    if (div == 0u)
        return 0u;
    return (d & 0x80000000u) ? 0u - (0u - d) / div : d / div;
}

#endif

#if FXL__V_ANY_Z
/* The signed step of z1 - z0 (|z1 - z0| < 2^32) truncated toward zero,
 * as bits modulo 2^32, as the generic walk's seg.dz. z is stepped in
 * uint32, so z0 plus i steps is z0 + i (z1 - z0) / n modulo 2^32, which is
 * the interpolated value itself for every pixel i < n of the segment even
 * when one step is 2^31 or more (a one-pixel step across a depth ratio
 * near 2^32); a step saturated to an int32 stopped there, short of z1. */
static inline uint32_t step_z_pow2(uint32_t z1, uint32_t z0, int k)
{
    return z1 >= z0 ? (z1 - z0) >> k : 0u - ((z0 - z1) >> k);
}

static inline uint32_t step_z_div(uint32_t z1, uint32_t z0, uint32_t div)
{
    if (div == 0u)
        return 0u;
    return z1 >= z0 ? (z1 - z0) / div : 0u - (z0 - z1) / div;
}
#endif

#if FXL__V_ANY
/* The walk along rows of constant q (FXL_T_ROWC, span_fast.h). One
 * segment of a batch: u, v (z) at its start and its steps, as the lean
 * walk computes them. */
typedef struct fxl__rseg {
    uint32_t u, du, v, dv, z, dz;
} fxl__rseg_t;

/* One coordinate of the walk: its plane value and value at the latest
 * correction point, its plane steps, and fxl__persp_lo32's shift k and
 * 2^(k-1) for the span's 1/q (r). */
typedef struct fxl__raxis {
    uint64_t s, gN, g, half;
    int32_t r;
    int k;
    uint32_t c;
} fxl__raxis_t;

/* One coordinate of a batch of segments of 2^segk pixels: nfull whole ones,
 * then (last) the span's last one, ending div pixels on. Writes each one's
 * start value and step to out[0], out[1] (a stride of one fxl__rseg_t) and
 * leaves ax at the last end. One axis at a time, out of line and shared by
 * every variant: its few live values stay in registers (both axes in one
 * loop inside the walk spilled ~20 Cortex-M4 instructions a segment).
 * rowc_run is its whole segments, with hi a constant (one copy each);
 * it returns out past them. */
static FXL__UNSWITCH uint32_t *rowc_run(fxl__raxis_t *ax, int segk, int32_t nfull, uint32_t *out, const int hi)
{
    const uint32_t stride = (uint32_t)(sizeof(fxl__rseg_t) / sizeof(uint32_t));
    const uint64_t gN = ax->gN;
    const int32_t r = ax->r;
    uint64_t s = ax->s;
    uint32_t c0 = ax->c;
    int32_t i;
    /* the next correction point's value into c */
#define FXL__ROWC_POINT(c) ((c) = rowc_value(s += gN, r, ax->k, ax->half, hi))
#if FXL__ROWC_LEAN
    for (i = 0; i < nfull; i++, out += stride) {
        uint32_t c1;
        FXL__ROWC_POINT(c1);
        out[0] = c0;
        out[1] = step_pow2_u32(c1 - c0, segk);
        c0 = c1;
    }
#else
    const uint32_t bias = (1u << segk) - 1u;
    /* two points an iteration: no register copy of c0 and half the loop
     * overhead (~2.5 Cortex-M4 instructions a point) */
    for (i = 1; i < nfull; i += 2, out += 2 * stride) {
        uint32_t c1, c2;
        FXL__ROWC_POINT(c1);
        out[0] = c0;
        out[1] = step_pow2_u32_b(c1 - c0, segk, bias);
        FXL__ROWC_POINT(c2);
        out[stride] = c1;
        out[stride + 1] = step_pow2_u32_b(c2 - c1, segk, bias);
        c0 = c2;
    }
    if (i == nfull) {
        uint32_t c1;
        FXL__ROWC_POINT(c1);
        out[0] = c0;
        out[1] = step_pow2_u32_b(c1 - c0, segk, bias);
        c0 = c1;
        out += stride;
    }
#endif
#undef FXL__ROWC_POINT
    ax->s = s;
    ax->c = c0;
    return out;
}

static FXL__NOINLINE void rowc_axis(fxl__raxis_t *ax, int segk, int32_t nfull, int last, uint32_t div, uint32_t *out)
{
    if (ax->g == 0u) {
        /* The coordinate's plane is constant along the row (v on a level
         * floor): every correction point has one value, c1 below, which
         * the loop would compute at each (s += 0), and after the first
         * step every step is 0: the same values for one product
         * (Cortex-M4 floor subdiv16 point 13.43 -> 13.04 instructions a
         * pixel). */
        const uint32_t stride = (uint32_t)(sizeof(fxl__rseg_t) / sizeof(uint32_t));
        const uint32_t c1 = rowc_value(ax->s, ax->r, ax->k, ax->half, 0);
        uint32_t c0 = ax->c;
        int32_t i;
        for (i = 0; i < nfull; i++, out += stride) {
            out[0] = c0;
            out[1] = step_pow2_u32(c1 - c0, segk);
            c0 = c1;
        }
        if (last) {
            out[0] = c0;
            out[1] = step_div_u32(c1 - c0, div);
            c0 = c1;
        }
        ax->c = c0;
        return;
    }
    /* shifts of 33 and more: one ASR of prod's high word (fxl__persp_lo32_hi) */
    out = FXL__WORD32 && ax->k >= 33 ? rowc_run(ax, segk, nfull, out, 1) : rowc_run(ax, segk, nfull, out, 0);
    if (last) {
        const uint32_t c0 = ax->c;
        const uint32_t c1 = rowc_value(ax->s += ax->g * div, ax->r, ax->k, ax->half, 0);
        out[0] = c0;
        out[1] = step_div_u32(c1 - c0, div);
        ax->c = c1;
    }
}

#if FXL__V_ANY_Z
/* z likewise (fast_z of the z plane; ax->c is z). */
static FXL__NOINLINE void rowc_zaxis(fxl__raxis_t *ax, int segk, int32_t nfull, int last, uint32_t div, uint32_t *out)
{
    const uint32_t stride = (uint32_t)(sizeof(fxl__rseg_t) / sizeof(uint32_t));
    uint64_t s = ax->s;
    uint32_t z0 = ax->c;
    int32_t i;
    if (ax->g == 0u) {
        /* z constant along the row too (a level floor): every point's z
         * is z0 and every step 0, as below (~1.5 x86-64 instructions a
         * pixel fewer on the floor) */
        for (i = nfull + (last ? 1 : 0); i > 0; i--, out += stride) {
            out[0] = z0;
            out[1] = 0u;
        }
        return;
    }
    for (i = 0; i < nfull; i++, out += stride) {
        const uint32_t z1 = fast_z((int64_t)(s += ax->gN));
        out[0] = z0;
        out[1] = step_z_pow2(z1, z0, segk);
        z0 = z1;
    }
    if (last) {
        const uint32_t z1 = fast_z((int64_t)(s += ax->g * div));
        out[0] = z0;
        out[1] = step_z_div(z1, z0, div);
        z0 = z1;
    }
    ax->s = s;
    ax->c = z0;
}
#endif
#endif

#if FXL_HAVE_MIPMAP && FXL__V_ANY
/* shift_step of an int32 step (no saturation needed), as bits. */
static inline uint32_t shift_step_u32(uint32_t d, int level)
{
    return (d & 0x80000000u) ? ~(~d >> level) : d >> level;
}

static inline int32_t fast_lod(const fxl__tri_t *tri, int64_t q0, const fxl__pt_t *p0)
{
    return tri->lod_at(tri, q0, p0->u64, p0->v64);
}
#endif

#if FXL_HAVE_MIPMAP
/* The level nearest a LOD (q8, clamped): rounded half up. Every walk's
 * FXL_MIP_NEAREST choice. */
static inline int lod_nearest(int32_t lod)
{
    return (lod + 128) >> 8;
}

/* A segment's LOD from lod_at's value: the bias added, clamped to the
 * levels (the generic and the fast walks, bit for bit the same). */
static inline int32_t seg_lod(const fxl__tri_t *tri, int32_t lod)
{
    lod += tri->draw->lod_bias_q8;
    if (lod < 0)
        lod = 0;
    if (lod > tri->lod_max_q8)
        lod = tri->lod_max_q8;
    return lod;
}

#if FXL_HAVE_RR
/* The LOD of a reciprocal run (recip_run.h) at its pixel rr->x (rr->left
 * >= 1) for a triangle with a per-segment LOD: lod_at from the run's u, v
 * there (rebased, |u| < 2^29: the int32 values are the 64-bit ones) and
 * the exact q. The generic and the fast walks take it on AUTO's LOD grid
 * (auto.h), as their segments do. */
static FXL__NOINLINE int32_t rr_lod(const fxl__tri_t *tri, int32_t dY, const fxl__rr_t *rr)
{
    const int64_t q = fxl__rr_plane(tri, &tri->q, rr->x, dY);
    const uint32_t r = fxl__rr_recip(rr->q);
    return seg_lod(tri, tri->lod_at(tri, q, fxl__i32_of_bits(fxl__rr_coord(rr->a, r)),
                                    fxl__i32_of_bits(fxl__rr_coord(rr->b, r))));
}

/* The run state at cl and the LOD its first pixel takes: the one of the
 * grid point at or left of cl (a span's walk from xl holds it there). */
static int32_t rr_start(const fxl__tri_t *tri, int32_t dY, int32_t xl, int32_t cl, fxl__rr_t *rr)
{
    const int grid = tri->nlevels > 1 && tri->lod_per_segment;
    int32_t lod = tri->lod_q8_tri;
    fxl__rr_seek(tri, dY, xl, grid ? FXL__AUTO_LOD_GRID(cl, xl) : cl, rr);
    if (grid) {
        lod = rr_lod(tri, dY, rr);
        fxl__rr_advance(tri, dY, xl, cl, rr);
    }
    return lod;
}
#endif

#endif

/* a variant's choice of walk for a triangle (span_fast.h, FXL_T_SPAN##_pick) */
typedef fxl__span_fn (*fxl__span_pick_fn)(fxl__tri_t *tri);

/* the variants, as FXL__V (top of the file) selects them */
#if FXL__FMT_RUNTIME ? FXL__VB(0, 0) : FXL__V(0, 0, 0)
#define FXL_T_LOOP loop_point
#define FXL_T_SPAN span_point
#define FXL_T_SEG seg_point
#define FXL_T_BILINEAR 0
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 0
#define FXL_T_SWAP FXL__SWAP_NAT
#include "span_fast.h"
#endif
#if !FXL__FMT_RUNTIME && FXL__V(0, 0, 1)
#define FXL_T_LOOP loop_point_swap
#define FXL_T_SPAN span_point_swap
#define FXL_T_SEG seg_point_swap
#define FXL_T_BILINEAR 0
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 0
#define FXL_T_SWAP 1
#include "span_fast.h"
#endif
#if FXL__FMT_RUNTIME ? FXL__VB(0, 1) : FXL__V(0, 1, 0)
#define FXL_T_LOOP loop_point_z
#define FXL_T_SPAN span_point_z
#define FXL_T_SEG seg_point_z
#define FXL_T_BILINEAR 0
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 1
#define FXL_T_SWAP FXL__SWAP_NAT
#include "span_fast.h"
#endif
#if !FXL__FMT_RUNTIME && FXL__V(0, 1, 1)
#define FXL_T_LOOP loop_point_z_swap
#define FXL_T_SPAN span_point_z_swap
#define FXL_T_SEG seg_point_z_swap
#define FXL_T_BILINEAR 0
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 1
#define FXL_T_SWAP 1
#include "span_fast.h"
#endif
#if FXL__FMT_RUNTIME ? FXL__VB(1, 0) && !FXL__VB(1, 1) : FXL__V(1, 0, 0)
#define FXL_T_LOOP loop_bilin
#define FXL_T_SPAN span_bilin
#define FXL_T_SEG seg_bilin
#define FXL_T_BILINEAR 1
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 0
#define FXL_T_SWAP FXL__SWAP_NAT
#include "span_fast.h"
#endif
#if !FXL__FMT_RUNTIME && FXL__V(1, 0, 1)
#define FXL_T_LOOP loop_bilin_swap
#define FXL_T_SPAN span_bilin_swap
#define FXL_T_SEG seg_bilin_swap
#define FXL_T_BILINEAR 1
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 0
#define FXL_T_SWAP 1
#include "span_fast.h"
#endif
#if FXL__FMT_RUNTIME ? FXL__VB(1, 1) : FXL__V(1, 1, 0)
#define FXL_T_LOOP loop_bilin_z
#define FXL_T_SPAN span_bilin_z
#define FXL_T_SEG seg_bilin_z
#define FXL_T_BILINEAR 1
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH FXL__DEPTH_BL
#define FXL_T_SWAP FXL__SWAP_NAT
#include "span_fast.h"
#endif
#if !FXL__FMT_RUNTIME && FXL__V(1, 1, 1)
#define FXL_T_LOOP loop_bilin_z_swap
#define FXL_T_SPAN span_bilin_z_swap
#define FXL_T_SEG seg_bilin_z_swap
#define FXL_T_BILINEAR 1
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 1
#define FXL_T_SWAP 1
#include "span_fast.h"
#endif
/* The tinted copies (FXL_FAST_TINT): the same walks and loops, each texel
 * modulated by the draw's flat colour before the store (FXL_T_TINT). */
#if FXL__V_TINT && FXL__V(0, 0, 0)
#define FXL_T_LOOP loop_point_t
#define FXL_T_SPAN span_point_t
#define FXL_T_SEG seg_point_t
#define FXL_T_BILINEAR 0
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 0
#define FXL_T_SWAP 0
#define FXL_T_TINT 1
#include "span_fast.h"
#endif
#if FXL__V_TINT && FXL__V(1, 0, 0)
#define FXL_T_LOOP loop_bilin_t
#define FXL_T_SPAN span_bilin_t
#define FXL_T_SEG seg_bilin_t
#define FXL_T_BILINEAR 1
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 0
#define FXL_T_SWAP 0
#define FXL_T_TINT 1
#include "span_fast.h"
#endif
#if FXL__V_TINT && FXL__V(0, 1, 0)
#define FXL_T_LOOP loop_point_z_t
#define FXL_T_SPAN span_point_z_t
#define FXL_T_SEG seg_point_z_t
#define FXL_T_BILINEAR 0
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 1
#define FXL_T_SWAP 0
#define FXL_T_TINT 1
#include "span_fast.h"
#endif
#if FXL__V_TINT && FXL__V(1, 1, 0)
#define FXL_T_LOOP loop_bilin_z_t
#define FXL_T_SPAN span_bilin_z_t
#define FXL_T_SEG seg_bilin_z_t
#define FXL_T_BILINEAR 1
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 1
#define FXL_T_SWAP 0
#define FXL_T_TINT 1
#include "span_fast.h"
#endif
#if FXL__V_TINT && FXL__V(0, 0, 1)
#define FXL_T_LOOP loop_point_swap_t
#define FXL_T_SPAN span_point_swap_t
#define FXL_T_SEG seg_point_swap_t
#define FXL_T_BILINEAR 0
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 0
#define FXL_T_SWAP 1
#define FXL_T_TINT 1
#include "span_fast.h"
#endif
#if FXL__V_TINT && FXL__V(1, 0, 1)
#define FXL_T_LOOP loop_bilin_swap_t
#define FXL_T_SPAN span_bilin_swap_t
#define FXL_T_SEG seg_bilin_swap_t
#define FXL_T_BILINEAR 1
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 0
#define FXL_T_SWAP 1
#define FXL_T_TINT 1
#include "span_fast.h"
#endif
#if FXL__V_TINT && FXL__V(0, 1, 1)
#define FXL_T_LOOP loop_point_z_swap_t
#define FXL_T_SPAN span_point_z_swap_t
#define FXL_T_SEG seg_point_z_swap_t
#define FXL_T_BILINEAR 0
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 1
#define FXL_T_SWAP 1
#define FXL_T_TINT 1
#include "span_fast.h"
#endif
#if FXL__V_TINT && FXL__V(1, 1, 1)
#define FXL_T_LOOP loop_bilin_z_swap_t
#define FXL_T_SPAN span_bilin_z_swap_t
#define FXL_T_SEG seg_bilin_z_swap_t
#define FXL_T_BILINEAR 1
#define FXL_T_MIPLIN 0
#define FXL_T_DEPTH 1
#define FXL_T_SWAP 1
#define FXL_T_TINT 1
#include "span_fast.h"
#endif
#if FXL__V(0, 0, 0) && FXL__V_MIP
#define FXL_T_LOOP loop_pml
#define FXL_T_LOOP1 loop_point
#define FXL_T_SPAN span_pml
#define FXL_T_BILINEAR 0
#define FXL_T_MIPLIN 1
#define FXL_T_DEPTH 0
#define FXL_T_SWAP 0
#include "span_fast.h"
#endif
#if FXL__V(0, 0, 1) && FXL__V_MIP
#define FXL_T_LOOP loop_pml_swap
#define FXL_T_LOOP1 loop_point_swap
#define FXL_T_SPAN span_pml_swap
#define FXL_T_BILINEAR 0
#define FXL_T_MIPLIN 1
#define FXL_T_DEPTH 0
#define FXL_T_SWAP 1
#include "span_fast.h"
#endif
#if FXL__V(0, 1, 0) && FXL__V_MIP
#define FXL_T_LOOP loop_pml_z
#define FXL_T_LOOP1 loop_point_z
#define FXL_T_SPAN span_pml_z
#define FXL_T_BILINEAR 0
#define FXL_T_MIPLIN 1
#define FXL_T_DEPTH 1
#define FXL_T_SWAP 0
#include "span_fast.h"
#endif
#if FXL__V(0, 1, 1) && FXL__V_MIP
#define FXL_T_LOOP loop_pml_z_swap
#define FXL_T_LOOP1 loop_point_z_swap
#define FXL_T_SPAN span_pml_z_swap
#define FXL_T_BILINEAR 0
#define FXL_T_MIPLIN 1
#define FXL_T_DEPTH 1
#define FXL_T_SWAP 1
#include "span_fast.h"
#endif
#if FXL__V(1, 0, 0) && FXL__V_MIP
#define FXL_T_LOOP loop_tri
#define FXL_T_LOOP1 loop_bilin
#define FXL_T_SPAN span_tri
#define FXL_T_BILINEAR 1
#define FXL_T_MIPLIN 1
#define FXL_T_DEPTH 0
#define FXL_T_SWAP 0
#include "span_fast.h"
#endif
#if FXL__V(1, 0, 1) && FXL__V_MIP
#define FXL_T_LOOP loop_tri_swap
#define FXL_T_LOOP1 loop_bilin_swap
#define FXL_T_SPAN span_tri_swap
#define FXL_T_BILINEAR 1
#define FXL_T_MIPLIN 1
#define FXL_T_DEPTH 0
#define FXL_T_SWAP 1
#include "span_fast.h"
#endif
#if FXL__V(1, 1, 0) && FXL__V_MIP
#define FXL_T_LOOP loop_tri_z
#define FXL_T_LOOP1 loop_bilin_z
#define FXL_T_SPAN span_tri_z
#define FXL_T_BILINEAR 1
#define FXL_T_MIPLIN 1
#define FXL_T_DEPTH 1
#define FXL_T_SWAP 0
#include "span_fast.h"
#endif
#if FXL__V(1, 1, 1) && FXL__V_MIP
#define FXL_T_LOOP loop_tri_z_swap
#define FXL_T_LOOP1 loop_bilin_z_swap
#define FXL_T_SPAN span_tri_z_swap
#define FXL_T_BILINEAR 1
#define FXL_T_MIPLIN 1
#define FXL_T_DEPTH 1
#define FXL_T_SWAP 1
#include "span_fast.h"
#endif

/* Variant table, id = 1 + bilinear + 2 depth + 4 swap + 8 mip-linear + 16
 * tinted (not with mip-linear: ids 17..24); the
 * seg column is what fxl__pick_seg_fn hands out for the id (seg_generic for
 * the blended variants, as they had no specialised loop), and draw_span
 * takes the span column only when the caller passed exactly that seg
 * function (a measuring probe gets the generic walk). */
#if FXL_HAVE_GENERIC
#define SEG_GENERIC seg_generic
#else
#define SEG_GENERIC 0
#endif
/* IF_<dimension>(x): x where that dimension's variants are built, else 0 */
#if FXL__V_PT
#define IF_PT(x) x
#else
#define IF_PT(x) 0
#endif
#if FXL__V_BL
#define IF_BL(x) x
#else
#define IF_BL(x) 0
#endif
#if FXL__V_NOZ
#define IF_NOZ(x) x
#else
#define IF_NOZ(x) 0
#endif
#if FXL__V_Z
#define IF_Z(x) x
#else
#define IF_Z(x) 0
#endif
#if FXL__V_NAT
#define IF_NAT(x) x
#else
#define IF_NAT(x) 0
#endif
#if FXL__V_SWP
#define IF_SWP(x) x
#else
#define IF_SWP(x) 0
#endif
#if FXL__V_MIP
#define IF_MIP(x) x
#else
#define IF_MIP(x) 0
#endif
/* A row of the table: ONE for a one-level variant, TWO for a two-level one
 * (its seg column is the generic seg function), built where FXL__V(bil, z,
 * sw) holds (and FXL__V_MIP for TWO), else empty. IF_V selects with the
 * same three flags through the dimensions' IF_ macros above. */
#define IF_FILT_0 IF_PT
#define IF_FILT_1 IF_BL
#define IF_DEPTH_0 IF_NOZ
#define IF_DEPTH_1 IF_Z
#define IF_FMT_0 IF_NAT
#define IF_FMT_1 IF_SWP
#define IF_V(bil, z, sw, x) IF_FILT_##bil(IF_DEPTH_##z(IF_FMT_##sw(x)))
#define ONE(bil, z, sw, name) FAST_ENTRY(IF_V(bil, z, sw, seg_##name), IF_V(bil, z, sw, span_##name##_pick))
/* the eight one-level rows in id order, their names ending in sfx (empty,
 * or _t for the tinted copies) */
#define ONE_ROWS(sfx)                                                                                       \
    ONE(0, 0, 0, point##sfx), ONE(1, 0, 0, bilin##sfx), ONE(0, 1, 0, point_z##sfx), ONE(1, 1, 0, bilin_z##sfx), \
        ONE(0, 0, 1, point_swap##sfx), ONE(1, 0, 1, bilin_swap##sfx), ONE(0, 1, 1, point_z_swap##sfx),         \
        ONE(1, 1, 1, bilin_z_swap##sfx)
/* Size builds: a row of a kept variant names its loop (FXL__FMT_RUNTIME):
 * bilinear, the one with depth where that is kept. */
#define RT_SEG_01 seg_point_z
#define RT_SEG_11 seg_bilin_z
#define RT_SEG_00 seg_point
#if FXL__VB(1, 1)
#define RT_SEG_10 seg_bilin_z
#else
#define RT_SEG_10 seg_bilin
#endif
#define RT_SEG(bil, z) RT_SEG_##bil##z
#define RT(bil, z, sw) FAST_ENTRY(IF_V(bil, z, sw, RT_SEG(bil, z)), 0)
#define TWO(bil, z, sw, name)                                                                               \
    FAST_ENTRY(IF_V(bil, z, sw, IF_MIP(SEG_GENERIC)), IF_V(bil, z, sw, IF_MIP(span_##name##_pick)))
/* The span column exists only where the specialised walks are built. */
#if FXL__FAST_SPANS
#define FAST_ENTRY(seg, pick) {seg, pick}
#else
#define FAST_ENTRY(seg, pick) {seg}
#endif
static const struct {
    fxl__seg_fn seg;
#if FXL__FAST_SPANS
    fxl__span_pick_fn pick;   /* the variant's walk for a triangle */
#endif
} fast_tab[FXL__V_TINT ? 25 : 17] = {
    FAST_ENTRY(0, 0),
#if FXL__FMT_RUNTIME
    RT(0, 0, 0),
    RT(1, 0, 0),
    RT(0, 1, 0),
    RT(1, 1, 0),
    RT(0, 0, 1),
    RT(1, 0, 1),
    RT(0, 1, 1),
    RT(1, 1, 1),
#else
    ONE_ROWS(),
#endif
    TWO(0, 0, 0, pml),
    TWO(1, 0, 0, tri),
    TWO(0, 1, 0, pml_z),
    TWO(1, 1, 0, tri_z),
    TWO(0, 0, 1, pml_swap),
    TWO(1, 0, 1, tri_swap),
    TWO(0, 1, 1, pml_z_swap),
    TWO(1, 1, 1, tri_z_swap),
#if FXL__V_TINT   /* the tinted one-level variants, ids 17..24 */
    ONE_ROWS(_t),
#endif
};

int fxl__fast_id(const fxl_target_t *target, const fxl_draw_t *d, int mip_linear)
{
    const fxl_texture_t *t = d->texture;
    const uint32_t both = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
    const int zmode = target->depth && (d->depth & both);
    int id, tinted = 0;

    /* (speed builds only look past REPLACE: the size builds' test is as
     * before, byte for byte) */
    if (!(t && tex_repeat565(t) && (d->texenv == FXL_TEXENV_REPLACE || (FXL_HAVE_GENERIC && FXL__FAST_SPANS)) &&
          t->log2_w + t->log2_h <= 16 && (!zmode || (d->depth & both) == both)))
        return 0;
    if (d->texenv != FXL_TEXENV_REPLACE) {
        /* a flat tint: white leaves every texel as it is (modulate565), so
         * it draws as REPLACE in speed builds (at -Os the test cost 32 of
         * the 82 bytes left under 16 KiB); other colours take the tinted
         * copies (one level) where they are built. Tested after REPLACE:
         * before it, small triangles cost 8 x86 instructions more. */
        if (!(FXL_HAVE_GENERIC && FXL__FAST_SPANS && d->texenv == FXL_TEXENV_MODULATE && d->shade == FXL_SHADE_FLAT))
            return 0;
        tinted = d->color != 0xFFFFu;
        if (tinted && (!FXL__V_TINT || mip_linear))
            return 0;
    }
    id = 1 + (d->filter == FXL_FILTER_BILINEAR ? 1 : 0) + (zmode ? 2 : 0) +
         (target->format == FXL_PIXFMT_RGB565_SWAP ? 4 : 0) + (mip_linear ? 8 : 0) + (tinted ? 16 : 0);
    return fast_tab[id].seg ? id : 0;
}

fxl__seg_fn fxl__pick_seg_fn(const fxl__tri_t *tri)
{
    /* fxl__span_setup found it (0 without texture coordinates, as
     * fxl__fast_id gives there) */
    int id = tri->fast_id;
    if (id)
        return fast_tab[id].seg;
#if FXL_HAVE_GENERIC && FXL__FAST_SPANS
    /* MODULATE draws of those textures: their own pixel loop */
    if (fxl__has_uv(tri) && tri->draw->texenv == FXL_TEXENV_MODULATE && tex_repeat565(tri->tex))
        return seg_modulate;
#endif
    return SEG_GENERIC;
}

void fxl__span_setup(fxl__tri_t *tri)
{
    int i, k = tri->seg_log2;
    tri->pl[PQ] = &tri->q;
    tri->pl[PZ] = &tri->z;
    for (i = 0; i < FXL__NATTR; i++)
        tri->pl[PA + i] = &tri->a[i];
    tri->np = fxl__has_color(tri) ? NPLANES : (fxl__has_uv(tri) ? PA + 2 : PA);
    /* planes past np are never read (correct, lod_at and the fast walk
     * read q, z, u, v, and the colours only with has_color) */
    for (i = 0; i < tri->np; i++) {
        uint64_t g = (uint64_t)tri->pl[i]->gx * FXL__ONE;   /* per pixel, modular */
        tri->gpx[i] = (int64_t)g;
        tri->gpxN[i] = (int64_t)(g << k);
    }
    tri->q_const = tri->q.gx == 0 && tri->q.gy == 0;
    if (tri->q_const)
        fxl__recip(tri->q_min, &tri->rc_qmin);
    tri->fast_id = 0;
    tri->lod_grid = 0;
    if (fxl__has_uv(tri)) {
        tri->persp_eb[0] = fxl__persp_eb(tri->a_shift[FXL__AU] + (int)tri->tex->log2_w);
        tri->persp_eb[1] = fxl__persp_eb(tri->a_shift[FXL__AV] + (int)tri->tex->log2_h);
        tri->fast_id = (uint8_t)fxl__fast_id(tri->target, tri->draw, tri->mip_linear);
#if FXL_HAVE_MIPMAP
        if (tri->lod_per_segment && tri->nlevels > 1)
            lod_setup(tri);
#endif
#if FXL_HAVE_MIPMAP && FXL_HAVE_AUTO
        /* whatever lengths AUTO chose (one for the triangle or one per
         * segment): both keep segments aligned from the span's left end;
         * one length of at least the grid (raster.c caps it there) puts
         * every segment start on the grid, with nothing to hold */
        tri->lod_grid = FXL__AUTO_LOD_GRIDDED(tri->draw, tri) && (tri->auto_seg || tri->seg_log2 < FXL__AUTO_LOD_LOG2);
#endif
    }
}

#if FXL_HAVE_MIPMAP
/* A segment's levels from its LOD (q8, clamped): the nearest one, or with
 * two blended the lower one, the weight and the next (none at the top).
 * Returns the level. */
static int seg_levels(const fxl__tri_t *tri, int32_t lod, fxl__seg_t *seg)
{
    int level;
    seg->lod_q8 = lod;
    if (tri->mip_linear) {
        level = lod >> 8;
        seg->lod_frac_q8 = (uint32_t)lod & 255u;
        seg->lvl2 = level + 1 < tri->nlevels ? &tri->level[level + 1] : 0;
    } else {
        level = lod_nearest(lod);
    }
    seg->lvl = &tri->level[level];
    return level;
}
#endif

#if FXL_HAVE_RR
/* AUTO's reciprocal runs (recip_run.h) in the generic walk: every pixel a
 * one-pixel segment with the run's u, v and the exact z, the values the
 * fast walks' FXL_T_RR (one level, two blended) and FXL_T_RRN (the nearest
 * of several) give. Repeat or mirror axes, no colours (auto.c). Out of
 * line: inlined into fxl__draw_span its frame (~200 bytes) was under every
 * generic walk's. */
static FXL__NOINLINE void draw_span_rr(const fxl__tri_t *tri, fxl__seg_fn fn, int32_t row, int32_t xl, int32_t cl,
                                       int32_t cr)
{
    const fxl_target_t *tg = tri->target;
    const int32_t dY = row * FXL__ONE + FXL__HALF - tri->Y0;
    int64_t sz = fxl__rr_plane(tri, &tri->z, cl, dY);
    int32_t idx = (row - tg->origin_y) * tg->stride + (cl - tg->origin_x);
    uint32_t written = 0;
    fxl__seg_t seg;
    fxl__rr_t rr;
    int32_t x;
#if FXL_HAVE_MIPMAP
    int32_t lod = rr_start(tri, dY, xl, cl, &rr);
#else
    fxl__rr_seek(tri, dY, xl, cl, &rr);
#endif

    seg_zero(&seg);
    seg.lvl = &tri->level[0];
    seg.n = 1;
    for (x = cl; x < cr; x++) {
        uint32_t r, u, v;
        if (rr.left == 0)
            fxl__rr_next(tri, dY, xl, &rr);
        r = fxl__rr_recip(rr.q);
        u = fxl__rr_coord(rr.a, r);
        v = fxl__rr_coord(rr.b, r);
        seg.u = u;
        seg.v = v;
#if FXL_HAVE_MIPMAP
        if (tri->nlevels > 1) {
            /* the generic walk's level choice for a segment (lod on
             * AUTO's grid), its coordinates shifted to the levels */
            int level;
            if (tri->lod_per_segment && x != cl && FXL__AUTO_LOD_ON_GRID(x, xl))
                lod = rr_lod(tri, dY, &rr);
            level = seg_levels(tri, lod, &seg);
            /* repeat and mirror axes (auto.c): shifted by the level alone,
             * as the fast walks do (an axis of one texel reads texel 0
             * whatever its shift) */
            seg.u = u >> level;
            seg.v = v >> level;
            seg.u2 = seg.u >> 1;
            seg.v2 = seg.v >> 1;
        }
#endif
        seg.z = FXL_HAVE_DEPTH ? sat_u32(sz >> FXL__PF) : 0u;
        seg.dst = tg->pixels + idx;
        seg.zb = tg->depth ? tg->depth + idx : 0;
        written += fn(tri, &seg);
        fxl__rr_skip(&rr, 1u);
        sz = (int64_t)((uint64_t)sz + (uint64_t)tri->gpx[FXL__PZ]);
        idx++;
    }
    if (tri->stats) {
        tri->stats->divisions++;   /* as the fast walks' FXL_T_RR */
        tri->stats->pixels += written;
        tri->stats->spans++;
    }
}
#endif

/* The generic walk's two correction points: swapped after each segment,
 * or (FXL__GW_SWAP 0) p1 copied to p0. Thumb-2 cores (Cortex-M3/M4/M7/M33)
 * copy the 48 bytes inline with LDM/STM, 28 B less code at -Os, where the
 * core keeps within 16 KiB. Elsewhere a size build calls memcpy for the
 * copy (newlib-nano's is a byte loop: ~290 Cortex-M0+ instructions a
 * segment), so the walk swaps. Those cores also step a full segment's
 * planes by gpxN instead of a product, four calls to __aeabi_lmul on the
 * Cortex-M0+ (Thumb-2 has UMULL; the branch costs 62 B at -Os). Cortex-M0+
 * -Os cube, subdiv16 point: 2.78 M -> 2.52 M instructions with the swap,
 * 2.32 M -> 2.23 M with gpxN (fixed.c's one-word division loop between;
 * docs/design.md, "Size builds on the Cortex-M0+"). 64-bit hosts swap too,
 * so the tests run this form; determinism.sh's -Os builds copy. */
#ifndef FXL__GW_SWAP
#if defined(__thumb2__)
#define FXL__GW_SWAP 0
#else
#define FXL__GW_SWAP 1
#endif
#endif

/* generic_walk and correct_t: always inline (GCC), in size builds too,
 * where each has one caller (no mod copy): left out of line at -Os the walk
 * sat under a wrapper's frame on the Cortex-M0+ (+24 B of stack, +16 B). */
#if defined(__GNUC__)
#define FXL__ONE_BODY inline __attribute__((always_inline))
#else
#define FXL__ONE_BODY inline
#endif

/* The generic walk: any attribute set, any seg function (or a probe).
 * Out of line: inlined into fxl__draw_span (GCC's choice at -O2 once its
 * plane evaluation was inline) its frame sat under the reciprocal-run
 * walk's too, +248 bytes on the Cortex-M4's deepest draw stack. */
static FXL__ONE_BODY void generic_walk(const fxl__tri_t *tri, fxl__seg_fn fn, int32_t row, int32_t xl,
                                        int32_t xr, int32_t cl, int32_t cr, const int mod)
{
    int64_t pv[NPLANES];         /* planes past np are 0 (set below, and -O3 sees them set) */
    const int32_t Yc = row * FXL__ONE + FXL__HALF;
    const fxl_target_t *tg = tri->target;
    const int np = mod ? NPLANES : tri->np;   /* mod: Gouraud, every plane */
    /* Affine spans are cut every FXL_PERSP_MAX pixels too (see raster.c). */
    const int k = tri->seg_log2;
    int32_t x, i;
    /* the segment's two correction points; FXL__GW_SWAP swaps them after
     * each segment instead of copying p1 to p0 */
    point_t pts[2];
#if FXL__GW_SWAP
    point_t *p0 = &pts[0], *p1 = &pts[1];
#else
    point_t *const p0 = &pts[0], *const p1 = &pts[1];
#endif
    fxl__seg_t seg;
    uint32_t written = 0;
#if FXL_HAVE_AUTO
    const int32_t t_row = GW_AUTO_ROWS ? fxl__auto_row(tri, Yc - tri->Y0) : 0;
#endif

    x = xl + ((cl - xl) >> k << k);      /* first segment that reaches the clip */
#if FXL_HAVE_AUTO
    if (GW_AUTO_ROWS && cl > xl)
        x = fxl__auto_first(tri, t_row, xl, xr, cl, Yc - tri->Y0);
#if FXL_HAVE_MIPMAP
    /* AUTO's LOD grid (auto.h): a walk that would start between grid
     * points starts at the one before (a segment start), so the LOD it
     * holds is the one a walk from xl holds; the segments left of the
     * clip are computed, not drawn */
    if (GW_LOD_GRID)
        x = FXL__AUTO_LOD_GRID(x, xl);
#endif
#endif
    /* inline outside -Os (fxl__rr_plane): seven calls a span were ~8% of
     * the firmware example's lit sphere on a Cortex-M4 */
    for (i = 0; i < np; i++)
        pv[i] = fxl__rr_plane(tri, tri->pl[i], x, Yc - tri->Y0);
    for (; i < NPLANES; i++)
        pv[i] = 0;
    /* A one-pixel segment whose pixel is the last one drawn (exact mode's
     * at a clip's right edge cr < xr, or AUTO's) needs no end either: its
     * end, past cr, would only give the step no pixel takes. It is made a
     * last segment (div 0, steps 0), as exact mode's runs (FXL_T_RUN) end
     * it: one division a clipped span less, and the same count in every
     * build. Speed builds end such a span at cr, here and in AUTO's
     * choice below (a test a segment cost the -O2 lit frame's Gouraud
     * walk 1.8%); size builds test each segment (below: the other way is
     * 38 B more, past the 16 KiB the every-feature Cortex-M4 core keeps). */
#if FXL__FAST_SPANS
    if (k == 0 && !GW_AUTO_ROWS && cr < xr)
        xr = cr;
#endif
    point_zero(p0);
    point_zero(p1);
    GW_CORRECT(p0);
#if FXL_HAVE_MIPMAP
    int32_t lod_held = 0;   /* AUTO: the LOD of the latest grid point */
#endif

    seg_zero(&seg);
    seg.lvl = GW_UV ? &tri->level[0] : 0;

    while (x < cr) {
        int32_t n, div, a, b, off;
        int64_t du0 = 0, dv0 = 0;
        int level = 0, lsu = 0, lsv = 0, full, ki = k, quad = 0;
        (void)quad;   /* without FXL_HAVE_AUTO */
#if FXL_HAVE_AUTO
        if (GW_AUTO_ROWS) {
            ki = fxl__auto_next_tri(tri, t_row, x, xl, xr, pv[PQ]);
            quad = ki >= FXL__AUTO_QUAD;
            ki = FXL__AUTO_LOG2(ki);
#if FXL__FAST_SPANS
            if (ki == 0 && x + 1 >= cr)
                xr = cr;   /* a one-pixel segment drawn last: as exact mode's, above */
#endif
        } else {
            quad = !mod && tri->auto_seg == 2;   /* one quadratic length */
        }
#endif
        full = xr - x > ((int32_t)1 << ki);

#if FXL_HAVE_MIPMAP
        const int64_t q0 = pv[PQ];   /* the segment's LOD is measured at its start */
#endif
        if (full) {
            n = (int32_t)1 << ki;
            div = n;
        } else {
            n = xr - x;
            div = n - 1;   /* the last segment ends on the last pixel */
        }
#if !FXL__FAST_SPANS
        if (x + 1 >= cr && n == 1)
            full = div = 0;   /* in this order: 36 B less at -Os than n == 1 first */
#endif
        /* A last segment of one pixel (div 0) ends where it starts: the
         * planes do not move and its end is p0, so it takes no second
         * division (every span of exact mode had one). p1 is then left as
         * it was, on which no value depends: every step over div = 0 is 0
         * (step_of, step_i32, fxl__quad_steps' len 0), the segment starts
         * from p0, and the walk ends with it (x + n >= cr: xr, or cr for a
         * one-pixel segment made last above). Tested as full || div so
         * that a full segment takes no second test. */
        if (full || div > 0) {
            /* div pixels on: a 64 x 32 multiply, modular, or for a full
             * segment of 2^k gpxN, the same value (on the Cortex-M0+ each
             * product is a call to __aeabi_lmul) */
            if (FXL__GW_SWAP && full && ki == k) {
                for (i = 0; i < np; i++)
                    pv[i] = (int64_t)((uint64_t)pv[i] + (uint64_t)tri->gpxN[i]);
            } else {
                for (i = 0; i < np; i++)
                    pv[i] = (int64_t)((uint64_t)pv[i] + (uint64_t)tri->gpx[i] * (uint32_t)div);
            }
            GW_CORRECT(p1);
        }
#define STEP(d) (full ? step_pow2((d), ki) : step_of((d), div))

        a = x > cl ? x : cl;
        b = x + n < cr ? x + n : cr;
        off = a - x;
        if (GW_UV) {
            du0 = STEP(coord_diff(p1, p0, FXL__AU, GW_SIGNED_U));
            dv0 = STEP(coord_diff(p1, p0, FXL__AV, GW_SIGNED_V));
#if FXL_HAVE_MIPMAP
            if (tri->nlevels > 1) {
                int32_t lod = tri->lod_q8_tri;
                if (tri->lod_per_segment) {
#if FXL_HAVE_AUTO
                    if (GW_LOD_GRID && !FXL__AUTO_LOD_ON_GRID(x, xl))
                        lod = lod_held;
                    else
#endif
                        lod = lod_held = seg_lod(tri, tri->lod_at(tri, q0, p0->u64, p0->v64));
                }
                level = seg_levels(tri, lod, &seg);
            }
#endif
            seg.lvl = &tri->level[level];
            /* level n is max(1, w >> n) x max(1, h >> n): an axis that
             * reached one texel stops halving (its coordinates with it;
             * visible on border axes, where the shift decides inside or
             * out; repeat, mirror and clamp read texel 0 either way, so
             * the fast walks, repeat only, shift by the level alone) */
            lsu = level < (int)tri->tex->log2_w ? level : (int)tri->tex->log2_w;
            lsv = level < (int)tri->tex->log2_h ? level : (int)tri->tex->log2_h;
            seg.du = shift_step(du0, lsu, GW_SIGNED_U);
            seg.dv = shift_step(dv0, lsv, GW_SIGNED_V);
            seg.ddu = seg.ddv = 0;
#if FXL_HAVE_AUTO
            if (quad) {
                /* one level, repeat or mirror axes (auto.c): level 0, and
                 * the differences are the modular ones */
                const int32_t d[2] = {fxl__i32_of_bits(p1->a[FXL__AU] - p0->a[FXL__AU]),
                                      fxl__i32_of_bits(p1->a[FXL__AV] - p0->a[FXL__AV])};
                uint32_t st[4];
                fxl__quad_steps(d, p0->g, p1->g, full ? n : div, full ? ki : -1, st);
                const uint32_t su = st[0], ddu = st[1], sv = st[2], ddv = st[3];
                /* the step at the first pixel drawn */
                seg.du = fxl__i32_of_bits(su + ddu * (uint32_t)off);
                seg.dv = fxl__i32_of_bits(sv + ddv * (uint32_t)off);
                seg.ddu = fxl__i32_of_bits(ddu);
                seg.ddv = fxl__i32_of_bits(ddv);
                seg.u = fxl__seg_coord(p0->a[FXL__AU], fxl__i32_of_bits(su), seg.ddu, off);
                seg.v = fxl__seg_coord(p0->a[FXL__AV], fxl__i32_of_bits(sv), seg.ddv, off);
            } else
#endif
            {
                seg.u = shift_coord(p0->a[FXL__AU], lsu, GW_SIGNED_U) + (uint32_t)seg.du * (uint32_t)off;
                seg.v = shift_coord(p0->a[FXL__AV], lsv, GW_SIGNED_V) + (uint32_t)seg.dv * (uint32_t)off;
            }
#if FXL_HAVE_MIPMAP
            if (seg.lvl2) {
                const int lsu2 = lsu < (int)tri->tex->log2_w ? lsu + 1 : lsu;
                const int lsv2 = lsv < (int)tri->tex->log2_h ? lsv + 1 : lsv;
                seg.du2 = shift_step(du0, lsu2, GW_SIGNED_U);
                seg.dv2 = shift_step(dv0, lsv2, GW_SIGNED_V);
                seg.u2 = shift_coord(p0->a[FXL__AU], lsu2, GW_SIGNED_U) + (uint32_t)seg.du2 * (uint32_t)off;
                seg.v2 = shift_coord(p0->a[FXL__AV], lsv2, GW_SIGNED_V) + (uint32_t)seg.dv2 * (uint32_t)off;
            }
#endif
        }
        if (GW_COLOR) {
            for (i = 0; i < 3; i++) {
                seg.dc[i] = step_i32((int32_t)p1->a[FXL__AR + i] - (int32_t)p0->a[FXL__AR + i], full, ki, div);
                seg.c[i] = p0->a[FXL__AR + i] + (uint32_t)seg.dc[i] * (uint32_t)off;
            }
        }
        /* modulo 2^32, like the fast walks' (step_z_pow2): a one-pixel
         * step can be 2^31 or more */
        seg.dz = FXL_HAVE_DEPTH ? fxl__i32_of_bits((uint32_t)(uint64_t)STEP((int64_t)p1->z - (int64_t)p0->z)) : 0;
#undef STEP
        seg.z = p0->z + (uint32_t)seg.dz * (uint32_t)off;

        if (a < b) {
            int32_t idx = (row - tg->origin_y) * tg->stride + (a - tg->origin_x);
            seg.dst = tg->pixels + idx;
            seg.zb = tg->depth ? tg->depth + idx : 0;
            seg.n = b - a;
            written += fn(tri, &seg);
        }
        x += n;
#if FXL__GW_SWAP
        {
            point_t *const t = p0;
            p0 = p1;
            p1 = t;
        }
#else
        *p0 = *p1;
#endif
    }
    if (tri->stats) {
        tri->stats->pixels += written;
        tri->stats->spans++;
    }
}

#undef GW_UV
#undef GW_COLOR
#undef GW_SIGNED_U
#undef GW_SIGNED_V
#undef GW_AUTO_ROWS
#undef GW_LOD_GRID
#undef GW_CORRECT

static FXL__NOINLINE void draw_span_generic(const fxl__tri_t *tri, fxl__seg_fn fn, int32_t row, int32_t xl,
                                            int32_t xr, int32_t cl, int32_t cr)
{
    generic_walk(tri, fn, row, xl, xr, cl, cr, 0);
}

#if FXL__SEG_MOD
/* The generic walk for seg_modulate's Gouraud draws (lit textures in
 * speed builds) without AUTO or wide coordinates: colours, seven planes,
 * repeat axes and fixed segments are constants in this copy, so their
 * tests fold away and the plane loops unroll, in the walk and in its
 * corrections (correct_mod); a colour's correction is one word on 32-bit
 * cores. The same arithmetic, so the same values; the firmware example's
 * lit frame at -O2 5.18 M -> 4.92 M Cortex-M4 instructions, +3.5 KB. */
static FXL__NOINLINE void draw_span_mod(const fxl__tri_t *tri, fxl__seg_fn fn, int32_t row, int32_t xl,
                                        int32_t xr, int32_t cl, int32_t cr)
{
    generic_walk(tri, fn, row, xl, xr, cl, cr, 1);
}
#endif

void fxl__draw_span(const fxl__tri_t *tri, fxl__seg_fn fn, int32_t row, int32_t xl, int32_t xr,
                    int32_t cl, int32_t cr)
{
    /* Every walk relies on xl <= cl < cr <= xr (raster.c clips so): with it
     * no segment's pixel count is negative. Checked here, once a span. */
    if (!(xl <= cl && cl < cr && cr <= xr))
        return;
#if FXL_HAVE_RR
    if (tri->auto_rr) {
        draw_span_rr(tri, fn, row, xl, cl, cr);
        return;
    }
#endif
#if FXL__SEG_MOD
    if (fn == seg_modulate && fxl__has_color(tri) && tri->draw->persp != FXL_PERSP_AUTO && !tri->uv_wide) {
        draw_span_mod(tri, fn, row, xl, xr, cl, cr);
        return;
    }
#endif
    draw_span_generic(tri, fn, row, xl, xr, cl, cr);
}

#if FXL__FAST_SPANS
fxl__span_fn fxl__pick_span_fn(fxl__tri_t *tri, fxl__seg_fn fn)
{
    /* only for exactly the seg function fxl__pick_seg_fn chose: a
     * measuring probe gets the generic walk; so do uv_wide triangles (the
     * specialised walks step from 32-bit coordinates) */
    if (tri->fast_id && !tri->uv_wide && fn == fast_tab[tri->fast_id].seg && fast_tab[tri->fast_id].pick)
        return fast_tab[tri->fast_id].pick(tri);
    return 0;
}
#endif
