#!/usr/bin/env bash
# The example program on bad input: a non-zero exit, exactly one line on stderr that starts
# with "error:" and names the problem, and no output file, not even a partial one.
#   check_example_rejects.sh EXAMPLE BAD_INPUT_DIR DATA_DIR WORK_DIR
set -u
example=$1 bad=$2 data=$3 work=$4
mkdir -p "$work"
failures=0

# expect REASON IN EPS OUT, or expect REASON ARGUMENTS... (with options)
expect() {
  local reason=$1
  shift
  rm -f "$work"/* "$work"/.[!.]*
  "$example" "$@" > "$work/stdout.txt" 2> "$work/stderr.txt"
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
expect "cannot read .*no_such_mesh.off" "$bad/no_such_mesh.off" 0.1 "$out"
expect "the mesh is empty" "$bad/empty.off" 0.1 "$out"
expect "the mesh is empty" "$bad/not_a_mesh.stl" 0.1 "$out"
expect "the mesh has no faces" "$bad/points_only.off" 0.1 "$out"
expect "face 0 has 4 vertices" "$bad/quad.off" 0.1 "$out"
expect "edge between vertices 0 and 1 has 3 faces" "$bad/non_manifold_edge.off" 0.1 "$out"
expect "inconsistent orientation" "$bad/inconsistent_orientation.off" 0.1 "$out"
expect "non-manifold vertex" "$bad/non_manifold_vertex.off" 0.1 "$out"
expect "vertex 3 has a NaN or infinite coordinate" "$bad/nan.ply" 0.1 "$out"
expect "face 1 of .* refers to vertex 1852400130, but there are 4 vertices" "$bad/face_index_out_of_range.ply" 0.1 "$out"
expect "all triangles of the mesh have zero area" "$bad/zero_area.off" 0.1 "$out"
expect "unknown option --bogus" --bogus "$data/head.off" 0.1 "$out"
expect "box-extents must be three non-negative numbers" --box-extents 1,2 "$data/head.off" "$out"
expect "box-extents must be three non-negative numbers" --box-extents 1,-2,1 "$data/head.off" "$out"
expect "box-extents needs a value" "$data/head.off" "$out" --box-extents
expect "needs a PLY input" --radius-from-property accuracy "$data/head.off" "$out"
expect "too many arguments" "$data/head.off" 0.1 "$out" extra
expect "cannot estimate the noise level" "$bad/zero_area.off" auto "$out"
for eps in 0 -1 nan inf 0.1x abc; do
  expect "epsilon\|EPS" "$data/head.off" "$eps" "$out"
done
expect "OUT must end with" "$data/head.off" 0.1 "$work/faired.txt"
expect "cannot write" "$data/head.off" 0.1 "$work/no_such_dir/faired.off"

exit $((failures > 0))
