# cmake/fxl_cross_tools.cmake - the part the toolchain files share: the
# compilers and binutils of one GCC prefix (_fxl_prefix, set by the caller:
# "arm-none-eabi-" or a directory and prefix), and cross-compiling lookups.
# Included by cmake/arm-none-eabi.cmake and cmake/riscv64-unknown-elf.cmake.

set(CMAKE_C_COMPILER   "${_fxl_prefix}gcc")
set(CMAKE_CXX_COMPILER "${_fxl_prefix}g++")
set(CMAKE_ASM_COMPILER "${_fxl_prefix}gcc")
# Full paths for the binutils so CMake and our targets agree on which to use.
find_program(CMAKE_AR      "${_fxl_prefix}ar")
find_program(CMAKE_RANLIB  "${_fxl_prefix}ranlib")
find_program(CMAKE_OBJCOPY "${_fxl_prefix}objcopy")
find_program(CMAKE_OBJDUMP "${_fxl_prefix}objdump")
find_program(CMAKE_NM      "${_fxl_prefix}nm")
find_program(CMAKE_SIZE    "${_fxl_prefix}size")

# Never pick up host libraries or headers; programs (code generators) are
# still found on the host.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
