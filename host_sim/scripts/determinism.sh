#!/usr/bin/env bash
# determinism.sh - the gallery CRCs must be bit-identical across builds.
#
# Renders the list in determinism/det_entries.h (every gallery scene x 9 draw
# variants, then every pipeline scene, the gallery's p_*, x 4 variants drawn
# from object-space meshes by the fixed-point front end, 320x240) with the
# core built by: gcc -O0, -O2 and -Os (-Os with the Cortex-M0+'s arithmetic,
# with FXL__DIV32_HW and FXL__GW_SWAP 0, and with
# FXL_SMALL_DIV64_HW too), gcc -O2 with
# the Cortex-M0+ arithmetic (FXL__MUL_HALVES, FXL__DIV_TABLE, FXL__DIV64_RECIP), gcc -O2
# with specialised code left out (FXL_FAST_POINT/SWAPPED/MIP 0), clang -O2 (when
# clang exists), arm-none-eabi-gcc -O2 for Cortex-M4 and -O2 and -Os for Cortex-M0+ run on
# qemu-system-arm -M mps2-an386 with semihosting (when both exist; the
# -Os one also with FXL_DIV_TABLE),
# riscv64-unknown-elf-gcc for RV32IMAC (-O2, -Os, and with Zbb), RV32I, RV32E
# and RV64IMAC run on qemu-system-riscv32/64 -M virt (when both exist), and
# compares each list
# with the one tests/test_determinism wrote (when it has run). Vertex data,
# meshes, front-end parameters (fixed point) and textures are generated once
# on the host (determinism/gen_data.c), so every build renders the same
# input. The front-end frames that are gallery images must also carry the
# gallery's golden CRC (tests/golden/gallery_crc.txt).
#   FXL_BUILD_DIR  a configured host build with lib/libfixel_host.a (default build)
#   FXL_DET_OUT    work folder (default $FXL_BUILD_DIR/determinism)
# Exit 0 when all lists agree, 1 on a mismatch or a failed build/run.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
bdir="${FXL_BUILD_DIR:-build}"
out="${FXL_DET_OUT:-$bdir/determinism}"
mkdir -p "$out"
lib="$bdir/lib"
if [ ! -f "$lib/libfixel_host.a" ] || [ ! -f "$lib/libfixel.a" ]; then
    echo "determinism.sh: $lib/libfixel_host.a missing; build first (make)" >&2
    exit 1
