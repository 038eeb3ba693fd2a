#!/usr/bin/env bash
# Checks glint against Blender the way a user would (not run in CI; docs/blender-reference.md):
# builds small scenes in Blender (principled variations, each light kind, image textures,
# transmission, instancing), exports each as GLB, OBJ+MTL and PLY, renders a Cycles
# reference (CPU, linear EXR), renders the exports with glint at the same samples per pixel
# and prints a table of relative MSE and channel means over the visible surfaces.
#
#   scripts/blender-reference.sh [OUTDIR] [SPP] [WIDTH] [HEIGHT]
#   SCENES="point spot" scripts/blender-reference.sh ...      (a few of them)
#
# Needs Debian's `blender` (3.4) and `python3-numpy` (Blender's glTF exporter imports it):
#   apt-get install blender python3-numpy
# and a built glint (build/glint, or $GLINT). Defaults: /tmp/glint-blender, 256 spp, 160 x 120.
# Everything runs under `nice -n 10` on the CPU.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-/tmp/glint-blender}
spp=${2:-256}
width=${3:-160}
height=${4:-120}
glint=${GLINT:-build/glint}
scenes=(${SCENES:-point spot sun principled lights texture transmission})
mkdir -p "$out"
command -v blender >/dev/null || { echo "blender-reference: install Debian's blender" >&2; exit 1; }
[ -x "$glint" ] || { echo "blender-reference: no glint at $glint (build it, or set GLINT)" >&2; exit 1; }

for scene in "${scenes[@]}"; do
  echo "== $scene: Blender build, exports, Cycles at $spp spp"
  nice -n 10 blender -b --factory-startup --python scripts/blender_reference.py -- \
    "$scene" "$out" "$spp" "$width" "$height" > "$out/$scene-blender.log" 2>&1 ||
    { tail -20 "$out/$scene-blender.log"; exit 1; }
  echo "== $scene: glint"
  nice -n 10 "$glint" render "$out/$scene.glb" --res "${width}x${height}" --spp "$spp" \
    -o "$out/$scene-glint-glb.exr" 2> "$out/$scene-glint-glb.log"
  for fmt in obj ply; do
    nice -n 10 "$glint" render "$out/$scene-$fmt.lua" --spp "$spp" \
      -o "$out/$scene-glint-$fmt.exr" 2> "$out/$scene-glint-$fmt.log"
  done
done
blender -b --factory-startup --python scripts/blender_compare.py -- "$out" "${scenes[@]}" 2>/dev/null |
  grep '^|' | tee "$out/table.md"
