#!/usr/bin/env bash
# Throughput of `urdfsnap dataset` at 640x480 (colour, depth, labels, COCO annotations; one process:
# drawing, llvmpipe's rasteriser and the writer on their own threads), for mrm and, when its folder
# is given, Franka's Panda (COLLADA meshes), also in two worker processes (`--jobs 2`, the default
# on 2 cores); and the cost of one frame through a camera (the
# calibration tests/data/camera/ost.yaml and a pose; rectified, and with --distort) against the
# orbit view (`render` of the same robot, same size, all with depth and labels). Wall time follows the load
# of a shared machine (printed first); CPU ms per sample (all threads) is the load-independent
# figure, and 2000 / that is what two idle cores would reach if both stay busy.
# usage: bench/dataset/dataset_bench.sh URDFSNAP [SAMPLES] [FRANKA_DESCRIPTION_DIR]
#   SAMPLES default 400; FRANKA_DESCRIPTION_DIR: a franka_description checkout (ROS package
#   franka_description, github.com/frankaemika/franka_ros), e.g. /work/robots/franka_description
set -euo pipefail
snap=$1
samples=${2:-400}
franka=${3:-}
source "$(dirname "$0")/../bench_work.sh" dataset_bench

echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
printf '%-8s %4s %8s %8s %10s %10s %12s %12s\n' robot jobs samples wall_s samples/s cpu_s cpu_ms/sample 2core_max/s

# bench NAME JOBS MODEL [OPTIONS...]
bench() {
  local name=$1 jobs=$2 model=$3
  shift 3
  rm -rf "$work/out"
  /usr/bin/time -f '%e %U %S' -o "$work/time" "$snap" dataset "$model" -o "$work/out" --count "$samples" \
    --seed 1 --no-shard --jobs "$jobs" --quiet "$@" 2>/dev/null
  read -r wall user sys <"$work/time"
  awk -v n="$name" -v j="$jobs" -v s="$samples" -v w="$wall" -v u="$user" -v y="$sys" 'BEGIN {
    c = u + y; printf "%-8s %4d %8d %8.2f %10.1f %10.2f %12.2f %12.0f\n", n, j, s, w, s / w, c, 1000 * c / s, 2 * s / c }'
}

bench mrm 1 "$root/models/mrm_description/urdf/mrm.urdf"
if [ -n "$franka" ]; then
  for jobs in 1 2; do
    bench panda "$jobs" "$franka/robots/panda/panda.urdf.xacro" --package "franka_description=$franka"
  done
fi

# one frame through a camera against the orbit view: 20 interleaved pairs of render processes
mrm=$root/models/mrm_description/urdf/mrm.urdf
orbit=(render "$mrm" -o "$work/o.png" --depth "$work/od.png" --labels "$work/ol.png")
camera=(render "$mrm" -o "$work/c.png" --depth "$work/cd.png" --labels "$work/cl.png"
  --camera-info "$root/tests/data/camera/ost.yaml" --camera-pose 4.5,-6,5,-0.8,-0.3,0.1,0.5)
total_orbit=0 total_camera=0 total_distort=0
# add_cpu TOTAL: TOTAL plus the user and system seconds in $work/t
add_cpu() { awk -v t="$1" '{print t + $1 + $2}' "$work/t"; }
for i in $(seq 20); do
  /usr/bin/time -f '%U %S' -o "$work/t" "$snap" "${orbit[@]}"
  total_orbit=$(add_cpu "$total_orbit")
  /usr/bin/time -f '%U %S' -o "$work/t" "$snap" "${camera[@]}"
  total_camera=$(add_cpu "$total_camera")
  /usr/bin/time -f '%U %S' -o "$work/t" "$snap" "${camera[@]}" --distort
  total_distort=$(add_cpu "$total_distort")
done
awk -v o="$total_orbit" -v c="$total_camera" -v d="$total_distort" 'BEGIN {
  printf "render mrm 640x480 with depth and labels, CPU ms per process (20 interleaved runs): orbit %.1f, camera %.1f, camera --distort %.1f\n", 50 * o, 50 * c, 50 * d }'
