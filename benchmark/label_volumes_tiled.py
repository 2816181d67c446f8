#!/usr/bin/env python3
"""A label volume's surfaces by chunks on Dask (`label_surfaces_tiled`) against the in-core call.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/label_volumes_tiled.py [--size 256]
        [--cells 480] [--chunks 64 96] [--workers 2] [--worker-limit 2GiB] [--in-core 1]
        [--folder DIR]

The volume, generated into a zarr array of 64^3 chunks, a slab at a time: touching Voronoi
cells of ``--cells`` random seeds, 12 sheets one voxel thick across it and 20 tubes of radius
1.5 voxels through it (labels 1 to cells + 32, background 0 on the outer voxel layers). Its true
surfaces are known: the Voronoi diagram's bisector planes, the sheets' sides and the tubes'
cylinders; a point's distance to the truth is its distance to the nearest of them (the two
nearest seeds' bisector, every sheet side, every cylinder).

``label_surfaces_tiled`` runs on a LocalCluster of ``--workers`` single-threaded processes, each
limited to ``--worker-limit``, once for each chunk size of ``--chunks`` (``auto``: sized so that
a tile fits 60 % of the limit, where Dask pauses a worker at 80 %); with ``--in-core 1``,
``label_surfaces`` on the whole array in this process (on the cores of the workers) too. Each
label's surface is checked closed and oriented (every directed edge once, its opposite once).
Printed: the nets' points and triangles, the labels and those closed, each run's time by phase,
sweeps and the workers' peak memory; the points' distances to the truth (RMS and 99th
percentile, in voxels); the runs' point differences (RMS, largest, share over 0.1 voxel), each
run's triangles against the in-core call's (the same rows in the same order, per label), and the
in-core call on the volume padded by two more background layers (a problem that differs only in
its size).
One run each; the CPU model and the threads are printed with the figures. Needs python3-scipy
(the seeds' nearest neighbours) besides the package's own.
"""

import argparse
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from benchmark_machine import cores, cpu_model  # noqa: E402

SHEETS, TUBES, TUBE_RADIUS = 12, 20, 1.5


class Truth:
    """The generated volume's surfaces: seeds, sheets (axis, plane) and tubes (point, axis)."""

    def __init__(self, size: int, cells: int, seed: int = 1):
        rng = np.random.default_rng(seed)
        self.size, self.cells = size, cells
        self.seeds = rng.uniform(0, size, (cells, 3))
        self.sheets = [(int(rng.integers(3)), float(rng.integers(4, size - 4))) for _ in range(SHEETS)]
        self.tubes = [(rng.uniform(0, size, 3), _unit(rng.normal(size=3))) for _ in range(TUBES)]
        from scipy.spatial import cKDTree
        self.tree = cKDTree(self.seeds)

    def labels(self, lo: int, hi: int) -> np.ndarray:
        """The labels of the slab of voxels `lo <= i < hi`."""
        n = self.size
        grid = np.stack(np.meshgrid(np.arange(lo, hi), np.arange(n), np.arange(n), indexing="ij"), -1)
        points = grid.reshape(-1, 3).astype(np.float64)
        L = (self.tree.query(points)[1] + 1).astype(np.uint16)
        for s, (axis, plane) in enumerate(self.sheets):
            L[np.abs(points[:, axis] - plane) < 0.5] = self.cells + 1 + s
        for t, (p, u) in enumerate(self.tubes):
            L[_line_distance(points, p, u) <= TUBE_RADIUS] = self.cells + 1 + SHEETS + t
        L = L.reshape(grid.shape[:3])
        border = (grid[..., 0] < 1) | (grid[..., 0] >= n - 1) | (grid[..., 1:] < 1).any(-1) | \
            (grid[..., 1:] >= n - 1).any(-1)
        L[border] = 0
        return L

    def distance(self, points: np.ndarray) -> np.ndarray:
        """Each point's distance to the nearest true surface, in voxels."""
        d2, i = self.tree.query(points, k=2)
        gap = np.linalg.norm(self.seeds[i[:, 0]] - self.seeds[i[:, 1]], axis=1)
        d = np.abs(d2[:, 1] ** 2 - d2[:, 0] ** 2) / (2 * gap)
        for axis, plane in self.sheets:
            d = np.minimum(d, np.abs(np.abs(points[:, axis] - plane) - 0.5))
        for p, u in self.tubes:
            d = np.minimum(d, np.abs(_line_distance(points, p, u) - TUBE_RADIUS))
        border = np.minimum(np.abs(points - 0.5), np.abs(points - (self.size - 1.5))).min(axis=1)
        return np.minimum(d, border)


def _unit(v):
    return v / np.linalg.norm(v)


def _line_distance(points, p, u):
    q = points - p
    return np.linalg.norm(q - np.outer(q @ u, u), axis=1)


def write_volume(truth: Truth, path: Path):
    import zarr
    n = truth.size
    array = zarr.open(str(path), mode="w", shape=(n, n, n), chunks=(64, 64, 64), dtype=np.uint16)
    for lo in range(0, n, 64):
        array[lo:lo + 64] = truth.labels(lo, min(n, lo + 64))
    return array


def read_surfaces(folder: Path, cf):
    return {int(p.stem.split("_")[1]): cf.read_mesh(p) for p in sorted(folder.glob("label_*.ply"))}


