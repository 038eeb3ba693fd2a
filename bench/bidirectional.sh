#!/usr/bin/env bash
# Bidirectional methods benchmark (issue 19): time for each integrator to reach a relative
# MSE of 0.02 and of 0.005 against a long reference, on three scenes:
#   cornell    examples/cornell-box.lua, whole image (reference: path)
#   spheres    examples/cornell-spheres.lua, the glass sphere's caustic on the floor
#              (reference: path at 65536 spp over the region alone, with --crop)
#   spheres-direct  the same renders, the part of that region where the caustic on the floor
#              is seen directly (light, glass, floor, lens; see bench/README.md)
#   spheres-glass   the same renders, the part seen through the glass sphere (lens, glass,
#              floor, glass, light: specular-diffuse-specular)
#   ajar       examples/ajar-door.lua, whole image: light reaches the room only by bouncing
#              through a door left ajar (reference: bdpt)
# Each integrator renders at a ladder of sample counts; the time to a target is interpolated
# in log-log between the two renders around it (a render's time is the CLI's own summary,
# scene loading excluded). See bench/README.md, "Bidirectional methods".
# At the defaults about 25 minutes on 2 cores; SCENES and INTEGRATORS pick a part. Scenes that
# share a file share their renders (each is made once per run, and timed once).
#
# Environment (all optional):
#   BUILD_DIR    build directory (default build), or a copy of its glint and
#                bench/glint_bench_region_error
#   THREADS      render threads (default 2)
#   RES          resolution (default 128x128; the spheres' region is given for it)
#   SCENES       scenes to run (default "cornell spheres ajar")
#   INTEGRATORS  integrators to time (default "path bdpt vcm mlt sppm"; those this build
#                does not have are skipped). An entry LABEL=INTEGRATOR times INTEGRATOR
#                under the name LABEL (letters, digits, _), so that one integrator can be
#                timed with several settings in one run
#   SETTINGS_<label>  extra glint.render{} settings (Lua) for the entry LABEL (or for a plain
#                entry, the integrator's name), e.g. SETTINGS_vcm8x="vcm_light_paths = 131072"
#   LADDER_<label>    its sample counts instead of the integrator's default ladder
#   REF_SPP      samples per pixel of the references (default 4096 for path, 1024 for bdpt)
#   TARGETS      relative MSE targets (default "0.02 0.005")
#   CLOCK        wall (default: the render's wall-clock seconds) or cpu (its processor
#                seconds, all threads: steadier on a machine busy with other work)
#   SEEDS        seeds each ladder step renders with (default "0"); the time and the relative
#                MSE printed are their means: at few samples one seed's error is heavy-tailed
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
THREADS=${THREADS:-2}
RES=${RES:-128x128}
SCENES=${SCENES:-cornell spheres ajar}
INTEGRATORS=${INTEGRATORS:-path bdpt vcm mlt sppm}
TARGETS=${TARGETS:-0.02 0.005}
CLOCK=${CLOCK:-wall}
SEEDS=${SEEDS:-0}
seed_count=$(wc -w <<<"$SEEDS")
# A directory without build.ninja holds copies of the two programs (glint and
# bench/glint_bench_region_error), so that a rebuild elsewhere cannot swap them mid-run.
if [[ -f $BUILD_DIR/build.ninja ]]; then
    ninja -C "$BUILD_DIR" glint_cli glint_bench_region_error >/dev/null
fi
glint=$BUILD_DIR/glint
error=$BUILD_DIR/bench/glint_bench_region_error
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
width=${RES%x*}
height=${RES#*x}

# scene name -> "file|region x0 y0 x1 y1|reference integrator|reference spp|crop"
# (crop: the reference renders the region alone, so it can afford many more samples)
scene_spec() {
    case $1 in
    cornell) echo "examples/cornell-box.lua|0 0 $width $height|path|${REF_SPP:-4096}|no" ;;
    spheres) echo "examples/cornell-spheres.lua|74 110 98 122|path|${REF_SPP:-65536}|yes" ;;
    # Parts of the spheres' region at 128 x 128 (bench/README.md says how they were chosen).
    spheres-direct) echo "examples/cornell-spheres.lua|78 116 92 118|path|${REF_SPP:-65536}|yes" ;;
    spheres-glass) echo "examples/cornell-spheres.lua|74 110 90 113|path|${REF_SPP:-65536}|yes" ;;
    ajar) echo "examples/ajar-door.lua|0 0 $width $height|bdpt|${REF_SPP:-1024}|no" ;;
    *) echo "unknown scene '$1' (expected: cornell, spheres, spheres-direct, spheres-glass," \
        "ajar)" >&2 && exit 2 ;;
    esac
}

# The sample counts an entry (label, integrator) is timed at: about the same time span for each.
ladder() {
    local override="LADDER_$1"
    if [[ -n ${!override:-} ]]; then
        echo "${!override}"
        return
    fi
    case $2 in
    path) echo "4 16 64 256 1024" ;;
    bdpt | vcm) echo "1 4 16 64 256" ;;
    mlt) echo "1 4 16 64 256" ;;
    sppm) echo "4 16 64 256" ;;
    *) echo "4 16 64 256" ;;
    esac
}

has_integrator() {
    "$glint" render "$1" --integrator "$2" --res 4x4 --spp 1 -o "$tmp/probe.exr" --quiet \
        >/dev/null 2>&1
}

