#!/usr/bin/env bash
# Photon mapping benchmark (issue #5): photon throughput, caustic-map quality with and
# without projection maps, and the time sppm and path need to reach the same relative MSE
# on the caustics scene. See bench/README.md, "Photon mapping". About 5 minutes on 2 cores.
#
# Environment (all optional):
#   BUILD_DIR        build directory (default build); configured as Release when it does not exist
#   JOBS             parallel compile jobs for ninja (default 2)
#   THREADS          render threads (default 2)
#   RATE_PHOTONS     photons per map for the throughput runs (default 1000000)
#   RATE_RUNS        runs per throughput configuration; the median counts (default 3)
#   QUALITY_PHOTONS  caustic photons of the quality runs (default "100000 300000 1000000 3000000")
#   QUALITY_REF      caustic photons of the quality reference, without projection maps (default 30000000)
#   RES              resolution of the quality and time-to-error renders (default 240x180)
#   REF_PASSES       sppm passes of the time-to-error reference (default 1024)
#   SPPM_PASSES      sppm passes to time (default "1 2 4 8 16 32 64 128")
#   PATH_SPP         path samples per pixel to time (default "16 64 256 1024 4096")
#   TARGETS          relative MSE targets (default "0.05 0.03")
#   SPOT_REF_PASSES  sppm passes of the spot-light reference (default 256)
#   SPOT_PATH_SPP    path samples per pixel on the spot-light scene (default "64 256 1024")
#   SECTIONS         which parts to run (default "1 2 3")
set -euo pipefail
shopt -s inherit_errexit

cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-2}
THREADS=${THREADS:-2}
RATE_PHOTONS=${RATE_PHOTONS:-1000000}
RATE_RUNS=${RATE_RUNS:-3}
QUALITY_PHOTONS=${QUALITY_PHOTONS:-"100000 300000 1000000 3000000"}
QUALITY_REF=${QUALITY_REF:-30000000}
RES=${RES:-240x180}
REF_PASSES=${REF_PASSES:-1024}
SPPM_PASSES=${SPPM_PASSES:-"1 2 4 8 16 32 64 128"}
PATH_SPP=${PATH_SPP:-"16 64 256 1024 4096"}
TARGETS=${TARGETS:-"0.05 0.03"}
SPOT_REF_PASSES=${SPOT_REF_PASSES:-256}
SPOT_PATH_SPP=${SPOT_PATH_SPP:-"64 256 1024"}
SECTIONS=${SECTIONS:-"1 2 3"}
SCENE=examples/caustics.lua

if [[ ! -f "$BUILD_DIR/build.ninja" ]]; then
    cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$BUILD_DIR/CMakeCache.txt")
if [[ "$build_type" != "Release" ]]; then
    echo "warning: $BUILD_DIR is a '$build_type' build; these are not release numbers" >&2
fi
ninja -C "$BUILD_DIR" -j "$JOBS" glint_cli >/dev/null
glint=$BUILD_DIR/glint
if pgrep -f cc1plus >/dev/null; then
    echo "warning: a compiler is running; the timings below share the machine with it" >&2
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# sed with a check that the expression changed something, so that an edit of the example
# that moves a setting fails here instead of silently benchmarking the wrong scene.
edit() {  # input, output, sed expressions...
    local in=$1 out=$2
    shift 2
    sed "$@" "$in" >"$out"
    if cmp -s "$in" "$out"; then
        echo "error: sed $* changed nothing in $in; has $SCENE changed?" >&2
        exit 1
    fi
}

summary_re='threads: ([0-9.]+) s, '
photon_re='^photon maps: ([0-9]+) global and ([0-9]+) caustic photons stored in ([0-9.]+) s \(([0-9.]+) M caustic photons emitted/s\)$'

render() {  # scene, output.exr, glint render flags... -> prints the render time in seconds
    local scene=$1 out=$2
    shift 2
    "$glint" render "$scene" --threads "$THREADS" -o "$out" "$@" 2>"$tmp/log" || {
        cat "$tmp/log" >&2
        exit 1
    }
    local line
    line=$(grep -E "$summary_re" "$tmp/log" || true)
    if [[ ! "$line" =~ $summary_re ]]; then
        echo "error: no summary line from glint render $scene:" >&2
        cat "$tmp/log" >&2
        exit 1
    fi
    echo "${BASH_REMATCH[1]}"
}

