# shellcheck shell=bash disable=SC2034  # cluster_error is read by the caller
# A throwaway single-node Slurm cluster on localhost, for ci/slurm-smoke.sh (sourced, not run).
# Everything lives in one directory: slurm.conf, a private munged socket, the controller's state,
# the node's spool, the logs. Nothing in /etc is touched except that /etc/munge/munge.key is
# created when it is missing. No systemd: the daemons run in the foreground as children of the
# calling shell, so their process ids are known and they are stopped by id. Needs root.
#
#   cluster_start DIR             start munged, slurmctld and slurmd, wait until the node is idle;
#                                 exports SLURM_CONF so sbatch, squeue and scontrol find the cluster
#   cluster_stop                  cancel the cluster's jobs, stop the daemons cluster_start started,
#                                 fail if any of the cluster's processes is left (idempotent)
#   cluster_wait_jobs SECS ID...  wait until the jobs have left the queue (pending or running)
#   cluster_job_states ID         one line per job record: TASK STATE EXIT_CODE REASON
#
# On failure a function returns non-zero and leaves a one-line reason in cluster_error.
#
# The configuration (see slurm.conf(5)): one node, NodeName=localhost, with the CPUs, cores and
# memory `slurmd -C` finds on this machine; select/cons_tres allocating single CPUs (CR_CPU), so
# one-CPU array tasks share the node; proctrack/linuxproc and task/none, which need no cgroups;
# no accounting database (job records stay in the controller for MinJobAge, read with scontrol).

cluster_dir=''
cluster_error=''
cluster_daemon_pids=()  # slurmd, slurmctld: children of this shell
cluster_munged_pid=''   # daemonized itself: not a child

# Prints the first port from $1 on that nothing listens on.
cluster_free_port() {
  local p
  for ((p = $1; p < $1 + 200; p++)); do
    if [ -z "$(ss -Hltn "sport = :$p")" ]; then
      echo "$p"
      return 0
    fi
  done
  return 1
}

cluster_start_munged() {
  local d=$cluster_dir/munge key=/etc/munge/munge.key
  if [ ! -s "$key" ]; then
    mungekey --create --keyfile="$key" || { cluster_error="cannot create $key"; return 1; }
    chown munge:munge "$key" && chmod 600 "$key"
  fi
  mkdir -p "$d" && chown munge:munge "$d" && chmod 755 "$d"  # munged checks these modes
  if ! runuser -u munge -- munged --socket="$d/munge.socket" --key-file="$key" \
    --pid-file="$d/munged.pid" --log-file="$d/munged.log" --seed-file="$d/munged.seed"; then
    cluster_error="munged did not start: $(tail -n1 "$d/munged.log" 2>/dev/null)"
    return 1
  fi
  cluster_munged_pid=$(cat "$d/munged.pid")
  if ! munge -n -S "$d/munge.socket" | unmunge -S "$d/munge.socket" >/dev/null; then
    cluster_error="munged runs but does not encode and decode a credential"
    return 1
  fi
}

cluster_write_conf() {
  local ctld_port slurmd_port hardware
  if ! ctld_port=$(cluster_free_port 6817) || ! slurmd_port=$(cluster_free_port $((ctld_port + 1)))
  then
    cluster_error="no free TCP port from 6817 on"
    return 1
  fi
  # `slurmd -C` prints "NodeName=<host> CPUs=.. Boards=.. ... RealMemory=..": keep all but the name.
  read -r _ hardware < <(slurmd -C | head -n1)
  [[ $hardware == CPUs=*RealMemory=* ]] || { cluster_error="slurmd -C: '$hardware'"; return 1; }
  local d=$cluster_dir
  cat >"$d/slurm.conf" <<EOF
# Written by ci/slurm/local-cluster.sh: a single-node cluster on localhost.
ClusterName=contact-suite-smoke
SlurmctldHost=localhost
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$d/munge/munge.socket
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool
SlurmctldPidFile=$d/slurmctld.pid
SlurmdPidFile=$d/slurmd.pid
SlurmctldLogFile=$d/log/slurmctld.log
SlurmdLogFile=$d/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
MinJobAge=3600
NodeName=localhost NodeAddr=127.0.0.1 $hardware State=UNKNOWN
PartitionName=smoke Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
}

# Waits until sinfo shows the node idle, or a daemon died, or 30 s passed.
cluster_wait_idle() {
  local deadline=$((SECONDS + 30)) state='' pid
  while [ "$state" != idle ]; do
    for pid in "${cluster_daemon_pids[@]}"; do
      if ! kill -0 "$pid" 2>/dev/null; then
        cluster_error="a Slurm daemon exited at start: $(tail -qn1 "$cluster_dir"/log/*.stderr | tr '\n' ' ')"
        return 1
      fi
    done
    if ((SECONDS >= deadline)); then
      cluster_error="node not idle after 30 s (state '${state}'; logs in $cluster_dir/log)"
      return 1
    fi
    sleep 0.2
    state=$(sinfo -h -N -n localhost -o %T 2>/dev/null) || state=''
  done
}

