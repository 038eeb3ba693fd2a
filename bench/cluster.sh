#!/usr/bin/env bash
# MPI on one machine: the single-process render against mpirun with 1, 2 and 4 ranks, for
# the path tracer (sample ranges) and sppm (photons shared every pass), the bytes rank 0
# exchanges, and the speed-up model of docs/cluster.md evaluated for N machines from the
# measured times. Not part of CI. On a 2-core machine expect no speed-up beyond 2 ranks:
# the numbers show the overhead. Settings: BUILD_DIR (build), SCENE
# (examples/cornell-box.lua), RES (128x128), SPP (64), SPPM_PASSES (16), PHOTONS (100000),
# CORES (2), BANDWIDTH (bytes/s of the modelled network, 1.25e8 = 1 Gbit/s).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
SCENE=${SCENE:-examples/cornell-box.lua}
RES=${RES:-128x128}
SPP=${SPP:-64}
SPPM_PASSES=${SPPM_PASSES:-16}
PHOTONS=${PHOTONS:-100000}
CORES=${CORES:-2}
BANDWIDTH=${BANDWIDTH:-1.25e8}
GLINT=$BUILD_DIR/glint
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1}
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}

# run LABEL RANKS ARGS...: prints wall seconds, bytes and collective seconds of rank 0.
run() {
  local label=$1 ranks=$2; shift 2
  local threads=$(( CORES / ranks )); [ "$threads" -ge 1 ] || threads=1
  local start end log=$out/$label.log
  start=$(date +%s.%N)
  if [ "$ranks" = 0 ]; then
    "$GLINT" render "$SCENE" --res "$RES" --threads "$CORES" "$@" -o "$out/$label.exr" 2> "$log"
  else
    mpirun --oversubscribe -np "$ranks" "$GLINT" render "$SCENE" --res "$RES" \
      --threads "$threads" "$@" -o "$out/$label.exr" 2> "$log"
  fi
  end=$(date +%s.%N)
  local bytes=0 seconds=0
  if grep -q "^cluster:" "$log"; then
    bytes=$(sed -n 's/^cluster: .* exchanged \([0-9]*\) bytes in \([0-9.]*\) s.*/\1/p' "$log")
    seconds=$(sed -n 's/^cluster: .* exchanged \([0-9]*\) bytes in \([0-9.]*\) s.*/\2/p' "$log")
  fi
  local wall; wall=$(echo "$end - $start" | bc -l)
  printf "%-14s ranks %-2s threads/rank %-2s wall %7.2f s  rank 0 exchanged %10s bytes in %6.3f s\n" \
    "$label" "${ranks/#0/-}" "$([ "$ranks" = 0 ] && echo "$CORES" || echo "$threads")" "$wall" "$bytes" "$seconds"
  echo "$wall $bytes $seconds" > "$out/$label.numbers"
  if [ "$ranks" != 0 ] && ! cmp -s "$out/$label.exr" "$out/${label%%-*}-single.exr"; then
    echo "  (image differs from the single-process one!)"
  fi
}

echo "== path, $RES, $SPP spp (ranks split each pixel's samples)"
run path-single 0 --integrator path --spp "$SPP" --quiet
for n in 1 2 4; do run "path-$n" "$n" --integrator path --spp "$SPP" --quiet; done
echo "== sppm, $RES, $SPPM_PASSES passes of $PHOTONS photons (ranks share each pass's photons)"
run sppm-single 0 --integrator sppm --spp "$SPPM_PASSES" --photons "$PHOTONS" --quiet
for n in 1 2 4; do run "sppm-$n" "$n" --integrator sppm --spp "$SPPM_PASSES" --photons "$PHOTONS" --quiet; done

read -r t1 _ _ < "$out/path-single.numbers"
read -r _ path_bytes2 _ < "$out/path-2.numbers"
read -r s1 _ _ < "$out/sppm-single.numbers"
read -r _ sppm_bytes2 _ < "$out/sppm-2.numbers"
echo
echo "bytes per image (path, one rank's film to rank 0): $path_bytes2 (2 ranks, as rank 0 received)"
echo "bytes per sppm pass (2 ranks, rank 0 sent + received): $(echo "$sppm_bytes2 / $SPPM_PASSES" | bc)"
echo
echo "Model for N machines of this one's speed, network $BANDWIDTH bytes/s (docs/cluster.md):"
echo "  path: T_N = T_1 / N + (N - 1) * F / B, F = one film ($path_bytes2 bytes)"
echo "  sppm: T_N = T_1 * (c + (1 - c) / N) + passes * (N - 1) * D / B; c = camera share, taken"
echo "        as 0.1 here; D = deposits of a pass ($sppm_bytes2 / passes bytes for 2 ranks)"
printf "%4s %12s %12s\n" N path_s sppm_s
for n in 1 2 4 8 16 32 64; do
  p=$(echo "$t1 / $n + ($n - 1) * $path_bytes2 / $BANDWIDTH" | bc -l)
  q=$(echo "$s1 * (0.1 + 0.9 / $n) + ($n - 1) * $sppm_bytes2 / $BANDWIDTH" | bc -l)
  printf "%4d %12.2f %12.2f\n" "$n" "$p" "$q"
done
