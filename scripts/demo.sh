#!/usr/bin/env bash
# demo.sh - installs what the demo needs and is missing, builds the library
# and the ggx tool (no tests, no Python module) and runs the main job:
# samples of every method for alpha 0.3, view at 60 degrees, in ./ggx-demo,
# with index.html, the page to open in a browser.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --demo
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGGXCL_BUILD_TESTS=OFF -DGGXCL_BUILD_PYTHON=OFF
cmake --build build -j"$(nproc)" --target ggx
./build/apps/ggx demo --out ggx-demo "$@"
echo "demo.sh: the Python module was left out of this build; for it (pybind11, NumPy): bash scripts/install-deps.sh && cmake -S . -B build -DGGXCL_BUILD_PYTHON=ON && cmake --build build -j$(nproc) --target _ggxcl, then PYTHONPATH=build/python python3 (or pip install . : docs/PYTHON.md)"
