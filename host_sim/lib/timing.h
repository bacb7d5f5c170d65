/* timing.h - monotonic wall-clock helpers for host measurements.
 *
 * Times come from clock_gettime(CLOCK_MONOTONIC): immune to clock changes,
 * but still wall time, so a busy machine inflates them. Report medians of
 * repeated runs (timing_median) rather than single figures; use callgrind
 * for numbers that must be repeatable.
 */
#ifndef FXL_HOST_TIMING_H
#define FXL_HOST_TIMING_H

#include <stddef.h>
#include <stdint.h>

/* Nanoseconds since an arbitrary fixed point. */
uint64_t timing_now_ns(void);

/* Seconds between two timing_now_ns() readings (end >= start). */
double timing_seconds(uint64_t start_ns, uint64_t end_ns);

/* Median of n values (n >= 1); sorts `values` in place. For even n, the
 * mean of the two middle values. Returns 0 for n == 0 or NULL. */
double timing_median(double *values, size_t n);

#endif
