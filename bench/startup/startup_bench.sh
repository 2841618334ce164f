#!/usr/bin/env bash
# Start-up of whole urdfsnap processes: wall time (median over rounds of hyperfine runs without a
# shell, every command once per round in turn, so a machine's changing load falls on all alike)
# and peak resident memory (/usr/bin/time, median of 3) of `--version`, `info`, `xacro`, `render` and `diff`
# on the tutorial robot mrm, of the real (Python) xacro on the same file when one is given, and of
# MuJoCo's load+render+PNG peer of `render` (mujoco_peer.c) when Debian's libmujoco-dev is
# installed, and of the floor under any process that draws with OSMesa (osmesa_floor.c: the library
# loaded, a context made, one triangle drawn at 4x MSAA and read back) when its headers are.
# Timings only; nothing asserts.
#
# usage: bench/startup/startup_bench.sh [URDFSNAP] [ROUNDS]   (default build/urdfsnap, 5 rounds)
#   URDFSNAP_REAL_XACRO  the real xacro's command (default: `xacro` when on PATH). ROS 2's xacro
#                        from source, without ROS: github.com/ros/xacro (branch ros2) and
#                        github.com/ament/ament_index (ament_index_python) side by side, then
#                        URDFSNAP_REAL_XACRO="env PYTHONPATH=XACRO:AMENT/ament_index_python
#                        python3 -c 'import sys, xacro; sys.exit(xacro.main())'" (python3-yaml).
#                        $(find mrm_description) resolves through ROS_PACKAGE_PATH (ROS 1) and a
#                        temporary AMENT_PREFIX_PATH (ROS 2) made here.
set -euo pipefail
source "$(dirname "$0")/../bench_work.sh" startup
urdfsnap=$(realpath "${1:-$root/build/urdfsnap}")
rounds=${2:-5}
for tool in hyperfine python3 /usr/bin/time; do
  command -v "$tool" >/dev/null || { echo "startup_bench.sh: $tool is missing" >&2; exit 2; }
done
real_xacro=${URDFSNAP_REAL_XACRO:-$(command -v xacro || true)}

models=$root/models
mrm=$models/mrm_description/urdf
golden=$root/tests/golden/mrm_zero.png
# the package index of a ROS 2 install holding mrm_description, for the real xacro
mkdir -p "$work/prefix/share/ament_index/resource_index/packages"
touch "$work/prefix/share/ament_index/resource_index/packages/mrm_description"
ln -s "$models/mrm_description" "$work/prefix/share/mrm_description"
export ROS_PACKAGE_PATH=$models AMENT_PREFIX_PATH=$work/prefix

names=(--version info xacro render diff)
commands=(
  "$urdfsnap --version"
  "$urdfsnap info $mrm/mrm.urdf"
  "$urdfsnap xacro $mrm/mrm.xacro -o $work/mrm.urdf"
  "$urdfsnap render $mrm/mrm.urdf -o $work/mrm.png"
  "$urdfsnap diff $golden $golden"
)
if [ -f /usr/include/mujoco/mujoco.h ] &&
    cc -O2 "$root/bench/startup/mujoco_peer.c" -o "$work/mujoco_peer" \
      $(pkg-config --cflags --libs osmesa libpng) -lmujoco 2>"$work/cc.log"; then
  # MuJoCo reads the URDF itself; links without inertia get its least mass, visuals are kept
  sed '0,/<robot[^>]*>/s//&<mujoco><compiler discardvisual="false" boundmass="0.001" boundinertia="0.000001"\/><\/mujoco>/' \
    "$mrm/mrm.urdf" >"$work/mrm_mujoco.urdf"
  names+=("MuJoCo peer")
  commands+=("$work/mujoco_peer $work/mrm_mujoco.urdf $work/mrm_mujoco.png")
fi
if cc -O2 "$root/bench/startup/osmesa_floor.c" -o "$work/osmesa_floor" $(pkg-config --cflags --libs osmesa) \
    2>"$work/cc_floor.log"; then
  for depth in load context triangle; do
    names+=("OSMesa $depth")
    commands+=("$work/osmesa_floor $depth")
  done
fi
if [ -n "$real_xacro" ]; then
  if (cd "$work" && eval "$real_xacro $mrm/mrm.xacro" >/dev/null 2>&1); then
    names+=("real xacro")
    commands+=("$real_xacro $mrm/mrm.xacro -o $work/mrm_real.urdf")
  else
    echo "startup_bench.sh: the real xacro ($real_xacro) fails on mrm; left out" >&2
  fi
fi

# rounds of hyperfine, each command's times gathered across them
for ((r = 0; r < rounds; r++)); do
  hyperfine -N --warmup 1 --runs 5 --export-json "$work/round$r.json" "${commands[@]}" \
    >/dev/null 2>&1
done
median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

echo "whole-process start-up, mrm ($(nproc) cores; median of $((rounds * 5)) runs in $rounds rounds)"
printf '%-16s %10s %12s\n' command "time (ms)" "peak RSS (MB)"
urdfsnap_xacro_ms="" urdfsnap_render_ms=""
for i in "${!commands[@]}"; do
  ms=$(python3 -c 'import json, sys
for path in sys.argv[2:]:
    for t in json.load(open(path))["results"][int(sys.argv[1])]["times"]: print(t * 1000)' \
         "$i" "$work"/round*.json | median)
  rss=$(for _ in 1 2 3; do
          /usr/bin/time -f %M bash -c "${commands[$i]}" 2>&1 >/dev/null | tail -n 1
        done | median)
  printf '%-16s %10.1f %12.1f\n' "${names[$i]}" "$ms" "$(awk -v k="$rss" 'BEGIN {print k / 1024}')"
  [ "${names[$i]}" = xacro ] && urdfsnap_xacro_ms=$ms
  [ "${names[$i]}" = render ] && urdfsnap_render_ms=$ms
  [ "${names[$i]}" = "MuJoCo peer" ] &&
    awk -v a="$urdfsnap_render_ms" -v b="$ms" 'BEGIN {printf "urdfsnap render takes %.2fx the MuJoCo peer'"'"'s time\n", a / b}'
  [ "${names[$i]}" = "real xacro" ] &&
    awk -v a="$ms" -v b="$urdfsnap_xacro_ms" 'BEGIN {printf "urdfsnap xacro is %.1fx faster than the real xacro\n", a / b}'
done
