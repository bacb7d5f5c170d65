# bare_metal.sh - sourced (bash) by determinism.sh and firmware.sh: link a
# freestanding image for qemu's RISC-V virt board, and run any semihosting
# image on qemu with its output to a file.

fxl_common_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../examples/common" && pwd)"

# fxl_rv_link ELF MARCH MABI OPT LIBMARCH ARGS...: sources and flags (ARGS)
# with the virt start-up and linker script, -Werror. LIBMARCH, when not
# empty, names the multilib whose libgcc to link: Debian's have no Zbb
# variant, and for -march=..._zbb gcc would pick the default (RV64) one.
fxl_rv_link() {
    local elf=$1 march=$2 mabi=$3 opt=$4 libmarch=$5 libgcc=-lgcc
    shift 5
    [ -n "$libmarch" ] && libgcc=$(riscv64-unknown-elf-gcc -march="$libmarch" -mabi="$mabi" -print-libgcc-file-name)
    riscv64-unknown-elf-gcc -std=c99 -ffreestanding -nostdlib "$opt" -Wall -Wextra -Wpedantic -Werror \
        -march="$march" -mabi="$mabi" -mcmodel=medany -ffunction-sections -fdata-sections \
        -I"$fxl_common_dir" -T "$fxl_common_dir/virt_rv.ld" -Wl,--gc-sections,--no-warn-rwx-segments \
        "$fxl_common_dir/virt_rv_startup.c" "$@" "$libgcc" -o "$elf"
}

# fxl_semihosted OUT SECONDS QEMU ARGS...: run a semihosting image (ARGS
# name the machine and -kernel), its output to the file OUT (a chardev:
# with -nographic and stdout redirected to a file, qemu 7.2 was seen to
# drop the tail of the output); returns qemu's status (124: timeout).
fxl_semihosted() {
    local out=$1 secs=$2 qemu=$3 status=0
    shift 3
    rm -f "$out"
    timeout "$secs" "$qemu" "$@" -display none -monitor none -serial none \
        -chardev file,id=semi,path="$out" -semihosting-config enable=on,target=native,chardev=semi || status=$?
    return $status
}
