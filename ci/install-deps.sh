#!/usr/bin/env bash
# Installs every dependency of contact-suite from Debian's package archive.
# Idempotent; run as root on Debian 12 (bookworm). Nothing else is downloaded.
set -euo pipefail

packages=(
  build-essential cmake pkg-config ninja-build
  libeigen3-dev                           # sparse and small dense algebra
  libsuitesparse-dev libmetis-dev         # CHOLMOD supernodal Cholesky, METIS ordering
  libopenblas0-pthread libopenblas-dev    # the system BLAS/LAPACK CHOLMOD runs on
  libgsl-dev                              # root finding, quadrature
  libfmt-dev libcli11-dev nlohmann-json3-dev
  libkainjow-mustache-dev                 # the report's prose templates (Mustache)
  libpugixml-dev                          # JUnit XML of run and gate (--junit)
  libgtest-dev libgmock-dev libbenchmark-dev
  gnuplot-nox                             # figures of the report
  libxml2-utils                           # xmllint: validates --junit output (tests/ci/junit.xsd)
  python3-dev pybind11-dev                # the Python module contact_suite (python/)
  python3-numpy python3-pytest            # its arrays and its tests
  python3 python3-meshio                  # independent VTU and MSH reader used by tests
  python3-getfem                          # the third graded code (adapters/getfem/)
  calculix-ccx                            # the second solver graded by the suite (ccx 2.20)
)
# Optional groups: `--slurm` adds a single-node Slurm cluster (ci/slurm-smoke.sh);
# `--fuzz` adds clang with libFuzzer and the sanitizer runtimes (ci/fuzz.sh, ci/sanitize.sh).
for arg in "$@"; do
  case "$arg" in
    --slurm) packages+=(slurm-wlm munge) ;;
    --fuzz) packages+=(clang libclang-rt-14-dev) ;;
    *) echo "ci/install-deps.sh: unknown option '$arg' (expected --slurm or --fuzz)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
echo "ci/install-deps.sh: all ${#packages[@]} packages present"
