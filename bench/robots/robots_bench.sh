#!/usr/bin/env bash
# The benchmark table of published robots: for mrm (in this repository), the Franka Panda and the
# PR2 (outside it: their licences and size keep them out), at 640x480 with 4x MSAA and --fit:
#   render    the whole `urdfsnap render` process, model file (xacro) to PNG: median wall ms of
#             RUNS, the CPU ms of that run (all threads) and its peak resident memory
#   draw      one frame drawn and read back in a prepared robot (urdfsnap_robot_frames, a
#             turntable of 60 yaw steps): median wall ms, and CPU ms of all threads per frame
#   png, mp4  `urdfsnap animate --turntable --duration 4 --fit --jobs 1` (121 frames) to a PNG sequence and
#             to H.264: frames per second of the whole process, startup included, and its CPU
#             ms (all threads) per frame
#   pngw      the same PNG sequence in animate's worker processes (--jobs by default: one per
#             core): frames per second and CPU ms per frame of the whole process tree
#   docs      the whole `urdfsnap docs` page (--no-shard; its worker processes, one per core, as
#             by default): wall s, CPU s of all its processes and the peak resident MB of the
#             whole process tree (summed over the processes, tree_peak.py)
# then the machine (CPU model, cores) and the load average before and after. On a shared machine
# wall times follow the load; the CPU figures do not.
# usage: bench/robots/robots_bench.sh URDFSNAP [RUNS]
#   URDFSNAP_FRANKA_DESCRIPTION  folder of franka_description (github.com/frankaemika/franka_ros,
#                                its franka_description package); its row is skipped when unset
#   URDFSNAP_PR2_DESCRIPTION     folder of pr2_description (github.com/PR2/pr2_common); likewise
set -euo pipefail
snap=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
runs=${2:-3}
source "$(dirname "$0")/../bench_work.sh" robots_bench
frames_tool=$(dirname "$snap")/urdfsnap_robot_frames

# timed COMMAND...: runs it under /usr/bin/time; sets wall, cpu (s) and peak (MB)
timed() {
  /usr/bin/time -f '%e %U %S %M' -o "$work/time" "$@" >/dev/null 2>"$work/stderr" || {
    echo "robots_bench: failed: $*" >&2; cat "$work/stderr" >&2; exit 1; }
  read -r wall user sys rss <"$work/time"
  cpu=$(awk "BEGIN {print $user + $sys}")
  peak=$(awk "BEGIN {printf \"%.0f\", $rss / 1024}")
}

# row NAME MODEL [PKG=DIR]: one line of the table
row() {
  local name=$1 model=$2 package=${3:-}
  local args=("$model")
  [ -n "$package" ] && args+=(--package "$package")
  # render: median wall of RUNS after one warm-up (Mesa's shader cache, the page cache)
  timed "$snap" render "${args[@]}" --fit -o "$work/one.png"
  local walls=()
  for _ in $(seq "$runs"); do
    timed "$snap" render "${args[@]}" --fit -o "$work/one.png"
    walls+=("$wall $cpu")
  done
  local render_ms render_cpu render_mb=$peak
  read -r render_ms render_cpu < <(printf '%s\n' "${walls[@]}" | sort -n |
    awk '{w[NR] = $1; c[NR] = $2} END {m = int((NR + 1) / 2); printf "%.0f %.0f\n", 1000 * w[m], 1000 * c[m]}')
  # draw: the typed core on the expanded URDF
  "$snap" xacro "${args[@]}" >"$work/robot.urdf"
  local draw
  draw=$("$frames_tool" "$work/robot.urdf" ${package:+"$package"})
  local triangles draw_ms draw_cpu
  read -r _ triangles _ draw_ms _ draw_cpu <<<"$draw"
  # animate: 121 frames
  local fps=()
  # in one process to PNG and to H.264, then to PNG in the default worker processes (/usr/bin/time
  # counts the CPU of the workers the parent waited for)
  local jobs output
  for run in "1 frames/%05d.png" "1 turn.mp4" "default frames/%05d.png"; do
    read -r jobs output <<<"$run"
    local options=(--turntable --duration 4 --fit --quiet --no-shard)
    [ "$jobs" = default ] || options+=(--jobs "$jobs")
    rm -rf "$work/anim" && mkdir -p "$work/anim"
    timed "$snap" animate "${args[@]}" "${options[@]}" -o "$work/anim/$output"
    fps+=("$(awk "BEGIN {printf \"%.0f\", 121 / $wall}")" "$(awk "BEGIN {printf \"%.1f\", 1000 * $cpu / 121}")")
  done
  # docs: a process tree
  rm -rf "$work/page"
  "$(dirname "$0")/tree_peak.py" "$work/tree" "$snap" docs "${args[@]}" --no-shard -q -o "$work/page" >/dev/null || {
    echo "robots_bench: failed: docs of $model" >&2; exit 1; }
  read -r wall cpu peak _ <"$work/tree"
  # shellcheck disable=SC2059
  printf "$format" "$name" "$triangles" "$render_ms" "$render_cpu" "$render_mb" "$draw_ms" "$draw_cpu" \
    "${fps[@]}" "$(printf %.1f "$wall")" "$(printf %.1f "$cpu")" "$peak"
}

echo "machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores; load average $(cut -d' ' -f1-3 /proc/loadavg)"
format='%-6s %9s | %6s %6s %6s | %6s %6s | %5s %6s | %5s %6s | %5s %6s | %6s %6s %6s\n'
# shellcheck disable=SC2059
printf "$format" "" "" render render render draw draw png png mp4 mp4 pngw pngw docs docs docs
# shellcheck disable=SC2059
printf "$format" robot triangles ms "cpu ms" MB "ms/f" "cpu/f" "f/s" "cpu/f" "f/s" "cpu/f" "f/s" "cpu/f" "s" "cpu s" MB
row mrm "$root/models/mrm_description/urdf/mrm.xacro"
if [ -n "${URDFSNAP_FRANKA_DESCRIPTION:-}" ]; then
  row panda "$URDFSNAP_FRANKA_DESCRIPTION/robots/panda/panda.urdf.xacro" "franka_description=$URDFSNAP_FRANKA_DESCRIPTION"
else
  echo "panda: skipped (set URDFSNAP_FRANKA_DESCRIPTION to a franka_description folder)"
fi
if [ -n "${URDFSNAP_PR2_DESCRIPTION:-}" ]; then
  row pr2 "$URDFSNAP_PR2_DESCRIPTION/robots/pr2.urdf.xacro" "pr2_description=$URDFSNAP_PR2_DESCRIPTION"
else
  echo "pr2: skipped (set URDFSNAP_PR2_DESCRIPTION to a pr2_description folder)"
fi
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
