#!/usr/bin/env bash
# Builds the Debian package of a configured build tree (`cpack -G DEB`) and checks that its
# contents work from an unpacked root, without installing it: the command (`list` with the
# packaged GetFEM adapter, `gate --help`, an oracle), the Python package (Hertz's plane-strain
# peak 4/pi, the solver protocol's read_case/write_results), and the oracles' consumer built
# against the unpacked tree with CMake and with pkg-config (tests/install/check.cmake). Prints
# the package's control fields (dpkg-deb -I), what it holds by folder, and the time cpack took.
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
dpkg-deb -f "$deb"  # every control field: Package, Version, Architecture, Depends ...
echo "Contents (files by folder):"
dpkg-deb -c "$deb" | awk '$1 !~ /^d/ {sub("^\\./", "", $6); n = split($6, p, "/");
  d = p[1]; for (i = 2; i < n && i < 5; ++i) d = d "/" p[i]; c[d]++; s[d] += $3}
  END {for (d in c) printf "  %-50s %4d files %9.1f KiB\n", d, c[d], s[d] / 1024}' | sort
dpkg-deb -f "$deb" Description | grep -q ";" &&
  { echo "ci/deb-package.sh: the description holds a CMake list separator ';'" >&2; exit 1; }
for dep in python3-numpy libgsl libpugixml libcholmod; do
  dpkg-deb -f "$deb" Depends | grep -q "$dep" || { echo "ci/deb-package.sh: Depends lacks $dep" >&2; exit 1; }
done

dpkg-deb -x "$deb" "$root/unpacked"
usr="$root/unpacked/usr"
for f in bin/contact-suite lib/pkgconfig/contact_suite_oracles.pc \
         lib/python3/dist-packages/contact_suite/__init__.py \
         share/contact-suite/adapters/getfem/manifest.json \
         lib/cmake/contact_suite/contact_suiteConfig.cmake lib/libcontact_suite_oracles.a \
         include/contact_suite/oracles/hertz_plane.hpp share/doc/contact-suite/README.md \
         share/contact-suite/data/study/ansys_results.csv; do
  [ -e "$usr/$f" ] || { echo "ci/deb-package.sh: the package lacks /usr/$f" >&2; exit 1; }
done

"$usr/bin/contact-suite" list | grep -q "getfem:nodal_al" ||
  { echo "ci/deb-package.sh: list does not show the packaged GetFEM adapter" >&2; exit 1; }
"$usr/bin/contact-suite" gate --help | grep -q -- "--baseline" ||
  { echo "ci/deb-package.sh: gate --help does not describe --baseline" >&2; exit 1; }
"$usr/bin/contact-suite" oracle hertz-plane --R 1 --E 1 --nu 0.25 --load 0.001
# The unpacked program reads its own study data, not the source tree's it was built from: with
# the packaged table spoiled, `report` fails naming the packaged file.
study="$usr/share/contact-suite/data/study/ansys_results.csv"
cp "$study" "$root/ansys_results.csv"
echo "not,the,study,table" >"$study"
if "$usr/bin/contact-suite" report --results "$src/tests/reports/data/small_results.json" \
     --out "$root/report" --no-figures >/dev/null 2>"$root/report.err" ||
   ! grep -q "$study" "$root/report.err"; then
  echo "ci/deb-package.sh: report did not read the packaged study data:" >&2
  cat "$root/report.err" >&2
  exit 1
fi
cp "$root/ansys_results.csv" "$study"
PYTHONPATH="$usr/lib/python3/dist-packages" /usr/bin/python3 - "$usr" <<'PY'
import math, sys
import contact_suite as cs
assert cs.__file__.startswith(sys.argv[1]), cs.__file__
c = cs.hertz_plane_contact(R=1.0, E=1.0, nu=0.25, P=1e-3)
assert abs(c.p_max / c.p_mean - 4 / math.pi) < 4e-16 * 4 / math.pi, c
print("python: import contact_suite from the package:", c.p_max / c.p_mean)
assert callable(cs.read_case) and callable(cs.write_results)
PY
# The packaged GetFEM adapter run by the unpacked command: it imports contact_suite from the
# unpacked tree (the engine puts it on the code's PYTHONPATH) and solves the patch test.
if /usr/bin/python3 -c "import getfem" 2>/dev/null; then
  "$usr/bin/contact-suite" run --solver getfem --solver-options nodal_al --problems P_p \
    --meshes C --elements Q4 --target rigid --recovery spr --no-report --out "$root/getfem" \
    >"$root/getfem.log" 2>&1 || { cat "$root/getfem.log"; exit 1; }
  echo "ci/deb-package.sh: the packaged GetFEM adapter solved P_p C Q4 from the unpacked root"
fi
cmake -DSOURCE_DIR="$src" -DWORK_DIR="$root/consumer" -DCXX_COMPILER="${CXX:-c++}" \
      -DPREFIX="$usr" -P "$src/tests/install/check.cmake" >"$root/consumer.log" 2>&1 ||
  { cat "$root/consumer.log"; exit 1; }
echo "ci/deb-package.sh: the package's command, Python module and oracles (CMake and pkg-config consumers) work from an unpacked root"
