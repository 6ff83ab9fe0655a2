#!/usr/bin/env bash
# Each code's cost on the same cases, measured in one run (issue #24):
#
#   bash ci/cost-run.sh [OUT_DIR] [BUILD_DIR]        (default out/cost, build; about 6 min)
#
# Ours, CalculiX and GetFEM solve the same models: the study's meshed indenter on P_p, P'_p, H_p
# and F_p, and the interference fit IF_p (two meshes), with the C, M and F meshes of Q4 and Q8.
# One model after another and, per model, the three codes one after another, each with one
# job: the codes meet the same machine state, so their time ratios are measured, not merely of
# the right order as the battery parts' (which ran at other times, often beside other work).
# Run it on an otherwise idle machine: it prints the load average before and after. The parts
# go to OUT_DIR-parts/ and are merged into OUT_DIR/results.json, which `ci/study-report.sh`
# hands to the cross-code report (--cost-run).
# Options: ours AL, PM, LMP with ns and ss (those the other codes' options map to); CalculiX all
# four; GetFEM nodal AL, integral AL and penalty (its Nitsche brick has no meshed target).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/cost}
build_dir=${2:-build}
exe="$build_dir/contact-suite"
parts="$out-parts"

[ -x "$exe" ] || { echo "cost-run: $exe not built (bash ci/build.sh $build_dir)" >&2; exit 2; }
command -v ccx > /dev/null || { echo "cost-run: ccx not on PATH (ci/install-deps.sh)" >&2; exit 2; }
/usr/bin/python3 -c 'import getfem' 2> /dev/null ||
  { echo "cost-run: python3-getfem is not installed (ci/install-deps.sh)" >&2; exit 2; }
mkdir -p "$parts"
echo "cost-run: load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
start=$(date +%s)

# Every part runs anew (the tool replaces an output set it wrote, and refuses a directory it did
# not make), and the merge reads this run's parts only.
done_parts=()
run_part() {
  local solver=$1 problem=$2 mesh=$3 element=$4
  local dir="$parts/$solver-$problem-$mesh-$element"
  local args=(run --solver "$solver" --problems "$problem" --meshes "$mesh" --elements "$element"
              --target discretized --jobs 1 --no-report --out "$dir")
  case "$solver" in
    builtin) args+=(--algorithms AL,PM,LMP --contacts ns,ss) ;;
    getfem) args+=(--solver-options nodal_al,integral_al,penalty) ;;
  esac
  local status=0
  "$exe" "${args[@]}" > /dev/null || status=$?
  [ "$status" -le 1 ] || { echo "cost-run: $solver $problem $mesh $element failed (exit $status)" >&2; exit "$status"; }
  done_parts+=("$dir/results.json")
}

for problem in P_p Pprime_p H_p F_p IF_p; do
  for mesh in C M F; do
    for element in Q4 Q8; do
      for solver in builtin calculix getfem; do run_part "$solver" "$problem" "$mesh" "$element"; done
    done
  done
  echo "cost-run: $problem done after $(($(date +%s) - start)) s"
done
"$exe" merge "$out" "${done_parts[@]}" || [ $? -le 1 ]
echo "cost-run: load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "cost-run: wall time $(($(date +%s) - start)) s; results in $out/results.json"
