"""The batch's tasks: which files to fair, and their tasks on a local or a given Dask cluster."""

import contextlib
import inspect
import json
import os
import signal
import threading
import time
import uuid
import warnings
from pathlib import Path
from typing import Any, Dict, List, Optional, Tuple

from .._errors import InputError
from .._fairing import fair, set_max_threads
from .._io import FORMATS, is_point_set_file, read_mesh, read_points, write_mesh, write_points
from .._label_map_files import label_map_stem, read_label_map
from .._labels import label_surfaces
from .._points import fair_points
from ._epsilon import mesh_epsilon, parse_eps, points_epsilon
from ._progress import Bar
from ._report_file import REPORT_NAME, Row, empty_row, read_report, write_report

# The statuses of a file that was faired, whose output the batch wrote.
DONE = ("converged", "iteration_limit_reached", "cancelled")


class Batch:
    """A checked batch: its inputs, outputs, options and the rows known before it runs."""

    def __init__(self, paths, out_dir, eps, force, fair_options, label_format="ply", repair=False):
        if isinstance(paths, (str, bytes, os.PathLike)):
            raise TypeError("paths must be a sequence of paths, not a single path")
        self.inputs = [Path(os.path.abspath(os.fspath(p))) for p in paths]
        self.out_dir = Path(os.path.abspath(os.fspath(out_dir)))
        self.eps = parse_eps(eps)
        self.force = bool(force)
        self.repair = bool(repair)
        self.fair_options = _check_fair_options(fair_options)
        self.label_format = _check_label_format(label_format)
        # A label map's surfaces go into a folder named after it.
        self.outputs = [self.out_dir / (label_map_stem(p) or p.name) for p in self.inputs]
        if any(label_map_stem(p) is not None for p in self.inputs):
            _check_label_map_options(self.fair_options)
        self.report_path = self.out_dir / REPORT_NAME
        self._check_names()
        self.rows: List[Optional[Row]] = [None] * len(self.inputs)
        self.kept: List[Row] = []
        self.skipped: List[int] = []
        self.todo: List[int] = []
        self.replace: List[bool] = [self.force] * len(self.inputs)

    def options(self, index: int) -> str:
        """What input `index`'s output is made with, as its report row records it."""
        if label_map_stem(self.inputs[index]) is not None:
            made = {"label_format": self.label_format, **self.fair_options}
        else:
            made = {"eps": list(self.eps), "repair": self.repair, **self.fair_options}
        return json.dumps(made, sort_keys=True)

    def _check_names(self):
        seen = {}
        for path, output in zip(self.inputs, self.outputs):
            if output.name in seen:
                raise ValueError(f"two inputs have the output file name {output.name!r} "
                                 f"({seen[output.name]} and {path}): their outputs would be the "
                                 "same file")
            seen[output.name] = path
            if output.name == REPORT_NAME:
                raise ValueError(f"{path}: an input named {REPORT_NAME} would overwrite the "
                                 "report")
            if any(_same_file(other, output) for other in self.inputs):
                raise ValueError(f"{path}: its output {output} would overwrite an input; "
                                 "choose another output folder")

    def plan(self):
        """Sort the inputs into those to fair, those done with the same options (skipped, their
        rows kept) and those whose output exists but that this batch did not write (an error,
        unless `force`): nothing the batch did not write is replaced."""
        previous = read_report(self.report_path)
        for index, (path, output) in enumerate(zip(self.inputs, self.outputs)):
            row = previous.pop(str(path), None)
            ours = (row is not None and row["status"] in DONE and row["output"] == str(output))
            if not output.exists():
                self.todo.append(index)
            elif ours and row.get("options") == self.options(index) and not self.force:
                self.skipped.append(index)
                self.rows[index] = row
            elif ours or self.force or output.is_dir():
                # A label map's folder only gets its own files, which its task checks.
                self.replace[index] = self.force or ours
                self.todo.append(index)
            else:
                row = empty_row(path)
                row.update(status="error", error=f"FileExistsError: {output} exists and this "
                           "batch's report does not record it as its output; force=True "
                           "(--force) replaces it")
                self.rows[index] = row
        self.kept = list(previous.values())

    def run(self, client, workers, threads, cores, show_progress) -> List[Row]:
        import_distributed()  # before anything is written
        os.makedirs(self.out_dir, exist_ok=True)
        self.plan()
        if self.todo:
            if client is not None:
                # dask-worker starts one process per machine by default: its tasks share
                # TBB's pool, so the library is not limited.
                self._run_on(client, threads=threads or 0, show_progress=show_progress)
            else:
                self._run_locally(workers, threads, cores, show_progress)
        write_report(self.report_path, self.rows, self.kept)
        return list(self.rows)

    def _run_locally(self, workers, threads, cores, show_progress):
        distributed = import_distributed()
        workers = min(workers or cores, cores, len(self.todo))
        with _workers_ignore_ctrl_c(), warnings.catch_warnings():
            # Its scheduler's HTTP routes move to a free port when another cluster holds
            # Dask's default one: nothing the user asked about, as the batch has no dashboard.
            warnings.filterwarnings("ignore", message="Port .* is already in use")
            cluster = distributed.LocalCluster(n_workers=workers, threads_per_worker=1,
                                               processes=True, dashboard_address=None)
        try:
            # Not the default client: the caller's own stays the default.
            with distributed.Client(cluster, set_as_default=False) as client:
                # The processes share the cores, so TBB gets each its share.
                self._run_on(client, threads=threads or max(1, cores // workers),
                             show_progress=show_progress)
        finally:
            cluster.close()

    def _run_on(self, client, threads, show_progress):
        distributed = import_distributed()
        token = uuid.uuid4().hex[:8]
        futures = {}
        # The largest files first, so that the last tasks are short and no worker idles long
        # while another finishes.
        for index in sorted(self.todo, key=lambda i: -_size(self.inputs[i])):
            key = f"fair_file-{self.inputs[index].name}-{token}-{index}"
            path, output = str(self.inputs[index]), str(self.outputs[index])
            job = dict(path=path, output=output, options=self.options(index), threads=threads,
                       replace=self.replace[index], fair_options=self.fair_options)
            if label_map_stem(path) is None:
                future = client.submit(_fair_file, job, self.eps, self.repair, key=key,
                                       pure=False)
            else:
                future = client.submit(_fair_label_map, job, self.label_format, key=key,
                                       pure=False)
            futures[future] = index
        bar = Bar(len(self.inputs), len(self.skipped)) if show_progress else None
        try:
            # The loop given: the batch's own client is not the default one.
            for future in distributed.as_completed(list(futures), loop=client.loop):
                index = futures[future]
                try:
                    row = future.result()
                except Exception as error:  # the task itself catches; this is a lost worker
                    row = empty_row(self.inputs[index])
                    row.update(status="error", error=_describe(error))
                self.rows[index] = row
                # Rewritten after each file, so an interrupted batch leaves what it did.
                write_report(self.report_path, self.rows, self.kept)
                if bar is not None:
                    bar.update(row)
        except BaseException:
            client.cancel(list(futures))
            raise
        finally:
            if bar is not None:
                bar.close()


@contextlib.contextmanager
def _workers_ignore_ctrl_c():
    """Processes started in the block ignore Ctrl-C, as they inherit an ignored SIGINT: on a
    terminal it reaches the whole process group, and the batch, which closes its cluster, is
    to answer it with one line rather than each worker with a traceback."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


def available_cores() -> int:
    """The cores this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def import_distributed():
    """Dask's ``distributed``, or an ImportError that says how to install it."""
    try:
        import distributed
    except ImportError as error:
        raise ImportError("cgal_constrained_fairing.batch needs Dask's distributed: "
                          "pip install distributed") from error
    return distributed


@contextlib.contextmanager
def _task(path: str):
    """A task's row, filled by the ``with`` block, which may raise: the error goes into the row,
    with the time taken."""
    start = time.perf_counter()
    row = empty_row(path)
    row["worker"] = _worker_address()
    try:
        yield row
    except Exception as error:
        row.update(status="error", error=_describe(error))
    row["seconds"] = time.perf_counter() - start


def _fair_file(job: Dict[str, Any], eps: Tuple[str, float], repair: bool) -> Row:
    """The task of one mesh or point set file, run in a worker: read, fair, write; never raises.
    A PLY file's properties are carried to its output, with each vertex's deviation and
    at_bound."""
    if is_point_set_file(job["path"]):
        return _fair_point_set_file(job, eps)
    path, output = job["path"], job["output"]
    with _task(path) as row:
        set_max_threads(job["threads"])
        ply = path.lower().endswith(".ply")
        V, F, *carried = read_mesh(path, properties=ply, repair=repair)
        row.update(vertices=int(V.shape[0]), faces=int(F.shape[0]))
        epsilon = mesh_epsilon(eps, V, F)
        row["epsilon"] = epsilon
        W, report = fair(V, F, epsilon, **_options_for(fair, job["fair_options"], "meshes"))
        properties = _with_bound_columns(carried[0] if carried and ply else None, report)
        _write_complete(output, job["replace"], lambda partial: write_mesh(partial, W, F, properties=properties))
        _record(row, report, output, job["options"])
    return row


def _fair_point_set_file(job: Dict[str, Any], eps: Tuple[str, float]) -> Row:
    """The task of one point set file (`fair_points`), as the command-line tool fairs it: its
    normals faired, a PLY file's properties carried. Never raises."""
    path, output = job["path"], job["output"]
    with _task(path) as row:
        set_max_threads(job["threads"])
        ply = path.lower().endswith(".ply")
        P, N, *carried = read_points(path, properties=ply)
        row.update(vertices=int(P.shape[0]), faces=0)
        epsilon = points_epsilon(eps, P)
        row["epsilon"] = epsilon
        options = _options_for(fair_points, job["fair_options"], "point sets")
        Q, report = fair_points(P, epsilon, N, **options)
        properties = _with_bound_columns(carried[0] if carried else None, report)
        _write_complete(output, job["replace"],
                        lambda partial: write_points(partial, Q, report.normals, properties=properties))
        _record(row, report, output, job["options"])
    return row


def _with_bound_columns(properties, report):
    """A PLY file's `properties` with each vertex's deviation and at_bound, as the tool adds
    them; None for a file without."""
    if properties is not None:
        properties.vertex["deviation"] = report.deviation
        properties.vertex["at_bound"] = report.at_bound.astype("uint8")
    return properties


def _write_complete(output: str, replace: bool, write) -> None:
    """`write(partial)` into a temporary beside `output`, then renamed into place, so that an
    output is always complete; an output that appeared during the run is kept unless
    `replace`."""
    # The temporary keeps the extension: the writer is chosen by it.
    stem, ext = os.path.splitext(os.path.basename(output))
    partial = os.path.join(os.path.dirname(output), f".{stem}.partial-{os.getpid()}{ext}")
    try:
        write(partial)
        if os.path.exists(output) and not replace:
            raise FileExistsError(f"{output} appeared during the run; it is not replaced")
        os.replace(partial, output)
    finally:
        with contextlib.suppress(OSError):
            os.remove(partial)


def _fair_label_map(job: Dict[str, Any], label_format: str) -> Row:
    """The task of one label map, run in a worker: its labels' surfaces, faired together within
    their voxels, each written in world coordinates to ``output/label_<L>.<format>``, which
    gets nothing else (`LabelSurfaces.write`). Never raises."""
    path, output = job["path"], job["output"]
    with _task(path) as row:
        set_max_threads(job["threads"])
        labels, affine = read_label_map(path)
        result = label_surfaces(labels, affine=affine, **job["fair_options"])
        row.update(vertices=int(result.vertices.shape[0]), faces=int(result.faces.shape[0]),
                   labels=int(result.labels.size))
        result.write(output, label_format, force=job["replace"])
        _record(row, result.report, output, job["options"])
    return row


def _record(row: Row, report, output: str, options: str) -> None:
    """What a finished task's row says of its fairing's `report` and where its output went."""
    row.update(status=report.status.value.lower(), iterations=report.number_of_iterations,
               initial_bending_energy=report.initial_bending_energy,
               final_bending_energy=report.final_bending_energy,
               initial_energy=report.initial_energy, final_energy=report.final_energy,
               max_deviation=report.max_deviation, output=output, options=options)


def _describe(error: BaseException) -> str:
    if isinstance(error, InputError):
        return f"{error.defect.value}: {error.message}"
    return f"{type(error).__name__}: {error}"


def _worker_address() -> Optional[str]:
    try:
        from distributed import get_worker
        return get_worker().address
    except (ImportError, ValueError):  # not in a worker
        return None


def _keywords(function) -> set:
    return {name for name, parameter in inspect.signature(function).parameters.items()
            if parameter.kind is inspect.Parameter.KEYWORD_ONLY and name != "progress"}


def _check_fair_options(options: Dict[str, Any]) -> Dict[str, Any]:
    taken = _keywords(fair) | _keywords(fair_points)
    for name in options:
        if name not in taken:
            raise TypeError(f"fair_files() got an option that neither fair() nor fair_points() "
                            f"takes in a batch: {name!r}")
    return dict(options)


def _options_for(function, options: Dict[str, Any], kind: str) -> Dict[str, Any]:
    """The batch's options for `function`; ValueError naming those that a `kind` does not take."""
    other = sorted(set(options) - _keywords(function))
    if other:
        raise ValueError(f"options that {kind} do not take: {', '.join(other)}")
    return options


# The options of `fair` that a label map's fairing takes too (`label_surfaces`).
_LABEL_MAP_OPTIONS = ("objective", "max_iterations")


def _check_label_map_options(options: Dict[str, Any]) -> None:
    other = sorted(set(options) - set(_LABEL_MAP_OPTIONS))
    if other:
        raise ValueError(f"options that label maps do not take: {', '.join(other)} (label maps "
                         f"take {', '.join(_LABEL_MAP_OPTIONS)})")


def _check_label_format(label_format: str) -> str:
    formats = [f[1:] for f in FORMATS]
    if not isinstance(label_format, str) or label_format.lower().lstrip(".") not in formats:
        raise ValueError(f"label_format must be one of {', '.join(formats)} (got {label_format!r})")
    return label_format.lower().lstrip(".")


def _size(path: Path) -> int:
    try:
        return path.stat().st_size
    except OSError:  # missing: its task reports it
        return 0


def _same_file(a: Path, b: Path) -> bool:
    try:
        return os.path.samefile(a, b)
    except OSError:  # one is missing: compare the names they resolve to
        return os.path.realpath(a) == os.path.realpath(b)
