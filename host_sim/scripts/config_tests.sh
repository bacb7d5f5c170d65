#!/usr/bin/env bash
# config_tests.sh - the whole test suite in reduced configurations.
#
# config_matrix.sh proves the core compiles in every documented
# configuration; this proves it behaves there. Each configuration below is
# built from scratch with the host compiler (-Werror) and runs every CTest
# test. Tests of a left-out feature report IGNORE with the flag's name
# (tests/support/test_features.h); test_left_out_features_are_refused checks
# the API refuses such draws with FXL_ERR_UNSUPPORTED; draws of present
# features must still match the default build's golden CRCs bit for bit.
# Between them the configurations leave every FXL_HAVE_* option out at
# least once, and the specialised walks of four kinds of draw; four have
# no generic walk, where a draw without its specialised walk is refused
# too (tests model the refusals with host_sim/lib/left_out.h). One of them,
# min-panel, draws byte-swapped targets only: tests that check native
# pixels draw in left_out.h's drawable_rgb565() order and convert. Each also
# runs fixel-fuzz (FXL_CONFIG_FUZZ_CASES, default 200000 cases), whose
# status check holds the core to the same model. Three more keep every
# feature and take a numeric option to its limit: tex14 (FXL_TEX_MAX_LOG2
# 14), sub1 and sub6 (FXL_SUBPIXEL_BITS 1 and 6: tests of golden values,
# which are the 1/16 px grid's, report IGNORE there; test_features.h).
# Two keep every feature with a size build's division (small-div, and
# small-div-hw with FXL_SMALL_DIV64_HW): the same images from other
# arithmetic. tint adds the opt-in tinted walks (FXL_FAST_TINT).
#
# Usage: config_tests.sh [name...]   (default: all). Environment: JOBS
# (default 2), FXL_CONFIG_TESTS_DIR (default build-config-tests).
# About 15 s a configuration on 2 cores.
set -uo pipefail
cd "$(dirname "$0")/../.."
out="${FXL_CONFIG_TESTS_DIR:-build-config-tests}"
jobs="${JOBS:-2}"

config_defines() {
    case "$1" in
    min) # bench's smallest useful core: point + bilinear, subdivided, RGB565
        echo FXL_HAVE_MIPMAP FXL_HAVE_GENERIC FXL_HAVE_DEPTH FXL_HAVE_AUTO ;;
    no-bilinear) echo FXL_HAVE_BILINEAR FXL_HAVE_QUAD FXL_HAVE_DEPTH ;;
    no-mipmap) echo FXL_HAVE_MIPMAP FXL_HAVE_AUTO ;;
    no-depth) # painter's order: everything else kept
        echo FXL_HAVE_DEPTH ;;
    subset) # specialised code left out: those draws take the generic walk
        echo FXL_FAST_SWAPPED FXL_FAST_POINT FXL_FAST_MIP ;;
    min-depth) # min with a depth buffer
        echo FXL_HAVE_MIPMAP FXL_HAVE_GENERIC FXL_HAVE_AUTO ;;
    min-native) # min for a panel fed native RGB565 in 16-bit SPI frames
        # (FXL_PORT_PIXELS_16BIT; no byte-swapped walks)
        echo FXL_HAVE_MIPMAP FXL_HAVE_GENERIC FXL_HAVE_DEPTH FXL_HAVE_AUTO FXL_FAST_SWAPPED ;;
    min-panel) # min-depth for an SPI panel fed byte-swapped RGB565 (no native
        # walks): tests that want native pixels draw swapped and convert
        # (left_out.h, drawable_rgb565)
        echo FXL_HAVE_MIPMAP FXL_HAVE_GENERIC FXL_HAVE_AUTO FXL_FAST_NATIVE ;;
    tex14) # every feature, textures up to 16384 texels a side (the
        # largest FXL_TEX_MAX_LOG2): limits that scale with it
        echo FXL_TEX_MAX_LOG2=14 ;;
    sub6) # every feature, vertices on a 1/64 px grid (the finest
        # FXL_SUBPIXEL_BITS; golden images are the 1/16 grid's: skipped)
        echo FXL_SUBPIXEL_BITS=6 ;;
    sub1) # every feature, vertices on a 1/2 px grid (the coarsest)
        echo FXL_SUBPIXEL_BITS=1 ;;
    small-div) # every feature, the size builds' 64-bit division (fixel's
        # loop, FXL_SMALL_DIV64) with the 32-bit steps of a core that
        # divides in hardware (FXL__DIV32_HW), as a Cortex-M4 -Os build
        echo FXL_SMALL_DIV64=1 FXL__DIV32_HW=1 ;;
    small-div-hw) # the same with FXL_SMALL_DIV64_HW: 32-bit divisors by
        # fxl__udiv64_by32, gradients with one division
        echo FXL_SMALL_DIV64=1 FXL__DIV32_HW=1 FXL_SMALL_DIV64_HW=1 ;;
    tint) # every feature, with the tinted copies of the specialised walks
        # (flat MODULATE draws drawn by them, against the generic loop)
        echo FXL_FAST_TINT=1 ;;
    *) return 1 ;;
    esac
}

