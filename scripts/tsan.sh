#!/usr/bin/env bash
# tsan.sh - builds the host code of the threaded tests (library, reference,
# test helpers, test_threads: 8 threads sharing Samplers; test_backend_threads:
# 8 threads sharing one Backend, on OpenCL and on Vulkan (lavapipe, outside
# the validation layer); test_runtime: a
# range split across samplers in threads; test_c_api: four C threads sharing
# one sampler of the C API) with ThreadSanitizer in
# build-tsan/ and runs them on PoCL.  Any report fails the run; none is
# suppressed (the OpenCL stack is not instrumented, and PoCL's threads
# reported nothing through the interceptors).
# Usage: bash scripts/tsan.sh [ctest arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
# Everything the tests need is installed here (scripts/install-deps.sh): a
# missing prerequisite fails its test case instead of skipping it
# (tests/helpers/skip.hpp).
export GGXCL_TESTS_REQUIRE_ALL=1
flags="-fsanitize=thread -fno-omit-frame-pointer"
cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DCMAKE_C_FLAGS_DEBUG="-O1 -g1" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread" \
  -DGGXCL_BUILD_PYTHON=OFF >/dev/null
cmake --build build-tsan -j"$(nproc)" --target test_threads test_backend_threads test_runtime test_c_api_cpp_dump test_c_api_consumer
icd_dir="$PWD/build-tsan/icd-pocl-only"
mkdir -p "$icd_dir"
cp /etc/OpenCL/vendors/pocl.icd "$icd_dir/"
export OCL_ICD_VENDORS="$icd_dir"
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"
ctest --test-dir build-tsan --output-on-failure -R '^test_(threads|backend_threads|runtime|c_api)$' "$@"
# The Backend's threads on Vulkan (lavapipe), without the validation layer: the layer's own
# threads are not instrumented, and TSan reports races between its internals (its delete against
# its rwlock) that no call of ours is part of.
echo "test_backend_threads on Vulkan (GGX_TEST_API=vulkan, no validation layer)"
GGX_TEST_API=vulkan build-tsan/tests/test_backend_threads
