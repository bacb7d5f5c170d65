/* main.c - the benchmark firmware: draws every configuration of
 * bench_data.c into a 320 x 240 RGB565 frame (no depth buffer; with
 * -DBENCH_DEPTH=1 a full one) and reports
 * how many instructions the draw calls took.
 *
 * Two ways to count, both used by host_sim/scripts/bench.sh:
 * - exact: run under `-singlestep -d exec,nochain`; bench_begin() and
 *   bench_end() bracket the draw calls and the trace counter (fixel-bench
 *   count-trace) adds up only the instructions between them whose PC lies
 *   in the core's functions (and the libgcc helpers they call).
 * - fast: run under `-icount shift=0`, where QEMU's virtual clock advances
 *   1 ns per instruction; SysTick (fed by the 25 MHz system clock) then
 *   ticks once per 40 instructions. The ratio is calibrated at start-up on
 *   a loop of known length, and the harness loop (the same calls to an
 *   empty function) is measured and subtracted. Resolution: +-1 tick per
 *   reading, i.e. about 80 instructions per frame.
 * On RISC-V (qemu-system-riscv32 -M virt, examples/common/virt_rv_startup.c)
 * the clock is the minstret counter, which qemu's -icount makes an exact
 * instruction count; the calibration and harness steps are the same.
 * Output lines (semihosting): "calib <ticks> <instructions>", then per
 * configuration "cfg <scene> <method> <filter> <ticks> <harness_ticks> <status>".
 * With front-end meshes in the data (gen-fw --meshes 1), then per mesh,
 * level and vertex cache (bench_frontend.h) "fe <mesh> <level> <cache>
 * <ticks> <status>": one fxl_pipeline_emit call into a callback that does
 * nothing (fixel-bench frontend converts ticks with the calib line).
 * After each of those a "stack <scene> <method> <filter> <bytes>" or "stack
 * fe <mesh> <level> <cache> <bytes>" line: the deepest stack the draw calls
 * (or the front end) reached below the caller, measured with
 * examples/common/fw_stack.h (host_sim/scripts/bench.sh sums them up in
 * docs/bench/footprint.txt).
 */
#include <stdint.h>

#include "bench_data.h"
#include "bench_frontend.h"
#include "bench_fw.h"

#define FB_W 320
#define FB_H 240

#if !defined(__riscv)
#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#endif

static uint16_t fb[FB_W * FB_H];
#if BENCH_DEPTH
/* OPT="-O2 -DBENCH_DEPTH=1": every draw with a full depth buffer, as the
 * host's callgrind figures (the published core figures are without) */
static uint16_t zbuf[FB_W * FB_H];
#endif
static fxl_vcache_entry_t vcache[BENCH_FE_CACHE];

/* The trace counter counts between these two (see bench_lib.h). */
__attribute__((noinline)) void bench_begin(void);
__attribute__((noinline)) void bench_end(void);
__attribute__((noinline)) void bench_begin(void)
{
    __asm__ volatile("" ::: "memory");
}
__attribute__((noinline)) void bench_end(void)
{
    __asm__ volatile("" ::: "memory");
}

/* Same signature as fxl_draw_triangle, does nothing: the harness cost. */
__attribute__((noinline)) fxl_status_t bench_nop(fxl_target_t *t, const fxl_draw_t *d, const fxl_vertex_t v[3],
                                                 fxl_stats_t *s);
__attribute__((noinline)) fxl_status_t bench_nop(fxl_target_t *t, const fxl_draw_t *d, const fxl_vertex_t v[3],
                                                 fxl_stats_t *s)
{
    (void)t;
    (void)d;
    (void)v;
    (void)s;
    __asm__ volatile("" ::: "memory");
    return FXL_OK;
}

typedef fxl_status_t (*draw_fn)(fxl_target_t *, const fxl_draw_t *, const fxl_vertex_t *, fxl_stats_t *);

#if defined(__riscv)
/* minstret's low word (machine mode: no counter enable needed; zicsr for
 * this one instruction, so -march stays the core's and its multilib) */
static uint32_t ticks_now(void)
{
    unsigned long v;
    __asm__ volatile(".option push\n\t.option arch, +zicsr\n\tcsrr %0, minstret\n\t.option pop" : "=r"(v));
    return (uint32_t)v;
}

/* Up-counter: elapsed ticks between two readings, modulo 2^32. */
static uint32_t ticks_since(uint32_t start)
{
    return ticks_now() - start;
}
#else
static uint32_t ticks_now(void)
{
    return SYST_CVR;
}

/* Down-counter, 24 bits: elapsed ticks between two readings. */
static uint32_t ticks_since(uint32_t start)
{
    return (start - SYST_CVR) & 0xFFFFFFu;
}
#endif

/* 2 instructions per iteration (subs, bne) on every Thumb core; addi, bnez
 * on RISC-V. */
__attribute__((noinline)) static void spin(uint32_t n)
{
#if defined(__riscv)
    __asm__ volatile("1: addi %0, %0, -1\n\tbnez %0, 1b" : "+r"(n));
#elif defined(__thumb2__)
    __asm__ volatile("1: subs %0, %0, #1\n\tbne 1b" : "+l"(n) : : "cc");
#else
    /* ARMv6-M: gcc emits divided syntax, where the 16-bit flag-setting
     * subtract is spelt `sub`. */
    __asm__ volatile("1: sub %0, #1\n\tbne 1b" : "+l"(n) : : "cc");
#endif
}

