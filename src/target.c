/* target.c - caller-owned RGB565 render targets, bands and clipping
 * (see include/fixel/target.h).
 *
 * Invariants every function here keeps for a target it accepted:
 *   1 <= width, height <= FXL_TARGET_MAX_DIM, width <= stride <= 4 * FXL_TARGET_MAX_DIM,
 *   (so any element offset y * stride + x fits
 *   an int32_t, for this file and for the span loops),
 *   |origin_x|, |origin_y| <= FXL_TARGET_MAX_ORIGIN (so origin + size and
 *   every frame coordinate inside the buffer fit an int32_t with lots of room),
 *   frame rectangle F = [origin_x, origin_x + width) x [origin_y, origin_y + height),
 *   F.x0 <= clip.x0 <= clip.x1 <= F.x1 and the same for y.
 * The struct is public, so a caller can still change fields by hand: every
 * function re-validates the layout, and clear re-intersects the clip with F
 * before it writes, so a hand-edited clip can never cause a write outside the
 * buffer.
 */
#include <stddef.h>

#include "fixel/config.h"
#include "fixel/target.h"
#include "align.h"

/* Layout checks shared by init and by every function that takes a target.
 * Pointer and enum problems are FXL_ERR_ARG, numbers outside their range
 * FXL_ERR_RANGE. */
static fxl_status_t check_layout(const uint16_t *pixels, int32_t width, int32_t height,
                                 int32_t stride, int format)
{
    if (pixels == NULL) {
        return FXL_ERR_ARG;
    }
    if (format != (int)FXL_PIXFMT_RGB565 && format != (int)FXL_PIXFMT_RGB565_SWAP) {
        return FXL_ERR_ARG;
    }
    if (width < 1 || width > FXL_TARGET_MAX_DIM || height < 1 || height > FXL_TARGET_MAX_DIM) {
        return FXL_ERR_RANGE;
    }
    /* The same stride limit the draw calls check (target.h), so a target
     * that initialises is always drawable. */
    if (stride < width || stride > 4 * FXL_TARGET_MAX_DIM) {
        return FXL_ERR_RANGE;
    }
    /* With stride <= 2^14 and height <= 2^12 every element offset is below
     * 2^26: no int32 index can overflow. */
    return FXL_OK;
}

static int origin_ok(int32_t o)
{
    return o >= -FXL_TARGET_MAX_ORIGIN && o <= FXL_TARGET_MAX_ORIGIN;
}

/* t's layout with the origin (origin_x, origin_y); t != NULL */
static fxl_status_t check_layout_at(const fxl_target_t *t, int32_t origin_x, int32_t origin_y)
{
    const fxl_status_t st = check_layout(t->pixels, t->width, t->height, t->stride, (int)t->format);
    if (st != FXL_OK) {
        return st;
    }
    return origin_ok(origin_x) && origin_ok(origin_y) ? FXL_OK : FXL_ERR_RANGE;
}

/* t's fields (edited by hand or not) with the origin (ox, oy) */
static fxl_status_t check_target_at(const fxl_target_t *t, int32_t ox, int32_t oy)
{
    if (t == NULL || !fxl__aligned(t->pixels, 2u)) {
        return FXL_ERR_ARG;
    }
    return check_layout_at(t, ox, oy);
}

static fxl_status_t check_target(const fxl_target_t *t)
{
    return t == NULL ? FXL_ERR_ARG : check_target_at(t, t->origin_x, t->origin_y);
}

