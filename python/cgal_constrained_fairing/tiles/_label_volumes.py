"""A label volume too large for one process: surface nets by chunks, faired as tiles on Dask."""

import dataclasses
import itertools
import math
import os
import shutil
import time
import warnings
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from .. import _core
from . import _label_tiles
from ._label_volume_sources import volume_source

# The cells a chunk owns along each axis at first; fewer where the nets show its tile would not
# fit `tile_memory`.
CHUNK_CELLS = 128
# What a tile's task holds per triangle of its tile above an idle worker: 1.8 and 1.9 kB at 0.29
# and 0.74 M triangles (a 256^3 volume of 512 labels in chunks of 64^3 and 96^3 cells).
BYTES_PER_TRIANGLE = 2000
# The sweeps end when the seams' points moved by at most this fraction of epsilon (the voxel
# diagonal) in one, as a root mean square: the meshes' tolerance (tiles/__init__.py).
MOTION_TOLERANCE = 0.005
MAX_SWEEPS = 20
FORMATS = ("ply", "off", "obj", "stl")


@dataclasses.dataclass(frozen=True, repr=False)
class TiledLabelReport:
    """What `label_surfaces_tiled` did.

    Attributes
    ----------
    files : list of pathlib.Path
        The surfaces written, ``label_<L>.<format>``, by label.
    labels : numpy.ndarray
        The labels that have a surface, sorted.
    chunks : tuple of int
        The chunks along each axis; `chunk_cells` the cells each owns along each axis.
    colour : numpy.ndarray
        Each chunk's colour in the sweeps after the first (chunks of one colour are two apart).
    sweeps : int
        Sweeps of descents over all chunks' tiles.
    motion : list of float
        The root mean square of the motions of the seams' points in each sweep, in units of
        epsilon (0 for the first, whose points all start from the nets).
    converged : bool
        Whether the last sweep moved the seams by at most 0.5 % of epsilon.
    points, triangles : int
        The surface nets' points and triangles, the whole volume's.
    peak_memory : int
        The largest resident memory of a worker at the end of one of its tasks, in bytes.
    seconds : dict of str to float
        The wall time of each phase: ``"nets"``, ``"tiles"``, ``"sweep 1"``, ... and ``"write"``.
    """

    files: List[Path]
    labels: np.ndarray
    chunks: tuple
    chunk_cells: tuple
    colour: np.ndarray
    sweeps: int
    motion: List[float]
    converged: bool
    points: int
    triangles: int
    peak_memory: int
    seconds: Dict[str, float]

    def __repr__(self):
        return (f"TiledLabelReport({len(self.labels)} labels, {self.points} points, "
                f"{self.triangles} triangles, {int(np.prod(self.chunks))} chunks, {self.sweeps} "
                f"sweeps, converged={self.converged})")


