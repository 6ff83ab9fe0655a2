#!/usr/bin/env bash
# The CalculiX battery (issue 13): every problem of the study's battery that CalculiX can take,
# on the C, M and F meshes, Q4 and Q8, with each CalculiX contact option the study's options map
# to, and the same cases with our built-in solver, so that the cost of the two solvers is
# measured in one run on the same cases. Writes OUT/results.json (both solvers) and its report.
#
#   bash ci/calculix-battery.sh [OUT] [BUILD_DIR]     # OUT: out/calculix, BUILD_DIR: build
#
# The selection: problems P_p P_a Pprime_p Pprime_a H_p H_a S_1 S_1_3 S_1_7 F_p F_a (a
# discretized indenter: CalculiX has no rigid analytic target) and the interference fits IF_p
# IF_a (two meshed bodies); CalculiX's four options by its
# own labels (LINEAR and HARD, node-to-surface and surface-to-surface; ccx 2.20 rejects mortar
# on 2D elements, and it has no augmented Lagrangian, Lagrange-multiplier or MPC contact in 2D),
# each graded on both stress bases (own and the common spr); ours with PM and LMP, ns and ss.
#
# How it runs:
#   - one `run` process per problem, mesh, element and solver (--jobs 1), so that a case's
#     peak_rss_mb (the process's peak, or ccx's, whichever is larger) is that model's and not
#     an earlier, larger one's; each writes OUT-parts/<solver>-<problem>-<mesh>-<element>/;
#   - the built-in solver first (minutes), then CalculiX on C and M but S, on F but S, on the
#     Steuermann C and M meshes, and on the Steuermann F meshes last (the slowest; the
#     Steuermann parts take most of the battery's hours). A case may take 600 s, a Steuermann
#     case on M or F CALCULIX_BATTERY_S_LIMIT s (default 3600: LINEAR contact needs more than
#     600 s on S(1/3) M Q8 on a quiet machine, and S(1/3) F Q4 timed out at 600 s);
#     CALCULIX_BATTERY_JOBS (default 1) sets --jobs of the CalculiX runs of the S F meshes;
#     CALCULIX_BATTERY_STAGES (default all: "builtin calculix-C-M calculix-F calculix-C-M-S
#     calculix-F-S")
#     runs only the stages named (e.g. the CalculiX stages in a second process beside the
#     built-in one; parts are directories of their own, so two processes share the work);
#   - a case CalculiX does not converge on is `not converged` with ccx's reason, one it does not
#     finish in its time limit is `timeout`; either way the run goes on (exit 1 of a run is accepted);
#   - finally `merge --mixed-builds OUT OUT-parts/*/results.json` combines the parts into one
#     results.json (parts resumed after a new commit come from another build: the merged run
#     names every build and its number of parts, and the report shows it) and
#     report, and the script prints the wall time of each stage and of the whole battery.
# Parts already present (a results.json in their directory) are not run again: after an
# interruption the script picks up where it stopped. Delete OUT-parts to start afresh.
# Two processes may share the work (e.g. a second one with CALCULIX_BATTERY_STAGES=calculix-F-S):
# each part is claimed by a lock directory OUT-parts/<part>.lock, so no part runs twice; the
# merge leaves out the parts another process still holds, and says how many. Memory: one ccx on
# a Steuermann F Q8 model takes 13-14 GB (LINEAR, ns and ss alike); two of them on a 24 GiB
# machine were killed by the kernel's OOM killer, so the CalculiX Steuermann F parts take turns
# across processes (lock OUT-parts/steuermann-F.lock): a process that finds the turn taken
# leaves that part for later, says so, and goes on.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/calculix}
build_dir=${2:-build}
exe="$build_dir/contact-suite"
parts="$out-parts"
s_jobs=${CALCULIX_BATTERY_JOBS:-1}
stages=${CALCULIX_BATTERY_STAGES:-builtin calculix-C-M calculix-F calculix-C-M-S calculix-F-S}
problems_not_s=(P_p P_a Pprime_p Pprime_a H_p H_a F_p F_a IF_p IF_a)
s_limit=${CALCULIX_BATTERY_S_LIMIT:-3600}
problems_s=(S_1 S_1_3 S_1_7)
common=(--target discretized --no-report)
# Ours: the study's PM and LMP with ns and ss. CalculiX: its own four options (linear-ns,
# linear-ss, hard-ns, hard-ss: `contact-suite list`), each on both stress bases (own and the
# common spr), one ccx run per option.
builtin_options=(--algorithms PM,LMP --contacts ns,ss)

