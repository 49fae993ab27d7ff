#!/usr/bin/env bash
# scale_shards.sh - the numbers of docs/PIPELINES.md "Scaling past one
# machine", on this machine's disk: the whole-process time of one `ggx
# sample` shard into .npy (fsync included), of `ggx merge` joining S such
# shards, of `ggx merge --manifest` listing them, and of `cat` + `sync` of
# the same bytes (the disk's own floor); medians of RUNS runs.
# Usage: bash bench/scale_shards.sh [GGX (build/apps/ggx)] [SHARD_SAMPLES (2^25)] [SHARDS (3)] [RUNS (5)] [DIR (/var/tmp)]
set -euo pipefail
ggx=$(realpath "${1:-build/apps/ggx}")
n=${2:-$((1 << 25))}
shards=${3:-3}
runs=${4:-5}
work=$(mktemp -d "${5:-/var/tmp}/ggx-scale.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"
options=(--method caps --alpha 0.2 --theta 70 --seed 7 --fields o,pdf_o,weight)

seconds() { local start=$EPOCHREALTIME; "$@" >/dev/null; awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { print b - a }'; }
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

for ((r = 0; r < runs; ++r)); do
  rm -f s-*
  for ((k = 0; k < shards; ++k)); do
    seconds "$ggx" sample "${options[@]}" -n $((n * shards)) --shard "$k/$shards" --out "s-{shard}.npy" >>sample.t
  done
  rm -f all.*; seconds "$ggx" merge --out all.npy s-*.npy >>merge.t
  rm -f list.json; seconds "$ggx" merge --manifest list.json s-*.npy >>manifest.t
  rm -f cat.bin; seconds sh -c 'cat s-*.npy > cat.bin && sync' >>cat.t
done
bytes=$(stat -c %s all.npy)
echo "# $shards shards of $n caps samples (o, pdf_o, weight), $bytes bytes merged, on $(df --output=source "$work" | tail -1); medians of $runs runs"
echo "step,seconds,ns_per_sample,MB_per_s"
for step in sample merge manifest cat; do
  count=$((n * shards)) step_bytes=$bytes
  [ "$step" = sample ] && count=$n step_bytes=$((bytes / shards))
  median <"$step.t" | awk -v s="$step" -v n="$count" -v b="$step_bytes" \
    '{ printf "%s,%.3f,%.2f,%s\n", s, $1, $1 * 1e9 / n, s == "manifest" ? "-" : sprintf("%.0f", b / $1 / 1e6) }'
done
