#!/usr/bin/env bash
# api_whole_process.sh - the whole `ggx` process on OpenCL and on Vulkan,
# side by side: sample (2^24 caps samples to .npy), histogram (1e8, no
# figure) and stress (every method), each run 5 times alternating the APIs;
# prints the median wall-clock seconds of each (docs/BENCHMARKS-VULKAN.md).
# Usage: bash bench/api_whole_process.sh [path/to/ggx]   (default build/apps/ggx)
# Run it on an idle machine: nothing else building or testing.
set -euo pipefail
ggx="${1:-build/apps/ggx}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
seconds() {  # the wall-clock seconds of one command
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null 2>&1
  end=$(date +%s.%N)
  echo "$end - $start" | bc
}
for round in 1 2 3 4 5; do
  for api in opencl vulkan; do
    seconds "$ggx" sample --api "$api" --method caps -n 2^24 --out "$out/s-$api.npy" >>"$out/sample-$api"
    seconds "$ggx" histogram --api "$api" --method caps -n 1e8 --no-png --out "$out/h-$api" >>"$out/histogram-$api"
    seconds "$ggx" stress --api "$api" --no-png --out "$out/t-$api" >>"$out/stress-$api"
  done
done
for job in sample histogram stress; do
  for api in opencl vulkan; do
    echo "$job $api $(sort -n "$out/$job-$api" | sed -n 3p) s"
  done
done