[ -x "$exe" ] || { echo "calculix-battery: $exe not built (bash ci/build.sh $build_dir)" >&2; exit 2; }
command -v ccx > /dev/null || { echo "calculix-battery: ccx not on PATH (ci/install-deps.sh)" >&2; exit 2; }
mkdir -p "$parts"
battery_start=$(date +%s)

# claim DIR: take the part DIR for this process (a lock directory holding our pid), or fail when
# a live process holds it; a lock left by a process that is gone is taken over.
claims=()
claim() {
  local lock="$1.lock"
  if ! mkdir "$lock" 2> /dev/null; then
    local holder
    holder=$(cat "$lock/pid" 2> /dev/null || true)
    # No pid yet: its holder is between mkdir and writing it.
    if [ -z "$holder" ] || kill -0 "$holder" 2> /dev/null; then return 1; fi
    rm -rf "$lock"
    mkdir "$lock" 2> /dev/null || return 1
  fi
  echo $$ > "$lock/pid"
  claims+=("$lock")
}
trap '[ ${#claims[@]} -eq 0 ] || rm -rf "${claims[@]}"' EXIT

# run_part SOLVER PROBLEM MESH ELEMENT JOBS: one `run` of the selection's cases of one model.
run_part() {
  local solver=$1 problem=$2 mesh=$3 element=$4 jobs=$5
  local dir="$parts/$solver-$problem-$mesh-$element"
  [ -f "$dir/results.json" ] && return 0
  claim "$dir" || return 0
  local status=0
  local options=()
  [ "$solver" = builtin ] && options=("${builtin_options[@]}")
  local limit=600
  [[ $problem == S_* && $mesh != C ]] && limit=$s_limit
  # A CalculiX Steuermann F part takes 13-14 GB: one at a time on the machine. A process that
  # finds another holding that turn leaves the part to it (or to a later run) and goes on.
  local heavy=0
  if [[ $solver == calculix && $problem == S_* && $mesh == F ]]; then
    if ! claim "$parts/steuermann-F"; then
      echo "calculix-battery: $dir left for later: another process runs a Steuermann F part" >&2
      rm -rf "$dir.lock"
      return 0
    fi
    heavy=1
  fi
  "$exe" run --solver "$solver" --problems "$problem" --meshes "$mesh" --elements "$element" \
    "${common[@]}" "${options[@]}" --time-limit "$limit" --jobs "$jobs" --out "$dir" || status=$?
  # Exit 1: some case did not converge or timed out; that is a result, recorded in the file.
  [ "$status" -le 1 ] || { echo "calculix-battery: $dir failed (exit $status)" >&2; exit "$status"; }
  rm -rf "$dir.lock"
  [ "$heavy" = 0 ] || rm -rf "$parts/steuermann-F.lock"
}

# stage NAME SOLVER JOBS MESHES PROBLEMS...: every part of the given meshes and problems.
stage() {
  local name=$1 solver=$2 jobs=$3 meshes=$4
  shift 4
  case " $stages " in *" $name "*) ;; *) return 0 ;; esac
  local start
  start=$(date +%s)
  for problem in "$@"; do
    for mesh in $meshes; do
      for element in Q4 Q8; do
        run_part "$solver" "$problem" "$mesh" "$element" "$jobs"
      done
    done
  done
  echo "calculix-battery: stage $name took $(($(date +%s) - start)) s"
}

stage builtin builtin 1 "C M F" "${problems_not_s[@]}" "${problems_s[@]}"
stage calculix-C-M calculix 1 "C M" "${problems_not_s[@]}"
stage calculix-F calculix 1 "F" "${problems_not_s[@]}"
stage calculix-C-M-S calculix 1 "C M" "${problems_s[@]}"
stage calculix-F-S calculix "$s_jobs" "F" "${problems_s[@]}"

held=$(find "$parts" -maxdepth 1 -type d -name '*.lock' | wc -l)
[ "$held" -eq 0 ] || echo "calculix-battery: $held part(s) still running in another process; merging what is done"
# exit 1: some case did not converge or timed out, recorded in the merged results
"$exe" merge --mixed-builds "$out" "$parts"/*/results.json || [ $? -le 1 ]
echo "calculix-battery: wall time $(($(date +%s) - battery_start)) s; results in $out/results.json"
