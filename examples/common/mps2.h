/* mps2.h - what the shared bare-metal start-up (mps2_startup.c) gives the
 * firmware images that run on qemu-system-arm -M mps2-an386: the example,
 * the benchmark firmware (bench/) and the determinism check (determinism/).
 * main() returns the exit status; output goes through semihosting.
 * virt_rv_startup.c gives the same two calls on qemu-system-riscv32/64
 * -M virt (the benchmark and determinism images for RISC-V). */
#ifndef FXL_EXAMPLES_MPS2_H
#define FXL_EXAMPLES_MPS2_H

/* SYS_WRITE0: a NUL-terminated string to the host's console. */
void fw_semihost_write0(const char *s);
/* SYS_EXIT_EXTENDED with the status; never returns. */
void fw_semihost_exit(int code);

/* Stack high-water marks (fw_stack.h): the depth a call used is
 * fw_stack_sp() before it, after fw_stack_paint(), minus fw_stack_low()
 * after it (0 from fw_stack_low: deeper than the painted window). */
#include <stdint.h>
void fw_stack_paint(void);
uintptr_t fw_stack_sp(void);
uintptr_t fw_stack_low(void);

#endif
