#!/usr/bin/env bash
# Denoiser benchmark (issues 21 and 33): for each scene, a reference at REF_SPP, then renders at
# each of SPP denoised by the network (`--denoise`, OIDN's U-Net) and by the non-local means
# filter (`--denoise nlm`); prints the render time, each denoiser's time, and the relative MSE
# (glint compare) of the noisy image and of both denoised images against the reference. Then
# an equal-time comparison: the noisy image at the sample count that takes as long as
# rendering SPP and running the network. Last, the network's seconds per megapixel at each
# size and thread count (glint_bench_denoise_network). See bench/README.md, "Denoiser".
#
# Environment (all optional):
#   BUILD_DIR  build directory (default build)
#   THREADS    render and denoise threads (default 2)
#   SPP        sample counts to compare (default "4 16")
#   REF_SPP    samples per pixel of the references (default 1024)
#   SCENES     "scene:WIDTHxHEIGHT ..." (default cornell-box 256x256, textures 320x180,
#              cornell-spheres 256x256)
#   QUALITY    the network's denoise_quality: fast, balanced (default) or high
#   SPEED      "WIDTH HEIGHT REPEATS" of the speed run (default "1024 1024 3"; "" skips it)
#   OUT        directory for the images (default a fresh temporary directory)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
THREADS=${THREADS:-2}
SPP=${SPP:-4 16}
REF_SPP=${REF_SPP:-1024}
SCENES=${SCENES:-cornell-box:256x256 textures:320x180 cornell-spheres:256x256}
QUALITY=${QUALITY:-balanced}
SPEED=${SPEED-1024 1024 3}
OUT=${OUT:-$(mktemp -d)}
mkdir -p "$OUT"
ninja -C "$BUILD_DIR" glint_cli glint_bench_denoise_network >/dev/null
glint=$(realpath "$BUILD_DIR/glint")

relmse() { "$glint" compare "$1" "$2" | sed -n 's/relative MSE: *//p'; }
render_seconds() { echo "$1" | sed -n 's/.* threads: \([0-9.]*\) s,.*/\1/p'; }
denoise_seconds() { echo "$1" | sed -n 's/^denoised in \([0-9.]*\) s/\1/p'; }

echo "network: denoise_quality $QUALITY"
printf "%-16s %-8s %4s %8s %7s %7s %9s %9s %9s %7s | %6s %9s\n" scene res spp render_s nlm_s net_s \
    noisy nlm network "nlm/net" eq_spp eq_noisy
for entry in $SCENES; do
    scene=${entry%%:*}
    res=${entry#*:}
    ref="$OUT/$scene-ref.exr"
    # Relative paths in the scene (textures) resolve against the scene's directory.
    "$glint" render "examples/$scene.lua" --res "$res" --spp "$REF_SPP" --seed 7 \
        --threads "$THREADS" -o "$ref" --quiet
    for spp in $SPP; do
        out="$OUT/$scene-$spp.exr"
        net_log=$("$glint" render "examples/$scene.lua" --res "$res" --spp "$spp" --seed 1 \
            --threads "$THREADS" --denoise --denoise-quality "$QUALITY" -o "$out" 2>&1)
        nlm_out="$OUT/$scene-$spp-nlm.exr"
        nlm_log=$("$glint" render "examples/$scene.lua" --res "$res" --spp "$spp" --seed 1 \
            --threads "$THREADS" --denoise nlm -o "$nlm_out" 2>&1)
        render_s=$(render_seconds "$net_log")
        net_s=$(denoise_seconds "$net_log")
        nlm_s=$(denoise_seconds "$nlm_log")
        # Equal time: the sample count whose render takes as long as this render and the network.
        eq_spp=$(awk -v n="$spp" -v r="$render_s" -v d="$net_s" 'BEGIN { printf "%d", n * (r + d) / r + 0.5 }')
        eq_out="$OUT/$scene-$eq_spp-eq.exr"
        "$glint" render "examples/$scene.lua" --res "$res" --spp "$eq_spp" --seed 1 \
            --threads "$THREADS" -o "$eq_out" --quiet
        noisy=$(relmse "$out" "$ref")
        net=$(relmse "${out%.exr}.denoised.exr" "$ref")
        nlm=$(relmse "${nlm_out%.exr}.denoised.exr" "$ref")
        eq=$(relmse "$eq_out" "$ref")
        awk -v s="$scene" -v r="$res" -v n="$spp" -v rt="$render_s" -v lt="$nlm_s" -v dt="$net_s" \
            -v a="$noisy" -v b="$nlm" -v c="$net" -v es="$eq_spp" -v e="$eq" 'BEGIN {
            printf "%-16s %-8s %4d %8.2f %7.2f %7.2f %9.5f %9.5f %9.5f %6.2fx | %6d %9.5f\n",
                   s, r, n, rt, lt, dt, a, b, c, b / c, es, e }'
    done
done
echo "images in $OUT"
if [ -n "$SPEED" ]; then
    echo "load average before the speed run: $(cut -d' ' -f1-3 /proc/loadavg)"
    # shellcheck disable=SC2086
    "$BUILD_DIR/bench/glint_bench_denoise_network" $SPEED
fi
