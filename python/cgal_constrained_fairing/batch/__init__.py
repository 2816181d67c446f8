"""Fair batches of mesh, point set and label map files on a Dask ``distributed`` cluster.

`fair_files` fairs each file in a task of its own, writes each result into an output folder
under the input's file name (same format), and keeps a table of what was done in
``OUT_DIR/report.csv``. Point sets (``.xyz``, ``.pwn``, and ``.ply`` and ``.off`` files
without faces) are faired with every point kept in its order. Label maps (NIfTI ``.nii``, ``.nii.gz``, INRIMAGE-4 ``.inr``,
``.inr.gz`` and ``.npy``) give one closed surface per label, faired together within their
voxels, in a folder named after the map. A file that cannot be read or is rejected gets its
error in the table and the batch goes on; a second run skips the files already done and
retries the others.

On this machine, one worker process per core::

    python3 -m cgal_constrained_fairing.batch scans/*.ply -o faired/ --eps 0.25h

On several machines, start a Dask scheduler on one of them (it listens on port 8786)::

    dask-scheduler

then a worker on each machine that should compute, with the package installed there, ``K``
being the number of files it fairs at once (its cores, or fewer when memory is short)::

    dask-worker tcp://HOST:8786 --nthreads K

and send the batch to the scheduler::

    python3 -m cgal_constrained_fairing.batch scans/*.ply -o faired/ --scheduler tcp://HOST:8786

The workers read the inputs and write the outputs themselves, so the input and output paths
must name the same files on every machine (a shared file system). Relative paths are made
absolute on the machine that sends the batch. From Python, pass ``distributed.Client(
"tcp://HOST:8786")`` as `fair_files`'s `client`.
"""

import operator
import os
from typing import TYPE_CHECKING, Any, List, Optional, Sequence

from ._command_line import main
from ._epsilon import DEFAULT_EPS, Eps
from ._progress import show_progress
from ._report_file import COLUMNS, REPORT_NAME, Row
from ._schedule import Batch, available_cores

if TYPE_CHECKING:
    import distributed

__all__ = ["COLUMNS", "REPORT_NAME", "fair_files", "main"]


