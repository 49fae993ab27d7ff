#!/usr/bin/env bash
# install-deps.sh - installs the Debian 12 packages ggxcl needs to build,
# run and test, skipping those already present; with --demo only those the
# demo needs (scripts/demo.sh).  Runs apt-get as root (or through sudo).
# PoCL is the default OpenCL device: it needs no hardware.
set -euo pipefail

# What `ggx demo` needs: the library and the ggx tool, the figures, the page.
demo_packages=(
  g++ cmake make                      # toolchain
  pocl-opencl-icd ocl-icd-opencl-dev  # OpenCL: PoCL CPU device + ICD loader
  opencl-c-headers opencl-clhpp-headers
  librandom123-dev                    # Philox reference (host)
  libboost-math-dev                   # chi-square distribution, Gauss-Legendre nodes
  libcli11-dev nlohmann-json3-dev     # CLI parsing, JSON sidecars
  libcmark-gfm-dev libcmark-gfm-extensions-dev  # the reports' Markdown as web pages (GitHub's CommonMark, tables)
  libjs-three                         # three.js r111 for the pages' 3-D sample clouds (copied beside each page)
  python3-matplotlib python3-numpy    # histogram figures (ggx histogram, ggx demo)
)
# What the whole test suite needs besides.
test_packages=(
  mesa-opencl-icd                     # Mesa rusticl (llvmpipe with RUSTICL_ENABLE=llvmpipe): a second CPU implementation
  oclgrind                            # simulated device that checks every access (test_oclgrind)
  doctest-dev                         # tests
  python3-dev pybind11-dev python3-pytest python3-pyopencl  # the ggxcl Python module and its tests
  python3-skbuild python3-pip python3-venv  # pip install . (scikit-build classic), offline
  libstb-dev                          # PNG decoding in the tests, PNG encoding in examples/albedo_table
  pkgconf                             # the install test builds a consumer with pkg-config
  patchelf                            # $ORIGIN run paths in the relocatable GPU-check bundle (device-check.sh --bundle)
  clang-15                            # the device headers as C++ and CUDA (test_languages); ggx-limits' op counts
  libclc-15-dev llvm-spirv-15 spirv-tools  # every program for AMD, NVPTX and SPIR-V targets (test_gpu_compilers)
  openmpi-bin libopenmpi-dev          # mpirun for test_mpi_shards (ggx itself links no MPI)
  slurm-wlm munge                     # a one-node Slurm started by test_slurm_cluster
  chromium chromium-driver python3-selenium  # the report pages in a headless browser (test_pages)
  glslang-tools glslang-dev libshaderc-dev  # the device headers as GLSL and HLSL: glslangValidator, shaderc (tests/vulkan)
  libvulkan-dev mesa-vulkan-drivers   # Vulkan-Hpp and Mesa's lavapipe, a Vulkan device on the CPU (lib/src/vulkan, tests/vulkan)
  vulkan-validationlayers             # the Khronos validation layer every Vulkan suite runs under
)

# --demo: the demo's packages only; else everything.
packages=("${demo_packages[@]}")
[ "${1:-}" = "--demo" ] || packages+=("${test_packages[@]}")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
