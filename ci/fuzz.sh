#!/usr/bin/env bash
# libFuzzer on the readers of untrusted input (fuzz/: results.json, the gate's baseline, --set
# and the list options, CalculiX's .frd and .sta). Builds the targets with clang
# (CONTACT_SUITE_FUZZ=ON, ASan + UBSan) in build-fuzz/ and runs each for SECONDS_PER_TARGET
# (default 600) from its committed seed corpus fuzz/corpus/<target>/, copied first into a scratch
# corpus so that the repository is not modified. Prints per target the executions, the corpus it
# grew and the crashes (any crash, sanitizer report, leak, timeout or out-of-memory), and exits 1
# if there is one; the input that caused it is kept in build-fuzz/work/<target>/findings/.
#   bash ci/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]   (default: every target in fuzz/)
# A finding reproduces with: build-fuzz/fuzz/<target> <input>. One instance at a time: the
# targets run one after the other (each is single-threaded).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
[ "$(id -u)" -ne 0 ] || bash ci/install-deps.sh --fuzz

# Every fuzz/<target>.cpp is a target (fuzz/CMakeLists.txt: cs_add_fuzz_target).
if [ $# -gt 0 ]; then
  targets=("$@")
else
  targets=()
  for f in fuzz/*.cpp; do
    grep -q LLVMFuzzerTestOneInput "$f" && targets+=("$(basename "$f" .cpp)")
  done
fi

build_dir=build-fuzz
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER=clang++ -DCONTACT_SUITE_FUZZ=ON "${launcher[@]}"
fi
cmake --build "$build_dir" --parallel "$(nproc)" --target "${targets[@]}"

export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1
failed=0
summary=()
for t in "${targets[@]}"; do
  work="$build_dir/work/$t"
  rm -rf "$work"
  mkdir -p "$work/corpus" "$work/findings"
  cp fuzz/corpus/"$t"/* "$work/corpus/"
  seeds=$(find "$work/corpus" -type f | wc -l)
  echo "ci/fuzz.sh: $t for ${seconds} s from $seeds seeds (log: $work/fuzz.log)"
  status=0
  "$build_dir/fuzz/$t" "$work/corpus" -max_total_time="$seconds" -rss_limit_mb=2048 \
    -timeout=10 -print_final_stats=1 -artifact_prefix="$work/findings/" \
    >"$work/fuzz.log" 2>&1 || status=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/fuzz.log" | tail -1)
  files=$(find "$work/corpus" -type f | wc -l)
  bytes=$(du -sb "$work/corpus" | cut -f1)
  crashes=$(find "$work/findings" -type f | wc -l)
  if [ "$status" -ne 0 ] || [ "$crashes" -ne 0 ]; then
    failed=1
    echo "ci/fuzz.sh: $t FAILED (exit $status):"
    grep -E 'ERROR: |runtime error|^SUMMARY|Test unit written' "$work/fuzz.log" | head -8
  fi
  summary+=("$(printf '%-14s %6s s  %12s executions  corpus %5s files %9s bytes  %s crashes' \
    "$t" "$seconds" "${execs:-?}" "$files" "$bytes" "$crashes")")
done

echo "ci/fuzz.sh: summary"
printf '  %s\n' "${summary[@]}"
if [ "$failed" -ne 0 ]; then
  echo "ci/fuzz.sh: FINDINGS (inputs in $build_dir/work/<target>/findings/)" >&2
  exit 1
fi
echo "ci/fuzz.sh: no crash in ${#targets[@]} targets"
