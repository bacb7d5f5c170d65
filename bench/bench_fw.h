/* bench_fw.h - what the benchmark firmware's start-up provides: the shared
 * start-up in examples/common/ (mps2_startup.c for the Cortex-M builds,
 * virt_rv_startup.c for RISC-V; both declared in mps2.h). */
#ifndef FXL_BENCH_FW_H
#define FXL_BENCH_FW_H
#include "../examples/common/mps2.h"
#define fw_write fw_semihost_write0
#define fw_exit fw_semihost_exit
#endif
