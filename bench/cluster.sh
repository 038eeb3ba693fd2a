#!/usr/bin/env bash
# MPI on one machine: the single-process render against mpirun with 1, 2 and 4 ranks, for
# the path tracer (sample ranges), sppm (photons shared every pass) and vcm (light subpaths
# shared every iteration), the bytes rank 0
# exchanges, and the speed-up model of docs/cluster.md evaluated for N machines from the
# measured times. Not part of CI. On a 2-core machine expect no speed-up beyond 2 ranks:
# the numbers show the overhead. Settings: BUILD_DIR (build), SCENE
# (examples/cornell-box.lua), RES (128x128), SPP (64), SPPM_PASSES (16), PHOTONS (100000),
# VCM_ITERATIONS (8),
# CORES (2), BANDWIDTH (bytes/s of the modelled network, 1.25e8 = 1 Gbit/s).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
SCENE=${SCENE:-examples/cornell-box.lua}
RES=${RES:-128x128}
SPP=${SPP:-64}
SPPM_PASSES=${SPPM_PASSES:-16}
VCM_ITERATIONS=${VCM_ITERATIONS:-8}
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
  local threads=$CORES
  if [ "$ranks" != 0 ]; then threads=$(( CORES / ranks )); [ "$threads" -ge 1 ] || threads=1; fi
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
  if grep -q "cluster: " "$log"; then
    bytes=$(sed -n 's/.*cluster: .* exchanged \([0-9]*\) bytes in \([0-9.]*\) s.*/\1/p' "$log")
    seconds=$(sed -n 's/.*cluster: .* exchanged \([0-9]*\) bytes in \([0-9.]*\) s.*/\2/p' "$log")
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
run path-single 0 --integrator path --spp "$SPP"
for n in 1 2 4; do run "path-$n" "$n" --integrator path --spp "$SPP"; done
echo "== sppm, $RES, $SPPM_PASSES passes of $PHOTONS photons (ranks share each pass's photons)"
run sppm-single 0 --integrator sppm --spp "$SPPM_PASSES" --photons "$PHOTONS"
for n in 1 2 4; do run "sppm-$n" "$n" --integrator sppm --spp "$SPPM_PASSES" --photons "$PHOTONS"; done

echo "== vcm, $RES, $VCM_ITERATIONS iterations (ranks share each iteration's light subpaths)"
run vcm-single 0 --integrator vcm --spp "$VCM_ITERATIONS"
for n in 1 2 4; do run "vcm-$n" "$n" --integrator vcm --spp "$VCM_ITERATIONS"; done

read -r t1 _ _ < "$out/path-single.numbers"
read -r _ film_bytes _ < "$out/path-2.numbers"
read -r s1 _ _ < "$out/sppm-single.numbers"
read -r _ sppm_bytes _ < "$out/sppm-2.numbers"
echo
echo "bytes per image (path): $film_bytes (rank 0 of 2: one film received, plus statuses)"
echo "bytes per sppm pass: $(awk -v b="$sppm_bytes" -v p="$SPPM_PASSES" 'BEGIN { printf "%d", b / p }')" \
     "(rank 0 of 2: its deposits sent, the other's received: all of a pass's deposits)"
echo
echo "Model for N machines like this one (docs/cluster.md), network $BANDWIDTH bytes/s:"
echo "  path: T_N = T_1 / N + (N - 1) F / B              F = one film"
echo "  sppm: T_N = T_1 (c + (1 - c) / N) + (N - 1) / N D / B   D = all passes' deposits,"
echo "        c = the camera pass's share of T_1 (repeated on every rank), taken as 0.1"
awk -v t1="$t1" -v s1="$s1" -v f="$film_bytes" -v d="$sppm_bytes" -v bw="$BANDWIDTH" 'BEGIN {
  printf "%4s %10s %10s %10s %10s\n", "N", "path_s", "speed-up", "sppm_s", "speed-up"
  split("1 2 4 8 16 32 64 128", ns, " ")
  for (i = 1; i <= 8; ++i) {
    n = ns[i]
    p = t1 / n + (n - 1) * f / bw
    q = s1 * (0.1 + 0.9 / n) + (n - 1) / n * d / bw
    printf "%4d %10.3f %10.2f %10.3f %10.2f\n", n, p, t1 / p, q, s1 / q
  }
}'