relmse() {  # test.exr, reference.exr
    "$glint" compare "$1" "$2" | sed -nE 's/^relative MSE: +//p'
}

median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
section() { [[ " $SECTIONS " == *" $1 "* ]]; }

echo "glint photon mapping benchmark, $(date +%F), $THREADS threads, $(nproc) cores visible," \
    "commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"

if section 1; then
    # 1. Throughput. The photon integrator traces RATE_PHOTONS photons into the global map and
    # RATE_PHOTONS into the caustic map (--photons sets both); the image is tiny so the maps
    # dominate. The CLI's note gives both maps' stored counts, the time to build both (tracing
    # and kd-trees), and the caustic map's emitted photons per second. Two lights: the
    # example's spot light (28 degree cone aimed at the objects) and, in its place, a point
    # light of the same intensity, which sends photons everywhere.
    cp "$SCENE" "$tmp/spot_on.lua"
    edit "$SCENE" "$tmp/spot_off.lua" -e 's/glint\.render{ /glint.render{ projection_maps = false, /'
    edit "$SCENE" "$tmp/point_on.lua" \
        -e 's/^glint\.spot_light{.*/glint.point_light{ position = {-4.5, 5, 0}, intensity = 260 }/'
    edit "$tmp/point_on.lua" "$tmp/point_off.lua" -e 's/glint\.render{ /glint.render{ projection_maps = false, /'

    echo
    echo "1. Photon throughput: $SCENE, photon integrator, $RATE_PHOTONS global + $RATE_PHOTONS caustic photons" \
        "emitted, 64x48, 1 spp, median of $RATE_RUNS runs"
    printf '%-6s %-10s %10s %10s %8s %14s %16s %16s %14s\n' light projection global caustic "maps s" \
        "M stored/s" "caustic/emitted" "M caustic em./s" "M caustic/s"
    for config in spot_on spot_off point_on point_off; do
        times=() rates=()
        for ((i = 0; i < RATE_RUNS; ++i)); do
            render "$tmp/$config.lua" "$tmp/rate.exr" --integrator photon --res 64x48 --spp 1 \
                --photons "$RATE_PHOTONS" >/dev/null
            line=$(grep -E "$photon_re" "$tmp/log" || true)
            if [[ ! "$line" =~ $photon_re ]]; then
                echo "error: no 'photon maps:' line from glint render:" >&2
                cat "$tmp/log" >&2
                exit 1
            fi
            global=${BASH_REMATCH[1]} caustic=${BASH_REMATCH[2]}
            times+=("${BASH_REMATCH[3]}")
            rates+=("${BASH_REMATCH[4]}")
        done
        t=$(printf '%s\n' "${times[@]}" | median)
        rate=$(printf '%s\n' "${rates[@]}" | median)
        awk -v c="$config" -v g="$global" -v k="$caustic" -v t="$t" -v r="$rate" -v n="$RATE_PHOTONS" 'BEGIN {
            split(c, part, "_")
            printf "%-6s %-10s %10d %10d %8.2f %14.2f %16.3f %16.2f %14.2f\n", part[1], part[2], g, k, t,
                   (g + k) / t * 1e-6, k / n, r, r * k / n }'
    done
fi

