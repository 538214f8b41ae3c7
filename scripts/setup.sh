#!/usr/bin/env bash
# Installs the Debian packages shadowlab needs (only the missing ones), then configures and
# builds into build/. Used by run.sh, test.sh and CI. (clang + libclang-rt-dev: libFuzzer, for
# scripts/fuzz.sh.)
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  build-essential cmake pkg-config
  libglfw3-dev libimgui-dev libglm-dev libtinygltf-dev libstb-dev nlohmann-json3-dev
  libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libgtest-dev libembree-dev
  xvfb xauth xdotool python3
  clang libclang-rt-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j"$(nproc)"
