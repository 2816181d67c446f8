"""Constrained fairing of one mesh too large for one process: tiles with frozen ghosts on Dask.

`fair_tiled` cuts the mesh into spatial tiles of about `tile_memory` each, every tile with rings
of its neighbours' vertices (ghosts) around the vertices it owns, and fairs the tiles as Dask
tasks, in sweeps in which the tiles of one colour (none reading another's points) descend at
once, from the smoothed start of the whole call where no tile has yet been. In the first sweep a
tile's ghosts within 8 rings of its vertices descend with them and are then dropped (an overlap),
the ghosts beyond frozen; after it, only each tile's band (its vertices within 16 rings of its
ghosts) descends, over the band's part of the tile's mesh, its ghosts frozen, until the vertices
next to the ghosts move by at most 0.5 % of epsilon in a sweep (RMS). Every vertex's bound is its
own, so each descent stays within the whole's bound, and those after the first lower the whole's
objective (a Schwarz method); the result approaches the in-core call's. No process holds the
whole mesh's fairing state: a task holds its tile's, the client the points and the tiles' plan.

The mesh is read in place when it is a binary PLY file (a memory map); another format is
converted once, in memory, into the run's folder. The output is a binary PLY file in the input's
vertex order with its properties, the faired positions in double, ``deviation`` and
``at_bound`` added, and the input's face block byte for byte.

From the command line::

    python3 -m cgal_constrained_fairing.tiles scan.ply faired.ply --eps 0.25h \\
        [--scheduler tcp://HOST:8786] [--tile-memory 2GiB]

On a cluster, the run's folder (`work_dir`, by default beside the output) must be on a file
system that every worker reads and writes.
"""

import dataclasses
import math
import os
import shutil
import time
import warnings
from pathlib import Path
from typing import Any, Dict, List, Optional

import numpy as np

from .. import _core
from .._fairing import call_options
from .._io import read_mesh
from ..batch._epsilon import parse_eps
from . import _partition, _ply_map, _sweeps
from ._streamed_conversion import NotStreamed, convert_streamed
from ._command_line import main
from ._label_volumes import TiledLabelReport, label_surfaces_tiled

__all__ = ["TiledLabelReport", "TiledReport", "fair_tiled", "label_surfaces_tiled", "main"]

# What a tile's task holds per triangle of its mesh, above an idle worker: measured 553 bytes at
# 197,000 triangles (the library's call holds about 340 for the tile's problem; the part that
# descends and the task's copies of points and faces add the rest), building it 500.
BYTES_PER_TRIANGLE = 600
# A sweep ends the run when the owned vertices next to the ghosts (the seams) moved by at most
# this fraction of epsilon in it, as a root mean square: the largest motion does not fall so far,
# since ten more iterations of the whole call from its own result move single vertices by 0.2
# to 0.4 epsilon. At 1 % the seams still moved by about 0.8 % a sweep, and the normal error
# within 3 rings of a tile border stayed 1.21 times the interiors' at 4.8 M triangles (1.88 at
# 19.3 M); at 0.5 % it was 1.02 times (0.3 %: 0.92, in 11 sweeps instead of 7). Since the first
# sweep's overlap, the first sweep after it ends below 0.5 % (0.34, 0.49 and 0.49 % at 1.2, 4.8
# and 19.3 M), the borders' normal error 0.87 to 0.89 times the interiors', as in core.
MOTION_TOLERANCE = 0.005
MAX_SWEEPS = 20
# The iterations of a tile's band's descent in the sweeps after the first, which mend the seams:
# the first descends each tile to the stopping rule; 10 and 25 left the same distance to the
# in-core result (0.076 and 0.075 epsilon RMS on the noisy camel in 6 tiles) and the same
# sweeps, and 40 the same seam motions at 4.8 M triangles for 3.6 times the time.
SEAM_ITERATIONS = 10
# The least tiles per task slot of the cluster once a mesh needs more than one tile: a tile of
# the first sweep waits for its neighbours of the colours before its own (4 or 5 colours), so
# with few tiles a slot idles. At 4.8 M triangles on 2 slots, 7, 8, 9, 10, 12, 16 and 24 tiles
# took 159, 112, 120, 117, 132, 149 and 153 s (in core 94 s on both cores; 117, 80, 85, 82, 85,
# 101 and 94 s in the first sweep), so 4 a slot; but no tile of fewer triangles than
# SMALLEST_TILE, where the ghosts add about 30 % to the vertices (15 % at 8 tiles there).
TILES_PER_SLOT = 4
SMALLEST_TILE = 200_000
# How long a run waits for a worker when the client's scheduler has none.
WORKER_WAIT_SECONDS = 60


