"""The tasks of a label volume's tiled surfaces: each chunk's nets, its tile, its descents, and
each label's file.

A chunk's tile holds the triangles whose corners all lie within `REACH` cells of the chunk's
own, from the nets of the chunk and its neighbours. In the first sweep its points within
`OVERLAP` cells descend from the smoothed start of the unfaired nets, the rest frozen there, and
only the chunk's own points are kept (a restricted overlapping Schwarz step: no tile reads
another's results, so all run at once); in the sweeps after, the tiles of one colour descend
their own points from the current ones with all others frozen, `SEAM_ITERATIONS` at most. Every
point's bound is its box, so every descent keeps the whole within its bounds. Everything a task
reads lies in the run's folder; it writes files of its own, renamed into place when complete,
so that a task run again (a worker lost) gives the same result.
"""

import os
from pathlib import Path
from typing import Any, Dict, List, Sequence

import numpy as np

from .. import _core
from .._io import write_mesh
from .._labels import fair_interfaces
from ._label_chunks import CELL_POINTS, block_of, canonical_triangles, cell_shape, chunk_nets
from ._sweeps import named, peak_memory

# Cells around a chunk's own whose points descend with its own in the first sweep: at 8 rings
# the kink that frozen ghosts at the start leave at a mesh tile's border had faded (design
# notes, "Tiles").
OVERLAP = 8
# Frozen cells beyond the overlap: the hinges of a point reach two rings, its junction line's
# neighbours one more.
FROZEN = 3
REACH = OVERLAP + FROZEN
# Owned points within this many cells of the chunk's border toward another chunk: the seams,
# whose motion ends the sweeps.
SEAM = 8
# The iterations of a descent in the sweeps after the first (as a mesh tile's band's).
SEAM_ITERATIONS = 10


def nets_task(folder: str, source, chunk: int, lo: Sequence[int], hi: Sequence[int], spacing,
              origin, background: int) -> Dict[str, Any]:
    """The nets of `chunk`'s cells `[lo, hi)`, sorted by key, into the run's folder; its
    current points are the unfaired ones."""
    start, stop = block_of(lo, hi, source.shape)
    nets = chunk_nets(source.read(start, stop), start, lo, hi, source.shape, spacing, origin,
                      background)
    order = np.argsort(nets["keys"])
    for name in ("keys", "points", "boxes"):
        nets[name] = nets[name][order]
    root = Path(folder) / "chunks"
    save(root / f"{chunk}.nets.npz", **nets)
    save(root / f"{chunk}.state.npy", nets["points"])
    return {"chunk": chunk, "points": len(nets["keys"]), "triangles": len(nets["triangles"]),
            "labels": np.unique(nets["face_labels"]), "peak_memory": peak_memory()}


