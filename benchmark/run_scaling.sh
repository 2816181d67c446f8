#!/bin/sh
# Runs fairing_scaling over mesh sizes, one process each, and fits the growth of the time with
# the number of triangles between the smallest and the largest size.
#
#   run_scaling.sh BUILD_DIR [LEVELS] [MESH]     (LEVELS default "0 1 2"; 3 gives 4.8 M triangles)
set -eu
program="$1/benchmark/fairing_scaling"
levels="${2:-0 1 2}"
mesh="${3:-}"
rows=$(mktemp)
output=$(mktemp)
for level in $levels; do
  $program $mesh --level "$level" > "$output"
  cat "$output"
  echo
  sed -n 's/^row: //p' "$output" >> "$rows"
done
echo "triangles  seconds  bytes/triangle  iterations  smooth_shape_s  cholmod_factor_s  with_rounding_math_s  without_rounding_math_s"
cat "$rows"
awk 'NR == 1 {t0 = $1; s0 = $2} {t1 = $1; s1 = $2}
     END {if (NR > 1) printf "time grows as n^%.2f from %d to %d triangles\n", log(s1 / s0) / log(t1 / t0), t0, t1}' "$rows"
rm -f "$rows" "$output"