if section 2; then
    # 2. Caustic-map quality. Final gathering off (gather_rays = 0), so an image is direct light
    # plus the caustic map's estimate. Every render has the same seed, so the camera samples and
    # the direct light are the same in all of them and only the caustic estimate differs. The
    # reference is the plain estimator, projection maps off, with QUALITY_REF caustic photons:
    # the runs with projection maps on share no photons with it; a run without them shares its
    # first photons (photon i is keyed by (seed, i)), which can only flatter the runs without.
    quality_scene() {  # projection maps (true/false), caustic photons, output
        edit "$SCENE" "$3" -e "s/glint\.render{ /glint.render{ projection_maps = $1, /" \
            -e "s/caustic_photons = [0-9]*/caustic_photons = $2/" -e 's/gather_rays = [0-9]*/gather_rays = 0/'
    }
    quality_scene false "$QUALITY_REF" "$tmp/quality_ref.lua"
    render "$tmp/quality_ref.lua" "$tmp/quality_ref.exr" --res "$RES" --spp 4 >/dev/null

    echo
    echo "2. Caustic-map quality: photon integrator without final gathering, $RES, 4 spp, relative MSE" \
        "against $QUALITY_REF caustic photons without projection maps"
    printf '%-10s %10s %10s %10s %10s\n' projection emitted stored "caustic s" "rel. MSE"
    for projection in true false; do
        for n in $QUALITY_PHOTONS; do
            quality_scene "$projection" "$n" "$tmp/quality.lua"
            render "$tmp/quality.lua" "$tmp/quality.exr" --res "$RES" --spp 4 >/dev/null
            [[ "$(grep -E "$photon_re" "$tmp/log")" =~ $photon_re ]]
            # The caustic map's own time, from its emitted photons per second.
            printf '%-10s %10d %10d %10.2f %10.5f\n' "$([[ $projection == true ]] && echo on || echo off)" "$n" \
                "${BASH_REMATCH[2]}" "$(awk -v n="$n" -v r="${BASH_REMATCH[4]}" 'BEGIN { print n / (r * 1e6) }')" \
                "$(relmse "$tmp/quality.exr" "$tmp/quality_ref.exr")"
        done
    done
fi

if section 3; then
    # 3. Time to error. Path tracing cannot find the caustics of a point or spot light (a path
    # from a diffuse surface through glass would have to hit a point), so the timed scene is the
    # example with its spot light replaced by a small square area light (0.5 x 0.5, same place,
    # facing the same point, same on-axis intensity); and its background is black, because sppm
    # takes no light from a constant background (it is not a photon source), while path does.
    # The reference is sppm with REF_PASSES passes: path at thousands of spp is still full of
    # caustic fireflies. Every timed render has seed 0, the reference seed 7.
    edit "$SCENE" "$tmp/area.lua" -e '/^glint\.spot_light{/d' \
        -e 's/^glint\.background{ radiance = [0-9.]* }/glint.background{ radiance = 0 }/'
    cat >>"$tmp/area.lua" <<'EOF'
-- bench/photons.sh: the spot light as a one-sided square area light at the same place,
-- facing the same point, with the same on-axis intensity (radiance x area = 260 W/sr).
do
    local side, intensity = 0.5, 260
    local c, d, u = {-4.5, 5, 0}, {4.9, -5, 0}, {0, 0, 1}
    local n = math.sqrt(d[1] * d[1] + d[2] * d[2] + d[3] * d[3])
    d = {d[1] / n, d[2] / n, d[3] / n}
    local v = {d[2] * u[3] - d[3] * u[2], d[3] * u[1] - d[1] * u[3], d[1] * u[2] - d[2] * u[1]}
    local function corner(a, b)
        local h = side / 2
        return {c[1] + h * (a * u[1] + b * v[1]), c[2] + h * (a * u[2] + b * v[2]),
                c[3] + h * (a * u[3] + b * v[3])}
    end
    glint.quad{ vertices = {corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)},
                material = glint.emissive{ radiance = intensity / (side * side), two_sided = false } }
