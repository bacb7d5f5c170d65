/* bench_fw.h - what the benchmark firmware's start-up provides. */
#ifndef FXL_BENCH_FW_H
#define FXL_BENCH_FW_H
void fw_write(const char *s);
void fw_exit(int code);
#endif
