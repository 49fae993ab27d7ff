#!/usr/bin/env bash
# check_bundle.sh - CI's check of the relocatable GPU-check bundle: writes it
# from this checkout's build (scripts/test.sh made it), moves it to another
# folder, renames the checkout away (so that no path of the source or build
# tree resolves), runs the bundle's run.sh --quick on PoCL, and renames the
# checkout back.  Fails when a step of run.sh fails or no suite ran; a skipped
# suite fails too (GGXCL_TESTS_REQUIRE_ALL).
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
[ "$status" -eq 0 ] || { echo "check_bundle: run.sh --quick failed: ctest's log follows"; cat "$work/out/ctest.log"; }
exit "$status"
