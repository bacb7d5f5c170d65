/* crc32.h - CRC-32 (IEEE 802.3) for golden-image checks, host side.
 *
 * The standard "CRC-32" of zlib and PNG: reflected, polynomial 0xEDB88320,
 * initial value and final xor 0xFFFFFFFF; crc32 of the ASCII bytes
 * "123456789" is 0xCBF43926. The table is a constant in crc32.c (no state).
 *
 * Streaming: start from 0 and feed the result back in, exactly like zlib's
 * crc32(): crc = crc32_update(0, a, na); crc = crc32_update(crc, b, nb);
 * equals crc32_update(0, ab, na + nb).
 */
#ifndef FXL_HOST_CRC32_H
#define FXL_HOST_CRC32_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/target.h"

uint32_t crc32_update(uint32_t crc, const void *data, size_t len);

/* CRC-32 over the rows of the clip rectangle of a target, top to bottom, each
 * row's pixels as stored in memory (so byte-swapped targets hash their
 * swapped bytes, and the value depends on the host's byte order for native
 * RGB565). Depth is not included. Returns 0 for a NULL target or buffer;
 * an empty clip rectangle hashes no bytes (also 0). */
uint32_t fxl_host_crc_target(const fxl_target_t *t);

#endif
