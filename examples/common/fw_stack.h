/* fw_stack.h - stack high-water marks for the bare-metal images (the
 * firmware example, bench/): what a call really used, measured on the
 * core, beside the compiler's static bound (docs/porting.md, section 10).
 *
 * fw_stack_paint() fills the stack below the caller with a pattern, down
 * to FW_STACK_WINDOW bytes under the top of RAM (never into .bss);
 * fw_stack_low() is the lowest word written since, scanning up from the
 * window's bottom. A call's depth is fw_stack_sp() taken just before it
 * minus fw_stack_low() after it. The pattern may be written by chance
 * (a stored value that equals it), which can only make the figure smaller
 * by the words below that store. Where the window's bottom word was
 * written too, the window was not deep enough: fw_stack_low() returns 0,
 * so the depth comes out as the whole top address, not as a plausible
 * figure. fw_stack_paint's own saved registers lie below its caller's
 * stack pointer and read as used: 8 B (Cortex-M0+ -O2) to ~32 B.
 *
 * Definitions: include this from exactly one file of an image, its
 * start-up file (mps2_startup.c, virt_rv_startup.c); mps2.h declares
 * them. */
#ifndef FXL_EXAMPLES_FW_STACK_H
#define FXL_EXAMPLES_FW_STACK_H

#include <stdint.h>

#define FW_STACK_WINDOW 0x10000u          /* 64 KB under the top of RAM */
#define FW_STACK_PATTERN 0x5AC3E1F0u

extern uint32_t _ebss, _estack;

/* The stack pointer (the caller's frame is above it). */
uintptr_t fw_stack_sp(void) __attribute__((noinline));
uintptr_t fw_stack_sp(void)
{
    uintptr_t sp;
#if defined(__riscv)
    __asm__ volatile("mv %0, sp" : "=r"(sp));
#else
    __asm__ volatile("mov %0, sp" : "=r"(sp));
#endif
    return sp;
}

static uint32_t *fw_stack_window(void)
{
    const uintptr_t top = (uintptr_t)&_estack;
    uintptr_t lo = top - FW_STACK_WINDOW;
    if (lo < (uintptr_t)&_ebss)
        lo = ((uintptr_t)&_ebss + 3u) & ~(uintptr_t)3u;
    return (uint32_t *)lo;
}

void fw_stack_paint(void)
{
    uint32_t *p = fw_stack_window();
    const uintptr_t sp = fw_stack_sp();
    while ((uintptr_t)p < sp) *p++ = FW_STACK_PATTERN;
}

uintptr_t fw_stack_low(void)
{
    const uint32_t *const bottom = fw_stack_window();
    const uint32_t *p = bottom;
    while ((uintptr_t)p < (uintptr_t)&_estack && *p == FW_STACK_PATTERN) p++;
    return p == bottom ? 0u : (uintptr_t)p;
}

#endif
