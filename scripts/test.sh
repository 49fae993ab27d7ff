#!/usr/bin/env bash
# test.sh - builds ggxcl and runs the whole test suite on the default OpenCL
# device (PoCL on the CPU unless GGXCL_DEVICE names another) and, at the
# same time, every suite labelled `device` again on Mesa rusticl over
# llvmpipe (RUSTICL_ENABLE=llvmpipe GGXCL_DEVICE=rusticl), then the fuzz
# targets for a few seconds each.  rusticl's program binaries are cached in
# build/program-cache for this build only (GGXCL_PROGRAM_CACHE); PoCL keeps
# its own.
# Usage: bash scripts/test.sh [ctest arguments for both passes]
set -euo pipefail
cd "$(dirname "$0")/.."
# Everything the tests need is installed here (scripts/install-deps.sh): a
# missing prerequisite fails its test case instead of skipping it
# (tests/helpers/skip.hpp).
export GGXCL_TESTS_REQUIRE_ALL=1
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGGXCL_BUILD_TESTS=ON -DGGXCL_BUILD_PYTHON=ON
cmake --build build -j"$(nproc)"
jobs="$(nproc)"

# rusticl in the background, its report printed after PoCL's.
rusticl_log=build/ctest-rusticl.log
( RUSTICL_ENABLE=llvmpipe GGXCL_DEVICE=rusticl GGXCL_PROGRAM_CACHE="$PWD/build/program-cache" \
    ctest --test-dir build --output-on-failure -L device -j"$jobs" "$@" >"$rusticl_log" 2>&1 ) &
rusticl_pid=$!
pocl_status=0
echo "== the whole suite on the default device (PoCL)"
ctest --test-dir build --output-on-failure -j"$jobs" "$@" || pocl_status=$?
rusticl_status=0
wait "$rusticl_pid" || rusticl_status=$?
echo "== the device suites on Mesa rusticl (llvmpipe)"
cat "$rusticl_log"
if [ "$pocl_status" -ne 0 ] || [ "$rusticl_status" -ne 0 ]; then
  echo "test.sh: failures (PoCL pass exit $pocl_status, rusticl pass exit $rusticl_status)"
  exit 1
fi
bash scripts/fuzz.sh 15   # the libFuzzer targets, briefly (fuzz/)
