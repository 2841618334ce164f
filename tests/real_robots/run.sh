#!/usr/bin/env bash
# Renders published robot descriptions that urdfsnap was not written against: the URDF models
# DART ships in Debian's dart-doc package (Boston Dynamics Atlas v3 with 62 COLLADA/STL meshes,
# DRC-Hubo with 104 STL meshes, a KUKA KR5 with plain mesh paths, a Barrett WAM whose package is
# missing). Each must render (or fail) as a user would expect, and each image must show a robot.
# usage: run.sh URDFSNAP CACHE_DIR     exits 77 (skipped) when dart-doc cannot be downloaded
set -euo pipefail
urdfsnap=$1
cache=$2
data=$cache/usr/share/doc/dart/data
if [ ! -d "$data" ]; then
  mkdir -p "$cache"
  if ! (cd "$cache" && apt-get download -q dart-doc >/dev/null 2>&1); then
    echo "skipped: cannot download Debian's dart-doc package"
    exit 77
  fi
  dpkg-deb -x "$cache"/dart-doc_*.deb "$cache"
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# share of pixels that are not the black background (the grid is off)
coverage() {
  python3 - "$1" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
width, height = struct.unpack(">II", data[16:24])
idat, pos = b"", 8
while pos < len(data):
    length, kind = struct.unpack(">I4s", data[pos:pos + 8])
    if kind == b"IDAT":
        idat += data[pos + 8:pos + 8 + length]
    pos += 12 + length
raw = zlib.decompress(idat)
row = 1 + 3 * width  # urdfsnap writes 8-bit RGB rows with filter 0
lit = sum(1 for y in range(height) for x in range(width)
          if any(raw[y * row + 1 + 3 * x:y * row + 4 + 3 * x]))
print("%.3f" % (lit / (width * height)))
PY
}

# render NAME MODEL MIN_COVERAGE [render args...]: exit 0, no output but the expected warnings,
# and at least MIN_COVERAGE of the image covered by the robot
render() {
  local name=$1 model=$2 min=$3
  shift 3
  local log=$out/$name.log
  if ! "$urdfsnap" render "$model" -o "$out/$name.png" --fit --no-grid --background 0,0,0 \
      --size 320x240 "$@" >"$log" 2>&1; then
    fail "$name: $(cat "$log")"
    return
  fi
  local c
  c=$(coverage "$out/$name.png")
  echo "ok   $name: $(wc -l <"$log") warning line(s), robot covers $c of the image"
  python3 -c "import sys; sys.exit(0 if $c >= $min else 1)" || fail "$name: coverage $c < $min"
}

render atlas "$data/sdf/atlas/atlas_v3_no_head.urdf" 0.10 --package atlas_description="$data/sdf" \
  -j l_arm_shx=-1.2 -j r_arm_shx=1.2 -j l_leg_kny=0.8
render drchubo "$data/urdf/drchubo/drchubo.urdf" 0.10
render drchubo_collision "$data/urdf/drchubo/drchubo.urdf" 0.10 --collision --no-visual
render kr5 "$data/urdf/KR5/KR5 sixx R650.urdf" 0.10
grep -q "mesh filenames without package:// or file://" "$out/kr5.log" ||
  fail "kr5: no warning about its plain mesh paths"

# the WAM's meshes are in a package (herb_description) that is not shipped: a located error...
wam="$data/urdf/wam/wam.urdf"
if "$urdfsnap" render "$wam" -o "$out/wam.png" >"$out/wam.log" 2>&1; then
  fail "wam: rendered although its meshes are missing"
elif ! grep -q "^urdfsnap: error: $wam:[0-9]*: link '/wam_base': mesh 'package://herb_description/meshes/wam/wam_base.dae' not found: package 'herb_description' not found" "$out/wam.log"; then
  fail "wam: unexpected error: $(cat "$out/wam.log")"
else
  echo "ok   wam: $(cat "$out/wam.log")"
fi
[ ! -e "$out/wam.png" ] || fail "wam: an image was written"
# ... and --allow-missing-meshes draws nothing of it but still succeeds, one warning per link
render wam_allowed "$wam" 0 --allow-missing-meshes
exit $((failures > 0))