def closed_and_oriented(F) -> bool:
    edges = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    keys = edges[:, 0].astype(np.int64) * (int(F.max()) + 1) + edges[:, 1]
    opposite = edges[:, 1].astype(np.int64) * (int(F.max()) + 1) + edges[:, 0]
    unique = np.unique(keys)
    return len(unique) == len(keys) and np.isin(opposite, unique).all()


def in_core_surfaces(r, cf):
    """Each label's surface of the in-core result `r`, its soup in the canonical order."""
    from cgal_constrained_fairing import _core
    from cgal_constrained_fairing.tiles._label_chunks import canonical_triangles
    T, FL = canonical_triangles(r.faces, r.face_labels)
    return {int(L): _core.label_surface(r.vertices, T, FL, int(L)) for L in r.labels}


def differences(a, b) -> str:
    d = np.concatenate([np.linalg.norm(a[L][0] - b[L][0], axis=1) for L in a])
    return (f"RMS {np.sqrt(np.mean(d ** 2)):.4f}, largest {d.max():.3f}, "
            f"over 0.1: {100 * np.mean(d > 0.1):.2f} %")


def same_triangles(a, b) -> bool:
    return sorted(a) == sorted(b) and all(np.array_equal(a[L][1], b[L][1]) for L in a)


def to_truth(surfaces, truth) -> str:
    d = truth.distance(np.concatenate([V for V, _ in surfaces.values()]))
    return f"RMS {np.sqrt(np.mean(d ** 2)):.4f}, 99 % {np.percentile(d, 99):.3f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--cells", type=int, default=480)
    parser.add_argument("--chunks", nargs="+", default=["64", "96"],
                        help="cells per chunk along each axis, or auto (sized by the tiles' memory)")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--worker-limit", default="2GiB")
    parser.add_argument("--in-core", type=int, default=1)
    parser.add_argument("--folder", default=None)
    args = parser.parse_args()
    import distributed
    from dask.utils import parse_bytes
    import cgal_constrained_fairing as cf
    from cgal_constrained_fairing.tiles import label_surfaces_tiled
    root = Path(tempfile.mkdtemp(dir=args.folder))
    try:
        print(f"CPU: {cpu_model()}; {cores()} cores; {args.workers} workers of 1 thread, "
              f"each limited to {args.worker_limit}")
        clock = time.perf_counter()
        truth = Truth(args.size, args.cells)
        volume = write_volume(truth, root / "volume.zarr")
        print(f"volume {args.size}^3, {args.cells} Voronoi cells, {SHEETS} sheets, {TUBES} tubes, "
              f"generated in {time.perf_counter() - clock:.1f} s")
        runs = {}
        with distributed.LocalCluster(n_workers=args.workers, threads_per_worker=1,
                                      memory_limit=args.worker_limit, dashboard_address=None) as cluster, \
                distributed.Client(cluster) as client:
            # As benchmark/tiled_fairing.py: Dask pauses a worker at 80 % of its limit.
            tile_memory = int(0.6 * parse_bytes(args.worker_limit))
            for chunk in args.chunks:
                clock = time.perf_counter()
                report = label_surfaces_tiled(volume, root / f"tiled{chunk}", client=client,
                                              chunk_cells=None if chunk == "auto" else int(chunk),
                                              tile_memory=tile_memory)
                seconds = time.perf_counter() - clock
                runs[f"tiled {chunk}"] = read_surfaces(root / f"tiled{chunk}", cf)
                phases = ", ".join(f"{k} {v:.1f}" for k, v in report.seconds.items())
                print(f"tiled, chunks of {report.chunk_cells} cells ({chunk}): {seconds:.1f} s "
                      f"({phases}); {report.chunks} chunks, {report.sweeps} sweeps, seam motions "
                      f"{[round(m, 4) for m in report.motion]}, worker peak "
                      f"{report.peak_memory / 2 ** 30:.2f} GiB; {report.points} points, "
                      f"{report.triangles} triangles, {len(report.labels)} labels")
                shutil.rmtree(root / f"tiled{chunk}")
        if args.in_core:
            cf.set_max_threads(args.workers)
            L = np.asarray(volume)
            clock = time.perf_counter()
            r = cf.label_surfaces(L)
            print(f"in core: {time.perf_counter() - clock:.1f} s, {len(r.vertices)} points, "
                  f"{len(r.faces)} triangles; {r.report.number_of_iterations} iterations")
            runs["in core"] = in_core_surfaces(r, cf)
            padded = np.zeros((L.shape[0] + 2,) + L.shape[1:], L.dtype)
            padded[2:] = L
            runs["in core, padded"] = in_core_surfaces(cf.label_surfaces(padded, origin=(-2, 0, 0)), cf)
        for name, surfaces in runs.items():
            closed = sum(closed_and_oriented(F) for _, F in surfaces.values())
            print(f"{name}: {closed} of {len(surfaces)} labels closed and oriented; to the truth "
                  f"{to_truth(surfaces, truth)}")
        names = list(runs)
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                print(f"{a} against {b}: same triangles {same_triangles(runs[a], runs[b])}; "
                      f"points {differences(runs[a], runs[b])}")
    finally:
        shutil.rmtree(root)


if __name__ == "__main__":
    main()
