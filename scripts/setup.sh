#!/usr/bin/env bash
# Installs the Debian packages angioray builds with, only those that are missing.
# Usage: scripts/setup.sh   (needs root or sudo; does nothing when all are present)
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config ccache clang-format xvfb xauth xdotool
  clang libclang-rt-dev llvm
  libinsighttoolkit5-dev libgdcm-dev libopenimageio-dev openimageio-tools libopencv-dev
  libtbb-dev libglm-dev nlohmann-json3-dev libcli11-dev libgtest-dev zlib1g-dev
  libpugixml-dev libimgui-dev libglfw3-dev libosmesa6-dev libgl-dev libxsimd-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
echo "setup: installing ${missing[*]}" >&2
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
