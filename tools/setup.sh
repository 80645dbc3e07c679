#!/usr/bin/env bash
# Installs Spindrift's build dependencies from Debian 12's packages (when run as
# root, or with sudo available) and builds it into build/ (Release).
# Usage: tools/setup.sh [extra cmake configure arguments]
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake pkg-config git
  libglfw3-dev libglm-dev libtinygltf-dev libpng-dev libopenexr-dev
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri nlohmann-json3-dev
  libgtest-dev libbenchmark-dev libimgui-dev libstb-dev libzstd-dev
  libopenal-dev libebur128-dev libreaderwriterqueue-dev sox
  libavformat-dev libavcodec-dev libswscale-dev  # replay --video (GPL: docs/REPLAYS.md#video-export)
  xvfb xauth
  glslang-tools
  help2man file  # the man page and cpack's scan of the programs (packaging/)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build -j"$(nproc)"
echo "setup: built build/game/spindrift"
