#!/usr/bin/env bash
# Installs glint's build and test dependencies from Debian's packages.
# Run as root (or with sudo). Idempotent: safe to run again.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libembree-dev        # ray queries (Embree 3)
  libtbb-dev           # threads (oneTBB)
  liblua5.4-dev        # scene language
  libopenimageio-dev   # image I/O (EXR, PNG, HDR, ...)
  libglm-dev           # vector math
  libcli11-dev         # command line
  libfmt-dev           # formatting
  libtinygltf-dev      # glTF import (glint.import)
  libgtest-dev libgmock-dev # tests
  libglfw3-dev libimgui-dev # the viewer (glint view): window and input, panel
  xvfb libgl1-mesa-dri # the viewer's end-to-end test: a virtual X server, software OpenGL
)

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

export DEBIAN_FRONTEND=noninteractive
# Skip the network round trip when every package is already present.
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages already installed"
  exit 0
fi
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
