#!/usr/bin/env bash
# Writes examples/gltf/ (scene.gltf, scene.bin and its PNG textures) with
# examples/gltf/make_gltf.cpp. The output is committed; run this after changing the program.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
[[ -f "$BUILD_DIR/build.ninja" ]] || cmake -S . -B "$BUILD_DIR" -G Ninja
cmake --build "$BUILD_DIR" --target glint_make_example_gltf
"$BUILD_DIR/examples/glint_make_example_gltf" examples/gltf
