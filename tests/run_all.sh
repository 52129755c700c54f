#!/usr/bin/env bash
# Builds everything with warnings as errors and runs every test, then builds the core once more under
# AddressSanitizer + UndefinedBehaviorSanitizer and runs the core tests again, then runs each libFuzzer target for
# 40 s (clang, tests/fuzz/run_fuzzers.sh). This is the README's test command and what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."

# Each step's header carries the seconds since the start and the CPU seconds of all commands run so far (user +
# system), so a CI log shows where its time went, also on a machine that other work slows down.
# (/proc/PID/stat fields 14-17: this shell's and its finished children's user and system clock ticks.)
cpu_seconds() { awk -v hz="$(getconf CLK_TCK)" '{ printf "%.0f", ($14 + $15 + $16 + $17) / hz }' "/proc/$$/stat"; }
phase() { echo "== $1 (at ${SECONDS} s, CPU $(cpu_seconds) s)"; }

phase "dependencies"
bash third_party/install-deps.sh
jobs=$(nproc)
# Ninja compiles a target's objects while the libraries it links are still being built (make waits for them), so
# both cores stay busy until the end. A build folder configured before with another generator keeps it.
generator() { [ -f "$1/CMakeCache.txt" ] || echo "-GNinja"; }

phase "build (Release, -Werror)"
cmake $(generator build) -S . -B build -DCMAKE_BUILD_TYPE=Release -DSOMICAGE_WERROR=ON >/dev/null
cmake --build build -j"$jobs"
phase "tests"
ctest --test-dir build --output-on-failure -j"$jobs"

# GCC, not clang (which compiles it in about 30 % less CPU time): under clang the core builds only the baseline
# copies of the SIMD kernels (base/cpu_dispatch.h), so the AVX2 and AVX-512 copies this machine runs would go
# unchecked (docs/building.md).
phase "core tests under ASan + UBSan"
cmake $(generator build-sanitize) -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSOMICAGE_WERROR=ON \
  -DSOMICAGE_SANITIZE=ON -DSOMICAGE_BUILD_EDITOR=OFF >/dev/null
cmake --build build-sanitize -j"$jobs" --target somicage_core_tests
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-sanitize --output-on-failure -j"$jobs" -L core

phase "fuzzing (40 s per target)"
bash tests/fuzz/run_fuzzers.sh 40
phase "done"
