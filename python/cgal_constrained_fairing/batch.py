"""Fair batches of mesh files on a Dask ``distributed`` cluster.

`fair_files` fairs each file in a task of its own, writes each result into an output folder
under the input's file name (same format), and keeps a table of what was done in
``OUT_DIR/report.csv``. A file that cannot be read or is rejected gets its error in the table
and the batch goes on; a second run skips the files already done and retries the others.

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

import argparse
import csv
import importlib.util
import inspect
import math
import operator
import os
import sys
import time
import uuid
from pathlib import Path
from typing import TYPE_CHECKING, Any, Dict, List, Optional, Sequence, Tuple, Union

from ._errors import InputError
from ._fairing import estimate_noise_level, fair, mean_edge_length, set_max_threads
from ._io import read_mesh, write_mesh

if TYPE_CHECKING:
    import distributed

__all__ = ["COLUMNS", "REPORT_NAME", "fair_files", "main"]

COLUMNS = ("path", "vertices", "faces", "epsilon", "status", "error", "iterations",
           "initial_bending_energy", "final_bending_energy", "initial_energy", "final_energy",
           "max_deviation", "seconds", "worker", "output")
"""The columns of the report, in order."""

REPORT_NAME = "report.csv"
"""The report's file name in the output folder."""

_INT_COLUMNS = ("vertices", "faces", "iterations")
_FLOAT_COLUMNS = ("epsilon", "initial_bending_energy", "final_bending_energy", "initial_energy",
                  "final_energy", "max_deviation", "seconds")
_DONE = ("converged", "iteration_limit_reached", "cancelled")

Eps = Union[str, float, int]
Row = Dict[str, Any]


def fair_files(paths: Sequence["os.PathLike[str] | str"],
               out_dir: "os.PathLike[str] | str",
               client: Optional["distributed.Client"] = None, *,
               eps: Eps = "0.25h",
               workers: Optional[int] = None,
               threads: Optional[int] = None,
               force: bool = False,
               progress: Optional[bool] = None,
               **fair_options: Any) -> List[Row]:
    """Fair mesh files on a Dask cluster, one task per file, and report what was done.

    Each file is read with `read_mesh`, faired with `fair` and written to
    ``out_dir / <its file name>`` (same format) through a temporary file, so that an output
    file is always complete. The report ``out_dir/report.csv`` is rewritten after each file,
    so that an interrupted batch leaves the table of what it did. Files whose output exists
    are skipped, whatever options made it: running the same batch again finishes it, and
    `force` redoes everything.

    Parameters
    ----------
    paths : sequence of str or os.PathLike
        The mesh files (OFF, OBJ, PLY or STL, by extension); their file names must differ.
        Relative paths are taken from the current directory.
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
        meshes' units.
    workers : int, optional
        The worker processes of the local cluster: default, and at most, one per core (and
        no more than files to fair). Only without `client`.
    threads : int, optional
        The threads of the library's parallel loops (TBB) in each worker process. Default:
        on the local cluster, the cores divided among its workers; on a `client`'s cluster,
        no limit (a ``dask-worker`` process per machine, whose tasks share its cores).
    force : bool
        Fair every file, even those whose output exists.
    progress : bool, optional
        Show a progress bar (tqdm) on stderr. Default: when stderr is a terminal and tqdm
        is installed.
    **fair_options
        Passed to `fair` unchanged for every file, e.g. ``objective="accurate"``
        (`progress` is the batch's own; `fair`'s progress is not available here).

    Returns
    -------
    list of dict
        The report's rows, one per input in input order, keyed by `COLUMNS`; missing values
        are ``None``. ``path`` and ``output`` are absolute paths; ``status`` is the lower-case
        `Status` of the run (``"converged"``, ``"iteration_limit_reached"``,
        ``"cancelled"``), ``"error"`` (``error`` says why: ``"DEFECT: message"`` for an
        `InputError`, ``"TypeName: message"`` otherwise) or ``"skipped"``; a skipped file
        whose row the previous report holds keeps that row (but a previous error is not kept:
        the file's output exists, so it shows as ``"skipped"``). ``seconds`` is the wall time
        of the file's task (read, fair, write) and ``worker`` the address of its worker.

    Raises
    ------
    ValueError
        Before anything is started or written: two inputs with the same file name, an output
        that would overwrite its input, a bad `eps` or `workers`, or `workers` with `client`.
    TypeError
        An option that `fair` does not take.
    ImportError
        Dask's ``distributed`` is not installed.

    Examples
    --------
    >>> from cgal_constrained_fairing import fair_files
    >>> rows = fair_files(["a.off", "b.ply"], "faired", eps="auto")      # doctest: +SKIP
    >>> [row["status"] for row in rows]                                 # doctest: +SKIP
    ['converged', 'converged']
    """
    batch = _Batch(paths, out_dir, eps, force, fair_options)
    if client is not None and workers is not None:
        raise ValueError("workers applies to the local cluster only; not with a client")
    cores = _cores()
    if workers is not None:
        workers = _positive_int(workers, "workers")
    if threads is not None:
        threads = _positive_int(threads, "threads")
    return batch.run(client, workers, threads, cores, _show_progress(progress))


