#!/usr/bin/env bash
# config_matrix.sh - compile the core in each configuration listed below,
# warnings as errors, with each compiler present.
#
# The default build only ever compiles config.h's defaults; a helper left
# unused by a smaller configuration (FXL_HAVE_*, FXL_FAST_*) would break a
# user's -Werror build and no other check would see it. Each configuration
# is compiled
#   - with the host gcc at -O2 (specialised walks built: FXL__FAST_SPANS 1),
#   - with arm-none-eabi-gcc for the Cortex-M4 at -Os (none built) and at
#     -O2 (built, with the Thumb-2 and DSP code: GCC's may-be-uninitialised
#     warnings differ there, and one broke the panel configuration),
#   - with clang -fsyntax-only at -O2 and -Os (clang also reports unused
#     static inline functions, which gcc does not),
# so both sides of FXL__FAST_SPANS are seen. That the configurations draw
# the same pixels is determinism.sh's job (its gcc-O2-subset build), and
# the Cortex-M0+ build of the default configuration is compiled there.
# Environment: CC (host compiler, default cc), JOBS (parallel
# configurations, default 2), FXL_BUILD_DIR (scratch space under it).
# Usage: bash host_sim/scripts/config_matrix.sh   (exit 1 on any failure)
set -uo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
out="${FXL_BUILD_DIR:-build}/config_matrix"
mkdir -p "$out"
out=$(cd "$out" && pwd)

configs=(
    "default:"
    "min:-DFXL_HAVE_MIPMAP=0 -DFXL_HAVE_GENERIC=0 -DFXL_HAVE_DEPTH=0 -DFXL_HAVE_AUTO=0"
    "min-native:-DFXL_HAVE_MIPMAP=0 -DFXL_HAVE_GENERIC=0 -DFXL_HAVE_DEPTH=0 -DFXL_HAVE_AUTO=0 -DFXL_FAST_SWAPPED=0"
    "min-point:-DFXL_HAVE_MIPMAP=0 -DFXL_HAVE_GENERIC=0 -DFXL_HAVE_DEPTH=0 -DFXL_HAVE_AUTO=0 -DFXL_HAVE_BILINEAR=0"
    "no-depth:-DFXL_HAVE_DEPTH=0"
    "no-bilinear:-DFXL_HAVE_BILINEAR=0"
    "no-auto:-DFXL_HAVE_AUTO=0"
    "no-quad:-DFXL_HAVE_QUAD=0"
    "no-mip:-DFXL_HAVE_MIPMAP=0"
    "native-only:-DFXL_FAST_SWAPPED=0"
    "panel:-DFXL_FAST_NATIVE=0 -DFXL_FAST_NO_DEPTH=0"
    "no-fast-point:-DFXL_FAST_POINT=0"
    "no-fast-bilinear-depth:-DFXL_FAST_BILINEAR=0 -DFXL_FAST_DEPTH=0"
    "no-fast-mip:-DFXL_FAST_MIP=0"
    "no-fast-at-all:-DFXL_FAST_NATIVE=0 -DFXL_FAST_SWAPPED=0"
    "small-div-hw:-DFXL_SMALL_DIV64_HW=1"
    "div-table:-DFXL_DIV_TABLE=1"
    "tint:-DFXL_FAST_TINT=1"
    "tint-panel:-DFXL_FAST_TINT=1 -DFXL_FAST_NATIVE=0 -DFXL_FAST_NO_DEPTH=0 -DFXL_FAST_MIP=0"
    "tint-native:-DFXL_FAST_TINT=1 -DFXL_FAST_SWAPPED=0 -DFXL_FAST_BILINEAR=0"
)
warn=(-Wall -Wextra -Wpedantic -Werror)
base=(-std=c99 -ffreestanding "-I$root/include" "-I$root/src")
core=("$root"/src/*.c)
read -r -a host_cc <<<"${CC:-cc}"   # CC may carry arguments (ccache gcc)
jobs_max="${JOBS:-2}"
case $jobs_max in
'' | *[!0-9]* | 0) jobs_max=2 ;;
esac

compilers=()
if command -v "${host_cc[0]}" >/dev/null 2>&1; then compilers+=("host"); else echo "  (host compiler ${host_cc[0]} not found: skipped)"; fi
if command -v arm-none-eabi-gcc >/dev/null 2>&1; then compilers+=("m4"); else echo "  (arm-none-eabi-gcc not found: skipped)"; fi
if command -v clang >/dev/null 2>&1; then compilers+=("clang"); else echo "  (clang not found: skipped)"; fi
if [ "${#compilers[@]}" -eq 0 ]; then
    echo "config_matrix.sh: no compiler found" >&2
    exit 1
fi

# one configuration: every compiler, in a scratch directory of its own
check() {   # name flags
    local name=$1 dir="$out/$1" ok=0
    local -a flags
    read -r -a flags <<<"$2"
    rm -rf "$dir"
    mkdir -p "$dir"
    (
        cd "$dir" || exit 1
        for c in "${compilers[@]}"; do
            case $c in
            host)  "${host_cc[@]}" "${base[@]}" -O2 "${warn[@]}" ${flags[@]+"${flags[@]}"} -c "${core[@]}" ;;
            m4)    arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb "${base[@]}" -Os "${warn[@]}" \
                       ${flags[@]+"${flags[@]}"} -c "${core[@]}" &&
                   arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb "${base[@]}" -O2 "${warn[@]}" \
                       ${flags[@]+"${flags[@]}"} -c "${core[@]}" ;;
            clang) clang "${base[@]}" -O2 "${warn[@]}" ${flags[@]+"${flags[@]}"} -fsyntax-only "${core[@]}" &&
                   clang "${base[@]}" -Os "${warn[@]}" ${flags[@]+"${flags[@]}"} -fsyntax-only "${core[@]}" ;;
            esac || { echo "    ($c)"; exit 1; }
        done
    ) >"$dir.log" 2>&1 || ok=1
    if [ $ok = 0 ]; then
        echo "  $name: ok"
    else
        echo "  $name: FAILED ($2)"
        grep -m 8 -E "error|warning|\(" "$dir.log" | sed 's/^/    /'
    fi
    rm -rf "$dir"
    return $ok
}

echo "== core configurations, ${compilers[*]}"
status=0
pids=()
for entry in "${configs[@]}"; do
    check "${entry%%:*}" "${entry#*:}" >"$out/${entry%%:*}.result" &
    pids+=($!)
    if [ "${#pids[@]}" -ge "$jobs_max" ]; then
        wait "${pids[0]}" || status=1
        pids=(${pids[@]+"${pids[@]:1}"})
    fi
done
for p in ${pids[@]+"${pids[@]}"}; do
    wait "$p" || status=1
done
for entry in "${configs[@]}"; do
    cat "$out/${entry%%:*}.result"
done
exit $status
