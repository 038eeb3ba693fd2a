#!/usr/bin/env bash
# Regenerates examples/smoke.nvdb (the density grid of examples/smoke.lua) with the
# glint_make_example_grid program (needs libnanovdb-dev). The file is committed; run this
# after changing examples/make_smoke_grid.cpp or the procedural cloud.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
[[ -f "$BUILD_DIR/build.ninja" ]] || cmake -S . -B "$BUILD_DIR" -G Ninja
cmake --build "$BUILD_DIR" --target glint_make_example_grid
"$BUILD_DIR/examples/glint_make_example_grid" examples/smoke.nvdb
