#!/usr/bin/env python3
"""One mesh faired as tiles on Dask (``fair_tiled``) against the in-core call, in one process.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/tiled_fairing.py [--build build]
        [--levels 2 3] [--runs 1] [--workers 2] [--worker-memory FRACTION] [--mesh MESH]
        [--crossing]
    PYTHONPATH=build/python /usr/bin/python3 benchmark/tiled_fairing.py --case NOISY.ply
        --worker-limit 5GiB [--workers 2] [--keep DIR]

For each level L, ``benchmark/fairing_call --write-case`` writes the bundled bunny (or MESH)
Loop subdivided L times with seeded noise of 0.25 h (binary PLY) and the clean subdivided mesh;
epsilon is 0.25 h. The in-core call ``fair()`` runs in this process on all threads; then
``fair_tiled`` on a LocalCluster of ``--workers`` single-threaded processes, each with a memory
limit of FRACTION (default 0.5) times what the in-core call needs (about 340 bytes per
triangle), so that no worker could hold the whole mesh's fairing, the tiles sized to half of
it. Printed per level: both times (medians) and their ratio; the tiled result against the
in-core one (RMS and largest vertex distance in epsilon, and the 99th percentile); against the
clean mesh for both, the RMS distance along the clean vertex normals (% of epsilon) and the
mean angle between corresponding face normals, and the tiled result's normal error within 3
rings of a tile border against the tiles' interiors; the bound, the faces, each worker's peak
memory against its limit, the sweeps and their motions. The CPU model and the threads are
printed with the figures.

With ``--crossing``, a second tiled run cuts each cell across its second widest extent instead
of its widest, so that its tile borders cross the first's tiles; printed: the two results'
RMS and largest difference, over all vertices and over the first run's border vertices 3 rings
or more from the second's. ``--case`` takes a noisy binary PLY mesh too large for the in-core
call (``fairing_call --write-case NOISY.ply --level 5`` writes the bunny at 77 M triangles):
epsilon is 0.25 times its mean edge length, the tiled runs (the second crossing) have workers
of ``--worker-limit`` each, and the client's peak memory in each run is printed. With ``--keep
DIR`` the outputs and tiles stay in DIR, and a run whose output is there already is not made
again (runs of two commits compared).
"""

import argparse
import contextlib
import functools
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import cgal_constrained_fairing as cf
from benchmark_machine import cpu_model
from cgal_constrained_fairing.tiles import BYTES_PER_TRIANGLE, _partition, _ply_map, fair_tiled
from cgal_constrained_fairing.tiles._sweeps import peak_memory

IN_CORE_BYTES_PER_TRIANGLE = 340


def write_case(build: Path, level: int, mesh, folder: Path):
    noisy, clean = folder / f"noisy_{level}.ply", folder / f"clean_{level}.ply"
    command = [str(build / "benchmark" / "fairing_call"), "--write-case", str(noisy),
               "--level", str(level), "--clean", str(clean)]
    if mesh:
        command.insert(3, mesh)
    subprocess.run(command, check=True)
    return noisy, clean


def vertex_normals(V, F):
    N = np.zeros_like(V)
    n = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    for c in range(3):
        np.add.at(N, F[:, c], n)
    return N / np.maximum(np.linalg.norm(N, axis=1, keepdims=True), 1e-300)


def face_normal_angles(V, clean, F):
    def unit(X):
        n = np.cross(X[F[:, 1]] - X[F[:, 0]], X[F[:, 2]] - X[F[:, 0]])
        return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)
    return np.degrees(np.arccos(np.clip((unit(V) * unit(clean)).sum(axis=1), -1, 1)))


def rings_from_border(tile, F, most=3):
    """Each vertex's rings to the nearest vertex with a neighbour in another tile (most+1 if
    farther)."""
    edges = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    rings = np.full(len(tile), most + 1)
    front = np.zeros(len(tile), bool)
    front[edges[tile[edges[:, 0]] != tile[edges[:, 1]]].ravel()] = True
    for r in range(most + 1):
        rings[front & (rings > r)] = r
        grown = np.zeros(len(tile), bool)
        grown[edges[front[edges[:, 0]] | front[edges[:, 1]]].ravel()] = True
        front = grown
    return rings


def quality(W, clean, normals, F, eps):
    along = ((W - clean) * normals).sum(axis=1)
    return 100 * np.sqrt(np.mean(along ** 2)) / eps, face_normal_angles(W, clean, F)


def in_core(V, F, eps, runs):
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        W, report = cf.fair(V, F, eps)
        times.append(time.perf_counter() - start)
    return W, report, statistics.median(times)


