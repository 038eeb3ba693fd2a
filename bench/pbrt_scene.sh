#!/usr/bin/env bash
# Loading a large pbrt-v4 scene (issue 32): FILES binary PLY files of about TRIANGLES
# triangles each (bench/make_mesh.cpp's torus, copied), placed by one .pbrt file as
# plymesh shapes, and the same PLYs placed by a Lua script (glint.mesh{ file = ... }, read
# one after another when the scene is built). For each, the wall time, CPU time and peak
# memory of `glint info` (read, build the meshes and Embree's BVH, print counts and memory).
# The pbrt importer reads its PLY files in parallel (TBB); the Lua scene's meshes are read
# in turn. See bench/README.md, "pbrt-v4 scenes".
#
# Environment (all optional):
#   BUILD_DIR   build directory (default build)
#   TRIANGLES   triangles per file (default 500000)
#   FILES       number of PLY files (default 8)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
TRIANGLES=${TRIANGLES:-500000}
FILES=${FILES:-8}
ninja -C "$BUILD_DIR" glint_cli glint_bench_make_mesh >/dev/null
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$BUILD_DIR/bench/glint_bench_make_mesh" "$dir" "$TRIANGLES" >/dev/null
rm -f "$dir/torus.obj" "$dir/torus.glb"
{
    echo 'LookAt 0 6 -12  0 0 0  0 1 0'
    echo 'Camera "perspective" "float fov" 45'
    echo 'Film "rgb" "integer xresolution" 64 "integer yresolution" 64'
    echo 'WorldBegin'
    echo 'LightSource "distant" "point3 from" [1 3 -2] "point3 to" [0 0 0]'
} > "$dir/scene.pbrt"
echo 'glint.camera{ eye = {0, 6, -12}, look_at = {0, 0, 0}, fov = 45 }' > "$dir/scene.lua"
echo 'local m = glint.diffuse{}' >> "$dir/scene.lua"
for ((i = 0; i < FILES; ++i)); do
    cp "$dir/torus.ply" "$dir/part$i.ply"
    x=$(( (i % 4) * 3 - 4 )); z=$(( (i / 4) * 3 ))
    printf 'AttributeBegin\n  Translate %d 0 %d\n  Shape "plymesh" "string filename" "part%d.ply"\nAttributeEnd\n' \
        "$x" "$z" "$i" >> "$dir/scene.pbrt"
    printf 'glint.mesh{ file = "part%d.ply", material = m, transform = glint.translate(%d, 0, %d) }\n' \
        "$i" "$((-x))" "$z" >> "$dir/scene.lua"
done
rm -f "$dir/torus.ply"
echo "$FILES files of $(( $(stat -c %s "$dir/part0.ply") / 1000000 )) MB"
for scene in scene.pbrt scene.lua; do
    for run in 1 2; do
        start=$(date +%s.%N)
        /usr/bin/time -f "   cpu: %U s user, %S s sys, %M KB peak" \
            "$BUILD_DIR/glint" info "$dir/$scene" > "$dir/info.txt" 2> "$dir/time.txt"
        end=$(date +%s.%N)
        echo "== $scene (run $run): glint info $(echo "$end - $start" | bc) s wall"
        grep -E "cpu:" "$dir/time.txt"
        grep -E "triangles|memory" "$dir/info.txt"
    done
done
