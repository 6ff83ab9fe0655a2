#!/usr/bin/env bash
# Times the contact algorithms (bench/bench_contact_algorithms, Google Benchmark) and writes a
# report with a "Benchmarks" section from the timings. Not part of ci/test.sh or ci/main.sh:
# the whole matrix takes long (see BENCH_FILTER).
#
#   bash ci/bench.sh [build-dir] [out-dir] [results.json]
#
#   build-dir     a built tree (default: build; build it with bash ci/build.sh)
#   out-dir       where bench.json and report/ go (default: <build-dir>/bench-out)
#   results.json  the results to report on beside the timings (default: out/results.json of
#                 bash ci/main.sh when it exists; else a run of the benchmarks' problems,
#                 H_p, S_1_7 and Pprime_p, on the C and M meshes, written to out-dir/run)
#
# Environment:
#   BENCH_FILTER  the --benchmark_filter regex. Default '^Contact': every Contact and
#                 ContactAllOptions benchmark of H_p, S_1_7 and P'_p on the C, M and F meshes.
#                 The F meshes of S_1_7 take about 7 s (Q4) and 30 s (Q8) per case on 2 cores,
#                 so the default runs for about 12 minutes. Names are
#                 Contact/<problem>/<mesh>/<element>/<contact>/<algorithm> and
#                 ContactAllOptions/<problem>/<mesh>/<element>, e.g.
#                   BENCH_FILTER='^Contact(AllOptions)?/[^/]+/(C|M)/'   C and M meshes only
#                   BENCH_FILTER='^Contact/H_p/F/'                      H_p at mesh F
#                 ModelCases/<problem>/<mesh>/<element> (a model's full set of cases against
#                 one analysis of it, shown in its own table) is not in the default, e.g.
#                   BENCH_FILTER='^ModelCases/(S_1_7|H_p)/F/Q8'        reports/study/bench/
#                                                  bench_model_cases.json, with 3 repetitions
#   BENCH_ARGS    further arguments of the benchmark program, e.g. --benchmark_repetitions=3
#                 (the report shows the median).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
out_dir=${2:-$build_dir/bench-out}
results=${3:-}
filter=${BENCH_FILTER:-^Contact}
bench="$build_dir/bench/bench_contact_algorithms"
exe="$build_dir/contact-suite"

for program in "$bench" "$exe"; do
  if [ ! -x "$program" ]; then
    echo "ci/bench.sh: $program not found: build first (bash ci/build.sh $build_dir)" >&2
    exit 2
  fi
done
mkdir -p "$out_dir"

# shellcheck disable=SC2086  # BENCH_ARGS is a list of words
"$bench" --benchmark_filter="$filter" --benchmark_out="$out_dir/bench.json" \
  --benchmark_out_format=json ${BENCH_ARGS:-}

if [ -z "$results" ] && [ -f out/results.json ]; then
  results=out/results.json
fi
if [ -z "$results" ]; then
  status=0
  "$exe" run --problems H_p,S_1_7,Pprime_p --meshes C,M --contacts ss,ns,mortar \
    --out "$out_dir/run" --no-report || status=$?
  # Exit 1: some analyses did not converge, a finding the report shows.
  [ "$status" -le 1 ] || exit "$status"
  results="$out_dir/run/results.json"
fi

"$exe" report --results "$results" --bench "$out_dir/bench.json" --out "$out_dir/report"
echo "ci/bench.sh: timings in $out_dir/bench.json, report in $out_dir/report/report.md"
