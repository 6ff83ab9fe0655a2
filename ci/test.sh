#!/usr/bin/env bash
# Every test: set up, build, and run the unit, verification and regression suites.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
bash ci/build.sh build
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 600
bash ci/accuracy-gate.sh build
echo "ci/test.sh: finished in $(( $(date +%s) - start )) s"