class _Batch:
    """A checked batch: its inputs, outputs, options and the rows known before it runs."""

    def __init__(self, paths, out_dir, eps, force, fair_options):
        if isinstance(paths, (str, bytes, os.PathLike)):
            raise TypeError("paths must be a sequence of paths, not a single path")
        self.inputs = [Path(os.path.abspath(os.fspath(p))) for p in paths]
        self.out_dir = Path(os.path.abspath(os.fspath(out_dir)))
        self.eps = _parse_eps(eps)
        self.force = bool(force)
        self.fair_options = _check_fair_options(fair_options)
        self.outputs = [self.out_dir / p.name for p in self.inputs]
        self.report_path = self.out_dir / REPORT_NAME
        self._check_names()
        self.rows: List[Optional[Row]] = [None] * len(self.inputs)
        self.skipped: List[int] = []
        self.todo: List[int] = []

    def _check_names(self):
        seen = {}
        for path, output in zip(self.inputs, self.outputs):
            if path.name in seen:
                raise ValueError(f"two inputs have the file name {path.name!r} ({seen[path.name]} "
                                 f"and {path}): their outputs would be the same file")
            seen[path.name] = path
            if path.name == REPORT_NAME:
                raise ValueError(f"{path}: an input named {REPORT_NAME} would overwrite the "
                                 "report")
            if _same_file(path, output):
                raise ValueError(f"{path}: the output would overwrite the input; "
                                 "choose another output folder")

    def plan(self):
        """Sort the inputs into those to fair and those done, whose rows are then known."""
        previous = _read_report(self.report_path)
        for index, (path, output) in enumerate(zip(self.inputs, self.outputs)):
            if self.force or not output.exists():
                self.todo.append(index)
                continue
            self.skipped.append(index)
            row = previous.get(str(path))
            if row is None or row["status"] == "error":
                row = _empty_row(path)
                row.update(status="skipped", output=str(output))
            self.rows[index] = row

    def run(self, client, workers, threads, cores, show_progress) -> List[Row]:
        _import_distributed()  # before anything is written
        os.makedirs(self.out_dir, exist_ok=True)
        self.plan()
        if self.todo:
            if client is not None:
                # dask-worker starts one process per machine by default: its tasks share
                # TBB's pool, so the library is not limited.
                self._run_on(client, threads=threads or 0, show_progress=show_progress)
            else:
                self._run_locally(workers, threads, cores, show_progress)
        _write_report(self.report_path, self.rows)
        return list(self.rows)

    def _run_locally(self, workers, threads, cores, show_progress):
        distributed = _import_distributed()
        workers = min(workers or cores, cores, len(self.todo))
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
        distributed = _import_distributed()
        token = uuid.uuid4().hex[:8]
        futures = {}
        # The largest files first, so that the last tasks are short and no worker idles long
        # while another finishes.
        for index in sorted(self.todo, key=lambda i: -_size(self.inputs[i])):
            key = f"fair_file-{self.inputs[index].name}-{token}-{index}"
            future = client.submit(_fair_file, str(self.inputs[index]), str(self.outputs[index]),
                                   self.eps, self.fair_options, threads, key=key, pure=False)
            futures[future] = index
        bar = _Bar(len(self.inputs), len(self.skipped)) if show_progress else None
        try:
            # The loop given: the batch's own client is not the default one.
            for future in distributed.as_completed(list(futures), loop=client.loop):
                index = futures[future]
                try:
                    row = future.result()
                except Exception as error:  # the task itself catches; this is a lost worker
                    row = _empty_row(self.inputs[index])
                    row.update(status="error", error=_describe(error))
                self.rows[index] = row
                # Rewritten after each file, so an interrupted batch leaves what it did.
                _write_report(self.report_path, self.rows)
                if bar is not None:
                    bar.update(row)
        except BaseException:
            client.cancel(list(futures))
            raise
        finally:
            if bar is not None:
                bar.close()


