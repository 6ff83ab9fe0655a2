#!/usr/bin/env bash
# The parameter sweeps of issue 14 (`contact-suite run --sweep`), answering the study's open
# question on FKN, FTOLN and the pinball, and the stiff-indenter question (E ratio):
#
#   bash ci/sweeps.sh [OUT] [build-dir]
#
#   OUT        output directory (default: out/sweeps). Each sweep is one run, written to
#              OUT/<name>/results.json; `merge` combines them into OUT/all/results.json (the
#              cases and rows of every run, every swept key in run.sweep) with its report
#              OUT/all/report.md and its "Parameter sweeps" section.
#   build-dir  a built tree (default: build)
#
# The sweeps (cases that differ only in FKN, FTOLN or the pinball share one model and its
# factorization; a different E ratio is a different model):
#   fkn      1e-3 .. 1e4 (8 values): AL, PM and LMP (the exactly enforced limit) with ss, ns and
#            mortar, Q4 and Q8, on H_p and H_a on C, M and F (convergence c); AL and PM ss on
#            S_1_7 and S_1_3 with Q4 on F (S(1/3) Q4 ss F is the study's -13 % AL case) and on
#            S_1_7 with Q8 on M (an F Q8 Steuermann model alone takes minutes); AL ns and
#            mortar on the axisymmetric patch tests P_a and Pprime_a, Q8, F;
#   ftoln    1e-3 .. 1 at the default FKN: AL, H_p and H_a, F, Q4 and Q8, ss and mortar;
#   pinball  1e-3 .. 1e3 for MPC (the study's IMC): H_p and H_a, F, Q4 and Q8, ss and ns;
#   E_ratio  1e3 .. 1e9: LMP and AL ss, Pprime_p and H_p, F, Q4 and Q8.
# SWEEP_JOBS sets --jobs (default 2). Time and memory: see docs/sweeps.md.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/sweeps}
build_dir=${2:-build}
exe="$build_dir/contact-suite"
if [ ! -x "$exe" ]; then
  echo "ci/sweeps.sh: $exe not found: build first (bash ci/build.sh $build_dir)" >&2
  exit 2
fi
mkdir -p "$out"
jobs=${SWEEP_JOBS:-2}
fkn=1e-3,1e-2,0.1,1,10,100,1e3,1e4

sweep() {  # sweep NAME ARGS...: one run into OUT/NAME, results.json only
  local name=$1
  shift
  echo "ci/sweeps.sh: $name: $*" >&2
  "$exe" run --jobs "$jobs" --out "$out/$name" --no-report "$@" || {
    local rc=$?
    # 1: some case did not converge, itself a finding of the sweep (high FKN cycles).
    [ "$rc" -eq 1 ] || exit "$rc"
  }
}

sweep fkn_H --problems H_p,H_a --elements Q4,Q8 --algorithms AL,PM,LMP \
  --contacts ss,ns,mortar --sweep fkn=$fkn
sweep fkn_P --problems P_a,Pprime_a --meshes F --elements Q8 --algorithms AL --contacts ns,mortar \
  --sweep fkn=$fkn
sweep fkn_S_Q4 --problems S_1_7,S_1_3 --meshes F --elements Q4 --algorithms AL,PM --contacts ss \
  --sweep fkn=$fkn
sweep fkn_S_Q8 --problems S_1_7 --meshes M --elements Q8 --algorithms AL,PM --contacts ss \
  --sweep fkn=$fkn
sweep ftoln --problems H_p,H_a --meshes F --elements Q4,Q8 --algorithms AL --contacts ss,mortar \
  --sweep ftoln=1e-3,1e-2,0.1,0.5,1
sweep pinball --problems H_p,H_a --meshes F --elements Q4,Q8 --algorithms MPC --contacts ss,ns \
  --sweep pinball=1e-3,1e-2,0.1,0.5,1,10,1e3
sweep E_ratio --problems Pprime_p,H_p --meshes F --elements Q4,Q8 --algorithms LMP,AL \
  --contacts ss --sweep E_ratio=1e3,1e4,1e5,1e6,1e7,1e8,1e9

# One results file of every sweep (`merge` joins unsharded runs too: their cases, rows and
# sweeps), and its report with the "Parameter sweeps" section.
parts=()
for name in fkn_H fkn_P fkn_S_Q4 fkn_S_Q8 ftoln pinball E_ratio; do
  parts+=("$out/$name/results.json")
done
"$exe" merge "$out/all" "${parts[@]}" || {
  rc=$?
  [ "$rc" -eq 1 ] || exit "$rc"  # 1: cases that did not converge are among the parts
}
echo "ci/sweeps.sh: wrote $out/all/results.json and $out/all/report.md" >&2
