#!/usr/bin/env bash
# Installs missing dependencies, builds urdfsnap into build/ and renders the sample robots to
# output/: the mrm manipulator from its xacro files (RViz's default view) and from its URDF.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
mkdir -p "$root/output"
"$root/build/urdfsnap" render "$root/models/mrm_description/urdf/mrm.xacro" -o "$root/output/mrm.png"
echo "$root/output/mrm.png"
"$root/build/urdfsnap" render "$root/models/mrm_description/urdf/mrm.urdf" -o "$root/output/mrm_urdf_pose.png" \
  -j link_01__link_02=0.5 -j link_02__link_03=-1.0 --yaw 0.6 --pitch 0.35 --distance 4.5 --focal 0,0,1.2
echo "$root/output/mrm_urdf_pose.png"
"$root/build/urdfsnap" render "$root/models/meshbot_description/urdf/meshbot.urdf" -o "$root/output/meshbot.png" --fit
echo "$root/output/meshbot.png"
