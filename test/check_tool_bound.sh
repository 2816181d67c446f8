#!/usr/bin/env bash
# The command-line tool's output file read back against its input: the same faces, vertices
# moved, and each vertex within its bound, in double arithmetic with no tolerance, as the
# library promises.
#   check_tool_bound.sh TOOL IN OUT BOUND [OPTIONS...]
# BOUND is box:HX,HY,HZ (each coordinate within that of its input value), ball:EPS, or
# auto:PROGRAM: the ball of the noise level that the tool estimated, which must be the one
# that PROGRAM (an example) prints for IN as "estimated noise level: X". IN and OUT are OFF.
set -u
tool=$1 in=$2 out=$3 bound=$4
shift 4
report=$("$tool" "$@" "$in" "$out" 2> /dev/null) || { echo "FAILED: exit $?"; exit 1; }
echo "$report"
case $bound in
  box:*) sizes=${bound#box:} ;;
  ball:*) eps=${bound#ball:}; sizes="$eps,$eps,$eps" ;;
  auto:*)
    expected=$("${bound#auto:}" "$in" | sed -n 's/^estimated noise level: //p')
    eps=$(echo "$report" | sed -n 's/.*; eps \([^ ]*\) (auto, .*/\1/p')
    if [ -z "$eps" ] || [ "$eps" != "$expected" ]; then
      echo "FAILED: the tool's estimate '$eps' is not the library's '$expected'"
      exit 1
    fi
    # The report rounds: its largest deviation, rounded, is at most the rounded tolerance.
    echo "$report" | awk -v eps="$eps" '{ if (match($0, /deviation at most [^,]*/)) d = substr($0, RSTART + 18, RLENGTH - 18) }
      END { exit !(d != "" && d + 0 <= eps + 0) }' || { echo "FAILED: deviation above $eps"; exit 1; }
    echo "ok: the estimate $eps is the library's"
    exit 0 ;;
  *) echo "FAILED: unknown bound $bound"; exit 1 ;;
esac
awk -v sizes="$sizes" -v shape="${bound%%:*}" '
  BEGIN { split(sizes, h, ",") }
  FNR == 1 { f++; n = 0 }
  { sub(/#.*/, ""); for (i = 1; i <= NF; i++) t[f, ++n] = $i; count[f] = n }
  END {
    if (t[1, 1] != "OFF" || t[2, 1] != "OFF" || t[1, 2] != t[2, 2] || t[1, 3] != t[2, 3]) {
      print "FAILED: not two OFF files of the same counts"; exit 1 }
    nv = t[1, 2]
    for (k = 5 + 3 * nv; k <= count[1]; k++)
      if (t[1, k] != t[2, k]) { print "FAILED: the faces differ"; exit 1 }
    moved = 0
    for (v = 0; v < nv; v++) {
      d2 = 0
      for (a = 1; a <= 3; a++) {
        d = t[2, 4 + 3 * v + a] - t[1, 4 + 3 * v + a]
        if (d != 0) moved++
        if (shape == "box" && (d > h[a] || -d > h[a])) { print "FAILED: vertex " v " leaves its box"; exit 1 }
        d2 += d * d
      }
      if (shape == "ball" && d2 > h[1] * h[1]) { print "FAILED: vertex " v " leaves its ball"; exit 1 }
    }
    if (moved == 0) { print "FAILED: no vertex moved"; exit 1 }
    print "ok: " nv " vertices, each within its " shape
  }' "$in" "$out"
