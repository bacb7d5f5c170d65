/* span_loop.h - the pixel loop of one segment (included by span_fast.h,
 * several times for each one-level variant).
 *
 * Contract: the macros of span_fast.h (FXL_T_BILINEAR, FXL_T_MIPLIN,
 * FXL_T_DEPTH, FXL_T_SWAP, FXL_T_LV, FXL_T_OUT) and
 *   FXL_T_LOOPFN  name of the generated function
 *   FXL_T_QUAD    0: affine steps; 1: quadratic segments (auto.h), whose
 *                 steps du, dv change by ddu, ddv a pixel (two more
 *                 parameters; not with FXL_T_MIPLIN)
 *   FXL_T_ZCONST  (optional, with FXL_T_DEPTH) 1: the caller guarantees
 *                 dz == 0 (a level floor's rows), so the depth compared
 *                 and written is z >> 16 throughout, hoisted out of the loop
 *   FXL_T_ROWLOOP (optional, one level, not FXL_T_QUAD) 1 or 2: the copy
 *                 for segments on one texel row, where the caller
 *                 guarantees dv == 0 (row_fits in span.c); 1 out of line,
 *                 2 forced inline. Without it a one-level loop is named
 *                 FXL_T_LOOPFN##_all, and FXL_T_LOOPFN is a dispatch to
 *                 it or to FXL_T_LOOPFN##_row, which must exist.
 * all undefined here. Two functions rather than one with a flag: in the
 * x86-64 depth loops, which use every register, a flag (even a constant
 * one the compiler propagates) cost the affine loop ~2 instructions a
 * pixel.
 *
 * One segment: n >= 1 pixels from dst (and zb). Returns the pixels
 * written. Forced inline for the point loops (they are small, and inline
 * they spend fewer instructions a segment); the bilinear loops are left to
 * the compiler: inlined into the lean walk they spilled more than the call
 * costs (Cortex-M4 floor subdiv16 bilinear 53.8 -> 61.8 instructions a
 * pixel). */
#ifndef FXL_T_ZCONST
#define FXL_T_ZCONST 0
#endif
#ifndef FXL_T_ROWLOOP
#define FXL_T_ROWLOOP 0
#endif
/* the column of a point sample on one texel row (span.c) */
#define FXL_T_RCOL(U) FXL__RCOL(U, shu, mu16)
/* A one-level loop hands segments on one texel row (v constant, 4 pixels
 * or more: span.c's row_fits) to its FXL_T_LOOPFN##_row copy
 * (FXL_T_ROWLOOP 1, included first): bilinear, one lerp a pixel where a
 * footprint is shared; point, no v in the address. That copy is out of
 * line: inline in every walk it cost the others' registers (x86-64
 * small_tris bilinear +0.8%). FXL_T_ROWLOOP 2 is a forced-inline copy for
 * the one walk that runs whole rows of them (span_fast.h). The test at
 * each call costs scenes without such rows 0.3-1.2% (Cortex-M4 point),
 * and saves level floors drawn in long segments ~30% (affine, AUTO). */
