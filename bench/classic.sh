#!/usr/bin/env bash
# Classic mode and adaptive sampling (issue 6): measures
#   a. the whitted integrator's penumbra shortcut, off and on, with 8 x 8 shadow rays, on
#      bench/soft_shadows.lua and on examples/classic.lua: time, rays traced, relMSE of on
#      against off, and of both against a reference;
#   b. adaptive supersampling (--adaptive sobel) against 16 samples in every pixel on
#      examples/classic.lua: samples per pixel, time, relMSE against a 1024-spp reference;
#   c. variance-driven adaptive sampling against uniform sampling at equal time on the
#      Cornell box at 256x256: relMSE against a 2048-spp reference.
# Times are the render times the CLI prints (scene loading excluded), median of RUNS runs,
# the configurations of one comparison interleaved so that load on a shared machine falls
# on both. References use another seed than the images they judge, so that they share no
# samples with them. See bench/README.md. Takes about 8 minutes on 2 cores.
#
# Environment (all optional):
#   BUILD_DIR        build directory (default build); configured as Release when missing
#   JOBS             parallel compile jobs for ninja (default 2)
#   THREADS          render threads (default 2)
#   RUNS             timed runs of each configuration; the median counts (default 3)
#   CLASSIC_REF_SPP  samples per pixel of the classic reference (default 1024)
#   SOFT_REF_SPP     samples per pixel of the soft-shadow reference (default 64)
#   CORNELL_REF_SPP  samples per pixel of the Cornell box reference (default 2048)
#   VARIANCE_SPP     first-round samples per pixel of the variance mode (default 16)
#   TARGET_ERROR     its target_error (default 0.05)
#   MAX_SPP          its max_spp (default 256)
#   KEEP             a folder to keep the images in (default: none, a temporary folder)
#   PARTS            which measurements to run (default "a b c")
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-2}
THREADS=${THREADS:-2}
RUNS=${RUNS:-3}
CLASSIC_REF_SPP=${CLASSIC_REF_SPP:-1024}
SOFT_REF_SPP=${SOFT_REF_SPP:-64}
CORNELL_REF_SPP=${CORNELL_REF_SPP:-2048}
VARIANCE_SPP=${VARIANCE_SPP:-16}
TARGET_ERROR=${TARGET_ERROR:-0.05}
MAX_SPP=${MAX_SPP:-256}
PARTS=${PARTS:-a b c}

if [[ ! -f "$BUILD_DIR/build.ninja" ]]; then
    cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$BUILD_DIR/CMakeCache.txt")
if [[ "$build_type" != "Release" ]]; then
    echo "warning: $BUILD_DIR is a '$build_type' build; these are not release numbers" >&2
fi
ninja -C "$BUILD_DIR" -j "$JOBS" glint_cli >/dev/null
glint=$PWD/$BUILD_DIR/glint

if [[ -n "${KEEP:-}" ]]; then
    mkdir -p "$KEEP"
    tmp=$(cd "$KEEP" && pwd)
else
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
fi

median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
relmse() { "$glint" compare "$1" "$2" | sed -nE 's/^relative MSE: +//p'; }

# Configurations are named; CMD[name] is the command line (without -o), OUT[name] the image.
declare -A CMD SECONDS_OF SPREAD_OF RAYS_OF SPP_OF
render_once() {
    local name=$1 log="$tmp/$1.log"
    # shellcheck disable=SC2086  # CMD holds words to split: an env prefix, glint and its flags
    if ! env ${CMD[$name]} --threads "$THREADS" -o "$tmp/$name.exr" 2>"$log"; then
        echo "error: '$name' failed:" >&2
        cat "$log" >&2
        exit 1
    fi
    sed -nE 's/^[0-9]+x[0-9]+, [0-9]+ spp, [0-9]+ threads: ([0-9.]+) s, .*/\1/p' "$log"
}
# timed NAME...: renders each configuration RUNS times, interleaved, and records the median
# time, the range of times, the rays traced (M; the same in every run) and, for adaptive
# modes, the average samples per pixel the CLI reports.
timed() {
    local -A times
    local name i
    for ((i = 0; i < RUNS; ++i)); do
        for name in "$@"; do
            times[$name]+=" $(render_once "$name")"
        done
    done
    for name in "$@"; do
        # shellcheck disable=SC2086
        SECONDS_OF[$name]=$(median ${times[$name]})
        # shellcheck disable=SC2086
        SPREAD_OF[$name]=$(printf '%s\n' ${times[$name]} | sort -g | sed -n '1p;$p' | paste -sd-)
        RAYS_OF[$name]=$(sed -nE 's/^.* threads: ([0-9.]+) s, [0-9.]+ M samples\/s, ([0-9.]+) M rays\/s$/\1 \2/p' \
            "$tmp/$name.log" | awk '{ printf "%.1f", $1 * $2 }')
        SPP_OF[$name]=$(sed -nE 's/^adaptive \([a-z]+\): ([0-9.]+) samples per pixel.*/\1/p' "$tmp/$name.log")
    done
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }
# A copy of a scene with one piece of text replaced; fails when the text is not there.
variant() {
    local source=$1 from=$2 to=$3 target=$4
    grep -qF "$from" "$source" || { echo "error: '$from' not found in $source" >&2; exit 1; }
    awk -v from="$from" -v to="$to" '{ i = index($0, from); if (i) $0 = substr($0, 1, i - 1) to substr($0, i + length(from)); print }' \
        "$source" >"$target"
}

