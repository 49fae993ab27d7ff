#!/usr/bin/env bash
# test.sh - builds ggxcl and runs the whole test suite on the default
# OpenCL device (PoCL on the CPU unless GGXCL_DEVICE names another), then
# the fuzz targets for a few seconds each.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
bash scripts/fuzz.sh 15   # the libFuzzer targets, briefly (fuzz/)