@dataclasses.dataclass(frozen=True, repr=False)
class TiledReport:
    """What `fair_tiled` did.

    Attributes
    ----------
    tile : numpy.ndarray
        ``(n,)`` int32, the tile that owns each vertex.
    colour : numpy.ndarray
        ``(T,)``, each tile's colour: tiles of one colour share no hinge and run at once.
    sweeps : int
        Sweeps of descents over all tiles.
    motion : list of float
        The root mean square of the motions in each sweep of the owned vertices within 8 rings
        of a ghost, where the seams are mended, in units of epsilon (0 in the first, whose
        vertices all descend from the start).
    largest_motion : list of float
        The largest motion of an owned vertex in each sweep, in units of epsilon.
    iterations : list of int
        The iterations of all tiles in each sweep.
    converged : bool
        Whether the last sweep moved the seams' vertices by at most `MOTION_TOLERANCE` (0.5 %)
        of epsilon (root mean square).
    epsilon : float
        The bound, as given or as measured from the tiles (``"0.25h"``, ``"auto"``).
    max_deviation : float
        The largest distance of an output vertex to its input position.
    tile_sizes : numpy.ndarray
        ``(T, 2)``: each tile's vertices with its ghosts, and its triangles.
    peak_memory : int
        The largest resident memory of a worker process at the end of one of its tasks, in
        bytes: what a worker's memory limit must hold.
    seconds : dict of str to float
        The wall time of each phase: ``"read"`` (the input's arrays), ``"tiles"`` (cutting
        and building them), ``"sweep 1"``, ... and ``"write"``.
    """

    tile: np.ndarray
    colour: np.ndarray
    sweeps: int
    motion: List[float]
    largest_motion: List[float]
    iterations: List[int]
    converged: bool
    epsilon: float
    max_deviation: float
    tile_sizes: np.ndarray
    peak_memory: int
    seconds: Dict[str, float] = dataclasses.field(default_factory=dict)

    def __repr__(self):
        return (f"TiledReport({len(self.colour)} tiles in {self.colour.max() + 1} colours, "
                f"{self.sweeps} sweeps, last motion {self.motion[-1] if self.motion else 0:.3g} "
                f"eps, converged={self.converged}, epsilon={self.epsilon:.6g}, "
                f"max_deviation={self.max_deviation:.6g})")