def label_surfaces_tiled(volume, out_dir: "os.PathLike[str] | str",
                         spacing: Optional[Sequence[float]] = None,
                         origin: Optional[Sequence[float]] = None, *, affine=None, client=None,
                         chunk_cells=None, tile_memory="2GiB", background: int = 0,
                         format: str = "ply",
                         force: bool = False, work_dir: "Optional[os.PathLike[str] | str]" = None,
                         max_iterations: Optional[int] = None) -> TiledLabelReport:
    """The faired surfaces of a label volume too large for one process, one file per label.

    The in-core `label_surfaces`, by chunks: each chunk's surface nets are made from its
    voxels and a halo, its points named by the voxel grid, so that neighbouring chunks make
    the same points without talking and the whole is the in-core call's nets. The nets are
    faired as tiles with frozen ghosts: a first sweep from the smoothed start in which each
    tile's points within 8 cells of the chunk descend with its own and only its own are
    kept, then coloured sweeps of the chunks' own points until the seams move by at most
    0.5 % of epsilon. Every point stays in its box, exactly in double, and the interfaces
    stay shared: each label's file is closed, its points those of the labels it touches.

    Parameters
    ----------
    volume : path-like, zarr.Array or array_like
        The labels, ``(I, J, K)`` integers: a zarr or N5 array (a folder, or a `zarr.Array`
        on a directory store), a TIFF stack, a NIfTI file (converted once into the run's
        folder) or an array (written there); never modified.
    out_dir : path-like
        The folder of the surfaces. A new folder appears with all its files at once; an
        existing one gets only the ``label_<L>`` files, refused if one of them exists unless
        `force`, renamed into place once all are complete.
    spacing, origin : sequences of 3 floats, optional
        As in `label_surfaces`; default (1, 1, 1) and (0, 0, 0), or a NIfTI file's affine.
    affine : array_like, shape (4, 4), optional
        Instead of `spacing` and `origin`, as in `label_surfaces`: the surfaces are faired in
        the voxels' frame and written in the world. Default: a NIfTI file's own (its sform, else
        its qform, else its voxel sizes, as `read_label_map` reads it).
    client : distributed.Client, optional
        The cluster; default a `distributed.LocalCluster` of single-threaded workers for the
        run. On a cluster `work_dir` must be on a file system that every worker shares.
    chunk_cells : int or sequence of 3 ints, optional
        The cells a chunk owns along each axis, at least 16. Default: 128, fewer where the
        densest chunk's nets show that its tile (11 cells more on every side) would hold more
        than `tile_memory` at about 2,000 bytes per triangle. A size given whose tiles
        would hold more is kept, with a warning.
    tile_memory : str or int
        What a tile's task may hold (``"2GiB"``, ``"500MB"`` or bytes).
    background : int
        The label of the outside, which gets no surface.
    format : {"ply", "off", "obj", "stl"}
        The files' format.
    force : bool
        Replace existing ``label_<L>`` files of `out_dir`.
    work_dir : path-like, optional
        Where the run keeps its arrays, a new folder removed at the end; default beside
        `out_dir`.
    max_iterations : int, optional
        As in `fair`, for each tile's first descent.

    Returns
    -------
    TiledLabelReport
    """
    if affine is not None and (spacing is not None or origin is not None):
        raise ValueError("give either affine, or spacing and origin")
    if format not in FORMATS:
        raise ValueError(f"format must be one of {FORMATS} (got {format!r})")
    from dask.utils import parse_bytes
    size = _chunk_size(CHUNK_CELLS if chunk_cells is None else chunk_cells)
    budget = parse_bytes(tile_memory) if isinstance(tile_memory, str) else int(tile_memory)
    out_dir = Path(out_dir).resolve()
    _check_not_input(volume, out_dir)
    if out_dir.exists() and not out_dir.is_dir():
        raise ValueError(f"{out_dir} is a file; a label volume's surfaces go into a folder")
    folder = Path(work_dir or out_dir.parent).resolve() / f".{out_dir.name}.label-tiles-{os.getpid()}"
    folder.mkdir()
    try:
        from . import _cluster
        with _cluster(client) as (running, threads):
            source = volume_source(volume, folder)
            if affine is None and spacing is None and origin is None:
                affine = source.affine
            run = _Run(folder, source, _voxel_frame(spacing, origin, affine), int(background),
                       running, threads)
            return run.surfaces(out_dir, size, budget, chunk_cells is not None, format, force,
                                {} if max_iterations is None else {"max_iterations": int(max_iterations)})
    finally:
        shutil.rmtree(folder)


def _voxel_frame(spacing, origin, affine):
    """The voxels' spacing and origin the nets are made in, and the move of the points into the
    world (axes, translation, whether it mirrors) or None."""
    from .._labels import _checked_spacing, _Frame
    if affine is None:
        h, o = _checked_spacing((1, 1, 1) if spacing is None else spacing,
                                (0, 0, 0) if origin is None else origin)
        return h, o, None
    frame = _Frame(affine)
    return frame.spacing, np.zeros(3), (frame.axes.tolist(), frame.translation.tolist(), bool(frame.mirrors))


