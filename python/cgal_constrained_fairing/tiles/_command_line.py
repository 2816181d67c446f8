"""The command line of `fair_tiled`."""

import argparse
from typing import Optional, Sequence

from .._errors import InputError
from ..batch._epsilon import DEFAULT_EPS


def main(argv: Optional[Sequence[str]] = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python3 -m cgal_constrained_fairing.tiles",
        description="Fair one mesh too large for one process as tiles on a Dask cluster; the "
                    "output is binary PLY, every vertex within eps of its input position.")
    parser.add_argument("input", help="a triangle mesh (binary PLY is read in place)")
    parser.add_argument("output", help="the faired mesh, a .ply file")
    parser.add_argument("--eps", default=DEFAULT_EPS,
                        help=f"a distance, a fraction of the mean edge length (0.25h) or auto "
                             f"(default {DEFAULT_EPS})")
    parser.add_argument("--scheduler", help="the address of a Dask scheduler (default: a local "
                                            "cluster of one process per core)")
    parser.add_argument("--tile-memory", default="2GiB", help="what a tile's task may hold")
    parser.add_argument("--work-dir", help="where the run keeps its arrays (default: the "
                                           "output's folder; shared by all workers)")
    args = parser.parse_args(argv)
    from . import fair_tiled
    client = None
    try:
        if args.scheduler:
            import distributed
            # Dask's connect timeout (distributed.comm.timeouts.connect, 30 s unless set).
            client = distributed.Client(args.scheduler)
        report = fair_tiled(args.input, args.output, args.eps, client=client,
                            tile_memory=args.tile_memory, work_dir=args.work_dir)
    except (InputError, ValueError, OSError) as error:
        print(f"error: {error}; nothing written")
        return 1
    finally:
        if client is not None:
            client.close()
    print(f"{args.output}: {report!r}")
    return 0
