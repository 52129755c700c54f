#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (build-fuzz/) and runs them side by side for a bounded time, one worker each.
# Fails on the first crash, sanitizer report, timeout (> 10 s for one input) or memory blow-up (> 2 GiB); the
# input that did it is written to build-fuzz/artifacts/. See docs/fuzzing.md.
#   bash tests/fuzz/run_fuzzers.sh [SECONDS_PER_TARGET (default 60)] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/../.."

seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(fuzz_obj_loader fuzz_session_loader fuzz_precompute_deform)

gen=(); [ -f build-fuzz/CMakeCache.txt ] || gen=(-GNinja)  # as tests/run_all.sh: Ninja keeps both cores busy
CC=clang CXX=clang++ cmake "${gen[@]}" -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSOMICAGE_WERROR=ON \
  -DSOMICAGE_FUZZ=ON -DSOMICAGE_BUILD_EDITOR=OFF -DSOMICAGE_BUILD_TESTS=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]}"

# The seed inputs of each target (read only); what a run discovers goes to build-fuzz/corpus/TARGET.
seeds_of() {
  case $1 in
    fuzz_obj_loader) echo "-dict=tests/fuzz/obj.dict tests/data tests/fuzz/corpus/medit" ;;
    fuzz_session_loader) echo "-dict=tests/fuzz/session.dict tests/fuzz/corpus/session" ;;
    *) echo "" ;;
  esac
}

# The targets run side by side (each one worker): the run takes one target's time instead of three on two cores.
mkdir -p build-fuzz/artifacts
declare -A pids
for target in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$target"
  echo "-- $target: $seconds s"
  # shellcheck disable=SC2046  # seeds_of gives separate words on purpose
  OMP_NUM_THREADS=1 timeout $((seconds + 120)) "build-fuzz/tests/fuzz/$target" -max_total_time="$seconds" \
    -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$target-" \
    "build-fuzz/corpus/$target" $(seeds_of "$target") >"build-fuzz/$target.log" 2>&1 &
  pids[$target]=$!
done
failed=0
for target in "${targets[@]}"; do
  if wait "${pids[$target]}"; then
    echo "-- $target:"
    grep -E "^(Done|stat::number_of_executed_units)" "build-fuzz/$target.log" || true
  else
    tail -n 60 "build-fuzz/$target.log"
    echo "$target FAILED: the input is in build-fuzz/artifacts/ (replay: build-fuzz/tests/fuzz/$target FILE)" >&2
    failed=1
  fi
done
exit "$failed"
