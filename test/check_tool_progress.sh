#!/usr/bin/env bash
# The command-line tool's output when stderr is not a terminal: plain progress lines on stderr,
# "iteration N, energy E, decrease D/it (threshold H), T s" every 100 iterations with N
# increasing and E decreasing (D the stopping rule's measure over its window of 50, full by then,
# H the default threshold), and the one-line report on stdout.
#   check_tool_progress.sh TOOL IN WORK_DIR
set -u
tool=$1 in=$2 work=$3
mkdir -p "$work"
"$tool" "$in" "$work/faired.off" > "$work/stdout.txt" 2> "$work/stderr.txt" || { echo "FAILED: exit $?"; exit 1; }
cat "$work/stderr.txt" "$work/stdout.txt"
awk '
  !/^iteration [1-9][0-9]*00, energy [0-9.e+-]+, decrease [0-9.e+-]+\/it \(threshold 0\.000125\), [0-9]+\.[0-9] s$/ { print "FAILED: not a progress line: " $0; bad = 1 }
  { n = $2 + 0; e = $4 + 0 }
  NR > 1 && (n <= last_n || e > last_e) { print "FAILED: not increasing iterations, decreasing energy: " $0; bad = 1 }
  { last_n = n; last_e = e }
  END { if (NR == 0) { print "FAILED: no progress line"; bad = 1 } exit bad }' "$work/stderr.txt" || exit 1
if [ "$(wc -l < "$work/stdout.txt")" -ne 1 ] || ! grep -q " -> .*iterations (converged).*s$" "$work/stdout.txt"; then
  echo "FAILED: the report is not one line"
  exit 1
fi
echo "ok"
