"""Mesh files through CGAL's readers and writers: OFF, OBJ, PLY and STL."""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Dict, List, Mapping, Optional, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike

from . import _core
from ._arrays import faces_array, numbers_array, vertices_array
from ._errors import InputError

FORMATS = (".off", ".obj", ".ply", ".stl")

# The PLY scalar types and their dtypes, as CGAL writes them.
_PLY_TYPES = {"char": np.int8, "uchar": np.uint8, "short": np.int16, "ushort": np.uint16,
              "int": np.int32, "uint": np.uint32, "float": np.float32, "double": np.float64}
_PLY_TYPE_OF = {np.dtype(dtype): name for name, dtype in _PLY_TYPES.items()}


@dataclass
class MeshProperties:
    """What a PLY file carries besides positions and faces, as `read_mesh` reads it.

    Attributes
    ----------
    vertex : dict of str to numpy.ndarray
        Each scalar vertex property by name, in the file's order: one value per vertex of the
        mesh read, of the dtype of its PLY type (``uchar`` is uint8, ``float`` float32, ...).
    face : dict of str to numpy.ndarray
        Each scalar face property likewise, one value per triangle (a polygon's triangles
        each get its value).
    comments : str
        The header's comment lines, each ended by a newline.
    dropped : list of str
        What the file holds that is not carried (other elements, list properties).
    repair : str
        With ``repair=True``, what the repair changed; empty otherwise.
    """

    vertex: Dict[str, np.ndarray] = field(default_factory=dict)
    face: Dict[str, np.ndarray] = field(default_factory=dict)
    comments: str = ""
    dropped: List[str] = field(default_factory=list)
    repair: str = ""

    def __repr__(self):
        def names(properties):
            return ", ".join(f"{name}: {values.dtype}" for name, values in properties.items())
        return f"MeshProperties(vertex=[{names(self.vertex)}], face=[{names(self.face)}])"