end
EOF

    series() {  # scene, reference, integrator, counts... -> "count seconds relmse" lines
        local scene=$1 ref=$2 integrator=$3 n t
        shift 3
        for n in "$@"; do
            t=$(render "$scene" "$tmp/t.exr" --integrator "$integrator" --res "$RES" --spp "$n" --seed 0)
            echo "$n $t $(relmse "$tmp/t.exr" "$ref")"
        done
    }

    # The first time a series reaches `target`, interpolated in log-log between the runs
    # around it: "= T", or "<= T" when its first run is already there, "> T" when none is.
    time_to() {  # target, series lines on stdin
        awk -v target="$1" '
            { n[NR] = $1; t[NR] = $2; e[NR] = $3 }
            END {
                for (i = 1; i <= NR; ++i) {
                    if (e[i] > target) continue
                    if (i == 1) { printf "<= %.3g\n", t[1]; exit }
                    slope = (log(t[i]) - log(t[i - 1])) / (log(e[i]) - log(e[i - 1]))
                    lt = log(t[i - 1]) + (log(target) - log(e[i - 1])) * slope
                    printf "= %.3g\n", exp(lt); exit
                }
                printf "> %.3g\n", t[NR]
            }'
    }

    echo
    echo "3. Time to error: $SCENE with a 0.5 x 0.5 area light and a black background, $RES"
    ref_seconds=$(render "$tmp/area.lua" "$tmp/area_ref.exr" --integrator sppm --res "$RES" --spp "$REF_PASSES" --seed 7)
    echo "reference: sppm, $REF_PASSES passes of 100000 photons, seed 7: $ref_seconds s"
    # shellcheck disable=SC2086
    sppm_rows=$(series "$tmp/area.lua" "$tmp/area_ref.exr" sppm $SPPM_PASSES)
    # shellcheck disable=SC2086
    path_rows=$(series "$tmp/area.lua" "$tmp/area_ref.exr" path $PATH_SPP)
    printf '%-6s %8s %9s %10s\n' integr. spp/pass seconds "rel. MSE"
    awk '{ printf "%-6s %8d %9.2f %10.5f\n", "sppm", $1, $2, $3 }' <<<"$sppm_rows"
    awk '{ printf "%-6s %8d %9.2f %10.5f\n", "path", $1, $2, $3 }' <<<"$path_rows"
    # The last path image checks the reference: path is unbiased, so the image means must agree.
    "$glint" compare "$tmp/t.exr" "$tmp/area_ref.exr" |
        awk '/^test mean/ { gsub(/[(),]/, " "); t = $3 + $4 + $5 } /^ref mean/ { gsub(/[(),]/, " "); r = $3 + $4 + $5 }
             END { printf "image mean, last path run / sppm reference: %.4f\n", t / r }'
    for target in $TARGETS; do
        s=$(time_to "$target" <<<"$sppm_rows")
        p=$(time_to "$target" <<<"$path_rows")
        awk -v target="$target" -v s="$s" -v p="$p" 'BEGIN {
            split(s, a, " "); split(p, b, " ")
            ratio = b[2] / a[2]
            lower = b[1] != "<=" && a[1] != ">"  # the ratio is at least this
            upper = b[1] != ">" && a[1] != "<="  # the ratio is at most this
            if (lower && upper) bound = ""; else if (lower) bound = ">= "; else if (upper) bound = "<= "
            else { printf "rel. MSE %s: sppm %s s, path %s s: ratio unknown\n", target, s, p; exit }
            printf "rel. MSE %s: sppm %s s, path %s s: sppm %s%.0fx sooner (target >= 5x)\n", target, s, p, bound, ratio }'
    done

    # The example as it is (spot light), background black as above: path never finds the
    # caustics, so its error stops falling at what they contribute.
    edit "$SCENE" "$tmp/spot.lua" -e 's/^glint\.background{ radiance = [0-9.]* }/glint.background{ radiance = 0 }/'
    ref_seconds=$(render "$tmp/spot.lua" "$tmp/spot_ref.exr" --integrator sppm --res "$RES" --spp "$SPOT_REF_PASSES" --seed 7)
    echo
    echo "The example's spot light (black background), $RES, against sppm with $SPOT_REF_PASSES passes ($ref_seconds s)"
    printf '%-6s %8s %9s %10s\n' integr. spp/pass seconds "rel. MSE"
    # shellcheck disable=SC2086
    series "$tmp/spot.lua" "$tmp/spot_ref.exr" path $SPOT_PATH_SPP | awk '{ printf "%-6s %8d %9.2f %10.5f\n", "path", $1, $2, $3 }'
    series "$tmp/spot.lua" "$tmp/spot_ref.exr" sppm 1 2 4 8 | awk '{ printf "%-6s %8d %9.2f %10.5f\n", "sppm", $1, $2, $3 }'
fi
