#!/usr/bin/env bash
# Light tracing benchmark (issue 16): time for `light`, `sppm` and `path` to reach a relative
# MSE of 0.02 in the glass sphere's caustic on examples/caustics.lua (its spot light; the
# background black, since neither `light` nor `sppm` takes light from a constant background).
# The error is measured over pixels [98,128) x [94,120) at 240x180, the floor under the
# sphere's caustic, against sppm with REF_PASSES passes. See bench/README.md, "Light tracing".
# About 4 minutes on 2 cores.
#
# Environment (all optional):
#   BUILD_DIR    build directory (default build)
#   THREADS      render threads (default 2)
#   REF_PASSES   sppm passes of the reference (default 256)
#   LIGHT_SPP    light paths per pixel to time (default "16 64 256 1024")
#   SPPM_PASSES  sppm passes to time (default "4 16 32 64 128")
#   PATH_SPP     path samples per pixel to time (default "16 64 256")
#   TARGET       relative MSE target (default 0.02)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
THREADS=${THREADS:-2}
REF_PASSES=${REF_PASSES:-256}
LIGHT_SPP=${LIGHT_SPP:-16 64 256 1024}
SPPM_PASSES=${SPPM_PASSES:-4 16 32 64 128}
PATH_SPP=${PATH_SPP:-16 64 256}
TARGET=${TARGET:-0.02}
RES=240x180
REGION="98 94 128 120"
ninja -C "$BUILD_DIR" glint_cli glint_bench_region_error >/dev/null
glint=$BUILD_DIR/glint
error=$BUILD_DIR/bench/glint_bench_region_error
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed 's/^glint\.background{ radiance = [0-9.]* }/glint.background{ radiance = 0 }/' examples/caustics.lua >"$tmp/scene.lua"

render() {  # output, args... -> seconds of the render (from the CLI's summary line)
    local out=$1
    shift
    "$glint" render "$tmp/scene.lua" --threads "$THREADS" --res "$RES" -o "$out" "$@" 2>"$tmp/log"
    sed -nE 's/^.*threads: ([0-9.]+) s,.*$/\1/p' "$tmp/log" | tail -1
}

ref_seconds=$(render "$tmp/ref.exr" --integrator sppm --spp "$REF_PASSES" --seed 7)
echo "Light tracing: examples/caustics.lua (black background), $RES, caustic region [98,128) x [94,120)"
echo "reference: sppm, $REF_PASSES passes, seed 7: $ref_seconds s"
printf '%-6s %8s %9s %10s\n' integr. spp seconds "rel. MSE"
rows=""
for spec in "light:$LIGHT_SPP" "sppm:$SPPM_PASSES" "path:$PATH_SPP"; do
    integrator=${spec%%:*}
    for n in ${spec#*:}; do
        t=$(render "$tmp/t.exr" --integrator "$integrator" --spp "$n" --seed 0)
        # shellcheck disable=SC2086
        e=$("$error" "$tmp/t.exr" "$tmp/ref.exr" $REGION)
        printf '%-6s %8d %9.2f %10.5f\n' "$integrator" "$n" "$t" "$e"
        rows+="$integrator $n $t $e"$'\n'
    done
done
# The first time each integrator reaches the target, interpolated in log-log between runs.
awk -v target="$TARGET" '
    NF == 4 { k = ++count[$1]; t[$1, k] = $3; e[$1, k] = $4 }
    END {
        for (name in count) {
            result = "> " t[name, count[name]] " s (not reached)"
            for (i = 1; i <= count[name]; ++i) {
                if (e[name, i] > target) continue
                if (i == 1) { result = "<= " t[name, 1] " s"; break }
                s = (log(t[name, i]) - log(t[name, i - 1])) / (log(e[name, i]) - log(e[name, i - 1]))
                result = sprintf("= %.3g s", exp(log(t[name, i - 1]) + (log(target) - log(e[name, i - 1])) * s))
                break
            }
            printf "time to rel. MSE %s in the caustic: %-5s %s\n", target, name, result
        }
    }' <<<"$rows"
