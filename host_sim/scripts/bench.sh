#!/usr/bin/env bash
# bench.sh - `make bench`: the speed-versus-accuracy benchmark (issue 4).
#
#   FXL_BUILD_DIR=build FXL_BIN_DIR=build/bin bash host_sim/scripts/bench.sh
#
# Writes docs/bench/results.csv, docs/bench/*.png (gnuplot),
# docs/bench/footprint.txt and docs/bench/frontend.csv (instructions per
# vertex of the 3D front end); prints summary tables. Progress goes to stderr.
# Work files: build-bench-host/ (callgrind), build-bench-m4/, build-bench-m0/,
# build-bench-rv32/ (firmware), build-bench-size/ (footprint builds).
# Optional tools, each skipped with a note when missing: valgrind (host
# instructions per pixel), arm-none-eabi-gcc + qemu-system-arm (Cortex-M
# figures), riscv64-unknown-elf-gcc + qemu-system-riscv32 (RV32IMAC
# figures), gnuplot (charts). Environment knobs:
#   BENCH_RUNS=5     timing runs per configuration (median; 0..15)
#   BENCH_TRACE=1    also count floor subdiv16 point/bilinear exactly from a
#                    QEMU exec trace (a few seconds); 0 skips it
#   BENCH_OUT=DIR    write the CSVs, charts and footprint there (relative to
#                    the repository root) instead of docs/bench/, which a run
#                    without every counting tool refuses to overwrite, unless
#                    BENCH_PARTIAL=1
set -euo pipefail
# A parent make (make bench) must not hand its jobserver to the make calls below.
unset MAKEFLAGS MFLAGS MAKELEVEL

root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
build=${FXL_BUILD_DIR:-build}
bin=${FXL_BIN_DIR:-$build/bin}
out=docs/bench
hostw=build-bench-host
m4w=build-bench-m4
m0w=build-bench-m0
rvw=build-bench-rv32
sizew=build-bench-size
runs=${BENCH_RUNS:-5}
# fixel-bench keeps at most 15 timings a configuration; checked here, not
# after the firmware work at the last step
if ! [[ "$runs" =~ ^[0-9]+$ ]] || [ "$runs" -gt 15 ]; then
    echo "bench.sh: BENCH_RUNS wants a whole number 0..15, got '$runs'" >&2
    exit 2
fi
trace=${BENCH_TRACE:-1}
scripts=host_sim/scripts
t_start=$SECONDS

say() { printf '[bench %3ds] %s\n' $((SECONDS - t_start)) "$*" >&2; }
have() { command -v "$1" >/dev/null 2>&1; }

