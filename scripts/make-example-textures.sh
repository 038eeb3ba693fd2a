#!/usr/bin/env bash
# Regenerates examples/textures/ (uv grid, checkerboard, tile normal map, sky and its
# mirror-ball probe, torus) with the glint_make_example_textures program. The images are committed; run this after
# changing examples/make_textures.cpp.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
[[ -f "$BUILD_DIR/build.ninja" ]] || cmake -S . -B "$BUILD_DIR" -G Ninja
cmake --build "$BUILD_DIR" --target glint_make_example_textures
"$BUILD_DIR/examples/glint_make_example_textures" examples/textures
