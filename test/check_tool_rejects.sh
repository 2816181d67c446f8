#!/usr/bin/env bash
# The command-line tool on bad input: a non-zero exit, exactly one line on stderr that starts
# with "error:" and names the problem, and no output file, not even a partial one.
#   check_tool_rejects.sh TOOL BAD_INPUT_DIR DATA_DIR WORK_DIR
set -u
tool=$1 bad=$2 data=$3 work=$4
mkdir -p "$work"
failures=0

# expect REASON ARGUMENTS...
expect() {
  local reason=$1
  shift
  rm -f "$work"/* "$work"/.[!.]*
  "$tool" "$@" > "$work/stdout.txt" 2> "$work/stderr.txt"
  local status=$? lines
  lines=$(wc -l < "$work/stderr.txt")
  if [ "$status" -eq 0 ] || [ "$lines" -ne 1 ] || ! grep -q "^error: .*$reason" "$work/stderr.txt" ||
     [ -n "$(find "$work" -name '*faired*')" ]; then
    echo "FAILED: $*: exit $status, $lines lines: $(cat "$work/stderr.txt")"
    failures=$((failures + 1))
  else
    echo "ok: $*: $(cat "$work/stderr.txt")"
  fi
}

out=$work/faired.off
expect "cannot read .*no_such_mesh.off" --eps 0.1 "$bad/no_such_mesh.off" "$out"
expect "the mesh is empty; nothing written" --eps 0.1 "$bad/empty.off" "$out"
expect "the mesh is empty" --eps 0.1 "$bad/not_a_mesh.stl" "$out"
expect "the point set has 3 points, not more than its 32 neighbours" --eps 0.1 "$bad/points_only.off" "$out"
expect "a point set needs --eps as a distance" --eps 0.25h "$bad/points_only.off" "$out"
expect "edge between vertices 0 and 1 has 3 faces" --eps 0.1 "$bad/non_manifold_edge.off" "$out"
expect "faces [0-9]* and [0-9]* are oriented inconsistently: both run from vertex" --eps 0.1 "$bad/inconsistent_orientation.off" "$out"
expect "vertex [0-9]* is non-manifold: its faces form more than one fan" --eps 0.1 "$bad/non_manifold_vertex.off" "$out"
expect "vertex 3 has a NaN or infinite coordinate" --eps 0.1 "$bad/nan.ply" "$out"
expect "face_index_out_of_range.ply: face 1 refers to vertex 1852400130, but there are 4 vertices" --eps 0.1 "$bad/face_index_out_of_range.ply" "$out"
expect "all triangles of the mesh have zero area" --eps 0.1 "$bad/zero_area.off" "$out"
expect "unknown option --bogus" --bogus "$data/head.off" "$out"
expect "box-extents must be three non-negative numbers" --box-extents 1,2 "$data/head.off" "$out"
expect "box-extents must be three non-negative numbers" --box-extents 1,-2,1 "$data/head.off" "$out"
expect "feature-angle must be a number of degrees (got sharp)" --feature-angle sharp "$data/head.off" "$out"
expect "feature_angle must be a number of degrees strictly between 0 and 180 (180" --feature-angle 180 "$data/head.off" "$out"
expect "feature_angle must be a number of degrees strictly between 0 and 180 (-5" --feature-angle -5 "$data/head.off" "$out"
expect "box-extents needs a value" "$data/head.off" "$out" --box-extents
expect "needs a PLY input" --radius-from-property accuracy "$data/head.off" "$out"
expect "nan.ply has no float or double vertex property accuracy" --radius-from-property accuracy "$bad/nan.ply" "$out"
expect "too many arguments" "$data/head.off" "$out" extra
expect "no input mesh" --eps 0.1
expect "cannot estimate the noise level" --eps auto "$bad/zero_area.off" "$out"
expect "eps needs a value" "$data/head.off" "$out" --eps
for eps in 0 -1 nan inf 0.1x abc; do
  expect "epsilon\|--eps" --eps "$eps" "$data/head.off" "$out"
done
expect "OUT must end with" --eps 0.1 "$data/head.off" "$work/faired.txt"
expect "cannot write" --eps 0.1 "$data/head.off" "$work/no_such_dir/faired.off"

# An output that is the input is refused, through another path too, and the input left as it
# was; --in-place lets the result replace it.
in_copy=$work/faired_input.off
for out in "$in_copy" "$work/./faired_input.off"; do
  rm -f "$work"/*
  cp "$data/head.off" "$in_copy"
  if "$tool" --eps 0.1 "$in_copy" "$out" 2> "$work/stderr.txt" || ! grep -q "^error: OUT is IN" "$work/stderr.txt" ||
     ! cmp -s "$data/head.off" "$in_copy"; then
    echo "FAILED: OUT $out is IN: $(cat "$work/stderr.txt")"
    failures=$((failures + 1))
  else
    echo "ok: OUT $out is IN: $(cat "$work/stderr.txt")"
  fi
done
if ! "$tool" --in-place --eps 0.1 "$in_copy" "$in_copy" > /dev/null 2>&1 || cmp -s "$data/head.off" "$in_copy"; then
  echo "FAILED: --in-place did not replace the input"
  failures=$((failures + 1))
else
  echo "ok: --in-place replaced the input"
fi

exit $((failures > 0))
