#!/usr/bin/env bash
# test_slurm_cluster.sh - CTest test: docs/CLI.md's Slurm recipe (the block
# marked `<!-- recipe: slurm -->`) run word for word against a real
# one-node Slurm, which submits examples/slurm_shards.sh as a job array with
# `sbatch --wait`; its merged .npy and .json must equal, byte for byte, one
# plain `ggx sample` run of the same job, and every array task must have
# taken its shard from SLURM_ARRAY_TASK_ID.
# The test starts its own munged (its own key and socket), slurmctld and
# slurmd, as children of this script, with a slurm.conf, ports, state,
# spool, pid and log files of their own in a temporary folder, and stops
# every one of them by pid in its exit trap, whatever happens.  Where Slurm
# cannot start here (not root, a daemon missing or dying, the node never
# idle) it prints why with the daemons' log tails and exits 77 (skipped).
# Usage: test_slurm_cluster.sh GGX_DIR SOURCE_DIR
set -euo pipefail
ggx_dir=$1
source_dir=$2
source "$(dirname "$0")/common.sh"
clean_launcher_environment

work=""
daemon_pids=()   # munged, slurmctld, slurmd: stopped in reverse order
daemon_names=()
recipe_pid=""    # the recipe, run in the background so that a signal stops the test at once

# The end of each daemon's log, else of what it printed (before its log opened).
log_tails() {
  local name log
  for name in munge/munged slurm/slurmctld slurm/slurmd; do
    log=$work/$name.log
    [ -s "$log" ] || log=$work/$name.out
    [ -s "$log" ] || continue
    echo "--- last lines of $log:"
    tail -n 15 "$log"
  done
}

