#!/bin/sh
# Checks that the package's functions in a program built with CGAL's flags hold no x87
# instruction. Under -frounding-math (which CGAL::CGAL adds for GCC) GCC leaves the conversion of
# an inexact long double constant, such as libstdc++'s denorm_min(), to run time, as x87 code;
# in a per-vertex loop that code made the whole call twice as slow on some CPUs. A program in
# which no function of the package is found fails too, so that the check cannot pass unread.
#
#   check_no_x87.sh OBJDUMP PROGRAM
set -eu
listing=$(mktemp)
trap 'rm -f "$listing"' EXIT
"$1" -d --no-show-raw-insn "$2" > "$listing"
checked=$(grep -c '^[0-9a-f]* <.*19Constrained_fairing' "$listing" || true)
if [ "$checked" -eq 0 ]; then
  echo "no function of the package found in $2"
  exit 1
fi
found=$(awk -F '\t' '
  /^[0-9a-f]+ </ { name = $0; package = index(name, "19Constrained_fairing") > 0 }
  package && $2 ~ /^f[a-z]+/ { print name; package = 0 }' "$listing")
if [ -n "$found" ]; then
  echo "x87 code in the package's functions of $2:"
  echo "$found" | c++filt | cut -c1-300
  exit 1
fi
echo "no x87 code in the $checked functions of the package in $2"
