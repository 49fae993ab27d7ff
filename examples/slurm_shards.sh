#!/usr/bin/env bash
# slurm_shards.sh - one ggx sampling job split into shards and run as a Slurm
# job array: each task samples its part with `ggx sample --shard auto`
# (shard R of S from SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT), and
# `ggx merge` joins the shards into exactly (byte for byte) the file one run
# over the whole range writes: sample k depends only on (seed, k), so no
# shard needs to know about the others.
#
#   SAMPLES=2^30 sbatch --wait --array=0-15 examples/slurm_shards.sh   # 16 shards
#   ggx merge --out shards/caps-all.npy shards/caps-[0-9]*.npy
#
# (Without --wait: sbatch --dependency=afterok:<array job id> --wrap 'ggx merge ...'.)
# The tasks run in the folder sbatch was called from and inherit its
# environment (ggx on PATH, SAMPLES).  Ask for what one ggx needs on your
# cluster, e.g. `--gpus-per-task=1` or `--cpus-per-task=8` (PoCL) on the
# sbatch command line.
#
# Without Slurm (SLURM_ARRAY_TASK_ID unset) it runs every shard in turn with
# --shard R/S and merges them, which is how to try it on one machine:
#   SHARDS=4 SAMPLES=400000 bash examples/slurm_shards.sh
# Settings (environment): SAMPLES (the whole job, 2^30), SHARDS (without
# Slurm: 16), GGX (ggx on PATH), OUT (shards/); the sampling options are in
# `sample_options`.
#SBATCH --job-name=ggx-shards
#SBATCH --array=0-15
#SBATCH --output=ggx-shard-%a.log
set -euo pipefail

samples=${SAMPLES:-2^30}
shards=${SHARDS:-16}
ggx=${GGX:-ggx}
out=${OUT:-shards}
sample_options=(--method caps --alpha 0.2 --theta 70 --seed 7 --fields o,pdf_o,weight)

# One shard: `auto` under Slurm, R/S otherwise; it writes $out/caps-RRRR.npy.
run_shard() {
  local shard=$1
  mkdir -p "$out"
  "$ggx" sample "${sample_options[@]}" -n "$samples" --shard "$shard" --out "$out/caps-{shard}.npy"
}

if [ -n "${SLURM_ARRAY_TASK_ID:-}" ]; then
  run_shard auto
else
  for ((task = 0; task < shards; ++task)); do
    run_shard "$task/$shards"
  done
  "$ggx" merge --out "$out/caps-all.npy" "$out"/caps-[0-9]*.npy
  echo "merged $shards shards into $out/caps-all.npy"
fi
