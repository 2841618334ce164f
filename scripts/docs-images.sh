#!/usr/bin/env bash
# Regenerates the images the README shows (docs/images/), rendered by urdfsnap itself.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
mkdir -p "$root/docs/images"
snap=$root/build/urdfsnap
mrm=$root/models/mrm_description/urdf/mrm.xacro
"$snap" render "$mrm" -o "$root/docs/images/mrm_default.png"
"$snap" render "$mrm" -o "$root/docs/images/mrm_pose.png" \
  -j base_link__link_01=0.5 -j link_01__link_02=-0.8 -j link_02__link_03=1.2 -j link_03__link_04=0.3 \
  --yaw 0.6 --pitch 0.35 --fit
ls "$root/docs/images"
