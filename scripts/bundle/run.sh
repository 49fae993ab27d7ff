#!/usr/bin/env bash
# run.sh - ggxcl's check of a device, from the relocatable bundle that
# `scripts/device-check.sh --bundle DIR` writes: for a GPU node with its
# driver and CMake but no package manager.  In order, so that the first
# minute already says whether the device works:
#   1. the node's glibc and libstdc++ against what the binaries need;
#   2. the OpenCL driver (an ICD file written for NVIDIA's libnvidia-opencl.so.1
#      when none names it) and `ggx devices`;
#   3. a chi-square test of every method and of a rough dielectric;
#   4. the device test suites (CTest, this folder's CTestTestfile.cmake);
#   5. `ggx stress` and `ggx bench`;
#   6. the CUDA example built by nvcc from the same device headers, when
#      nvcc is present.
# --quick: the chi-squares, the suites' fast subset (label quick) and a
# short bench.  The device: GGXCL_DEVICE when set, else an NVIDIA device
# when one is listed, else the first.  Logs and summary.txt go to $OUT
# (default: DIR-out beside this folder).  Exit 0 when every step passed.
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
quick=0
case "${1:-}" in
  --quick) quick=1 ;;
  "") ;;
  *) echo "run.sh: unknown argument '$1': allowed is --quick or nothing" >&2; exit 2 ;;
esac
out="${OUT:-$here-out}"
mkdir -p "$out" || { echo "run.sh: cannot make the output folder $out" >&2; exit 2; }
summary="$out/summary.txt"
: >"$summary"
start=$(date +%s)
say() { echo "$*" | tee -a "$summary"; }
elapsed() { echo "$(( $(date +%s) - start )) s"; }
failures=()
failed() { failures+=("$1"); say "FAILED: $1"; }
ggx="$here/build/apps/ggx"

# True when version $1 >= $2 (dotted numbers).
version_at_least() { [ "$(printf '%s\n%s\n' "$2" "$1" | sort -V | head -1)" = "$2" ]; }

# 1. The C and C++ runtimes.
need_glibc=$(sed -n 's/^GLIBC //p' "$here/requirements.txt")
need_glibcxx=$(sed -n 's/^GLIBCXX //p' "$here/requirements.txt")
have_glibc=$(getconf GNU_LIBC_VERSION 2>/dev/null | awk '{print $2}')
if [ -z "$have_glibc" ] || ! version_at_least "$have_glibc" "$need_glibc"; then
  say "run.sh: this machine's glibc is ${have_glibc:-unknown}; the bundle needs GLIBC $need_glibc or newer (build it on an older Debian/Ubuntu, or run it in a newer container)"
  exit 1
fi
libstdcxx=$(ldconfig -p 2>/dev/null | awk '/libstdc\+\+\.so\.6 .*x86-64/ {print $NF; exit}')
for candidate in "$libstdcxx" /usr/lib/x86_64-linux-gnu/libstdc++.so.6 /usr/lib64/libstdc++.so.6; do
  [ -n "$candidate" ] && [ -e "$candidate" ] && { libstdcxx="$candidate"; break; }
done
if [ -z "$libstdcxx" ] || ! grep -qa "GLIBCXX_$need_glibcxx" "$libstdcxx"; then
  say "run.sh: this machine's libstdc++ (${libstdcxx:-not found}) lacks GLIBCXX_$need_glibcxx, which the bundle needs (GCC 12's runtime or newer)"
  exit 1
fi
say "runtimes: glibc $have_glibc (needs $need_glibc), $libstdcxx has GLIBCXX_$need_glibcxx"

# 2. The OpenCL driver: NVIDIA's, named by an ICD file of our own when the system has none.
. "$here/nvidia_icd.sh"
# (into a file, not a pipe: the function exports OCL_ICD_VENDORS); no NVIDIA driver: the system's devices
nvidia_icd "$out" >"$out/icd.txt" || true
tee -a "$summary" <"$out/icd.txt"
if ! timeout 60 "$ggx" devices >"$out/devices.txt" 2>&1; then
  cat "$out/devices.txt" | tee -a "$summary"
  say "run.sh: FAILED: ggx devices (no OpenCL device usable: see devices.txt)"
  exit 1
fi
tee -a "$summary" <"$out/devices.txt"
if [ -z "${GGXCL_DEVICE:-}" ] && grep -qi nvidia "$out/devices.txt"; then
  export GGXCL_DEVICE=nvidia
