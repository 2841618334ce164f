#!/usr/bin/env bash
# Installs the Debian packages urdfsnap needs to build, test and package, only those that are
# missing (chromium, ffmpeg's command-line tools, nodejs/npm, python3-jsonschema and python3-yaml
# are for the tests only; help2man and dpkg-dev for scripts/package.sh; hyperfine and time for
# bench/startup; the Python package's below).
# Idempotent and quiet when everything is already there. Needs root (apt-get).
# usage: scripts/deps.sh [--sanitizers]   (--sanitizers: also clang and libFuzzer, for the
# sanitizer build and scripts/fuzz.sh; the normal build does not need them)
set -euo pipefail
packages=(
  cmake g++ make pkg-config ccache
  liburdfdom-dev libeigen3-dev libstb-dev libjpeg-dev zlib1g-dev
  # GL: the core-profile header; OSMesa; EGL with Mesa's vendor library and drivers (llvmpipe)
  libgl-dev libosmesa6-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
  libtinyxml2-dev libexpat1-dev libassimp-dev libcli11-dev libyaml-cpp-dev nlohmann-json3-dev
  googletest libgtest-dev libbenchmark-dev fonts-liberation libfreetype-dev python3
  libcpp-httplib-dev nodejs
  libzstd-dev liblz4-dev libsqlite3-dev libqhull-dev libdeflate-dev
  libavcodec-dev libavformat-dev libavfilter-dev libswscale-dev libavutil-dev libwebp-dev ffmpeg
  chromium  # the browser tests (the HTML report, serve's page), headless; CI fails them without it
  python3-jsonschema python3-yaml help2man dpkg-dev
  # the Python package (src/python, python/): pybind11 and numpy to build, pytest for its tests,
  # setuptools, wheel and pip for `pip install .`
  pybind11-dev python3-dev python3-numpy python3-pytest python3-setuptools python3-wheel python3-pip
  hyperfine time
)
# npm only for the test tooling, and only when no npm is on the PATH (NodeSource's nodejs package
# brings its own, which Debian's npm package would conflict with)
command -v npm >/dev/null || packages+=(npm)
if [ "${1:-}" = "--sanitizers" ]; then packages+=(clang libclang-rt-14-dev llvm-14); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "deps.sh: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -ne 0 ] && sudo=sudo
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
