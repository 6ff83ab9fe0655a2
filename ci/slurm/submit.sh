#!/usr/bin/env bash
# Submits the contact-suite case matrix to Slurm: a job array of N slices, then a merge job that
# runs once every slice has succeeded. See docs/slurm.md.
#
#   bash ci/slurm/submit.sh [--shards N] [--out DIR] [--exe PATH] [--rerun K,K...] [--] [run flags...]
#
#   --shards N      number of slices (default: $CS_SHARDS, else 3)
#   --out DIR       output directory on a filesystem the compute nodes share (default: out/slurm);
#                   slice K writes DIR/shard-K/, the merge DIR/results.json and the report,
#                   Slurm's logs go to DIR/logs/
#   --exe PATH      the contact-suite binary (default: $CONTACT_SUITE, else build/contact-suite of
#                   this repository, else contact-suite on PATH)
#   --rerun LIST    resubmit only these slices (e.g. 2 or 2,5) into an existing DIR, then merge
#   run flags       passed to every slice's `contact-suite run` (not --shard, --out or --jobs)
#
# sbatch reads the site settings from its own environment variables, for both jobs:
# SBATCH_PARTITION, SBATCH_ACCOUNT, SBATCH_QOS, SBATCH_TIMELIMIT, SBATCH_MEM_PER_CPU, ...
# Prints the job ids on stdout as `array_job=ID` and `merge_job=ID`, one a line.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/../.." && pwd)

die() {
  echo "ci/slurm/submit.sh: $*" >&2
  exit 2
}

shards=${CS_SHARDS:-3}
out=out/slurm
exe=${CONTACT_SUITE:-}
rerun=''
run_flags=()
while [ $# -gt 0 ]; do
  case $1 in
    --shards) [ $# -ge 2 ] || die "--shards needs a value"; shards=$2; shift 2 ;;
    --out) [ $# -ge 2 ] || die "--out needs a value"; out=$2; shift 2 ;;
    --exe) [ $# -ge 2 ] || die "--exe needs a value"; exe=$2; shift 2 ;;
    --rerun) [ $# -ge 2 ] || die "--rerun needs a value"; rerun=$2; shift 2 ;;
    -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
    --) shift; run_flags+=("$@"); break ;;
    *) run_flags+=("$1"); shift ;;
  esac
done

[[ $shards =~ ^[1-9][0-9]*$ ]] || die "--shards '$shards' is not a positive integer"
command -v sbatch >/dev/null 2>&1 || die "sbatch not found: run this on a Slurm login node"

if [ -z "$exe" ]; then
  if [ -x "$repo/build/contact-suite" ]; then
    exe=$repo/build/contact-suite
  else
    exe=$(command -v contact-suite) || die "no contact-suite binary: build it or pass --exe PATH"
  fi
fi
[ -x "$exe" ] || die "'$exe' is not an executable file"
exe=$(readlink -f "$exe")
out=$(readlink -m "$out")

array=1-$shards
if [ -n "$rerun" ]; then
  [[ $rerun =~ ^[1-9][0-9]*(,[1-9][0-9]*)*$ ]] || die "--rerun '$rerun' is not a list like 2 or 2,5"
  IFS=, read -r -a again <<<"$rerun"
  for k in "${again[@]}"; do
    [ "$k" -le "$shards" ] || die "--rerun slice $k is not one of 1..$shards"
  done
  [ -d "$out" ] || die "--rerun needs the existing output directory $out"
  array=$rerun
elif compgen -G "$out/shard-*" >/dev/null || [ -e "$out/results.json" ]; then
  die "$out already holds a run: choose a new --out, or --rerun the slices that failed"
fi
mkdir -p "$out/logs"

# The binary and N travel in the environment, the run flags as the scripts' arguments (kept word
# for word). Not --export=ALL,VAR=value: a list there makes slurmd load the user's login
# environment for every task (`su - user -c env`), which took 5 s a task in our measurements.
export CONTACT_SUITE=$exe CS_SHARDS=$shards
common=(--parsable --chdir="$out" --export=ALL)
array_job=$(sbatch "${common[@]}" --array="$array" --output="$out/logs/%x-%A_%a.out" \
  "$here/contact-suite-array.sbatch" "$out" "${run_flags[@]}")
array_job=${array_job%%;*}  # --parsable prints ID or ID;CLUSTER
merge_job=$(sbatch "${common[@]}" --dependency="afterok:$array_job" --kill-on-invalid-dep=yes \
  --output="$out/logs/%x-%j.out" "$here/contact-suite-merge.sbatch" "$out" "$shards")
merge_job=${merge_job%%;*}

echo "ci/slurm/submit.sh: array job $array_job (slices $array of $shards), merge job $merge_job" \
  "after it; results in $out/results.json, logs in $out/logs/" >&2
echo "array_job=$array_job"
echo "merge_job=$merge_job"
