#!/usr/bin/env bash
# The Debian package as a user gets it: built from BUILD_DIR by scripts/package.sh (packing the
# tree as it is, nothing compiled again), read with dpkg-deb (name, fields, contents, Depends
# covering every shared library the binary needs and what it loads at run time), then unpacked
# with dpkg-deb -x and its binary run from there: --version, and a render of mrm that must match
# the golden image tests/golden/mrm_zero.png; and so for the Python package when it is built.
# usage: scripts/test-package.sh [BUILD_DIR]   (default: build/)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/urdfsnap_test_package.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "test-package.sh: $*" >&2; exit 1; }

deb=$("$root/scripts/package.sh" --build-dir "$build" --out "$work")
version=$("$build/urdfsnap" --version | awk 'NR == 1 {print $2}')
arch=$(dpkg --print-architecture)
[ "$(basename "$deb")" = "urdfsnap_${version}_${arch}.deb" ] || fail "package named $(basename "$deb")"

# control fields
[ "$(dpkg-deb -f "$deb" Package)" = urdfsnap ] || fail "Package: $(dpkg-deb -f "$deb" Package)"
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "Version: $(dpkg-deb -f "$deb" Version)"
[ "$(dpkg-deb -f "$deb" Architecture)" = "$arch" ] || fail "Architecture: $(dpkg-deb -f "$deb" Architecture)"
depends=$(dpkg-deb -f "$deb" Depends)
# the package names in Depends, alternatives included, without versions
depends_names=" $(echo "$depends" | tr ',|' '\n\n' | sed 's/(.*)//; s/ //g' | tr '\n' ' ') "
# loaded at run time, invisible to dpkg-shlibdeps
for package in libosmesa6 fonts-liberation; do
  [[ "$depends_names" == *" $package "* ]] || fail "Depends lacks $package: $depends"
done

# contents
contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
for file in ./usr/bin/urdfsnap ./usr/lib/liburdfsnap_snapshot.a ./usr/lib/liburdfsnap_shard.a \
    ./usr/include/urdfsnap/snapshot/results_file.h ./usr/include/urdfsnap/shard/shard_assignment.h \
    ./usr/lib/cmake/urdfsnap/urdfsnapConfig.cmake ./usr/lib/cmake/urdfsnap/urdfsnapSnapshotTest.cmake \
    ./usr/share/man/man1/urdfsnap.1.gz; do
  grep -qxF "$file" <<<"$contents" || fail "the package has no $file"
done

dpkg-deb -x "$deb" "$work/root"
binary="$work/root/usr/bin/urdfsnap"
# every shared library the binary links directly (NEEDED) is owned by a package in Depends; the
# libraries those load are their packages' own dependencies
for library in $(objdump -p "$binary" | awk '$1 == "NEEDED" {print $2}'); do
  path=$(ldconfig -p | awk -v l="$library" '$1 == l && !found {print $NF; found = 1}')
  [ -n "$path" ] || fail "$library, which the binary needs, is not installed here"
  owner=$(dpkg -S "$path" 2>/dev/null || dpkg -S "$(readlink -f "$path")" 2>/dev/null) ||
    fail "no Debian package owns $path ($library)"
  owner=${owner%%:*}
  [[ "$depends_names" == *" $owner "* ]] || fail "$library is in $owner, which is not in Depends: $depends"
done

# every command `urdfsnap --help` lists has its man page, and each page is intact
for command in $("$binary" --help | awk '/^Subcommands:/ {on = 1; next} on && NF {print $1}'); do
  pages=$(ls "$work/root/usr/share/man/man1" | grep -c "^urdfsnap-$command[.-]") ||
    fail "no man page for 'urdfsnap $command'"
done
for page in "$work"/root/usr/share/man/man1/*.gz; do gzip -t "$page"; done

# the unpacked binary renders the reference robot as the goldens were made
[ "$("$binary" --version | head -n 1)" = "urdfsnap $version" ] || fail "--version: $("$binary" --version)"
"$binary" render "$root/models/mrm_description/urdf/mrm.urdf" -o "$work/mrm.png"
"$binary" diff "$root/tests/golden/mrm_zero.png" "$work/mrm.png" >/dev/null ||
  fail "the packaged binary's render of mrm differs from tests/golden/mrm_zero.png"
# the Python package, when the tree builds it: importable from the unpacked dist-packages with
# Debian's python3, rendering the same pixels
if grep -q '^URDFSNAP_BUILD_PYTHON:BOOL=ON' "$build/CMakeCache.txt"; then
  for package in python3 python3-numpy; do
    [[ "$depends_names" == *" $package "* ]] || fail "Depends lacks $package: $depends"
  done
  grep -q '^./usr/lib/python3/dist-packages/urdfsnap/_urdfsnap\..*\.so$' <<<"$contents" ||
    fail "the package has no Python module in /usr/lib/python3/dist-packages/urdfsnap"
  PYTHONPATH="$work/root/usr/lib/python3/dist-packages" /usr/bin/python3 -c \
    'import sys, urdfsnap; urdfsnap.write_png(urdfsnap.Robot(sys.argv[1]).render(), sys.argv[2])' \
    "$root/models/mrm_description/urdf/mrm.urdf" "$work/mrm_python.png"
  "$binary" diff "$root/tests/golden/mrm_zero.png" "$work/mrm_python.png" >/dev/null ||
    fail "the packaged Python module's render of mrm differs from tests/golden/mrm_zero.png"
fi
echo "$(basename "$deb"): $(wc -l <<<"$contents") entries, Depends: $depends"