fi
warn="-Wall -Wextra -Wpedantic -Werror"
# shellcheck source=host_sim/scripts/bare_metal.sh
. "$root/host_sim/scripts/bare_metal.sh"
inc="-I$root/include -I$root/src -I$root/determinism -I$out"
core=$(ls "$root"/src/*.c)

echo "== generating vertex data and textures on the host"
cc=${CC:-gcc}
"$cc" -std=c99 -O2 -D_POSIX_C_SOURCE=200809L -I"$root/include" -I"$root/host_sim/lib" \
    "$root/determinism/gen_data.c" "$lib/libfixel_host.a" "$lib/libfixel.a" \
    $( [ -f "$lib/libfixel_port.a" ] && echo "$lib/libfixel_port.a" ) -lpng -lm -o "$out/gen_data"
"$out/gen_data" "$out/det_data.h" "$root/tests/golden/gallery_crc.txt" "$out/det_golden.txt"

lists=()
run_host() {   # name compiler flags...
    local name=$1 comp=$2
    shift 2
    echo "== $name: $comp $*"
    # shellcheck disable=SC2086
    "$comp" -std=c99 "$@" $warn -DDET_HOST $inc "$root/determinism/det_main.c" $core -o "$out/det_$name"
    "$out/det_$name" > "$out/$name.txt"
    lists+=("$name")
}

run_host gcc-O0 gcc -O0
run_host gcc-O2 gcc -O2
# -Os selects the size-optimised code: the generic span walk instead of the
# specialised ones, fixel's own 64-bit division (FXL_SMALL_DIV64); with the
# 32-bit steps of cores that divide in hardware (FXL__DIV32_HW), as a
# Cortex-M4 or RV32IMAC -Os firmware has them, and the generic walk's
# copied correction point (FXL__GW_SWAP 0, span.c) of Thumb-2 cores
run_host gcc-Os gcc -Os -DFXL__DIV32_HW=1 -DFXL__GW_SWAP=0
# and with FXL_SMALL_DIV64_HW (config.h): set-up's 32-bit divisors by
# fxl__udiv64_by32, its gradients with one division, as such a build has them
run_host gcc-Os-hwdiv gcc -Os -DFXL__DIV32_HW=1 -DFXL__GW_SWAP=0 -DFXL_SMALL_DIV64_HW=1
# and as a Cortex-M0+ -Os build has them: every step through the division
# loop, in one word below 2^32 (fixed.c), 32 x 32-bit products from halves
# out of line (FXL__MUL_HALVES_CALL, div64.h)
run_host gcc-Os-m0 gcc -Os -DFXL__MUL_HALVES_CALL=1
# the arithmetic of 32-bit cores without UMULL or UDIV (Cortex-M0+ at -O2):
# products from 16-bit halves, the table-started reciprocal, set-up's
# division by a reciprocal, and the 32-bit word forms of the roundings
# (FXL__WORD32), on the host (the M0+ image on qemu below runs them too, as
# Thumb-1 code)
run_host gcc-O2-m0arith gcc -O2 -DFXL__MUL_HALVES=1 -DFXL__DIV_TABLE=1 -DFXL__DIV64_RECIP=1 -DFXL__WORD32=1
# Specialised code left out (config.h, FXL_FAST_*): point and two-level draws
# take the generic walk at -O2, bilinear ones keep theirs; the same pixels.
run_host gcc-O2-subset gcc -O2 -DFXL_FAST_POINT=0 -DFXL_FAST_SWAPPED=0 -DFXL_FAST_MIP=0
if command -v clang >/dev/null 2>&1; then
    run_host clang-O2 clang -O2
else
    echo "== clang-O2: clang not found (apt-get install clang); skipped"
fi

# One bare-metal build run on qemu-system-arm -M mps2-an386 (a Cortex-M4),
# with semihosting for the output. A failed run leaves an incomplete list,
# which the comparison reports.
run_arm() {   # name cpu [opt]
    local name=$1 cpu=$2 opt=${3:--O2}
    echo "== $name: arm-none-eabi-gcc -mcpu=$cpu $opt on qemu-system-arm -M mps2-an386"
    # shellcheck disable=SC2086
    arm-none-eabi-gcc -std=c99 -ffreestanding -nostdlib $opt $warn -mcpu="$cpu" -mthumb \
        -mfloat-abi=soft -ffunction-sections -fdata-sections $inc \
        -T "$root/examples/common/mps2_an386.ld" -Wl,--gc-sections \
        "$root/examples/common/mps2_startup.c" "$root/determinism/det_main.c" $core -lgcc -o "$out/det_$name.elf"
    fxl_semihosted "$out/$name.txt" 900 qemu-system-arm -M mps2-an386 -cpu cortex-m4 -kernel "$out/det_$name.elf" ||
        echo "determinism.sh: the $cpu run failed (exit $?)" >&2
    lists+=("$name")
}

if command -v arm-none-eabi-gcc >/dev/null 2>&1 && command -v qemu-system-arm >/dev/null 2>&1; then
    run_arm m4-O2 cortex-m4
    # Cortex-M0+ code (Thumb-1: the masks form of the texel index, the M0
    # arithmetic, rowc_run's plain loop) on the same machine: ARMv6-M code
    # runs unchanged on the M4's ARMv7-M, and the micro:bit model has too
    # little RAM for a 320x240 frame.
    run_arm m0plus-O2 cortex-m0plus
    # and its size build: the generic walk with swapped correction points,
    # gpxN steps and the one-word division loop (span.c, fixed.c)
    run_arm m0plus-Os cortex-m0plus -Os
    # and that size build with the table-started reciprocal (FXL_DIV_TABLE,
    # config.h: off at -Os by default, public for firmware that trades
    # 558 B for ~7% fewer instructions)
    run_arm m0plus-Os-table cortex-m0plus "-Os -DFXL_DIV_TABLE=1"
else
    echo "== m4-O2: needs arm-none-eabi-gcc and qemu-system-arm (apt-get install gcc-arm-none-eabi" \
         "libnewlib-arm-none-eabi qemu-system-arm); skipped"
fi

# RISC-V: bare-metal builds run on qemu-system-riscv32/64 -M virt -bios none
# with semihosting (examples/common/virt_rv_startup.c), the same output.
run_riscv() {   # name xlen march mabi opt [libgcc-march qemu-cpu]
    local name=$1 xlen=$2 march=$3 mabi=$4 opt=$5 libmarch=${6:-} cpu=${7:-}
    local cpuopt=()
    echo "== $name: riscv64-unknown-elf-gcc -march=$march -mabi=$mabi $opt on qemu-system-riscv$xlen -M virt${cpu:+ -cpu $cpu}"
    [ -n "$cpu" ] && cpuopt=(-cpu "$cpu")
    # shellcheck disable=SC2086
    fxl_rv_link "$out/det_$name.elf" "$march" "$mabi" "$opt" "$libmarch" $inc "$root/determinism/det_main.c" $core
    fxl_semihosted "$out/$name.txt" 900 "qemu-system-riscv$xlen" -M virt "${cpuopt[@]}" -bios none \
        -kernel "$out/det_$name.elf" || echo "determinism.sh: the $march $opt run failed (exit $?)" >&2
    lists+=("$name")
}

if command -v riscv64-unknown-elf-gcc >/dev/null 2>&1 && command -v qemu-system-riscv32 >/dev/null 2>&1 &&
    command -v qemu-system-riscv64 >/dev/null 2>&1; then
    # RV32IMAC: the common microcontroller core (multiply and divide, no
    # CLZ: the soft CLZ and libgcc's 64-bit divisions)
    run_riscv rv32imac-O2 32 rv32imac ilp32 -O2
    # the size-optimised code: generic walk, fixel's own 64-bit division
    run_riscv rv32imac-Os 32 rv32imac ilp32 -Os
    # RV32I: no multiply instruction at all (every product through libgcc)
    run_riscv rv32i-O2 32 rv32i ilp32 -O2
    # RV32E (16 registers, the ilp32e ABI), as on the smallest parts
    run_riscv rv32emc-O2 32 rv32emc ilp32e -O2
    # a 64-bit core that is neither x86-64 nor AArch64: the 64-bit paths
    # without their CLZ builtins
    run_riscv rv64imac-O2 64 rv64imac lp64 -O2
    # Zbb (bit manipulation): CLZ and CTZ instructions instead of the
    # binary search
    run_riscv rv32imac_zbb-O2 32 rv32imac_zbb ilp32 -O2 rv32imac rv32,zbb=true
else
    echo "== rv32imac-O2: needs riscv64-unknown-elf-gcc and qemu-system-riscv32/64 (apt-get install" \
         "gcc-riscv64-unknown-elf qemu-system-misc); skipped"
fi

ctest_list="$bdir/tests/output/determinism_crcs.txt"
if [ -f "$ctest_list" ]; then
    cp "$ctest_list" "$out/ctest.txt"
    lists+=("ctest")
fi

status=0
ref="$out/gcc-O2.txt"
frames=$(grep -v -c -e '^done$' -e '^stress' "$ref")
stress=$(grep -c '^stress' "$ref" || true)
echo
echo "== comparison against gcc-O2 ($frames frames, $stress lines of stress cases)"
for name in "${lists[@]}"; do
    f="$out/$name.txt"
    if [ ! -s "$f" ] || ! grep -q '^done$' "$f"; then
        echo "  $name: incomplete output"
        status=1
    elif cmp -s "$ref" "$f"; then
        echo "  $name: identical"
    else
        echo "  $name: DIFFERS"
        diff "$ref" "$f" | head -20
        status=1
    fi
done
# gen_data wrote the golden CRC of every front-end frame that is a gallery
# image (det_entries.h: golden keys) as the line det_main prints for it.
golden=$(grep -c . "$out/det_golden.txt" || true)
matched=0
while read -r want; do
    if grep -Fxq "$want" "$ref"; then
        matched=$((matched + 1))
    else
        echo "  golden: $want, but gcc-O2 printed: $(grep "^${want% FXL_OK *} " "$ref" || echo nothing)"
        status=1
    fi
done < "$out/det_golden.txt"
echo "== front-end frames with a gallery golden CRC: $matched of $golden equal it"
if [ "$golden" -eq 0 ]; then
    echo "determinism.sh: no front-end frame found in tests/golden/gallery_crc.txt" >&2
    status=1
fi
# Every frame must draw; stress cases fail on purpose (their lines count
# the FXL_OK ones and are compared above).
if grep -v -e '^done$' -e '^stress' "$ref" | grep -v ' FXL_OK ' >/dev/null; then
    echo "determinism.sh: some draws failed:" >&2
    grep -v -e '^done$' -e '^stress' "$ref" | grep -v ' FXL_OK ' >&2
    status=1
fi
exit $status