def _fair_file(path: str, output: str, eps: Tuple[str, float], fair_options: Dict[str, Any],
               threads: int) -> Row:
    """The task of one file, run in a worker: read, fair, write; never raises."""
    start = time.perf_counter()
    row = _empty_row(path)
    row["worker"] = _worker_address()
    partial = None
    try:
        set_max_threads(threads)
        V, F = read_mesh(path)
        row.update(vertices=int(V.shape[0]), faces=int(F.shape[0]))
        epsilon = _epsilon(eps, V, F)
        row["epsilon"] = epsilon
        W, report = fair(V, F, epsilon, **fair_options)
        # The temporary keeps the extension: the writer is chosen by it.
        stem, ext = os.path.splitext(os.path.basename(output))
        partial = os.path.join(os.path.dirname(output), f".{stem}.partial{ext}")
        write_mesh(partial, W, F)
        os.replace(partial, output)
        partial = None
        row.update(status=report.status.value.lower(), iterations=report.number_of_iterations,
                   initial_bending_energy=report.initial_bending_energy,
                   final_bending_energy=report.final_bending_energy,
                   initial_energy=report.initial_energy, final_energy=report.final_energy,
                   max_deviation=report.max_deviation, output=output)
    except Exception as error:
        row.update(status="error", error=_describe(error))
    finally:
        if partial is not None:
            try:
                os.remove(partial)
            except OSError:
                pass
    row["seconds"] = time.perf_counter() - start
    return row


def _epsilon(eps: Tuple[str, float], V, F) -> float:
    kind, value = eps
    if kind == "h":
        return value * mean_edge_length(V, F)
    if kind == "auto":
        noise = estimate_noise_level(V, F)
        if not noise > 0:
            raise ValueError("cannot estimate the noise level of so small a mesh; give eps")
        return noise
    return value


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


def _empty_row(path) -> Row:
    row = dict.fromkeys(COLUMNS)
    row["path"] = str(path)
    return row


def _parse_eps(eps: Eps) -> Tuple[str, float]:
    """``("h", x)``, ``("auto", nan)`` or ``("value", epsilon)``; ValueError if malformed."""
    if isinstance(eps, str):
        text = eps.strip().lower()
        if text == "auto":
            return ("auto", math.nan)
        kind = "h" if text.endswith("h") else "value"
        number = text[:-1].strip() if kind == "h" else text
        try:
            value = float(number or "1")
        except ValueError:
            raise ValueError(f"eps must be '<x>h', 'auto' or a number (got {eps!r})") from None
    elif isinstance(eps, (int, float)) and not isinstance(eps, bool):
        kind, value = "value", float(eps)
    else:
        raise ValueError(f"eps must be '<x>h', 'auto' or a number (got {eps!r})")
    if not (math.isfinite(value) and value > 0):
        raise ValueError(f"eps must be positive and finite (got {eps!r})")
    return (kind, value)


