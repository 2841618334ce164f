#!/usr/bin/env bash
# CI's sanitizer stage (scripts/test.sh runs it when CI=true): builds everything with clang,
# AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer's instrumentation into build-asan/
# (-O1: the tests run a few times slower than in build/), runs the whole test suite there, then
# each fuzz target for a short time from its seeds (scripts/fuzz.sh with the same build).
# usage: scripts/test-sanitizers.sh [FUZZ_SECONDS_PER_TARGET]   (default 10)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-asan
"$root/scripts/deps.sh" --sanitizers
# through ccache, as scripts/build.sh: the slowest build of CI compiles only what changed since a
# build of the same tree on this machine (relative paths, so another clone hits the cache too)
export CCACHE_BASEDIR=$root
if [ ! -f "$build/CMakeCache.txt" ]; then
  (cd "$root" && cmake --preset sanitizers >/dev/null)   # CMakePresets.json
fi
cmake --build "$build" -j "$(nproc)" >/dev/null

# leaks are errors, except the ones Mesa's llvmpipe keeps for the life of the process (see the
# suppression file); undefined behaviour stops the process with a stack. The cli tests run the
# multi-threaded urdfsnap binary hundreds of times, where LeakSanitizer's stop-the-world at exit
# fails now and then under load ("does not work under ptrace"): they check leaks off.
asan=check_initialization_order=1:strict_init_order=1
export LSAN_OPTIONS=suppressions=$root/scripts/lsan-suppressions.txt:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
(cd "$build" && ASAN_OPTIONS=detect_leaks=1:$asan ctest --output-on-failure -j "$(nproc)" -LE cli)
(cd "$build" && ASAN_OPTIONS=detect_leaks=0:$asan ctest --output-on-failure -j "$(nproc)" -L cli)
URDFSNAP_FUZZ_BUILD=$build "$root/scripts/fuzz.sh" "${1:-10}"
