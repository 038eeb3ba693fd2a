#!/usr/bin/env bash
# Light sampling benchmark (issue 31). Prints:
#  1. Cornell box (examples/cornell-box.lua) at 256x256, THREADS threads: seconds, relative
#     MSE against a REF_SPP reference and efficiency 1 / (relMSE x seconds), for this build
#     and for BEFORE (a glint binary built from the commit to compare with, e.g. main), at
#     SPP samples per pixel;
#  2. examples/many-lights.lua at 160x120: relative MSE and seconds of the light tree (this
#     build, and BEFORE's) and of power sampling, and the render time each needs for relative
#     MSE TARGET (relMSE falls as 1 / samples: render seconds x relMSE / TARGET);
#  3. the light tree's build time and memory for 10^6 emissive triangles.
# Environment: BUILD_DIR (build), BEFORE (unset: section 1 for this build only), THREADS (2),
# SPP (64), REF_SPP (1024), ML_SPP (48: the tree then has about the target error),
# ML_POWER_SPP (640: likewise for power), ML_REF_SPP (4096), TARGET (0.02), TRIANGLES (1000000).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
THREADS=${THREADS:-2}
SPP=${SPP:-64}
REF_SPP=${REF_SPP:-1024}
ML_SPP=${ML_SPP:-48}
ML_POWER_SPP=${ML_POWER_SPP:-640}
ML_REF_SPP=${ML_REF_SPP:-4096}
TARGET=${TARGET:-0.02}
TRIANGLES=${TRIANGLES:-1000000}
ninja -C "$BUILD_DIR" glint_cli glint_bench_light_tree_build >/dev/null
glint=$BUILD_DIR/glint
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Seconds of wall time of a render (the CLI's own timing is processor time).
timed_render() {
  local start end
  start=$(date +%s.%N)
  "$@" -q --threads "$THREADS"
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
relmse() { "$glint" compare "$1" "$2" | awk '/relative MSE/ {print $3}'; }

echo "== Cornell box 256x256, $THREADS threads, $SPP spp (reference: $REF_SPP spp, this build)"
"$glint" render examples/cornell-box.lua --res 256x256 --spp "$REF_SPP" --seed 99 -q \
  --threads "$THREADS" -o "$work/ref.exr"
echo "| build | seconds | relMSE | efficiency 1/(relMSE s) |"
echo "|---|---|---|---|"
for build in after ${BEFORE:+before}; do
  binary=$glint
  [ "$build" = before ] && binary=$BEFORE
  s=$(timed_render "$binary" render examples/cornell-box.lua --res 256x256 --spp "$SPP" --seed 1 \
      -o "$work/$build.exr")
  e=$(relmse "$work/$build.exr" "$work/ref.exr")
  printf '| %s | %.2f | %.5f | %.1f |\n' "$build" "$s" "$e" "$(echo "1 / ($e * $s)" | bc -l)"
done

echo "== many-lights 160x120, $THREADS threads (reference: tree, $ML_REF_SPP spp)"
for sampler in tree power; do
  sed "s/integrator = \"path\",/integrator = \"path\", light_sampler = \"$sampler\",/" \
    examples/many-lights.lua > "$work/ml-$sampler.lua"
done
"$glint" render "$work/ml-tree.lua" --res 160x120 --spp "$ML_REF_SPP" --seed 99 -q \
  --threads "$THREADS" -o "$work/ml-ref.exr"
# The render's own time: the wall time less the start-up (scene load, BVH and tree builds),
# measured as the wall time of a 1-spp render of 8x6 pixels; the start-up is the same for
# both samplers and does not shrink with the error.
echo "| glint | light_sampler | spp | wall s | start-up s | relMSE | render s to relMSE $TARGET |"
echo "|---|---|---|---|---|---|---|"
for run in "after tree $ML_SPP" ${BEFORE:+"before tree $ML_SPP"} "after power $ML_POWER_SPP"; do
  read -r build sampler spp <<< "$run"
  binary=$glint
  [ "$build" = before ] && binary=$BEFORE
  startup=$(timed_render "$binary" render "$work/ml-$sampler.lua" --res 8x6 --spp 1 -o "$work/st.exr")
  s=$(timed_render "$binary" render "$work/ml-$sampler.lua" --res 160x120 --spp "$spp" --seed 1 \
      -o "$work/ml-$sampler.exr")
  e=$(relmse "$work/ml-$sampler.exr" "$work/ml-ref.exr")
  printf '| %s | %s | %s | %.3f | %.3f | %.4f | %.3f |\n' "$build" "$sampler" "$spp" "$s" "$startup" \
    "$e" "$(echo "($s - $startup) * $e / $TARGET" | bc -l)"
done

echo "== light tree build"
/usr/bin/time -f "peak resident memory %M KB" "$BUILD_DIR/bench/glint_bench_light_tree_build" "$TRIANGLES"
