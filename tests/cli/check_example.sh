#!/usr/bin/env bash
# Renders one example small and checks its image, not only the exit status: every value
# finite, the image not black, and its mean per channel within 15 % (relative, or 1e-3
# absolute for a channel near zero) of the value recorded in example_means.txt.
# Usage: check_example.sh GLINT NAME OUTPUT.exr RENDER-ARGUMENTS...
# With RECORD=1 it prints the line to record instead of checking.
set -u
glint=$1
name=$2
output=$3
shift 3
tolerance=0.15
means_file="$(dirname "$0")/example_means.txt"

"$glint" render "$@" --res 16x16 --spp 4 --quiet -o "$output" || exit 1
report=$("$glint" compare "$output" "$output" 2>&1) || { echo "$report"; exit 1; }
if grep -q "NaN or infinite" <<< "$report"; then
    echo "FAIL $name: the image holds values that are not finite"
    exit 1
fi
mean=$(sed -n 's/^test mean: *(\(.*\))$/\1/p' <<< "$report" | tr -d ',')
[ -n "$mean" ] || { echo "FAIL $name: no mean in: $report"; exit 1; }
if [ "${RECORD:-0}" = 1 ]; then
    echo "$name $mean"
    exit 0
fi
recorded=$(awk -v n="$name" '$1 == n { print $2, $3, $4 }' "$means_file")
[ -n "$recorded" ] || { echo "FAIL $name: no recorded mean in $means_file (mean $mean)"; exit 1; }
awk -v got="$mean" -v want="$recorded" -v tol="$tolerance" -v name="$name" 'BEGIN {
    split(got, g, " "); split(want, w, " ");
    black = 1; bad = 0;
    for (c = 1; c <= 3; ++c) {
        if (g[c] > 1e-6) black = 0;
        d = g[c] - w[c]; if (d < 0) d = -d;
        allowed = tol * (w[c] < 0 ? -w[c] : w[c]); if (allowed < 1e-3) allowed = 1e-3;
        if (d > allowed) { printf "FAIL %s: channel %d mean %g, recorded %g (tolerance %g)\n", name, c - 1, g[c], w[c], allowed; bad = 1 }
    }
    if (black) { printf "FAIL %s: the image is black\n", name; bad = 1 }
    if (!bad) printf "ok %s: mean %s (recorded %s)\n", name, got, want;
    exit bad
}'
