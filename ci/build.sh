#!/usr/bin/env bash
# Installs the Debian dependencies, then configures and builds contact-suite (Release).
# Usage: bash ci/build.sh [build-dir]     (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}

if [ "$(id -u)" -eq 0 ]; then
  bash ci/install-deps.sh
else
  echo "ci/build.sh: not root, assuming the dependencies of ci/install-deps.sh are installed"
fi
generator=()
command -v ninja >/dev/null 2>&1 && generator=(-G Ninja)
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  cmake -S . -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release
elif [ ! -f "$build_dir/build.ninja" ] && [ ! -f "$build_dir/Makefile" ]; then
  # An earlier configure stopped (a dependency was missing) after writing its cache: again.
  cmake -S . -B "$build_dir"
fi
cmake --build "$build_dir" --parallel "$(nproc)"
