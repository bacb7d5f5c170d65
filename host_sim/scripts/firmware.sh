#!/usr/bin/env bash
# firmware.sh - build the firmware example (examples/m4_band) if needed, run
# it on qemu-system-arm -M mps2-an386 (Cortex-M4) with semihosting, and
# compare the CRC of every frame's wire bytes with examples/expected_crc.txt
# (the host test tests/test_firmware_scene.c checks the same file). Where
# riscv64-unknown-elf-gcc and qemu-system-riscv32 exist, the same program
# is also built for RV32IMAC (-Os, examples/common/virt_rv_startup.c) and
# run on qemu-system-riscv32 -M virt against the same file: the band
# renderer, the panel driver and the front end on a second architecture.
#
#   host_sim/scripts/firmware.sh            build + run + compare; exit 0/1
#   host_sim/scripts/firmware.sh --update   rewrite examples/expected_crc.txt
#                                           from the Cortex-M4 run (after an
#                                           intended change of the output)
# Environment:
#   FXL_FW_BUILD_DIR  cross build directory (default build-fw-m4, the one
#                     `make firmware` uses; configured here when missing)
#   FXL_FW_ELF        use this ELF instead of building
#   FXL_FW_TIMEOUT    seconds for the qemu run (default 120)
# Each leg prints a "SKIP" line when its tools are missing (install:
# apt-get install gcc-arm-none-eabi qemu-system-arm; gcc-riscv64-unknown-elf
# qemu-system-misc).
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
expected=examples/expected_crc.txt
update=0
case "${1:-}" in
    --update) update=1 ;;
    "") ;;
    *) echo "usage: $0 [--update]" >&2; exit 2 ;;
esac

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
grep -v '^#' "$expected" | sed '/^[[:space:]]*$/d' > "$tmp/want.txt"

# check NAME OUT: the run's output OUT must end in "status ok" and carry
# exactly the expected CRCs. Returns 0/1.
check() {
    local name=$1 out=$2
    sed -n 's/^crc //p' "$out" > "$tmp/got.txt"
    if ! grep -q '^status ok' "$out"; then
        echo "firmware.sh: FAIL: $name: no 'status ok' (exit status above; 124 = timeout)" >&2
        return 1
    fi
    if diff -u "$tmp/want.txt" "$tmp/got.txt" > "$tmp/diff.txt"; then
        echo "firmware.sh: PASS: $name: $(wc -l < "$tmp/got.txt") CRCs on qemu equal $expected"
        return 0
    fi
    echo "firmware.sh: FAIL: $name: qemu CRCs differ from $expected (- expected, + qemu):" >&2
    cat "$tmp/diff.txt" >&2
    return 1
}

result=0

# run_leg NAME PACKAGES FUNCTION TOOL...: FUNCTION when every TOOL exists,
# else a SKIP line naming the Debian PACKAGES; a failure sets result.
run_leg() {
    local name=$1 pkgs=$2 fn=$3 t
    shift 3
    for t in "$@"; do
        if ! command -v "$t" >/dev/null 2>&1; then
            echo "firmware.sh: SKIP: $name: $t not found (apt-get install $pkgs)"
            return 0
        fi
    done
    "$fn" || result=1
}

# shellcheck source=host_sim/scripts/bare_metal.sh
. "$root/host_sim/scripts/bare_metal.sh"

# semihosted OUT QEMU ARGS...: fxl_semihosted with this script's timeout,
# and its status shown (FAIL when not 0).
semihosted() {
    local out=$1 qemu=$2 status=0
    shift 2
    fxl_semihosted "$out" "${FXL_FW_TIMEOUT:-120}" "$qemu" "$@" || status=$?
    echo "(exit status $status)"
    [ "$status" -eq 0 ] || echo "firmware.sh: FAIL: $qemu exited with status $status (124 = timeout)" >&2
    return $status
}

# ---- Cortex-M4 -----------------------------------------------------------------------
m4_leg() {
    elf=${FXL_FW_ELF:-}
    if [ -z "$elf" ]; then
        dir=${FXL_FW_BUILD_DIR:-build-fw-m4}
        if [ ! -f "$dir/CMakeCache.txt" ]; then
            env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL \
                cmake -S . -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/arm-none-eabi.cmake" \
                -DFXL_BUILD_HOST=OFF -DFXL_CPU=cortex-m4 -DCMAKE_BUILD_TYPE=MinSizeRel >/dev/null ||
                { echo "firmware.sh: FAIL: Cortex-M4: cmake configure failed" >&2; return 1; }
        fi
        # Builds the ELF and runs examples/elf_report.sh (size, no floating
        # point). `|| return`: set -e does not reach into a function called
        # from `||` (run_leg), and an old ELF must not pass for a new one.
        env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL \
            cmake --build "$dir" -j "${JOBS:-2}" --target m4_band_report ||
            { echo "firmware.sh: FAIL: Cortex-M4: the build or elf_report.sh failed" >&2; return 1; }
        elf=$dir/bin/m4_band.elf
    fi
    [ -f "$elf" ] || { echo "firmware.sh: $elf was not built" >&2; return 1; }

    local status=0
    semihosted "$tmp/out.txt" qemu-system-arm -M mps2-an386 -kernel "$elf" || status=$?
    cat "$tmp/out.txt"

    if [ "$update" -eq 1 ]; then
        if [ "$status" -ne 0 ] || ! grep -q '^status ok' "$tmp/out.txt"; then
            echo "firmware.sh: FAIL: the firmware exited with status $status; nothing written" >&2
            exit 1
        fi
        sed -n 's/^crc //p' "$tmp/out.txt" > "$tmp/got.txt"
        { grep '^#' "$expected"; cat "$tmp/got.txt"; } > "$tmp/new.txt"
        cp "$tmp/new.txt" "$expected"
        echo "firmware.sh: wrote $(wc -l < "$tmp/got.txt") CRCs to $expected;" \
             "now run tests/test_firmware_scene.c (ctest -R test_firmware_scene)"
        exit 0
    fi
    [ "$status" -eq 0 ] && check "Cortex-M4" "$tmp/out.txt"
}

run_leg "Cortex-M4" "gcc-arm-none-eabi qemu-system-arm" m4_leg arm-none-eabi-gcc qemu-system-arm

# ---- RV32IMAC ------------------------------------------------------------------------
# The same sources with the RISC-V start-up, built directly (the example's
# CMake target is the M4 board's), at -Os as `make firmware` builds the core.
rv_leg() {
    local c=examples/common elf_rv="$tmp/rv_band.elf"
    echo "== RV32IMAC -Os on qemu-system-riscv32 -M virt"
    fxl_rv_link "$elf_rv" rv32imac ilp32 -Os "" -Iinclude -Isrc -Iport \
        examples/m4_band/main.c "$c/fw_app.c" "$c/fw_scenes.c" src/*.c port/*.c ||
        { echo "firmware.sh: FAIL: RV32IMAC: the build failed" >&2; return 1; }
    semihosted "$tmp/out_rv.txt" qemu-system-riscv32 -M virt -bios none -kernel "$elf_rv" &&
        check "RV32IMAC" "$tmp/out_rv.txt"
}

run_leg "RV32IMAC" "gcc-riscv64-unknown-elf qemu-system-misc" rv_leg riscv64-unknown-elf-gcc qemu-system-riscv32
exit $result
