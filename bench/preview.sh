#!/usr/bin/env bash
# The preview integrator's frame rate and convergence (issue 18). For each scene and
# resolution, glint_bench_preview (bench/preview.cpp) calls render_pass() as the viewer does
# each frame and prints the median frames per second and ms per frame, split into the photon
# pass and the camera pass (the window's display is measured in the viewer), the first pass
# after a camera move and after a light move, and the CPU time per frame divided by the threads
# (what the frame would take on an otherwise idle machine), and, for a scene with a light the
# viewer can move, how long the viewer takes from a light move to its first image (the scene
# rebuilt and the reduced pass) and to its first full pass; then the same for the fog of
# examples/volumetric-caustics.lua. Then, on examples/caustics.lua at 640x480, it
# renders from no photons for 4 s, keeps the image reached after 0.25, 1 and 4 s, and prints
# each one's relative MSE over the caustics against a converged sppm image.
# About 4 minutes on 2 idle cores (the sppm reference takes about half).
#
# Environment (all optional):
#   BUILD_DIR  build directory (default build)
#   THREADS    render threads (default 2)
#   FRAMES     passes timed per scene and resolution (default 30)
#   RESOLUTIONS (default "320x240 640x480 1280x720")
#   SCENES     (default "examples/caustics.lua examples/cornell-spheres.lua")
#   REF_SPP    sppm passes of the reference (default 64)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
THREADS=${THREADS:-2}
FRAMES=${FRAMES:-30}
RESOLUTIONS=${RESOLUTIONS:-320x240 640x480 1280x720}
SCENES=${SCENES:-examples/caustics.lua examples/cornell-spheres.lua}
REF_SPP=${REF_SPP:-64}
ninja -C "$BUILD_DIR" glint_cli glint_bench_preview glint_bench_region_error >/dev/null
bench=$BUILD_DIR/bench/glint_bench_preview
error=$BUILD_DIR/bench/glint_bench_region_error
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "preview, $THREADS threads, $(date +%F), commit $(git rev-parse --short HEAD), load $(cut -d' ' -f1-3 /proc/loadavg)"
for scene in $SCENES; do
    for res in $RESOLUTIONS; do
        "$bench" "$scene" --res "$res" --threads "$THREADS" --frames "$FRAMES" --moves 5
    done
done

# Fog and volumetric caustics (issue 29): the frame rate at 640x480, and the viewer's first
# pass after a camera or light move, which it renders at a quarter of the size (160x120).
echo
for res in 640x480 160x120; do
    "$bench" examples/volumetric-caustics.lua --res "$res" --threads "$THREADS" --frames "$FRAMES" --moves 5
done

# The caustics of examples/caustics.lua at 640x480: the glass sphere's spot and its shadow,
# the ring and its cardioid.
region="200 190 520 320"
echo
echo "examples/caustics.lua 640x480, region [$region], reference sppm $REF_SPP passes"
"$BUILD_DIR/glint" render examples/caustics.lua --integrator sppm --spp "$REF_SPP" --res 640x480 \
    --seed 7 --threads "$THREADS" --quiet -o "$tmp/ref.exr" 2>/dev/null
"$bench" examples/caustics.lua --res 640x480 --threads "$THREADS" --frames 1 --moves 0 \
    --snapshots "0.25 1 4" --prefix "$tmp/preview" | sed -n '2,$p' >"$tmp/passes"
for t in 0.25 1 4; do
    passes=$(sed -nE "s/^ +$t s: ([0-9]+) passes/\1/p" "$tmp/passes")
    # shellcheck disable=SC2086
    printf '  after %4s s (%s passes): relative MSE %s\n' "$t" "$passes" \
        "$("$error" "$tmp/preview.$t.exr" "$tmp/ref.exr" $region)"
done
# The same by pass count, which does not depend on the machine's load: 15 passes are 1 s at
# the 15 frames per second aimed at.
for n in 4 15 60; do
    "$BUILD_DIR/glint" render examples/caustics.lua --integrator preview --spp "$n" --res 640x480 \
        --threads "$THREADS" --quiet -o "$tmp/passes$n.exr" 2>/dev/null
    # shellcheck disable=SC2086
    printf '  after %3d passes: relative MSE %s\n' "$n" "$("$error" "$tmp/passes$n.exr" "$tmp/ref.exr" $region)"
done