def read_mesh(path: "os.PathLike[str] | str", *, properties: bool = False,
              repair: bool = False) -> Union[Tuple[np.ndarray, np.ndarray],
                                             Tuple[np.ndarray, np.ndarray, MeshProperties]]:
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
    properties : bool
        Also return the file's `MeshProperties`: every scalar vertex and face property of a
        PLY file (colours, a scanner's confidence, ...), which `write_mesh` writes back. The
        file must then be a mesh (manifold, consistently oriented).
    repair : bool
        Make a mesh of a soup that is not one, as the tool's ``--repair``: CGAL's soup repair
        merges duplicate points and faces, splits non-manifold edges and vertices into copies
        at the same position and turns faces to agree (``MeshProperties.repair`` says what it
        changed; implies `properties`).

    Returns
    -------
    vertices : numpy.ndarray
        ``(n, 3)`` float64, in the file's order.
    faces : numpy.ndarray
        ``(m, 3)`` int64 vertex indices.
    properties : MeshProperties
        With `properties` or `repair` only.

    Raises
    ------
    FileNotFoundError
        No such file.
    ValueError
        The file cannot be read as a mesh, or its polygons cannot be triangulated; with
        `properties` or `repair`, an `InputError` naming the defect of a soup that is no mesh
        (``NON_MANIFOLD_EDGE``, ...), as `fair` would.
    """
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise FileNotFoundError(f"no such file: {path}")
    if not (properties or repair):
        return _core.read_mesh(path)
    read = _core.read_mesh_with_properties(path, bool(repair))
    if len(read) == 2:
        defect, message = read
        if defect.name == "NONE":
            raise ValueError(message)
        raise InputError(defect.name, message)
    V, F, vertex, face, comments, dropped, summary = read
    return V, F, MeshProperties(_typed(vertex), _typed(face), comments, list(dropped), summary)


def write_mesh(path: "os.PathLike[str] | str", vertices: ArrayLike, faces: ArrayLike, *,
               properties: Optional[MeshProperties] = None) -> None:
    """Write a triangle mesh to an OFF, OBJ, PLY or STL file, coordinates at full precision.

    Parameters
    ----------
    path : str or os.PathLike
        The file; its extension (``.off``, ``.obj``, ``.ply``, ``.stl``) names the format.
    vertices : array_like, shape (n, 3)
        Vertex positions, any floating-point dtype.
    faces : array_like, shape (m, 3)
        Triangles as vertex indices, any integer dtype, each in ``[0, n)``.
    properties : MeshProperties, optional
        Vertex and face properties to write into a PLY file, one value per vertex or face,
        each as a PLY property of its dtype's type (int8 to uint32, float32, float64; bool as
        uchar), in order, with the comments; the mesh must then be manifold and consistently
        oriented.

    Raises
    ------
    ValueError
        An unknown extension, arrays of the wrong shape, face indices out of range, properties
        for a file that is not PLY or of the wrong length or dtype, or a file that cannot be
        written.
    """
    path = os.fspath(path)
    if os.path.splitext(path)[1].lower() not in FORMATS:
        raise ValueError(f"{path}: the extension must be one of {', '.join(FORMATS)}")
    V = vertices_array(vertices)
    F = faces_array(faces, V.shape[0])
    if F.size and (F.min() < 0 or F.max() >= V.shape[0]):
        raise ValueError(f"faces refer to vertices outside [0, {V.shape[0]})")
    if properties is None or not (properties.vertex or properties.face):
        _core.write_mesh(path, V, F)
        return
    if os.path.splitext(path)[1].lower() != ".ply":
        raise ValueError(f"{path}: properties are written to a .ply file only")
    _core.write_mesh_with_properties(path, V, F, _untyped(properties.vertex, len(V), "vertex"),
                                     _untyped(properties.face, len(F), "face"), properties.comments)


POINT_SET_FORMATS = (".xyz", ".pwn", ".ply", ".off")
"""The extensions of point set files; a ``.ply`` or ``.off`` file is one when it has no face."""


def is_point_set_file(path: "os.PathLike[str] | str") -> bool:
    """Whether `path` holds a point set, as the command-line tool decides.

    An ``.xyz`` or ``.pwn`` file, or a ``.ply`` or ``.off`` file whose header declares points
    and no face.
    """
    return bool(_core.is_point_set_file(os.fspath(path)))


def read_points(path: "os.PathLike[str] | str", *, properties: bool = False):
    """Read a point set file as the command-line tool does: ``.xyz``, ``.pwn`` (with normals),
    or ``.ply`` and ``.off`` without faces.

    ``fair_points(*read_points(p), eps)`` gives the tool's points for ``p``, bit for bit.

    Parameters
    ----------
    path : str or os.PathLike
        The file; its extension names the format.
    properties : bool
        Also return the file's `MeshProperties`: every scalar vertex property of a PLY file
        (its normals ``nx``, ``ny``, ``nz`` among them), which `write_points` writes back.

    Returns
    -------
    points : numpy.ndarray
        ``(n, 3)`` float64, in the file's order.
    normals : numpy.ndarray or None
        ``(n, 3)`` float64, the file's normals (``.pwn``, a PLY's ``nx``, ``ny``, ``nz``), or
        None.
    properties : MeshProperties
        With ``properties=True`` only.

    Raises
    ------
    ValueError
        A file that cannot be read as a point set, with the reason.
    """
    P, N, vertex, comments, dropped = _core.read_point_set(os.fspath(path))
    if not properties:
        return P, N
    return P, N, MeshProperties(vertex=_typed(vertex), comments=comments, dropped=list(dropped))


def write_points(path: "os.PathLike[str] | str", points: ArrayLike,
                 normals: Optional[ArrayLike] = None, *,
                 properties: Optional[MeshProperties] = None) -> None:
    """Write a point set file as the command-line tool writes its output, at full precision.

    Parameters
    ----------
    path : str or os.PathLike
        The file; its extension (``.xyz``, ``.pwn``, ``.ply``, ``.off``) names the format.
    points : array_like, shape (n, 3)
        The points, any floating-point dtype.
    normals : array_like, shape (n, 3), optional
        Their normals, written to a ``.pwn`` (which needs them) or a ``.ply`` file, where they
        replace the properties' ``nx``, ``ny``, ``nz``.
    properties : MeshProperties, optional
        Vertex properties and comments for a ``.ply`` file, as `write_mesh` takes them; face
        properties are refused, a point set has no face.

    Raises
    ------
    ValueError
        An unknown extension, arrays of the wrong shape, properties for a file that is not PLY
        or of the wrong length or dtype, or a file that cannot be written.
    """
    path = os.fspath(path)
    extension = os.path.splitext(path)[1].lower()
    if extension not in POINT_SET_FORMATS:
        raise ValueError(f"{path}: the extension must be one of {', '.join(POINT_SET_FORMATS)}")
    P = vertices_array(points)
    N = None if normals is None else numbers_array(normals, "normals", [(P.shape[0], 3)])
    if extension == ".pwn" and N is None:
        raise ValueError(f"{path}: a .pwn file holds normals; give them")
    vertex, comments = [], ""
    if properties is not None:
        if properties.face:
            raise ValueError(f"{path}: a point set has no face for face properties")
        if properties.vertex and extension != ".ply":
            raise ValueError(f"{path}: properties are written to a .ply file only")
        vertex, comments = _untyped(properties.vertex, len(P), "vertex"), properties.comments
    _core.write_point_set(path, P, N, vertex, comments)


def _typed(properties) -> Dict[str, np.ndarray]:
    return {name: values.astype(_PLY_TYPES[kind]) for name, kind, values in properties}


def _untyped(properties: Mapping[str, ArrayLike], count: int, item: str):
    listed = []
    for name, values in properties.items():
        array = np.asarray(values)
        if array.dtype == np.bool_:
            array = array.astype(np.uint8)
        if array.shape != (count,):
            raise ValueError(f"{item} property {name!r} must have one value per {item} "
                             f"({count}; got shape {array.shape})")
        if array.dtype not in _PLY_TYPE_OF:
            raise ValueError(f"{item} property {name!r} has dtype {array.dtype}; PLY takes "
                             f"{', '.join(str(np.dtype(d)) for d in _PLY_TYPES.values())} and bool")
        if not isinstance(name, str) or not name or any(c.isspace() for c in name):
            raise ValueError(f"{item} property name {name!r} must be a word without blanks")
        listed.append((name, _PLY_TYPE_OF[array.dtype], np.ascontiguousarray(array, dtype=np.float64)))
    return listed
