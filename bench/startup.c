/* startup.c - bare-metal start-up for the benchmark firmware on qemu's
 * mps2-an386 (the Cortex-M0+ build runs there too: ARMv6-M code executes
 * unchanged on the M4 model, and an instruction count is a property of the
 * code, not of the core that runs it).
 *
 * Vector table, .data copy, .bss clear, semihosting output and exit, and the
 * memcpy/memset that the compiler may emit for struct copies (no libc). */
#include <stddef.h>
#include <stdint.h>

#include "bench_fw.h"

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;
int main(void);

void *memcpy(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);
void Reset_Handler(void);
void Default_Handler(void);

void *memcpy(void *dst, const void *src, size_t n)
{
    uint8_t *d = (uint8_t *)dst;
    const uint8_t *s = (const uint8_t *)src;
    while (n--)
        *d++ = *s++;
    return dst;
}

void *memset(void *dst, int c, size_t n)
{
    uint8_t *d = (uint8_t *)dst;
    while (n--)
        *d++ = (uint8_t)c;
    return dst;
}

/* ARM semihosting: operation in r0, parameter block in r1, then BKPT 0xAB
 * (the Thumb-only M profile uses BKPT, not SVC). */
static int semihost(int op, void *arg)
{
    register int r0 __asm__("r0") = op;
    register void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void fw_write(const char *s)
{
    (void)semihost(0x04, (void *)(uintptr_t)s); /* SYS_WRITE0 */
}

void fw_exit(int code)
{
    /* SYS_EXIT_EXTENDED carries the exit code; SYS_EXIT as a fallback. */
    static uint32_t block[2];
    block[0] = 0x20026u; /* ADP_Stopped_ApplicationExit */
    block[1] = (uint32_t)code;
    (void)semihost(0x20, block);
    (void)semihost(0x18, (void *)(uintptr_t)0x20026u);
    for (;;) {
    }
}

void Reset_Handler(void)
{
    uint32_t *src = &_sidata, *dst = &_sdata;
    while (dst < &_edata)
        *dst++ = *src++;
    for (dst = &_sbss; dst < &_ebss; dst++)
        *dst = 0;
    fw_exit(main());
}

void Default_Handler(void)
{
    fw_write("fault\n");
    fw_exit(2);
}

/* Stack pointer, then handlers stored as addresses (ISO C has no conversion
 * between object and function pointers). */
__attribute__((section(".isr_vector"), used)) static const uintptr_t vectors[16] = {
    (uintptr_t)&_estack,        (uintptr_t)Reset_Handler,   (uintptr_t)Default_Handler,
    (uintptr_t)Default_Handler, (uintptr_t)Default_Handler, (uintptr_t)Default_Handler,
    (uintptr_t)Default_Handler, 0, 0, 0, 0, (uintptr_t)Default_Handler, (uintptr_t)Default_Handler,
    0, (uintptr_t)Default_Handler, (uintptr_t)Default_Handler};
