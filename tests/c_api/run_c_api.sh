#!/bin/sh
# run_c_api.sh - test_c_api: the C++ API's bits (cpp_dump), then the C
# program against them (c_consumer bits, threads), and the statuses that need
# a process of their own: no OpenCL platform (an empty OCL_ICD_VENDORS), no
# writable cache for the device headers, host memory exhausted.
# Usage: run_c_api.sh CPP_DUMP C_CONSUMER USER_SAMPLER_DIR WORK_PARENT
# (each run works in a folder of its own under WORK_PARENT: test.sh runs the
# suite on two devices at once in one build tree).  The environment's
# GGX_C_API_CPP_DUMP, GGX_C_API_CONSUMER, GGX_USER_SAMPLERS_DIR and
# GGX_C_API_WORK_DIR, where set, come before the arguments (a copy of the
# tests run on another machine).
set -eu
cpp_dump=${GGX_C_API_CPP_DUMP:-${1-}} consumer=${GGX_C_API_CONSUMER:-${2-}}
user_dir=${GGX_USER_SAMPLERS_DIR:-${3-}} work_parent=${GGX_C_API_WORK_DIR:-${4-}}
if [ -z "$cpp_dump" ] || [ -z "$consumer" ] || [ -z "$user_dir" ] || [ -z "$work_parent" ]; then
  echo "usage: run_c_api.sh CPP_DUMP C_CONSUMER USER_SAMPLER_DIR WORK_PARENT (or their variables)" >&2
  exit 2
fi
mkdir -p "$work_parent"
work=$(mktemp -d "$work_parent/run.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/no-vendors"
"$cpp_dump" "$work/cpp-dump.f32" "$user_dir"
"$consumer" bits "$work/cpp-dump.f32" "$user_dir"
"$consumer" threads "$work/cpp-dump.f32"
OCL_ICD_VENDORS="$work/no-vendors" "$consumer" no-device
env -u GGXCL_DEVICE_INCLUDE_DIR XDG_CACHE_HOME=/dev/null/cache HOME=/dev/null TMPDIR=/dev/null "$consumer" no-cache
"$consumer" out-of-memory
