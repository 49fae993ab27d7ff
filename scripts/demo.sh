#!/usr/bin/env bash
# demo.sh - installs what is missing, builds ggxcl and runs the main job:
# samples of every method for alpha 0.3, view at 60 degrees, in ./ggx-demo.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
./build/apps/ggx demo --out ggx-demo "$@"
