/* fw_mem.h - memcpy and memset for the bare-metal start-up files (there is
 * no libc in these images, and GCC may emit calls to both for struct copies
 * and initialisers even with -ffreestanding). It holds their definitions:
 * include it from exactly one file of an image, its start-up file. */
#ifndef FXL_EXAMPLES_FW_MEM_H
#define FXL_EXAMPLES_FW_MEM_H

#include <stddef.h>
#include <stdint.h>

void *memcpy(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);

void *memcpy(void *dst, const void *src, size_t n)
{
    uint8_t *d = (uint8_t *)dst;
    const uint8_t *s = (const uint8_t *)src;
    while (n--) *d++ = *s++;
    return dst;
}

void *memset(void *dst, int c, size_t n)
{
    uint8_t *d = (uint8_t *)dst;
    while (n--) *d++ = (uint8_t)c;
    return dst;
}

#endif