static void put_u32(char **p, uint32_t v)
{
    char tmp[10];
    int n = 0;
    do {
        tmp[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    while (n)
        *(*p)++ = tmp[--n];
}

static void put_str(char **p, const char *s)
{
    while (*s)
        *(*p)++ = *s++;
}

/* "<prefix><mesh> <level> <cache> ": the front-end run a line is about */
static void put_fe_run(char **p, const char *prefix, const char *mesh, int level, int cache)
{
    put_str(p, prefix);
    put_str(p, mesh);
    put_str(p, " ");
    put_str(p, bench_fe_level_names[level]);
    put_str(p, cache ? " 1 " : " 0 ");
}

/* The draw calls' stack depth (fw_stack.h), measured with fxl_draw_triangle
 * only: bytes below run()'s stack pointer written during them. */
static fxl_status_t run(const bench_cfg_t *c, draw_fn fn, uint32_t *ticks, uint32_t *depth)
{
    const bench_scene_t *s = &bench_scenes[c->scene];
    fxl_target_t t;
    fxl_draw_t d;
    fxl_status_t st;
    uint32_t i, t0;
    uintptr_t top = 0;

    st = fxl_target_init(&t, fb, FB_W, FB_H, FB_W, FXL_PIXFMT_RGB565);
    if (st != FXL_OK)
        return st;
    (void)fxl_target_clear(&t, 0);
#if BENCH_DEPTH
    st = fxl_target_set_depth(&t, zbuf);
    if (st != FXL_OK)
        return st;
    (void)fxl_target_clear_depth(&t);
#endif
    fxl_draw_defaults(&d);
    d.texture = s->tex;
    d.persp = c->persp;
    d.filter = c->filter;
    d.mip = c->mip;
    d.lod = FXL_LOD_SEGMENT;
    if (fn == fxl_draw_triangle) {
        fw_stack_paint();
        top = fw_stack_sp();
        bench_begin();
    }
    t0 = ticks_now();
    for (i = 0; i < s->ntri; i++) {
        st = fn(&t, &d, &s->verts[3u * i], 0);
        if (st != FXL_OK)
            break;
    }
    *ticks = ticks_since(t0);
    if (fn == fxl_draw_triangle) {
        bench_end();
        *depth = (uint32_t)(top - fw_stack_low());
    }
    return st;
}

int main(void)
{
    char line[256];
    uint32_t k, t0, calib;
    int bad = 0;

#if !defined(__riscv)
    SYST_RVR = 0xFFFFFFu;
    SYST_CVR = 0;
    SYST_CSR = 5u; /* enable, processor clock, no interrupt */
#endif

    t0 = ticks_now();
    spin(1000000u);
    calib = ticks_since(t0);
    {
        char *p = line;
        put_str(&p, "calib ");
        put_u32(&p, calib);
        put_str(&p, " 2000000\n");
        *p = 0;
        fw_write(line);
    }
    for (k = 0; k < bench_ncfg; k++) {
        const bench_cfg_t *c = &bench_cfgs[k];
        uint32_t tk = 0, th = 0, depth = 0;
        fxl_status_t st = run(c, fxl_draw_triangle, &tk, &depth);
        char *p = line;
        (void)run(c, bench_nop, &th, &depth);
        put_str(&p, "cfg ");
        put_str(&p, c->name);
        put_str(&p, " ");
        put_u32(&p, tk);
        put_str(&p, " ");
        put_u32(&p, th);
        put_str(&p, st == FXL_OK ? " ok\n" : " error\n");
        put_str(&p, "stack ");
        put_str(&p, c->name);
        put_str(&p, " ");
        put_u32(&p, depth);
        put_str(&p, "\n");
        *p = 0;
        fw_write(line);
        bad |= st != FXL_OK;
    }
    for (k = 0; k < bench_nmeshes; k++) {
        const bench_mesh_t *bm = &bench_meshes[k];
        int lv, c;
        for (lv = 0; lv < BENCH_FE_LEVELS; lv++)
            for (c = 0; c < 2; c++) {
                fxl_pipeline_t p;
                uint32_t ntri = 0, tk = 0, depth = 0;
                fxl_status_t st = bench_fe_setup(&p, lv, bm->texgen);
                char *q = line;
                if (st == FXL_OK)
                    st = fxl_pipeline_set_vertex_cache(&p, c ? vcache : 0, c ? BENCH_FE_CACHE : 0u);
                if (st == FXL_OK) {
                    uintptr_t top;
                    fw_stack_paint();
                    top = fw_stack_sp();
                    t0 = ticks_now();
                    st = fxl_pipeline_emit(&p, &bm->mesh, bench_fe_sink, &ntri, 0);
                    tk = ticks_since(t0);
                    depth = (uint32_t)(top - fw_stack_low());
                }
                put_fe_run(&q, "fe ", bm->name, lv, c);
                put_u32(&q, tk);
                put_str(&q, st == FXL_OK ? " ok\n" : " error\n");
                put_fe_run(&q, "stack fe ", bm->name, lv, c);
                put_u32(&q, depth);
                put_str(&q, "\n");
                *q = 0;
                fw_write(line);
                bad |= st != FXL_OK;
            }
    }
    return bad;
}