echo "glint classic mode and adaptive sampling, $THREADS threads, $(date +%F), $(nproc) cores visible," \
     "commit $(git rev-parse --short HEAD)"

part() { [[ " $PARTS " == *" $1 "* ]]; }
# Renders a reference once (parts a and b share one).
reference() { [[ -f "$tmp/$1.exr" ]] || render_once "$1" >/dev/null; }
CMD[classic_ref]="$glint render examples/classic.lua --spp $CLASSIC_REF_SPP --seed 7"
CMD[soft_ref]="GLINT_PENUMBRA_SHORTCUT=0 $glint render bench/soft_shadows.lua --spp $SOFT_REF_SPP --seed 7"

# a. Penumbra shortcut.
if part a; then
    variant examples/classic.lua 'shadow_samples = 3,' \
        'shadow_samples = 8, penumbra_shortcut = os.getenv("GLINT_PENUMBRA_SHORTCUT") == "1",' "$tmp/classic8.lua"
    CMD[soft_off]="GLINT_PENUMBRA_SHORTCUT=0 $glint render bench/soft_shadows.lua"
    CMD[soft_on]="GLINT_PENUMBRA_SHORTCUT=1 $glint render bench/soft_shadows.lua"
    CMD[classic_off]="GLINT_PENUMBRA_SHORTCUT=0 $glint render $tmp/classic8.lua"
    CMD[classic_on]="GLINT_PENUMBRA_SHORTCUT=1 $glint render $tmp/classic8.lua"
    timed soft_off soft_on
    timed classic_off classic_on
    echo
    echo "a. penumbra shortcut, shadow_samples = 8 (64 shadow rays per area light and hit)"
    reference soft_ref
    reference classic_ref
    printf '%-10s %8s %12s %8s %12s %9s %14s %14s %24s\n' scene "off (s)" "off range" "on (s)" "on range" speed-up \
        "M rays off/on" "relMSE on/off" "relMSE to ref off/on"
    for scene in soft classic; do
        printf '%-10s %8s %12s %8s %12s %9s %14s %14s %24s\n' "$scene" \
            "${SECONDS_OF[${scene}_off]}" "${SPREAD_OF[${scene}_off]}" "${SECONDS_OF[${scene}_on]}" "${SPREAD_OF[${scene}_on]}" \
            "$(ratio "${SECONDS_OF[${scene}_off]}" "${SECONDS_OF[${scene}_on]}")x" \
            "${RAYS_OF[${scene}_off]}/${RAYS_OF[${scene}_on]}" "$(relmse "$tmp/${scene}_on.exr" "$tmp/${scene}_off.exr")" \
            "$(relmse "$tmp/${scene}_off.exr" "$tmp/${scene}_ref.exr")/$(relmse "$tmp/${scene}_on.exr" "$tmp/${scene}_ref.exr")"
    done
    echo "(references: soft_shadows.lua shortcut off at $SOFT_REF_SPP spp, classic.lua at $CLASSIC_REF_SPP spp with" \
         "its own shadow_samples = 3; both seed 7)"

fi

