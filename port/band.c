/* port/band.c - a frame drawn as horizontal bands with two band buffers,
 * triangles binned once per frame. Contract: include/fixel/port.h.
 *
 * Timeline for bands 0..n-1 into buffers A, B:
 *   render 0 -> A, send A | render 1 -> B (A on the wire) | wait A, send B |
 *   render 2 -> A (B on the wire) | wait B, send A | ...
 * A buffer is drawn into only after the transfer that last read it has
 * completed (seq[] records its transfer number). Sending waits for the
 * previous transfer anyway (one DMA channel, one RAMWR stream), so in the
 * steady state the render-side wait returns at once; it stays as the
 * guarantee that holds even if the send side changes.
 *
 * All bands stream into one CASET/RASET/RAMWR window covering the frame:
 * the controller's address counter continues across transfers, so no
 * command (and no D/C toggle) is needed between bands.
 */
#include "fixel/port.h"

/* Floor division by 65536 of a value that may be negative (right shifts of
 * negative values are implementation-defined in C99). */
static int64_t floor_px(int64_t q16)
{
    return q16 >= 0 ? q16 / 65536 : -((-q16 + 65535) / 65536);
}

/* The target of a band of `rows` rows from frame row y0, `width` pixels
 * wide: buffer buf in the format the panel's HAL sends as it is, with the
 * depth band if any. */
static fxl_status_t target_of(const fxl_panel_t *panel, int32_t width, uint16_t *depth, uint16_t *buf, int32_t y0,
                              int32_t rows, fxl_target_t *t)
{
    fxl_status_t st = fxl_target_init(t, buf, width, rows, width, fxl_panel_pixel_format(panel));
    if (st == FXL_OK) st = fxl_target_set_origin(t, 0, y0);
    if (st == FXL_OK && depth != NULL) st = fxl_target_set_depth(t, depth);
    return st;
}

static fxl_status_t band_target(const fxl_band_t *b, uint16_t *buf, int32_t y0, int32_t rows, fxl_target_t *t)
{
    return target_of(b->panel, b->width, b->depth, buf, y0, rows, t);
}

static int binning(const fxl_band_t *b)
{
    return b->bins != NULL && b->bin_cap >= (uint32_t)b->band_count;
}

/* Do two of the caller's five buffers share a byte? p[i] is a buffer's
 * address as uintptr_t (comparing pointers into different objects is
 * undefined in C), len[i] its bytes (0: unused). By address differences
 * modulo the address space: a buffer that ends at its top cannot wrap the
 * test. Carved from one array at wrong offsets, a depth band on a colour
 * band (or the triangle store on either) drew a wrong image, or sent
 * half-drawn bands, with no error. */
static int buffers_overlap(const uintptr_t p[5], const uintptr_t len[5])
{
    int i, j;
    for (i = 0; i < 5; i++)
        for (j = i + 1; j < 5; j++)
            if (len[i] && len[j] && ((uintptr_t)(p[i] - p[j]) < len[j] || (uintptr_t)(p[j] - p[i]) < len[i]))
                return 1;
    return 0;
}

