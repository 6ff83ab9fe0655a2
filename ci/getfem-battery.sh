#!/usr/bin/env bash
# The GetFEM battery (issue 24): GetFEM's four contact bricks for a rigid obstacle (nodal and
# integral augmented Lagrangian, penalty, Nitsche; adapters/getfem/manifest.json) on the
# plane-strain problems with a rigid target, and its bricks between non-matching meshes on the
# interference fit IF_p (two meshed bodies; Nitsche, which the manifest declares for a rigid
# obstacle only, is left out there by `run`), C, M and F meshes, Q4 and Q8, and, like CalculiX and the study, with the meshed
# indenter on P_p, P'_p, H_p and F_p (its bricks between non-matching meshes but Nitsche), graded
# on both stress bases (spr = common: our patch recovery of GetFEM's displacements; own:
# GetFEM's own nodal stresses), and the same models with
# our built-in solver for the cost comparison. The axisymmetric problems are not supported by
# the adapter: not run.
#
#   bash ci/getfem-battery.sh [OUT] [BUILD_DIR]      # OUT: out/getfem, BUILD_DIR: build
#
# How it runs:
#   - one `run` process per solver, problem, mesh and element (--jobs 1, so that a case's peak
#     memory is that model's), each writing OUT-parts/<solver>-<problem>-<mesh>-<element>/;
#   - stages, in order: builtin (ours, about a minute), getfem (every GetFEM part but the
#     Steuermann F meshes with Q8), getfem-S-F-Q8 (those three models: GetFEM's Newton factorizes
#     their 0.4-1.7 M equations once per iteration, 7-24 iterations per case, so each case takes
#     tens of minutes on 2 cores; --time-limit 3600 s per case), meshed (GetFEM with the meshed
#     indenter, and ours with AL beside it: ours PM and LMP with that indenter are the CalculiX
#     battery's, and the cross-code report reads both batteries; parts OUT-parts/<solver>-meshed-
#     <problem>-<mesh>-<element>/). GETFEM_BATTERY_STAGES (default all four) runs only the
#     stages named;
#   - a case GetFEM does not converge on is `not converged` with the reason, one over the time
#     limit `timeout`; either way the run goes on (exit 1 of a run is accepted);
#   - parts already present (a results.json in their directory) are not run again, so the
#     battery resumes after an interruption; delete OUT-parts to start afresh;
#   - finally `merge --mixed-builds OUT OUT-parts/*/results.json` combines the parts.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/getfem}
build_dir=${2:-build}
exe="$build_dir/contact-suite"
parts="$out-parts"
stages=${GETFEM_BATTERY_STAGES:-builtin getfem getfem-S-F-Q8 meshed}
problems=(P_p Pprime_p H_p F_p S_1 S_1_3 S_1_7 IF_p)

[ -x "$exe" ] || { echo "getfem-battery: $exe not built (bash ci/build.sh $build_dir)" >&2; exit 2; }
/usr/bin/python3 -c 'import getfem' 2> /dev/null ||
  { echo "getfem-battery: python3-getfem is not installed (ci/install-deps.sh)" >&2; exit 2; }
mkdir -p "$parts"
battery_start=$(date +%s)

# run_part SOLVER PROBLEM MESH ELEMENT TIME_LIMIT [meshed]: one `run` of one model's cases;
# with "meshed", the study's meshed indenter instead of the rigid obstacle.
run_part() {
  local solver=$1 problem=$2 mesh=$3 element=$4 limit=$5 meshed=${6:-}
  local dir="$parts/$solver-${meshed:+meshed-}$problem-$mesh-$element"
  [ -f "$dir/results.json" ] && return 0
  local target=rigid
  # IF_p: two meshed bodies, no rigid form
  { [ -n "$meshed" ] || [ "$problem" = IF_p ]; } && target=discretized
  local args=(run --solver "$solver" --problems "$problem" --meshes "$mesh" --elements "$element"
              --target "$target" --jobs 1 --time-limit "$limit" --no-report --out "$dir")
  if [ "$solver" = builtin ]; then
    # with the meshed indenter ours PM and LMP are the CalculiX battery's
    if [ -n "$meshed" ]; then args+=(--algorithms AL --contacts ns,ss)
    else args+=(--algorithms AL,PM,LMP --contacts ns,ss); fi
  fi
  local status=0
  "$exe" "${args[@]}" || status=$?
  # Exit 1: some case did not converge or timed out; that is a result, recorded in the file.
  [ "$status" -le 1 ] || { echo "getfem-battery: $dir failed (exit $status)" >&2; exit "$status"; }
}

# in_stage NAME: whether the stage is selected.
in_stage() { case " $stages " in *" $1 "*) return 0 ;; *) return 1 ;; esac; }

for solver in builtin getfem; do
  for mesh in C M F; do
    for element in Q4 Q8; do
      for problem in "${problems[@]}"; do
        stage=$solver
        [ "$solver" = getfem ] && [ "$mesh$element" = FQ8 ] && [[ $problem == S_* ]] &&
          stage=getfem-S-F-Q8
        in_stage "$stage" || continue
        limit=600
        [ "$stage" = getfem-S-F-Q8 ] && limit=3600
        run_part "$solver" "$problem" "$mesh" "$element" "$limit"
      done
    done
  done
  echo "getfem-battery: $solver parts done after $(($(date +%s) - battery_start)) s"
done
if in_stage meshed; then
  for solver in builtin getfem; do
    for mesh in C M F; do
      for element in Q4 Q8; do
        for problem in P_p Pprime_p H_p F_p; do
          run_part "$solver" "$problem" "$mesh" "$element" 600 meshed
        done
      done
    done
  done
  echo "getfem-battery: meshed parts done after $(($(date +%s) - battery_start)) s"
fi

# exit 1: some case did not converge or timed out, recorded in the merged results
"$exe" merge --mixed-builds "$out" "$parts"/*/results.json || [ $? -le 1 ]
echo "getfem-battery: wall time $(($(date +%s) - battery_start)) s; results in $out/results.json"
