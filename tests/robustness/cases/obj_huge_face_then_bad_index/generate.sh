#!/usr/bin/env bash
# A 200 000-corner polygon (a circle) and a bad face after it.
awk 'BEGIN { n = 200000; for (i = 0; i < n; i++) printf "v %.6f %.6f 0\n", cos(6.283185307 * i / n), sin(6.283185307 * i / n);
  printf "f"; for (i = 1; i <= n; i++) printf " %d", i; printf "\nf 1 2 300000\n" }' > mesh.obj