fxl_status_t fxl_band_init(fxl_band_t *b, fxl_panel_t *panel, uint16_t *buf0, uint16_t *buf1,
                           uint16_t *depth, int32_t band_rows, fxl_band_tri_t *tris,
                           uint32_t tri_cap, fxl_band_bin_t *bins, uint32_t bin_cap)
{
    int32_t band_count;
    if (b == NULL || panel == NULL || panel->preset == NULL || buf0 == NULL || buf1 == NULL ||
        buf0 == buf1 || tris == NULL || tri_cap == 0 || band_rows <= 0 || (bins == NULL && bin_cap > 0))
        return FXL_ERR_ARG;
    if (band_rows > panel->height || panel->width > FXL_TARGET_MAX_DIM) return FXL_ERR_RANGE;
    band_count = (panel->height + band_rows - 1) / band_rows;
    /* Every band's target sits at origin (0, y0): refused up front when the
     * last one's y0 is beyond what a target allows, rather than mid-frame
     * with part of it on the wire. */
    if ((int64_t)(band_count - 1) * band_rows > FXL_TARGET_MAX_ORIGIN) return FXL_ERR_RANGE;
    if (bin_cap > 0 && bin_cap < (uint32_t)band_count) return FXL_ERR_NOMEM;
    {
        /* the bytes each buffer is used for (width <= 4096 and rows <=
         * height < 2^16 here; at most 65535 entries of tris and bins are) */
        const uintptr_t band_bytes = (uintptr_t)panel->width * (uint32_t)band_rows * 2u;
        const uintptr_t p[5] = {(uintptr_t)buf0, (uintptr_t)buf1, (uintptr_t)depth, (uintptr_t)tris,
                                (uintptr_t)bins};
        const uintptr_t len[5] = {band_bytes, band_bytes, depth ? band_bytes : 0u,
                                  (uintptr_t)(tri_cap > FXL_BAND_MAX_TRIS ? FXL_BAND_MAX_TRIS : tri_cap) *
                                      sizeof(fxl_band_tri_t),
                                  (uintptr_t)(bin_cap > 0xFFFFu ? 0xFFFFu : bin_cap) * sizeof(fxl_band_bin_t)};
        if (buffers_overlap(p, len)) return FXL_ERR_ARG;
    }
    {
        /* A band the core cannot draw into is refused now rather than
         * mid-frame: a depth band in a build without FXL_HAVE_DEPTH, or a
         * buffer at an odd address (fxl_target_init, _set_depth), which a
         * 16-bit HAL would refuse only with the frame's window sent. */
        fxl_target_t t;
        fxl_status_t st = target_of(panel, panel->width, depth, buf0, 0, band_rows, &t);
        if (st == FXL_OK) st = target_of(panel, panel->width, NULL, buf1, 0, band_rows, &t);
        if (st != FXL_OK) return st;
    }
    /* Only a binding that is whole is written: after an error b is as it
     * was. */
    b->panel = panel;
    b->buf[0] = buf0;
    b->buf[1] = buf1;
    b->depth = depth;
    b->width = panel->width;
    b->height = panel->height;
    b->band_rows = band_rows;
    b->band_count = band_count;
    b->tris = tris;
    /* Triangle and entry indices are uint16 with FXL_BAND_NONE as the end. */
    b->tri_cap = tri_cap > FXL_BAND_MAX_TRIS ? FXL_BAND_MAX_TRIS : tri_cap;
    b->bins = bins;
    b->bin_cap = bin_cap > 0xFFFFu ? 0xFFFFu : bin_cap;
    b->seq[0] = 0;
    b->seq[1] = 0;
    return fxl_band_begin(b);
}

fxl_status_t fxl_band_begin(fxl_band_t *b)
{
    int32_t k;
    if (b == NULL || b->panel == NULL) return FXL_ERR_ARG;
    b->tri_count = 0;
    b->bin_used = 0;
    b->checked = NULL;
    if (binning(b)) {
        /* The first band_count entries are list headers: tri = first entry,
         * next = last entry (so appending keeps submission order in O(1)). */
        for (k = 0; k < b->band_count; k++) {
            b->bins[k].tri = FXL_BAND_NONE;
            b->bins[k].next = FXL_BAND_NONE;
        }
        b->bin_used = (uint32_t)b->band_count;
        b->first_unbinned = UINT32_MAX;
    } else {
        b->first_unbinned = 0;
    }
    return FXL_OK;
}

fxl_status_t fxl_band_add(fxl_band_t *b, const fxl_vertex_t v[3], const fxl_draw_t *draw)
{
    int64_t lo, hi, ymin, ymax;
    /* The core snaps y to the sub-pixel grid (at most half a step away) and
     * draws row j only when its centre j + 0.5 lies within the snapped y
     * range. Widening the raw range by half a step h therefore gives rows
     * floor(ymin - h) .. floor(ymax + h), a superset of the covered rows:
     * ceil(ymin - h - 0.5) >= floor(ymin - h) and ymax + h - 0.5 < ymax + h. */
    const int64_t half_step_q16 = (int64_t)1 << (15 - FXL_SUBPIXEL_BITS);
    fxl_band_tri_t *t;
    fxl_target_t band;
    fxl_status_t st;
    uint32_t idx, need;
    int32_t k, band0, band1;
    int i;
    if (b == NULL || v == NULL || draw == NULL || b->panel == NULL) return FXL_ERR_ARG;
    /* Settings every band would refuse are refused here, before anything
     * is sent (the core would return the same status for each band). A
     * draw is referenced, so it keeps its state for the frame: once found
     * valid it is not checked again for the next triangle (a scene's
     * triangles mostly share one; the check is ~2/3 of an add on x86-64).
     * One changed during the frame is found per band (port.h). */
    if (draw != b->checked) {
        st = band_target(b, b->buf[0], 0, b->band_rows, &band);
        if (st == FXL_OK) st = fxl_draw_check(&band, draw);
        if (st != FXL_OK) return st;
        b->checked = draw;
    }
    for (i = 0; i < 3; i++)
        if (v[i].inv_w == 0) return FXL_ERR_RANGE;
    ymin = ymax = v[0].y;
    for (i = 1; i < 3; i++) {
        if (v[i].y < ymin) ymin = v[i].y;
        if (v[i].y > ymax) ymax = v[i].y;
    }
    lo = floor_px(ymin - half_step_q16);
    hi = floor_px(ymax + half_step_q16);
    if (hi < 0 || lo >= b->height) return FXL_OK; /* touches no band: nothing to draw */
    if (b->tri_count >= b->tri_cap) return FXL_ERR_NOMEM;
    if (lo < 0) lo = 0;
    if (hi > b->height - 1) hi = b->height - 1;
    band0 = (int32_t)lo / b->band_rows;
    band1 = (int32_t)hi / b->band_rows;

    idx = b->tri_count;
    t = &b->tris[idx];
    t->v[0] = v[0];
    t->v[1] = v[1];
    t->v[2] = v[2];
    t->draw = draw;
    t->band0 = (uint16_t)band0;
    t->band1 = (uint16_t)band1;
    b->tri_count++;

    if (idx >= b->first_unbinned) return FXL_OK; /* already in fallback mode */
    need = (uint32_t)(band1 - band0 + 1);
    if (need > b->bin_cap - b->bin_used) {
        /* Out of bin memory: this triangle and all later ones are found by
         * scanning their band ranges. Binned triangles all precede them, so
         * drawing the bin list first and the scan second keeps the order. */
        b->first_unbinned = idx;
        return FXL_OK;
    }
    for (k = band0; k <= band1; k++) {
        uint32_t e = b->bin_used++;
        fxl_band_bin_t *head = &b->bins[k];
        b->bins[e].tri = (uint16_t)idx;
        b->bins[e].next = FXL_BAND_NONE;
        if (head->tri == FXL_BAND_NONE)
            head->tri = (uint16_t)e;
        else
            b->bins[head->next].next = (uint16_t)e;
        head->next = (uint16_t)e;
    }
    return FXL_OK;
}

