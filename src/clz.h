/* clz.h - count leading zeros in plain C, for cores without a CLZ
 * instruction (Cortex-M0+): a binary search of five compares, where GCC's
 * __builtin_clz would call the libgcc helper __clzsi2. fixed.c's fxl_clz32
 * and, inline in speed-optimised builds, the correction point's
 * normalisation (persp.h) share it.
 */
#ifndef FIXEL_CLZ_H
#define FIXEL_CLZ_H

#include <stdint.h>

/* leading zeros of x != 0 */
static inline int fxl__clz32_soft(uint32_t x)
{
    int n = 0;
    if (x <= 0x0000FFFFu) { n += 16; x <<= 16; }
    if (x <= 0x00FFFFFFu) { n += 8;  x <<= 8; }
    if (x <= 0x0FFFFFFFu) { n += 4;  x <<= 4; }
    if (x <= 0x3FFFFFFFu) { n += 2;  x <<= 2; }
    if (x <= 0x7FFFFFFFu) { n += 1; }
    return n;
}

#endif
