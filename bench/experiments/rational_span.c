/* rational_span.c - an experiment, not part of the core: what a pixel of a
 * "rational" AUTO segment would cost on a Cortex-M4 (docs/design.md,
 * "The rolled floor").
 *
 * Between an exact point and the next, perspective interpolation is exact
 * in the form u(m) = u0 + m C_u rho(m), with rho(m) = q0 / q(m) and
 * C_u = du/dx at the start. rho is stepped by Newton from the previous
 * pixel's value against qh(m) = q(m) / q0, which steps exactly:
 *   rho <- rho + rho (1 - qh rho)     (relative error e -> e^2)
 * Formats: qh, rho q29 (a segment keeps q within 4x of its start); sigma
 * and C_u scaled per segment so that |u - u0| < 4096 texels; u, v q16.
 * 1 - qh rho is the high word of qh rho (q26) shifted to q32 and negated
 * by MVN (one ulp of bias, 2^-32).
 *
 * Two passes over a batch, as the lean walks batch their segments: the
 * first steps rho and forms sigma(m) = m rho(m) (scaled per segment), the
 * second maps the texels, u = u0 + C_u sigma(m) in one SMMLA. One loop
 * doing both spilled four values a pixel; a first pass storing rho alone
 * left the second with six live steps and spilled there. The loops are
 * straight-line, so the disassembly is the count:
 *
 *   arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -O2 -DNEWTON=1 -c rational_span.c
 *   arm-none-eabi-objdump -d rational_span.o
 *
 * With arm-none-eabi-gcc 12.2, per pixel, loops unrolled by four:
 *   rat_sigma   8.5 (1 Newton step), 12.75 (2), 15.75 (3)
 *   rat_texels  11 (point sampling, RGB565)
 * so 19.5, 23.75 and 26.75 instructions a pixel, against 7.5 for an affine
 * and 10 for a quadratic segment (span_loop.h).
 */
#include <stdint.h>

#ifndef NEWTON
#define NEWTON 1
#endif

#if defined(__GNUC__) && defined(__ARM_ARCH_7EM__)
static inline int32_t smmul(int32_t a, int32_t b)
{
    int32_t r;
    __asm__("smmul %0, %1, %2" : "=r"(r) : "r"(a), "r"(b));
    return r;
}
static inline int32_t smmla(int32_t a, int32_t b, int32_t acc)
{
    int32_t r;
    __asm__("smmla %0, %1, %2, %3" : "=r"(r) : "r"(a), "r"(b), "r"(acc));
    return r;
}
#else
static inline int32_t smmul(int32_t a, int32_t b)
{
    return (int32_t)(((int64_t)a * b) >> 32);
}
static inline int32_t smmla(int32_t a, int32_t b, int32_t acc)
{
    return (int32_t)((uint32_t)acc + (uint32_t)smmul(a, b));
}
#endif

/* One Newton step: rho (q29) towards 1 / qh (qh q29). */
#define NEWTON_STEP(qh, rho) ((rho) = smmla((rho), (int32_t) ~((uint32_t)smmul((qh), (rho)) << 6), (rho)))
#if NEWTON == 1
#define RHO_NEXT(qh, rho) NEWTON_STEP(qh, rho)
#elif NEWTON == 2
#define RHO_NEXT(qh, rho) (NEWTON_STEP(qh, rho), NEWTON_STEP(qh, rho))
#else
#define RHO_NEXT(qh, rho) (NEWTON_STEP(qh, rho), NEWTON_STEP(qh, rho), NEWTON_STEP(qh, rho))
#endif

/* Four pixels of a loop body M(i), straight-line (the count is the
 * disassembly's). */
#define UNROLL4(M) \
    M(0);          \
    M(1);          \
    M(2);          \
    M(3)

/* Pass 1: sigma(m) = m rho(m) 2^-s for n pixels (n a multiple of 4), qh
 * stepping by g; mk steps by k = 2^(32 - s) so that smmul(mk, rho) is it. */
void rat_sigma(int32_t *out, int32_t n, int32_t qh, int32_t g, int32_t rho, int32_t mk, int32_t k)
{
    int32_t *end = out + n;
#define RAT_SIGMA(i) (qh += g, RHO_NEXT(qh, rho), mk += k, out[i] = smmul(mk, rho))
    while (out != end) {
        UNROLL4(RAT_SIGMA);
        out += 4;
    }
#undef RAT_SIGMA
}

/* Pass 2: point-sampled texels, u = u0 + C_u sigma (C_u scaled per segment). */
void rat_texels(uint16_t *dst, int32_t n, const uint16_t *tex, uint32_t lw, uint32_t mu16, uint32_t mv16,
                const int32_t *sigma, int32_t cu, int32_t cv, int32_t u0, int32_t v0)
{
    uint16_t *end = dst + n;
#define RAT_PIXEL(i)                                                                                        \
    do {                                                                                                    \
        const uint32_t u = (uint32_t)smmla(cu, sigma[i], u0), v = (uint32_t)smmla(cv, sigma[i], v0);        \
        dst[i] = tex[(((v << lw) & mv16) | (u & mu16)) >> 16];                                              \
    } while (0)
    while (dst != end) {
        UNROLL4(RAT_PIXEL);
        dst += 4;
        sigma += 4;
    }
#undef RAT_PIXEL
}