static int32_t clamp_i32(int32_t v, int32_t lo, int32_t hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

/* Intersection of r with the frame rectangle of t, normalised so that
 * F.x0 <= x0 <= x1 <= F.x1 (and y): an empty or inverted r gives an empty
 * rectangle that still lies inside F. Needs a target that passed
 * check_target (origin + size cannot overflow). */
static fxl_rect_t clip_to_frame(const fxl_target_t *t, const fxl_rect_t *r)
{
    const int32_t fx0 = t->origin_x, fx1 = t->origin_x + t->width;
    const int32_t fy0 = t->origin_y, fy1 = t->origin_y + t->height;
    fxl_rect_t c;
    c.x0 = clamp_i32(r->x0, fx0, fx1);
    c.x1 = clamp_i32(r->x1, c.x0, fx1);
    c.y0 = clamp_i32(r->y0, fy0, fy1);
    c.y1 = clamp_i32(r->y1, c.y0, fy1);
    return c;
}

static void reset_clip(fxl_target_t *t)
{
    t->clip.x0 = t->origin_x;
    t->clip.y0 = t->origin_y;
    t->clip.x1 = t->origin_x + t->width;
    t->clip.y1 = t->origin_y + t->height;
}

fxl_status_t fxl_target_init(fxl_target_t *t, uint16_t *pixels, int32_t width,
                             int32_t height, int32_t stride, fxl_pixfmt_t format)
{
    fxl_status_t st;
    /* odd pixels: every uint16 store misaligned (align.h); check_target
     * refuses one edited in by hand after init as well */
    if (t == NULL || !fxl__aligned(pixels, 2u)) {
        return FXL_ERR_ARG;
    }
    st = check_layout(pixels, width, height, stride, (int)format);
    if (st != FXL_OK) {
        return st; /* *t is left untouched */
    }
    t->pixels = pixels;
    t->depth = NULL;
    t->width = width;
    t->height = height;
    t->stride = stride;
    t->origin_x = 0;
    t->origin_y = 0;
    t->format = format;
    reset_clip(t);
    return FXL_OK;
}

fxl_status_t fxl_target_set_origin(fxl_target_t *t, int32_t origin_x, int32_t origin_y)
{
    /* The old origin is not checked: it is being replaced. */
    const fxl_status_t st = check_target_at(t, origin_x, origin_y);
    if (st != FXL_OK) {
        return st;
    }
    t->origin_x = origin_x;
    t->origin_y = origin_y;
    reset_clip(t);
    return FXL_OK;
}

fxl_status_t fxl_target_set_clip(fxl_target_t *t, const fxl_rect_t *clip)
{
    fxl_status_t st;
    if (clip == NULL) {
        return FXL_ERR_ARG;
    }
    st = check_target(t);
    if (st != FXL_OK) {
        return st;
    }
    t->clip = clip_to_frame(t, clip);
    return FXL_OK;
}

fxl_status_t fxl_target_set_depth(fxl_target_t *t, uint16_t *depth)
{
    fxl_status_t st = check_target(t);
    if (st != FXL_OK) {
        return st;
    }
    if (!fxl__aligned(depth, 2u)) {
        return FXL_ERR_ARG;
    }
#if !FXL_HAVE_DEPTH
    if (depth != NULL) {
        return FXL_ERR_UNSUPPORTED;
    }
#endif
    t->depth = depth;
    return FXL_OK;
}

/* One row of w pixels set to v. A band clear is a large share of a band's
 * time on a Cortex-M (30,720 bytes of colour and depth a 320x24 band), so
 * where the compiler has a type that may alias the uint16_t buffers (GCC,
 * Clang: may_alias) the row is written in 32-bit words from its first
 * 4-byte boundary, eight a step (the portable form, four halfword stores
 * a step, is for the short rows and the ends). Both halves of a word are
 * v, so the byte order does not matter. */
#if defined(__GNUC__) && defined(UINTPTR_MAX)
typedef uint32_t fxl__u32_alias_t __attribute__((__may_alias__));
#define FXL__WIDE_FILL 1
#else
#define FXL__WIDE_FILL 0
#endif

static void fill_row(uint16_t *row, int32_t w, uint16_t v)
{
    int32_t i = 0;
#if FXL__WIDE_FILL
    if (w >= 16) {
        const uint32_t v2 = (uint32_t)v * 0x10001u;
        uint32_t nw;
        fxl__u32_alias_t *p, *end;
        if ((uintptr_t)row & 2u) {   /* row is 2-aligned (check_target) */
            row[0] = v;
            i = 1;
        }
        nw = (uint32_t)(w - i) >> 1;   /* whole words from row + i */
        p = (fxl__u32_alias_t *)(void *)(row + i);
        end = p + (nw & ~7u);
        while (p != end) {
            p[0] = v2;
            p[1] = v2;
            p[2] = v2;
            p[3] = v2;
            p[4] = v2;
            p[5] = v2;
            p[6] = v2;
            p[7] = v2;
            p += 8;
        }
        end = p + (nw & 7u);
        while (p != end)
            *p++ = v2;
        i += (int32_t)(nw << 1);
    }
#endif
    for (; i + 4 <= w; i += 4) {
        row[i] = v;
        row[i + 1] = v;
        row[i + 2] = v;
        row[i + 3] = v;
    }
    for (; i < w; i++)
        row[i] = v;
}

/* Fill the part of buf inside clip with v. buf has t's layout; the clip is
 * re-intersected with the frame so a hand-edited t->clip stays harmless. */
static void fill_clip(const fxl_target_t *t, uint16_t *buf, uint16_t v)
{
    const fxl_rect_t c = clip_to_frame(t, &t->clip);
    const int32_t w = c.x1 - c.x0;
    int32_t y;
    /* Offsets: 0 <= y - origin_y < height and 0 <= x0 - origin_x <= width,
     * so (y - origin_y) * stride + (x0 - origin_x) <= stride * height
     * < 2^26. Computed in size_t all the same. */
    for (y = c.y0; y < c.y1; y++)
        fill_row(buf + (size_t)(y - t->origin_y) * (size_t)t->stride + (size_t)(c.x0 - t->origin_x), w, v);
}

fxl_status_t fxl_target_clear(fxl_target_t *t, uint16_t rgb565)
{
    uint16_t v = rgb565;
    fxl_status_t st = check_target(t);
    if (st != FXL_OK) {
        return st;
    }
    if (t->format == FXL_PIXFMT_RGB565_SWAP) {
        /* The bytes in memory must be big-endian whatever the host: write
         * them through a character view of the stored word (always allowed
         * aliasing), so no byte-order test is needed at all. */
        unsigned char *b = (unsigned char *)&v;
        b[0] = (unsigned char)(rgb565 >> 8);
        b[1] = (unsigned char)(rgb565 & 0xFFu);
    }
    fill_clip(t, t->pixels, v);
    return FXL_OK;
}

fxl_status_t fxl_target_clear_depth(fxl_target_t *t)
{
    fxl_status_t st = check_target(t);
    if (st != FXL_OK) {
        return st;
    }
#if !FXL_HAVE_DEPTH
    return FXL_ERR_UNSUPPORTED;
#else
    if (t->depth == NULL || !fxl__aligned(t->depth, 2u)) {
        return FXL_ERR_ARG; /* no depth buffer attached, or one edited to an odd address */
    }
    fill_clip(t, t->depth, 0u);
    return FXL_OK;
#endif
}
