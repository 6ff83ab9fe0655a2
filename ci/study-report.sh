#!/usr/bin/env bash
# Regenerates the committed report, reports/study/, from the main job and the studies beyond it:
#
#   bash ci/study-report.sh [--reuse]
#
# Runs ci/main.sh (out/results.json), the friction problems FP_p and CM_p (out/friction/; 20 s),
# ci/extent.sh (out/extent/) and ci/sweeps.sh (out/sweeps/) unless --reuse is given, in which case it uses the results already in out/. Results of the
# VF refinement (ci/refine.sh: out/refine/results.json and out/refine/steuermann/results.json;
# its C, M and F cases repeat the main job's and are kept once) are added when present; the
# other codes' battery parts (ci/calculix-battery.sh: out/calculix-parts/, ci/getfem-battery.sh:
# out/getfem-parts/) are merged into a report of their own, reports/study/cross-code/ (ours,
# CalculiX and GetFEM graded alike), when present;
# they take long, so they are not run here; nor is ci/cost-run.sh (out/cost/: the cross-code
# cost tables, every code on the same models in one run). The coarse meshes of four problems
# are exported for Figure 3, and the committed benchmark JSON files are shown as the benchmarks appendix.
set -euo pipefail
cd "$(dirname "$0")/.."
reuse=0
case "${1:-}" in
  --reuse) reuse=1 ;;
  '') ;;
  *) echo "ci/study-report.sh: unknown argument '$1' (only --reuse)" >&2; exit 2 ;;
esac
if [ "$reuse" = 0 ]; then
  bash ci/main.sh
  ./build/contact-suite run --problems FP_p,CM_p --algorithms AL,PM,LMP,PLM \
    --contacts ss,ns,mortar --recovery spr --no-report --out out/friction || [ $? -le 1 ]
  bash ci/extent.sh out/extent
  bash ci/sweeps.sh out/sweeps
fi
exe=./build/contact-suite
results=(--results out/results.json)
for f in out/friction/results.json out/extent/*/results.json out/sweeps/all/results.json out/refine/results.json \
  out/refine/steuermann/results.json; do
  if [ -f "$f" ]; then results+=(--results "$f"); fi
done
rm -rf out/meshes
"$exe" export --problems H_p,S_1_3,F_p,Pprime_p --meshes C --elements Q4 --algorithms LMP \
  --contacts ss --out out/meshes >/dev/null
# the median runs last: a case measured in several files is shown from the last; ModelCases
# (issue #27: a model's 30 cases against one analysis) share no case with the others
bench=()
for f in bench_all_meshes bench_F_H_p_Pprime_p_median5 bench_F_H_p_Q8_median7 bench_model_cases; do
  if [ -f "reports/study/bench/$f.json" ]; then bench+=(--bench "reports/study/bench/$f.json"); fi
done
# The other codes' batteries (ci/calculix-battery.sh, ci/getfem-battery.sh) as one report of their
# own: each battery's parts hold both its code's and our cases of the same models, run the same
# way (one job, one model per part), so that the cost ratios compare like with like.
others=()
for code in calculix getfem; do
  if compgen -G "out/$code-parts/*/results.json" > /dev/null; then
    # exit 1: some case did not converge or timed out, a finding recorded in the results;
    # its parts may span commits (the battery resumes): the merged run names each build
    "$exe" merge --mixed-builds "out/$code" "out/$code-parts"/*/results.json || [ $? -le 1 ]
    others+=(--results "out/$code/results.json")
  fi
done
# every code on the same models in one run (ci/cost-run.sh): the cross-code cost tables
cost=()
if [ -f out/cost/results.json ]; then cost=(--cost-run out/cost/results.json); fi
if [ ${#others[@]} -gt 0 ]; then
  "$exe" report "${others[@]}" "${cost[@]}" --out reports/study/cross-code
fi
# linked from the main report's header when present
companion=()
if [ -f reports/study/cross-code/report.md ]; then companion=(--companion cross-code/report.md); fi
"$exe" report "${results[@]}" --mesh-pictures out/meshes "${bench[@]}" "${companion[@]}" \
  --out reports/study
echo "ci/study-report.sh: reports/study/report.md from ${#results[@]} results arguments"
