/* bench_fw.h - what the benchmark firmware's start-up provides: the shared
 * mps2-an386 start-up in examples/common/. */
#ifndef FXL_BENCH_FW_H
#define FXL_BENCH_FW_H
#include "../examples/common/mps2.h"
#define fw_write fw_semihost_write0
#define fw_exit fw_semihost_exit
#endif
