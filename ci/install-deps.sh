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
  libgtest-dev libgmock-dev libbenchmark-dev
  gnuplot-nox                             # figures of the report
  python3 python3-meshio                  # independent VTU reader used by a test
)

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
