#!/usr/bin/env bash
# The installed C++ API is self-contained: `cmake --install` into a scratch prefix, then every
# installed header, preprocessed alone against the installed include folder (and the system's),
# finds every header it names, and none names a private header (an internal/ folder).
# usage: check_installed_headers.sh BUILD_DIR CXX_COMPILER
set -euo pipefail
build=$1
cxx=$2
prefix=$(mktemp -d "${TMPDIR:-/tmp}/urdfsnap_headers.XXXXXX")
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" >/dev/null
include=$prefix/include/urdfsnap
cd "$include"
headers=$(find . -name '*.h' | sed 's|^\./||' | sort)
[ -n "$headers" ] || { echo "no headers installed under $include"; exit 1; }
status=0
if private=$(grep -rn '#include "[^"]*internal/' .); then
  echo "installed headers name private headers:"; echo "$private"; status=1
fi
if find . -path '*internal*' | grep -q .; then
  echo "private headers were installed:"; find . -path '*internal*'; status=1
fi
check() {
  printf '#include "%s"\n' "$1" | "$cxx" -std=c++20 -E -x c++ -I "$include" -I /usr/include/eigen3 - \
    -o /dev/null 2>&1 | sed "s|^|$1: |"
}
export -f check
export cxx include
failures=$(printf '%s\n' $headers | xargs -P 2 -I{} bash -c 'check "$@"' _ {})
if [ -n "$failures" ]; then echo "$failures"; status=1; fi
echo "$(echo "$headers" | wc -l) installed headers checked"
exit $status
