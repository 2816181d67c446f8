"""Mesh files through CGAL's readers and writers: OFF, OBJ, PLY and STL."""

import os
from typing import Tuple

import numpy as np
from numpy.typing import ArrayLike

from . import _core
from ._arrays import faces_array, vertices_array

FORMATS = (".off", ".obj", ".ply", ".stl")


def read_mesh(path: "os.PathLike[str] | str") -> Tuple[np.ndarray, np.ndarray]:
    """Read a triangle mesh from an OFF, OBJ, PLY or STL file, as the command-line tool does.

    Faces with more than three vertices are triangulated (the mesh must then be manifold and
    consistently oriented). The arrays are what the tool fairs, so ``fair(*read_mesh(p), eps)``
    gives the tool's result for ``p``, bit for bit. A file that CGAL reads as holding no vertex
    gives empty arrays, which `fair` rejects as ``EMPTY_MESH``. For other formats, use meshio
    or Open3D.

    Parameters
    ----------
    path : str or os.PathLike
        The file; its extension names the format.

    Returns
    -------
    vertices : numpy.ndarray
        ``(n, 3)`` float64, in the file's order.
    faces : numpy.ndarray
        ``(m, 3)`` int64 vertex indices.

    Raises
    ------
    FileNotFoundError
        No such file.
    ValueError
        The file cannot be read as a mesh, or its polygons cannot be triangulated.
    """
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise FileNotFoundError(f"no such file: {path}")
    return _core.read_mesh(path)


def write_mesh(path: "os.PathLike[str] | str", vertices: ArrayLike, faces: ArrayLike) -> None:
    """Write a triangle mesh to an OFF, OBJ, PLY or STL file, coordinates at full precision.

    Parameters
    ----------
    path : str or os.PathLike
        The file; its extension (``.off``, ``.obj``, ``.ply``, ``.stl``) names the format.
    vertices : array_like, shape (n, 3)
        Vertex positions, any floating-point dtype.
    faces : array_like, shape (m, 3)
        Triangles as vertex indices, any integer dtype, each in ``[0, n)``.

    Raises
    ------
    ValueError
        An unknown extension, arrays of the wrong shape, face indices out of range, or a file
        that cannot be written.
    """
    path = os.fspath(path)
    if os.path.splitext(path)[1].lower() not in FORMATS:
        raise ValueError(f"{path}: the extension must be one of {', '.join(FORMATS)}")
    V = vertices_array(vertices)
    F = faces_array(faces, V.shape[0])
    if F.size and (F.min() < 0 or F.max() >= V.shape[0]):
        raise ValueError(f"faces refer to vertices outside [0, {V.shape[0]})")
    _core.write_mesh(path, V, F)