cluster_start() {
  cluster_dir=$1
  chmod 755 "$cluster_dir"  # munged, as user munge, must reach its socket directory
  mkdir -p "$cluster_dir"/{state,spool,log}
  cluster_start_munged || return 1
  cluster_write_conf || return 1
  export SLURM_CONF=$cluster_dir/slurm.conf
  slurmctld -D -f "$SLURM_CONF" >"$cluster_dir/log/slurmctld.stderr" 2>&1 &
  cluster_daemon_pids+=("$!")
  slurmd -D -N localhost -f "$SLURM_CONF" >"$cluster_dir/log/slurmd.stderr" 2>&1 &
  cluster_daemon_pids+=("$!")
  cluster_wait_idle
}

cluster_wait_jobs() {
  local seconds=$1 ids queued
  shift
  ids=$(IFS=,; echo "$*")
  local deadline=$((SECONDS + seconds))
  while :; do
    queued=$(squeue -h -j "$ids" -o '%i %T %r' 2>&1) || {
      cluster_error="squeue failed: $queued"
      return 1
    }
    [ -z "$queued" ] && return 0
    if ((SECONDS >= deadline)); then
      cluster_error="jobs not finished after $seconds s: $(echo "$queued" | tr '\n' ';')"
      return 1
    fi
    sleep 0.5
  done
}

cluster_job_states() {
  local line task state code reason
  while read -r line; do
    task='-' state='?' code='?' reason='?'
    [[ $line =~ ArrayTaskId=([^ ]+) ]] && task=${BASH_REMATCH[1]}
    [[ $line =~ JobState=([^ ]+) ]] && state=${BASH_REMATCH[1]}
    [[ $line =~ \ ExitCode=([^ ]+) ]] && code=${BASH_REMATCH[1]}
    [[ $line =~ \ Reason=([^ ]+) ]] && reason=${BASH_REMATCH[1]}
    echo "$task $state $code $reason"
  done < <(scontrol -o show job "$1") | sort -n
}

# Stops $1 (a pid) with SIGTERM, then SIGKILL after 10 s; 0 once it is gone.
cluster_stop_pid() {
  local pid=$1 i
  kill -TERM "$pid" 2>/dev/null || return 0
  for ((i = 0; i < 100; i++)); do
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.1
  done
  kill -KILL "$pid" 2>/dev/null
  sleep 0.2
  ! kill -0 "$pid" 2>/dev/null
}

# Prints the pids of processes that belong to this cluster: a command line, environment
# (SLURM_CONF) or working directory that names its directory. Three scans of /proc, not a fork
# per process (forks are slow in a gVisor sandbox: 10 s for 150 processes). The scanners match
# themselves and are gone by the time a pid is confirmed; the calling shell is skipped.
cluster_processes() {
  local pid candidates
  candidates=$({
    grep -alF -- "$cluster_dir" /proc/[0-9]*/cmdline
    grep -alzx -- "SLURM_CONF=$cluster_dir/slurm.conf" /proc/[0-9]*/environ
    find /proc/[0-9]*/cwd -maxdepth 0 -lname "$cluster_dir*"
  } 2>/dev/null | cut -d/ -f3 | sort -un)
  for pid in $candidates; do
    if [ "$pid" != "$$" ] && [ -d "/proc/$pid" ]; then
      echo "$pid"
    fi
  done
}

cluster_stop() {
  [ -n "$cluster_dir" ] || return 0
  local pid ok=0 jobs left
  if [ ${#cluster_daemon_pids[@]} -gt 0 ] && kill -0 "${cluster_daemon_pids[0]}" 2>/dev/null; then
    jobs=$(squeue -h -o %A 2>/dev/null | sort -u | paste -sd, -) || jobs=''
    if [ -n "$jobs" ]; then
      local -a ids
      IFS=, read -r -a ids <<<"$jobs"
      scancel --quiet "${ids[@]}" 2>/dev/null || true
      cluster_wait_jobs 20 "$jobs" || true
    fi
  fi
  for pid in "${cluster_daemon_pids[@]}"; do
    cluster_stop_pid "$pid" || ok=1
    wait "$pid" 2>/dev/null || true
  done
  cluster_daemon_pids=()
  if [ -n "$cluster_munged_pid" ]; then
    cluster_stop_pid "$cluster_munged_pid" || ok=1
    cluster_munged_pid=''
  fi
  cluster_processes >"$cluster_dir/left-over.pids"
  left=$(paste -sd' ' "$cluster_dir/left-over.pids")
  if [ -n "$left" ] || [ $ok -ne 0 ]; then
    cluster_error="processes of the cluster left after stopping it: ${left:-a daemon would not stop}"
    return 1
  fi
}
