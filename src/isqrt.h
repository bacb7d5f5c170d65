/* isqrt.h - the integer square root of the core (fixed.c): q16 square
 * roots, vector lengths in the front end and texgen all take it. */
#ifndef FIXEL_ISQRT_H
#define FIXEL_ISQRT_H

#include <stdint.h>

/* floor(sqrt(x)), digit by digit (no division, no floating point). */
uint64_t fxl__isqrt64(uint64_t x);

#endif
