#!/usr/bin/env bash
# Builds the Debian package of a configured build tree (`cpack -G DEB`) and checks that its
# contents work from an unpacked root, without installing it: the command (`list`, an oracle),
# the Python module (Hertz's plane-strain peak 4/pi), and the oracles' consumer built against the
# unpacked tree with CMake and with pkg-config (tests/install/check.cmake). Prints the package's
# declared dependencies and the time cpack took.
#
# Usage: bash ci/deb-package.sh [BUILD_DIR]    (default: build; built with everything, since
#        cpack installs every target)
# Needs: dpkg-dev (dpkg-shlibdeps computes the dependencies), pkg-config, cmake, a C++ compiler.
set -euo pipefail

src=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-build}" && pwd)
root=$(mktemp -d /tmp/contact-suite-deb-XXXXXX)
trap 'rm -rf "$root"' EXIT

cmake --build "$build" --parallel 2
rm -f "$build"/contact-suite_*.deb
start=$(date +%s.%N)
(cd "$build" && cpack -G DEB >"$root/cpack.log") || { cat "$root/cpack.log"; exit 1; }
end=$(date +%s.%N)
deb=$(ls "$build"/contact-suite_*.deb)
echo "ci/deb-package.sh: built $(basename "$deb") ($(du -h "$deb" | cut -f1)) in $(awk "BEGIN{printf \"%.1f\", $end - $start}") s"
echo "Depends: $(dpkg-deb -f "$deb" Depends)"
for dep in python3-numpy libgsl libpugixml libcholmod; do
  dpkg-deb -f "$deb" Depends | grep -q "$dep" || { echo "ci/deb-package.sh: Depends lacks $dep" >&2; exit 1; }
done

dpkg-deb -x "$deb" "$root/unpacked"
usr="$root/unpacked/usr"
for f in bin/contact-suite lib/pkgconfig/contact_suite_oracles.pc \
         lib/cmake/contact_suite/contact_suiteConfig.cmake lib/libcontact_suite_oracles.a \
         include/contact_suite/oracles/hertz_plane.hpp share/doc/contact-suite/README.md \
         share/contact-suite/data/study/ansys_results.csv; do
  [ -e "$usr/$f" ] || { echo "ci/deb-package.sh: the package lacks /usr/$f" >&2; exit 1; }
done

"$usr/bin/contact-suite" list >/dev/null
"$usr/bin/contact-suite" oracle hertz-plane --R 1 --E 1 --nu 0.25 --load 0.001
PYTHONPATH="$usr/lib/python3/dist-packages" /usr/bin/python3 - "$usr" <<'PY'
import math, sys
import contact_suite as cs
assert cs.__file__.startswith(sys.argv[1]), cs.__file__
c = cs.hertz_plane_contact(R=1.0, E=1.0, nu=0.25, P=1e-3)
assert abs(c.p_max / c.p_mean - 4 / math.pi) < 4e-16 * 4 / math.pi, c
print("python: import contact_suite from the package:", c.p_max / c.p_mean)
PY
cmake -DSOURCE_DIR="$src" -DWORK_DIR="$root/consumer" -DCXX_COMPILER="${CXX:-c++}" \
      -DPREFIX="$usr" -P "$src/tests/install/check.cmake" >"$root/consumer.log" 2>&1 ||
  { cat "$root/consumer.log"; exit 1; }
echo "ci/deb-package.sh: the package's command, Python module and oracles (CMake and pkg-config consumers) work from an unpacked root"