def _check_fair_options(options: Dict[str, Any]) -> Dict[str, Any]:
    taken = {name for name, parameter in inspect.signature(fair).parameters.items()
             if parameter.kind is inspect.Parameter.KEYWORD_ONLY and name != "progress"}
    for name in options:
        if name not in taken:
            raise TypeError(f"fair_files() got an option that fair() does not take in a batch: "
                            f"{name!r}")
    return dict(options)


def _positive_int(value, name: str) -> int:
    try:
        number = operator.index(value)  # numpy integers too, but not 2.0
    except TypeError:
        number = 0
    if isinstance(value, bool) or number < 1:
        raise ValueError(f"{name} must be a positive integer (got {value!r})")
    return number


def _cores() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


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


def _show_progress(progress: Optional[bool]) -> bool:
    if progress is None:
        return sys.stderr.isatty() and importlib.util.find_spec("tqdm") is not None
    if not isinstance(progress, bool):
        raise ValueError(f"progress must be None, True or False (got {progress!r})")
    return progress


class _Bar:
    """A tqdm bar of files on stderr, or a line rewritten in place without tqdm."""

    def __init__(self, total: int, done: int):
        self._total, self._done = total, done
        try:
            from tqdm import tqdm
        except ImportError:
            self._bar = None
            self._line()
        else:
            self._bar = tqdm(total=total, initial=done, desc="fairing files", unit="file",
                             file=sys.stderr)

    def update(self, row: Row):
        self._done += 1
        if self._bar is not None:
            self._bar.set_postfix_str(f"{Path(row['path']).name}: {row['status']}",
                                      refresh=False)
            self._bar.update(1)
        else:
            self._line()

    def close(self):
        if self._bar is not None:
            self._bar.close()
        else:
            sys.stderr.write("\n")
            sys.stderr.flush()

    def _line(self):
        sys.stderr.write(f"\rfairing files: {self._done}/{self._total}\x1b[K")
        sys.stderr.flush()


def _cell(value) -> str:
    if value is None:
        return ""
    if isinstance(value, float):
        return repr(value)  # full precision
    return str(value)


def _write_report(path: Path, rows: Sequence[Optional[Row]]) -> None:
    """Write the rows known so far, in input order, through a temporary file."""
    partial = path.with_name(f".{path.stem}.partial{path.suffix}")
    try:
        with open(partial, "w", newline="", encoding="utf-8") as stream:
            writer = csv.writer(stream)
            writer.writerow(COLUMNS)
            for row in rows:
                if row is not None:
                    writer.writerow([_cell(row[column]) for column in COLUMNS])
        os.replace(partial, path)
    except BaseException:
        try:
            os.remove(partial)
        except OSError:
            pass
        raise


def _read_report(path: Path) -> Dict[str, Row]:
    """The rows of an earlier report by path; none if it is missing or not a report."""
    try:
        with open(path, newline="", encoding="utf-8") as stream:
            reader = csv.DictReader(stream)
            if tuple(reader.fieldnames or ()) != COLUMNS:
                return {}
            rows = {}
            for cells in reader:
                row = _parse_row(cells)
                if row is not None:
                    rows[row["path"]] = row
            return rows
    except (OSError, UnicodeDecodeError, csv.Error):
        return {}


def _parse_row(cells: Dict[str, Optional[str]]) -> Optional[Row]:
    row: Row = {}
    try:
        for column in COLUMNS:
            text = cells.get(column)
            if text is None or text == "":
                row[column] = None
            elif column in _INT_COLUMNS:
                row[column] = int(text)
            elif column in _FLOAT_COLUMNS:
                row[column] = float(text)
            else:
                row[column] = text
    except ValueError:  # a damaged row is ignored
        return None
    return row if row["path"] and row["status"] else None


