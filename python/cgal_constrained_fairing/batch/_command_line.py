"""The batch's command line: ``python3 -m cgal_constrained_fairing.batch IN... -o OUT_DIR``."""

import argparse
import sys
from typing import Optional, Sequence

from ._epsilon import DEFAULT_EPS
from ._progress import show_progress
from ._schedule import DONE, Batch, available_cores, import_distributed


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
                    "epsilon of its input, and label maps (NIfTI .nii, .nii.gz, INRIMAGE-4 .inr, "
                    ".inr.gz, numpy .npy) "
                    "into one closed surface per label, faired together within their voxels. "
                    "Meshes go to OUT_DIR under the inputs' file names, a label map's surfaces "
                    "to OUT_DIR/<its name>/label_<L>.<format> in world coordinates, with a "
                    "table of what was done in OUT_DIR/report.csv; files already done with the "
                    "same options are skipped, and nothing the batch did not write is replaced "
                    "without --force.")
    parser.add_argument("inputs", nargs="+", metavar="IN", help="mesh files and label maps")
    parser.add_argument("-o", "--out-dir", required=True, metavar="OUT_DIR",
                        help="the output folder (created if missing)")
    parser.add_argument("--eps", default=DEFAULT_EPS,
                        help="the tolerance: '<x>h' (x times each mesh's mean edge length), "
                             "'auto' (each mesh's estimated noise level) or a value "
                             f"(default: {DEFAULT_EPS})")
    parser.add_argument("--label-format", default="ply", choices=("ply", "off", "obj", "stl"),
                        help="the format of the labels' surfaces (default: ply)")
    parser.add_argument("--accurate", action="store_true",
                        help="fair towards a denoised copy of each input (objective "
                             "'accurate'): closer to the true surface of a noisy scan")
    parser.add_argument("--feature-angle", type=float, metavar="DEG",
                        help="keep creases sharp: the edges across which the filtered face "
                             "normals are more than DEG degrees apart (mesh files only)")
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
                        help="fair every file, even those done with the same options, and "
                             "replace outputs the report does not record (never an input)")
    parser.add_argument("--repair", action="store_true",
                        help="make a mesh of each mesh file that is a soup but not a mesh "
                             "(CGAL's soup repair), as the tool's --repair")
    args = parser.parse_args(argv)
    if args.workers is not None and args.workers < 1:
        parser.error(f"--workers must be at least 1 (got {args.workers})")
    if args.threads is not None and args.threads < 1:
        parser.error(f"--threads must be at least 1 (got {args.threads})")

    options = {"objective": "accurate"} if args.accurate else {}
    if args.feature_angle is not None:
        options["feature_angle"] = args.feature_angle
    try:
        batch = Batch(args.inputs, args.out_dir, args.eps, args.force, options,
                      args.label_format, args.repair)
    except ValueError as error:
        parser.error(str(error))

    distributed = import_distributed()
    cores, progress = available_cores(), show_progress(None)
    try:
        if args.scheduler is not None:
            try:
                client = distributed.Client(args.scheduler)
            except OSError as error:  # TimeoutError included
                print(f"error: cannot connect to the scheduler {args.scheduler}: {error}",
                      file=sys.stderr)
                return 1
            with client:
                rows = batch.run(client, None, args.threads, cores, progress)
        else:
            rows = batch.run(None, args.workers, args.threads, cores, progress)
    except KeyboardInterrupt:
        # The report holds the files done so far; running again goes on from there.
        print(f"interrupted; report: {batch.report_path}", file=sys.stderr)
        return 130

    skipped = set(batch.skipped)
    failed = [row for row in rows if row["status"] == "error"]
    faired = sum(1 for index, row in enumerate(rows)
                 if index not in skipped and row["status"] in DONE)
    for row in failed:
        print(f"error: {row['path']}: {row['error']}", file=sys.stderr)
    print(f"{faired} faired, {len(skipped)} skipped, {len(failed)} failed; "
          f"report: {batch.report_path}")
    return 1 if failed else 0