#define FXL_T_ROWS (FXL__FAST_SPANS && !FXL_T_MIPLIN && !FXL_T_QUAD && !FXL_T_ROWLOOP)
#if FXL_T_ROWLOOP == 1
static FXL__NOINLINE
#elif FXL_T_ROWLOOP == 2
static FXL__HOT_INLINE
#elif FXL_T_BILINEAR || FXL_T_MIPLIN
static inline
#else
static FXL__UNSWITCH
#endif
#if FXL_T_ROWS
#define FXL_T_FNAME FXL__CAT(FXL_T_LOOPFN, _all)
#else
#define FXL_T_FNAME FXL_T_LOOPFN
#endif
uint32_t FXL_T_FNAME(uint16_t *dst, uint16_t *zb, int32_t n, uint32_t z, uint32_t dz,
                                  FXL_T_LV *L, uint32_t u, uint32_t v, uint32_t du, uint32_t dv
#if FXL_T_QUAD
                                  ,
                                  uint32_t ddu, uint32_t ddv
#endif
#if FXL_T_MIPLIN
                                  ,
                                  FXL_T_LV *L2, uint32_t u2, uint32_t v2, uint32_t du2, uint32_t dv2, uint32_t f
#endif
)
{
#if FXL_T_DEPTH
    uint32_t rejected = 0;
#if FXL_T_ZCONST
    /* the row's one depth (dz == 0) */
    const uint16_t zrow = (uint16_t)(z >> 16);
    (void)dz;
#endif
#else
    (void)zb;
    (void)z;
    (void)dz;
#endif
#if FXL_T_ROWLOOP && FXL_T_BILINEAR
    /* one texel row: v is constant to the weight (row_fits) */
    uint32_t uu = u - 0x8000u;
    bl_row_t R;
    bl_row_begin(L, &R, v - 0x8000u);
    (void)dv;
#define FXL_T_STEP() (uu += du)
#define FXL_T_TEXEL() compact565(bl_row_sample(&R, uu))
#elif FXL_T_BILINEAR
    /* texel centres at +0.5: the half texel is taken off once here */
    uint32_t uu = u - 0x8000u, vv = v - 0x8000u;
#if FXL_T_MIPLIN
    uint32_t uu2 = u2 - 0x8000u, vv2 = v2 - 0x8000u;
#endif
#define FXL_T_STEP() (uu += du, vv += dv)
#define FXL_T_CURVE() (du += ddu, dv += ddv)
#if FXL_T_MIPLIN
#define FXL_T_STEP2() (uu2 += du2, vv2 += dv2)
#define FXL_T_TEXEL()                                                                                       \
    compact565(lerp565x(bl_sample(L, uu, vv), bl_sample(L2, uu2, vv2), f))
#else
#define FXL_T_TEXEL() compact565(bl_sample(L, uu, vv))
#endif
#else /* point */
    /* level constants come prepared (fl_init) */
    const uint16_t *tex = L->tex;
    const uint32_t lw = L->lw, shu = L->shu, mu16 = L->mu16, mv16 = L->mv16;
    (void)shu;    /* one of shu, mu16 is unused, see FXL__IDX */
    (void)mu16;
    uint32_t U = FXL__IDX_TOPU ? (lw ? u << (16u - lw) : 0u) : u, V = v << lw;
#if FXL_T_QUAD
    uint32_t dU = FXL__IDX_TOPU ? (lw ? du << (16u - lw) : 0u) : du, dV = dv << lw;
#else
    const uint32_t dU = FXL__IDX_TOPU ? (lw ? du << (16u - lw) : 0u) : du, dV = dv << lw;
#endif
#if FXL_T_QUAD
    /* quadratic segments: the steps change by ddu, ddv a pixel (shifted
     * like the steps: << is exact modulo 2^32) */
    const uint32_t ddU = FXL__IDX_TOPU ? (lw ? ddu << (16u - lw) : 0u) : ddu, ddV = ddv << lw;
#endif
#if FXL_T_MIPLIN
    const uint16_t *tex2 = L2->tex;
    const uint32_t lw2 = L2->lw, shu2 = L2->shu, mu16b = L2->mu16, mv16b = L2->mv16;
    (void)shu2;
    (void)mu16b;
    uint32_t U2 = FXL__IDX_TOPU ? (lw2 ? u2 << (16u - lw2) : 0u) : u2, V2 = v2 << lw2;
    const uint32_t dU2 = FXL__IDX_TOPU ? (lw2 ? du2 << (16u - lw2) : 0u) : du2, dV2 = dv2 << lw2;
#define FXL_T_STEP2() (U2 += dU2, V2 += dV2)
#define FXL_T_TEXEL()                                                                                       \
    compact565(lerp565x(expand565(FXL__TEXEL(tex, U, V, shu, mu16, mv16)),                                  \
                        expand565(FXL__TEXEL(tex2, U2, V2, shu2, mu16b, mv16b)), f))
#elif FXL_T_ROWLOOP
    /* v constant: one texel row, as in the run loop below */
    const uint16_t *const row = tex + ((V & mv16) >> 16);
    (void)dV;
#define FXL_T_TEXEL() ((uint32_t)row[FXL_T_RCOL(U)])
#else
#define FXL_T_TEXEL() ((uint32_t)FXL__TEXEL(tex, U, V, shu, mu16, mv16))
#endif
#if FXL_T_ROWLOOP
#define FXL_T_STEP() (U += dU)
#else
#define FXL_T_STEP() (U += dU, V += dV)
#endif
#define FXL_T_CURVE() (dU += ddU, dV += ddV)
#endif

#if FXL_T_MIPLIN
#define FXL_T_ADVANCE() (FXL_T_STEP(), FXL_T_STEP2())
#else
#if FXL_T_QUAD
#define FXL_T_ADVANCE() (FXL_T_STEP(), FXL_T_CURVE())
#else
#define FXL_T_ADVANCE() FXL_T_STEP()
#endif
#endif

#if FXL_T_DEPTH
    /* The rejected count is kept on the rare path so the drawn one stays
     * short. zz is a uint16_t (the stored depth's type; z >> 16 < 2^16):
     * x86-64 then compares it with the buffer in one instruction, where a
     * uint32_t took a zero-extending load and a compare (-1 instruction a
     * pixel, floor subdiv16 point with depth 27.36 -> 26.28; the Cortex-M4
     * code is the same). */
#if FXL_T_ZCONST
#define FXL_T_ZNEXT(zz) const uint16_t zz = zrow
#else
#define FXL_T_ZNEXT(zz)                                                                                     \
    const uint16_t zz = (uint16_t)(z >> 16);                                                                \
    z += dz
#endif
#if FXL_T_DEPTH == 2
/* size builds' one loop for draws with depth and without (zb NULL) */
#define FXL_T_ZPASS(zz, i) (!zb || (zz) > zb[i])
#define FXL_T_ZSTORE(zz, i)                                                                                 \
    if (zb)                                                                                                 \
    zb[i] = (uint16_t)(zz)
#else
#define FXL_T_ZPASS(zz, i) ((zz) > zb[i])
#define FXL_T_ZSTORE(zz, i) zb[i] = (uint16_t)(zz)
#endif
#define FXL_T_PIXEL(i)                                                                                      \
    do {                                                                                                    \
        FXL_T_ZNEXT(zz);                                                                                    \
        if (FXL_T_ZPASS(zz, i)) {                                                                           \
            uint32_t c = FXL_T_TEXEL();                                                                     \
            FXL_T_ZSTORE(zz, i);                                                                            \
            dst[i] = FXL_T_OUT(c);                                                                          \
        } else {                                                                                            \
            rejected++;                                                                                     \
        }                                                                                                   \
        FXL_T_ADVANCE();                                                                                    \
    } while (0)
#else
#define FXL_T_PIXEL(i)                                                                                      \
    do {                                                                                                    \
        uint32_t c = FXL_T_TEXEL();                                                                         \
        dst[i] = FXL_T_OUT(c);                                                                              \
        FXL_T_ADVANCE();                                                                                    \
    } while (0)
#endif

    {
#if !FXL__FAST_SPANS
        /* size-optimised build: no unrolling */
        int32_t i;
        for (i = 0; i < n; i++)
            FXL_T_PIXEL(i);
#elif FXL_T_DEPTH
        /* Two pixels per iteration, indexed from the end: i runs from -n up
         * to 0, so one ADD steps both dst and zb and sets the loop flag (2
         * loop instructions a pair on x86-64, where two pointers and an end
         * would spend a register the depth loop does not have). The odd
         * pixel goes first. */
        ptrdiff_t i = -(ptrdiff_t)n;
        dst += n;
        zb += n;
        if (n & 1) {
            FXL_T_PIXEL(i);
            i++;
        }
        while (i != 0) {
            FXL_T_PIXEL(i);
            FXL_T_PIXEL(i + 1);
            i += 2;
        }
#else
        /* Four pixels per iteration with one pointer: GCC turns the count
         * into an end-pointer compare (ADDS, CMP, BNE on a Cortex-M4), paid
         * once per four (the point loop is 7 instructions a pixel plus 3 a
         * quad). The n % 4 odd pixels go first. */
        int32_t quads = n >> 2, r = n & 3;
        while (r-- > 0) {
            FXL_T_PIXEL(0);
            dst++;
        }
        while (quads-- > 0) {
            FXL_T_PIXEL(0);
            FXL_T_PIXEL(1);
            FXL_T_PIXEL(2);
            FXL_T_PIXEL(3);
            dst += 4;
        }
#endif
    }
#if FXL_T_ROWLOOP && FXL_T_BILINEAR
    bl_row_end(L, &R);
#endif
#if FXL_T_DEPTH
    return (uint32_t)n - rejected;
#else
    return (uint32_t)n;
#endif
}

