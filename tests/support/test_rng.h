/* test_rng.h - the deterministic random numbers the front-end tests share
 * (xorshift64*): the same seed gives the same cases on every machine. */
#ifndef FXL_TEST_RNG_H
#define FXL_TEST_RNG_H

#include <stdint.h>

/* Seed the generator (0 is mapped to 1: xorshift never leaves 0). */
void rng_seed(uint64_t s);
uint64_t rng_next(void);
/* Uniform in [0, 1) with 53 bits. */
double rng_unit(void);
/* Uniform in [a, b). */
double rng_range(double a, double b);

#endif
