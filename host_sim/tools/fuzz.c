/* fuzz.c - fixel-fuzz: randomized, deterministic fuzzing of fxl_draw_triangle
 * and of the 3D front end (fxl_mesh_draw and the rest of fixel/pipeline.h).
 *
 *   fixel-fuzz [--cases N] [--seed S] [--start I] [--long] [--bytes B]
 *              [--replay HEX] [--stop-after K] [--quiet]
 *
 * Case i of seed S is B bytes (default 192) from a SplitMix64 stream keyed by
 * (S, i). When bits 3..5 of its last byte are 0 (1 in 8) it is a front-end
 * case: it is extended to max(B, FZP_BYTES = 448) bytes of the same stream,
 * the last one set to that byte again, and decoded and checked by
 * tests/fuzz/fuzz_pipe.h (documented statuses, canaries and guard pages
 * around every caller buffer, clip, bands, fxl_mesh_draw against emit plus
 * fxl_draw_indexed, vertex cache, the stages alone). Every other case is
 * decoded and checked by tests/fuzz/fuzz_case.h as before (status codes,
 * canaries and guard pages, clip, determinism, exact coverage, stats).
 * A finding prints the seed, the case index, its bytes as hex (feed them to
 * --replay or to tests/test_fuzz_regress.c) and the decoded case. Exit 0 when
 * nothing was found, 1 otherwise, 2 on usage errors. --long runs 10^8 cases.
 * Build it with -fsanitize=address,undefined for the CI run (ci_extra.sh).
 */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../../tests/fuzz/fuzz_pipe.h"

#define MAX_BYTES 1024