#if FXL_T_ROWS
/* The dispatch, inline at every call: the loops themselves stay as they
 * were (a test inside the bilinear loop cost its prologue stack copies:
 * Cortex-M4 small_tris +1.3%). */
static FXL__HOT_INLINE uint32_t FXL_T_LOOPFN(uint16_t *dst, uint16_t *zb, int32_t n, uint32_t z, uint32_t dz,
                                             FXL_T_LV *L, uint32_t u, uint32_t v, uint32_t du, uint32_t dv)
{
    if (row_fits(dv, n))
        return FXL__CAT(FXL_T_LOOPFN, _row)(dst, zb, n, z, dz, L, u, v, du, dv);
    return FXL_T_FNAME(dst, zb, n, z, dz, L, u, v, du, dv);
}
#endif
#undef FXL_T_FNAME

#if FXL__FAST_SPANS && !FXL__ROWC_LEAN && !FXL_T_QUAD && !FXL_T_MIPLIN && !FXL_T_DEPTH && !FXL_T_ROWLOOP
/* m >= 1 whole segments of n = 2^k >= 4 pixels back to back from dst,
 * their starts and steps in sg[0 .. m) (the rowc walk's runs); no depth:
 * with depth a run loop cost x86-64 instructions, or, at 16 pixels with a
 * constant z, ran 3-4 times longer for fewer instructions (not understood
 * yet). Bit for bit FXL_T_LOOPFN once per segment, but:
 * - one call for the run, so the level's constants stay in registers
 *   across it;
 * - for the point loops at n = 16 (subdiv16, the default) a segment is one
 *   straight block of 16 pixels: per segment only its values are loaded
 *   and shifted (Cortex-M4 floor subdiv16 point: ~11 instructions a
 *   segment besides its pixels, where FXL_T_LOOPFN per segment spent ~39
 *   on its set-up, spills and counter).
 * The point loops at FXL__IDX_TOPU take U = u << (16 - lw), so lw > 0 (the
 * rowc walk checks it). */
