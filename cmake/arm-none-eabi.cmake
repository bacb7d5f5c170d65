# cmake/arm-none-eabi.cmake - toolchain file for bare-metal Cortex-M builds.
#
#   cmake -S . -B build-fw-m4 -DCMAKE_TOOLCHAIN_FILE=cmake/arm-none-eabi.cmake \
#         -DFXL_CPU=cortex-m4 -DFXL_BUILD_HOST=OFF
#
# FXL_CPU selects -mcpu and the float ABI (table below); default cortex-m0plus,
# the most restrictive core we support (no divider, no clz, Thumb-1 only), so
# a default cross build exposes every libgcc helper the core pulls in.
# FXL_ARM_TOOLCHAIN_DIR (cache or environment) points at a toolchain's bin/
# directory when arm-none-eabi-gcc is not on PATH.
#
# CMake reads this file once per language and again inside every try_compile,
# so it only sets variables and never caches flags of its own.

set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

# The compiler checks cannot link a program without a board's startup code and
# linker script, so they build a static library instead.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
# Hand these to the try_compile projects, which re-read this file.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES FXL_CPU FXL_ARM_TOOLCHAIN_DIR)

if(NOT FXL_CPU)
  set(FXL_CPU cortex-m0plus)
endif()
if(NOT FXL_ARM_TOOLCHAIN_DIR AND DEFINED ENV{FXL_ARM_TOOLCHAIN_DIR})
  set(FXL_ARM_TOOLCHAIN_DIR "$ENV{FXL_ARM_TOOLCHAIN_DIR}")
endif()

set(_fxl_prefix arm-none-eabi-)
if(FXL_ARM_TOOLCHAIN_DIR)
  set(_fxl_prefix "${FXL_ARM_TOOLCHAIN_DIR}/arm-none-eabi-")
endif()

include("${CMAKE_CURRENT_LIST_DIR}/fxl_cross_tools.cmake")

# CPU -> code generation flags. Cores without an FPU use the soft-float ABI;
# the M4/M7 FPUs are single/double precision and use the hard-float ABI.
if(FXL_CPU STREQUAL "cortex-m0" OR FXL_CPU STREQUAL "cortex-m0plus"
   OR FXL_CPU STREQUAL "cortex-m3")
  set(_fxl_cpu_flags "-mcpu=${FXL_CPU} -mthumb -mfloat-abi=soft")
elseif(FXL_CPU STREQUAL "cortex-m4")
  set(_fxl_cpu_flags "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
elseif(FXL_CPU STREQUAL "cortex-m7")
  set(_fxl_cpu_flags "-mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard")
else()
  message(FATAL_ERROR "FXL_CPU='${FXL_CPU}' is not known to cmake/arm-none-eabi.cmake "
                      "(use cortex-m0, cortex-m0plus, cortex-m3, cortex-m4 or cortex-m7)")
endif()

# -Os for every build type; -ffreestanding is added per target (fixel,
# fixel_port) by the project, so firmware examples may still use newlib.
# Sections let the linker drop unused functions of the static libraries.
set(CMAKE_C_FLAGS_INIT   "${_fxl_cpu_flags} -Os -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "${_fxl_cpu_flags} -Os -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "${_fxl_cpu_flags}")
# For firmware executables (examples/): newlib-nano without OS stubs' syscalls.
set(CMAKE_EXE_LINKER_FLAGS_INIT "--specs=nano.specs --specs=nosys.specs -Wl,--gc-sections")
