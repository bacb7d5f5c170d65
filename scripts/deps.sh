#!/usr/bin/env bash
# scripts/deps.sh - make sure the build tools are installed.
#
#   scripts/deps.sh [group...]      groups: host (default), firmware, cppcheck,
#                                   optional
#
#   host      cmake (>= 3.20), a C compiler, make, libpng-dev; and, never
#             an error, ca-certificates (the pinned Unity download is HTTPS)
#   firmware  cmake, make, gcc-arm-none-eabi, libnewlib-arm-none-eabi
#   cppcheck  cppcheck
#   optional  g++ (C++ check of the public headers), clang (libFuzzer,
#             determinism across compilers), qemu-system-arm,
#             gcc-riscv64-unknown-elf and qemu-system-misc (RISC-V),
#             gnuplot-nox, valgrind: installed one by one when possible,
#             never an error
#
# When everything is present this only looks at PATH, pkg-config or a
# compile probe for libpng, and the CA bundle: no apt.
# Otherwise it runs `apt-get update` once and `apt-get install -y` as root,
# or through `sudo -n` when that needs no password; failing both, it prints
# the exact command to run and exits 1.
set -euo pipefail

groups=("$@")
if [ ${#groups[@]} -eq 0 ]; then
    groups=(host)
fi

missing=()          # required Debian packages not yet installed
optional_missing=() # optional ones
notes=()

have() { command -v "$1" >/dev/null 2>&1; }

add() {
    local pkg
    for pkg in "$@"; do
        case " ${missing[*]-} " in *" $pkg "*) ;; *) missing+=("$pkg") ;; esac
    done
}

check_cmake() {
    if ! have cmake; then
        add cmake
        return
    fi
    local v
    v=$(cmake --version | sed -n 's/^cmake version \([0-9]*\.[0-9]*\).*/\1/p')
    local major=${v%%.*} minor=${v#*.}
    if [ -z "$v" ] || [ "$major" -lt 3 ] || { [ "$major" -eq 3 ] && [ "$minor" -lt 20 ]; }; then
        # Debian 11 (bullseye) ships 3.18: its backports carry a newer one.
        # (Other releases' backports may not; no guess for them.)
        local id="" codename=""
        if [ -r /etc/os-release ]; then
            id=$(sed -n 's/^ID=//p' /etc/os-release | tr -d '"')
            codename=$(sed -n 's/^VERSION_CODENAME=//p' /etc/os-release | tr -d '"')
        fi
        if [ "$id" = debian ] && [ "$codename" = bullseye ] && have apt-get; then
            notes+=("cmake ${v:-?} is older than 3.20; as root, run:
  echo 'deb http://deb.debian.org/debian bullseye-backports main' > /etc/apt/sources.list.d/backports.list
  apt-get update && apt-get install -y -t bullseye-backports cmake")
        else
            notes+=("cmake ${v:-?} is older than 3.20; install cmake 3.20 or newer")
        fi
    fi
}

# libpng's headers and library, as CMake's FindPNG looks for them (the build
# does not use pkg-config, so neither does this).
have_libpng() {
    if have pkg-config && pkg-config --exists libpng 2>/dev/null; then
        return 0
    fi
    if have dpkg-query && dpkg-query -W -f='${Status}' libpng-dev 2>/dev/null | grep -q 'ok installed'; then
        return 0
    fi
    local c=${CC:-cc} probe
    have "${c%% *}" || c=gcc
    have "${c%% *}" || return 1
    probe=$(mktemp -d) || return 1
    printf '#include <png.h>\nint main(void) { return png_access_version_number() == 0; }\n' > "$probe/p.c"
    if $c "$probe/p.c" -lpng -o "$probe/p" >/dev/null 2>&1; then
        rm -rf "$probe"
        return 0
    fi
    rm -rf "$probe"
    return 1
}

check_host() {
    check_cmake
    have make || add make
    if [ -n "${CC:-}" ]; then
        have "${CC%% *}" || notes+=("CC=$CC is not on PATH")
    elif ! have cc && ! have gcc && ! have clang; then
        add gcc libc6-dev
    fi
    have_libpng || add libpng-dev
    # Without a CA bundle the HTTPS download of the pinned Unity fails its
    # certificate check and the tests fall back to tests/unity_compat.
    [ -f /etc/ssl/certs/ca-certificates.crt ] || optional_missing+=(ca-certificates)
}

check_firmware() {
    check_cmake
    have make || add make
    if ! have arm-none-eabi-gcc; then
        add gcc-arm-none-eabi binutils-arm-none-eabi libnewlib-arm-none-eabi
        return
    fi
    # newlib provides libc.a for the example firmware; gcc prints the bare
    # name when it cannot find the file.
    local libc
    libc=$(arm-none-eabi-gcc -print-file-name=libc.a 2>/dev/null || true)
    [ -f "$libc" ] || add libnewlib-arm-none-eabi
}

check_optional() {
    have g++ || have clang++ || optional_missing+=(g++)
    have qemu-system-arm || optional_missing+=(qemu-system-arm)
    # RISC-V determinism builds (determinism.sh): the cross compiler and
    # qemu-system-riscv32/64
    have riscv64-unknown-elf-gcc || optional_missing+=(gcc-riscv64-unknown-elf)
    have qemu-system-riscv32 || optional_missing+=(qemu-system-misc)
    have gnuplot || optional_missing+=(gnuplot-nox)
    have valgrind || optional_missing+=(valgrind)
    # clang: libFuzzer target and the clang -O2 determinism build (issue 5)
    have clang || optional_missing+=(clang)
}

for group in "${groups[@]}"; do
    case "$group" in
    host) check_host ;;
    firmware) check_firmware ;;
    cppcheck) have cppcheck || add cppcheck ;;
    optional) check_optional ;;
    *) echo "deps.sh: unknown group '$group' (host, firmware, cppcheck, optional)" >&2; exit 2 ;;
    esac
