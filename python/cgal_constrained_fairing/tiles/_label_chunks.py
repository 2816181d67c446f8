"""The surface nets of one chunk of a label volume, named by the voxel grid.

A chunk owns the dual cells of a box of the cell grid (cell ``c`` lies between voxels ``c - 1``
and ``c`` on each axis, ``0 <= c <= n``, as in ``label_surface_nets()``). Its nets are made from
its voxels with `HALO` more on every side: every choice the nets make for a cell (its points,
their boxes, the cuts of its faces, the untangling moves) depends on voxels near it, so that the
owned cells get the points that the whole volume's nets give them, without the chunks talking.
A point is named by its cell and its rank among its cell's points (``key = cell * CELL_POINTS +
rank``, ``cell`` the linear index of the whole volume's cell grid): the in-core call numbers
points in the order of their cells and within a cell by their first triangle, so sorting the
keys gives its numbering. A triangle is owned by the chunk that owns its corner of least key.
"""

from typing import Dict, Sequence, Tuple

import numpy as np

from .. import _core

# The voxels beyond a chunk's cells on every side whose labels its nets read. A cell's points
# and cuts read its neighbours' voxels, but the untangling moves points for up to 8 rounds, each
# reaching a ring farther, and compares them with the triangles around: on random voxels of 3 to
# 6 labels in chunks of 8 cells (test_label_volumes_tiled.py), a halo of 6 left 5 of 8,993
# points 1e-7 from the whole volume's, 10 none.
HALO = 10
# The points of one cell at most, and then some: a cell of four labels on opposite voxels gets
# a point on each of its 12 edges around the centre, two where faces pair up, and a ball's.
CELL_POINTS = 64


def cell_shape(shape: Sequence[int]) -> Tuple[int, int, int]:
    """The whole volume's grid of dual cells."""
    return tuple(int(s) + 1 for s in shape)


def block_of(lo: Sequence[int], hi: Sequence[int], shape: Sequence[int], halo: int = HALO):
    """The voxels `[start, stop)` whose labels the nets of owned cells `[lo, hi)` read."""
    start = np.maximum(np.asarray(lo) - 1 - halo, 0)
    stop = np.minimum(np.asarray(hi) + halo, np.asarray(shape))
    return start, stop


def chunk_nets(block: np.ndarray, start: Sequence[int], lo: Sequence[int], hi: Sequence[int],
               shape: Sequence[int], spacing, origin, background: int) -> Dict[str, np.ndarray]:
    """The points of the owned cells `[lo, hi)` and the triangles owned by the chunk, from
    `block`, the voxels from `start` on (`block_of`).

    Returns a dict of ``keys`` (int64), ``points`` and ``boxes`` (float64, the unfaired points
    and their boxes' half-extents), ``triangles`` (int64 keys of the corners, oriented as the
    in-core nets) and ``face_labels`` (int64, the two labels of each triangle).
    """
    h, o = np.asarray(spacing, np.float64), np.asarray(origin, np.float64)
    V, F, FL, H = _core.label_surface_nets(np.ascontiguousarray(block, dtype=np.int64), h.tolist(),
                                           o.tolist(), int(background),
                                           [int(s) for s in start])
    cells = np.floor((V - o) / h).astype(np.int64) + 1
    keys = _keys(cells, cell_shape(shape))
    owned = np.all((cells >= lo) & (cells < hi), axis=1)
    corner_keys = keys[F]
    first = np.argmin(corner_keys, axis=1)
    first_cells = cells[F[np.arange(len(F)), first]]
    mine = np.all((first_cells >= lo) & (first_cells < hi), axis=1)
    return {"keys": keys[owned], "points": V[owned], "boxes": H[owned],
            "triangles": corner_keys[mine], "face_labels": FL[mine]}


def _keys(cells: np.ndarray, grid: Tuple[int, int, int]) -> np.ndarray:
    """Each point's key: its cell's linear index times CELL_POINTS plus its rank among the
    points of its cell, in the nets' order."""
    linear = (cells[:, 0] * grid[1] + cells[:, 1]) * grid[2] + cells[:, 2]
    order = np.argsort(linear, kind="stable")
    ordered = linear[order]
    new_cell = np.r_[True, ordered[1:] != ordered[:-1]]
    first_of_cell = np.maximum.accumulate(np.where(new_cell, np.arange(len(ordered)), 0))
    rank = np.empty_like(linear)
    rank[order] = np.arange(len(ordered)) - first_of_cell
    if len(rank) and rank.max() >= CELL_POINTS:
        raise RuntimeError(f"a dual cell with {rank.max() + 1} points, more than {CELL_POINTS}")
    return linear * CELL_POINTS + rank


def canonical_triangles(triangles: np.ndarray, face_labels: np.ndarray):
    """Triangles (and their labels) each turned to start at its least corner, sorted: an
    order that depends on the triangles alone, not on the chunks that made them. Keys and the
    in-core call's point indices are in the same order, so that its soup so sorted gives each
    label's surface the same vertices and triangles in the same order."""
    T = np.asarray(triangles)
    turn = (np.argmin(T, axis=1)[:, None] + np.arange(3)) % 3
    T = np.take_along_axis(T, turn, 1)
    order = np.lexsort((T[:, 2], T[:, 1], T[:, 0]))
    return T[order], np.asarray(face_labels)[order]