fi
say "device: ${GGXCL_DEVICE:-the first listed}"
on_gpu=0
grep -qi nvidia <<<"${GGXCL_DEVICE:-}" && on_gpu=1

# 3. Every method's samples and a rough dielectric's against their pdfs (chi-square, p >= 0.001).
samples=$([ "$on_gpu" -eq 1 ] && echo 1e8 || echo 1e6)
chi_square() {  # name, then ggx histogram's options
  local name="$1"; shift
  if timeout 120 "$ggx" histogram "$@" -n "$samples" --check 0.001 --no-png --out "$out/histogram-$name" \
      >"$out/histogram-$name.log" 2>&1; then
    say "chi-square $name: passed ($(grep -o 'p = [^ ,;]*' "$out/histogram-$name.log" | head -1))"
  else
    tail -3 "$out/histogram-$name.log" | tee -a "$summary"
    failed "chi-square $name (histogram-$name.log)"
  fi
}
for method in $("$ggx" methods --names); do
  chi_square "$method" --method "$method"
done
chi_square caps-dielectric --method caps --eta 1.5 --alpha 0.5
if [ ${#failures[@]} -eq 0 ]; then
  say "the device works: every chi-square passed after $(elapsed)"
fi

# 4. The device suites.
jobs=$(nproc 2>/dev/null || echo 2)
[ "$jobs" -gt 8 ] && jobs=8
label_args=()
[ "$quick" -eq 1 ] && label_args=(-L quick)
timeout 600 ctest --test-dir "$here" "${label_args[@]}" -j"$jobs" --timeout 240 --output-on-failure \
  >"$out/ctest.log" 2>&1
ctest_status=$?
grep -E "tests passed|tests failed|Not Run|\*\*\*|Skipped" "$out/ctest.log" | tee -a "$summary"
grep -q "tests passed" "$out/ctest.log" || failed "no suite ran (ctest.log)"
[ "$ctest_status" -eq 0 ] || failed "device suites (ctest.log)"
say "suites done after $(elapsed)"

# 5. The stability map and the bench.
if [ "$quick" -eq 0 ]; then
  if timeout 180 "$ggx" stress --no-png --out "$out/stress" >"$out/stress.log" 2>&1; then
    say "stress: $(tail -1 "$out/stress.log")"
  else
    tail -5 "$out/stress.log" | tee -a "$summary"
    failed "ggx stress (stress.log)"
  fi
fi
if [ "$quick" -eq 1 ]; then
  bench_args=(--methods caps,heitz --precisions precise --jobs write,furnace -n 2^20 --repeats 5 --no-accuracy --no-startup)
else
  bench_args=(--methods all --precisions precise,relaxed -n "$([ "$on_gpu" -eq 1 ] && echo 2^27 || echo 2^22)")
fi
if timeout 300 "$ggx" bench "${bench_args[@]}" --no-native --csv "$out/bench.csv" --markdown "$out/BENCH.md" \
    >"$out/bench.log" 2>&1; then
  sed -n '/^## Which sampler/,/^## /p' "$out/BENCH.md" | sed '$d' | tee -a "$summary"
else
  tail -5 "$out/bench.log" | tee -a "$summary"
  failed "ggx bench (bench.log)"
fi
say "bench done after $(elapsed)"

# 6. The device headers as CUDA, built by nvcc for the GPU it finds.
nvcc_bin="$(command -v nvcc || echo /usr/local/cuda/bin/nvcc)"
if [ "$quick" -eq 1 ]; then
  say "CUDA example: left to the full run"
elif [ -x "$nvcc_bin" ]; then
  if timeout 180 "$nvcc_bin" -std=c++17 -O2 -I"$here/src/kernels" "$here/src/examples/cuda/cuda_sample.cu" \
      -o "$out/cuda_sample" >"$out/cuda-build.log" 2>&1 && timeout 60 "$out/cuda_sample" >"$out/cuda-sample.txt" 2>&1; then
    tee -a "$summary" <"$out/cuda-sample.txt"
  else
    tail -10 "$out/cuda-build.log" "$out/cuda-sample.txt" 2>/dev/null | tee -a "$summary"
    failed "CUDA example (cuda-build.log, cuda-sample.txt)"
  fi
else
  say "nvcc not found: the CUDA example was skipped"
fi

if [ ${#failures[@]} -gt 0 ]; then
  say "run.sh: FAILED after $(elapsed): ${failures[*]}"
  exit 1
fi
say "run.sh: PASSED after $(elapsed)"
