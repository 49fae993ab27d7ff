#!/usr/bin/env bash
# device-check.sh - one prepared check of ggxcl on a Linux machine with an
# NVIDIA GPU and its OpenCL driver: builds ggxcl, runs the device test
# suites on the GPU (GGXCL_DEVICE=nvidia), then a short `ggx bench` (caps,
# heitz and caps-iso; write, fused furnace and world space; measured ratios
# beside docs/DEVICES.md's static predictions), ggx-limits (% of the GPU's
# limits) and, where nvcc is installed,
# the CUDA example built from the same device headers, in under 8 minutes.  It fails
# with a clear message, never hangs, when there is no GPU, no OpenCL ICD
# for it, or a missing build tool.  When the driver is installed but no ICD
# file names it, one is written to a private vendors folder
# (OCL_ICD_VENDORS) from the driver's libnvidia-opencl.so.1.
# Everything it prints and writes goes to $OUT (default ./device-check-out):
# summary.txt, the logs of each step, the bench report.
# Usage: bash scripts/device-check.sh
#        bash scripts/device-check.sh --bundle DIR
# --bundle, on the Debian build machine: builds ggxcl with its tests and
# writes DIR, a relocatable folder (scripts/bundle/make_bundle.py) to carry
# to a GPU node that has no package manager and run there: DIR/run.sh
# [--quick] (scripts/bundle/run.sh; docs/DEVICES.md).
set -uo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--bundle" ]; then
  [ -n "${2:-}" ] || { echo "device-check.sh: --bundle needs a folder: --bundle DIR" >&2; exit 2; }
  set -e
  bash scripts/install-deps.sh
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGGXCL_BUILD_TESTS=ON
  cmake --build build -j"$(nproc)"
  exec python3 scripts/bundle/make_bundle.py --build build --source . --out "$2"
fi
out="${OUT:-$PWD/device-check-out}"
mkdir -p "$out"
summary="$out/summary.txt"
: >"$summary"
say() { echo "$*" | tee -a "$summary"; }
fail() { say "device-check: FAILED: $*"; exit 1; }
step_start=$(date +%s)
elapsed() { echo "$(( $(date +%s) - step_start )) s"; }

# 1. The GPU and its driver.
if command -v nvidia-smi >/dev/null 2>&1; then
  timeout 30 nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader >"$out/gpu.txt" 2>&1 ||
    fail "nvidia-smi did not answer within 30 s (see gpu.txt)"
  say "GPU: $(head -1 "$out/gpu.txt")"
else
  say "nvidia-smi not found: looking for the OpenCL driver anyway"
fi
. scripts/bundle/nvidia_icd.sh
# (into a file, not a subshell: the function exports OCL_ICD_VENDORS)
nvidia_icd "$out" >"$out/icd.txt" ||
  fail "no NVIDIA OpenCL driver: no ICD file names it and libnvidia-opencl.so.1 is not installed"
tee -a "$summary" <"$out/icd.txt"

# 2. Build tools and build.
missing=""
for tool in cmake c++ make; do command -v "$tool" >/dev/null 2>&1 || missing="$missing $tool"; done
[ -z "$missing" ] || fail "missing build tools:$missing (Debian: bash scripts/install-deps.sh)"
# NVIDIA keeps compiled programs itself: the library adds no cache of its own there.
if ! timeout 60 cmake -S . -B build-gpu -DCMAKE_BUILD_TYPE=Release >"$out/configure.log" 2>&1; then
  tail -20 "$out/configure.log" | tee -a "$summary"
  fail "cmake configure (see configure.log; on Debian: bash scripts/install-deps.sh)"
fi
if ! timeout 140 cmake --build build-gpu -j"$(nproc)" >"$out/build.log" 2>&1; then
  tail -30 "$out/build.log" | tee -a "$summary"
  fail "build (see build.log)"
fi
say "built in $(elapsed)"

