# cmake/riscv64-unknown-elf.cmake - toolchain file for bare-metal RISC-V builds
# with Debian's riscv64-unknown-elf-gcc (it targets RV32 and RV64 alike).
#
#   cmake -S . -B build-fw-rv32imac -DCMAKE_TOOLCHAIN_FILE=cmake/riscv64-unknown-elf.cmake \
#         -DFXL_CPU=rv32imac -DFXL_BUILD_HOST=OFF
#
# FXL_CPU is the -march string (default rv32imac: multiply and divide,
# compressed instructions, no CLZ - the common microcontroller core).
# FXL_RISCV_ABI is the -mabi; by default ilp32e for RV32E, ilp32 for other
# RV32 and lp64 for RV64 (set ilp32f/lp64d yourself for a hard-float ABI;
# the core uses no floating point either way). FXL_RISCV_TOOLCHAIN_DIR
# (cache or environment) points at a toolchain's bin/ directory when the
# compiler is not on PATH; FXL_RISCV_PREFIX changes the prefix (e.g.
# riscv-none-elf- for xPack builds).
#
# Like cmake/arm-none-eabi.cmake this file is read once per language and in
# every try_compile, so it only sets variables.

set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv)

# No board start-up or linker script here: the compiler checks build a
# static library instead of linking a program.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES FXL_CPU FXL_RISCV_ABI FXL_RISCV_TOOLCHAIN_DIR FXL_RISCV_PREFIX)

if(NOT FXL_CPU)
  set(FXL_CPU rv32imac)
endif()
if(NOT FXL_CPU MATCHES "^rv(32|64)[a-z]")
  message(FATAL_ERROR "FXL_CPU='${FXL_CPU}' is not a RISC-V -march string "
                      "(cmake/riscv64-unknown-elf.cmake: e.g. rv32imac, rv32emc, rv64imac)")
endif()
if(NOT FXL_RISCV_ABI)
  if(FXL_CPU MATCHES "^rv32e")
    set(FXL_RISCV_ABI ilp32e)
  elseif(FXL_CPU MATCHES "^rv32")
    set(FXL_RISCV_ABI ilp32)
  else()
    set(FXL_RISCV_ABI lp64)
  endif()
endif()
if(NOT FXL_RISCV_TOOLCHAIN_DIR AND DEFINED ENV{FXL_RISCV_TOOLCHAIN_DIR})
  set(FXL_RISCV_TOOLCHAIN_DIR "$ENV{FXL_RISCV_TOOLCHAIN_DIR}")
endif()
if(NOT FXL_RISCV_PREFIX)
  set(FXL_RISCV_PREFIX riscv64-unknown-elf-)
endif()

set(_fxl_prefix "${FXL_RISCV_PREFIX}")
if(FXL_RISCV_TOOLCHAIN_DIR)
  set(_fxl_prefix "${FXL_RISCV_TOOLCHAIN_DIR}/${FXL_RISCV_PREFIX}")
endif()

include("${CMAKE_CURRENT_LIST_DIR}/fxl_cross_tools.cmake")

# medany: code and data may live anywhere (flash at 0x0, 0x08000000 or
# 0x20000000 on common parts, RAM elsewhere), not only in the low or high
# 2 GB that the default medlow model reaches.
set(_fxl_cpu_flags "-march=${FXL_CPU} -mabi=${FXL_RISCV_ABI} -mcmodel=medany")
set(CMAKE_C_FLAGS_INIT   "${_fxl_cpu_flags} -Os -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "${_fxl_cpu_flags} -Os -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "${_fxl_cpu_flags}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-Wl,--gc-sections")