names=("$@")
[ ${#names[@]} -gt 0 ] || names=(min min-depth min-native min-panel no-bilinear no-mipmap no-depth subset tex14 sub1 sub6 small-div small-div-hw tint)
status=0
mkdir -p "$out"
for name in "${names[@]}"; do
    if ! defs=$(config_defines "$name"); then
        echo "config_tests: unknown configuration '$name'" >&2
        exit 2
    fi
    dir="$out/$name"
    rm -rf "$dir"
    mkdir -p "$dir"
    # NAME: #define NAME 0 (left out); NAME=VALUE: #define NAME VALUE
    for d in $defs; do
        case "$d" in
        *=*) printf '#define %s %s\n' "${d%%=*}" "${d#*=}" ;;
        *) printf '#define %s 0\n' "$d" ;;
        esac
    done >"$dir/config.h"
    t0=$SECONDS
    echo "== $name: $(for d in $defs; do case "$d" in *=*) echo "$d" ;; *) echo "$d=0" ;; esac; done | paste -sd' ')"
    if ! cmake -S . -B "$dir/build" -DFXL_CONFIG_FILE="$(cd "$dir" && pwd)/config.h" >"$dir/configure.log" 2>&1 ||
        ! cmake --build "$dir/build" -j "$jobs" >"$dir/build.log" 2>&1; then
        grep -E 'error|Error' "$dir/build.log" "$dir/configure.log" | head -n 20
        echo "-- $name: build FAILED (see $dir/build.log)"
        status=1
        continue
    fi
    # -V keeps every test's Unity output: the IGNORE lines say what this
    # configuration does not test.
    if (cd "$dir/build" && ctest -j "$jobs" -V >../ctest.log 2>&1); then
        result=ok
    else
        result=FAILED
        status=1
        grep -E ':FAIL' "$dir/ctest.log" | grep -v 'unity_compat/selftest' | head -n 30
    fi
    fuzz=$("$dir/build/bin/fixel-fuzz" --cases "${FXL_CONFIG_FUZZ_CASES:-200000}" 2>&1 | tail -n 1)
    case "$fuzz" in
    *" 0 finding(s)"*) ;;
    *) result=FAILED; status=1; echo "$fuzz" ;;
    esac
    # Unity summary lines, "N: T Tests F Failures I Ignored" (N: ctest's test
    # number), less the compat runner's self-test, whose failures are its test.
    cases=$(awk '/unity_compat\/selftest\.c/ { self[$1] = 1 }
        $3 == "Tests" && $5 == "Failures" && $7 == "Ignored" { t[$1] = $2; f[$1] = $4; i[$1] = $6 }
        END { for (n in t) if (!(n in self)) { T += t[n]; F += f[n]; I += i[n] }
              printf "%d test cases, %d failed, %d ignored", T, F, I }' "$dir/ctest.log")
    echo "-- $name: $result; $(grep -E 'tests passed' "$dir/ctest.log" | sed 's/^[0-9]*: //'); $cases; fuzz: $(echo "$fuzz" | sed -n 's/.*run in [^,]*, \([0-9]* valid\).*\( [0-9]* finding(s)\)$/\1,\2/p') ($((SECONDS - t0)) s)"
done
exit $status
