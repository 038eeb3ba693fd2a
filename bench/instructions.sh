#!/usr/bin/env bash
# Instructions per ray, split between glint and Embree, counted by callgrind: a measure of
# the render's cost that does not depend on what else the machine is doing. On a shared VM
# run-to-run timings spread by 10-15 %, which hides the few-per-cent changes that hot-path
# work is made of; instruction counts are exact and repeatable. They stand in for time
# because the render runs at a steady 2-2.5 instructions per cycle (see bench/README.md,
# "The instruction budget"), so fewer instructions is faster. Confirm the result with
# bench/run before claiming a speed-up: cache misses and long dependency chains are
# invisible here.
#
# It counts one render of SCENE on one thread and the bare Embree loop on the same scene,
# and prints instructions per ray for each, and their ratio, which is roughly what
# bench/run's "render rays/s / bare rays/s" would be if both ran at the same IPC.
# Takes about half a minute. Needs valgrind (apt-get install valgrind).
#
# Environment (all optional):
#   BUILD_DIR  build directory (default build); configured as Release when it does not exist
#   SCENE      scene to count (default examples/cornell-box.lua)
#   RES        resolution (default 64x64)
#   SPP        samples per pixel (default 16)
#   RAYS       rays of the bare Embree loop (default 2e5)
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
SCENE=${SCENE:-examples/cornell-box.lua}
RES=${RES:-64x64}
SPP=${SPP:-16}
RAYS=${RAYS:-2e5}

if ! command -v valgrind >/dev/null || ! command -v callgrind_annotate >/dev/null; then
    echo "error: bench/instructions.sh needs valgrind (apt-get install valgrind)" >&2
    exit 1
fi
if [[ ! -f "$BUILD_DIR/build.ninja" ]]; then
    cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
ninja -C "$BUILD_DIR" glint_cli glint_bench_embree >/dev/null

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Inclusive instructions of the functions whose names match the extended regex $2 in the
# callgrind profile $1, summed.
inclusive() {
    callgrind_annotate --inclusive=yes --threshold=100 "$1" 2>/dev/null |
        grep -E "$2" | awk '{ gsub(",", "", $1); sum += $1 } END { printf "%.0f\n", sum }'
}
# Embree's entry points for ray queries (single rays and packets).
embree_re='(rtcIntersect|rtcOccluded)(1|4|8|16|1M|1Mp|NM|NMp) \['

valgrind --tool=callgrind --callgrind-out-file="$tmp/render.out" "$BUILD_DIR/glint" render \
    "$SCENE" --res "$RES" --spp "$SPP" --threads 1 -o "$tmp/out.exr" 2>"$tmp/render.log" \
    >/dev/null
totals=$(grep -E '^[0-9]+ samples and [0-9]+ rays in all$' "$tmp/render.log" || true)
if [[ -z "$totals" ]]; then
    echo "error: no totals line from glint render:" >&2
    cat "$tmp/render.log" >&2
    exit 1
fi
read -r samples rays < <(awk '{ print $1, $4 }' <<<"$totals")
# The tile loop: for the path tracers all of the render (photon mapping's passes that trace
# photons are outside it and not counted).
render_total=$(inclusive "$tmp/render.out" 'glint::TileIntegrator::render\(')
render_embree=$(inclusive "$tmp/render.out" "$embree_re")

valgrind --tool=callgrind --callgrind-out-file="$tmp/bare.out" \
    "$BUILD_DIR/bench/glint_bench_embree" "$SCENE" --threads 1 --rays "$RAYS" >/dev/null 2>&1
bare_total=$(inclusive "$tmp/bare.out" 'trace_chunk\(')
bare_embree=$(inclusive "$tmp/bare.out" "$embree_re")
# trace_chunk also runs for the loop's untimed warm-up of min(rays / 20 + 1, 10^6) rays.
bare_rays=$(awk -v r="$RAYS" 'BEGIN { r = int(r); w = int(r / 20) + 1; if (w > 1e6) w = 1e6;
                                      printf "%.0f\n", r + w }')

awk -v s="$samples" -v r="$rays" -v t="$render_total" -v e="$render_embree" \
    -v bt="$bare_total" -v be="$bare_embree" -v br="$bare_rays" -v scene="$SCENE" \
    -v res="$RES" -v spp="$SPP" 'BEGIN {
    printf "instructions (callgrind), %s, %s, %s spp, 1 thread\n", scene, res, spp
    printf "render: %.0f samples, %.0f rays, %.2f rays per sample\n", s, r, r / s
    printf "  per ray:    %6.0f in all = %6.0f Embree + %6.0f glint\n", t / r, e / r, (t - e) / r
    printf "  per sample: %6.0f in all = %6.0f Embree + %6.0f glint\n", t / s, e / s, (t - e) / s
    printf "bare Embree loop: %.0f rays\n", br
    printf "  per ray:    %6.0f in all = %6.0f Embree + %6.0f ray generation\n", bt / br, be / br,
           (bt - be) / br
    printf "bare / render instructions per ray: %.2f (bench/run target for the time ratio: 0.70)\n",
           (bt / br) / (t / r)
}'
