#!/usr/bin/env bash
# Motion blur's cost (issue 34): bench/motion_scene.lua, 144 placed groups, rendered by the
# path tracer as
#   still    nothing moves, no shutter (the scene as glint rendered it before motion blur)
#   instant  every group moving (motion BVH), shutter {0, 0}: no time drawn
#   blurred  every group moving, shutter {0, 1}: a time per camera sample
# and prints samples/s and rays/s of each, and samples per processor-second (median of RUNS
# runs, interleaved so that load on a shared machine falls on all three). See bench/README.md.
#
# Environment (all optional): BUILD_DIR (build), JOBS (2), THREADS (2), RUNS (3), SPP (32).
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-2}
THREADS=${THREADS:-2}
RUNS=${RUNS:-3}
SPP=${SPP:-32}

if [[ ! -f "$BUILD_DIR/build.ninja" ]]; then
    cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$BUILD_DIR/CMakeCache.txt")
if [[ "$build_type" != "Release" ]]; then
    echo "warning: $BUILD_DIR is a '$build_type' build; these are not release numbers" >&2
fi
ninja -C "$BUILD_DIR" -j "$JOBS" glint_cli >/dev/null
glint="$BUILD_DIR/glint"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
make_scene() {  # name moving shutter
    sed -e "s/= MOVING/= $2/" -e "s/shutter = SHUTTER/shutter = $3/" bench/motion_scene.lua \
        >"$tmp/$1.lua"
}
make_scene still false "{0, 0}"
make_scene instant true "{0, 0}"
make_scene blurred true "{0, 1}"

declare -A LOGS
for run in $(seq "$RUNS"); do
    for name in still instant blurred; do
        "$glint" render "$tmp/$name.lua" --spp "$SPP" --threads "$THREADS" \
            -o "$tmp/$name.exr" 2>"$tmp/$name-$run.log"
        LOGS[$name]+=" $tmp/$name-$run.log"
    done
done

summary() {  # name: "seconds M-samples/s M-rays/s cpu-seconds" of the median run by time
    for log in ${LOGS[$1]}; do
        line=$(sed -nE 's/^.* threads: ([0-9.]+) s, ([0-9.]+) M samples\/s, ([0-9.]+) M rays\/s$/\1 \2 \3/p' "$log")
        cpu=$(sed -nE 's/^([0-9]+) samples and [0-9]+ rays in all, ([0-9.]+) s of processor time$/\1 \2/p' "$log")
        echo "$line $cpu"
    done | sort -g | sed -n "$(((RUNS + 1) / 2))p"
}
# On a shared machine wall-clock throughput follows the load; samples per processor-second
# (all threads) less so.
printf '%-8s %8s %14s %12s %22s\n' scene seconds "M samples/s" "M rays/s" "M samples/cpu-second"
for name in still instant blurred; do
    read -r seconds samples rays count cpu <<<"$(summary "$name")"
    per_cpu=$(awk -v n="$count" -v c="$cpu" 'BEGIN { printf "%.3f", n / c * 1e-6 }')
    printf '%-8s %8s %14s %12s %22s\n' "$name" "$seconds" "$samples" "$rays" "$per_cpu"
done
