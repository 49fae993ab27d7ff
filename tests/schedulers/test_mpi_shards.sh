#!/usr/bin/env bash
# test_mpi_shards.sh - CTest test: docs/CLI.md's MPI recipe (the block
# marked `<!-- recipe: mpi -->`), extracted and run word for word under Open
# MPI's mpirun in a temporary folder with the built `ggx` first on PATH.
# Its merged .npy and .json must equal, byte for byte, one plain `ggx
# sample` run of the same job (the recipe's command without --shard), and
# every rank must have taken its shard from OMPI_COMM_WORLD_RANK.
# A missing mpirun fails the test (scripts/install-deps.sh installs it); it
# is skipped (exit 77, with the reason) only where `mpirun` is not Open
# MPI's or cannot start even `true` here, which is no fault of ggx.
# Usage: test_mpi_shards.sh GGX_DIR SOURCE_DIR
set -euo pipefail
ggx_dir=$1
source_dir=$2
source "$(dirname "$0")/common.sh"
clean_launcher_environment

if ! command -v mpirun >/dev/null; then
  echo "FAIL: mpirun not found: scripts/install-deps.sh installs openmpi-bin"
  exit 1
fi
if ! mpirun --version 2>&1 | grep -q "Open MPI"; then
  echo "SKIPPED: the recipe is for Open MPI's mpirun; this one is: $(mpirun --version 2>&1 | head -n 1)"
  exit 77
fi
if ! probe=$(timeout 60 mpirun -n 1 --allow-run-as-root --oversubscribe true 2>&1); then
  echo "SKIPPED: mpirun cannot start a process on this machine:"
  echo "$probe" | tail -n 20
  exit 77
fi

recipe=$(readme_recipe "$source_dir/docs/CLI.md" mpi)
work=$(mktemp -d "${TMPDIR:-/tmp}/ggx-mpi-shards.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"
export PATH="$ggx_dir:$PATH"
printf '%s\n' "$recipe" >recipe.sh
echo "== docs/CLI.md's MPI recipe, in $work:"
cat recipe.sh
start=$SECONDS
if ! timeout 300 bash -euo pipefail recipe.sh >recipe.log 2>&1; then
  echo "FAIL: the recipe failed:"
  cat recipe.log
  exit 1
fi
cat recipe.log
echo "(the recipe took $((SECONDS - start)) s)"

# Every rank took a different shard from Open MPI's variables.
ranks=$(joined_lines "$recipe" | grep -o 'mpirun -n [0-9]*' | cut -d ' ' -f 3)
taken=$(grep -c "(from OMPI_COMM_WORLD_RANK/OMPI_COMM_WORLD_SIZE)" recipe.log || true)
if [ -z "$ranks" ] || [ "$taken" -ne "$ranks" ]; then
  echo "FAIL: $taken shards taken from OMPI_COMM_WORLD_RANK, for mpirun -n ${ranks:-?}"
  exit 1
fi
for ((rank = 0; rank < ranks; ++rank)); do
  grep -q "shard $rank/$ranks " recipe.log || { echo "FAIL: no rank took shard $rank/$ranks"; exit 1; }
done

# One plain run: the recipe's `ggx sample` without --shard, into one.npy.
one_run=$(joined_lines "$recipe" | grep -e '--shard auto' | sed -e 's/.*\(ggx sample \)/\1/' -e 's/ --shard auto//' \
  -e 's/--out [^ ]*/--out one.npy/')
read -r -a words <<<"$one_run"
ggx "${words[@]:1}" >/dev/null
merged=$(merged_output "$recipe")
same_as_one_run "$merged" one.npy
echo "PASS: $merged and its sidecar equal one run ($one_run) byte for byte"
