#!/usr/bin/env python3
"""The Python module against the C++ call, and batches on Dask against a serial loop.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/python_batch.py [--build build] [--runs 5]
        [--demo-dir build/cgal_demo_data/meshes] [--skip-call] [--skip-batch]

1. The call: fairing_scaling's 301,632-triangle case (the bundled bunny Loop subdivided once,
   seeded noise of 0.25 h), written once by the C++ program ``benchmark/fairing_call`` and read
   back by both sides. Each run times the C++ default call (in its own process, on the mesh it
   read) and then ``fair()`` on the arrays read by ``read_mesh`` (checks, mesh construction and
   the copy of the result included), one after the other; the overhead is the ratio of the
   medians. The C++ program also times the construction of its mesh from the file's arrays
   followed by the call, what a C++ program holding the arrays does. The results must be
   bit-identical.
2. The batch: 40 small noisy scans, the bundled meshes and CGAL's demo meshes (filled in by
   benchmark/get_demo_meshes.sh; without them, the bundled meshes alone, with more seeds), each
   with seeded noise of 0.25 h at 5 seeds, epsilon 0.25 h. A serial Python loop (read, fair,
   write; the library's loops on all cores), then ``fair_files`` on a LocalCluster of 1 worker
   (the library on both cores, and on one), and of 2 workers (one core each), the cluster's
   start included, as the command line pays it. The outputs must be bit-identical to the
   loop's.

Medians of ``--runs`` runs; the CPU model and the threads are printed with the figures.
"""

import argparse
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import cgal_constrained_fairing as cf
from benchmark_machine import cores, cpu_model

ROOT = Path(__file__).resolve().parents[1]
BUNDLED = ["head.off", "elephant.off", "bunny00.off"]
DEMO = ["femur.off", "homer.off", "bull.off", "lion-head.off", "camel.off", "armadillo.off"]


def machine_line():
    return (f"{cpu_model()}, {cores()} cores; TBB threads {cf.max_threads()}; "
            f"Python {platform.python_version()}, numpy {np.__version__}")


def bench_call(build, runs, work):
    program = Path(build) / "benchmark" / "fairing_call"
    if not program.exists():
        print(f"call: {program} not built, skipped")
        return
    case = work / "bunny_level1.off"
    subprocess.run([str(program), "--write-case", str(case), "--level", "1"], check=True)
    V, F = cf.read_mesh(case)
    eps = 0.25 * cf.mean_edge_length(V, F)
    cpp_out = work / "cpp_out.off"
    cpp, arrays, py = [], [], []
    W = None
    for run in range(runs):
        command = [str(program), str(case)] + (["--output", str(cpp_out)] if run == 0 else [])
        line = subprocess.run(command, check=True, capture_output=True, text=True).stdout
        cpp.append(float(re.search(r"seconds (\S+)", line).group(1)))
        arrays.append(float(re.search(r"from_arrays (\S+)", line).group(1)))
        start = time.perf_counter()
        W, report = cf.fair(V, F, eps)
        py.append(time.perf_counter() - start)
    identical = np.array_equal(cf.read_mesh(cpp_out)[0], W)
    c, a, p = statistics.median(cpp), statistics.median(arrays), statistics.median(py)
    print(f"call: {len(F)} triangles, eps 0.25 h, default call, {report.number_of_iterations} "
          f"iterations; {machine_line()}")
    print(f"  C++ call on the mesh          {c:8.3f} s   (runs: {', '.join(f'{t:.3f}' for t in cpp)})")
    print(f"  C++ mesh from arrays, call    {a:8.3f} s   (runs: {', '.join(f'{t:.3f}' for t in arrays)})")
    print(f"  Python fair() on the arrays   {p:8.3f} s   (runs: {', '.join(f'{t:.3f}' for t in py)})")
    # Each run's ratio, its three calls made one after the other, is less exposed to the
    # machine's drift than the ratio of the medians.
    on_mesh = statistics.median(q / r for q, r in zip(py, cpp))
    on_arrays = statistics.median(q / r for q, r in zip(py, arrays))
    print(f"  overhead {100 * (p / c - 1):+.1f} % against the call on the mesh, "
          f"{100 * (p / a - 1):+.1f} % against the C++ program that holds the arrays "
          f"(ratio of the medians); {100 * (on_mesh - 1):+.1f} % and {100 * (on_arrays - 1):+.1f} % "
          f"(median of each run's ratio); results {'bit-identical' if identical else 'DIFFERENT'}")