# 3. The GPU must be an OpenCL device.
timeout 30 build-gpu/apps/ggx devices >"$out/devices.txt" 2>&1 || { cat "$out/devices.txt" | tee -a "$summary"; fail "ggx devices"; }
cat "$out/devices.txt" | tee -a "$summary"
grep -qi nvidia "$out/devices.txt" || fail "no NVIDIA OpenCL device listed (see devices.txt)"
export GGXCL_DEVICE=nvidia

# 4. The device suites on the GPU.
timeout 180 ctest --test-dir build-gpu -L 'device|cross' -j"$(( $(nproc) < 8 ? $(nproc) : 8 ))" --timeout 170 \
  --output-on-failure >"$out/ctest.log" 2>&1
ctest_status=$?
grep -E "tests passed|tests failed|\*\*\*|Passed|Failed" "$out/ctest.log" | tee -a "$summary"
say "suites done after $(elapsed) (exit $ctest_status)"

# 5. A short bench: caps, heitz and caps-iso, write, furnace and world space, with accuracy, and the
#    measured speed ratios beside the static predictions of docs/DEVICES.md (instruction counts of
#    the PTX); each write and furnace job's % of the GPU's own limits (ggx-limits: the compute limit
#    needs clang 15 for the op counts, else the bandwidth limit alone); the driver's SPIR-V (IL) version.
timeout 90 build-gpu/apps/ggx bench --methods caps,heitz,caps-iso --precisions precise,relaxed \
  --jobs write,furnace,world -n 2^22 --repeats 5 --no-startup --scene 8 --csv "$out/bench.csv" \
  --markdown "$out/BENCH.md" --charts "$out/bench" >"$out/bench.log" 2>&1
bench_status=$?
sed -n '/## Speed (ns per sample)/,/## Speed against numerical error/p' "$out/BENCH.md" 2>/dev/null | tee -a "$summary"
python3 scripts/predicted_vs_measured.py "$out/bench.csv" docs/DEVICES.md 2>&1 | tee -a "$summary"
timeout 60 build-gpu/bench/limits/ggx-limits --methods caps,heitz,caps-iso -n 2^22 --repeats 5 \
  --csv "$out/limits.csv" --markdown "$out/LIMITS.md" >"$out/limits.log" 2>&1 || bench_status=$?
sed -n '/^| method | job | measured/,/^$/p' "$out/LIMITS.md" 2>/dev/null | tee -a "$summary"
if command -v clinfo >/dev/null; then
  clinfo 2>/dev/null | grep -E "Device Name|IL version" | tee -a "$summary"
else
  say "clinfo not installed: the driver's IL (SPIR-V) version not read"
fi
say "bench done after $(elapsed) (exit $bench_status)"

# 6. The device headers as CUDA: examples/cuda built by nvcc and run on the GPU.
cuda_status=0
nvcc_bin="$(command -v nvcc || echo /usr/local/cuda/bin/nvcc)"
if [ -x "$nvcc_bin" ]; then
  if timeout 120 "$nvcc_bin" -std=c++17 -O2 -Ikernels examples/cuda/cuda_sample.cu -o build-gpu/cuda_sample \
      >"$out/cuda-build.log" 2>&1; then
    timeout 60 build-gpu/cuda_sample >"$out/cuda-sample.txt" 2>&1
    cuda_status=$?
    cat "$out/cuda-sample.txt" | tee -a "$summary"
  else
    cuda_status=1
    tail -20 "$out/cuda-build.log" | tee -a "$summary"
  fi
  say "CUDA example done after $(elapsed) (exit $cuda_status)"
else
  say "nvcc not found: the CUDA example was not built"
fi

[ "$ctest_status" -eq 0 ] || fail "device suites (see ctest.log)"
[ "$bench_status" -eq 0 ] || fail "bench (see bench.log)"
[ "$cuda_status" -eq 0 ] || fail "CUDA example (see cuda-build.log, cuda-sample.txt)"
say "device-check: PASSED in $(elapsed)"