static FXL__NOINLINE void FXL__CAT(FXL_T_LOOPFN, _segs)(uint16_t *dst, const fxl__rseg_t *sg, int32_t m, int32_t n,
                                                        FXL_T_LV *L)
{
    const fxl__rseg_t *const end = sg + m;
#if FXL_T_BILINEAR
#define FXL_T_SEG_UV()                                                                                      \
    uint32_t uu = sg->u - 0x8000u, vv = sg->v - 0x8000u;                                                    \
    const uint32_t du = sg->du, dv = sg->dv
#else
    const uint16_t *tex = L->tex;
    const uint32_t lw = L->lw, shu = L->shu, mu16 = L->mu16, mv16 = L->mv16;
    const uint32_t su = FXL__IDX_TOPU ? 16u - lw : 0u;
    (void)shu;
    (void)mu16;
#define FXL_T_SEG_UV()                                                                                      \
    uint32_t U = sg->u << su, V = sg->v << lw;                                                              \
    const uint32_t dU = sg->du << su, dV = sg->dv << lw
#endif
/* a pixel of a segment on one texel row: bilinear from the row cache R,
 * point from the texel row `row` */
#if FXL_T_BILINEAR
#define FXL_T_RPIXEL(i)                                                                                     \
    do {                                                                                                    \
        uint32_t c = compact565(bl_row_sample(&R, uu));                                                     \
        dst[i] = FXL_T_OUT(c);                                                                              \
        uu += du;                                                                                           \
    } while (0)
#else
#define FXL_T_RPIXEL(i)                                                                                     \
    do {                                                                                                    \
        uint32_t c = row[FXL_T_RCOL(U)];                                                                    \
        dst[i] = FXL_T_OUT(c);                                                                              \
        U += dU;                                                                                            \
    } while (0)
#endif
#if !FXL_T_BILINEAR
    if (n == 16) {
        do {
            FXL_T_SEG_UV();
            if (dV == 0u) {
                /* v constant (a level floor's rows): one texel row, whose
                 * index is found once; a pixel is the column's shift, the
                 * load, the store and one step (Cortex-M4 4 instructions
                 * where the general pixel takes 7) */
                const uint16_t *const row = tex + ((V & mv16) >> 16);
                FXL_T_RPIXEL(0);
                FXL_T_RPIXEL(1);
                FXL_T_RPIXEL(2);
                FXL_T_RPIXEL(3);
                FXL_T_RPIXEL(4);
                FXL_T_RPIXEL(5);
                FXL_T_RPIXEL(6);
                FXL_T_RPIXEL(7);
                FXL_T_RPIXEL(8);
                FXL_T_RPIXEL(9);
                FXL_T_RPIXEL(10);
                FXL_T_RPIXEL(11);
                FXL_T_RPIXEL(12);
                FXL_T_RPIXEL(13);
                FXL_T_RPIXEL(14);
                FXL_T_RPIXEL(15);
                dst += 16;
                continue;
            }
            FXL_T_PIXEL(0);
            FXL_T_PIXEL(1);
            FXL_T_PIXEL(2);
            FXL_T_PIXEL(3);
            FXL_T_PIXEL(4);
            FXL_T_PIXEL(5);
            FXL_T_PIXEL(6);
            FXL_T_PIXEL(7);
            FXL_T_PIXEL(8);
            FXL_T_PIXEL(9);
            FXL_T_PIXEL(10);
            FXL_T_PIXEL(11);
            FXL_T_PIXEL(12);
            FXL_T_PIXEL(13);
            FXL_T_PIXEL(14);
            FXL_T_PIXEL(15);
            dst += 16;
        } while (++sg != end);
    } else
#endif
    {
        do {
            FXL_T_SEG_UV();
            int32_t quads = n >> 2;
            /* one texel row (FXL_T_ROWLOOP above; point as at n == 16) */
#if FXL_T_BILINEAR
            if (row_fits(dv, n)) {
                bl_row_t R;
                bl_row_begin(L, &R, vv);
#else
            if (dV == 0u) {
                const uint16_t *const row = tex + ((V & mv16) >> 16);
#endif
                do {
                    FXL_T_RPIXEL(0);
                    FXL_T_RPIXEL(1);
                    FXL_T_RPIXEL(2);
                    FXL_T_RPIXEL(3);
                    dst += 4;
                } while (--quads != 0);
#if FXL_T_BILINEAR
                bl_row_end(L, &R);
#endif
                continue;
            }
            do {
                FXL_T_PIXEL(0);
                FXL_T_PIXEL(1);
                FXL_T_PIXEL(2);
                FXL_T_PIXEL(3);
                dst += 4;
            } while (--quads != 0);
        } while (++sg != end);
    }
#undef FXL_T_SEG_UV
#undef FXL_T_RPIXEL
}
#endif

/* the pixel macros serve both functions above */
#undef FXL_T_PIXEL
#ifdef FXL_T_ZNEXT
#undef FXL_T_ZNEXT
#undef FXL_T_ZPASS
#undef FXL_T_ZSTORE
#endif
#undef FXL_T_TEXEL
#undef FXL_T_STEP
#undef FXL_T_CURVE
#undef FXL_T_ADVANCE
#if FXL_T_MIPLIN
#undef FXL_T_STEP2
#endif

#undef FXL_T_LOOPFN
#undef FXL_T_QUAD
#undef FXL_T_ZCONST
#undef FXL_T_ROWLOOP
#undef FXL_T_ROWS
#undef FXL_T_RCOL