# "slurmd exited" for each daemon no longer running.
dead_daemons() {
  local k
  for ((k = 0; k < ${#daemon_pids[@]}; ++k)); do
    kill -0 "${daemon_pids[k]}" 2>/dev/null || echo "${daemon_names[k]} exited"
  done
}

skip() {
  echo "SKIPPED: $* $(dead_daemons | paste -sd ' ' | sed 's/.\+/(&)/')"
  [ -z "$work" ] || log_tails
  exit 77
}

fail() {
  echo "FAIL: $*"
  [ -z "$work" ] || log_tails
  exit 1
}

# Stops process PID with TERM, then KILL after 10 s; returns when it is gone.
stop_pid() {
  local pid=$1 waited
  kill -TERM "$pid" 2>/dev/null || return 0
  for ((waited = 0; waited < 100; ++waited)); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  kill -KILL "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
}

# Processes whose working folder is inside the test's folder: the jobs' ggx
# and shells, should a job outlive its cancellation.
processes_in_work() {
  local entry
  for entry in /proc/[0-9]*; do
    [[ "$(readlink "$entry/cwd" 2>/dev/null)" == "$work"/* ]] && echo "${entry#/proc/}"
  done
  return 0
}

cleanup() {
  local status=$? pid k
  trap - EXIT
  cd /  # out of the folder processes_in_work looks for
  [ -z "$recipe_pid" ] || stop_pid "$recipe_pid"
  if [ -n "$work" ] && [ -f "$work/slurm/slurm.conf" ] && [ ${#daemon_pids[@]} -ge 2 ]; then
    SLURM_CONF=$work/slurm/slurm.conf timeout 10 scancel --full --quiet --user=root >/dev/null 2>&1 || true
  fi
  for pid in $(processes_in_work); do stop_pid "$pid"; done
  for ((k = ${#daemon_pids[@]} - 1; k >= 0; --k)); do stop_pid "${daemon_pids[k]}"; done
  [ -z "$work" ] || rm -rf "$work"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 143' TERM
trap 'exit 130' INT

[ "$(id -u)" -eq 0 ] || skip "starting slurmd (which runs jobs as their users) and munged needs root; ran as $(id -un)"
for tool in munged munge unmunge slurmctld slurmd sbatch scontrol sinfo scancel; do
  command -v "$tool" >/dev/null || skip "$tool not found (scripts/install-deps.sh installs slurm-wlm and munge)"
done

# Two TCP ports nobody listens on (from /proc/net/tcp*), into ports[0] and ports[1].
pick_ports() {
  local used port try
  used=$(awk 'FNR > 1 && $4 == "0A" { split($2, a, ":"); print a[2] }' /proc/net/tcp /proc/net/tcp6 2>/dev/null || true)
  ports=()
  for ((try = 0; try < 200 && ${#ports[@]} < 2; ++try)); do
    port=$((20000 + RANDOM % 30000))
    grep -qix "$(printf %04X "$port")" <<<"$used" || [ "${ports[0]:-}" = "$port" ] || ports+=("$port")
  done
  [ ${#ports[@]} -eq 2 ] || skip "no two free TCP ports found"
}

# Waits up to SECONDS for COMMAND to succeed while every daemon lives.
wait_for() {
  local seconds=$1 waited pid
  shift
  for ((waited = 0; waited < seconds * 5; ++waited)); do
    "$@" >/dev/null 2>&1 && return 0
    for pid in "${daemon_pids[@]}"; do
      kill -0 "$pid" 2>/dev/null || return 1
    done
    sleep 0.2
  done
  return 1
}

# munged with its own key, socket, pid, seed and log files.  Every folder
# on the socket's path must be searchable by all (munged checks).
start_munge() {
  mkdir -m 755 "$work/munge"
  head -c 1024 /dev/urandom >"$work/munge/munge.key"
  chmod 400 "$work/munge/munge.key"
  munge_socket=$work/munge/munge.socket
  munged --foreground --socket="$munge_socket" --key-file="$work/munge/munge.key" \
    --pid-file="$work/munge/munged.pid" --seed-file="$work/munge/munged.seed" \
    --log-file="$work/munge/munged.log" >"$work/munge/munged.out" 2>&1 &
  daemon_pids+=($!)
  daemon_names+=(munged)
  munge_works() { munge --socket="$munge_socket" -n | unmunge --socket="$munge_socket"; }
  wait_for 20 munge_works || skip "munged did not start"
}

# slurm.conf for one node (this machine, as `slurmd -C` describes it, at
# 127.0.0.1 whatever its name resolves to) with everything in the temporary
# folder and ports of its own.
write_slurm_conf() {
  local node host
  host=$(hostname -s)
  node=$(slurmd -C 2>/dev/null | head -n 1)
  [[ "$node" == NodeName=* ]] || skip "slurmd -C could not describe this machine: $node"
  pick_ports
  mkdir -p "$work/slurm/state" "$work/slurm/spool"
  cat >"$work/slurm/slurm.conf" <<EOF
ClusterName=ggxtest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=${ports[0]}
SlurmdPort=${ports[1]}
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$munge_socket
StateSaveLocation=$work/slurm/state
SlurmdSpoolDir=$work/slurm/spool
SlurmctldPidFile=$work/slurm/slurmctld.pid
SlurmdPidFile=$work/slurm/slurmd.pid
SlurmctldLogFile=$work/slurm/slurmctld.log
SlurmdLogFile=$work/slurm/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
$node NodeAddr=127.0.0.1
PartitionName=ggxtest Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
}

node_idle() { [ "$(sinfo --noheader --format=%t)" = idle ]; }

start_slurm() {
  export SLURM_CONF=$work/slurm/slurm.conf
  slurmctld -D -f "$SLURM_CONF" >"$work/slurm/slurmctld.out" 2>&1 &
  daemon_pids+=($!)
  daemon_names+=(slurmctld)
  wait_for 30 scontrol ping || skip "slurmctld did not answer"
  slurmd -D -f "$SLURM_CONF" >"$work/slurm/slurmd.out" 2>&1 &
  daemon_pids+=($!)
  daemon_names+=(slurmd)
  wait_for 30 node_idle || skip "the node did not come up idle: $(sinfo --noheader 2>&1)"
}

work=$(mktemp -d /tmp/ggx-slurm.XXXXXX)  # short: the munge socket's path must fit in sun_path
chmod 755 "$work"
start=$SECONDS
start_munge
write_slurm_conf
start_slurm
echo "== Slurm up in $((SECONDS - start)) s ($(sinfo --noheader --format='%P %D node %N %t, %c CPUs'))"

# The recipe, in a folder holding examples/slurm_shards.sh as in the source tree.
recipe=$(readme_recipe "$source_dir/docs/CLI.md" slurm)
mkdir -p "$work/job/examples"
cp "$source_dir/examples/slurm_shards.sh" "$work/job/examples/"
cd "$work/job"
export PATH="$ggx_dir:$PATH"
printf '%s\n' "$recipe" >recipe.sh
echo "== docs/CLI.md's Slurm recipe, in $work/job:"
cat recipe.sh
start=$SECONDS
timeout 240 bash -euo pipefail recipe.sh >recipe.log 2>&1 &
recipe_pid=$!
if ! wait "$recipe_pid"; then
  cat recipe.log
  for log in ggx-shard-*.log; do [ ! -f "$log" ] || { echo "--- $log:"; cat "$log"; }; done
  fail "the recipe failed (or ran past 240 s)"
fi
recipe_pid=""
cat recipe.log
echo "(the recipe took $((SECONDS - start)) s)"

# Every array task took a different shard from the job array's variables.
tasks=(ggx-shard-*.log)
[ -f "${tasks[0]}" ] || fail "no task log ggx-shard-*.log: the script did not run as a job array"
for log in "${tasks[@]}"; do
  echo "--- $log:"
  cat "$log"
  grep -q "(from SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT)" "$log" || fail "$log: no shard from the job array"
done
for ((task = 0; task < ${#tasks[@]}; ++task)); do
  grep -q "shard $task/${#tasks[@]} " ggx-shard-*.log || fail "no task took shard $task/${#tasks[@]}"
done

# One plain run of the script's sampling options over the recipe's SAMPLES.
eval "$(grep '^sample_options=' examples/slurm_shards.sh)"
samples=$(joined_lines "$recipe" | grep -o 'SAMPLES=[^ ]*' | head -n 1 | cut -d = -f 2)
[ -n "$samples" ] || fail "the recipe sets no SAMPLES"
ggx sample "${sample_options[@]}" -n "$samples" --out one.npy >/dev/null
merged=$(merged_output "$recipe")
same_as_one_run "$merged" one.npy || fail "the merged shards differ from one run"
echo "PASS: ${#tasks[@]} array tasks merged into $merged, equal to one run of $samples samples byte for byte"
