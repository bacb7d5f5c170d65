#!/usr/bin/env bash
# ci_extra.sh - CI steps of the stability issue, run last by .ci/run:
#   1. fixel-fuzz, 10^6 cases built with -fsanitize=address,undefined
#      (two processes, half the cases each; fixed seed, so a finding
#      reproduces with the printed bytes);
#   2. the stability sweeps (fixel-stability, all of them) in the same
#      sanitizer build; the libFuzzer target for 20 s when clang is
#      installed; host_sim/scripts/msan.sh: the tests (less the three that
#      write PNGs through the uninstrumented libpng), 200,000 fuzz cases and
#      the sweeps built with clang's MemorySanitizer, where clang is
#      installed (reads of uninitialised memory), and those three under
#      valgrind's memcheck;
#   3. host_sim/scripts/config_matrix.sh: the core compiles warning-free in
#      every documented configuration (FXL_HAVE_*, FXL_FAST_*);
#      host_sim/scripts/config_tests.sh: the whole test suite and 200,000
#      fuzz cases pass in eight reduced ones, with FXL_TEX_MAX_LOG2 14 and
#      with FXL_SUBPIXEL_BITS 1 and 6
#      (every FXL_HAVE_* option left
#      out at least once, four without the generic walk, one of them an SPI
#      panel's with byte-swapped walks only, and point, swapped and
#      two-level specialisations);
#   4. the whole suite built as Release and MinSizeRel, and with clang
#      (Release) where installed; fixel-fuzz of the MinSizeRel build (the
#      generic walk for every draw), FXL_OS_FUZZ_CASES (default 200000);
#      host_sim/scripts/determinism.sh (gcc -O0/-O2, clang -O2, a build with
#      specialised code left out, Cortex-M4 and Cortex-M0+ code on
#      qemu-system-arm, RV32IMAC/RV32I/RV32E/RV64IMAC code on
#      qemu-system-riscv32/64, where the tools exist);
#      the core's tests again under ASan+UBSan with the 32-bit cores'
#      arithmetic forced on the host (FXL__WORD32, FXL__MUL_HALVES, ...);
#   5. bench/experiments/*.c compile warning-free (host, and Cortex-M4 where
#      the cross compiler exists), so the measurements they record stay
#      reproducible.
# Environment: FXL_BUILD_DIR (host build, default build), FXL_ASAN_DIR
# (sanitizer build from `make sanitize`, default build-asan; configured here
# when missing), FXL_FUZZ_CASES (default 1000000), FXL_FUZZ_SEED (default 1).
# Optional tools: clang, qemu-system-arm, gcc-arm-none-eabi,
# gcc-riscv64-unknown-elf, qemu-system-misc (steps skip without them).
# Takes about 33 minutes on 2 cores with every tool (1,811 s in the
# forty-seventh session's CI; the MemorySanitizer step, added after it,
# took ~3 minutes on its own).
set -euo pipefail
cd "$(dirname "$0")/../.."
bdir="${FXL_BUILD_DIR:-build}"
adir="${FXL_ASAN_DIR:-build-asan}"
cases="${FXL_FUZZ_CASES:-1000000}"
seed="${FXL_FUZZ_SEED:-1}"
status=0

echo "== fuzz: $cases cases, seed $seed, ASan+UBSan"
if [ ! -x "$adir/bin/fixel-fuzz" ]; then
    # Debug, as `make sanitize` builds it (at -O2 with the sanitizers GCC 12
    # reports a false -Wstringop-overread in the fuzz's reference calls)
    cmake -S . -B "$adir" -DCMAKE_BUILD_TYPE=Debug -DFXL_SANITIZE=ON >/dev/null
    cmake --build "$adir" -j "${JOBS:-2}" --target fixel-fuzz
fi
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
half=$((cases / 2))
t0=$SECONDS
"$adir/bin/fixel-fuzz" --seed "$seed" --start 0 --cases "$half" --quiet > "$adir/fuzz_a.txt" 2>&1 &
pa=$!
"$adir/bin/fixel-fuzz" --seed "$seed" --start "$half" --cases "$((cases - half))" --quiet > "$adir/fuzz_b.txt" 2>&1 &
pb=$!
wait "$pa" || status=1
wait "$pb" || status=1
cat "$adir/fuzz_a.txt" "$adir/fuzz_b.txt"
echo "-- fuzz: $((SECONDS - t0)) s"

# The stability sweeps (issue 5: nothing in them may crash, trip a
# sanitizer or write outside the target) in the sanitizer build.
# fixel-stability exits non-zero itself on a damaged canary, a probe outside
# the target, coverage that differs from the exact rule or a failed draw.
echo "== stability sweeps: ASan+UBSan"
t0=$SECONDS
if ! cmake --build "$adir" -j "${JOBS:-2}" --target fixel-stability > "$adir/stability_build.txt" 2>&1; then
    tail -n 20 "$adir/stability_build.txt"
    status=1
elif "$adir/bin/fixel-stability" --out "$adir/stability" > "$adir/stability.txt" 2>&1; then
    tail -n 1 "$adir/stability.txt"
else
    tail -n 20 "$adir/stability.txt"
    status=1
fi
echo "-- stability sweeps: $((SECONDS - t0)) s"

