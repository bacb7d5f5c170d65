/* span_walk.h - the batch walk of one variant (included by span_fast.h,
 * once, and with depth on 64-bit hosts a second time).
 *
 * Contract: the macros of span_fast.h, its pixel loops (FXL_T_LOOP,
 * FXL_T_LOOP1, and FXL_T_ZLOOP with depth) and
 *   FXL_T_WZ  0: the walk, FXL_T_WALK; 1: its copy for triangles whose z
 *             is constant along rows (a level floor: tri->gpx[FXL__PZ] ==
 *             0, so every segment's dz is 0), FXL_T_WALK##_z0, whose pixel
 *             loops hold the depth in a register (FXL_T_ZLOOP), and
 *             where q is constant along the row too, its correction points
 *             share one 1/q and one LOD log2 q term: x86-64 floor subdiv16
 *             with depth, trilinear 110.4 -> 99.6 instructions a pixel,
 *             per-segment-LOD bilinear 79.5 -> 72.2
 * undefined here. Two copies of the source, not one function with a flag
 * (the extra loop cost the other scenes' trilinear 0.7-0.9% in registers)
 * nor one body forced inline into two functions (as much again: GCC then
 * compiled the walk differently, though its per-segment-LOD bilinear floor
 * was 3.8% faster than this copy's).
 */

/* The whole span [xl, xr) of `row` clipped to [cl, cr): the segment walk of
 * fxl__draw_span (see there for the rules) restricted to the fast case.
 * Every value is computed exactly as the generic walk computes it; only
 * what this variant uses is computed (no z without a depth buffer).
 * The walk runs in batches of up to FXL__BATCH segments, in two phases:
 * first the correction points of the batch (plane steps and divisions: a
 * loop with few live values, so they stay in registers), then the pixel
 * loops between them. Interleaved, the two phases competed for registers
 * and each segment spilled and reloaded most of its state. */
#if FXL_T_WZ
static FXL__NOINLINE void FXL__CAT(FXL_T_WALK, _z0)(const fxl__tri_t *tri, int32_t row, int32_t xl, int32_t xr,
                                                    int32_t cl, int32_t cr)
#else
static FXL__NOINLINE void FXL_T_WALK(const fxl__tri_t *tri, int32_t row, int32_t xl, int32_t xr, int32_t cl,
                                      int32_t cr)
