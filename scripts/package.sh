#!/usr/bin/env bash
# Builds the Debian package urdfsnap_<version>_<arch>.deb with CPack: the binary, the static
# libraries with their headers, the CMake package and the man pages, under /usr, with Depends from
# dpkg-shlibdeps plus what is loaded at run time (cmake/urdfsnapPackage.cmake).
#
# usage: scripts/package.sh [--build-dir DIR] [--out DIR]
#   --build-dir DIR  package a configured and built tree as it is (CI packs the tree its tests
#                    ran, so nothing is compiled twice); by default build-package/ is configured
#                    (Release, no tests or benchmarks) and built
#   --out DIR        where the .deb goes (default: output/)
# Prints the path of the package. Install it with: apt-get install ./urdfsnap_<version>_<arch>.deb
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="" out="$root/output"
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build=$(cd "$2" && pwd); shift 2 ;;
    --out) mkdir -p "$2"; out=$(cd "$2" && pwd); shift 2 ;;
    *) echo "package.sh: unknown argument '$1' (usage: package.sh [--build-dir DIR] [--out DIR])" >&2; exit 2 ;;
  esac
done
# the build's own dependencies are scripts/deps.sh's; these are the packaging tools
for tool in cpack dpkg-shlibdeps help2man; do
  command -v "$tool" >/dev/null || { echo "package.sh: $tool is missing (scripts/deps.sh installs it)" >&2; exit 2; }
done
# CPack stages the install in a scratch folder; only the .deb is kept
scratch=$(mktemp -d "${TMPDIR:-/tmp}/urdfsnap_package.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
if [ -z "$build" ]; then
  build="$root/build-package"
  echo "package.sh: building $build (Release)" >&2
  { (cd "$root" && cmake --preset package) &&
    cmake --build "$build" -j "$(nproc)"; } >"$scratch/build.log" 2>&1 ||
    { cat "$scratch/build.log" >&2; exit 1; }
fi
grep -q '^URDFSNAP_MAN_PAGES:BOOL=ON' "$build/CMakeCache.txt" ||
  { echo "package.sh: $build is configured without man pages (-DURDFSNAP_MAN_PAGES=ON)" >&2; exit 2; }
(cd "$build" && cpack -G DEB -B "$scratch" >"$scratch/cpack.log" 2>&1) ||
  { cat "$scratch/cpack.log" >&2; exit 1; }
deb=$(ls "$scratch"/urdfsnap_*.deb)
mv "$deb" "$out/"
echo "$out/$(basename "$deb")"
