"""The command line of `fair_tiled`."""

import argparse
from typing import Optional, Sequence

from .._errors import InputError
from ..batch._epsilon import DEFAULT_EPS
from ._label_volume_sources import is_label_volume


def main(argv: Optional[Sequence[str]] = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python3 -m cgal_constrained_fairing.tiles",
        description="Fair one mesh too large for one process as tiles on a Dask cluster; the "
                    "output is binary PLY, every vertex within eps of its input position. A "
                    "label volume (zarr, N5, TIFF stack, NIfTI) gives the folder OUTPUT of its "
                    "labels' closed surfaces, label_<L>.ply, each point within its voxels.")
    parser.add_argument("input", help="a triangle mesh (binary PLY is read in place), or a "
                                      "label volume")
    parser.add_argument("output", help="the faired mesh, a .ply file; a folder for a label volume")
    parser.add_argument("--eps", default=None,
                        help=f"a distance, a fraction of the mean edge length (0.25h) or auto "
                             f"(default {DEFAULT_EPS}); not for label volumes")
    parser.add_argument("--spacing", type=float, nargs=3, metavar=("SX", "SY", "SZ"),
                        help="a label volume's voxel sizes (default: a NIfTI file's own, else 1)")
    parser.add_argument("--chunk-cells", type=int, default=None,
                        help="the cells a label volume's chunk owns along each axis (default: 128, "
                             "fewer where a tile would not fit --tile-memory)")
    parser.add_argument("--scheduler", help="the address of a Dask scheduler (default: a local "
                                            "cluster of one process per core)")
    parser.add_argument("--tile-memory", default="2GiB", help="what a tile's task may hold")
    parser.add_argument("--work-dir", help="where the run keeps its arrays (default: the "
                                           "output's folder; shared by all workers)")
    args = parser.parse_args(argv)
    volume = is_label_volume(args.input)
    if volume and args.eps is not None:
        parser.error("a label volume's points are bound by their voxels; --eps is for meshes")
    if not volume and (args.spacing or args.chunk_cells):
        parser.error("--spacing and --chunk-cells are for label volumes")
    from . import fair_tiled, label_surfaces_tiled
    client = None
    try:
        if args.scheduler:
            import distributed
            # Dask's connect timeout (distributed.comm.timeouts.connect, 30 s unless set).
            client = distributed.Client(args.scheduler)
        if volume:
            report = label_surfaces_tiled(args.input, args.output, args.spacing, client=client,
                                          chunk_cells=args.chunk_cells, tile_memory=args.tile_memory,
                                          work_dir=args.work_dir)
        else:
            report = fair_tiled(args.input, args.output, args.eps or DEFAULT_EPS, client=client,
                                tile_memory=args.tile_memory, work_dir=args.work_dir)
    except (InputError, ValueError, OSError) as error:
        print(f"error: {error}; nothing written")
        return 1
    finally:
        if client is not None:
            client.close()
    print(f"{args.output}: {report!r}")
    return 0