def _chunk_size(chunk_cells) -> np.ndarray:
    size = np.broadcast_to(np.asarray(chunk_cells, dtype=np.int64), (3,)).copy()
    if (size < 2 * _label_tiles.SEAM).any():
        raise ValueError(f"chunk_cells must be at least {2 * _label_tiles.SEAM} (got {size.tolist()})")
    return size


class _Run:
    """One run's folder, chunks and sweeps."""

    def __init__(self, folder: Path, source, frame, background: int, client, threads: int):
        self.folder, self.source = folder, source
        self.h, self.o, self.to_world = frame
        self.background, self.client, self.threads = background, client, threads
        self.seconds: Dict[str, float] = {}

    def _layout(self, size: np.ndarray) -> None:
        """Chunks of `size` cells, and a new folder for their files."""
        shutil.rmtree(self.folder / "chunks", ignore_errors=True)
        (self.folder / "chunks").mkdir()
        cells = np.asarray(self.source.shape) + 1
        self.size = size
        self.grid = tuple(int(g) for g in -(-cells // size))
        self.boxes = [(np.asarray(c) * size, np.minimum((np.asarray(c) + 1) * size, cells))
                      for c in itertools.product(*[range(g) for g in self.grid])]

    def _nets(self, size: np.ndarray, budget: int, fixed: bool) -> List[Dict[str, Any]]:
        """The chunks' nets; unless the size is `fixed`, made again in smaller chunks while the
        densest chunk's tile would hold more than `budget` (smaller chunks' densest is denser,
        so the size shrinks in a few steps, and ends at the least); a warning where a tile
        still would."""
        reach = 2 * _label_tiles.REACH
        while True:
            self._layout(size)
            nets = self._timed("nets", [self._submit(_label_tiles.nets_task, self.source, c, lo, hi,
                                                     self.h.tolist(), self.o.tolist(), self.background)
                                        for c, (lo, hi) in enumerate(self.boxes)])
            density = max(n["triangles"] / np.prod(hi - lo) for n, (lo, hi) in zip(nets, self.boxes))
            need = int(density * np.prod(size + reach) * BYTES_PER_TRIANGLE)
            fitting = int(np.cbrt(budget / BYTES_PER_TRIANGLE / max(density, 1e-9))) - reach
            smaller = np.minimum(size, max(fitting, 2 * _label_tiles.SEAM))
            if need <= budget or fixed or (smaller == size).all():
                break
            size = smaller
        if need > budget:
            warnings.warn(f"the densest chunk's tile of {(size + reach).tolist()} cells needs "
                          f"about {need} bytes, more than tile_memory ({budget})"
                          + ("; give fewer chunk_cells" if fixed else ""))
        return nets

    def _timed(self, name: str, futures) -> List[Dict[str, Any]]:
        clock = time.perf_counter()
        done = self.client.gather(futures)
        self.seconds[name] = self.seconds.get(name, 0.0) + time.perf_counter() - clock
        return done

    def _submit(self, function, *args):
        return self.client.submit(function, str(self.folder), *args, pure=False, retries=2)

    def surfaces(self, out_dir: Path, size, budget: int, fixed: bool, format: str, force: bool,
                 keywords) -> TiledLabelReport:
        nets = self._nets(size, budget, fixed)
        labels = np.unique(np.concatenate([n["labels"] for n in nets] + [np.zeros(0, np.int64)]))
        labels = labels[labels != self.background]
        if len(labels) == 0:
            raise ValueError("the label volume holds nothing but the background label")
        names = [out_dir / f"label_{int(L)}.{format}" for L in labels]
        _check_outputs(names, force)
        self._timed("tiles", [self._submit(_label_tiles.build_tile, c, lo, hi, self.source.shape,
                                           self.size, self.grid, self._neighbours(c))
                              for c, (lo, hi) in enumerate(self.boxes)])
        epsilon = _core.label_map_epsilon(self.h.tolist())
        colour = np.array([sum((x % 2) << a for a, x in enumerate(np.unravel_index(c, self.grid)))
                           for c in range(len(self.boxes))])
        motion, peak = [], max(n["peak_memory"] for n in nets)
        for sweep in range(1, MAX_SWEEPS + 1):
            done = []
            for k in ([None] if sweep == 1 else range(colour.max() + 1)):
                chunks = range(len(self.boxes)) if k is None else np.flatnonzero(colour == k)
                done += self._timed(f"sweep {sweep}", [self._submit(_label_tiles.fair_tile, int(c), sweep,
                                                                    epsilon, keywords, self.threads)
                                                       for c in chunks])
                for c in chunks:
                    _label_tiles.apply_sweep(self.folder, int(c), sweep)
            seam = sum(d["seam"] for d in done)
            motion.append(math.sqrt(sum(d["squared_motion"] for d in done) / max(seam, 1)) / epsilon)
            peak = max([peak] + [d["peak_memory"] for d in done])
            if len(self.boxes) == 1 or (sweep > 1 and motion[-1] <= MOTION_TOLERANCE):
                break
        files = self._write(labels, names, nets, out_dir)
        return TiledLabelReport(files, labels, self.grid, tuple(self.size.tolist()), colour,
                                len(motion), motion,
                                len(self.boxes) == 1 or motion[-1] <= MOTION_TOLERANCE,
                                sum(n["points"] for n in nets), sum(n["triangles"] for n in nets),
                                peak, self.seconds)

    def _neighbours(self, c: int) -> List[int]:
        at = np.array(np.unravel_index(c, self.grid))
        near = []
        for step in itertools.product((-1, 0, 1), repeat=3):
            n = at + step
            if any(step) and (n >= 0).all() and (n < self.grid).all():
                near.append(int(np.ravel_multi_index(tuple(n), self.grid)))
        return near

    def _write(self, labels, names: List[Path], nets, out_dir: Path) -> List[Path]:
        """Each label's file into a folder of the run's, then all renamed into `out_dir`."""
        staged = out_dir.parent / f".{out_dir.name}.partial-{os.getpid()}" if not out_dir.exists() \
            else out_dir / f".label_surfaces.partial-{os.getpid()}"
        staged.mkdir()
        try:
            self._timed("write", [self._submit(_label_tiles.write_label, int(L),
                                               [n["chunk"] for n in nets if L in n["labels"]],
                                               self.source.shape, self.size, self.grid,
                                               str(staged / name.name), self.to_world)
                                  for L, name in zip(labels, names)])
            if staged.parent == out_dir:
                for name in names:
                    os.replace(staged / name.name, name)
                staged.rmdir()
            else:
                os.rename(staged, out_dir)
        except BaseException:
            shutil.rmtree(staged, ignore_errors=True)
            raise
        return names


def _check_not_input(volume, out_dir: Path) -> None:
    """Refuses an output folder that is the input volume's file or store, or lies in it."""
    path = volume if isinstance(volume, (str, Path)) else \
        getattr(getattr(volume, "store", None), "path", None)
    if path is not None and Path(path).resolve() in [out_dir, *out_dir.parents]:
        raise ValueError(f"{out_dir} is the input volume or lies in it; choose another folder")


def _check_outputs(names: List[Path], force: bool) -> None:
    existing = [n for n in names if n.exists() or n.is_symlink()]
    if existing and not force:
        raise FileExistsError(f"{existing[0]} exists ({len(existing)} of the surfaces' files do); "
                              "give force=True to replace them")
    for n in existing:
        if n.is_dir():
            raise IsADirectoryError(f"{n} is a folder; it is not replaced")