def _import_distributed():
    try:
        import distributed
    except ImportError as error:
        raise ImportError("cgal_constrained_fairing.batch needs Dask's distributed: "
                          "pip install distributed") from error
    return distributed


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command line: ``python3 -m cgal_constrained_fairing.batch IN... -o OUT_DIR``.

    Parameters
    ----------
    argv : sequence of str, optional
        The arguments, without the program name; default ``sys.argv[1:]``.

    Returns
    -------
    int
        0 when every file was faired or skipped, 1 when a file failed (or the scheduler
        cannot be reached); usage errors exit with 2.
    """
    parser = argparse.ArgumentParser(
        prog="python3 -m cgal_constrained_fairing.batch",
        description="Fair mesh files (OFF, OBJ, PLY, STL) on a Dask cluster, each within "
                    "epsilon of its input. Outputs go to OUT_DIR under the inputs' file names, "
                    "with a table of what was done in OUT_DIR/report.csv; files already done "
                    "are skipped.")
    parser.add_argument("inputs", nargs="+", metavar="IN", help="mesh files")
    parser.add_argument("-o", "--out-dir", required=True, metavar="OUT_DIR",
                        help="the output folder (created if missing)")
    parser.add_argument("--eps", default="0.25h",
                        help="the tolerance: '<x>h' (x times each mesh's mean edge length), "
                             "'auto' (each mesh's estimated noise level) or a value "
                             "(default: 0.25h)")
    parser.add_argument("--accurate", action="store_true",
                        help="fair towards a denoised copy of each input (objective "
                             "'accurate'): closer to the true surface of a noisy scan")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, metavar="N",
                       help="worker processes on this machine (default: one per core)")
    where.add_argument("--scheduler", metavar="ADDRESS",
                       help="run on the cluster of this Dask scheduler, e.g. tcp://host:8786")
    parser.add_argument("--threads", type=int, metavar="K",
                        help="threads of the library's parallel loops in each worker process "
                             "(default: the cores shared among the local workers; no limit on "
                             "a scheduler's cluster)")
    parser.add_argument("--force", action="store_true",
                        help="fair every file, even those whose output exists")
    args = parser.parse_args(argv)
    if args.workers is not None and args.workers < 1:
        parser.error(f"--workers must be at least 1 (got {args.workers})")
    if args.threads is not None and args.threads < 1:
        parser.error(f"--threads must be at least 1 (got {args.threads})")

    options = {"objective": "accurate"} if args.accurate else {}
    try:
        batch = _Batch(args.inputs, args.out_dir, args.eps, args.force, options)
    except ValueError as error:
        parser.error(str(error))

    distributed = _import_distributed()
    try:
        if args.scheduler is not None:
            try:
                client = distributed.Client(args.scheduler)
            except OSError as error:  # TimeoutError included
                print(f"error: cannot connect to the scheduler {args.scheduler}: {error}",
                      file=sys.stderr)
                return 1
            with client:
                rows = batch.run(client, None, args.threads, _cores(), _show_progress(None))
        else:
            rows = batch.run(None, args.workers, args.threads, _cores(), _show_progress(None))
    except KeyboardInterrupt:
        # The report holds the files done so far; running again goes on from there.
        print(f"interrupted; report: {batch.report_path}", file=sys.stderr)
        return 130

    skipped = set(batch.skipped)
    failed = [row for row in rows if row["status"] == "error"]
    faired = sum(1 for index, row in enumerate(rows)
                 if index not in skipped and row["status"] in _DONE)
    for row in failed:
        print(f"error: {row['path']}: {row['error']}", file=sys.stderr)
    print(f"{faired} faired, {len(skipped)} skipped, {len(failed)} failed; "
          f"report: {batch.report_path}")
    return 1 if failed else 0


if __name__ == "__main__":
    # Run as the package's module, not as __main__, so that the tasks sent to the workers
    # refer to functions they can import.
    from cgal_constrained_fairing.batch import main as _package_main
    sys.exit(_package_main())