def worker_base(workers):
    """The memory of an idle worker that has imported the package: what a limit adds to."""
    import distributed

    def resident():
        import cgal_constrained_fairing.tiles  # noqa: F401 (what a task imports)
        with open("/proc/self/statm") as f:
            return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    with distributed.LocalCluster(n_workers=workers, threads_per_worker=1,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        return max(client.run(resident).values())


@contextlib.contextmanager
def cut(crossing):
    """The tiles cut across each cell's widest extent, or its second widest (`crossing`)."""
    widest = _partition.kd_tiles
    if crossing:
        _partition.kd_tiles = functools.partial(widest, across=1)
    try:
        yield
    finally:
        _partition.kd_tiles = widest


def tiled(noisy, out, eps, runs, workers, limit, tile_memory, crossing=False):
    """The report, the median time, the workers' peaks and the client's peak of the runs."""
    import distributed
    times, client_peak = [], 0
    for _ in range(runs):
        with distributed.LocalCluster(n_workers=workers, threads_per_worker=1, memory_limit=limit,
                                      dashboard_address=None) as cluster, \
                distributed.Client(cluster) as client, cut(crossing):
            with open("/proc/self/clear_refs", "w") as f:
                f.write("5")  # this process's peak from here on
            start = time.perf_counter()
            report = fair_tiled(noisy, out, eps, client=client, tile_memory=tile_memory)
            times.append(time.perf_counter() - start)
            client_peak = max(client_peak, peak_memory())
            peaks = client.run(peak_memory)
    return report, statistics.median(times), peaks, client_peak


def compare_cuts(first, second, T1, T2, F, eps):
    """The two runs' results apart, over all vertices and the first's border vertices 3 rings
    or more from the second's borders (`first`, `second`: each vertex's tile in each run)."""
    d = np.linalg.norm(T1 - T2, axis=1) / eps
    near_first, near_second = (rings_from_border(tile, F) for tile in (first, second))
    apart = (near_first == 0) & (near_second > 3)
    print(f"  crossing cut against the first: RMS {np.sqrt(np.mean(d ** 2)):.4f} eps, largest "
          f"{d.max():.4f} eps; on the first's {int(apart.sum())} border vertices 3 rings or more "
          f"from the second's borders (of {int((near_first == 0).sum())}): RMS "
          f"{np.sqrt(np.mean(d[apart] ** 2)):.4f} eps, largest {d[apart].max(initial=0):.4f} eps")


def measure(args, level, folder):
    noisy, clean_path = write_case(args.build, level, args.mesh, folder)
    V, F = cf.read_mesh(noisy)
    clean, _ = cf.read_mesh(clean_path)
    eps = 0.25 * cf.mean_edge_length(clean, F)
    W, whole, t_in = in_core(V, F, eps, args.runs)
    base = worker_base(args.workers)
    share = int(args.worker_memory * IN_CORE_BYTES_PER_TRIANGLE * len(F))
    # Dask pauses a worker at 80 % of its limit: the tiles get 60 % of what is above the base.
    limit, tile_memory = base + share, int(0.6 * share)
    out = folder / f"tiled_{level}.ply"
    report, t_tiled, peaks, _ = tiled(noisy, out, eps, args.runs, args.workers, limit, tile_memory)
    T, F_out = cf.read_mesh(out)
    print(f"level {level}: {len(V)} vertices, {len(F)} triangles, eps 0.25 h = {eps:.6g}; "
          f"medians of {args.runs} runs")
    print(f"  in-core: {t_in:.2f} s, {whole.number_of_iterations} iterations; tiled: "
          f"{t_tiled:.2f} s ({t_tiled / t_in:.3f} times), {report!r}")
    print(f"  tiles: {len(report.colour)}, vertices with ghosts {report.tile_sizes[:, 0].min()} "
          f"to {report.tile_sizes[:, 0].max()}; sweep motions (RMS, eps) "
          f"{[round(m, 4) for m in report.motion]}, largest {[round(m, 3) for m in report.largest_motion]}")
    print("  phases (s): " + ", ".join(f"{k} {v:.2f}" for k, v in report.seconds.items()))
    d = np.linalg.norm(T - W, axis=1) / eps
    print(f"  tiled against in-core: RMS {np.sqrt(np.mean(d ** 2)):.4f} eps, largest {d.max():.4f} "
          f"eps, 99th percentile {np.percentile(d, 99):.4f} eps")
    normals = vertex_normals(clean, F)
    (rms_in, angle_in), (rms_t, angle_t) = (quality(X, clean, normals, F, eps) for X in (W, T))
    print(f"  against the clean mesh: RMS distance along its normals {rms_in:.3f} / {rms_t:.3f} % of "
          f"eps (in-core / tiled, ratio {rms_t / rms_in:.4f}), mean normal error {angle_in.mean():.4f} "
          f"/ {angle_t.mean():.4f} deg (ratio {angle_t.mean() / angle_in.mean():.4f})")
    near = rings_from_border(report.tile, F)[F].min(axis=1) <= 3
    if near.any() and (~near).any():
        print(f"  tiled normal error within 3 rings of a tile border {angle_t[near].mean():.4f} deg, "
              f"interiors {angle_t[~near].mean():.4f} deg (ratio "
              f"{angle_t[near].mean() / angle_t[~near].mean():.4f}; in-core there "
              f"{angle_in[near].mean():.4f} / {angle_in[~near].mean():.4f})")
    bound = bool((np.linalg.norm(T - V, axis=1) <= eps).all())
    print(f"  bound holds: {bound}; faces identical: {bool(np.array_equal(F_out, F))}; worker peaks "
          f"{sorted(round(p / 2 ** 20) for p in peaks.values())} MiB (tasks' largest "
          f"{report.peak_memory / 2 ** 20:.0f}) against a limit of "
          f"{limit / 2 ** 20:.0f} MiB (an idle worker {base / 2 ** 20:.0f} MiB, the in-core call "
          f"about {IN_CORE_BYTES_PER_TRIANGLE * len(F) / 2 ** 20:.0f} MiB more)")
    if args.crossing:
        second, _, _, _ = tiled(noisy, folder / "crossing.ply", eps, 1, args.workers, limit,
                                tile_memory, crossing=True)
        compare_cuts(report.tile, second.tile, T, cf.read_mesh(folder / "crossing.ply")[0], F,
                     eps)


def mapped_points(path):
    records = _ply_map.map_ply(path).vertices()
    return np.stack([records[name] for name in "xyz"], axis=1).astype(np.float64)


def measure_case(args, folder):
    """The mesh of --case, too large for the in-core call, in two tiled runs, the second's cut
    crossing the first's."""
    from dask.utils import format_bytes, parse_bytes
    from cgal_constrained_fairing.batch._epsilon import mesh_epsilon, parse_eps
    mapped = _ply_map.map_ply(args.case)
    F = np.asarray(mapped.faces()["corners"], np.int32)
    V = mapped_points(args.case)
    eps = mesh_epsilon(parse_eps("0.25h"), V, F)
    base = worker_base(args.workers)
    limit = parse_bytes(args.worker_limit)
    tile_memory = int(0.6 * (limit - base))
    print(f"{args.case}: {len(V)} vertices, {len(F)} triangles, eps 0.25 h = {eps:.6g}; workers "
          f"of {format_bytes(limit)} (idle {format_bytes(base)}), tiles of {format_bytes(tile_memory)}")
    keep = args.keep or folder
    runs = []
    for cut in ("widest", "crossing"):
        out, tile = keep / f"tiled_{cut}.ply", keep / f"tile_{cut}.npy"
        if out.exists() and tile.exists():
            print(f"  {cut} cut: {out} of an earlier run")
        else:
            report, seconds, peaks, client_peak = tiled(args.case, out, eps, 1, args.workers,
                                                        limit, tile_memory, cut == "crossing")
            np.save(tile, report.tile)
            print_case_run(cut, report, seconds, peaks, client_peak, out, V, F, eps)
        runs.append((np.load(tile), mapped_points(out)))
        sys.stdout.flush()
    compare_cuts(runs[0][0], runs[1][0], runs[0][1], runs[1][1], F, eps)


def print_case_run(cut, report, seconds, peaks, client_peak, out, V, F, eps):
    T = mapped_points(out)
    print(f"  {cut} cut: {seconds:.1f} s, {report!r}")
    print(f"    tiles: {len(report.colour)}, vertices with ghosts {report.tile_sizes[:, 0].min()} "
          f"to {report.tile_sizes[:, 0].max()}, triangles {report.tile_sizes[:, 1].min()} to "
          f"{report.tile_sizes[:, 1].max()}; iterations by sweep {report.iterations}")
    print("    phases (s): " + ", ".join(f"{k} {v:.1f}" for k, v in report.seconds.items()))
    print(f"    sweep motions (RMS, eps) {[round(m, 4) for m in report.motion]}; bound holds: "
          f"{bool((np.linalg.norm(T - V, axis=1) <= eps).all())}; faces identical: "
          f"{bool(np.array_equal(np.asarray(_ply_map.map_ply(out).faces()['corners']), F))}; "
          f"peaks: client {client_peak / 2 ** 30:.2f} GiB, workers "
          f"{sorted(round(p / 2 ** 30, 2) for p in peaks.values())} GiB (tasks' largest "
          f"{report.peak_memory / 2 ** 30:.2f})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", type=Path, default=Path("build"))
    parser.add_argument("--levels", type=int, nargs="+", default=[2, 3])
    parser.add_argument("--runs", type=int, default=1)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--worker-memory", type=float, default=0.5)
    parser.add_argument("--mesh", default="")
    parser.add_argument("--crossing", action="store_true")
    parser.add_argument("--case", type=Path)
    parser.add_argument("--worker-limit", default="5GiB")
    parser.add_argument("--keep", type=Path)
    args = parser.parse_args()
    if not (args.build / "benchmark" / "fairing_call").exists():
        print(f"skipped: {args.build}/benchmark/fairing_call is not built")
        return 0
    print(f"{cpu_model()}, {os.cpu_count()} CPUs; in-core on {cf.max_threads()} threads, tiles on "
          f"{args.workers} workers of 1 thread; tiles sized at {BYTES_PER_TRIANGLE} bytes per triangle")
    if args.case:
        with tempfile.TemporaryDirectory(dir=args.case.parent) as folder:
            measure_case(args, Path(folder))
        return 0
    with tempfile.TemporaryDirectory() as folder:
        for level in args.levels:
            measure(args, level, Path(folder))
            sys.stdout.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
