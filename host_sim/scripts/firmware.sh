#!/usr/bin/env bash
# firmware.sh - build the Cortex-M4 firmware example (examples/m4_band) if
# needed, run it on qemu-system-arm -M mps2-an386 with semihosting, and
# compare the CRC of every frame's wire bytes with examples/expected_crc.txt
# (the host test tests/test_firmware_scene.c checks the same file).
#
#   host_sim/scripts/firmware.sh            build + run + compare; exit 0/1
#   host_sim/scripts/firmware.sh --update   rewrite examples/expected_crc.txt
#                                           from the qemu run (after an
#                                           intended change of the output)
# Environment:
#   FXL_FW_BUILD_DIR  cross build directory (default build-fw-m4, the one
#                     `make firmware` uses; configured here when missing)
#   FXL_FW_ELF        use this ELF instead of building
#   FXL_FW_TIMEOUT    seconds for the qemu run (default 120)
# Exits 0 with a "SKIP" line when arm-none-eabi-gcc or qemu-system-arm is
# missing (install: apt-get install gcc-arm-none-eabi qemu-system-arm).
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

for tool in arm-none-eabi-gcc qemu-system-arm; do
    if ! command -v "$tool" >/dev/null 2>&1; then
        echo "firmware.sh: SKIP: $tool not found (apt-get install gcc-arm-none-eabi qemu-system-arm)"
        exit 0
    fi
done

elf=${FXL_FW_ELF:-}
if [ -z "$elf" ]; then
    dir=${FXL_FW_BUILD_DIR:-build-fw-m4}
    if [ ! -f "$dir/CMakeCache.txt" ]; then
        env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL \
            cmake -S . -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/arm-none-eabi.cmake" \
            -DFXL_BUILD_HOST=OFF -DFXL_CPU=cortex-m4 -DCMAKE_BUILD_TYPE=MinSizeRel >/dev/null
    fi
    # Builds the ELF and runs examples/elf_report.sh (size, no floating point).
    env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL \
        cmake --build "$dir" -j "${JOBS:-2}" --target m4_band_report
    elf=$dir/bin/m4_band.elf
fi
[ -f "$elf" ] || { echo "firmware.sh: $elf was not built" >&2; exit 1; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Semihosting output goes to a chardev file: with -nographic and stdout
# redirected to a file, qemu 7.2 was seen to drop the tail of the output.
status=0
timeout "${FXL_FW_TIMEOUT:-120}" qemu-system-arm -M mps2-an386 -nographic -monitor none \
    -serial none -chardev file,id=semi,path="$tmp/out.txt" \
    -semihosting-config enable=on,target=native,chardev=semi -kernel "$elf" || status=$?
cat "$tmp/out.txt"
if [ "$status" -ne 0 ] || ! grep -q '^status ok' "$tmp/out.txt"; then
    echo "firmware.sh: FAIL: the firmware exited with status $status (124 = timeout)" >&2
    exit 1
fi

sed -n 's/^crc //p' "$tmp/out.txt" > "$tmp/got.txt"
grep -v '^#' "$expected" | sed '/^[[:space:]]*$/d' > "$tmp/want.txt"
if [ "$update" -eq 1 ]; then
    { grep '^#' "$expected"; cat "$tmp/got.txt"; } > "$tmp/new.txt"
    cp "$tmp/new.txt" "$expected"
    echo "firmware.sh: wrote $(wc -l < "$tmp/got.txt") CRCs to $expected;" \
         "now run tests/test_firmware_scene.c (ctest -R test_firmware_scene)"
    exit 0
fi
if diff -u "$tmp/want.txt" "$tmp/got.txt" > "$tmp/diff.txt"; then
    echo "firmware.sh: PASS: $(wc -l < "$tmp/got.txt") CRCs on qemu equal $expected"
    exit 0
fi
echo "firmware.sh: FAIL: qemu CRCs differ from $expected (- expected, + qemu):" >&2
cat "$tmp/diff.txt" >&2
exit 1
