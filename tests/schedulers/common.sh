# common.sh - what the launcher tests (test_mpi_shards.sh,
# test_slurm_cluster.sh) share, sourced by them: the recipes of docs/CLI.md
# extracted word for word, the plain `ggx sample` run a recipe must equal,
# a clean launcher environment, and byte-for-byte comparison of a merged
# file and its sidecar with one run's.

# The lines of the ```sh block between `<!-- recipe: NAME -->` and
# `<!-- /recipe -->` in README (fences dropped); fails when there is none.
readme_recipe() {
  local readme=$1 name=$2 recipe
  recipe=$(awk -v start="<!-- recipe: $name -->" '
    $0 == start { inside = 1; next }
    inside && $0 == "<!-- /recipe -->" { exit }
    inside && /^```/ { fences++; next }
    inside && fences == 1 { print }' "$readme")
  if [ -z "$recipe" ]; then
    echo "$readme has no recipe '$name' (a \`\`\`sh block between <!-- recipe: $name --> and <!-- /recipe -->)" >&2
    return 1
  fi
  printf '%s\n' "$recipe"
}

# The recipe's lines with backslash continuations joined.
joined_lines() {
  sed -e ':more' -e '/\\$/ { N; s/\\\n//; b more' -e '}' <<<"$1" | tr -s ' '
}

# The path after `ggx merge --out` in the recipe: the merged file.
merged_output() {
  joined_lines "$1" | grep -o 'ggx merge --out [^ ]*' | head -n 1 | cut -d ' ' -f 4
}

# Unsets what a surrounding launcher may have set (the suite itself may run
# under mpirun or in a Slurm job), so that only the recipe's launcher counts.
clean_launcher_environment() {
  local name
  for name in $(compgen -e); do
    case $name in
      OMPI_COMM_WORLD_* | OMPI_UNIVERSE_SIZE | PMI_* | PMIX_* | SLURM_* | SBATCH_* | SRUN_* | SALLOC_*) unset "$name" ;;
    esac
  done
}

# Fails, naming both files, unless A and B are equal byte for byte.
same_bytes() {
  if ! cmp "$1" "$2"; then
    echo "FAIL: $1 ($(stat -c %s "$1") bytes) differs from $2 ($(stat -c %s "$2") bytes)"
    [ "${1##*.}" != json ] || diff "$1" "$2" || true
    return 1
  fi
}

# Checks MERGED.npy and MERGED.json against ONE.npy and ONE.json.
same_as_one_run() {
  local merged=$1 one=$2
  same_bytes "$merged" "$one" && same_bytes "${merged%.*}.json" "${one%.*}.json"
}
