# Makefile - a thin wrapper around CMake. `make help` lists the targets.
#
# Every target first runs scripts/deps.sh, which returns at once when the
# tools are there and otherwise installs them (Debian/Ubuntu) or says how.
# Variables you may override:  make test JOBS=8 CMAKE_ARGS=-DFXL_WERROR=OFF

BUILD_DIR  ?= build
ASAN_DIR   ?= build-asan
FW_CPUS    ?= cortex-m0plus cortex-m4
# RISC-V -march strings cross-built too when riscv64-unknown-elf-gcc exists
FW_RV_CPUS ?= rv32imac
RV_PREFIX  ?= riscv64-unknown-elf-
BUILD_TYPE ?= RelWithDebInfo
JOBS       ?= $(shell nproc 2>/dev/null || echo 2)
CTEST_JOBS ?= 2
CMAKE      ?= cmake
CTEST      ?= ctest
CMAKE_ARGS ?=
ARM_PREFIX ?= arm-none-eabi-
GALLERY    ?= out

SHELL := /bin/bash
.SHELLFLAGS := -eu -o pipefail -c
# The targets configure and build the same directories; never overlap them.
.NOTPARALLEL:
.DEFAULT_GOAL := build

# CMake runs its own make; keep ours (jobserver, -j, -n) out of it.
RUN := env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL

.PHONY: all build configure run test firmware bench stability sanitize msan cppcheck \
        clean help deps deps-firmware

all: build

help:
	@echo "make [build]    configure $(BUILD_DIR)/ ($(BUILD_TYPE), -O2) and build everything"
	@echo "make run        build, then $(BUILD_DIR)/bin/fixel-sim --gallery $(GALLERY)"
	@echo "make test       build, then ctest --output-on-failure -j$(CTEST_JOBS)"
	@echo "make firmware   cross-build the core for $(FW_CPUS) (build-fw-*),"
	@echo "                and $(FW_RV_CPUS) where $(RV_PREFIX)gcc exists;"
	@echo "                print sizes, check the archives use no libc"
	@echo "make bench      build, then host_sim/scripts/bench.sh and the stability sweeps"
	@echo "make stability  build, then host_sim/scripts/stability.sh"
	@echo "make sanitize   ASan+UBSan Debug build in $(ASAN_DIR)/ and ctest there"
	@echo "make msan       MemorySanitizer (clang) build in build-msan/: tests, fuzz, sweeps"
	@echo "make cppcheck   static analysis of src/ and port/ (informational)"
	@echo "make clean      remove the build directories and $(GALLERY)/"

deps:
	@scripts/deps.sh host

deps-firmware:
	@scripts/deps.sh firmware

configure: deps
	$(RUN) $(CMAKE) -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) $(CMAKE_ARGS)

build: configure
	$(RUN) $(CMAKE) --build $(BUILD_DIR) -j $(JOBS)

run: build
	$(BUILD_DIR)/bin/fixel-sim --gallery $(GALLERY)

test: build
	cd $(BUILD_DIR) && $(RUN) $(CTEST) --output-on-failure -j$(CTEST_JOBS)

# $(call fw_core,CPU,DIR,TOOLCHAIN FILE,PREFIX,EXTRA CMAKE ARGS): one cross
# build of the core and the port layer (MinSizeRel), its sizes and the
# no-libc check; shell text for the loops below (CPU and DIR may be $$vars).
fw_core = echo "==== firmware: $(1) in $(2)"; \
  $(RUN) $(CMAKE) -S . -B $(2) "-DCMAKE_TOOLCHAIN_FILE=$(CURDIR)/cmake/$(3)" \
    -DFXL_BUILD_HOST=OFF -DFXL_CPU=$(1) $(5) -DCMAKE_BUILD_TYPE=MinSizeRel $(CMAKE_ARGS); \
  $(RUN) $(CMAKE) --build $(2) -j $(JOBS); \
  archives=""; \
  for lib in fixel fixel_port; do \
    if [ -f $(2)/lib/lib$$lib.a ]; then archives="$$archives $(2)/lib/lib$$lib.a"; fi; \
  done; \
  if [ -z "$$archives" ]; then \
    echo "make firmware: no archive was built in $(2)/lib"; \
    exit 1; \
  fi; \
  $(4)size -t $$archives; \
  NM=$(4)nm FXL_FREESTANDING_STRICT=1 scripts/check_freestanding.sh $$archives

# One build directory per CPU: build-fw-m0plus, build-fw-m4, ...,
# build-fw-rv32imac.
firmware: deps-firmware
	@for cpu in $(FW_CPUS); do \
	  $(call fw_core,$$cpu,build-fw-$${cpu#cortex-},arm-none-eabi.cmake,$(ARM_PREFIX),); \
	done
	@# RISC-V: optional (the issue's targets are the Cortex-M ones)
	@if ! command -v $(RV_PREFIX)gcc >/dev/null 2>&1; then \
	  echo "==== firmware: $(RV_PREFIX)gcc not found (apt-get install gcc-riscv64-unknown-elf): RISC-V skipped"; \
	  exit 0; \
	fi; \
	for cpu in $(FW_RV_CPUS); do \
	  $(call fw_core,$$cpu,build-fw-$$cpu,riscv64-unknown-elf.cmake,$(RV_PREFIX),-DFXL_RISCV_PREFIX=$(RV_PREFIX)); \
	done

bench: build
	FXL_BUILD_DIR=$(BUILD_DIR) FXL_BIN_DIR=$(BUILD_DIR)/bin bash host_sim/scripts/bench.sh
	@# issue 5: the stability sweeps are part of the benchmark too
	FXL_BUILD_DIR=$(BUILD_DIR) FXL_BIN_DIR=$(BUILD_DIR)/bin bash host_sim/scripts/stability.sh

stability: build
	FXL_BUILD_DIR=$(BUILD_DIR) FXL_BIN_DIR=$(BUILD_DIR)/bin bash host_sim/scripts/stability.sh

sanitize: deps
	$(RUN) $(CMAKE) -S . -B $(ASAN_DIR) -DCMAKE_BUILD_TYPE=Debug -DFXL_SANITIZE=ON $(CMAKE_ARGS)
	$(RUN) $(CMAKE) --build $(ASAN_DIR) -j $(JOBS)
	cd $(ASAN_DIR) && $(RUN) $(CTEST) --output-on-failure -j$(CTEST_JOBS)

# Reads of uninitialised memory (clang's MemorySanitizer); skips without clang.
msan: deps
	JOBS=$(JOBS) bash host_sim/scripts/msan.sh

# Informational: findings are printed, never fail the target.
cppcheck:
	@scripts/deps.sh cppcheck || { echo "make cppcheck: cppcheck unavailable, skipped"; exit 0; }
	@if command -v cppcheck >/dev/null; then \
	  cppcheck --std=c99 --language=c --enable=warning,style,performance,portability \
	    --inline-suppr --quiet --suppress=missingIncludeSystem \
	    -I include -I src -I port src port || true; \
	fi

# Every build tree and log the Makefile and the scripts make (build-*/ and
# build-*.log: bench, stability, configuration tests, CI's extra build types).
clean:
	rm -rf $(BUILD_DIR) $(ASAN_DIR) $(foreach cpu,$(FW_CPUS),build-fw-$(patsubst cortex-%,%,$(cpu))) $(GALLERY)
	rm -rf build-*/ build-*.log