def make_scans(demo_dir, work):
    """40 noisy scans, as OFF files in work/scans; returns their paths."""
    sources = [ROOT / "data" / name for name in BUNDLED]
    demo = [Path(demo_dir) / name for name in DEMO]
    if all(p.exists() for p in demo):
        sources += demo
    else:
        print(f"batch: no CGAL demo meshes in {demo_dir} (benchmark/get_demo_meshes.sh fetches "
              "them): the bundled meshes alone")
    seeds = -(-40 // len(sources))
    folder = work / "scans"
    folder.mkdir()
    paths = []
    for seed in range(seeds):
        for source in sources:
            if len(paths) == 40:
                break
            V, F = cf.read_mesh(source)
            h = cf.mean_edge_length(V, F)
            rng = np.random.default_rng(seed + 1)
            # uniform in the ball of radius 0.25 h
            direction = rng.normal(size=V.shape)
            direction /= np.linalg.norm(direction, axis=1, keepdims=True)
            radius = 0.25 * h * rng.uniform(0, 1, (len(V), 1)) ** (1 / 3)
            path = folder / f"{source.stem}_seed{seed + 1}.off"
            cf.write_mesh(path, V + radius * direction, F)
            paths.append(path)
    return paths


def serial_loop(paths, out):
    out.mkdir()
    for path in paths:
        V, F = cf.read_mesh(path)
        W, _ = cf.fair(V, F, 0.25 * cf.mean_edge_length(V, F))
        cf.write_mesh(out / path.name, W, F)


def bench_batch(demo_dir, runs, work):
    from cgal_constrained_fairing.batch import fair_files

    paths = make_scans(demo_dir, work)
    triangles = sum(len(cf.read_mesh(p)[1]) for p in paths)
    # (name, workers, library threads per worker): one worker on both cores, one worker on one
    # core, and two workers of one core each.
    batches = [("1 worker", 1, None), ("1 worker, 1 thread", 1, 1), ("2 workers", 2, None)]
    times = {name: [] for name in ["serial loop"] + [b[0] for b in batches]}
    for run in range(runs):
        out = work / f"serial{run}"
        start = time.perf_counter()
        serial_loop(paths, out)
        times["serial loop"].append(time.perf_counter() - start)
        for name, workers, threads in batches:
            batch_out = work / f"batch{len(times[name])}_{name.replace(' ', '_')}"
            start = time.perf_counter()
            rows = fair_files(paths, batch_out, workers=workers, threads=threads, progress=False)
            times[name].append(time.perf_counter() - start)
            failed = [row for row in rows if row["status"] == "error"]
            different = [p.name for p in paths
                         if not np.array_equal(cf.read_mesh(batch_out / p.name)[0],
                                               cf.read_mesh(out / p.name)[0])]
            if failed or different:
                print(f"batch {name}: {len(failed)} errors, outputs different from the serial "
                      f"loop's: {different}")
    print(f"batch: {len(paths)} noisy scans, {triangles} triangles in all, eps 0.25 h; "
          f"{machine_line()}")
    median = {name: statistics.median(t) for name, t in times.items()}
    for name, t in times.items():
        print(f"  {name:20s} {median[name]:8.2f} s   (runs: {', '.join(f'{x:.2f}' for x in t)})")
    print(f"  2 workers against 1 worker on both cores: "
          f"{median['1 worker'] / median['2 workers']:.2f}x, against 1 worker on one core: "
          f"{median['1 worker, 1 thread'] / median['2 workers']:.2f}x, against the serial loop: "
          f"{median['serial loop'] / median['2 workers']:.2f}x (cluster start included; "
          "outputs bit-identical to the loop's)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--demo-dir", default=str(ROOT / "build" / "cgal_demo_data" / "meshes"))
    parser.add_argument("--skip-call", action="store_true")
    parser.add_argument("--skip-batch", action="store_true")
    args = parser.parse_args()
    work = Path(tempfile.mkdtemp(prefix="python_batch_"))
    try:
        if not args.skip_call:
            bench_call(args.build, args.runs, work)
        if not args.skip_batch:
            bench_batch(args.demo_dir, args.runs, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