# docs/bench/ holds the published figures: without the counting tools a run
# would replace every instruction count in results.csv and frontend.csv by
# an empty cell or nan. Refuse unless asked (BENCH_PARTIAL=1), or write to
# BENCH_OUT instead.
# (BENCH_OUT is relative to the repository root, where this script runs.)
out=${BENCH_OUT:-$out}
if [ "$(realpath -m "$out")" = "$(realpath -m docs/bench)" ] && [ "${BENCH_PARTIAL:-0}" != 1 ]; then
    lacking=()
    for tool in valgrind arm-none-eabi-gcc qemu-system-arm riscv64-unknown-elf-gcc qemu-system-riscv32; do
        have "$tool" || lacking+=("$tool")
    done
    if [ ${#lacking[@]} -gt 0 ]; then
        echo "bench.sh: missing ${lacking[*]}; docs/bench/ would lose their counts." >&2
        echo "  install them (scripts/deps.sh firmware optional), or rerun with" >&2
        echo "  BENCH_OUT=<dir> (write elsewhere) or BENCH_PARTIAL=1 (overwrite anyway)" >&2
        exit 1
    fi
fi
mkdir -p "$out" "$hostw" "$m4w" "$m0w" "$rvw" "$sizew"

if [ ! -d "$build" ]; then
    say "configuring $build"
    cmake -S . -B "$build" >&2
fi
say "building fixel-bench in $build"
cmake --build "$build" --target fixel-bench -j 2 >&2
bench="$bin/fixel-bench"

# ---- host instructions per pixel (callgrind), in the background ------------------
host_ir=""
cg_pid=""
fe_ir=""
fe_pid=""
if have valgrind; then
    host_ir="$hostw/host_ir.txt"
    # cg_dumps OUT PREFIX [TAG]: one line "name words... total [TAG]" per
    # callgrind dump OUT.N that a client request named PREFIX<name>
    # (slashes in the name become spaces)
    cg_dumps() {
        local f name tot
        for f in "$1".*; do
            name=$(sed -n "s|^desc: Trigger: Client Request: $2||p" "$f")
            tot=$(sed -n 's/^totals: //p;s/^summary: //p' "$f" | head -n 1)
            [ -n "$name" ] && [ -n "$tot" ] && echo "${name//\// } $tot${3:+ $3}"
        done
        return 0
    }
    say "callgrind: every configuration, draw calls only (background)"
    (
        rm -f "$hostw"/cg.out*
        valgrind --tool=callgrind --collect-atstart=no --toggle-collect=fxl_draw_triangle \
            --callgrind-out-file="$hostw/cg.out" "$bench" draw >"$hostw/draw.txt" 2>"$hostw/valgrind.log"
        if grep -q '^# client requests: yes' "$hostw/draw.txt"; then
            cg_dumps "$hostw/cg.out" "" callgrind >"$host_ir"
        else
            # No valgrind headers at build time: one process per configuration.
            : >"$host_ir"
            grep -v '^#' "$hostw/draw.txt" | while IFS=/ read -r s m fl; do
                valgrind --tool=callgrind --collect-atstart=no --toggle-collect=fxl_draw_triangle \
                    --callgrind-out-file="$hostw/one.out" "$bench" draw --scene "$s" --method "$m" \
                    --filter "$fl" >/dev/null 2>>"$hostw/valgrind.log"
                echo "$s $m $fl $(sed -n 's/^totals: //p;s/^summary: //p' "$hostw/one.out" | head -n 1) callgrind"
            done >"$host_ir"
        fi
    ) &
    cg_pid=$!
    fe_ir="$hostw/fe_ir.txt"
    say "callgrind: the 3D front end per vertex (background)"
    (
        rm -f "$hostw"/fe.out*
        valgrind --tool=callgrind --collect-atstart=no --toggle-collect=fxl_pipeline_emit \
            --callgrind-out-file="$hostw/fe.out" "$bench" frontend-run >"$hostw/fe_run.txt" 2>"$hostw/fe_valgrind.log"
        : >"$fe_ir"
        if grep -q '^# client requests: yes' "$hostw/fe_run.txt"; then
            cg_dumps "$hostw/fe.out" "fe/" >"$fe_ir"
        fi
    ) &
    fe_pid=$!
else
    say "valgrind not found (apt-get install valgrind): no host instruction counts"
fi

# ---- Cortex-M firmware --------------------------------------------------------------
m4_counts=""
m0_counts=""
m4_os_counts=""
footprint="$out/footprint.txt"
# shellcheck source=host_sim/scripts/bare_metal.sh
. "$scripts/bare_metal.sh"
qemu_run() { # elf fw_out [extra qemu args...]
    local elf=$1 fw=$2
    shift 2
    fxl_semihosted "$fw" 600 qemu-system-arm -M mps2-an386 "$@" -kernel "$elf"
}
if have arm-none-eabi-gcc; then
    say "firmware data from the host scenes"
    "$bench" gen-fw "$m4w/data_all.c" --filters point,bilinear,trilinear --meshes 1
    "$bench" gen-fw "$m0w/data_point.c" --filters point --meshes 1
    "$bench" gen-fw "$m4w/data_trace.c" --filters point,bilinear --scene floor --method subdiv16
    say "building the M4 (-O2) and M0+ (-O2) firmware"
    make -s -j 2 -C bench fw CPU=cortex-m4 OPT=-O2 OUT="$root/$m4w/icount" DATA="$root/$m4w/data_all.c" >&2
    make -s -j 2 -C bench fw CPU=cortex-m0plus OPT=-O2 OUT="$root/$m0w/icount" DATA="$root/$m0w/data_point.c" >&2
    make -s -j 2 -C bench fw CPU=cortex-m4 OPT=-O2 OUT="$root/$m4w/trace" DATA="$root/$m4w/data_trace.c" >&2
    # A size build (every draw through the generic walk), as flash-bound
    # products build the core: its own column, m4_os_ipp.
    make -s -j 2 -C bench fw CPU=cortex-m4 OPT=-Os OUT="$root/$m4w/icount-os" DATA="$root/$m4w/data_all.c" >&2
    if have qemu-system-arm; then
        say "qemu mps2-an386, -icount shift=0: M4 (all configurations) and M0+ code (point)"
        qemu_run "$m4w/icount/bench.elf" "$m4w/icount/fw.txt" -icount shift=0
        qemu_run "$m0w/icount/bench.elf" "$m0w/icount/fw.txt" -icount shift=0
        python3 "$scripts/m4_count.py" icount "$m4w/icount/fw.txt" >"$m4w/counts.txt"
        python3 "$scripts/m4_count.py" icount "$m0w/icount/fw.txt" >"$m0w/counts.txt"
        say "qemu mps2-an386, -icount shift=0: M4 -Os (all configurations)"
        qemu_run "$m4w/icount-os/bench.elf" "$m4w/icount-os/fw.txt" -icount shift=0
        python3 "$scripts/m4_count.py" icount "$m4w/icount-os/fw.txt" >"$m4w/counts_os.txt"
        if [ "$trace" = 1 ]; then
            say "exact trace count: floor subdiv16 point/bilinear on M4"
            arm-none-eabi-nm "$m4w/trace/libfixel.a" >"$m4w/trace/lib.nm"
            dfilter=$(python3 "$scripts/m4_count.py" ranges "$m4w/trace/bench.nm" "$m4w/trace/ranges.nm" \
                "$m4w/trace/lib.nm")
            rm -f "$m4w/trace/fw.txt"
            timeout 600 qemu-system-arm -M mps2-an386 -display none -monitor none -serial none \
                -chardev file,id=semi,path="$m4w/trace/fw.txt" \
                -semihosting-config enable=on,target=native,chardev=semi \
                -singlestep -d exec,nochain -dfilter "$dfilter" -D /dev/stdout \
                -kernel "$m4w/trace/bench.elf" |
                "$bench" count-trace "$m4w/trace/ranges.nm" >"$m4w/trace/segments.txt"
            python3 "$scripts/m4_count.py" trace "$m4w/trace/fw.txt" "$m4w/trace/segments.txt" \
                >"$m4w/trace/counts.txt"
            # Later lines win in fixel-bench: exact counts replace the icount ones.
            cat "$m4w/trace/counts.txt" >>"$m4w/counts.txt"
            say "trace vs icount: $(tr '\n' ';' <"$m4w/trace/counts.txt")"
        fi
        m4_counts="$m4w/counts.txt"
        m0_counts="$m0w/counts.txt"
        m4_os_counts="$m4w/counts_os.txt"
    else
        say "qemu-system-arm not found (apt-get install qemu-system-arm): no Cortex-M counts"
    fi

    say "footprint: core alone for M0+ and M4 at -Os and -O2, and the smallest configuration"
    cat >"$sizew/min_config.h" <<'EOF'
/* The smallest useful fixel: point + bilinear, subdivided perspective,
 * RGB565 repeat textures, no mip maps, no generic path, no depth buffer,
 * no adaptive mode. */
#define FXL_HAVE_MIPMAP 0
#define FXL_HAVE_GENERIC 0
#define FXL_HAVE_DEPTH 0
#define FXL_HAVE_AUTO 0
EOF
    cat >"$sizew/panel_config.h" <<'EOF'
/* Every feature, with specialised code only for what a product driving one
 * SPI panel with a depth buffer draws fast: byte-swapped RGB565 targets,
 * depth on. Other draws take the generic walk (same pixels, slower). */
#define FXL_FAST_NATIVE 0
#define FXL_FAST_NO_DEPTH 0
EOF
    cat >"$sizew/hwdiv_config.h" <<'EOF'
/* Every feature; a size build's set-up divides by 32-bit divisors with the
 * core's divide instruction (config.h). */
#define FXL_SMALL_DIV64_HW 1
EOF
    cat >"$sizew/table_config.h" <<'EOF'
/* Every feature; the reciprocal's first estimate from a table instead of a
 * 32-bit division (config.h), as ARMv6-M -O2 builds take it. */
#define FXL_DIV_TABLE 1
EOF
    {
        echo "# Core footprint in bytes, $(date -u +%Y-%m-%d). archive: arm-none-eabi-size (rv32imac:"
        echo "# riscv64-unknown-elf-size) of libfixel.a"
        echo "# (every src/*.c module, the 3D front end included); linked: the core code + const data"
        echo "# that one textured fxl_draw_triangle program keeps after --gc-sections (bench/size_main.c),"
        echo "# including runtime: the compiler's helpers (libgcc shifts, multiplies, divisions) it pulls in."
        echo "# min = point + bilinear, subdivided, RGB565: FXL_HAVE_MIPMAP/GENERIC/DEPTH/AUTO 0."
        echo "# panel = every feature, specialised code only for byte-swapped targets with depth"
        echo "# (FXL_FAST_NATIVE 0, FXL_FAST_NO_DEPTH 0): what one SPI-panel product keeps."
        echo "# hwdiv (-Os only) = every feature with FXL_SMALL_DIV64_HW 1: set-up's 32-bit divisors by the"
        echo "# core's divide instruction (the M0+ has none: the same code as full there)."
        echo "# table (-Os only) = every feature with FXL_DIV_TABLE 1: the reciprocal's estimate from a"
        echo "# 512-byte table, for cores without a divide instruction (ARMv6-M -O2 builds have it)."
        echo "# linked -1: that configuration did not link (see build-bench-size/*/link.log)."
        printf '%-14s %-4s %-5s %9s %6s %6s %9s %8s\n' cpu opt cfg archive data bss linked runtime
        cpus=(cortex-m0plus cortex-m4)
        have riscv64-unknown-elf-gcc && cpus+=(rv32imac)
        for cpu in "${cpus[@]}"; do
            # the tools and bench/Makefile arguments of this core
            if [ "$cpu" = rv32imac ]; then
                tp=riscv64-unknown-elf-
                target=(ARCH=riscv MARCH=$cpu MABI=ilp32)
            else
                tp=arm-none-eabi-
                target=(CPU=$cpu)
            fi
            for opt in -Os -O2; do
                cfgs=(full min panel)
                [ "$opt" = -Os ] && cfgs+=(hwdiv table)
                for cfg in "${cfgs[@]}"; do
                    d="$root/$sizew/${cpu#cortex-}$opt-$cfg"
                    # From scratch: bench/Makefile's objects do not depend on
                    # the config header, so a changed configuration would
                    # otherwise reuse stale objects.
                    rm -rf "$d"
                    mkdir -p "$d"
                    extra=()
                    [ "$cfg" = full ] || extra=(CONFIG="$root/$sizew/${cfg}_config.h")
                    if ! make -s -j 2 -C bench "$d/libfixel.a" "${target[@]}" OPT=$opt OUT="$d" "${extra[@]}" \
                        >"$d.build.log" 2>&1; then
                        say "footprint: the core does not build for $cpu $opt $cfg (see $d.build.log)"
                        printf '%-14s %-4s %-5s %9s\n' $cpu $opt $cfg "build-failed"
                        continue
                    fi
                    "${tp}nm" "$d/libfixel.a" >"$d/lib.nm" 2>/dev/null
                    # A link failure (a symbol missing in this configuration) is
                    # reported in the table, not fatal.
                    if make -s -C bench core "${target[@]}" OPT=$opt OUT="$d" "${extra[@]}" >"$d/link.log" 2>&1; then
                        "${tp}nm" "$d"/app/*.o >"$d/app.nm" 2>/dev/null
                        read -r linked _ _ runtime < <(python3 "$scripts/m4_count.py" linked "$d/size.nm" "$d/lib.nm" "$d/app.nm")
                    else
                        linked=-1
                        runtime=-1
                        say "footprint: $cpu $opt $cfg does not link: $(grep -m1 'undefined reference' "$d/link.log" || tail -n 1 "$d/link.log")"
                    fi
                    "${tp}size" -t "$d/libfixel.a" | tail -n 1 |
                        awk -v c=$cpu -v o=$opt -v g=$cfg -v l="$linked" -v r="$runtime" \
                            '{printf "%-14s %-4s %-5s %9d %6d %6d %9d %8d\n", c, o, g, $1, $2, $3, l, r}'
                done
            done
        done
        echo
        echo "# worst-case stack of one fxl_draw_triangle call (gcc -fcallgraph-info=su, frames summed"
        echo "# along the deepest call chain; libgcc helpers not included). An upper bound: the tool"
        echo "# lets the generic walk's pointer call reach the specialised walks too (draw_span_generic's"
        echo "# frame in the -O2 rows, above them), which only fxl__draw_valid calls."
        # stack_rows ROOT [CALLER=CALLEE...]: the bound for every core and level
        stack_rows() {
            local cpu opt d
            for cpu in "${cpus[@]}"; do
                for opt in -Os -O2; do
                    d="$root/$sizew/${cpu#cortex-}$opt-full/core"
                    [ -d "$d" ] || continue
                    printf '%-14s %-4s %s\n' $cpu $opt "$(python3 "$scripts/m4_count.py" stack "$d" "$@")"
                done
            done
        }
        stack_rows fxl_draw_triangle
        echo
        echo "# the same for fxl_mesh_draw (the front end's frame under every draw: its callback"
        echo "# draw_one calls the rasterizer) and fxl_pipeline_emit with a callback that does nothing"
        stack_rows fxl_mesh_draw fxl_pipeline_emit=draw_one
        stack_rows fxl_pipeline_emit
        if [ -f "$m4w/icount/fw.txt" ]; then
            echo
            echo "# measured on qemu (benchmark firmware, -O2, examples/common/fw_stack.h): the deepest"
            echo "# stack written below the caller by one configuration's fxl_draw_triangle calls (every"
            echo "# scene, method and filter; M0+: point) or by one fxl_pipeline_emit (every mesh, level and"
            echo "# cache; callback does nothing). Written, not reserved: a frame's unused array space is"
            echo "# not counted, so the bound above is what to size a stack (and its interrupts) by."
            for w in "cortex-m4:$m4w" "cortex-m0plus:$m0w"; do
                f="${w#*:}/icount/fw.txt"
                [ -f "$f" ] || continue
                python3 "$scripts/m4_count.py" peak "$f" | while read -r kind bytes what; do
                    printf '%-14s %-4s %-8s %5d  %s\n' "${w%%:*}" -O2 "$kind" "$bytes" "$what"
                done
            done
        fi
        echo
        "$bench" ram
    } >"$footprint"
    say "footprint written to $footprint"
else
    say "arm-none-eabi-gcc not found (apt-get install gcc-arm-none-eabi): no Cortex-M figures"
fi

# ---- RISC-V firmware ----------------------------------------------------------------
# The same firmware and data built for RV32IMAC (-O2, no depth buffer, as the
# Cortex-M rows) and run on qemu-system-riscv32 -M virt, where -icount makes
# the minstret counter an exact instruction count.
rv_counts=""
if have riscv64-unknown-elf-gcc && have qemu-system-riscv32; then
    say "RV32IMAC (-O2) firmware on qemu-system-riscv32 -M virt, -icount shift=0"
    "$bench" gen-fw "$rvw/data_all.c" --filters point,bilinear,trilinear
    make -s -j 2 -C bench fw ARCH=riscv MARCH=rv32imac MABI=ilp32 OPT=-O2 OUT="$root/$rvw/icount" \
        DATA="$root/$rvw/data_all.c" >&2
    fxl_semihosted "$rvw/icount/fw.txt" 600 qemu-system-riscv32 -M virt -bios none -icount shift=0 \
        -kernel "$rvw/icount/bench.elf"
    python3 "$scripts/m4_count.py" icount "$rvw/icount/fw.txt" >"$rvw/counts.txt"
    rv_counts="$rvw/counts.txt"
else
    say "riscv64-unknown-elf-gcc or qemu-system-riscv32 not found (apt-get install gcc-riscv64-unknown-elf" \
        "qemu-system-misc): no RISC-V counts"
fi

if [ -n "$cg_pid" ]; then
    say "waiting for callgrind"
    wait "$cg_pid" || say "callgrind failed (see $hostw/valgrind.log)"
fi
if [ -n "$fe_pid" ]; then
    wait "$fe_pid" || say "callgrind of the front end failed (see $hostw/fe_valgrind.log)"
    [ -s "$fe_ir" ] || say "no host front-end counts (valgrind/callgrind.h missing at build time?)"
fi

# ---- the 3D front end per vertex (issue 7) ------------------------------------------
say "front end per vertex: host callgrind, M4 and M0+ icount -> $out/frontend.csv"
fe_args=(frontend --csv "$out/frontend.csv")
[ -n "$fe_ir" ] && [ -s "$fe_ir" ] && fe_args+=(--host-ir "$fe_ir")
[ -n "$m4_counts" ] && fe_args+=(--m4 "$m4w/icount/fw.txt")
[ -n "$m0_counts" ] && fe_args+=(--m0 "$m0w/icount/fw.txt")
"$bench" "${fe_args[@]}" >"$hostw/frontend.txt"

# ---- accuracy, speed, CSV and the summary -------------------------------------------
say "accuracy against the reference renderer and host timing (median of $runs runs)"
args=(accuracy --runs "$runs" --csv "$out/results.csv" --plot-dir "$hostw")
[ -n "$host_ir" ] && [ -s "$host_ir" ] && args+=(--host-ir "$host_ir")
[ -n "$m4_counts" ] && args+=(--m4 "$m4_counts")
[ -n "$m0_counts" ] && args+=(--m0 "$m0_counts")
[ -n "$rv_counts" ] && args+=(--rv32 "$rv_counts")
[ -n "$m4_os_counts" ] && args+=(--m4-os "$m4_os_counts")
"$bench" "${args[@]}" >"$hostw/summary.txt"

if have gnuplot; then
    say "charts"
    for gp in speed_error error_len psnr_cost; do
        gnuplot -e "datadir='$hostw'; outdir='$out'" "$scripts/$gp.gp"
    done
else
    say "gnuplot not found (apt-get install gnuplot-nox): no charts"
fi

cat "$hostw/summary.txt"
echo
cat "$hostw/frontend.txt"
[ -f "$footprint" ] && { echo; cat "$footprint"; }
say "done: $out/results.csv, $out/frontend.csv, $out/*.png, $footprint"
