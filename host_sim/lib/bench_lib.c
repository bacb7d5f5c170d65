/* bench_lib.c - see bench_lib.h. */
#include "bench_lib.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

double bench_wrap_diff(uint32_t core_q16, double exact, uint32_t n)
{
    double c = (double)core_q16 / 65536.0, d, nn = (double)n;
    d = fmod(c - exact, nn);          /* in (-n, n) */
    if (d < -nn / 2)
        d += nn;
    if (d >= nn / 2)
        d -= nn;
    return d;
}

double bench_affine_bound(double L, double grad_len, double q, double dq_dx)
{
    if (!(q > 0))
        return 0;
    return L * L * grad_len * fabs(dq_dx) / (4.0 * q);
}

size_t bench_pareto(const double *x, const double *y, size_t n, uint8_t *on_front)
{
    size_t i, j, count = 0;
    for (i = 0; i < n; i++) {
        int dominated = isnan(x[i]) || isnan(y[i]);
        for (j = 0; j < n && !dominated; j++) {
            if (j == i || isnan(x[j]) || isnan(y[j]))
                continue;
            if (x[j] <= x[i] && y[j] <= y[i] && (x[j] < x[i] || y[j] < y[i]))
                dominated = 1;
        }
        on_front[i] = (uint8_t)!dominated;
        count += (size_t)!dominated;
    }
    return count;
}

int bench_trace_pc(const char *line, uint32_t *pc)
{
    const char *p;
    char *end;
    unsigned long v;
    if (strncmp(line, "Trace ", 6) != 0)
        return 0;
    p = strchr(line, '[');
    if (!p)
        return 0;
    p = strchr(p, '/');   /* skip cs_base */
    if (!p)
        return 0;
    v = strtoul(p + 1, &end, 16);
    if (end == p + 1 || *end != '/')
        return 0;
    *pc = (uint32_t)v;
    return 1;
}

static int cmp_range(const void *a, const void *b)
{
    const bench_range_t *x = a, *y = b;
    return (x->lo > y->lo) - (x->lo < y->lo);
}

size_t bench_trace_count(FILE *f, const bench_range_t *ranges, size_t nranges, uint32_t begin,
                         uint32_t end, uint64_t *counts, size_t max_seg, uint64_t *unclosed)
{
    char line[512];
    size_t seg = 0;
    uint64_t cur = 0;
    int armed = 0;
    /* The core's functions are contiguous in the link, so remembering the
     * last range hit answers almost every lookup without a search. */
    const bench_range_t *last = NULL;
    while (fgets(line, sizeof line, f)) {
        uint32_t pc;
        size_t len = strlen(line);
        /* a line longer than the buffer: skip the rest of it */
        if (len > 0 && line[len - 1] != '\n') {
            int ch;
            while ((ch = fgetc(f)) != EOF && ch != '\n') {
            }
        }
        if (!bench_trace_pc(line, &pc))
            continue;
        if (pc == begin) {
            armed = 1;
            cur = 0;
            continue;
        }
        if (pc == end) {
            if (armed) {
                if (seg < max_seg)
                    counts[seg] = cur;
                seg++;
            }
            armed = 0;
            continue;
        }
        if (!armed)
            continue;
        if (last && pc >= last->lo && pc < last->hi) {
            cur++;
        } else {
            size_t i;
            for (i = 0; i < nranges; i++)
                if (pc >= ranges[i].lo && pc < ranges[i].hi) {
                    last = &ranges[i];
                    cur++;
                    break;
                }
        }
    }
    if (unclosed)
        *unclosed = armed ? cur : 0;
    return seg;
}

long bench_read_nm(const char *path, bench_range_t *ranges, size_t max, const char *begin_name,
                   uint32_t *begin, const char *end_name, uint32_t *end)
{
    FILE *f = fopen(path, "r");
    char line[512];
    size_t n = 0;
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f)) {
        unsigned long addr, size;
        char type, name[400];
        if (sscanf(line, "%lx %lx %c %399s", &addr, &size, &type, name) != 4)
            continue;
        if (begin_name && begin && strcmp(name, begin_name) == 0) {
            *begin = (uint32_t)(addr & ~1ul);
            continue;
        }
        if (end_name && end && strcmp(name, end_name) == 0) {
            *end = (uint32_t)(addr & ~1ul);
            continue;
        }
        if (type != 't' && type != 'T' && type != 'w' && type != 'W')
            continue;
        if (n < max) {
            ranges[n].lo = (uint32_t)(addr & ~1ul);
            ranges[n].hi = (uint32_t)((addr & ~1ul) + size);
            n++;
        }
    }
    fclose(f);
    qsort(ranges, n, sizeof *ranges, cmp_range);
    return (long)n;
}