def fair_files(paths: Sequence["os.PathLike[str] | str"],
               out_dir: "os.PathLike[str] | str",
               client: Optional["distributed.Client"] = None, *,
               eps: Eps = DEFAULT_EPS,
               workers: Optional[int] = None,
               threads: Optional[int] = None,
               force: bool = False,
               progress: Optional[bool] = None,
               label_format: str = "ply",
               repair: bool = False,
               **fair_options: Any) -> List[Row]:
    """Fair mesh, point set and label map files on a Dask cluster, one task per file; report
    what was done.

    Each mesh file is read with `read_mesh`, faired with `fair` and written to
    ``out_dir / <its file name>`` (same format) through a temporary file, so that an output
    file is always complete; a PLY file's vertex and face properties are carried to its output,
    with each vertex's ``deviation`` and ``at_bound``. Each point set file (`is_point_set_file`)
    is read with `read_points`, faired with `fair_points` (its normals, if it has them, faired
    too) and written likewise, a PLY file's properties carried. Each label map (``.nii``, ``.nii.gz``,
    ``.inr``, ``.inr.gz``, ``.npy``) is read with `read_label_map`, its surfaces made and faired together within
    their voxels with `label_surfaces` (its affine applied: the surfaces are in world
    coordinates), and each label's closed surface written to
    ``out_dir / <its name> / label_<L>.<label_format>`` (`LabelSurfaces.write`: the folder
    gets nothing else). The report ``out_dir/report.csv`` is rewritten after each file, so
    that an interrupted batch leaves the table of what it did; it keeps the rows of files that
    are not in this batch. Nothing the batch did not write is replaced: a file whose output
    the report records as made with the same options is skipped (running the same batch again
    finishes it), one made with other options is faired again, and an output that the report
    does not record is an error row unless `force`, which replaces outputs (never an input).

    Parameters
    ----------
    paths : sequence of str or os.PathLike
        The mesh files (OFF, OBJ, PLY or STL), point sets (XYZ, PWN, and PLY or OFF without
        faces) and label maps (NIfTI ``.nii``, ``.nii.gz``,
        INRIMAGE-4 ``.inr``, ``.inr.gz``, numpy ``.npy``), by extension; their outputs' names
        must differ. Relative paths are taken from the current directory.
    out_dir : str or os.PathLike
        The output folder, created if missing; it must not hold an input (outputs would
        overwrite inputs).
    client : distributed.Client, optional
        The client of the cluster to run on. Default: a `distributed.LocalCluster` of
        `workers` processes of one thread each, started for the batch (only if a file is left
        to fair) and closed at its end.
    eps : str or float
        The tolerance of each file: ``"<x>h"`` for x times its `mean_edge_length`,
        ``"auto"`` for its `estimate_noise_level`, or a number (or numeric string) in the
        meshes' units; the command-line tool's ``--eps`` reads the same texts (default
        ``"0.25h"``). A point set has no edges: it takes a number or ``"auto"``, and is an
        error row with ``"<x>h"``. Label maps are bounded by their voxels instead.
    workers : int, optional
        The worker processes of the local cluster: default, and at most, one per core (and
        no more than files to fair). Only without `client`.
    threads : int, optional
        The threads of the library's parallel loops (TBB) in each worker process. Default:
        on the local cluster, the cores divided among its workers; on a `client`'s cluster,
        no limit (a ``dask-worker`` process per machine, whose tasks share its cores).
    force : bool
        Fair every file, even those done with the same options, and replace outputs that the
        report does not record (a label map's folder: only its ``label_<L>`` files).
    progress : bool, optional
        Show a progress bar (tqdm) on stderr. Default: when stderr is a terminal and tqdm
        is installed.
    label_format : {"ply", "off", "obj", "stl"}
        The format of the labels' surfaces.
    repair : bool
        Make a mesh of each mesh file that is a soup but not a mesh, as `read_mesh`'s
        `repair` (the command-line tool's ``--repair``); point sets are read as they are.
    **fair_options
        Passed to `fair` unchanged for every mesh file and to `fair_points` for every point
        set, e.g. ``objective="accurate"`` (`progress` is the batch's own; `fair`'s progress
        is not available here); a file whose function does not take one of them (``region``
        for a point set, ``neighbors`` for a mesh) is an error row. With label maps among the
        inputs, only ``objective`` and ``max_iterations``, which `label_surfaces` takes too.

    Returns
    -------
    list of dict
        The report's rows, one per input in input order, keyed by `COLUMNS`; missing values
        are ``None``. ``path`` and ``output`` are absolute paths; ``status`` is the lower-case
        `Status` of the run (``"converged"``, ``"iteration_limit_reached"``,
        ``"cancelled"``) or ``"error"`` (``error`` says why: ``"DEFECT: message"`` for an
        `InputError`, ``"TypeName: message"`` otherwise); a skipped file keeps the row of the
        previous report, whose ``options`` are this batch's. ``seconds`` is the wall time
        of the file's task (read, fair, write) and ``worker`` the address of its worker. For a
        label map, ``vertices`` and ``faces`` count its multi-label surface (each point and
        triangle once), ``labels`` the surfaces written, ``output`` is their folder and
        ``epsilon`` is missing.

    Raises
    ------
    ValueError
        Before anything is started or written: two inputs with the same output name, an
        output that would overwrite its input, a bad `eps`, `workers` or `label_format`,
        `workers` with `client`, or label maps with options they do not take.
    TypeError
        An option that neither `fair` nor `fair_points` takes.
    ImportError
        Dask's ``distributed`` is not installed.

    Examples
    --------
    >>> from cgal_constrained_fairing import fair_files
    >>> rows = fair_files(["a.off", "b.ply"], "faired", eps="auto")      # doctest: +SKIP
    >>> [row["status"] for row in rows]                                 # doctest: +SKIP
    ['converged', 'converged']
    """
    batch = Batch(paths, out_dir, eps, force, fair_options, label_format, repair)
    if client is not None and workers is not None:
        raise ValueError("workers applies to the local cluster only; not with a client")
    cores = available_cores()
    if workers is not None:
        workers = _positive_int(workers, "workers")
    if threads is not None:
        threads = _positive_int(threads, "threads")
    return batch.run(client, workers, threads, cores, show_progress(progress))


def _positive_int(value, name: str) -> int:
    try:
        number = operator.index(value)  # numpy integers too, but not 2.0
    except TypeError:
        number = 0
    if isinstance(value, bool) or number < 1:
        raise ValueError(f"{name} must be a positive integer (got {value!r})")
    return number
