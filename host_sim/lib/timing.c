/* timing.c - see timing.h. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include "timing.h"

#include <stdlib.h>
#include <time.h>

uint64_t timing_now_ns(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0) {
        return 0;
    }
    return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

double timing_seconds(uint64_t start_ns, uint64_t end_ns)
{
    return end_ns >= start_ns ? (double)(end_ns - start_ns) * 1e-9 : 0.0;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double timing_median(double *values, size_t n)
{
    if (values == NULL || n == 0) {
        return 0.0;
    }
    qsort(values, n, sizeof(values[0]), cmp_double);
    if (n % 2u == 1u) {
        return values[n / 2u];
    }
    return 0.5 * (values[n / 2u - 1u] + values[n / 2u]);
}
