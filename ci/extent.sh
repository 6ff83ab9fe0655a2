#!/usr/bin/env bash
# The domain-extent study (issue #12): how much of each error is the study's finite block and
# how much the discretization, and the Steuermann grades at a block that stands for a
# half-space ("S, half-space"). The block is enlarged with `--set extent=K` (width and depth K
# times the study's; the mesh within half the study's extent is unchanged).
#
#   bash ci/extent.sh [OUT]      (default: out/extent)
#
# Writes OUT/lmp-extent-{2,4}/results.json (LMP ss, Q4 and Q8, C M F, on S_1, S_1_3, S_1_7, H_p
# and F_p: a Richardson limit per extent), OUT/all-extent-8/results.json (every algorithm and
# discretization of the Steuermann problems at extent 8) and OUT/lmp-extent-8/results.json (H_p
# and F_p at extent 8), OUT/lmp-extent-16/results.json (S_1_7, LMP ss, at extent 16: its
# half-space extent lies beyond 4), OUT/all-extent-8-half-space-gap/results.json (the Steuermann problems at
# extent 8 again, with gaps along the block's own normal: `--set half_space_gap=1`). The extent-1 rows are the main job's (ci/main.sh); give all of them to
# `contact-suite report --results ...` (ci/study-report.sh does) for the report's section.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/extent}
case "$out" in -*) echo "ci/extent.sh: OUT must not start with '-'" >&2; exit 2 ;; esac
bash ci/build.sh build
mkdir -p "$out"
exe=./build/contact-suite
common=(--algorithms LMP --contacts ss --recovery spr --no-report)
# exit 1 means some case did not converge: recorded in the results, not a failure of the study
run() { "$exe" run "$@" || [ $? -le 1 ]; }
for k in 2 4; do
  run --problems S_1,S_1_3,S_1_7,H_p,F_p "${common[@]}" --set "extent=$k" \
    --out "$out/lmp-extent-$k"
done
run --problems H_p,F_p "${common[@]}" --set extent=8 --out "$out/lmp-extent-8"
# S(1/7) still changes by more than 0.05 % from 4 to 8: one more doubling for its half-space extent
run --problems S_1_7 "${common[@]}" --set extent=16 --out "$out/lmp-extent-16"
run --problems S_1,S_1_3,S_1_7 --contacts ss,ns,mortar --recovery spr --no-report \
  --set extent=8 --out "$out/all-extent-8"
# The same with the half-space theory's gap (along the block's own normal; the report's
# "half-space gap" tables): what is left of the S errors once the first-order tilt term is gone.
run --problems S_1,S_1_3,S_1_7 --contacts ss,ns,mortar --recovery spr --no-report \
  --set extent=8 --set half_space_gap=1 --out "$out/all-extent-8-half-space-gap"
echo "ci/extent.sh: results in $out/*/results.json"
