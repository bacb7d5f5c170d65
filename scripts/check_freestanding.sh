#!/usr/bin/env bash
# scripts/check_freestanding.sh - prove that firmware archives need no libc.
#
#   scripts/check_freestanding.sh <archive.a>...      (NM=arm-none-eabi-nm)
#
# Collects the undefined symbols of all members of all archives given, drops
# those defined by any member (one core file calling another, the port layer
# calling the core), and fails, listing them, if anything is left besides:
#   memcpy memset memmove   which GCC may emit for struct copies and
#                           initialisers even with -ffreestanding
#   __aeabi_*               ARM EABI run-time helpers (division, 64-bit
#                           shifts and multiplies, soft float) from libgcc
#   __divdi3 __ashldi3 ...  libgcc's integer helpers under their generic
#                           names, which targets without an EABI (RISC-V)
#                           call for the same work: 64-bit shifts, products,
#                           divisions and remainders, 32-bit ones on cores
#                           without M
#   __gnu_thumb1_case_*     libgcc switch-table helpers on Thumb-1 cores
#   __clzsi2 __ctzsi2 ...   libgcc bit-count helpers for cores without CLZ
# The last two groups are compiler run-time, not libc: a plain switch
# statement or __builtin_clz on Cortex-M0+ needs them. Set
# FXL_FREESTANDING_STRICT=1 to allow only memcpy/memset/memmove/__aeabi_*
# and the generic integer helpers (issue 2's rule; `make firmware` does:
# fixel's own archives need none of the last two groups, which this default
# still lets other code use).
set -euo pipefail

NM=${NM:-arm-none-eabi-nm}

if [ $# -eq 0 ]; then
    echo "usage: NM=<nm> $0 <archive.a>..." >&2
    exit 2
fi
for archive in "$@"; do
    if [ ! -f "$archive" ]; then
        echo "check_freestanding: no such archive: $archive" >&2
        exit 2
    fi
done
if ! command -v "$NM" >/dev/null 2>&1; then
    echo "check_freestanding: $NM not found (set NM=...)" >&2
    exit 2
fi

intops='__(ashl|ashr|lshr|mul|div|udiv|mod|umod|neg)[sd]i3|__udivmoddi4|__u?cmpdi2'
allowed="^(memcpy|memset|memmove|__aeabi_[A-Za-z0-9_]+|$intops)\$"
if [ "${FXL_FREESTANDING_STRICT:-0}" != 1 ]; then
    allowed="^(memcpy|memset|memmove|__aeabi_[A-Za-z0-9_]+|$intops|__gnu_thumb1_case_[a-z0-9]+|__(clz|ctz|popcount|parity|ffs)[sd]i2)\$"
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# "nm -u" lines are "<spaces>U name" (or w for weak); member headers and
# blank lines have another shape and are skipped.
"$NM" -u "$@" | awk 'NF == 2 && ($1 == "U" || $1 == "w") { print $2 }' | sort -u >"$tmp/undefined"
"$NM" -g --defined-only "$@" | awk 'NF == 3 { print $3 }' | sort -u >"$tmp/defined"
comm -23 "$tmp/undefined" "$tmp/defined" >"$tmp/external"

grep -Ev "$allowed" "$tmp/external" >"$tmp/offending" || true

echo "check_freestanding: $*"
if [ -s "$tmp/external" ]; then
    echo "  external references: $(tr '\n' ' ' <"$tmp/external")"
else
    echo "  external references: none"
fi
if [ -s "$tmp/offending" ]; then
    echo "check_freestanding: FAIL: not freestanding; these symbols would come from libc or the OS:" >&2
    sed 's/^/  /' "$tmp/offending" >&2
    echo "  used by:" >&2
    while read -r sym; do
        "$NM" -A -u "$@" 2>/dev/null |
            awk -v s="$sym" '$NF == s { sub(/:$/, "", $1); print "    " $1 ": " s }' >&2
    done <"$tmp/offending"
    exit 1
fi
echo "check_freestanding: OK"
