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
# an animation: mrm playing the example JointTrajectory, one camera fitted to every frame
"$snap" animate "$mrm" --trajectory "$root/examples/trajectories/mrm_wave.yaml" --fit --fps 15 --size 480x360 \
  --yaw 0.6 --pitch 0.4 --quiet -o "$root/docs/images/mrm_wave.gif"
# the depth and link-label images beside the colour image, made viewable (they hold millimetres and
# link numbers) by a docs-only script that needs Debian's python3-numpy and python3-pil
for package in python3-numpy python3-pil; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    apt-get install -y -qq --no-install-recommends "$package" >/dev/null
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# the mobile sample driving its loop, from its test bag alone (description, wheels and TF inside)
"$root/scripts/make-test-bags.sh" "$work/bags" >/dev/null
"$snap" animate "$work/bags/rover_loop.mcap" --fixed-frame odom --fps 10 --size 320x240 --yaw 0.6 \
  --pitch 0.7 --distance 4.5 --focal 0,1,0 --quiet -o "$root/docs/images/rover_loop.gif"
"$snap" render "$mrm" -o "$work/colour.png" --size 320x240 --depth "$work/depth.png" --labels "$work/labels.png" \
  -j base_link__link_01=0.5 -j link_01__link_02=-0.8 -j link_02__link_03=1.2 -j link_03__link_04=0.3 \
  --yaw 0.6 --pitch 0.35 --fit 2>/dev/null
"$root/scripts/depth_labels_preview.py" "$work/colour.png" "$work/depth.png" "$work/labels.png" \
  "$root/docs/images/mrm_depth_labels.png"
# a calibration check (docs/camera.md): a grey "camera image" (the arm drawn through the test
# calibration's distorting lens), and the model over it from a pose 4 cm off with one joint 0.15 rad
# off, as `render --underlay` shows it
calibration=$root/tests/data/camera/ost.yaml
arm=(-j base_link__link_01=0.5 -j link_01__link_02=-0.6 -j link_02__link_03=1.1)
"$snap" render "$mrm" -o "$work/photo.png" --camera-info "$calibration" --distort "${arm[@]}" \
  -j link_03__link_04=0.4 --camera-pose 5.5,2.5,3.2,-0.43156,-0.67022,0.50765,0.32689 --background 150,160,170
python3 -c 'import sys; from PIL import Image; Image.open(sys.argv[1]).convert("L").convert("RGB").save(sys.argv[1])' \
  "$work/photo.png"
"$snap" render "$mrm" -o "$root/docs/images/mrm_calibration_overlay.png" --camera-info "$calibration" --distort \
  "${arm[@]}" -j link_03__link_04=0.55 --camera-pose 5.52,2.46,3.23,-0.43478,-0.66976,0.50493,0.32778 \
  --underlay "$work/photo.png" --no-grid
# the live view's page in headless Chromium, after its browser test has dragged a slider and orbited
"$root/tests/serve/serve_page_browser.sh" "$snap" "$root/docs/images/serve_page.png" >/dev/null
ls "$root/docs/images"
