#!/usr/bin/env bash
# Radiosity against path tracing on the diffuse Cornell box (issue 20): for each patch size,
# the radiosity solve and display (time, patches, elements, vertices, shots per second,
# bytes per element) and its relative MSE against a converged path-traced reference; then
# the time the path tracer needs to reach the same relative MSE (samples per pixel doubled
# until it does). Times are those the CLI prints: the solve's from its radiosity line, the
# display's and the path tracer's from the summary line (scene loading excluded). The
# reference uses another seed than the path renders it judges. See bench/README.md.
#
# Environment (all optional):
#   BUILD_DIR   build directory (default build); configured as Release when missing
#   JOBS        parallel compile jobs for ninja (default 2)
#   THREADS     render threads (default 2)
#   RES         image size (default 64x64)
#   REF_SPP     samples per pixel of the reference (default 8192)
#   SIZES       radiosity patch sizes in mm (default "280 140 100")
#   DISPLAY_SPP samples per pixel of the radiosity display (default 256)
#   MAX_SPP     the path tracer's largest samples per pixel (default 4096)
#   KEEP        a folder to keep the images in (default: none, a temporary folder)
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-2}
THREADS=${THREADS:-2}
RES=${RES:-64x64}
REF_SPP=${REF_SPP:-8192}
SIZES=${SIZES:-"280 140 100"}
DISPLAY_SPP=${DISPLAY_SPP:-256}
MAX_SPP=${MAX_SPP:-4096}

if [ ! -f "$BUILD_DIR/build.ninja" ]; then
    cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
fi
ninja -C "$BUILD_DIR" -j"$JOBS" glint_cli > /dev/null
GLINT="$BUILD_DIR/glint"
WORK=${KEEP:-$(mktemp -d)}
mkdir -p "$WORK"
SCENE=examples/cornell-box.lua

# render_time LOG: seconds of the render from the summary line "WxH, N spp, T threads: S s".
render_time() { sed -n 's/.* threads: \([0-9.]*\) s.*/\1/p' "$1" | tail -1; }
rel_mse() { "$GLINT" compare "$1" "$WORK/reference.exr" | sed -n 's/relative MSE: *//p'; }

echo "reference: path, $RES, $REF_SPP spp"
"$GLINT" render "$SCENE" --res "$RES" --spp "$REF_SPP" --seed 7 --threads "$THREADS" -q \
    -o "$WORK/reference.exr"

printf '\n| patch size (mm) | patches | elements | vertices | shots | shots/s | bytes/element | solve s | display s | relative MSE | path spp | path s |\n'
printf '|---|---|---|---|---|---|---|---|---|---|---|---|\n'
for size in $SIZES; do
    sed "s/glint.render{.*/glint.render{ integrator = 'radiosity', radiosity_patch_size = $size,/" \
        "$SCENE" > "$WORK/radiosity-$size.lua"
    "$GLINT" render "$WORK/radiosity-$size.lua" --res "$RES" --spp "$DISPLAY_SPP" \
        --threads "$THREADS" -o "$WORK/radiosity-$size.exr" > "$WORK/radiosity-$size.log" 2>&1
    line=$(grep ' patches, ' "$WORK/radiosity-$size.log")
    # "radiosity: P patches, E elements, V vertices; S shots (R/s) and N rays in T s, U % unshot; B bytes per element"
    read -r patches elements vertices shots rate solve bytes < <(echo "$line" |
        sed 's/radiosity: \([0-9]*\) patches, \([0-9]*\) elements, \([0-9]*\) vertices; \([0-9]*\) shots (\([0-9]*\)\/s) and [0-9]* rays in \([0-9.]*\) s, [0-9.]* % unshot; \([0-9]*\) bytes per element/\1 \2 \3 \4 \5 \6 \7/')
    display=$(render_time "$WORK/radiosity-$size.log")
    error=$(rel_mse "$WORK/radiosity-$size.exr")
    # The path tracer, samples doubled until its error is at most the radiosity image's.
    spp=8
    path_time=""
    while [ "$spp" -le "$MAX_SPP" ]; do
        "$GLINT" render "$SCENE" --res "$RES" --spp "$spp" --seed 1 --threads "$THREADS" \
            -o "$WORK/path-$spp.exr" > "$WORK/path-$spp.log" 2>&1
        path_error=$(rel_mse "$WORK/path-$spp.exr")
        if awk -v a="$path_error" -v b="$error" 'BEGIN { exit !(a <= b) }'; then
            path_time=$(render_time "$WORK/path-$spp.log")
            break
        fi
        spp=$((spp * 2))
    done
    [ -n "$path_time" ] || { spp=">$MAX_SPP"; path_time="-"; }
    printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$size" "$patches" \
        "$elements" "$vertices" "$shots" "$rate" "$bytes" "$solve" "$display" "$error" "$spp" \
        "$path_time"
done
[ -n "${KEEP:-}" ] || rm -rf "$WORK"
