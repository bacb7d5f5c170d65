/* test_rng.c - see test_rng.h. One state per test executable. */
#include "test_rng.h"

static uint64_t rng_state = 1;

void rng_seed(uint64_t s)
{
    rng_state = s ? s : 1;
}

uint64_t rng_next(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 2685821657736338717ULL;
}

double rng_unit(void)
{
    return (double)(rng_next() >> 11) / 9007199254740992.0;
}

double rng_range(double a, double b)
{
    return a + (b - a) * rng_unit();
}
