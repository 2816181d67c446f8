"""Spatial tiles of a mesh: which vertices each tile owns, its rings of ghosts, its colour.

A tile owns the vertices of one cell of a k-d split of the input points (cells of equal counts,
cut on a sample's quantiles). Its mesh is the triangles within ``rings`` rings of its owned
vertices, found among the triangles with a corner in the cell's box grown by a margin, which one
pass over the face array finds for all tiles at once (a block's corners bucketed by a grid). Its band is the part of that mesh that the sweeps after the first
need: the owned vertices within `BAND_RINGS` rings of a ghost, which descend, and the triangles
within ``rings`` rings of them. Two tiles get different colours when one's ghosts within
`OVERLAP_RINGS` + `HINGE_RINGS` rings are owned by the other: the descents of tiles of one colour
then read none of each other's points (those of the hinges of the vertices they move), and run
at once.
"""

import dataclasses
import math
from typing import List, Set, Tuple

import numpy as np

from ._ply_map import BLOCK_ROWS

# The rings around a moving vertex that its hinges reach (their triangles' corners).
HINGE_RINGS = 2
# The rings of owned vertices next to the ghosts whose motion tells whether the seams are
# mended: the sweeps after the first move little else, and a measure over all owned vertices
# would fall below its tolerance while the seams still moved.
SEAM_RINGS = 8
# The rings of owned vertices next to the ghosts that descend in the sweeps after the first:
# there the first sweep's tiles met ghosts that had not descended yet (or had, while they had
# not); the vertices deeper in stay where the first sweep left them.
BAND_RINGS = 16
# The rings of ghosts that descend with a tile's owned vertices in the first sweep, their points
# then dropped (an overlap, as in restricted Schwarz methods): ghosts frozen at the smoothed
# start, where no tile has faired them yet, bent the owned vertices next to them, and the sweeps
# after the first mended that kink slowly.
OVERLAP_RINGS = 8
# The points whose quantiles make the k-d cuts, at most: cells of equal counts of a sample hold
# counts of all the points within about one over the square root of a cell's sample of each
# other (0.3 % for 16 cells), and the client holds the sample, not copies of the cells' points.
CUT_SAMPLE = 1 << 21
# The cells per axis of the grid that buckets faces for the boxes that search them: a box of
# a tile of T spans about 32^3 / T cells, and a corner is tested against the few boxes whose
# cells hold it; 32^3 cells have keys of 15 bits, sorted by radix.
GRID_CELLS = 32


@dataclasses.dataclass
class Tiles:
    """The k-d cells: each vertex's tile and each tile's box."""

    tile: np.ndarray    # (n,) int32, each vertex's tile
    boxes: np.ndarray   # (T, 2, 3): each tile's lower and upper corner

    @property
    def count(self) -> int:
        return len(self.boxes)


def kd_tiles(points: np.ndarray, count: int, across: int = 0) -> Tiles:
    """`points` split into `count` cells of equal counts, each cut across its widest extent, or
    its second widest for `across` 1: a cut whose borders cross the first's, which shows how far
    a result depends on where the borders lie. The cuts are quantiles of every k-th point, at
    most `CUT_SAMPLE` of them; the points are then put in their cells and the cells' boxes found
    a block at a time, so that no copy of the points is made."""
    step = max(1, math.ceil(len(points) / CUT_SAMPLE))
    tree = _Kd_tree(np.asarray(points[::step], np.float64), step, count, across)
    tile = np.empty(len(points), np.int32)
    boxes = np.stack([np.full((tree.leaves, 3), np.inf), np.full((tree.leaves, 3), -np.inf)], 1)
    for begin in range(0, len(points), BLOCK_ROWS):
        p = np.asarray(points[begin:begin + BLOCK_ROWS], np.float64)
        t = tree.cell(p, begin + np.arange(len(p)))
        tile[begin:begin + len(p)] = t
        order = np.argsort(t, kind="stable")
        present, first = np.unique(t[order], return_index=True)
        boxes[present, 0] = np.minimum(boxes[present, 0], np.minimum.reduceat(p[order], first))
        boxes[present, 1] = np.maximum(boxes[present, 1], np.maximum.reduceat(p[order], first))
    return Tiles(tile, boxes)


