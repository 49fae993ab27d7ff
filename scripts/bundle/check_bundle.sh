#!/usr/bin/env bash
# check_bundle.sh - CI's check of the relocatable GPU-check bundle: writes it
# from this checkout's build (scripts/test.sh made it), moves it to another
# folder, renames the checkout away (so that no path of the source or build
# tree resolves), runs the bundle's run.sh --quick on PoCL, and renames the
# checkout back.  Fails when a step of run.sh fails or no suite ran; a skipped
# suite fails too (GGXCL_TESTS_REQUIRE_ALL).  Then, as on a GPU node without
# three.js or a Python with matplotlib, the suites that use them must pass
# with those cases skipped, each naming what is missing.
# Usage: bash scripts/bundle/check_bundle.sh
set -euo pipefail
repo="$(cd "$(dirname "$0")/../.." && pwd)"
work="$(mktemp -d)"
python3 "$repo/scripts/bundle/make_bundle.py" --build "$repo/build" --source "$repo" --out "$work/made"
mkdir "$work/elsewhere"
mv "$work/made" "$work/elsewhere/bundle"
away="$repo.away-$$"
mv "$repo" "$away"
trap 'mv "$away" "$repo"; rm -rf "$work"' EXIT
cd "$work"
status=0
GGXCL_TESTS_REQUIRE_ALL=1 GGXCL_DEVICE=pthread OUT="$work/out" bash "$work/elsewhere/bundle/run.sh" --quick || status=$?
[ "$status" -eq 0 ] || { echo "check_bundle: run.sh --quick failed: ctest's log follows"; cat "$work/out/ctest.log"; exit "$status"; }

# Neither three.js nor matplotlib: GGX_THREE_DIR names an empty folder, GGX_PYTHON a program that fails.
mkdir -p "$work/no-three"
log="$work/out/bare.log"
GGXCL_DEVICE=pthread GGX_THREE_DIR="$work/no-three" GGX_PYTHON=/bin/false \
  ctest --test-dir "$work/elsewhere/bundle" -R '^(test_cli|test_converge|test_histogram_cli|test_user_sampler_cli)$' \
  -j"$(nproc)" -V >"$log" 2>&1 || status=$?
grep -E "tests passed|tests failed|Skipped|Passed|Failed" "$log" || true
if [ "$status" -ne 0 ] || ! grep -q "100% tests passed" "$log" || ! grep -q "needs three.js" "$log" ||
   ! grep -q "needs a Python with numpy and matplotlib" "$log"; then
  echo "check_bundle: without three.js and matplotlib some suite failed or skipped nothing: its log follows"
  cat "$log"
  exit 1
fi
echo "check_bundle: without three.js and matplotlib the suites pass, the cases that need them skipped"
