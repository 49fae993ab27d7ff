#!/bin/sh
# run_c_api_vulkan.sh - test_c_api_vulkan: the C API on a Vulkan sampler.  The
# C++ API's bits on OpenCL and on Vulkan (cpp_dump, cpp_dump ... vulkan),
# then the C program on Vulkan against both (c_consumer vulkan), run with an
# empty OCL_ICD_VENDORS: no OpenCL platform is needed.
# Usage: run_c_api_vulkan.sh CPP_DUMP C_CONSUMER USER_SAMPLER_DIR WORK_PARENT
set -eu
cpp_dump=$1 consumer=$2 user_dir=$3 work_parent=$4
mkdir -p "$work_parent"
work=$(mktemp -d "$work_parent/run-vulkan.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/no-vendors"
"$cpp_dump" "$work/opencl.f32" "$user_dir"
"$cpp_dump" "$work/vulkan.f32" "$user_dir" vulkan
OCL_ICD_VENDORS="$work/no-vendors" "$consumer" vulkan "$work/opencl.f32" "$work/vulkan.f32" "$user_dir"
