/* edge.c - exact scanline edge walking.
 *
 * An edge from (Xa, Ya) to (Xb, Yb), Ya < Yb, crosses the centre line of
 * row j (Yc = j * ONE + HALF, subpx) at X(Yc) = Xa + (Yc - Ya) * dx / dy.
 * Under the top-left rule a pixel centre exactly on a left edge is inside and
 * one on a right edge is outside, so for BOTH sides the boundary pixel is
 *   x(j) = ceil((X(Yc) - HALF) / ONE) = ceil(num / den),
 *   num = (Xa - HALF) * dy + (Yc - Ya) * dx,  den = ONE * dy,
 * and a span is [x_left, x_right). Rather than stepping a rounded 16.16
 * slope, which drifts by up to rows * 2^-16 px and flips pixels whose centre
 * lies that close to the edge, the walk keeps the exact remainder
 * err = x * den - num in [0, den): a Bresenham-style DDA with no drift.
 *
 * Ranges: snapped |X|, |Y| <= 2^(15 + S) with S <= 6, so dy <= 2^22,
 * den <= 2^28 and every per-row quantity fits int32; num needs int64.
 */
#include "raster_int.h"
#include "div64.h"

/* ceil(n / d) for d > 0, |n| < 2^62: on magnitudes, ceil(-a / d) being
 * -floor(a / d) */
static int64_t ceil_div(int64_t n, int64_t d)
{
    return n >= 0 ? (int64_t)fxl__udiv64((uint64_t)n + (uint64_t)d - 1u, (uint64_t)d)
                  : -(int64_t)fxl__udiv64((uint64_t)0 - (uint64_t)n, (uint64_t)d);
}

void fxl__edge_init(fxl__edge_t *e, int32_t Xa, int32_t Ya, int32_t Xb, int32_t Yb, int32_t row)
{
    int64_t dx = (int64_t)Xb - Xa;
    int64_t dy = (int64_t)Yb - Ya;                 /* > 0 by the caller */
    int64_t den = dy * FXL__ONE;
    int64_t yc = (int64_t)row * FXL__ONE + FXL__HALF;
    int64_t num = ((int64_t)Xa - FXL__HALF) * dy + (yc - Ya) * dx;
    int64_t x = ceil_div(num, den);
    /* floor(ONE*dx / ONE*dy), |dx|, dy <= 2^22: an unsigned 32-bit division
     * (the one helper a Cortex-M0+ links anyway); floor(-a / b) = -ceil(a / b) */
    const uint32_t adx = (uint32_t)(dx < 0 ? -dx : dx), udy = (uint32_t)dy;
    const int32_t step = dx >= 0 ? (int32_t)(adx / udy) : -(int32_t)((adx + udy - 1u) / udy);

    e->x = (int32_t)x;
    e->err = (int32_t)(x * den - num);
    e->den = (int32_t)den;
    e->step = step;
    e->rem = (int32_t)((dx - step * dy) * FXL__ONE);
}

#if defined(__OPTIMIZE_SIZE__)
void fxl__edge_step(fxl__edge_t *e)
{
    fxl__edge_next(e);
}
#endif
