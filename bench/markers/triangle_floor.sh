#!/usr/bin/env bash
# The floor under a frame of markers on llvmpipe (issue 23's 1,000 mixed markers <= 10 ms): how long
# OSMesa itself takes to clear, draw, resolve and read back a 640x480 frame of N small flat-shaded
# triangles in one draw call (triangle_floor.c), for counts around what the marker benchmark's
# frame sends (urdfsnap_markers_bench: ~43,000 front-facing triangles, most a few pixels wide).
# usage: bench/markers/triangle_floor.sh [EDGE [SAMPLES [FRAMES]]]   (defaults 3, 4, 30)
set -euo pipefail
source "$(dirname "$0")/../bench_work.sh" triangle_floor
cc -O2 "$root/bench/markers/triangle_floor.c" -o "$work/triangle_floor" $(pkg-config --cflags --libs osmesa)
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
for count in 0 10000 20000 30000 43000 67000; do
  "$work/triangle_floor" "$count" "${1:-3}" "${2:-4}" "${3:-30}"
done
