#!/usr/bin/env bash
# slurm_shards.sh - one ggx sampling job split into shards of consecutive
# sample indices, run as a Slurm job array, then merged into exactly (byte
# for byte) the file one run over the whole range writes: sample k depends
# only on (seed, k), so no shard needs to know about the others.
#
#   sbatch --array=0-15 examples/slurm_shards.sh            # 16 shards
#   sbatch --dependency=afterok:<array job id> --wrap \
#       'ggx merge --out shards/caps-all.npy shards/caps-[0-9]*.npy'   # when all are done
#
# Without Slurm (SLURM_ARRAY_TASK_ID unset) it runs every shard in turn and
# merges them, which is how to try it on one machine:
#   SHARDS=4 SHARD_SIZE=100000 bash examples/slurm_shards.sh
# Settings (environment): SHARDS (16), SHARD_SIZE (2^26 samples), GGX (ggx
# on PATH), OUT (shards/); the sampling options are in `sample_options`.
#SBATCH --job-name=ggx-shards
#SBATCH --array=0-15
#SBATCH --cpus-per-task=4
#SBATCH --output=ggx-shard-%a.log
set -euo pipefail

shards=${SHARDS:-16}
shard_size=${SHARD_SIZE:-$((1 << 26))}
ggx=${GGX:-ggx}
out=${OUT:-shards}
sample_options=(--method caps --alpha 0.2 --theta 70 --seed 7 --fields o,pdf_o,weight)

# Shard `task` holds samples task * shard_size .. (task + 1) * shard_size - 1.
run_shard() {
  local task=$1
  mkdir -p "$out"
  "$ggx" sample "${sample_options[@]}" --first $((task * shard_size)) -n "$shard_size" \
    --out "$out/caps-$(printf %04d "$task").npy"
}

if [ -n "${SLURM_ARRAY_TASK_ID:-}" ]; then
  run_shard "$SLURM_ARRAY_TASK_ID"
else
  for ((task = 0; task < shards; ++task)); do
    run_shard "$task"
  done
  "$ggx" merge --out "$out/caps-all.npy" "$out"/caps-[0-9]*.npy
  echo "merged $shards shards into $out/caps-all.npy"
fi
