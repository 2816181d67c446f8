#!/usr/bin/env python3
"""The client's part of a tiled fairing, the cut into tiles, against its direct definitions.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/tile_cut.py [--build build]
        [--levels 3 4] [--tiles 12 48] [--runs 3]

For each level L, ``benchmark/fairing_call --write-case`` writes the bundled bunny Loop
subdivided L times with seeded noise (binary PLY), read through a memory map as `fair_tiled`
reads it. Timed for T tiles: the k-d cut (`kd_tiles`: quantiles of a sample of at most 2 M
points, the points then put in their cells a block at a time) against the same cut on the
quantiles of all the points (copies of every cell's points), and the search for each tile's candidate faces
(`candidate_faces`: a block's corners bucketed by a grid, each box testing the faces of its
cells) against the test of every face against every box; printed: both times (medians), their
ratio, the nanoseconds per face and tile, the cells' counts against the exact cut's, and
whether the candidate faces are the same. The CPU model is printed with the figures; all runs
are single-threaded numpy.
"""

import argparse
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

from benchmark_machine import cpu_model, median_seconds
from cgal_constrained_fairing.tiles import _partition, _ply_map


def exact_kd_tiles(points, count):
    """The same cut with the quantiles of every point (a copy of each cell's points)."""
    sample = _partition.CUT_SAMPLE
    _partition.CUT_SAMPLE = len(points)
    try:
        return _partition.kd_tiles(points, count).tile
    finally:
        _partition.CUT_SAMPLE = sample


def every_box(corners, points, boxes):
    """Each box's faces with a corner in it, every face tested against every box."""
    found = [[] for _ in boxes]
    for begin in range(0, len(corners), _partition.BLOCK_ROWS):
        block = np.asarray(corners[begin:begin + _partition.BLOCK_ROWS], np.int64)
        p = points[block.ravel()].reshape(-1, 3, 3)
        for t, box in enumerate(boxes):
            inside = ((p >= box[0]) & (p <= box[1])).all(axis=2).any(axis=1)
            found[t].append(begin + np.flatnonzero(inside))
    return [np.concatenate(f) for f in found]


def measure(build, level, counts, runs, folder):
    path = folder / f"noisy_{level}.ply"
    subprocess.run([str(build / "benchmark" / "fairing_call"), "--write-case", str(path),
                    "--level", str(level)], check=True)
    mapped = _ply_map.map_ply(path)
    records = mapped.vertices()
    points = np.stack([records[name] for name in "xyz"], axis=1).astype(np.float64)
    corners = np.ascontiguousarray(mapped.faces()["corners"])
    sample = np.asarray(corners[::max(1, len(corners) // 100000)], np.int64)
    edge = np.linalg.norm(points[sample] - points[np.roll(sample, 1, axis=1)], axis=2).mean()
    print(f"level {level}: {len(points)} vertices, {len(corners)} triangles; medians of {runs} runs")
    for count in counts:
        t_kd, tiles = median_seconds(lambda: _partition.kd_tiles(points, count), runs)
        t_exact, exact = median_seconds(lambda: exact_kd_tiles(points, count), runs)
        sizes, exact_sizes = (np.bincount(t, minlength=count) for t in (tiles.tile, exact))
        print(f"  {count} tiles: k-d cut {t_kd:.2f} s, on all the points {t_exact:.2f} s "
              f"(ratio {t_exact / t_kd:.2f}); cells of {sizes.min()} to {sizes.max()} vertices "
              f"(all points' quantiles {exact_sizes.min()} to {exact_sizes.max()})")
        # fair_tiled's margin: 1.5 edge lengths for each of the 18 ghost rings and one more.
        boxes = np.array([_partition.grown(box, 28.5 * edge) for box in tiles.boxes])
        t_grid, found = median_seconds(
            lambda: _partition.candidate_faces(corners, points, boxes), runs)
        t_every, direct = median_seconds(lambda: every_box(corners, points, boxes), runs)
        per = 1e9 / (len(corners) * count)
        print(f"    candidate faces: bucketed {t_grid:.2f} s ({t_grid * per:.1f} ns per face "
              f"and tile), every box {t_every:.2f} s ({t_every * per:.1f} ns; ratio "
              f"{t_every / t_grid:.2f}); the same faces: "
              f"{all(np.array_equal(a, b) for a, b in zip(found, direct))}")
        sys.stdout.flush()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", type=Path, default=Path("build"))
    parser.add_argument("--levels", type=int, nargs="+", default=[3, 4])
    parser.add_argument("--tiles", type=int, nargs="+", default=[12, 48])
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    if not (args.build / "benchmark" / "fairing_call").exists():
        print(f"skipped: {args.build}/benchmark/fairing_call is not built")
        return 0
    print(f"{cpu_model()}, {os.cpu_count()} CPUs; single-threaded numpy")
    with tempfile.TemporaryDirectory() as folder:
        for level in args.levels:
            measure(args.build, level, args.tiles, args.runs, Path(folder))
    return 0


if __name__ == "__main__":
    sys.exit(main())
