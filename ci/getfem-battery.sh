#!/usr/bin/env bash
# The GetFEM battery (issue 24): GetFEM's four contact bricks for a rigid obstacle (nodal and
# integral augmented Lagrangian, penalty, Nitsche; adapters/getfem/manifest.json) on the
# plane-strain problems with a rigid target, C, M and F meshes, Q4 and Q8, graded on both stress
# bases (spr = common: our patch recovery of GetFEM's displacements; own: GetFEM's own nodal
# stresses), and the same models with our built-in solver for the cost comparison. IF_p has no
# rigid target and the axisymmetric problems are not supported by the adapter: not run.
#
#   bash ci/getfem-battery.sh [OUT] [BUILD_DIR]      # OUT: out/getfem, BUILD_DIR: build
#
# Each part is one `run` per problem (--jobs 1, so that peak memory is one case's); the parts
# are merged into OUT/results.json with its report. Exit 0 when every part ran (cases that fail
# or time out are results: a run's exit 1 is accepted).
set -euo pipefail
out=${1:-out/getfem}
build=${2:-build}
exe="$build/contact-suite"
problems=(P_p Pprime_p H_p S_1 S_1_3 S_1_7 F_p)
parts="$out-parts"
mkdir -p "$parts"
for solver in getfem builtin; do
  for problem in "${problems[@]}"; do
    dir="$parts/$solver-$problem"
    [[ -f "$dir/results.json" ]] && continue
    args=(run --problems "$problem" --meshes C,M,F --elements Q4,Q8 --target rigid --jobs 1
          --no-report --out "$dir")
    if [[ $solver == getfem ]]; then
      args+=(--solver getfem)
    else
      args+=(--algorithms AL,PM,LMP --contacts ns,ss)
    fi
    "$exe" "${args[@]}" || [[ $? -eq 1 ]]
  done
done
"$exe" merge "$out" "$parts"/*/results.json || [[ $? -eq 1 ]]
