#!/usr/bin/env bash
# Large-mesh loading (issue 21, item 7): a torus of about TRIANGLES triangles written by
# bench/make_mesh.cpp as OBJ (with uvs and normals), binary PLY and GLB; for each, the wall
# time of `glint info FILE` (read, build the meshes and Embree's BVH, print the counts and
# the memory per triangle) and of a tiny render. See bench/README.md, "Large meshes".
#
# Environment (all optional):
#   BUILD_DIR   build directory (default build)
#   TRIANGLES   triangles in the torus (default 1000000)
#   THREADS     render threads (default 2)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
TRIANGLES=${TRIANGLES:-1000000}
THREADS=${THREADS:-2}
ninja -C "$BUILD_DIR" glint_cli glint_bench_make_mesh >/dev/null
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$BUILD_DIR/bench/glint_bench_make_mesh" "$dir" "$TRIANGLES"
ls -l "$dir"
# The GLB has no material, and glTF's default is the principled material: until that is
# in, it is loaded through bench/large_mesh_glb.lua with a diffuse one.
scene_for() {
    if [[ $1 == glb ]]; then echo bench/large_mesh_glb.lua; else echo "$dir/torus.$1"; fi
}
export GLINT_BENCH_MESH=$dir/torus.glb
for ext in obj ply glb; do
    file=$(scene_for $ext)
    start=$(date +%s.%N)
    /usr/bin/time -f "   cpu: %U s user, %S s sys, %M KB peak" "$BUILD_DIR/glint" info "$file" > "$dir/info.txt"
    end=$(date +%s.%N)
    echo "== $ext: glint info $(echo "$end - $start" | bc) s"
    grep -E "triangles|memory" "$dir/info.txt"
    start=$(date +%s.%N)
    "$BUILD_DIR/glint" render "$file" --res 64x64 --spp 1 --threads "$THREADS" --quiet -o "$dir/out.exr"
    end=$(date +%s.%N)
    echo "== $ext: glint render --res 64x64 --spp 1: $(echo "$end - $start" | bc) s"
done