def fair_tiled(in_path: "os.PathLike[str] | str", out_path: "os.PathLike[str] | str",
               epsilon: float, *, client=None, tile_memory="2GiB",
               work_dir: "Optional[os.PathLike[str] | str]" = None,
               **fair_keywords) -> TiledReport:
    """Fair the mesh file `in_path` into `out_path` (binary PLY) as tiles on a Dask cluster.

    Parameters
    ----------
    in_path : path-like
        A triangle mesh file: binary PLY is read in place; OFF and OBJ files of triangles are
        converted a block of lines at a time, other files (polygons, STL, ASCII PLY) read whole
        and converted.
    out_path : path-like
        The output, a ``.ply`` file; written beside its place and renamed when complete, so
        that an existing file of that name (never the input, nor a folder) is replaced only by
        a complete output.
    epsilon : float or str
        The largest distance a vertex may move, as in `fair`, or as the command-line tool's
        ``--eps`` reads it (``"0.25h"``, a fraction of the mean edge length, or ``"auto"``):
        measured from the tiles, as the whole mesh's up to rounding, the noise estimate with
        the client holding one number per vertex.
    client : distributed.Client, optional
        The cluster to run on. Default: a `distributed.LocalCluster` of one single-threaded
        process per core, for the run only.
    tile_memory : str or int
        What a tile's task may hold (``"2GiB"``, ``"500MB"`` or bytes): the tiles are made
        small enough, at about 600 bytes per triangle; once the mesh needs more than one, at
        least 4 per thread of the cluster's workers (none under 200,000 triangles), so that
        no worker waits for the colours before its tile's.
    work_dir : path-like, optional
        Where the run keeps its arrays; a new folder in it is removed at the end. Default: the
        output's folder.
    **fair_keywords
        The settings of `fair` (``max_iterations``, ``objective``, ...), but the per-vertex
        arrays, ``region``, ``feature_edges`` and ``feature_angle``, which tiles do not take.

    Returns
    -------
    TiledReport
        Each vertex's tile, the colours, the sweeps and their motions.

    Raises
    ------
    InputError
        A tile's mesh was rejected (the defect of the input around it).
    ValueError
        A file that cannot be read, an output that is not PLY or is the input, a keyword
        tiles do not take.
    """
    from dask.utils import parse_bytes
    in_path, out_path = Path(in_path).resolve(), Path(out_path).resolve()
    _check_paths(in_path, out_path)
    _check_keywords(fair_keywords)
    eps = parse_eps(epsilon)
    call_options(eps[1] if eps[0] == "value" else 1.0, **fair_keywords)  # before anything is made
    budget = parse_bytes(tile_memory) if isinstance(tile_memory, str) else int(tile_memory)
    folder = Path(work_dir or out_path.parent).resolve() / f".{out_path.name}.tiles-{os.getpid()}"
    folder.mkdir()
    try:
        with _cluster(client) as (running, threads):
            clock = time.perf_counter()
            run = _Run(folder, in_path, eps, fair_keywords, running, threads)
            run.seconds["read"] = time.perf_counter() - clock
            report = run.fair(budget)
            clock = time.perf_counter()
            run.write(out_path)
            run.seconds["write"] = time.perf_counter() - clock
        return dataclasses.replace(report, seconds=run.seconds)
    finally:
        shutil.rmtree(folder)


def _check_paths(in_path: Path, out_path: Path) -> None:
    if not in_path.is_file():
        raise FileNotFoundError(f"{in_path}: no such file")
    if out_path.is_dir():
        raise ValueError(f"{out_path} is a folder; name the output file (.ply)")
    if out_path.suffix.lower() != ".ply":
        raise ValueError(f"{out_path}: a tiled fairing writes PLY; name the output .ply")
    if out_path.exists() and os.path.samefile(in_path, out_path):
        raise ValueError(f"{out_path} is the input; choose another output")


_NOT_TILED = ("tolerance", "fixed", "region", "feature_edges", "feature_angle",
              "box_half_extents", "box_centers", "bound", "progress")


def _check_keywords(keywords: Dict[str, Any]) -> None:
    for name in keywords:
        if name in _NOT_TILED:
            raise ValueError(f"fair_tiled does not take {name!r}: tiles fair the whole mesh "
                             "within the ball bound, without creases")


class _cluster:
    """The caller's client, or a local cluster of single-threaded workers for the run; with
    the threads each task's library loops may take."""

    def __init__(self, client):
        self.client, self.cluster = client, None

    def __enter__(self):
        if self.client is not None:
            return self.client, _threads_per_task(self.client)
        import distributed
        self.cluster = distributed.LocalCluster(n_workers=os.cpu_count() or 1,
                                                threads_per_worker=1, dashboard_address=None)
        self.client = distributed.Client(self.cluster, set_as_default=False)
        return self.client, 1

    def __exit__(self, *exc):
        if self.cluster is not None:
            self.client.close()
            self.cluster.close()


