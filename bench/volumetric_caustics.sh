#!/usr/bin/env bash
# Volumetric caustics (issue 29): time to a relative MSE of TARGET over the beam that the
# glass sphere of examples/volumetric-caustics.lua focuses into the fog, for volpath and for
# the light tracer, bdpt and vcm. Each renders at its own sample count; relative MSE over the beam's
# pixels (glint_bench_region_error) is taken against a long light-traced reference, and,
# since relative MSE falls as 1 / time, the time to TARGET is seconds x relMSE / TARGET.
# The beam's pixels see fog and floor only (no glass, no lamp), which both integrators
# render: their converged images agree there (LightTracerMedia.ConvergesToVolpathInAFogBox).
# Environment: BUILD_DIR (build), THREADS (2), RES (192), REGION (x0 y0 x1 y1 of the beam at
# 192x192: 72 112 120 150), VOLPATH_SPP (64), LIGHT_SPP (4), BDPT_SPP (4), VCM_SPP (4),
# REF_SPP (256),
# TARGET (0.05).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
THREADS=${THREADS:-2}
RES=${RES:-192}
REGION=${REGION:-72 112 120 150}
VOLPATH_SPP=${VOLPATH_SPP:-64}
LIGHT_SPP=${LIGHT_SPP:-4}
BDPT_SPP=${BDPT_SPP:-4}
VCM_SPP=${VCM_SPP:-4}
REF_SPP=${REF_SPP:-256}
TARGET=${TARGET:-0.05}
ninja -C "$BUILD_DIR" glint_cli glint_bench_region_error >/dev/null
glint=$BUILD_DIR/glint
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene=examples/volumetric-caustics.lua

seconds_of() {
  local start end
  start=$(date +%s.%N)
  "$@" -q --threads "$THREADS" --res "${RES}x${RES}"
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
region_relmse() {
  # shellcheck disable=SC2086
  "$BUILD_DIR/bench/glint_bench_region_error" "$1" "$2" $REGION
}

echo "== $scene at ${RES}x${RES}, $THREADS threads, beam pixels [$REGION)"
ref_s=$(seconds_of "$glint" render "$scene" --integrator light --spp "$REF_SPP" --seed 99 -o "$work/ref.exr")
printf 'reference: light, %s spp, %.1f s\n' "$REF_SPP" "$ref_s"
echo "| integrator | spp | seconds | relMSE (beam) | seconds to relMSE $TARGET |"
echo "|---|---|---|---|---|"
for run in "volpath $VOLPATH_SPP" "light $LIGHT_SPP" "bdpt $BDPT_SPP" "vcm $VCM_SPP"; do
  set -- $run
  s=$(seconds_of "$glint" render "$scene" --integrator "$1" --spp "$2" --seed 1 -o "$work/$1.exr")
  e=$(region_relmse "$work/$1.exr" "$work/ref.exr")
  printf '| %s | %s | %.2f | %.4f | %.1f |\n' "$1" "$2" "$s" "$e" "$(echo "$s * $e / $TARGET" | bc -l)"
done
