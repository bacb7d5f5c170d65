/* virt_rv_startup.c - the bare-metal start-up for images that run on
 * qemu-system-riscv32/64 -M virt -bios none (determinism/, bench/ and the
 * band example in firmware.sh): stack and global pointer, a trap handler,
 * .bss clear, semihosting output and exit, and the memcpy/memset the
 * compiler may emit (no libc here).
 * It offers the same two calls as mps2_startup.c (mps2.h), so a program
 * written against them runs on either. */
#include <stddef.h>
#include <stdint.h>
#include "mps2.h"
#include "fw_mem.h"
#include "fw_stack.h"

extern uint32_t _sbss, _ebss;
int main(void);
void fw_rv_reset(void);

/* _start: gp with relaxation off (it must not be addressed through itself),
 * the stack at the top of RAM (16-byte aligned, as the ABI wants), then C. */
__asm__(".section .text.start, \"ax\"\n"
        ".globl _start\n"
        "_start:\n"
        ".option push\n"
        ".option norelax\n"
        "    la gp, __global_pointer$\n"
        ".option pop\n"
        "    la sp, _estack\n"
        "    andi sp, sp, -16\n"
        "    call fw_rv_reset\n"
        "1:  j 1b\n"
        ".text\n");

/* RISC-V semihosting: operation in a0, argument in a1, and EBREAK between
 * the two marker instructions (slli x0, x0, 0x1f before, srai x0, x0, 7
 * after), all three uncompressed and in one 16-byte block (never across a
 * page) so qemu recognises them. A function of its own, so the C compiler
 * and linker relaxation cannot move code around the sequence. */
long fw_rv_semihost(long op, void *arg);
__asm__(".section .text.semihost, \"ax\"\n"
        ".balign 16\n"
        ".globl fw_rv_semihost\n"
        "fw_rv_semihost:\n"
        ".option push\n"
        ".option norvc\n"
        "    slli x0, x0, 0x1f\n"
        "    ebreak\n"
        "    srai x0, x0, 7\n"
        ".option pop\n"
        "    ret\n"
        ".text\n");

void fw_semihost_write0(const char *s)
{
    (void)fw_rv_semihost(0x04, (void *)s); /* SYS_WRITE0 */
}

void fw_semihost_exit(int code)
{
    /* SYS_EXIT_EXTENDED: the reason ADP_Stopped_ApplicationExit and the
     * code, in words of the target's width */
    static uintptr_t block[2];
    block[0] = 0x20026u;
    block[1] = (uintptr_t)(unsigned)code;
    (void)fw_rv_semihost(0x20, block);
    /* Where that call is missing, SYS_EXIT: on RV64 it reads the same
     * block; on RV32 it takes only a reason, so a failure must say
     * RunTimeErrorUnknown (0x20023), not ApplicationExit (exit 0). */
#if UINTPTR_MAX > 0xFFFFFFFFu
    (void)fw_rv_semihost(0x18, block);
#else
    (void)fw_rv_semihost(0x18, (void *)(uintptr_t)(code ? 0x20023u : 0x20026u));
#endif
    for (;;) {
    }
}

static unsigned long read_mcause(void)
{
    unsigned long v;
    __asm__ volatile(".option push\n\t.option arch, +zicsr\n\tcsrr %0, mcause\n\t.option pop" : "=r"(v));
    return v;
}

static unsigned long read_mepc(void)
{
    unsigned long v;
    __asm__ volatile(".option push\n\t.option arch, +zicsr\n\tcsrr %0, mepc\n\t.option pop" : "=r"(v));
    return v;
}

static void put_hex(char *p, unsigned long v)
{
    int i;
    for (i = (int)sizeof v * 2 - 1; i >= 0; i--)
        *p++ = "0123456789abcdef"[(v >> (4 * i)) & 15u];
    *p = 0;
}

/* Every trap (an illegal instruction, a faulting or misaligned access) ends
 * the run with status 2 and its cause, as mps2_startup.c's Default_Handler
 * does: without it the core would jump to address 0 and fault there until
 * the caller's timeout. mtvec's direct mode wants it 4-byte aligned. */
void fw_rv_trap(void) __attribute__((aligned(4), noreturn));
void fw_rv_trap(void)
{
    char hex[2 * sizeof(unsigned long) + 1];
    fw_semihost_write0("fault: mcause 0x");
    put_hex(hex, read_mcause());
    fw_semihost_write0(hex);
    fw_semihost_write0(" mepc 0x");
    put_hex(hex, read_mepc());
    fw_semihost_write0(hex);
    fw_semihost_write0("\n");
    fw_semihost_exit(2);
    for (;;) {
    }
}

void fw_rv_reset(void)
{
    uint32_t *p;
    const uintptr_t trap = (uintptr_t)fw_rv_trap;
    __asm__ volatile(".option push\n\t.option arch, +zicsr\n\tcsrw mtvec, %0\n\t.option pop" : : "r"(trap));
    for (p = &_sbss; p < &_ebss; p++) *p = 0;
    fw_semihost_exit(main());
}
