#!/usr/bin/env bash
# Installs glint's build and test dependencies from Debian's packages.
# Run it as root, or as a user who may use sudo: it calls sudo itself only when it is not
# root, so it also works on a machine where sudo does not exist. Idempotent.
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
if [ "$(id -u)" -ne 0 ]; then
  if ! command -v sudo >/dev/null 2>&1; then
    echo "install-deps: not root and sudo is not installed; run this script as root" >&2
    exit 1
  fi
  SUDO="sudo"
fi

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