# The scene for an entry: `scene` itself, or a copy beside the other temporary files with the
# entry's settings added to its glint.render{} (the scene must not require files beside it).
scene_for() {  # scene, label -> path
    local settings="SETTINGS_$2"
    if [[ -z ${!settings:-} ]]; then
        echo "$1"
        return
    fi
    local out
    out="$tmp/$2.$(basename "$1")"
    sed "s/glint\.render{ */glint.render{ ${!settings}, /" "$1" >"$out"
    if cmp -s "$1" "$out"; then
        echo "error: no glint.render{ in $1 to add SETTINGS_$2 to" >&2
        exit 2
    fi
    echo "$out"
}

render() {  # scene, output, args... -> seconds of the render (from the CLI's summary line)
    local scene=$1 out=$2
    shift 2
    "$glint" render "$scene" --threads "$THREADS" --res "$RES" -o "$out" "$@" 2>"$tmp/log"
    if [[ $CLOCK == cpu ]]; then
        sed -nE 's/^.* ([0-9.]+) s of processor time$/\1/p' "$tmp/log" | tail -1
    else
        sed -nE 's/^.*threads: ([0-9.]+) s,.*$/\1/p' "$tmp/log" | tail -1
    fi
}

echo "Bidirectional methods, $RES, $THREADS threads, $CLOCK seconds, $(date +%F)," \
    "commit $(git rev-parse --short HEAD)"
for name in $SCENES; do
    IFS='|' read -r scene region ref_integrator ref_spp ref_crop <<<"$(scene_spec "$name")"
    if [[ ! -f "$scene" ]]; then
        echo "$name: $scene not found, skipped"
        continue
    fi
    crop_args=()
    if [[ $ref_crop == yes ]]; then
        read -r x0 y0 x1 y1 <<<"$region"
        crop_args=(--crop "$x0,$y0,$x1,$y1")
    fi
    ref_seconds=$(render "$scene" "$tmp/ref.exr" --integrator "$ref_integrator" --spp "$ref_spp" \
        --seed 7 "${crop_args[@]}")
    echo
    echo "$name: $scene, region [$region], reference $ref_integrator $ref_spp spp" \
        "$([[ $ref_crop == yes ]] && echo "over the region ")($ref_seconds s)"
    printf '  %-6s %6s %9s %10s\n' integr. spp seconds "rel. MSE"
    rows=""
    for entry in $INTEGRATORS; do
        label=${entry%%=*}
        integrator=${entry#*=}
        if [[ ! $label =~ ^[A-Za-z0-9_]+$ ]]; then
            echo "error: '$label' in INTEGRATORS is not a label (letters, digits, _)" >&2
            exit 2
        fi
        if ! has_integrator "$scene" "$integrator"; then
            echo "  $integrator: not in this build, skipped"
            continue
        fi
        entry_scene=$(scene_for "$scene" "$label")
        for n in $(ladder "$label" "$integrator"); do
            # Each seed's render: its time and error are averaged over the seeds (the mean
            # relative MSE is the expected error, which one seed's only estimates).
            t=0
            e=0
            for seed in $SEEDS; do
                # Renders are kept for the run: scenes that share a file share them.
                cached="$tmp/cache.$(basename "$scene").$label.$n.$seed"
                if [[ ! -f $cached.exr ]]; then
                    render "$entry_scene" "$cached.exr" --integrator "$integrator" --spp "$n" \
                        --seed "$seed" >"$cached.seconds"
                fi
                # shellcheck disable=SC2086
                seed_error=$("$error" "$cached.exr" "$tmp/ref.exr" $region)
                t=$(awk -v a="$t" -v b="$(cat "$cached.seconds")" 'BEGIN { print a + b }')
                e=$(awk -v a="$e" -v b="$seed_error" 'BEGIN { print a + b }')
            done
            t=$(awk -v a="$t" -v k="$seed_count" 'BEGIN { print a / k }')
            e=$(awk -v a="$e" -v k="$seed_count" 'BEGIN { print a / k }')
            printf '  %-6s %6d %9.2f %10.5f\n' "$label" "$n" "$t" "$e"
            rows+="$label $n $t $e"$'\n'
        done
    done
    for target in $TARGETS; do
        # The first time each integrator reaches the target, interpolated in log-log.
        awk -v target="$target" -v scene="$name" '
            NF == 4 { if (!(($1) in count)) order[++names] = $1
                      k = ++count[$1]; t[$1, k] = $3; e[$1, k] = $4 }
            END {
                for (j = 1; j <= names; ++j) {
                    name = order[j]
                    result = "> " t[name, count[name]] " s (not reached)"
                    for (i = 1; i <= count[name]; ++i) {
                        if (e[name, i] > target) continue
                        if (i == 1) { result = "<= " t[name, 1] " s"; break }
                        dt = log(t[name, i]) - log(t[name, i - 1])
                        de = log(e[name, i]) - log(e[name, i - 1])
                        at = log(t[name, i - 1]) + (log(target) - log(e[name, i - 1])) * dt / de
                        result = sprintf("= %.3g s", exp(at))
                        break
                    }
                    printf "  %s: time to rel. MSE %s: %-5s %s\n", scene, target, name, result
                }
            }' <<<"$rows"
    done
done
