#!/bin/sh
# elf_report.sh - print a firmware ELF's flash and RAM, and fail when it
# contains floating point (the examples promise integer-only firmware).
#   elf_report.sh <elf> [size] [objdump] [nm]
# Flash = .text + .data (initial values are stored in flash), RAM = .data +
# .bss (the stack grows down from the top of RAM and is not counted).
set -eu
elf=$1
size=${2:-arm-none-eabi-size}
objdump=${3:-arm-none-eabi-objdump}
nm=${4:-arm-none-eabi-nm}

echo "---- $(basename "$elf"): arm-none-eabi-size"
"$size" "$elf"
"$size" "$elf" | awk 'NR == 2 {
    printf "---- flash %d B (text %d + data %d), RAM %d B (data %d + bss %d)\n",
           $1 + $2, $1, $2, $2 + $3, $2, $3 }'

# Floating-point arithmetic: VFP data-processing and conversion instructions
# (vadd.f32, vmul, vdiv, vsqrt, vcvt, vcmp, ...) and the soft-float helpers
# (__aeabi_f*, __aeabi_d*, libgcc __*sf* / __*df*). Plain VFP loads, stores
# and moves (vldr, vstr, vmov, vpush, vpop) are not counted: under the
# hard-float ABI gcc may use the FPU registers as spill space for 64-bit
# integers, which computes nothing in floating point.
dis=$("$objdump" -d "$elf")
fp_insns=$(printf '%s\n' "$dis" | awk -F '\t' 'NF >= 3 && $3 ~ /^v(add|sub|mul|nmul|div|fma|fms|fnm|neg|abs|sqrt|cvt|cmp|max|min|rint|sel)/ { n++ } END { print n + 0 }')
vfp_moves=$(printf '%s\n' "$dis" | awk -F '\t' 'NF >= 3 && $3 ~ /^v(ldr|str|ldm|stm|mov|push|pop)/ { n++ } END { print n + 0 }')
fp_syms=$("$nm" "$elf" | awk '$3 ~ /^__aeabi_[fd]|^__(add|sub|mul|div|float|fix|extend|trunc|cmp|eq|ne|lt|le|gt|ge|un)[a-z]*[sd]f/ { print $3 }')
if [ "$fp_insns" -ne 0 ] || [ -n "$fp_syms" ]; then
    echo "elf_report.sh: $elf computes in floating point: $fp_insns FP instructions;" \
         "helpers: $fp_syms" >&2
    exit 1
fi
echo "---- no floating point: 0 FP arithmetic instructions, no soft-float helpers" \
     "($vfp_moves VFP register loads/stores/moves of integer data)"