class _Kd_tree:
    """The cuts of a k-d split of a sample (every `step`-th point) into `count` cells: a cell
    to become k cells is cut at the quantile that leaves k // 2 of them below, so that all end
    alike (halving the cell of most points, as before, left cells of 1/8 and 1/16 of the mesh for
    15). Each node's axis (-1 at a cell), value and children, and at a cell its number; a point
    on a cut goes below it when its index is below the cut's `tie` (points alike across the
    axis, as on a CAD part's planes, are split by their order)."""

    def __init__(self, sample: np.ndarray, step: int, count: int, across: int):
        self.axis, self.value, self.tie, self.children = [-1], [0.0], [0], [(0, 0)]
        cells = [(0, sample, np.arange(len(sample)) * step, count)]
        c = 0
        while c < len(cells):
            node, members, ids, leaves = cells[c]
            rank = len(members) * (leaves // 2) // max(leaves, 1)
            if leaves < 2 or rank == 0:
                c += 1  # one cell, or too few points to cut
                continue
            axis = int(np.argsort(members.min(axis=0) - members.max(axis=0), kind="stable")[across])
            value, tie = _quantile(members[:, axis], ids, rank)
            below = _below(members[:, axis], ids, value, tie)
            low, high = self._add(), self._add()
            self.axis[node], self.value[node], self.tie[node] = axis, value, tie
            self.children[node] = (low, high)
            cells[c:c + 1] = [(low, members[below], ids[below], leaves // 2),
                              (high, members[~below], ids[~below], leaves - leaves // 2)]
        self.number = np.full(len(self.axis), -1)
        self.number[[cell[0] for cell in cells]] = np.arange(len(cells))
        self.axis, self.value, self.tie, self.children = (
            np.array(self.axis), np.array(self.value), np.array(self.tie), np.array(self.children))

    def _add(self) -> int:
        for nodes, empty in ((self.axis, -1), (self.value, 0.0), (self.tie, 0),
                             (self.children, (0, 0))):
            nodes.append(empty)
        return len(self.axis) - 1

    @property
    def leaves(self) -> int:
        return int(self.number.max()) + 1

    def cell(self, p: np.ndarray, ids: np.ndarray) -> np.ndarray:
        """The cell of each point of `p` (of indices `ids`), down the cuts a level at a time."""
        node = np.zeros(len(p), np.int64)
        inner = np.flatnonzero(self.axis[node] >= 0)
        while inner.size:
            at = node[inner]
            low = _below(p[inner, self.axis[at]], ids[inner], self.value[at], self.tie[at])
            node[inner] = self.children[at, (~low).astype(np.int64)]
            inner = inner[self.axis[node[inner]] >= 0]
        return self.number[node].astype(np.int32)


def _quantile(x: np.ndarray, ids: np.ndarray, rank: int):
    """The cut (value, tie) that puts the `rank` points of smallest (x, id) below."""
    value = np.partition(x, rank)[rank]
    ties = np.sort(ids[x == value])
    return float(value), int(ties[rank - int((x < value).sum())])


def _below(x, ids, value, tie) -> np.ndarray:
    return (x < value) | ((x == value) & (ids < tie))


def candidate_faces(corners: np.ndarray, points: np.ndarray,
                    boxes: np.ndarray) -> List[np.ndarray]:
    """For each box ((T, 2, 3)), the faces with a corner in it, in one pass over the face array
    a block at a time. A block's corners are bucketed by the cells of a grid over the boxes,
    and each box tests only the faces with a corner in the cells it overlaps: the pass costs
    about the faces times the boxes a corner lies in, not times all the boxes."""
    low, high = boxes[:, 0].min(axis=0), boxes[:, 1].max(axis=0)
    size = np.maximum(high - low, np.finfo(float).tiny) / GRID_CELLS

    def cell(x):  # a point outside the grid in its nearest cell, which the test then refuses
        return np.clip(((x - low) / size).astype(np.int32), 0, GRID_CELLS - 1)
    spans = [(cell(box[0]), cell(box[1])) for box in boxes]
    found: List[List[np.ndarray]] = [[] for _ in boxes]
    for begin in range(0, len(corners), BLOCK_ROWS):
        block = np.asarray(corners[begin:begin + BLOCK_ROWS], np.int64)
        p = points[block.ravel()]
        c = cell(p)
        # Keys of 15 bits, which numpy sorts by radix.
        keys = (c[:, 0] + GRID_CELLS * (c[:, 1] + GRID_CELLS * c[:, 2])).astype(np.int16)
        order = np.argsort(keys, kind="stable")
        # The cells the block's corners occupy, each a run of `order`.
        first = np.flatnonzero(np.diff(keys[order], prepend=-1))
        counts = np.diff(first, append=len(keys))
        occupied = c[order[first]]
        p = p.reshape(-1, 3, 3)
        for t, (lower, upper) in enumerate(spans):
            runs = ((occupied >= lower) & (occupied <= upper)).all(axis=1)
            near = np.zeros(len(block), bool)  # a mask, not a sort: a face holds 3 corners
            near[order[concatenated_ranges(first[runs], counts[runs])] // 3] = True
            faces = np.flatnonzero(near)
            box = boxes[t]
            inside = ((p[faces] >= box[0]) & (p[faces] <= box[1])).all(axis=2).any(axis=1)
            found[t].append(begin + faces[inside])
    return [np.concatenate(f) if f else np.zeros(0, np.int64) for f in found]


def concatenated_ranges(first: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """The integers of the ranges [first, first + counts), one after the other."""
    return np.repeat(first - np.cumsum(counts) + counts, counts) + np.arange(counts.sum())


def grown(box: np.ndarray, margin: float) -> np.ndarray:
    return box + np.array([[-margin], [margin]])


@dataclasses.dataclass
class Tile_mesh:
    """One tile's triangles, over its vertices (global ids), which vertices it owns, and the
    owners of its ghosts within `OVERLAP_RINGS` + `HINGE_RINGS` rings, whose points its
    descents read."""

    vertices: np.ndarray   # (k,) int64, global ids
    faces: np.ndarray      # (f,) int64 global face ids, in the input's order
    local_faces: np.ndarray  # (f, 3) int32 into vertices
    owned: np.ndarray      # (k,) bool
    seam: np.ndarray       # (k,) bool, the owned vertices within SEAM_RINGS rings of a ghost
    overlap: np.ndarray    # (k,) bool, the vertices within OVERLAP_RINGS rings of an owned one
    near_owners: np.ndarray  # tiles owning vertices within OVERLAP_RINGS + HINGE_RINGS rings
    rings: "Rings"           # the rings around its vertices, over local_faces


@dataclasses.dataclass
class Band_mesh:
    """The part of a tile's mesh that descends after the first sweep: its vertices (into the
    tile's), its triangles over them, which of them descend and which are seam vertices."""

    vertices: np.ndarray     # (b,) int64 into the tile's vertices
    local_faces: np.ndarray  # (g, 3) int32 into vertices
    free: np.ndarray         # (b,) bool, the owned vertices within BAND_RINGS rings of a ghost
    seam: np.ndarray         # (b,) bool, the tile's seam vertices


class MarginTooSmall(Exception):
    """The rings left the region searched for triangles."""


def tile_mesh(t: int, tiles: Tiles, corners, points, rings: int, box, faces) -> Tile_mesh:
    """Tile `t`'s triangles within `rings` rings of its owned vertices, found among `faces`,
    those with a corner in `box`; MarginTooSmall if the rings reach beyond it."""
    local = np.asarray(corners[faces] if len(faces) else np.zeros((0, 3)), np.int64)
    vertices, local = np.unique(local, return_inverse=True)
    local = local.reshape(-1, 3)
    owned = tiles.tile[vertices] == t
    around = Rings(local, len(vertices))
    near = around.within(owned, OVERLAP_RINGS + HINGE_RINGS)
    inner = around.within(owned, rings - 1)
    kept = _closed_fans(local, inner[local].any(axis=1), len(vertices),
                        lambda bad: _check_inside(points[vertices[bad]], box))
    _check_inside(points[vertices][inner], box)
    used, local_faces = _used_and_renumbered(local, kept, len(vertices))
    near_owners = np.unique(tiles.tile[vertices[near & used]])
    around = Rings(local_faces, int(used.sum()))
    seam = around.within(~owned[used], SEAM_RINGS) & owned[used]
    overlap = around.within(owned[used], OVERLAP_RINGS)
    return Tile_mesh(vertices[used], faces[kept], local_faces, owned[used], seam, overlap,
                     near_owners[near_owners != t], around)


def owned_edge_lengths(mesh: Tile_mesh, X: np.ndarray) -> Tuple[float, int]:
    """The sum and the number of the lengths, at the points `X` of the tile's vertices, of its
    edges whose endpoint of smaller global id it owns: over all tiles, every edge of the mesh
    once, as the mean edge length counts them (a ghost ring holds an owned vertex's edges)."""
    a, b = mesh.local_faces.ravel(), np.roll(mesh.local_faces, -1, axis=1).ravel()
    owner = np.where(mesh.vertices[a] < mesh.vertices[b], a, b)
    kept = mesh.owned[owner]
    a, b = a[kept], b[kept]
    edges = np.unique(np.minimum(a, b).astype(np.int64) * len(X) + np.maximum(a, b))
    a, b = edges // len(X), edges % len(X)
    return float(np.linalg.norm(X[a] - X[b], axis=1).sum()), len(edges)


def band_mesh(mesh: Tile_mesh, rings: int) -> Band_mesh:
    """The triangles of `mesh` within `rings` rings of its owned vertices within `BAND_RINGS`
    rings of a ghost, and which of their vertices descend. The ghosts within `rings` rings of an
    owned vertex are within as many of one next to a ghost, so the band keeps all of them, and
    the band's start and normals are the tile's at its descending vertices."""
    free = mesh.rings.within(~mesh.owned, BAND_RINGS) & mesh.owned
    inner = mesh.rings.within(free, rings - 1)
    n = len(mesh.owned)
    kept = _closed_fans(mesh.local_faces, inner[mesh.local_faces].any(axis=1), n)
    used, local_faces = _used_and_renumbered(mesh.local_faces, kept, n)
    return Band_mesh(np.flatnonzero(used), local_faces, free[used], mesh.seam[used])


def _used_and_renumbered(faces: np.ndarray, kept: np.ndarray, n: int):
    """Which of `n` vertices the `kept` faces use, and those faces over them alone."""
    used = np.zeros(n, bool)
    used[faces[kept].ravel()] = True
    return used, (np.cumsum(used) - 1)[faces[kept]].astype(np.int32)


class Rings:
    """The rings of vertices around sets of vertices of a triangle mesh: each vertex's faces
    from one sort of the corners, then one ring at a time over the faces of the vertices the
    last ring reached."""

    def __init__(self, faces: np.ndarray, n: int):
        self.faces = faces
        corners = faces.ravel()
        self.order = np.argsort(corners, kind="stable")
        self.first = np.searchsorted(corners[self.order], np.arange(n + 1))

    def within(self, start: np.ndarray, rings: int) -> np.ndarray:
        """The vertices within `rings` rings of those of `start` ((n,) bool)."""
        reached = start.copy()
        frontier = np.flatnonzero(start)
        for _ in range(rings):
            if frontier.size == 0:
                break
            counts = self.first[frontier + 1] - self.first[frontier]
            # The positions in `order` of the frontier's corners.
            runs = concatenated_ranges(self.first[frontier], counts)
            near = self.faces[self.order[runs] // 3].ravel()
            frontier = np.unique(near[~reached[near]])
            reached[frontier] = True
        return reached


def _closed_fans(local: np.ndarray, kept: np.ndarray, n: int, check=None) -> np.ndarray:
    """`kept` with the whole fan of each vertex whose kept triangles form more than one fan
    (a vertex on more than two border edges), so that the tile is a manifold mesh; `check`
    is called on the vertices whose fans are added."""
    for _ in range(64):
        bad = _split_fan_vertices(local[kept], n)
        if bad.size == 0:
            return kept
        if check is not None:
            check(bad)
        is_bad = np.zeros(n, bool)
        is_bad[bad] = True
        kept = kept | is_bad[local].any(axis=1)
    raise MarginTooSmall()


def _split_fan_vertices(faces: np.ndarray, n: int) -> np.ndarray:
    edges = np.sort(np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), axis=1)
    # Each edge as one integer: a 1-D unique is many times faster than one over rows.
    keys, counts = np.unique(edges[:, 0].astype(np.int64) * n + edges[:, 1], return_counts=True)
    border = keys[counts == 1]
    on_border = np.bincount(np.concatenate([border // n, border % n]), minlength=n)
    return np.flatnonzero(on_border > 2)


def _check_inside(p: np.ndarray, box) -> None:
    if len(p) and not ((p >= box[0]) & (p <= box[1])).all():
        raise MarginTooSmall()


def adjacency(neighbours: List[np.ndarray]) -> List[Set[int]]:
    """Each tile's neighbours, taken both ways (a tile's own: the tiles owning its ghosts
    within `HINGE_RINGS` rings)."""
    adjacent: List[Set[int]] = [set() for _ in neighbours]
    for t, near in enumerate(neighbours):
        for s in near:
            adjacent[t].add(int(s))
            adjacent[int(s)].add(t)
    return adjacent


def colour_tiles(adjacent: List[Set[int]]) -> np.ndarray:
    """Greedy colours of the tiles, no two neighbours alike, the tiles of most neighbours
    first."""
    count = len(adjacent)
    colour = np.full(count, -1)
    for t in sorted(range(count), key=lambda t: -len(adjacent[t])):
        taken = {colour[s] for s in adjacent[t]}
        colour[t] = next(c for c in range(count + 1) if c not in taken)
    return colour
