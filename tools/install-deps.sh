#!/bin/sh
# Installs everything cavewall needs to build, test and run on Debian 12 (as root or with sudo).
set -eu
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
  cmake ninja-build g++ pkg-config git ca-certificates \
  libglm-dev nlohmann-json3-dev libtinygltf-dev libopenimageio-dev libmeshoptimizer-dev libdraco-dev libsquish-dev libstb-dev zlib1g-dev libzstd-dev \
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libepoxy-dev libglfw3-dev \
  libgtest-dev libgmock-dev libbenchmark-dev \
  libopenmpi-dev openmpi-bin \
  xvfb xauth xdotool openscenegraph gltfpack draco gnuplot-nox python3 \
  clang >/dev/null
echo "install-deps: done"