static uint64_t splitmix(uint64_t *s)
{
    uint64_t z = (*s += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

static void case_bytes(uint64_t seed, uint64_t index, uint8_t *b, size_t n)
{
    uint64_t s = seed * UINT64_C(0xD1B54A32D192ED03) ^ index * UINT64_C(0x9E3779B97F4A7C15);
    size_t i;
    for (i = 0; i < n; i += 8) {
        uint64_t r = splitmix(&s);
        size_t k;
        for (k = 0; k < 8 && i + k < n; k++)
            b[i + k] = (uint8_t)(r >> (8 * k));
    }
}

static int hex_digit(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

/* Two hex digits per byte, nothing else ("%2x" took "0g" as 00 and "+1"). */
static int parse_hex(const char *h, uint8_t *b, size_t cap, size_t *n)
{
    size_t len = strlen(h), i;
    if (len % 2 != 0 || len / 2 > cap)   /* '' is the 0-byte case libFuzzer tries first */
        return -1;
    for (i = 0; i < len / 2; i++) {
        int hi = hex_digit(h[2 * i]), lo = hex_digit(h[2 * i + 1]);
        if (hi < 0 || lo < 0)
            return -1;
        b[i] = (uint8_t)(hi * 16 + lo);
    }
    *n = len / 2;
    return 0;
}

/* A whole non-negative number (decimal, 0x hex or 0 octal): strtoull alone
 * read "abc" as 0 and "1e6" as 1, and "-1" wrapped to 2^64 - 1, so a typo
 * ran no cases, or one, and exited 0 with "0 finding(s)". */
static int parse_u64(const char *opt, const char *s, uint64_t *out)
{
    char *end;
    unsigned long long v;
    errno = 0;
    v = strtoull(s, &end, 0);
    if (s[0] < '0' || s[0] > '9' || *end != '\0' || errno != 0) { /* no sign, no blank */
        fprintf(stderr, "fixel-fuzz: %s wants a non-negative whole number, got '%s'\n", opt, s);
        return -1;
    }
    *out = (uint64_t)v;
    return 0;
}

static void print_hex(FILE *f, const uint8_t *b, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        fprintf(f, "%02x", b[i]);
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static void usage(FILE *to)
{
    fprintf(to, "usage: fixel-fuzz [--cases N] [--seed S] [--start I] [--long] [--bytes B]\n"
                "                  [--replay HEX] [--stop-after K] [--quiet]\n");
}

int main(int argc, char **argv)
{
    uint64_t cases = 100000, seed = 1, start = 0, i, findings = 0, stop_after = 10;
    uint64_t n_ok = 0, n_err = 0, n_px = 0, n_equal = 0, n_pipe = 0, n_pipe_ok = 0, n_tris = 0, n_placed = 0, n_texel = 0, n_texel_wide = 0;
    uint64_t n_alone = 0, n_alone_px = 0, n_alone_checked = 0, n_depth = 0;
    size_t nbytes;
    uint64_t bytes64 = 192;
    const char *replay = NULL;
    int quiet = 0, a;
    uint8_t buf[MAX_BYTES];
    static fz_state st;
    static fz_pstate pst;
    char msg[FZ_MSG];
    double t0;

    for (a = 1; a < argc; a++) {
        uint64_t *num = !strcmp(argv[a], "--cases")        ? &cases
                      : !strcmp(argv[a], "--seed")         ? &seed
                      : !strcmp(argv[a], "--start")        ? &start
                      : !strcmp(argv[a], "--bytes")        ? &bytes64
                      : !strcmp(argv[a], "--stop-after")   ? &stop_after
                                                           : NULL;
        if ((num != NULL || !strcmp(argv[a], "--replay")) && a + 1 >= argc) {
            fprintf(stderr, "fixel-fuzz: %s needs a value\n", argv[a]);
            usage(stderr);
            return 2;
        }
        if (num != NULL) {
            if (parse_u64(argv[a], argv[a + 1], num) != 0)
                return 2;
            a++;
        } else if (!strcmp(argv[a], "--replay") && a + 1 < argc)
            replay = argv[++a];
        else if (!strcmp(argv[a], "--long"))
            cases = 100000000u;
        else if (!strcmp(argv[a], "--quiet"))
            quiet = 1;
        else if (!strcmp(argv[a], "--help") || !strcmp(argv[a], "-h")) {
            usage(stdout);
            return 0;
        } else {
            fprintf(stderr, "fixel-fuzz: unknown option '%s'\n", argv[a]);
            usage(stderr);
            return 2;
        }
    }
    if (cases > UINT64_MAX - start) {
        fprintf(stderr, "fixel-fuzz: --start + --cases is past 2^64 - 1\n");
        return 2;
    }
    nbytes = bytes64 <= MAX_BYTES ? (size_t)bytes64 : 0;
    if (nbytes < 1 || nbytes > MAX_BYTES) {
        fprintf(stderr, "fixel-fuzz: --bytes must be 1..%d\n", MAX_BYTES);
        return 2;
    }
    if (fz_state_init(&st) != 0 || fz_pstate_init(&pst, &st) != 0) {
        fprintf(stderr, "fixel-fuzz: out of memory\n");
        return 2;
    }

    if (replay) {
        fz_outcome o;
        size_t n;
        int bad;
        if (parse_hex(replay, buf, sizeof buf, &n) != 0) {
            fprintf(stderr, "fixel-fuzz: --replay wants hex digits, two per byte (max %d bytes)\n", MAX_BYTES);
            return 2;
        }
        bad = fz_input_run(&pst, buf, n, &o, msg, NULL, 0);
        if (o.pipe)
            printf("replay: %s (front end, status %s, %u written, %u screen triangles)\n", bad ? msg : "ok",
                   fxl_status_name(o.status), (unsigned)o.written, (unsigned)o.emitted);
        else
            printf("replay: %s (status %s, %u written, %u covered)\n", bad ? msg : "ok", fxl_status_name(o.status),
                   (unsigned)o.written, (unsigned)o.covered);
        fz_input_run(&pst, buf, n, &o, msg, stdout, 1);
        return bad;
    }

    t0 = now_s();
    for (i = start; i < start + cases; i++) {
        fz_outcome o;
        size_t n = nbytes;
        case_bytes(seed, i, buf, nbytes);
        if (fz_input_is_pipe(buf, nbytes) && nbytes < FZP_BYTES) {
            /* a front-end case needs more bytes: the same stream, longer,
             * ending in the byte that made it one */
            uint8_t sel = buf[nbytes - 1];
            n = FZP_BYTES;
            case_bytes(seed, i, buf, n);
            buf[n - 1] = sel;
        }
        if (fz_input_run(&pst, buf, n, &o, msg, NULL, 0)) {
            findings++;
            printf("FINDING seed %llu case %llu: %s\n  bytes ", (unsigned long long)seed, (unsigned long long)i, msg);
            print_hex(stdout, buf, n);
            printf("\n");
            fz_input_run(&pst, buf, n, &o, msg, stdout, 1);
            fflush(stdout);
            if (findings >= stop_after)
                break;
        }
        if (o.status == FXL_OK)
            n_ok++;
        else
            n_err++;
        n_px += o.written;
        n_equal += (uint64_t)o.checked_equal;
        n_pipe += (uint64_t)o.pipe;
        n_pipe_ok += (uint64_t)(o.pipe && o.status == FXL_OK);
        n_tris += o.emitted;
        n_placed += o.placed;
        n_texel += o.texel_checked;
        n_texel_wide += o.texel_wide;
        n_alone += o.alone_tris;
        n_alone_px += o.alone_written;
        n_alone_checked += o.alone_checked;
        n_depth += o.depth_checked;
        if (!quiet && (i - start + 1) % 1000000u == 0) {
            fprintf(stderr, "fixel-fuzz: %llu cases, %.0f cases/s\n", (unsigned long long)(i - start + 1),
                    (double)(i - start + 1) / (now_s() - t0));
        }
    }
    {
        double dt = now_s() - t0;
        uint64_t done = i - start;
        printf("fixel-fuzz: seed %llu, cases %llu..%llu: %llu run in %.1f s (%.0f cases/s), %llu valid "
               "(%llu with exact coverage equality), %llu rejected with an error status, %llu pixels written "
               "(%llu held to the texels or colour their mode's bound allows, %llu of them through level indexes; "
               "%llu depth values held to the exact plane); "
               "%llu front-end cases (%llu valid, %llu screen triangles, %llu mesh triangles placed against a "
               "double projection; %llu screen triangles drawn alone, %llu pixels written, %llu of them held to "
               "the texels or colour); %llu finding(s)\n",
               (unsigned long long)seed, (unsigned long long)start, (unsigned long long)(start + done),
               (unsigned long long)done, dt, dt > 0 ? (double)done / dt : 0.0, (unsigned long long)n_ok,
               (unsigned long long)n_equal, (unsigned long long)n_err, (unsigned long long)n_px,
               (unsigned long long)n_texel, (unsigned long long)n_texel_wide, (unsigned long long)n_depth,
               (unsigned long long)n_pipe, (unsigned long long)n_pipe_ok, (unsigned long long)n_tris,
               (unsigned long long)n_placed, (unsigned long long)n_alone, (unsigned long long)n_alone_px,
               (unsigned long long)n_alone_checked, (unsigned long long)findings);
    }
    return findings ? 1 : 0;
}