done

if [ ${#notes[@]} -gt 0 ]; then
    printf 'deps.sh: %s\n' "${notes[@]}" >&2
    if [ ${#missing[@]} -gt 0 ]; then
        echo "deps.sh: also missing: ${missing[*]}; as root, run:" >&2
        echo "  apt-get update && apt-get install -y ${missing[*]}" >&2
    fi
    exit 1
fi
if [ ${#missing[@]} -eq 0 ] && [ ${#optional_missing[@]} -eq 0 ]; then
    exit 0
fi

# ---- install ----------------------------------------------------------------
all_missing=("${missing[@]}" "${optional_missing[@]}")
echo "deps.sh: missing packages: ${all_missing[*]}"

sudo_cmd=()
if ! have apt-get; then
    echo "deps.sh: no apt-get here; install the equivalent of: ${all_missing[*]}" >&2
    [ ${#missing[@]} -eq 0 ] && exit 0
    exit 1
fi
if [ "$(id -u)" -ne 0 ]; then
    if have sudo && sudo -n true 2>/dev/null; then
        # sudo's env_reset drops DEBIAN_FRONTEND: pass it through env
        sudo_cmd=(sudo -n env DEBIAN_FRONTEND=noninteractive)
    elif have sudo; then
        echo "deps.sh: not root and sudo needs a password; run:" >&2
        echo "  sudo apt-get update && sudo apt-get install -y ${all_missing[*]}" >&2
        [ ${#missing[@]} -eq 0 ] && exit 0
        exit 1
    else
        echo "deps.sh: not root and no sudo; as root, run:" >&2
        echo "  apt-get update && apt-get install -y ${all_missing[*]}" >&2
        [ ${#missing[@]} -eq 0 ] && exit 0
        exit 1
    fi
fi

export DEBIAN_FRONTEND=noninteractive
apt=("${sudo_cmd[@]}" apt-get -q -o Dpkg::Use-Pty=0)
echo "deps.sh: ${apt[*]} update"
if ! "${apt[@]}" update; then
    echo "deps.sh: '${apt[*]} update' failed (network? sources.list?)" >&2
    # only optional packages missing (ca-certificates on an offline
    # machine): never an error
    [ ${#missing[@]} -eq 0 ] && exit 0
    exit 1
fi

if [ ${#missing[@]} -gt 0 ]; then
    echo "deps.sh: ${apt[*]} install -y --no-install-recommends ${missing[*]}"
    if ! "${apt[@]}" install -y --no-install-recommends "${missing[@]}"; then
        echo "deps.sh: installing ${missing[*]} failed" >&2
        exit 1
    fi
fi
# Optional packages one at a time, so one that this release lacks does not
# stop the others.
for pkg in "${optional_missing[@]}"; do
    if ! "${apt[@]}" install -y --no-install-recommends "$pkg"; then
        echo "deps.sh: optional package $pkg not installed (continuing)" >&2
    fi
done

# Re-check what was required.
missing=()
notes=()
for group in "${groups[@]}"; do
    case "$group" in
    host) check_host ;;
    firmware) check_firmware ;;
    cppcheck) have cppcheck || add cppcheck ;;
    esac
done
if [ ${#missing[@]} -gt 0 ] || [ ${#notes[@]} -gt 0 ]; then
    echo "deps.sh: still missing after install: ${missing[*]-} ${notes[*]-}" >&2
    exit 1
fi
echo "deps.sh: ok"
