"""Meshes shared by the Python tests: the bundled ones, and seeded noisy spheres of any size."""

import os
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
DATA = Path(os.environ.get("CONSTRAINED_FAIRING_DATA_DIR", ROOT / "data"))
BAD_INPUT = ROOT / "test" / "bad_input"


def icosphere(subdivisions):
    """A unit sphere: an icosahedron whose triangles are split in four `subdivisions` times,
    new vertices pushed onto the sphere. 20 * 4**subdivisions triangles."""
    t = (1 + 5 ** 0.5) / 2
    V = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t),
         (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    F = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    V = np.array(V, dtype=float)
    F = np.array(F, dtype=np.int64)
    for _ in range(subdivisions):
        edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
        unique, inverse = np.unique(edges, axis=0, return_inverse=True)
        inverse = inverse.reshape(3, -1).T + len(V)
        V = np.vstack([V, (V[unique[:, 0]] + V[unique[:, 1]]) / 2])
        a, b, c = F.T
        ab, bc, ca = inverse.T
        F = np.concatenate([np.stack(x, axis=1) for x in
                            ((a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca))])
    V /= np.linalg.norm(V, axis=1, keepdims=True)
    return V, F


def noisy(V, F, amplitude, seed=1):
    """V with seeded noise along the vertex normals (the sphere's), of at most `amplitude` times
    the mean edge length."""
    rng = np.random.default_rng(seed)
    h = np.linalg.norm(V[F[:, 0]] - V[F[:, 1]], axis=1).mean()
    return V + (amplitude * h) * rng.uniform(-1, 1, (len(V), 1)) * V


def lost_once(task, marker: Path, when):
    """`task` (of a run's folder, a tile, a sweep and more) lost once, when its tile and sweep
    are `when`, after its work: a worker lost after its write, before Dask heard of it. The loss
    is marked in the file `marker`, since Dask hands its workers a copy of the function."""
    def lost(folder, tile, sweep, *arguments):
        done = task(folder, tile, sweep, *arguments)
        if (tile, sweep) == when and not marker.exists():
            marker.write_text(f"tile {tile}, sweep {sweep}")
            raise RuntimeError("worker lost")
        return done
    return lost


@pytest.fixture(scope="session")
def sphere():
    """A noisy sphere of 5120 triangles, noise up to 0.2 h along the normal."""
    V, F = icosphere(4)
    return noisy(V, F, 0.2), F


@pytest.fixture(scope="module")
def client():
    """A Dask LocalCluster of 2 single-threaded worker processes, for the module's tests."""
    distributed = pytest.importorskip("distributed")
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=None)
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()
