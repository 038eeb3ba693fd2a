#!/usr/bin/env bash
# glint against Blender Cycles on the Cornell box (issue 31): efficiency 1 / (relative MSE x
# seconds) of glint's `path` and of Cycles at a few samples per pixel, 256x256, 2 threads, in
# the same run. See bench/README.md, "Against Blender Cycles: the Cornell box".
#
# 1. References: glint `path` at REF_SPP and Cycles at CYCLES_REF_SPP, each with its own seed
#    (7), so no test image shares samples with a reference. Their channel means should agree
#    within about 1 %: that checks the scene's conversion (scripts/blender_cornell.py).
# 2. Timed renders at each of SPP, alternating glint and Cycles, REPS times; the minimum time
#    counts (the machine is shared). glint's time is the render as its summary line reports
#    it (no start-up, no scene load); Cycles' is time.perf_counter around
#    bpy.ops.render.render inside Blender, after an untimed 1-spp warm-up render in the same
#    process (Blender's start-up is not counted; sync, BVH and writing the EXR are).
# 3. Relative MSE as `glint compare` computes it, (t - r)^2 / (r^2 + 0.01) over pixels and
#    channels, of each test image against both references, so a bias in either renderer shows.
#    Efficiency uses glint's reference for both renderers (the less noisy one); the reference's
#    own noise adds the same small amount to both errors.
# About 7 to 9 minutes on 2 cores.
#
# Needs Debian's `blender` (3.4) and a glint binary.
# Environment (all optional):
#   GLINT           glint binary (default build/glint)
#   OUT             directory for the images and logs (default /tmp/glint-cycles-cornell)
#   THREADS         render threads for both (default 2)
#   SIZE            image side in pixels (default 256)
#   REF_SPP         glint reference samples per pixel (default 4096)
#   CYCLES_REF_SPP  Cycles reference samples per pixel (default 2048)
#   SPP             samples per pixel to time (default "16 64 256")
#   REPS            timed renders of each (default 3)
#   KEEP_REFERENCES 1: reuse OUT's references from an earlier run with the same settings
#                   (only the timed renders run: about 3 minutes)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
GLINT=${GLINT:-build/glint}
OUT=${OUT:-/tmp/glint-cycles-cornell}
THREADS=${THREADS:-2}
SIZE=${SIZE:-256}
REF_SPP=${REF_SPP:-4096}
CYCLES_REF_SPP=${CYCLES_REF_SPP:-2048}
SPP=${SPP:-16 64 256}
REPS=${REPS:-3}
KEEP_REFERENCES=${KEEP_REFERENCES:-0}
SCENE=examples/cornell-box.lua
command -v blender >/dev/null || { echo "cycles_cornell: install Debian's blender" >&2; exit 1; }
[ -x "$GLINT" ] || { echo "cycles_cornell: no glint at $GLINT (build it, or set GLINT)" >&2; exit 1; }
if [ "$THREADS" != 2 ]; then
    # scripts/blender_cornell.py fixes Cycles at 2 threads; keep both renderers alike.
    sed "s/scene.render.threads = 2/scene.render.threads = $THREADS/" scripts/blender_cornell.py \
        >"$OUT.blender_cornell.py"
    blender_script=$OUT.blender_cornell.py
else
    blender_script=scripts/blender_cornell.py
fi
mkdir -p "$OUT"

glint_seconds() {  # log -> "wall processor" seconds of the render (the CLI's summary lines)
    echo "$(sed -nE 's/^.*threads: ([0-9.]+) s,.*$/\1/p' "$1" | tail -1)" \
        "$(sed -nE 's/^.* ([0-9.]+) s of processor time$/\1/p' "$1" | tail -1)"
}

cycles_seconds() {  # log -> "wall processor" seconds of the render inside Blender
    echo "$(sed -nE 's/^cycles-render-seconds: ([0-9.]+)$/\1/p' "$1")" \
        "$(sed -nE 's/^cycles-render-cpu-seconds: ([0-9.]+)$/\1/p' "$1")"
}

glint_render() {  # output spp seed -> "wall processor" seconds of the render
    "$GLINT" render "$SCENE" --integrator path --threads "$THREADS" --res "${SIZE}x${SIZE}" \
        --spp "$2" --seed "$3" -o "$1" 2>"$1.log"
    glint_seconds "$1.log"
}

cycles_render() {  # output spp seed -> "wall processor" seconds of the render
    blender -b --factory-startup --python "$blender_script" -- "$1" "$2" "$SIZE" "$3" \
        >"$1.log" 2>&1 || { tail -20 "$1.log" >&2; exit 1; }
    cycles_seconds "$1.log"
}

compare() {  # test reference -> "relMSE test_mean(R G B) ref_mean(R G B)"
    "$GLINT" compare "$1" "$2" | awk -F'[:(), ]+' '
        /^relative MSE/ { rel = $3 }
        /^test mean/ { t = $3 " " $4 " " $5 }
        /^ref mean/ { r = $3 " " $4 " " $5 }
        END { print rel, t, r }'
}

