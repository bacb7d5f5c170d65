/* mps2_startup.c - the bare-metal start-up shared by every firmware image
 * that runs on qemu's mps2-an386 (the example, bench/, determinism/):
 * vector table, .data copy and .bss clear, semihosting output and exit, and
 * the memcpy/memset the compiler may emit for struct copies (no libc here).
 * ARMv6-M builds (the benchmark's M0+ code) use it unchanged: the FPU enable
 * below is a plain store that the M4 model qemu runs them on accepts. */
#include <stddef.h>
#include <stdint.h>

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;
int main(void);

#include "mps2.h"
#include "fw_mem.h"
#include "fw_stack.h"
void Reset_Handler(void);
void Default_Handler(void);

/* ARM semihosting: operation in r0, argument block in r1, BKPT 0xAB. */
static int semihost(int op, void *arg)
{
    register int r0 __asm__("r0") = op;
    register void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void fw_semihost_write0(const char *s)
{
    (void)semihost(0x04, (void *)s); /* SYS_WRITE0 */
}

void fw_semihost_exit(int code)
{
    /* SYS_EXIT with ADP_Stopped_ApplicationExit (0x20026) and the code. */
    static uint32_t block[2];
    block[0] = 0x20026u;
    block[1] = (uint32_t)code;
    (void)semihost(0x20, block); /* SYS_EXIT_EXTENDED */
    /* Where that call is missing, SYS_EXIT, which on 32-bit ARM takes only
     * a reason: RunTimeErrorUnknown for a failure, so it cannot read as
     * success. */
    (void)semihost(0x18, (void *)(uintptr_t)(code ? 0x20023u : 0x20026u));
    for (;;) {
    }
}

void Reset_Handler(void)
{
    uint32_t *src = &_sidata, *dst = &_sdata;
    while (dst < &_edata) *dst++ = *src++;
    for (dst = &_sbss; dst < &_ebss; dst++) *dst = 0;
#if defined(__ARM_FP)
    /* Enable the FPU (CP10/CP11 full access): the hard-float ABI may touch
     * it. Only where there is one: on an ARMv6-M core CPACR is reserved. */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb");
#endif
    fw_semihost_exit(main());
}

void Default_Handler(void)
{
    fw_semihost_write0("fault\n");
    fw_semihost_exit(2);
}

/* Initial stack pointer, then the handlers (as addresses: ISO C has no
 * conversion between object and function pointers). */
__attribute__((section(".isr_vector"), used)) static const uintptr_t vectors[16] = {
    (uintptr_t)&_estack, (uintptr_t)Reset_Handler, (uintptr_t)Default_Handler,
    (uintptr_t)Default_Handler, (uintptr_t)Default_Handler, (uintptr_t)Default_Handler,
    (uintptr_t)Default_Handler, 0, 0, 0, 0, (uintptr_t)Default_Handler,
    (uintptr_t)Default_Handler, 0, (uintptr_t)Default_Handler, (uintptr_t)Default_Handler,
};