if command -v clang >/dev/null 2>&1; then
    echo "== libFuzzer: 20 s"
    out="$adir/fuzz_raster"
    clang -std=c99 -g -O1 -fno-omit-frame-pointer -fsanitize=fuzzer,address,undefined \
        -fno-sanitize-recover=all -D_POSIX_C_SOURCE=200809L -I include -I src -I host_sim/lib \
        tests/fuzz/fuzz_raster.c host_sim/lib/reference.c src/*.c -lm -o "$out"
    mkdir -p "$adir/fuzz_corpus"
    if ! "$out" -max_len=256 -max_total_time=20 -seed="$seed" -artifact_prefix="$adir/" \
        "$adir/fuzz_corpus" > "$adir/libfuzzer.txt" 2>&1; then
        tail -40 "$adir/libfuzzer.txt"
        status=1
    fi
    tail -n 1 "$adir/libfuzzer.txt"
else
    echo "== libFuzzer: clang not found (apt-get install clang); skipped"
fi

echo "== MemorySanitizer (clang): tests, fuzz, stability sweeps"
bash host_sim/scripts/msan.sh || status=1

echo "== configurations"
FXL_BUILD_DIR="$bdir" bash host_sim/scripts/config_matrix.sh || status=1
# The whole test suite in reduced configurations (a left-out feature's
# tests IGNORE, its draws must be refused, everything else must still match
# the default build's goldens).
bash host_sim/scripts/config_tests.sh || status=1

# Optimisers warn about different things (gcc -O3 found a snprintf that
# could truncate, which -O2 did not): the whole suite in the other build
# types, and with clang when it is installed.
echo "== build types"
build_type() { # name compiler build-type
    local dir="${bdir%/}-$1"
    if CC="$2" cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE="$3" -DFXL_UNITY_DOWNLOAD=OFF >"$dir.log" 2>&1 &&
        cmake --build "$dir" -j "${JOBS:-2}" >>"$dir.log" 2>&1 &&
        ctest --test-dir "$dir" -j "${JOBS:-2}" --output-on-failure >>"$dir.log" 2>&1; then
        echo "$1 ($2, $3): built warning-free, tests pass"
    else
        tail -n 30 "$dir.log"
        echo "$1 ($2, $3): FAILED"
        status=1
    fi
}
build_type release "${CC:-cc}" Release
build_type minsizerel "${CC:-cc}" MinSizeRel
# At -Os every draw takes the generic walk, as size-optimised firmware's
# do: the fuzz's checks (check 7's texel values included) on that code too.
osdir="${bdir%/}-minsizerel"
if [ -x "$osdir/bin/fixel-fuzz" ]; then
    if "$osdir/bin/fixel-fuzz" --seed "$seed" --cases "${FXL_OS_FUZZ_CASES:-200000}" --quiet \
        > "$osdir/fuzz.txt" 2>&1; then
        echo "minsizerel fuzz: $(tail -n 1 "$osdir/fuzz.txt")"
    else
        tail -n 40 "$osdir/fuzz.txt"
        echo "minsizerel fuzz: FAILED"
        status=1
    fi
fi
if command -v clang >/dev/null 2>&1; then
    build_type clang-release clang Release
else
    echo "clang not found (apt-get install clang): clang build skipped"
fi

echo "== determinism"
FXL_BUILD_DIR="$bdir" bash host_sim/scripts/determinism.sh || status=1

# The 32-bit cores' arithmetic (16-bit-half products, the table-started
# reciprocal, the one-word roundings of FXL__WORD32 that exact runs and row
# walks take, the plain C CLZ of cores without one) runs on the host only in
# determinism.sh's m0arith build,
# without sanitizers: the whole suite here under ASan+UBSan with it (a Debug
# build, like `make sanitize`'s).
echo "== 32-bit arithmetic: the tests under ASan+UBSan"
t0=$SECONDS
wdir="${adir%/}-word32"
if cmake -S . -B "$wdir" -DCMAKE_BUILD_TYPE=Debug -DFXL_SANITIZE=ON -DFXL_UNITY_DOWNLOAD=OFF \
    -DCMAKE_C_FLAGS="-DFXL__WORD32=1 -DFXL__MUL_HALVES=1 -DFXL__DIV_TABLE=1 -DFXL__DIV64_RECIP=1 -DFXL_USE_BUILTIN_CLZ=0" \
    >"$wdir.log" 2>&1 && cmake --build "$wdir" -j "${JOBS:-2}" >>"$wdir.log" 2>&1 &&
    ctest --test-dir "$wdir" -j "${JOBS:-2}" --output-on-failure --no-tests=error >>"$wdir.log" 2>&1; then
    echo "32-bit arithmetic: $(grep -E 'tests passed' "$wdir.log" | tail -n 1)"
else
    tail -n 30 "$wdir.log"
    echo "32-bit arithmetic: FAILED"
    status=1
fi
echo "-- 32-bit arithmetic: $((SECONDS - t0)) s"

echo "== experiments"
for src in bench/experiments/*.c; do
    obj="$bdir/$(basename "$src" .c)"
    ok=1
    "${CC:-cc}" -std=c99 -Wall -Wextra -Wpedantic -Werror -O2 -c "$src" -o "$obj.o" || ok=0
    if command -v arm-none-eabi-gcc >/dev/null 2>&1; then
        arm-none-eabi-gcc -std=c99 -Wall -Wextra -Wpedantic -Werror -mcpu=cortex-m4 -mthumb -O2 \
            -c "$src" -o "$obj.m4.o" || ok=0
    fi
    if [ "$ok" = 1 ]; then echo "$src: compiled"; else echo "$src: FAILED"; status=1; fi
done
exit $status
