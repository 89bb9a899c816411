#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A single-node Slurm cluster on this machine, for a test: sourced, it gives
#   slurm_start DIR   munged on its own key and socket, slurmctld and slurmd
#                     on free ports, every file (key, sockets, slurm.conf,
#                     state, spool, logs, pid files) under DIR; exports
#                     SLURM_CONF so that sbatch, squeue, sinfo and scontrol
#                     talk to it; waits until the node is idle
#   slurm_stop        stops the three daemons it started (by their pids,
#                     never by name) and waits until they are gone
# It touches nothing outside DIR: no system service, no /etc file, no
# default port (a cluster or munged already on the machine is left alone).
# Needs root (slurmd runs jobs as their users), munge (munged, mungekey) and
# Slurm (slurmctld, slurmd, sbatch, sinfo, scontrol): Debian's munge and
# slurm-wlm.

slurm_pids=()
slurm_dir=""

slurm_fail() {
  echo "slurm_single_node: $*" >&2
  for log in "$slurm_dir"/log/*.log; do
    [ -f "$log" ] || continue
    echo "--- $log (last lines)" >&2
    tail -n 20 "$log" >&2
  done
  return 1
}

# A TCP port nobody listens on (and, the range being above the kernel's
# ephemeral ports' usual start, seldom taken in between).
slurm_free_port() {
  python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()'
}

slurm_start() {
  slurm_dir=$1
  local missing=()
  for program in munged mungekey slurmctld slurmd sbatch sinfo scontrol squeue python3; do
    command -v "$program" > /dev/null || missing+=("$program")
  done
  [ ${#missing[@]} -eq 0 ] ||
    { slurm_fail "missing ${missing[*]} (Debian: apt-get install munge slurm-wlm)"; return 1; }
  [ "$(id -u)" = 0 ] || { slurm_fail "needs root (slurmd runs each job as its user)"; return 1; }
  mkdir -p "$slurm_dir"/{munge,log,state,spool,run}
  chmod 700 "$slurm_dir/munge"
  mungekey --create --keyfile="$slurm_dir/munge/munge.key" --force ||
    { slurm_fail "mungekey could not write a key"; return 1; }
  chmod 400 "$slurm_dir/munge/munge.key"
  local socket=$slurm_dir/munge/munge.socket
  # --force: the key's folder lies under a world-writable /tmp (sticky).
  munged --foreground --force --key-file="$slurm_dir/munge/munge.key" --socket="$socket" \
         --pid-file="$slurm_dir/run/munged.pid" --seed-file="$slurm_dir/munge/munge.seed" \
         --log-file="$slurm_dir/log/munged.log" > /dev/null 2>&1 &
  slurm_pids+=($!)
  local i
  for i in $(seq 100); do [ -S "$socket" ] && break; sleep 0.1; done
  [ -S "$socket" ] || { slurm_fail "munged did not open $socket"; return 1; }

  local host node ctld_port slurmd_port
  host=$(hostname -s)
  # The node as slurmd sees it (CPUs, sockets, cores, threads, memory), so
  # that slurmctld takes its registration as valid.
  node=$(slurmd -C | head -n 1)
  case "$node" in NodeName=*) ;; *) slurm_fail "slurmd -C printed '$node'"; return 1 ;; esac
  ctld_port=$(slurm_free_port)
  slurmd_port=$(slurm_free_port)
  export SLURM_CONF=$slurm_dir/slurm.conf
  cat > "$SLURM_CONF" <<CONF
ClusterName=cmfiltertest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$slurm_dir/state
SlurmdSpoolDir=$slurm_dir/spool/%n
SlurmctldPidFile=$slurm_dir/run/slurmctld.pid
SlurmdPidFile=$slurm_dir/run/slurmd.pid
SlurmctldLogFile=$slurm_dir/log/slurmctld.log
SlurmdLogFile=$slurm_dir/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=1
SwitchType=switch/none
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
ReturnToService=2
SlurmdTimeout=30
InactiveLimit=0
MinJobAge=300
KillWait=5
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=farm Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
  slurmctld -D -c -i -f "$SLURM_CONF" > "$slurm_dir/log/slurmctld.out" 2>&1 &
  slurm_pids+=($!)
  slurmd -D -f "$SLURM_CONF" > "$slurm_dir/log/slurmd.out" 2>&1 &
  slurm_pids+=($!)
  # Until the node is idle: registered, and its CPUs free.
  local state=""
  for i in $(seq 120); do
    state=$(sinfo -h -N -n "$host" -o %t 2>/dev/null || true)
    [ "$state" = idle ] && return 0
    for pid in "${slurm_pids[@]}"; do
      kill -0 "$pid" 2>/dev/null || { slurm_fail "a daemon (pid $pid) exited while starting"; return 1; }
    done
    sleep 0.5
  done
  slurm_fail "node $host not idle after 60 s (state '${state:-none}')"
}

slurm_stop() {
  local pid i n
  [ ${#slurm_pids[@]} -gt 0 ] || return 0
  # Jobs still queued or running are cancelled first, so that no job step
  # outlives the cluster.
  if [ -n "${SLURM_CONF:-}" ] && squeue -h > /dev/null 2>&1; then
    squeue -h -o %A | sort -u | xargs -r scancel 2>/dev/null || true
    for i in $(seq 60); do [ -z "$(squeue -h 2>/dev/null)" ] && break; sleep 0.5; done
  fi
  # slurmd, slurmctld, then munged: the order they were started, reversed.
  for ((n = ${#slurm_pids[@]} - 1; n >= 0; n--)); do
    pid=${slurm_pids[n]}
    kill -TERM "$pid" 2>/dev/null || continue
    for i in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
  slurm_pids=()
  # A job's processes carry this cluster's SLURM_CONF (sbatch exports the
  # submitter's environment): any left over are this cluster's own.
  for pid in $(grep -lsaF "SLURM_CONF=$slurm_dir/slurm.conf" /proc/[0-9]*/environ | cut -d/ -f3); do
    [ "$pid" != $$ ] && [ "$pid" != "$BASHPID" ] && kill -KILL "$pid" 2>/dev/null || true
  done
}