echo "glint against Cycles: $SCENE, ${SIZE}x${SIZE}, $THREADS threads, $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "glint: $GLINT ($("$GLINT" --version 2>/dev/null | head -1)); $(blender --version 2>/dev/null | head -1)"
echo "load before: $(uptime)"
kept=""
if [ "$KEEP_REFERENCES" = 1 ] && [ -f "$OUT/glint-ref.exr" ] && [ -f "$OUT/cycles-ref.exr" ]; then
    g_ref_s=$(glint_seconds "$OUT/glint-ref.exr.log")
    c_ref_s=$(cycles_seconds "$OUT/cycles-ref.exr.log")
    kept=" (kept from an earlier run)"
else
    g_ref_s=$(glint_render "$OUT/glint-ref.exr" "$REF_SPP" 7)
    c_ref_s=$(cycles_render "$OUT/cycles-ref.exr" "$CYCLES_REF_SPP" 7)
fi
echo "Cycles sampling pattern: $(sed -n 's/^cycles-sampling-pattern: //p' "$OUT/cycles-ref.exr.log")"
read -r ref_rel c_r c_g c_b g_r g_g g_b < <(compare "$OUT/cycles-ref.exr" "$OUT/glint-ref.exr")
echo
echo "References (wall and processor seconds): glint $REF_SPP spp ($g_ref_s), Cycles $CYCLES_REF_SPP spp ($c_ref_s)$kept"
awk -v gr="$g_r" -v gg="$g_g" -v gb="$g_b" -v cr="$c_r" -v cg="$c_g" -v cb="$c_b" -v rel="$ref_rel" 'BEGIN {
    printf "| | R mean | G mean | B mean |\n|---|---|---|---|\n"
    printf "| glint | %.5f | %.5f | %.5f |\n| Cycles | %.5f | %.5f | %.5f |\n", gr, gg, gb, cr, cg, cb
    printf "| Cycles / glint - 1 | %+.3f %% | %+.3f %% | %+.3f %% |\n",
        100 * (cr / gr - 1), 100 * (cg / gg - 1), 100 * (cb / gb - 1)
    printf "relative MSE of the Cycles reference against glint'"'"'s: %.6f\n", rel }'

# Timed renders, alternating. Seed 1 for every test image: repeats only re-time the same image.
declare -A wall cpu
for rep in $(seq "$REPS"); do
    for n in $SPP; do
        for who in glint cycles; do
            read -r w c < <("${who}_render" "$OUT/$who-$n.exr" "$n" 1)
            [ -n "$w" ] && [ -n "$c" ] || { echo "cycles_cornell: no time in $OUT/$who-$n.exr.log" >&2; exit 1; }
            wall[$who,$n]=$(awk -v a="${wall[$who,$n]:-$w}" -v b="$w" 'BEGIN { print (b + 0 < a + 0) ? b : a }')
            cpu[$who,$n]=$(awk -v a="${cpu[$who,$n]:-$c}" -v b="$c" 'BEGIN { print (b + 0 < a + 0) ? b : a }')
            echo "  rep $rep: $who $n spp: $w s ($c s of processor time)" >&2
        done
    done
done

echo
echo "Timed renders (minimum of $REPS, alternating glint and Cycles); relative MSE against each reference"
echo "| spp | glint s | glint CPU s | Cycles s | Cycles CPU s | glint relMSE (glint ref) | glint relMSE (Cycles ref) | Cycles relMSE (glint ref) | Cycles relMSE (Cycles ref) | glint eff. | Cycles eff. | glint / Cycles | by CPU s | by Cycles ref |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
rows=""
for n in $SPP; do
    read -r gg _ < <(compare "$OUT/glint-$n.exr" "$OUT/glint-ref.exr")
    read -r gc _ < <(compare "$OUT/glint-$n.exr" "$OUT/cycles-ref.exr")
    read -r cg _ < <(compare "$OUT/cycles-$n.exr" "$OUT/glint-ref.exr")
    read -r cc _ < <(compare "$OUT/cycles-$n.exr" "$OUT/cycles-ref.exr")
    row=$(awk -v n="$n" -v gs="${wall[glint,$n]}" -v cs="${wall[cycles,$n]}" \
        -v gp="${cpu[glint,$n]}" -v cp="${cpu[cycles,$n]}" \
        -v gg="$gg" -v gc="$gc" -v cg="$cg" -v cc="$cc" 'BEGIN {
        ge = 1 / (gg * gs); ce = 1 / (cg * cs)
        printf "| %d | %.2f | %.2f | %.2f | %.2f | %.5f | %.5f | %.5f | %.5f | %.1f | %.1f | %.2f | %.2f | %.2f |\n",
            n, gs, gp, cs, cp, gg, gc, cg, cc, ge, ce, ge / ce, (cg * cp) / (gg * gp),
            (cc * cs) / (gc * gs) }')
    echo "$row"
    rows+="$row"$'\n'
done
printf '%s' "$rows" | awk -F'|' '
    { w += log($13); p += log($14); c += log($15); k++ }
    END { printf "glint / Cycles, geometric mean over the spp: %.2f (wall), %.2f (processor time), %.2f (wall, Cycles reference)\n",
          exp(w / k), exp(p / k), exp(c / k) }'
echo "efficiency = 1 / (relative MSE against glint's reference x wall seconds of the render)"
echo "load after: $(uptime)"
