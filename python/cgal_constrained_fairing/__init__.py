"""Constrained fairing of triangle meshes: noise goes, every vertex stays within epsilon.

The Python interface of CGAL Constrained Fairing, the implementation of K. Hildebrandt and
K. Polthier, "Constraint-based fairing of surface meshes" (SGP 2007), on numpy arrays:

- `fair` fairs a mesh ``(vertices, faces)`` within a tolerance ``epsilon``;
- `fair_points` fairs a point set within ``epsilon``, every point kept in its order;
- `mean_edge_length` and `estimate_noise_level` help choose ``epsilon``;
- `read_mesh` and `write_mesh` read and write OFF, OBJ, PLY and STL files, `read_points` and
  `write_points` point sets (XYZ, PWN, and PLY and OFF without faces);
- `label_surfaces` makes a label map's surfaces, one closed surface per label with the interfaces
  shared exactly, faired together within their voxels; `fair_interfaces` fairs such a
  multi-label triangle soup; `read_label_map` reads a label map from a NIfTI, INRIMAGE-4 or
  .npy file;
- `fair_files` (module `cgal_constrained_fairing.batch`) fairs many files, meshes, point sets
  and label maps, on a Dask cluster, also from the command line:
  ``python3 -m cgal_constrained_fairing.batch IN... -o OUT_DIR``;
- `fair_tiled` (module `cgal_constrained_fairing.tiles`) fairs one mesh too large for one
  process as tiles on a Dask cluster: ``python3 -m cgal_constrained_fairing.tiles IN OUT``;
  `label_surfaces_tiled` makes and fairs a label volume's surfaces so, chunk by chunk.

Example
-------
>>> import cgal_constrained_fairing as cf
>>> V, F = cf.read_mesh("scan.off")                         # doctest: +SKIP
>>> W, report = cf.fair(V, F, 0.25 * cf.mean_edge_length(V, F))  # doctest: +SKIP
>>> print(report)                                           # doctest: +SKIP
"""

from ._errors import Defect, InputError
from ._fairing import estimate_noise_level, fair, max_threads, mean_edge_length, set_max_threads
from ._io import MeshProperties, is_point_set_file, read_mesh, read_points, write_mesh, write_points
from ._label_map_files import read_label_map
from ._labels import LABEL_BOX_MARGIN, LabelSurfaces, fair_interfaces, label_surfaces
from ._points import PointsReport, fair_points
from ._report import Report, Status

__version__ = "0.1.0"

__all__ = [
    "LABEL_BOX_MARGIN", "Defect", "InputError", "LabelSurfaces", "MeshProperties", "Report", "Status", "estimate_noise_level", "fair",
    "fair_files", "fair_interfaces", "fair_tiled", "fair_points", "label_surfaces_tiled", "PointsReport", "label_surfaces", "max_threads", "mean_edge_length",
    "is_point_set_file", "read_label_map", "read_mesh", "read_points", "set_max_threads", "write_mesh",
    "write_points",
]


def __getattr__(name):
    # The batch and the tiles need Dask, imported only when they are used.
    if name == "fair_files":
        from .batch import fair_files
        return fair_files
    if name == "fair_tiled":
        from .tiles import fair_tiled
        return fair_tiled
    if name == "label_surfaces_tiled":
        from .tiles import label_surfaces_tiled
        return label_surfaces_tiled
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
