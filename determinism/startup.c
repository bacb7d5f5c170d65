/* startup.c - minimal Cortex-M4 start-up for qemu-system-arm -M mps2-an386:
 * vector table, .data copy and .bss clear, semihosting output and exit.
 * Semihosting (ARM DUI 0471): operation number in r0, argument block in r1,
 * then BKPT 0xAB; SYS_WRITE0 = 0x04, SYS_EXIT = 0x18 with
 * ADP_Stopped_ApplicationExit (0x20026) and, for SYS_EXIT_EXTENDED = 0x20, a
 * block {reason, code} so the exit status reaches the host.
 */
#include <stdint.h>

extern uint32_t __data_load, __data_start, __data_end, __bss_start, __bss_end, __stack_top;
int main(void);
void det_semihost_write0(const char *s);
void det_semihost_exit(int code);
void det_reset(void);
void det_fault(void);

static int semihost(int op, void *arg)
{
    register int r0 __asm__("r0") = op;
    register void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void det_semihost_write0(const char *s)
{
    (void)semihost(0x04, (void *)s);
}

void det_semihost_exit(int code)
{
    uint32_t block[2];
    block[0] = 0x20026u;   /* ADP_Stopped_ApplicationExit */
    block[1] = (uint32_t)code;
    (void)semihost(0x20, block);
    for (;;)
        ;
}

void det_fault(void)
{
    det_semihost_write0("det: fault\n");
    det_semihost_exit(3);
}

void det_reset(void)
{
    uint32_t *s = &__data_load, *d = &__data_start;
    /* Enable the FPU (CPACR CP10/CP11 full access) in case the compiler
     * uses it for anything; the core itself is integer-only. */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    while (d < &__data_end)
        *d++ = *s++;
    for (d = &__bss_start; d < &__bss_end;)
        *d++ = 0;
    det_semihost_exit(main());
}

/* Initial stack pointer, reset, NMI, HardFault, MemManage, BusFault,
 * UsageFault, 4 reserved, SVC, DebugMon, reserved, PendSV, SysTick. As
 * integers: ISO C has no conversion between object and function pointers. */
__attribute__((section(".vectors"), used)) static const uintptr_t vectors[16] = {
    (uintptr_t)&__stack_top, (uintptr_t)det_reset, (uintptr_t)det_fault, (uintptr_t)det_fault,
    (uintptr_t)det_fault, (uintptr_t)det_fault, (uintptr_t)det_fault, 0, 0, 0, 0,
    (uintptr_t)det_fault, (uintptr_t)det_fault, 0, (uintptr_t)det_fault, (uintptr_t)det_fault};
