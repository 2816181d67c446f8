"""The tasks of a tiled fairing and the sweeps that schedule them on Dask.

Everything a task needs lies in the run's folder (a shared file system on a cluster): the
input points, the current points, each tile's mesh. A task reads them and writes its owned
vertices' new points to a file of its own, renamed into place when complete; the client applies
a colour's files once all its tasks are done. A task run twice (a worker lost, Dask's retry)
writes the same file, so the result does not depend on the scheduling.
"""

import os
from pathlib import Path
from typing import Any, Dict

import numpy as np

from .. import _core
from .._errors import InputError
from .._fairing import call_options, result_of, set_max_threads
from . import _partition

# Ghost rings around a tile's owned vertices: one more than the smoothing steps of the start,
# whose every step reaches a ring farther, and one for the normals there, so that the start and
# the lines along which the owned vertices move are the whole call's.
def ghost_rings(smoothing_steps: int) -> int:
    return max(smoothing_steps + 2, _partition.HINGE_RINGS + 1)


def open_array(path: Path, mode: str = "r") -> np.ndarray:
    return np.lib.format.open_memmap(path, mode=mode)


def open_array_new(path: Path, shape, dtype) -> np.ndarray:
    """A new .npy file of zeros, mapped for writing."""
    return np.lib.format.open_memmap(path, mode="w+", dtype=dtype, shape=shape)


def build_tile(folder: str, t: int, rings: int, margin: float, measure: str) -> Dict[str, Any]:
    """Tile `t`'s mesh into the run's folder, from the faces found in its box grown by `margin`
    (the tile's candidates file), searched again with a doubled margin where the rings reach
    farther; its ghosts' owners near enough to share a hinge; and the tile's part of the whole
    mesh's epsilon where `measure` (the kind of the run's eps) asks for one: its owned edges'
    lengths for "h", its owned vertices' noise heights for "auto"."""
    root = Path(folder)
    points = open_array(root / "input.npy")
    corners = open_array(root / "faces.npy")
    tiles = _partition.Tiles(open_array(root / "tile.npy"), np.load(root / "boxes.npy"))
    faces = np.load(root / "tiles" / f"{t}.candidates.npy")
    while True:
        box = _partition.grown(tiles.boxes[t], margin)
        try:
            mesh = _partition.tile_mesh(t, tiles, corners, points, rings, box, faces)
            break
        except _partition.MarginTooSmall:
            margin *= 2
            faces = _partition.candidate_faces(corners, points,
                                               _partition.grown(tiles.boxes[t], margin)[None])[0]
    band = _partition.band_mesh(mesh, rings)
    _save(root / "tiles" / f"{t}.npz", vertices=mesh.vertices, faces=mesh.local_faces,
          owned=mesh.owned, seam=mesh.seam, overlap=mesh.overlap)
    _save(root / "tiles" / f"{t}.band.npz", vertices=mesh.vertices[band.vertices],
          faces=band.local_faces, owned=band.free, seam=band.seam)
    X = np.ascontiguousarray(points[mesh.vertices])
    length, edges = _partition.owned_edge_lengths(mesh, X) if measure == "h" else (0.0, 0)
    heights = None
    if measure == "auto":
        heights, defect, message = _core.noise_heights(X, mesh.local_faces.astype(np.int64),
                                                       np.flatnonzero(mesh.owned))
        if defect.name != "NONE":
            raise InputError(defect.name, message)
    return {"tile": t, "near": mesh.near_owners, "vertices": len(mesh.vertices),
            "faces": len(mesh.local_faces), "owned": int(mesh.owned.sum()),
            "band_faces": len(band.local_faces), "edge_length": length, "edges": edges,
            "noise_heights": heights, "peak_memory": peak_memory()}


def fair_tile(folder: str, t: int, sweep: int, epsilon: float, keywords: Dict[str, Any],
              max_iterations: int, threads: int) -> Dict[str, Any]:
    """Tile `t`'s owned vertices faired from the current points, written to the tile's file
    for `sweep`; the vertices no tile has faired yet start at the smoothed start. In the first
    sweep the ghosts of the tile's overlap descend too, their points dropped; after it, only
    the tile's band descends, over the band's mesh."""
    set_max_threads(threads)
    root = Path(folder)
    tile = np.load(root / "tiles" / (f"{t}.npz" if sweep == 1 else f"{t}.band.npz"))
    vertices, owned = tile["vertices"], tile["owned"]
    X0 = np.ascontiguousarray(open_array(root / "input.npy")[vertices])
    current = np.ascontiguousarray(open_array(root / "state.npy")[vertices])
    at_start = open_array(root / "faired.npy")[vertices] == 0
    options = call_options(epsilon, **keywords)
    free = tile["overlap"] if sweep == 1 else owned
    outcome = _core.fair_tile(X0, current, tile["faces"], free, at_start, options,
                              max_iterations)
    W, report = result_of(outcome)
    moved = np.linalg.norm(W - current, axis=1)
    moved[at_start] = 0  # the start is no motion of the sweeps
    seam, moved = moved[tile["seam"]], moved[owned]
    _save(root / "tiles" / f"{t}.sweep{sweep}.npz", points=W[owned],
          deviation=report.deviation[owned], at_bound=report.at_bound[owned])
    return {"tile": t, "squared_motion": float(np.square(seam).sum()),
            "seam": len(seam), "largest_motion": float(moved.max(initial=0.0)),
            "iterations": report.number_of_iterations, "status": report.status.value,
            "peak_memory": peak_memory()}


def peak_memory() -> int:
    """The largest resident memory of this process so far, in bytes: the kernel's high-water
    mark of its own memory (getrusage's would count the spawning parent's, which a process
    started by fork and exec inherits); 0 where /proc does not tell."""
    try:
        with open("/proc/self/status") as status:
            for line in status:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return 0


def apply_tile(folder: Path, t: int, sweep: int) -> None:
    """Tile `t`'s points of `sweep` into the run's current points, deviations and flags; its
    owned vertices are faired from now on."""
    tile = np.load(folder / "tiles" / (f"{t}.npz" if sweep == 1 else f"{t}.band.npz"))
    result_path = folder / "tiles" / f"{t}.sweep{sweep}.npz"
    result = np.load(result_path)
    rows = tile["vertices"][tile["owned"]]
    for name, key in (("state", "points"), ("deviation", "deviation"), ("at_bound", "at_bound"),
                      ("faired", None)):
        target = open_array(folder / f"{name}.npy", "r+")
        target[rows] = result[key] if key else 1
        target.flush()
        del target
    result_path.unlink()


def _save(path: Path, **arrays) -> None:
    # Written whole beside its place, then renamed: a reader never sees half a file. A write
    # refused (a full disk) names the file, which numpy's writes into an open file do not.
    partial = path.with_name(path.name + f".partial-{os.getpid()}")
    try:
        with open(partial, "wb") as f:
            np.savez(f, **arrays)
    except OSError as error:
        partial.unlink(missing_ok=True)
        raise named(error, path) from None
    os.replace(partial, path)


def named(error: OSError, path: Path) -> OSError:
    """`error` naming `path` when it names no file (a write into an open file refused)."""
    if error.errno is None or error.filename is not None:
        return error
    return OSError(error.errno, error.strerror, str(path))
