#!/usr/bin/env bash
# Spectral mode (issue 30). Part 1: the cost of spectral mode against RGB on the Cornell box
# (path): samples per second, and relative MSE at equal time, each mode against a long
# reference of its own mode. Part 2: examples/prism.lua's rainbow, time to a relative MSE of
# TARGET over the rainbow's pixels (glint_bench_region_error) against a long light-traced
# reference, for light, bdpt and sppm (relative MSE falls as 1 / time, so the time to TARGET
# is seconds x relMSE / TARGET). path finds no rainbow at all: the beam comes from a spot
# light (a point) through glass, which no camera path can reach.
# Environment: BUILD_DIR (build), THREADS (2), CORNELL_RES (96), CORNELL_SPP (32),
# CORNELL_REF_SPP (512), PRISM_RES (160x120), REGION (x0 y0 x1 y1 of the rainbow at 160x120:
# 28 48 98 70), PRISM_REF_SPP (256), TARGET (0.02).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR=${BUILD_DIR:-build}
THREADS=${THREADS:-2}
CORNELL_RES=${CORNELL_RES:-96}
CORNELL_SPP=${CORNELL_SPP:-32}
CORNELL_REF_SPP=${CORNELL_REF_SPP:-512}
PRISM_RES=${PRISM_RES:-160x120}
REGION=${REGION:-28 48 98 70}
PRISM_REF_SPP=${PRISM_REF_SPP:-256}
TARGET=${TARGET:-0.02}
ninja -C "$BUILD_DIR" glint_cli glint_bench_region_error >/dev/null
glint=$BUILD_DIR/glint
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

seconds_of() {
  local start end
  start=$(date +%s.%N)
  "$@" -q --threads "$THREADS"
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
full_relmse() { "$glint" compare "$1" "$2" | awk '/relative MSE/ {print $3}'; }

echo "== Cornell box, path, ${CORNELL_RES}x${CORNELL_RES}, $THREADS threads"
echo "| mode | spp | seconds | samples/s | relMSE | relMSE x seconds |"
echo "|---|---|---|---|---|---|"
cornell=examples/cornell-box.lua
for mode in rgb spectral; do
  flag=""
  [ "$mode" = spectral ] && flag=--spectral
  seconds_of "$glint" render $cornell $flag --res "${CORNELL_RES}x${CORNELL_RES}" --spp "$CORNELL_REF_SPP" --seed 99 -o "$work/ref-$mode.exr" >/dev/null
  s=$(seconds_of "$glint" render $cornell $flag --res "${CORNELL_RES}x${CORNELL_RES}" --spp "$CORNELL_SPP" --seed 1 -o "$work/$mode.exr")
  e=$(full_relmse "$work/$mode.exr" "$work/ref-$mode.exr")
  rate=$(echo "$CORNELL_RES * $CORNELL_RES * $CORNELL_SPP / $s" | bc -l)
  printf '| %s | %s | %.2f | %.0f | %.5f | %.5f |\n' "$mode" "$CORNELL_SPP" "$s" "$rate" "$e" "$(echo "$e * $s" | bc -l)"
done

echo
echo "== examples/prism.lua (spectral), $PRISM_RES, $THREADS threads, rainbow pixels [$REGION)"
prism=examples/prism.lua
ref_s=$(seconds_of "$glint" render $prism --integrator light --res "$PRISM_RES" --spp "$PRISM_REF_SPP" --seed 99 -o "$work/prism-ref.exr")
printf 'reference: light, %s spp, %.1f s\n' "$PRISM_REF_SPP" "$ref_s"
echo "| integrator | spp | seconds | relMSE (rainbow) | seconds to relMSE $TARGET |"
echo "|---|---|---|---|---|"
for run in "light 8" "bdpt 8" "sppm 16"; do
  set -- $run
  extra=""
  true
  s=$(seconds_of "$glint" render $prism --integrator "$1" --res "$PRISM_RES" --spp "$2" --seed 1 $extra -o "$work/prism-$1.exr")
  # shellcheck disable=SC2086
  e=$("$BUILD_DIR/bench/glint_bench_region_error" "$work/prism-$1.exr" "$work/prism-ref.exr" $REGION)
  printf '| %s | %s | %.2f | %.5f | %.3f |\n' "$1" "$2" "$s" "$e" "$(echo "$s * $e / $TARGET" | bc -l)"
done
