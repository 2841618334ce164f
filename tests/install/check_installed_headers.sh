#!/usr/bin/env bash
# The installed C++ API is self-contained: `cmake --install` into a scratch prefix, then
# - no private header (an internal/ folder) is installed, and no installed header names one;
# - every installed header compiles alone: a translation unit holding only `#include "ROOM/FILE.h"`
#   passes the compiler's syntax check against the installed include folder. A header that relies
#   on another urdfsnap header being included before it fails;
# - all of them together compile in one unit (no two define the same thing).
# The other libraries' headers (the standard library's, Eigen's) that many installed headers name
# are precompiled once and put before each unit (-include): parsing them was two thirds of the
# cost (156 headers: 125 s of CPU parsed alone, 45 s so). A header that forgets one of those
# includes is therefore not caught here; one that forgets an urdfsnap header is.
# usage: check_installed_headers.sh BUILD_DIR CXX_COMPILER
set -euo pipefail
build=$1
cxx=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/urdfsnap_headers.XXXXXX")
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
include=$work/prefix/include/urdfsnap
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

# the other libraries' headers that five or more installed headers name, precompiled (GCC finds
# external.h.gch beside it, Clang external.h.pch); the rest (nlohmann/json.hpp, <thread>, ...) are
# parsed by the few units that name them, cheaper than loading a larger precompiled header in all
grep -rh '^#include <' . | sort | uniq -c | awk '$1 >= 5 { print $2, $3 }' > "$work/external.h"
suffix=gch
if "$cxx" --version | grep -q clang; then suffix=pch; fi
"$cxx" -std=c++20 -isystem /usr/include/eigen3 -x c++-header "$work/external.h" -o "$work/external.h.$suffix"

check() {
  printf '#include "%s"\n' "$1" |
    "$cxx" -std=c++20 -I "$include" -isystem /usr/include/eigen3 -Winvalid-pch -include "$work/external.h" \
      -fsyntax-only -x c++ - 2>&1 | sed "s|^|$1: |"
}
export -f check
export cxx include work
failures=$(printf '%s\n' $headers | xargs -P "$(nproc)" -I{} bash -c 'check "$@"' _ {})
if [ -n "$failures" ]; then echo "$failures"; status=1; fi
# and all of them in one unit: no two define the same thing
printf '#include "%s"\n' $headers |
  "$cxx" -std=c++20 -I "$include" -isystem /usr/include/eigen3 -fsyntax-only -x c++ - || status=1
echo "$(echo "$headers" | wc -l) installed headers compiled alone"
exit $status