int fxl_band_overflowed(const fxl_band_t *b)
{
    return b != NULL && b->first_unbinned < b->tri_count;
}

static void draw_one(fxl_target_t *t, const fxl_band_tri_t *tri, fxl_stats_t *stats,
                     fxl_status_t *first_err)
{
    fxl_status_t st = fxl_draw_triangle(t, tri->draw, tri->v, stats);
    if (st != FXL_OK && *first_err == FXL_OK) *first_err = st;
}

fxl_status_t fxl_band_render(fxl_band_t *b, uint16_t clear_rgb565, fxl_stats_t *stats)
{
    fxl_status_t st, first_err = FXL_OK;
    int32_t k;
    if (b == NULL || b->panel == NULL) return FXL_ERR_ARG;
    /* The band geometry was derived from the panel's rotation at init. */
    if (b->panel->width != b->width || b->panel->height != b->height) return FXL_ERR_ARG;
    st = fxl_panel_set_window(b->panel, 0, 0, b->width, b->height);
    if (st != FXL_OK) return st;

    for (k = 0; k < b->band_count; k++) {
        const int i = (int)(k & 1);
        const int32_t y0 = k * b->band_rows;
        const int32_t rows = b->height - y0 < b->band_rows ? b->height - y0 : b->band_rows;
        uint32_t n;
        fxl_target_t t;

        /* Never draw into a buffer the DMA may still be reading. */
        st = fxl_panel_wait_done(b->panel, b->seq[i]);
        if (st != FXL_OK) return st;

        /* Band k is the frame rectangle [0, width) x [y0, y0 + rows). */
        st = band_target(b, b->buf[i], y0, rows, &t);
        if (st == FXL_OK) st = fxl_target_clear(&t, clear_rgb565);
        if (st == FXL_OK && b->depth != NULL) st = fxl_target_clear_depth(&t);
        if (st != FXL_OK) {
            (void)fxl_panel_wait_idle(b->panel);
            return st;
        }

        if (binning(b)) {
            uint16_t e = b->bins[k].tri;
            while (e != FXL_BAND_NONE) {
                draw_one(&t, &b->tris[b->bins[e].tri], stats, &first_err);
                e = b->bins[e].next;
            }
        }
        for (n = b->first_unbinned; n < b->tri_count; n++) {
            const fxl_band_tri_t *tri = &b->tris[n];
            if (tri->band0 <= k && k <= tri->band1) draw_one(&t, tri, stats, &first_err);
        }

        /* rows * width * 2 <= 2 * 4096 * 65535 fits in size_t >= 32 bits. */
        st = fxl_panel_write(b->panel, b->buf[i], (size_t)rows * (size_t)b->width * 2u);
        if (st != FXL_OK) {
            (void)fxl_panel_wait_idle(b->panel);
            return st;
        }
        b->seq[i] = b->panel->started;
    }
    st = fxl_panel_wait_idle(b->panel);
    return st != FXL_OK ? st : first_err;
}
