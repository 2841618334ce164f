#!/usr/bin/env bash
# The OSMesa and EGL backends draw the same pictures: every view below is rendered with each
# backend (URDFSNAP_GL_BACKEND) and the two colour images must match by `urdfsnap diff`'s default
# tolerance (the one snapshot suites use), and their depth and link-label images byte for byte
# (both are exact values, drawn without multisampling by the same llvmpipe; `urdfsnap diff` reads
# a 16-bit PNG as 8 bits, too coarse for depth). Each view also differs from the same view with the
# robot hidden, so that two blank frames cannot pass. The views cover what could render
# differently: 4x multisampling and its resolve, none, an odd size, transparency, TF axes, arrows
# and names (blended text), meshes, textures and emission, collision geometry.
# usage: backends_agree.sh URDFSNAP   (prints one line per view; exit 0 when all agree)
set -u
urdfsnap=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
mrm=$root/models/mrm_description/urdf/mrm.urdf
meshbot=$root/models/meshbot_description/urdf/meshbot.urdf
texbot=$root/tests/data/texbot_description/urdf/texbot.urdf
looks=$root/tests/data/looks/looks.urdf
mixed="-j base_link__link_01=1.2 -j link_01__link_02=-0.6 -j link_02__link_03=1.1 -j link_03__link_04=0.9"
looks_view="-j lift=0.15 -j shoulder=-0.5 -j wheel_joint=0.7 --yaw 0.6 --pitch 0.5 --distance 2.2 --focal 0,0,0.35"
# name|model|render options
views=(
  "mrm_default|$mrm|$mixed"
  "mrm_tf_names_see_through|$mrm|$mixed --tf --alpha 0.3 --fit --yaw 1.2"
  "mrm_alpha_no_aa_odd_size|$mrm|$mixed --alpha 0.4 --no-aa --size 333x217 --distance 2"
  "meshbot_fit|$meshbot|--fit"
  "meshbot_tf_alpha|$meshbot|--fit --tf --alpha 0.5 --yaw 2.2"
  "texbot_textures|$texbot|-j drum_joint=0.6 -j lamp_joint=0.8 --fit"
  "looks_alpha|$looks|$looks_view --alpha 0.5"
  "looks_collision|$looks|$looks_view --collision --no-visual"
)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
passed=0 failed=0 identical=0
for view in "${views[@]}"; do
  IFS='|' read -r name model options <<<"$view"
  ok=1
  for backend in osmesa egl; do
    # shellcheck disable=SC2086  # options are words
    if ! URDFSNAP_GL_BACKEND=$backend "$urdfsnap" render "$model" $options -o "$out/$name.$backend.png" \
        --depth "$out/$name.$backend.depth.png" --labels "$out/$name.$backend.labels.png" \
        >"$out/$name.$backend.log" 2>&1; then
      echo "FAIL $name: $backend: $(cat "$out/$name.$backend.log")"
      ok=0
    fi
  done
  if [ $ok = 1 ]; then
    # the same view without the robot: no visual, collision or TF display
    empty_options=$(sed -e 's/ --collision//; s/ --no-visual//; s/ --tf//' <<<" $options")
    # shellcheck disable=SC2086
    "$urdfsnap" render "$model" $empty_options --no-visual -o "$out/$name.empty.png" >/dev/null 2>&1
    figures=$("$urdfsnap" diff "$out/$name.osmesa.png" "$out/$name.egl.png" 2>&1)
    status=$?
    if [ $status -ne 0 ]; then
      echo "FAIL $name: the backends differ: $figures"
      ok=0
    elif ! cmp -s "$out/$name.osmesa.depth.png" "$out/$name.egl.depth.png"; then
      echo "FAIL $name: the backends' depth images differ"
      ok=0
    elif ! cmp -s "$out/$name.osmesa.labels.png" "$out/$name.egl.labels.png"; then
      echo "FAIL $name: the backends' label images differ"
      ok=0
    elif "$urdfsnap" diff "$out/$name.osmesa.png" "$out/$name.empty.png" >/dev/null 2>&1; then
      echo "FAIL $name: the image matches the view without the robot: nothing was drawn"
      ok=0
    else
      cmp -s "$out/$name.osmesa.png" "$out/$name.egl.png" && identical=$((identical + 1))
      echo "ok   $name: $figures"
    fi
  fi
  if [ $ok = 1 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
done
echo "backends: $identical of ${#views[@]} views byte-identical"
echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
