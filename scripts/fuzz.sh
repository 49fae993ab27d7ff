#!/usr/bin/env bash
# fuzz.sh - builds the libFuzzer targets of fuzz/ (clang++-15 with
# AddressSanitizer and UndefinedBehaviorSanitizer, in build-fuzz/) and runs
# each for SECONDS (default 15) from a copy of its seed corpus in
# fuzz/corpus/<target>.  A finding stops it with a non-zero status and
# leaves the input in build-fuzz/.  Usage: bash scripts/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-15}"
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++-15 -DGGXCL_BUILD_FUZZERS=ON >/dev/null
cmake --build build-fuzz -j"$(nproc)"
for target in npy sidecar values cli; do
  work="$(mktemp -d)"
  cp fuzz/corpus/"$target"/* "$work"/
  echo "fuzz_$target: ${seconds} s"
  status=0
  build-fuzz/fuzz/fuzz_"$target" -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix=build-fuzz/ "$work" >build-fuzz/fuzz_"$target".log 2>&1 || status=$?
  grep -E "stat::number_of_executed_units|ERROR|SUMMARY|Test unit" build-fuzz/fuzz_"$target".log || true
  rm -rf "$work"
  [ "$status" -eq 0 ] || { echo "fuzz_$target found a failing input (see build-fuzz/)"; exit 1; }
done
