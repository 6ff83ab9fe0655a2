#!/usr/bin/env bash
# The fourth mesh (VF, h/8, beyond the study): runs the battery on C, M, F and VF so that every
# row has its C-M-F and M-F-VF verdicts side by side ("Error estimates and refinement" in the
# report), and records the time and peak memory of each run.
#
#   bash ci/refine.sh [OUT]        (default: out/refine)
#
# Writes
#   OUT/results.json, OUT/report.md   P, P', H, F: Q4 and Q8, every algorithm, ss and ns,
#                                     the study's discretized (stiff) target
#   OUT/steuermann/results.json, ...  S(1), S(1/3), S(1/7): Q4 with the rigid target (the
#                                     largest, S(1/7) VF Q4, has 2.15 million equations and
#                                     peaks at 3.8 GB this way; Q8 at VF, three times the
#                                     equations, is not run)
#   OUT/time-*.txt                    /usr/bin/time -v of each run (wall time, peak memory)
# Not part of ci/main.sh: the VF cases alone take far longer than its 5-minute budget.
# Exit 0 on success, 1 if some analyses did not converge (a finding, in the report), else the
# failing command's code.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/refine}
bash ci/build.sh build
exe=./build/contact-suite
timer=()
[ -x /usr/bin/time ] && timer=(/usr/bin/time -v)
mkdir -p "$out"
status=0

# Runs contact-suite run with the given flags, timed into $out/time-NAME.txt.
timed_run() {
  local name=$1 dir=$2
  shift 2
  local rc=0
  if [ ${#timer[@]} -gt 0 ]; then
    "${timer[@]}" -o "$out/time-$name.txt" "$exe" run "$@" --out "$dir" || rc=$?
    grep -E "Elapsed|Maximum resident" "$out/time-$name.txt" | sed "s/^\s*/ci\/refine.sh: $name: /"
  else
    "$exe" run "$@" --out "$dir" || rc=$?
  fi
  [ "$rc" -le 1 ] || exit "$rc"
  [ "$rc" -eq 0 ] || status=1
}

rm -rf "$out/run" "$out/steuermann"
timed_run structured "$out/run" --problems P_p,P_a,Pprime_p,Pprime_a,H_p,H_a,F_p,F_a \
  --meshes C,M,F,VF --elements Q4,Q8 --contacts ss,ns
timed_run steuermann "$out/steuermann" --problems S_1,S_1_3,S_1_7 --meshes C,M,F,VF \
  --elements Q4 --contacts ss,ns --target rigid
# The structured run is the main result: its files at the top of OUT.
for f in "$out"/run/*; do
  rm -rf "$out/$(basename "$f")"
  mv "$f" "$out/"
done
# What is left is run/'s own marks (.contact-suite*): the directory is dissolved into OUT.
rm -f "$out"/run/.contact-suite*
rmdir "$out/run"
echo "ci/refine.sh: report in $out/report.md, Steuermann rows in $out/steuermann/report.md"
exit "$status"