def cells_of(keys: np.ndarray, shape) -> np.ndarray:
    """The cells of points named by `keys`, as (n, 3) indices."""
    return np.stack(np.unravel_index(keys // CELL_POINTS, cell_shape(shape)), axis=1)


def chunk_of_cells(cells: np.ndarray, size: Sequence[int], grid: Sequence[int]) -> np.ndarray:
    """The linear index of the chunk that owns each cell."""
    return np.ravel_multi_index(tuple((cells // np.asarray(size)).T), tuple(grid))


def build_tile(folder: str, chunk: int, lo, hi, shape, size, grid, neighbours: List[int]) -> Dict[str, Any]:
    """`chunk`'s tile from the nets of it and its `neighbours`: the triangles within REACH
    cells, their points' owners and places in the owners' arrays, and which points are the
    chunk's, descend in the first sweep, or lie on its seams."""
    root = Path(folder) / "chunks"
    lo, hi = np.asarray(lo), np.asarray(hi)
    parts = [np.load(root / f"{c}.nets.npz") for c in [chunk] + list(neighbours)]
    triangles = np.concatenate([p["triangles"] for p in parts])
    face_labels = np.concatenate([p["face_labels"] for p in parts])
    corner_cells = cells_of(triangles.ravel(), shape).reshape(-1, 3, 3)
    near = np.all((corner_cells >= lo - REACH) & (corner_cells < hi + REACH), axis=(1, 2))
    triangles, face_labels = triangles[near], face_labels[near]
    keys, local = np.unique(triangles, return_inverse=True)
    cells = cells_of(keys, shape)
    owner = chunk_of_cells(cells, size, grid)
    place = np.empty(len(keys), np.int64)
    unfaired, boxes = np.empty((len(keys), 3)), np.empty((len(keys), 3))
    for c, part in zip([chunk] + list(neighbours), parts):
        mine = owner == c
        place[mine] = np.searchsorted(part["keys"], keys[mine])
        if not np.array_equal(part["keys"][np.minimum(place[mine], len(part["keys"]) - 1)], keys[mine]):
            raise RuntimeError(f"chunk {chunk}: a triangle's corner that chunk {c} does not have")
        unfaired[mine], boxes[mine] = part["points"][place[mine]], part["boxes"][place[mine]]
    if not np.isin(owner, [chunk] + list(neighbours)).all():
        raise RuntimeError(f"chunk {chunk}: chunks smaller than {REACH} cells")
    inner_lo = np.where(lo > 0, lo + SEAM, lo)
    inner_hi = np.where(hi < np.asarray(shape) + 1, hi - SEAM, hi)
    owned = owner == chunk
    save(root / f"{chunk}.tile.npz", keys=keys, faces=local.reshape(-1, 3), face_labels=face_labels,
         unfaired=unfaired, boxes=boxes, owner=owner, place=place, owned=owned,
         overlap=np.all((cells >= lo - OVERLAP) & (cells < hi + OVERLAP), axis=1),
         seam=owned & ~np.all((cells >= inner_lo) & (cells < inner_hi), axis=1))
    return {"chunk": chunk, "points": len(keys), "triangles": len(local) // 3,
            "peak_memory": peak_memory()}


def fair_tile(folder: str, chunk: int, sweep: int, epsilon: float, keywords: Dict[str, Any],
              threads: int) -> Dict[str, Any]:
    """`chunk`'s own points faired in `sweep`, written to its file of the sweep (the client
    makes them its current points once the sweep's colour is done, so that a task run again
    reads what the first run read)."""
    from .._fairing import set_max_threads
    set_max_threads(threads)
    root = Path(folder) / "chunks"
    tile = np.load(root / f"{chunk}.tile.npz")
    owner, place, owned = tile["owner"], tile["place"], tile["owned"]
    if sweep == 1:
        current, free = tile["unfaired"], tile["overlap"]
        settings = dict(keywords)
    else:
        current = np.empty_like(tile["unfaired"])
        for c in np.unique(owner):
            mine = owner == c
            current[mine] = np.load(root / f"{c}.state.npy")[place[mine]]
        free = owned
        most = min(SEAM_ITERATIONS, keywords.get("max_iterations") or SEAM_ITERATIONS)
        settings = dict(keywords, initial_smoothing_steps=0, max_iterations=most)
    W, report = fair_interfaces(current, tile["faces"], tile["face_labels"], epsilon,
                                box_half_extents=tile["boxes"], box_centers=tile["unfaired"],
                                fixed=~free, **settings)
    moved = np.linalg.norm(W - current, axis=1) if sweep > 1 else np.zeros(len(W))
    points = np.empty((int(owned.sum()), 3))
    points[place[owned]] = W[owned]
    save(root / f"{chunk}.sweep{sweep}.npy", points)
    seam = moved[tile["seam"]]
    return {"chunk": chunk, "squared_motion": float(np.square(seam).sum()), "seam": len(seam),
            "largest_motion": float(moved[owned].max(initial=0.0)),
            "iterations": report.number_of_iterations, "peak_memory": peak_memory()}


def apply_sweep(folder: Path, chunk: int, sweep: int) -> None:
    """`chunk`'s points of `sweep` made its current points."""
    root = folder / "chunks"
    os.replace(root / f"{chunk}.sweep{sweep}.npy", root / f"{chunk}.state.npy")


def write_label(folder: str, label: int, chunks: List[int], shape, size, grid, path: str,
                to_world=None) -> Dict[str, Any]:
    """`label`'s closed surface from the triangles of `chunks` that name it, at the current
    points moved by `to_world` (axes, translation, whether it mirrors) where given, written to
    `path` (its format by its extension); its triangles in their canonical order, so that the
    file does not depend on the chunks."""
    root = Path(folder) / "chunks"
    triangles, face_labels = [], []
    for c in chunks:
        nets = np.load(root / f"{c}.nets.npz")
        mine = np.any(nets["face_labels"] == label, axis=1)
        triangles.append(nets["triangles"][mine])
        face_labels.append(nets["face_labels"][mine])
    T, FL = canonical_triangles(np.concatenate(triangles), np.concatenate(face_labels))
    keys, local = np.unique(T, return_inverse=True)
    owner = chunk_of_cells(cells_of(keys, shape), size, grid)
    points = np.empty((len(keys), 3))
    for c in np.unique(owner):
        mine = owner == c
        own_keys = np.load(root / f"{c}.nets.npz")["keys"]
        points[mine] = np.load(root / f"{c}.state.npy")[np.searchsorted(own_keys, keys[mine])]
    V, F = _core.label_surface(points, local.reshape(-1, 3).astype(np.int64), FL, int(label))
    if to_world is not None:  # as label_surfaces moves its points out of the voxels' frame
        axes, translation, mirrors = to_world
        V = V @ np.asarray(axes).T + np.asarray(translation)
        F = np.ascontiguousarray(F[:, [0, 2, 1]]) if mirrors else F
    try:
        write_mesh(path, V, F)
    except OSError as error:
        raise named(error, Path(path)) from None
    return {"label": label, "points": len(V), "triangles": len(F), "peak_memory": peak_memory()}


def save(path: Path, array=None, /, **arrays) -> None:
    """A .npy file of `array`, or a .npz file of `arrays`, written beside its place and then
    renamed: a reader never sees half a file."""
    partial = path.with_name(path.name + f".partial-{os.getpid()}")
    try:
        with open(partial, "wb") as f:
            if array is not None:
                np.save(f, array)
            else:
                np.savez(f, **arrays)
    except OSError as error:
        partial.unlink(missing_ok=True)
        raise named(error, path) from None
    os.replace(partial, path)
