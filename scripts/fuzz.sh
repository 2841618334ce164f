#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan+UBSan, into build-fuzz/) and runs each for SECONDS
# (default 60), one after the other, from the seeds in tests/fuzz/<target>/ plus what earlier runs
# found (build-fuzz/corpus/<target>/). A crash, sanitizer report, timeout (30 s per input, wall
# time: a loaded machine needs the margin) or memory blow-up (2 GB) stops with the input saved as
# build-fuzz/artifacts/<target>-*; copy it into tests/fuzz/<target>/regression-<what> once fixed
# (replay_<target> runs them all in ctest). Prints the executions per target.
# usage: scripts/fuzz.sh [SECONDS] [TARGET...]      e.g. scripts/fuzz.sh 600 xacro_processor
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] &&
  targets=(xacro_processor xacro_expression urdf_loader joint_file rviz_config png_reader
    mcap_reader trajectory_text animation_reader results_file suite_file)
build=${URDFSNAP_FUZZ_BUILD:-$root/build-fuzz}

"$root/scripts/deps.sh" --sanitizers
if [ ! -f "$build/CMakeCache.txt" ]; then
  (cd "$root" && cmake --preset fuzz -B "$build" >/dev/null)   # CMakePresets.json
fi
cmake --build "$build" -j "$(nproc)" --target "${targets[@]/#/fuzz_}" >/dev/null

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
status=0
for target in "${targets[@]}"; do
  corpus="$build/corpus/$target"
  mkdir -p "$corpus" "$build/artifacts"
  log="$build/fuzz-$target.log"
  set +e
  "$build/fuzz_$target" "$corpus" "$root/tests/fuzz/$target" \
    -dict="$root/fuzz/$target.dict" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 \
    -max_len=16384 -print_final_stats=1 -artifact_prefix="$build/artifacts/$target-" \
    </dev/null >"$log" 2>&1
  result=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  if [ $result -eq 0 ]; then
    echo "fuzz $target: ${runs:-?} executions in ${seconds} s, no failure"
  else
    echo "fuzz $target: FAILED after ${runs:-?} executions; see $log" >&2
    grep -E "ERROR|SUMMARY|Test unit written" "$log" | head -5 >&2
    status=1
  fi
done
exit $status
