#!/usr/bin/env bash
# The accuracy gate of CI: runs the C and M meshes of every problem and option (and the F mesh
# of every problem but the Steuermann ones, whose fine meshes take most of the full matrix's
# time), the problems beyond the study (the mismatched-node patches of one modulus, the
# interference fits and the two friction problems; 10 s on 2 cores for C, M and F), then checks the results against the committed baseline ci/baseline.json. The gate's
# verdict per row is written as JUnit XML to <build-dir>/ci-accuracy/junit.xml, for the CI's
# test report, and its Markdown summary appended to $GITHUB_STEP_SUMMARY when that is set.
#
#   bash ci/accuracy-gate.sh [build-dir]            # check
#   bash ci/accuracy-gate.sh [build-dir] --update   # rewrite the baseline deliberately
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
exe="$build_dir/contact-suite"
out="$build_dir/ci-accuracy"
rm -rf "$out"
mkdir -p "$out"

"$exe" run --meshes C,M --problems S_1,S_1_3,S_1_7 --contacts ss,ns,mortar \
  --out "$out/steuermann" --no-report
"$exe" run --meshes C,M,F --problems P_p,P_a,Pprime_p,Pprime_a,H_p,H_a,F_p,F_a \
  --contacts ss,ns,mortar --out "$out/others" --no-report
"$exe" run --meshes C,M,F --problems Pprime_p_E1,Pprime_a_E1,IF_p,IF_a,FP_p,CM_p \
  --contacts ss,ns,mortar --out "$out/beyond" --no-report
"$exe" merge "$out/all" "$out/steuermann/results.json" "$out/others/results.json" \
  "$out/beyond/results.json" --no-report
if [ "${2:-}" = "--update" ]; then
  "$exe" gate --baseline ci/baseline.json --results "$out/all/results.json" --update
else
  summary=()
  [ -n "${GITHUB_STEP_SUMMARY:-}" ] && summary=(--summary "$GITHUB_STEP_SUMMARY")
  "$exe" gate --baseline ci/baseline.json --results "$out/all/results.json" \
    --junit "$out/junit.xml" "${summary[@]}"
fi
