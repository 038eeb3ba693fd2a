#!/usr/bin/env bash
# Denoiser benchmark (issue 21): for each scene, a reference at REF_SPP, then renders at each
# of SPP with --denoise; prints the render time, the denoiser's time (and per megapixel), and
# the relative MSE (glint compare) of the noisy and of the denoised image against the
# reference. Noisy and denoised at the same spp cost the same render: the denoised image's
# extra time is the denoiser's. See bench/README.md, "Denoiser".
#
# Environment (all optional):
#   BUILD_DIR  build directory (default build)
#   THREADS    render threads (default 2)
#   SPP        sample counts to compare (default "16 64")
#   REF_SPP    samples per pixel of the references (default 1024)
#   SCENES     "scene:WIDTHxHEIGHT ..." (default cornell-box at 128x128, textures at 160x90)
#   OUT        directory for the images (default a fresh temporary directory)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
THREADS=${THREADS:-2}
SPP=${SPP:-16 64}
REF_SPP=${REF_SPP:-1024}
SCENES=${SCENES:-cornell-box:128x128 textures:160x90}
OUT=${OUT:-$(mktemp -d)}
ninja -C "$BUILD_DIR" glint_cli >/dev/null
glint=$(realpath "$BUILD_DIR/glint")

printf "%-12s %-8s %5s %9s %10s %10s %12s %12s %7s\n" scene res spp render_s denoise_s "s/Mpixel" \
    noisy_relmse denoised_relmse gain
for entry in $SCENES; do
    scene=${entry%%:*}
    res=${entry#*:}
    pixels=$(( ${res%x*} * ${res#*x} ))
    ref="$OUT/$scene-ref.exr"
    # Relative paths in the scene (textures) resolve against the scene's directory.
    "$glint" render "examples/$scene.lua" --res "$res" --spp "$REF_SPP" --seed 7 \
        --threads "$THREADS" -o "$ref" --quiet
    for spp in $SPP; do
        out="$OUT/$scene-$spp.exr"
        log=$("$glint" render "examples/$scene.lua" --res "$res" --spp "$spp" --seed 1 \
            --threads "$THREADS" --denoise -o "$out" 2>&1)
        render_s=$(echo "$log" | sed -n 's/.* threads: \([0-9.]*\) s,.*/\1/p')
        denoise_s=$(echo "$log" | sed -n 's/^denoised in \([0-9.]*\) s/\1/p')
        noisy=$("$glint" compare "$out" "$ref" | sed -n 's/relative MSE: *//p')
        denoised=$("$glint" compare "${out%.exr}.denoised.exr" "$ref" | sed -n 's/relative MSE: *//p')
        awk -v s="$scene" -v r="$res" -v n="$spp" -v rt="$render_s" -v dt="$denoise_s" \
            -v p="$pixels" -v a="$noisy" -v b="$denoised" 'BEGIN {
            printf "%-12s %-8s %5d %9.2f %10.2f %10.2f %12.5f %12.5f %6.1fx\n",
                   s, r, n, rt, dt, dt / (p / 1e6), a, b, a / b }'
    done
done
echo "images in $OUT"