def _threads_per_task(client) -> int:
    """The cores of a machine over the tasks its workers run at once, the least over the
    machines: the library's loops of concurrent tasks then share the cores. A scheduler with
    no worker yet (one starting, or scaling up) is given `WORKER_WAIT_SECONDS` for one."""
    if not client.nthreads():
        try:
            client.wait_for_workers(1, timeout=WORKER_WAIT_SECONDS)
        except TimeoutError:
            raise TimeoutError(f"no Dask worker joined the scheduler {client.scheduler.address} "
                               f"within {WORKER_WAIT_SECONDS} s") from None
    cores = client.run(os.cpu_count)
    on_host: Dict[str, int] = {}
    for address, threads in client.nthreads().items():
        host = address.rsplit(":", 1)[0]
        on_host[host] = on_host.get(host, 0) + threads
    return max(1, min((cores[a] or 1) // on_host[a.rsplit(":", 1)[0]] for a in cores))


def _fitting_count(count: int, faces: int, largest: int, most: float) -> Optional[int]:
    """The tiles to cut next, when a cut into `count` tiles of `faces` triangles in all made
    one of `largest` triangles with its ghosts, over `most`; None when it fits, or when the
    ghosts alone would fill a tile (a patch of f owned triangles has ghosts g sqrt(f), and
    f + g sqrt(f) <= most for f up to the square of (sqrt(g^2 + 4 most) - g) / 2)."""
    if largest <= most:
        return None
    own = faces / count
    ghosts = (largest - own) / math.sqrt(own)
    if ghosts ** 2 >= most:
        return None
    fitting = ((math.sqrt(ghosts ** 2 + 4 * most) - ghosts) / 2) ** 2
    return max(count + 1, math.ceil(faces / fitting))


def _tiles_epsilon(eps, built: List[Dict[str, Any]]) -> float:
    """The epsilon of an ``"h"`` or ``"auto"`` `eps` from the tiles' parts: the mean edge
    length from their owned edges, the noise estimate from the median of their owned vertices'
    heights; the whole mesh's, up to the rounding of sums in another order."""
    kind, value = eps
    if kind == "h":
        return value * sum(b["edge_length"] for b in built) / max(1, sum(b["edges"] for b in built))
    heights = np.concatenate([b.pop("noise_heights") for b in built])
    noise = _core.noise_radius(heights[~np.isnan(heights)])
    if not noise > 0:
        raise ValueError("cannot estimate the noise level of so small a mesh; give eps")
    return noise


class _Run:
    """One run's folder, mesh, tiles and sweeps."""

    def __init__(self, folder: Path, in_path: Path, eps, keywords, client, threads):
        self.folder, self.keywords = folder, keywords
        self.seconds: Dict[str, float] = {}
        self.client, self.threads = client, threads
        if not _ply_map.is_binary_ply(in_path):
            converted = folder / "input.ply"
            try:
                convert_streamed(in_path, converted)
            except NotStreamed:  # properties, polygons, STL's soups: the file read whole
                _ply_map.convert_to_ply(read_mesh, in_path, converted)
            in_path = converted
        self.mesh = _ply_map.map_ply(in_path)
        _ply_map.check_triangles(self.mesh)
        self._write_arrays()
        self.eps, self.epsilon = eps, eps[1] if eps[0] == "value" else None

    def _write_arrays(self) -> None:
        n = self.mesh.vertex.count
        records = self.mesh.vertices()
        points = _sweeps.open_array_new(self.folder / "input.npy", (n, 3), np.float64)
        for axis, name in enumerate("xyz"):
            points[:, axis] = records[name]
        state = _sweeps.open_array_new(self.folder / "state.npy", (n, 3), np.float64)
        state[:] = points
        _sweeps.open_array_new(self.folder / "deviation.npy", (n,), np.float64)
        _sweeps.open_array_new(self.folder / "at_bound.npy", (n,), np.uint8)
        _sweeps.open_array_new(self.folder / "faired.npy", (n,), np.uint8)
        faces = _sweeps.open_array_new(self.folder / "faces.npy", (self.mesh.face.count, 3),
                                       self.mesh.face.dtype["corners"].base.newbyteorder("="))
        faces[:] = self.mesh.faces()["corners"]
        if len(faces) and (faces.min() < 0 or faces.max() >= n):
            raise ValueError(f"{self.mesh.path}: a face refers to a vertex that does not exist")
        self.points, self.faces = points, faces

    def fair(self, budget: int) -> TiledReport:
        clock = time.perf_counter()
        tiles, built = self._tiles(budget)
        self.seconds["tiles"] = time.perf_counter() - clock
        self.epsilon = self.epsilon or _tiles_epsilon(self.eps, built)
        adjacent = _partition.adjacency([b["near"] for b in built])
        colour = _partition.colour_tiles(adjacent)
        sizes = np.array([[b["vertices"], b["faces"]] for b in built])
        motion, largest, iterations = [], [], []
        peak = max(b["peak_memory"] for b in built)
        for sweep in range(1, MAX_SWEEPS + 1):
            clock = time.perf_counter()
            done = self._sweep(sweep, colour, adjacent)
            self.seconds[f"sweep {sweep}"] = time.perf_counter() - clock
            squares = sum(d["squared_motion"] for d in done)
            seam = sum(d["seam"] for d in done)
            motion.append(math.sqrt(squares / max(seam, 1)) / self.epsilon)
            largest.append(max(d["largest_motion"] for d in done) / self.epsilon)
            iterations.append(sum(d["iterations"] for d in done))
            peak = max([peak] + [d["peak_memory"] for d in done])
            # Tiles of one colour share no hinge: their first descents are final.
            if (sweep > 1 and motion[-1] <= MOTION_TOLERANCE) or colour.max() == 0:
                break
        deviation = _sweeps.open_array(self.folder / "deviation.npy")
        return TiledReport(tiles.tile, colour, len(motion), motion, largest, iterations,
                           motion[-1] <= MOTION_TOLERANCE or colour.max() == 0, self.epsilon,
                           float(deviation.max(initial=0.0)), sizes, peak)

    def _tiles(self, budget: int):
        """Tiles whose meshes, ghosts included, fit `budget` at BYTES_PER_TRIANGLE: a first cut
        by the owned triangles alone, then, while the ghosts push a tile over (twice at most),
        a cut sized by the ghosts the last one showed (a patch of f triangles has ghosts in
        proportion to its border, about sqrt(f)). Each cut is judged first on one tile, the
        cell of most vertices, so that a cut too coarse costs one tile's mesh, not all."""
        rings = _sweeps.ghost_rings(self._smoothing_steps())
        # Rings reach about an edge length each, farther across long edges: 3 times as far, and
        # build_tile doubles it where they reach farther still, searching every face again. At
        # 1.5 and 2 times, every tile and half the tiles were searched again on the bunny of
        # 4.8 M triangles in 8 tiles and the elephant of 5.7 M in 10; at 3, none (the candidates
        # 15 to 30 % more), the tiles built in 1.1 to 1.3 s instead of 2.8 to 3.3.
        margin = 3 * (rings + 1) * self._edge_scale()
        most = budget / BYTES_PER_TRIANGLE
        count = max(1, math.ceil(len(self.faces) / most))
        if count > 1:
            slots = sum(self.client.nthreads().values())
            count = max(count, min(TILES_PER_SLOT * slots, len(self.faces) // SMALLEST_TILE))
        for attempt in range(3):
            tiles = self._cut(count, margin)
            probe = int(np.argmax(np.bincount(tiles.tile, minlength=tiles.count)))
            built = self._build_tiles([probe], rings, margin)
            if built[probe]["faces"] <= most:
                built = self._build_tiles(range(tiles.count), rings, margin, built)
            refit = _fitting_count(count, len(self.faces), max(b["faces"] for b in built.values()), most)
            if refit is None or attempt == 2:
                break
            count = refit
        built = self._build_tiles(range(tiles.count), rings, margin, built)
        largest = max(b["faces"] for b in built.values())
        if largest > most:
            warnings.warn(f"tiles of {largest} triangles with their {rings} rings of "
                          f"ghosts need about {largest * BYTES_PER_TRIANGLE} bytes, "
                          f"more than tile_memory ({budget})")
        return tiles, [built[t] for t in range(tiles.count)]

    def _cut(self, count: int, margin: float) -> _partition.Tiles:
        """The k-d cells of `count` tiles, and each one's candidate faces, in the run's
        folder."""
        tiles = _partition.kd_tiles(self.points, count)
        np.save(self.folder / "tile.npy", tiles.tile)
        np.save(self.folder / "boxes.npy", tiles.boxes)
        (self.folder / "tiles").mkdir(exist_ok=True)
        boxes = np.array([_partition.grown(box, margin) for box in tiles.boxes])
        for t, faces in enumerate(_partition.candidate_faces(self.faces, self.points, boxes)):
            np.save(self.folder / "tiles" / f"{t}.candidates.npy", faces)
        return tiles

    def _build_tiles(self, tiles, rings: int, margin: float, built=None) -> Dict[int, Dict[str, Any]]:
        """The meshes of `tiles` that `built` does not hold yet, added to it, by tile."""
        built = dict(built or {})
        wanted = [int(t) for t in tiles if int(t) not in built]
        done = self.client.gather([self.client.submit(_sweeps.build_tile, str(self.folder), t, rings,
                                                      margin, self.eps[0], pure=False)
                                   for t in wanted])
        built.update({b["tile"]: b for b in done})
        return built

    def _sweep(self, sweep: int, colour: np.ndarray, adjacent) -> List[Dict[str, Any]]:
        """Every tile's descent of `sweep` in the order of the colours, each tile submitted as
        soon as its neighbours of the colours before its own are applied, not once their whole
        colours are: a descent reads the points of the hinges it touches alone, all of them
        its neighbours', so it sees what it would after the colours before (and a task run
        again reads what it read). Each result is applied as it comes; by tile."""
        from distributed import as_completed
        waiting = {t: {s for s in adjacent[t] if colour[s] < colour[t]} for t in range(len(colour))}

        def submit(t: int):
            return self.client.submit(_sweeps.fair_tile, str(self.folder), t, sweep, self.epsilon,
                                      self.keywords, self._max_iterations(sweep), self.threads,
                                      pure=False, retries=2)
        # On the run's client's loop: Dask's default client may be another, or none.
        running = as_completed([submit(t) for t, before in waiting.items() if not before],
                               loop=self.client.loop)
        done = []
        for future in running:
            d = future.result()
            _sweeps.apply_tile(self.folder, d["tile"], sweep)
            done.append(d)
            for t, before in waiting.items():
                if d["tile"] in before:
                    before.discard(d["tile"])
                    if not before:
                        running.add(submit(t))
        return sorted(done, key=lambda d: d["tile"])

    def _setting(self, name: str) -> int:
        """A setting of the run's calls: the user's, or the library's default."""
        if name in self.keywords:
            return int(self.keywords[name])
        method = call_options(1.0, **self.keywords).method  # whatever the epsilon
        return int(_core.default_settings(method)[name])

    def _smoothing_steps(self) -> int:
        return self._setting("initial_smoothing_steps")

    def _max_iterations(self, sweep: int) -> int:
        most = self._setting("max_iterations")
        return most if sweep <= 1 else min(most, SEAM_ITERATIONS)

    def _edge_scale(self) -> float:
        # The mean edge length of a sample of faces: the margin's unit, grown where rings reach
        # beyond it.
        sample = np.asarray(self.faces[::max(1, len(self.faces) // 100000)], np.int64)
        p = self.points[sample.ravel()].reshape(-1, 3, 3)
        return float(np.linalg.norm(p - np.roll(p, 1, axis=1), axis=2).mean())

    def write(self, out_path: Path) -> None:
        partial = out_path.with_name(f".{out_path.name}.partial-{os.getpid()}")
        try:
            _ply_map.write_ply(self.mesh, partial, _sweeps.open_array(self.folder / "state.npy"),
                               _sweeps.open_array(self.folder / "deviation.npy"),
                               _sweeps.open_array(self.folder / "at_bound.npy"))
            os.replace(partial, out_path)
        except BaseException as error:
            partial.unlink(missing_ok=True)
            if isinstance(error, OSError):  # a full disk, named: numpy's writes into a file are not
                raise _sweeps.named(error, out_path) from None
            raise