#endif
{
    const fxl_target_t *tg = tri->target;
    const int k = tri->seg_log2;
    int32_t x = xl + ((cl - xl) >> k << k);
    const int32_t dY = row * FXL__ONE + FXL__HALF - tri->Y0;
#if FXL_HAVE_AUTO
    /* FXL_PERSP_AUTO per segment: lengths from the error bound (auto.h);
     * never in the constant-depth copy (its pick leaves those triangles to
     * the walk: with q constant along x auto.c makes none anyway) */
    int autoseg = FXL_T_WZ ? 0 : tri->auto_seg;
    const int32_t t_row = autoseg ? fxl__auto_row(tri, dY) : 0;
#endif
    /* index of frame pixel (0, row) in the buffer; a pointer is only formed
     * for pixels inside the clip rectangle */
    const int32_t rowidx = (row - tg->origin_y) * tg->stride - tg->origin_x;
    /* plane values (modular int64) at the latest correction point, and
     * its u, v */
    fxl__walk_t w;
#if FXL_T_WZ
    fxl__recip_t rc_row;
    const fxl__recip_t *rowrc = 0;
    int32_t rowlq = 0;
#endif
    /* the batch's correction points: cu[i], cv[i] (and cz[i]) start
     * segment i, cu[i + 1] ends it */
    uint32_t cu[FXL__BATCH + 1], cv[FXL__BATCH + 1];
#if FXL_HAVE_AUTO
    /* each segment's log2 length (AUTO per segment); ck[FXL__BATCH] the
     * latest batch's last */
    uint8_t ck[FXL__BATCH + 1];
#endif
#if FXL_T_DEPTH && FXL_T_WZ
    uint32_t zc;   /* the row's one z: the batches compute none */
#define FXL_T_CZ 0
#elif FXL_T_DEPTH
    uint32_t cz[FXL__BATCH + 1];
#define FXL_T_CZ cz
#else
#define FXL_T_CZ 0
#endif
#if FXL_HAVE_MIPMAP
    /* each segment's LOD, q8, clamped; clod[-1] the previous batch's last
     * (AUTO holds it between grid points, auto.h) */
    int32_t clodb[FXL__BATCH + 1];
    int32_t *const clod = clodb + 1;
#define FXL_T_CLOD clod
#else
#define FXL_T_CLOD 0
#endif
    uint32_t written = 0, segments = 0;
    /* the prepared level(s), redone only when a segment's level changes */
    const fxl__level_t *cur = &tri->level[0];
    FXL_T_LV L;
#if FXL_T_MIPLIN
    FXL_T_LV L2;
    const fxl__level_t *cur2 = cur;
#endif
#if FXL_HAVE_AUTO
    if (autoseg) {
        /* A span whose every block of 2^k fits the bound (k is auto_cap
         * here, auto.c) is cut as the fixed walk cuts it: that walk's
         * segments after one test, not a bound each (with auto.c taking
         * such triangles per segment, the near quad's trilinear went from
         * 1.28x to 1.02x fixed subdiv16's Cortex-M4 instructions). x is on
         * the LOD grid then: with the grid, k is 4, or less where no span
         * is longer than 2^k (x is xl). */
        if (fxl__auto_span_fits_cap(tri, t_row, x, xr,
                                    fxl__plane_eval(&tri->q, x * FXL__ONE + FXL__HALF - tri->X0, dY)))
            autoseg = 0;
        else if (cl > xl)
            x = fxl__auto_first(tri, t_row, xl, xr, cl, dY);
    }
#if FXL_HAVE_MIPMAP
    if (tri->lod_grid)
        x = FXL__AUTO_LOD_GRID(x, xl);   /* as the generic walk (draw_span_generic) */
#endif
#endif

    {
        const int32_t dX = x * FXL__ONE + FXL__HALF - tri->X0;
        w.sq = (uint64_t)fxl__plane_eval(&tri->q, dX, dY);
        w.su = (uint64_t)fxl__plane_eval(&tri->a[FXL__AU], dX, dY);
        w.sv = (uint64_t)fxl__plane_eval(&tri->a[FXL__AV], dX, dY);
#if FXL_T_DEPTH && FXL_T_WZ
        w.sz = 0;
        zc = fast_z(fxl__plane_eval(&tri->z, dX, dY));
#elif FXL_T_DEPTH
        w.sz = (uint64_t)fxl__plane_eval(&tri->z, dX, dY);
        cz[0] = fast_z((int64_t)w.sz);
#else
        w.sz = 0;
#endif
    }
#if FXL_T_WZ
    /* q constant along the row too (a level floor): its 1/q and the LOD's
     * log2 q term once, for every correction point (BATCH) */
    if (q_row_const(tri)) {
        recip_batch(tri, (int64_t)w.sq, &rc_row);
        rowrc = &rc_row;
#if FXL_HAVE_MIPMAP
        if (tri->lod_per_segment && tri->nlevels > 1 && tri->lod_at_lq)
            rowlq = lod_lq(tri, (int64_t)w.sq);
#endif
    }
#endif
    fast_correct(tri, (int64_t)w.sq, (int64_t)w.su, (int64_t)w.sv, &w.pt);
    cu[0] = w.pt.u;
    cv[0] = w.pt.v;
    FXL_T_LV_INIT(&L, cur, cu[0], cv[0]);
#if FXL_T_MIPLIN
    L2 = L;   /* level 0 too: the first blended segment prepares its own */
#endif
#if FXL_HAVE_MIPMAP
    clod[0] = 0;   /* written before it is read; this tells the compiler */
    clodb[0] = 0;  /* the walk starts on the LOD grid, where it is computed */
#endif

    while (x < cr) {
        int32_t cnt, i, xe = x;

        /* phase 1: the batch's correction points */
#if FXL_HAVE_AUTO && !FXL_T_WZ
        if (autoseg) {
            fxl__walk_t wa = w;
            int32_t xa = xe;
            cnt = FXL_T_BATCH_AUTO(tri, t_row, &xa, xl, xr, cr, &wa, cu, cv, FXL_T_CZ, FXL_T_CLOD, ck);
            w = wa;
            xe = xa;
        } else
#endif
#if FXL_T_WZ
            cnt = FXL_T_BATCH(tri, 0, 0, &xe, xl, xr, cr, &w, cu, cv, FXL_T_CZ, 0, rowrc, rowlq, FXL_T_CLOD, 0);
#else
            cnt = FXL_T_BATCH(tri, 0, 0, &xe, xl, xr, cr, &w, cu, cv, FXL_T_CZ, 1, 0, 0, FXL_T_CLOD, 0);
#endif
        segments += (uint32_t)cnt;

        /* phase 2: the pixels between them */
        for (i = 0; i < cnt; i++) {
#if FXL_HAVE_AUTO
            const int ki = autoseg ? ck[i] : k;
#else
            const int ki = k;
#endif
            int32_t n, a = x, b;
            uint32_t du, dv, dz = 0, u = cu[i], v = cv[i], z = 0;
            const fxl__level_t *lv = &tri->level[0];

            if (xr - x > ((int32_t)1 << ki)) {
                n = (int32_t)1 << ki;
                du = step_pow2_u32(cu[i + 1] - u, ki);
                dv = step_pow2_u32(cv[i + 1] - v, ki);
#if FXL_T_DEPTH && !FXL_T_WZ
                dz = step_z_pow2(cz[i + 1], cz[i], ki);
#endif
            } else {
                const uint32_t div = (uint32_t)(xr - x - 1);
                /* Phase 1 divided at a one-pixel end twice: one point
                 * (raster.h). Counted here, in memory, once a span: a
                 * count held in a register through the walk cost
                 * Cortex-M4 trilinear rows up to 1.3%, and one worked out
                 * after the walk up to 2.6% of a firmware frame. */
                if (div == 0u && tri->stats)
                    tri->stats->divisions--;
                n = xr - x;
                du = step_div_u32(cu[i + 1] - u, div);
                dv = step_div_u32(cv[i + 1] - v, div);
#if FXL_T_DEPTH && !FXL_T_WZ
                dz = step_z_div(cz[i + 1], cz[i], div);
#endif
            }
#if FXL_T_DEPTH && FXL_T_WZ
            z = zc;
#elif FXL_T_DEPTH
            z = cz[i];
#endif
            b = x + n < cr ? x + n : cr;
#if FXL_T_MIPLIN
            /* the second level and the blend weight, when f != 0 */
            const fxl__level_t *lv2 = 0;
            uint32_t u2 = 0, v2 = 0, du2 = 0, dv2 = 0, f = 0;
#endif
#if FXL_HAVE_MIPMAP
            if (tri->nlevels > 1) {
                const int32_t lod = clod[i];
                int level;
#if FXL_T_MIPLIN
                /* The blend weight is lod_frac >> 3; with weight 0 the blend
                 * is the identity ((a * 32 + 16) >> 5 = a per channel), so
                 * such segments run the one-level loop. The top level has
                 * weight 0 (the LOD is clamped to it). */
                f = ((uint32_t)lod & 255u) >> 3;
                level = lod >> 8;
                if (level + 1 >= tri->nlevels)
                    f = 0;
#else
                level = lod_nearest(lod);
#endif
                lv = &tri->level[level];
                du = shift_step_u32(du, level);
                dv = shift_step_u32(dv, level);
                u >>= level;
                v >>= level;
#if FXL_T_MIPLIN
                if (f != 0u) {
                    /* level + 1: the floor shifts compose, so this is the
                     * level-0 value shifted by level + 1 */
                    lv2 = lv + 1;
                    du2 = shift_step_u32(du, 1);
                    dv2 = shift_step_u32(dv, 1);
                    u2 = u >> 1;
                    v2 = v >> 1;
                }
#endif
            }
#endif
            if (x < cl) {
                /* A segment that starts left of the clip: the pixel loop
                 * starts `off` pixels in (the first segment; under AUTO's
                 * LOD grid up to 15 pixels of segments lie wholly left of
                 * it, and a >= b skips them). */
                const uint32_t off = (uint32_t)(cl - x);
                a = cl;
                u += du * off;
                v += dv * off;
                z += dz * off;
#if FXL_T_MIPLIN
                u2 += du2 * off;
                v2 += dv2 * off;
#endif
            }
            if (a < b) {
                int32_t idx = rowidx + a;
                if (lv != cur) {
                    cur = lv;
                    FXL_T_LV_INIT(&L, lv, u, v);
                }
#if FXL_T_MIPLIN
                if (f != 0u) {
                    if (lv2 != cur2) {
                        cur2 = lv2;
                        FXL_T_LV_INIT(&L2, lv2, u2, v2);
                    }
#if FXL_T_WZ
                    written += FXL_T_ZLOOP(tg->pixels + idx, tg->depth + idx, b - a, z, 0u, &L, u, v, du, dv, &L2,
                                           u2, v2, du2, dv2, f);
#else
                    written += FXL_T_LOOP(tg->pixels + idx, FXL_T_DEPTH ? tg->depth + idx : 0, b - a, z, dz, &L, u,
                                          v, du, dv, &L2, u2, v2, du2, dv2, f);
#endif
                } else {
#if FXL_T_WZ
                    written += FXL__CAT(FXL_T_LOOP1, _z0)(tg->pixels + idx, tg->depth + idx, b - a, z, 0u, &L, u, v,
                                                          du, dv);
#else
                    written += FXL_T_LOOP1(tg->pixels + idx, FXL_T_DEPTH ? tg->depth + idx : 0, b - a, z, dz, &L,
                                           u, v, du, dv);
#endif
                }
#else
#if FXL_T_WZ
                written += FXL_T_ZLOOP(tg->pixels + idx, tg->depth + idx, b - a, z, 0u, &L, u, v, du, dv);
#else
                written += FXL_T_LOOP(tg->pixels + idx, FXL_T_DEPTH ? tg->depth + idx : 0, b - a, z, dz, &L, u, v,
                                      du, dv);
#endif
#endif
            }
            x += n;
        }
        cu[0] = cu[cnt];
        cv[0] = cv[cnt];
#if FXL_T_DEPTH && !FXL_T_WZ
        cz[0] = cz[cnt];
#endif
#if FXL_HAVE_MIPMAP
        clodb[0] = clod[cnt - 1];
#endif
    }
#undef FXL_T_CZ
#undef FXL_T_CLOD
    if (tri->stats) {
        uint32_t points = segments + 1u;
        /* a one-pixel segment that ends a span clipped at cr < xr is one
         * point too (raster.h): there the last segment is full, 2^ki */
        if (cr < xr) {
#if FXL_HAVE_AUTO
            const int ki_last = autoseg ? ck[FXL__BATCH] : k;
#else
            const int ki_last = k;
#endif
            points -= ki_last == 0;
        }
        tri->stats->divisions += points;
        tri->stats->pixels += written;
        tri->stats->spans++;
    }
}


#undef FXL_T_WZ
