#!/usr/bin/env bash
# A stand-in for the contact-suite binary, for `ci/slurm-smoke.sh --selftest`: it proves the
# Slurm machinery (daemons, array indices, argument passing, the afterok dependency, cleanup)
# without building or running the solver. It knows two commands, with the real one's syntax:
#
#   stand-in run [flags...] [--shard K/N] [--jobs J] [--no-report] --out DIR
#       writes DIR/results.json, a plain-text record (not the real schema) of what the slice
#       saw: K/N, the Slurm task and node, CPUs, BLAS threads, start and end times, and every
#       argument as `printf %q` prints it
#   stand-in merge OUT_DIR SLICE...
#       checks that the slices are 1..N of one N, each once (exit 2 naming the missing or
#       overlapping slice otherwise), and writes OUT_DIR/results.json: a header and the slices
#
# Environment: CS_STANDIN_SLEEP (seconds a slice takes, default 1); CS_STANDIN_FAIL_SHARD=K
# makes slice K fail with exit code 3, to test what a failed slice does to the merge.
set -euo pipefail

die() {
  echo "stand-in contact-suite: $*" >&2
  exit 2
}

run() {
  local shard=unsharded jobs=1 out='' arg
  local -a args=("$@")
  while [ $# -gt 0 ]; do
    case $1 in
      --shard) shard=$2; shift 2 ;;
      --jobs) jobs=$2; shift 2 ;;
      --out) out=$2; shift 2 ;;
      *) shift ;;
    esac
  done
  [ -n "$out" ] || die "run: --out DIR is required"
  if [ "$shard" != unsharded ] && [ "${CS_STANDIN_FAIL_SHARD:-}" = "${shard%/*}" ]; then
    echo "stand-in contact-suite: failing slice $shard on purpose (CS_STANDIN_FAIL_SHARD)" >&2
    exit 3
  fi
  local started=$EPOCHREALTIME
  sleep "${CS_STANDIN_SLEEP:-1}"
  mkdir -p "$out"
  {
    echo "stand-in contact-suite slice"
    echo "shard=$shard"
    echo "array_task=${SLURM_ARRAY_TASK_ID:-none}"
    echo "job=${SLURM_JOB_ID:-none}"
    echo "node=${SLURMD_NODENAME:-none}"
    echo "cpus_per_task=${SLURM_CPUS_PER_TASK:-none}"
    echo "jobs=$jobs"
    echo "openblas_threads=${OPENBLAS_NUM_THREADS:-unset}"
    echo "started=$started"
    echo "finished=$EPOCHREALTIME"
    for arg in "${args[@]}"; do
      printf 'arg=%q\n' "$arg"
    done
  } >"$out/results.json.tmp"
  mv "$out/results.json.tmp" "$out/results.json"
}

merge() {
  [ $# -ge 2 ] || die "merge: usage: merge OUT_DIR SLICE..."
  local out=$1 started=$EPOCHREALTIME n='' file line k
  shift
  local -A seen=()
  for file in "$@"; do
    [ -f "$file" ] || die "merge: no slice file $file"
    line=$(grep -m1 '^shard=' "$file") || die "merge: $file is not a slice"
    line=${line#shard=}
    [[ $line =~ ^([0-9]+)/([0-9]+)$ ]] || die "merge: $file is an unsharded run"
    k=${BASH_REMATCH[1]}
    [ -z "$n" ] || [ "$n" = "${BASH_REMATCH[2]}" ] || die "merge: $file is a slice of ${BASH_REMATCH[2]}, not of $n"
    n=${BASH_REMATCH[2]}
    [ -z "${seen[$k]:-}" ] || die "merge: slice $k/$n given twice ($file and ${seen[$k]})"
    seen[$k]=$file
  done
  for ((k = 1; k <= n; k++)); do
    [ -n "${seen[$k]:-}" ] || die "merge: slice $k/$n is missing"
  done
  mkdir -p "$out"
  {
    echo "stand-in contact-suite merge"
    echo "merged=$n"
    echo "merge_node=${SLURMD_NODENAME:-none}"
    echo "merge_started=$started"
    for ((k = 1; k <= n; k++)); do
      echo "--- ${seen[$k]}"
      cat "${seen[$k]}"
    done
  } >"$out/results.json.tmp"
  mv "$out/results.json.tmp" "$out/results.json"
}

case ${1:-} in
  run) shift; run "$@" ;;
  merge) shift; merge "$@" ;;
  *) die "unknown command '${1:-}' (a stand-in: run or merge only)" ;;
esac