# b. Adaptive supersampling on the classic example.
if part b; then
    variant examples/classic.lua 'integrator = "whitted",' 'integrator = "whitted", sampler = "stratified",' \
        "$tmp/classic_stratified.lua"
    CMD[full_stratified]="$glint render $tmp/classic_stratified.lua --spp 16"
    CMD[full_sobol]="$glint render examples/classic.lua --spp 16"
    CMD[sobel]="$glint render examples/classic.lua --adaptive sobel"
    reference classic_ref
    timed full_stratified full_sobol sobel
    echo
    echo "b. adaptive supersampling on examples/classic.lua (640x400), against $CLASSIC_REF_SPP spp"
    printf '%-30s %10s %8s %12s %10s\n' render "samples/px" "time (s)" "range" relMSE
    printf '%-30s %10s %8s %12s %10s\n' "16 spp, stratified" 16 "${SECONDS_OF[full_stratified]}" "${SPREAD_OF[full_stratified]}" \
        "$(relmse "$tmp/full_stratified.exr" "$tmp/classic_ref.exr")"
    printf '%-30s %10s %8s %12s %10s\n' "16 spp, sobol (default)" 16 "${SECONDS_OF[full_sobol]}" "${SPREAD_OF[full_sobol]}" \
        "$(relmse "$tmp/full_sobol.exr" "$tmp/classic_ref.exr")"
    printf '%-30s %10s %8s %12s %10s\n' "--adaptive sobel (4x4 at edges)" "${SPP_OF[sobel]}" "${SECONDS_OF[sobel]}" "${SPREAD_OF[sobel]}" \
        "$(relmse "$tmp/sobel.exr" "$tmp/classic_ref.exr")"

fi

# c. Variance-driven adaptive sampling against uniform sampling at equal time.
if part c; then
    variant examples/cornell-box.lua 'integrator = "path",' \
        "integrator = \"path\", target_error = $TARGET_ERROR, max_spp = $MAX_SPP," "$tmp/cornell_adaptive.lua"
    CMD[cornell_ref]="$glint render examples/cornell-box.lua --res 256x256 --spp $CORNELL_REF_SPP --seed 7"
    CMD[variance]="$glint render $tmp/cornell_adaptive.lua --res 256x256 --spp $VARIANCE_SPP --adaptive variance"
    CMD[calibrate]="$glint render examples/cornell-box.lua --res 256x256 --spp 64"
    render_once cornell_ref >/dev/null
    # The uniform spp that takes as long as the adaptive render: first from a 64-spp render,
    # then corrected once from the pair timed together, when they differ by more than 5 %.
    timed variance calibrate
    equal_spp=$(awk -v a="${SECONDS_OF[variance]}" -v c="${SECONDS_OF[calibrate]}" 'BEGIN { printf "%d", 64 * a / c + 0.5 }')
    CMD[uniform]="$glint render examples/cornell-box.lua --res 256x256 --spp $equal_spp"
    timed variance uniform
    corrected=$(awk -v a="${SECONDS_OF[variance]}" -v u="${SECONDS_OF[uniform]}" -v n="$equal_spp" \
        'BEGIN { printf "%d", n * a / u + 0.5 }')
    if awk -v a="$corrected" -v n="$equal_spp" 'BEGIN { exit !(a > 1.05 * n || a < n / 1.05) }'; then
        equal_spp=$corrected
        CMD[uniform]="$glint render examples/cornell-box.lua --res 256x256 --spp $equal_spp"
        timed variance uniform
    fi
    CMD[uniform_equal_samples]="$glint render examples/cornell-box.lua --res 256x256 --spp $(printf '%.0f' "${SPP_OF[variance]}")"
    timed uniform_equal_samples
    echo
    echo "c. examples/cornell-box.lua at 256x256 (path), against $CORNELL_REF_SPP spp"
    printf '%-60s %10s %8s %12s %10s\n' render "samples/px" "time (s)" "range" relMSE
    printf '%-60s %10s %8s %12s %10s\n' \
        "--adaptive variance, spp $VARIANCE_SPP, target_error $TARGET_ERROR, max_spp $MAX_SPP" \
        "${SPP_OF[variance]}" "${SECONDS_OF[variance]}" "${SPREAD_OF[variance]}" "$(relmse "$tmp/variance.exr" "$tmp/cornell_ref.exr")"
    printf '%-60s %10s %8s %12s %10s\n' "uniform, equal time" "$equal_spp" "${SECONDS_OF[uniform]}" "${SPREAD_OF[uniform]}" \
        "$(relmse "$tmp/uniform.exr" "$tmp/cornell_ref.exr")"
    printf '%-60s %10s %8s %12s %10s\n' "uniform, equal samples" "$(printf '%.0f' "${SPP_OF[variance]}")" \
        "${SECONDS_OF[uniform_equal_samples]}" "${SPREAD_OF[uniform_equal_samples]}" "$(relmse "$tmp/uniform_equal_samples.exr" "$tmp/cornell_ref.exr")"
fi
