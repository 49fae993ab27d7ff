#!/usr/bin/env bash
# run_examples.sh - the test_readme_examples CTest test: every block of the
# README marked `<!-- example: sh -->`, `<!-- example: python -->` or
# `<!-- example: file NAME -->` runs as written, in order, in a fresh folder
# (a file block is written to NAME for the blocks after it), as a user who
# built ggxcl has it: `ggx` on PATH, the Python module importable, and the
# device headers installed alone to a prefix that PKG_CONFIG_PATH names.
# Fails on the first block that fails, printing it; and when the README has
# no example of a kind (a marker lost in an edit).
# Usage: run_examples.sh README GGX_DIR PYTHON PYTHON_DIR SOURCE_DIR
set -euo pipefail
readme=$1 ggx_dir=$2 python=$3 python_dir=$4 source_dir=$5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake -S "$source_dir" -B "$work/headers-build" -DGGXCL_DEVICE_HEADERS_ONLY=ON >/dev/null
cmake --install "$work/headers-build" --prefix "$work/prefix" >/dev/null
export PKG_CONFIG_PATH="$(ls -d "$work"/prefix/lib*/pkgconfig)"
export PATH="$ggx_dir:$PATH" PYTHONPATH="$python_dir"
mkdir "$work/user" && cd "$work/user"

# The marked blocks as records: kind, argument, then the block's lines, ended by a NUL.
"$python" - "$readme" >"$work/blocks" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
for m in re.finditer(r"<!-- example: (\w+) ?(\S*) -->\n```\w*\n(.*?)```", text, re.S):
    sys.stdout.write(f"{m.group(1)}\t{m.group(2)}\n{m.group(3)}\0")
PY
declare -A seen
while IFS= read -r -d '' record; do
  header=${record%%$'\n'*} body=${record#*$'\n'}
  kind=${header%%$'\t'*} arg=${header#*$'\t'}
  seen[$kind]=1
  echo "== README example ($kind $arg)"
  case $kind in
    sh) bash -euo pipefail -c "$body" || { echo "failed:"; echo "$body"; exit 1; } ;;
    python) "$python" -c "$body" || { echo "failed:"; echo "$body"; exit 1; } ;;
    file) printf '%s' "$body" >"$arg" ;;
    *) echo "unknown example kind '$kind'"; exit 1 ;;
  esac
done <"$work/blocks"
for kind in sh python file; do
  [ -n "${seen[$kind]:-}" ] || { echo "the README has no '$kind' example"; exit 1; }
done
echo "every README example ran"
