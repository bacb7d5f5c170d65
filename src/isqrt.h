/* isqrt.h - the integer square root of the core (fixed.c): q16 square
 * roots, vector lengths in the front end and texgen all take it. */
#ifndef FIXEL_ISQRT_H
#define FIXEL_ISQRT_H

#include <stdint.h>

/* floor(sqrt(x)): a 16-bit root of the top word, one 32-bit division for
 * the next 16 bits and at most two steps down (fixed.c); no floating point.
 * On cores without a divide instruction the division is libgcc's. */
uint64_t fxl__isqrt64(uint64_t x);

#endif
