#!/usr/bin/env bash
# compile_examples.sh - examples/glsl and examples/hlsl compiled as their
# files say (glslangValidator, the device headers by -I), each module checked
# by spirv-val for Vulkan 1.1.  Fails on any error or warning.
# Usage: compile_examples.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir="$1"
work="$2"
mkdir -p "$work"
kernels="$source_dir/kernels"
check() {  # NAME COMMAND...: the command must succeed and print nothing but the file's name
  local name="$1"
  shift
  local output
  output="$("$@" 2>&1)" || { echo "$name failed:"; echo "$output"; exit 1; }
  [ -z "$output" ] || { echo "$name printed:"; echo "$output"; exit 1; }
  echo "$name: ok"
}
check "glsl/furnace.comp" glslangValidator --quiet -V -I"$kernels" "$source_dir/examples/glsl/furnace.comp" \
  -o "$work/furnace_glsl.spv"
check "hlsl/furnace.hlsl" glslangValidator --quiet -V -D -e main -S comp --target-env vulkan1.1 -DGGX_HLSL=1 \
  -I"$kernels" "$source_dir/examples/hlsl/furnace.hlsl" -o "$work/furnace_hlsl.spv"
check "spirv-val glsl" spirv-val --target-env vulkan1.1 "$work/furnace_glsl.spv"
check "spirv-val hlsl" spirv-val --target-env vulkan1.1 "$work/furnace_hlsl.spv"
