#!/usr/bin/env bash
# ASan + UBSan: builds everything with CONTACT_SUITE_SANITIZE=ON in build-sanitize/, runs every
# test and a short run of the battery. Too slow for every CI run (a sanitized build of the whole
# project is several times the Release build); run it before a release and after changes to
# parsers, the solver's memory handling or the process layer.
#   bash ci/sanitize.sh
set -euo pipefail
cd "$(dirname "$0")/.."
[ "$(id -u)" -ne 0 ] || bash ci/install-deps.sh
build_dir=build-sanitize
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCONTACT_SUITE_SANITIZE=ON -DCONTACT_SUITE_BUILD_BENCH=OFF
fi
cmake --build "$build_dir" --parallel "$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1
# The tests that load the sanitized Python module into python3 (the module's own tests, and the
# GetFEM protocol tests, whose script imports it) run apart: python3 is not built with ASan, so
# its runtime must come first (LD_PRELOAD), with libstdc++ (python3 does not link it, and ASan
# finds __cxa_throw only in a library loaded before it), without leak checks (the interpreter's
# own allocations at exit), and with allocations too large to make returning null, so that an
# evaluation too large raises MemoryError as in a normal build.
hosted='python|Getfem'
ctest --test-dir "$build_dir" --output-on-failure --parallel "$(nproc)" --timeout 1800 \
  -E "$hosted"
LD_PRELOAD="$(gcc -print-file-name=libasan.so) $(readlink -f "$(gcc -print-file-name=libstdc++.so)")" \
  ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:allocator_may_return_null=1 \
  ctest --test-dir "$build_dir" --output-on-failure --parallel "$(nproc)" --timeout 1800 \
  -R "$hosted"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$build_dir/contact-suite" run --problems P_p,H_p,F_p,S_1 --meshes C,M --contacts ss,ns,mortar \
  --out "$out/run" --jobs 2 || [ $? -eq 1 ]
echo "ci/sanitize.sh: ASan+UBSan clean on the tests and a run"
