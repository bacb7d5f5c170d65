/* src/align.h - the alignment check of the API boundary (internal, not installed).
 *
 * The core reads and writes RGB565 pixels, depth values, texels and palette
 * entries as uint16_t. At an odd address that is undefined behaviour in C
 * and a HardFault on a Cortex-M0+, so the calls that take such buffers
 * (target.c, texture.c, mip.c) refuse them with FXL_ERR_ARG.
 */
#ifndef FIXEL_ALIGN_H
#define FIXEL_ALIGN_H

#include <stdint.h>

/* Is p a multiple of `bytes` (1 or 2)? uintptr_t is optional in C99;
 * without it the check is left to the caller. */
static inline int fxl__aligned(const void *p, uint32_t bytes)
{
#ifdef UINTPTR_MAX
    return ((uintptr_t)p & (uintptr_t)(bytes - 1u)) == 0u;
#else
    (void)p;
    (void)bytes;
    return 1;
#endif
}

#endif /* FIXEL_ALIGN_H */
