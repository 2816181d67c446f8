"""Label maps to surfaces: one closed surface per label, the interfaces shared exactly."""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import List, Optional, Sequence, Tuple

import numpy as np
from numpy.typing import ArrayLike

from . import _core
from ._arrays import bound_arrays, invalid, numbers_array, vertices_array
from ._errors import Defect, InputError
from ._fairing import Progress, _Progress, call_options, result_of
from ._report import Report

#: The margin, a fraction of the voxel spacing, that every point's box keeps from the sides of its
#: dual cell (``CGAL::Polygon_mesh_processing::label_box_margin``): the boxes of two points are
#: at least twice this apart, so that no two points of a faired label map meet.
LABEL_BOX_MARGIN: float = _core.label_box_margin


@dataclass(frozen=True, repr=False)
class LabelSurfaces:
    """The surfaces of a label map, as one multi-label triangle soup.

    Attributes
    ----------
    vertices : numpy.ndarray
        ``(n, 3)`` float64, the points, shared by the surfaces of the labels they separate.
    faces : numpy.ndarray
        ``(m, 3)`` int64, the triangles.
    face_labels : numpy.ndarray
        ``(m, 2)`` int64: the normal of face ``f`` points from the region of
        ``face_labels[f, 0]`` into that of ``face_labels[f, 1]``.
    unfaired_vertices : numpy.ndarray
        ``(n, 3)`` float64, the surface-nets points: the centres of the boxes in which the
        faired points stay.
    box_half_extents : numpy.ndarray
        ``(n, 3)`` float64, the half-extents of each point's box (in the voxels' frame): its dual
        cell shrunk by `LABEL_BOX_MARGIN` of the spacing, or a part of it where the cell holds
        several sheets of a surface, smaller around a point moved off its centre to part
        crossing triangles (``CGAL::Polygon_mesh_processing::label_surface_nets()``).
    report : Report or None
        What the fairing did; ``None`` when it was not asked for.
    labels : numpy.ndarray
        The labels that have a surface, sorted (the background is not among them).
    """

    vertices: np.ndarray
    faces: np.ndarray
    face_labels: np.ndarray
    unfaired_vertices: np.ndarray
    box_half_extents: np.ndarray
    report: Optional[Report]
    labels: np.ndarray

    def surface(self, label: int) -> Tuple[np.ndarray, np.ndarray]:
        """The closed surface of `label`, oriented outward, as ``(V, F)``.

        Its points are copies of `vertices`, bit for bit, so that two labels' surfaces fit
        together exactly. Where the label's voxels touch only along an edge or at a corner, its
        sheets there have points of their own, kept apart by their boxes.
        """
        if label not in set(self.labels.tolist()):
            raise invalid(f"label {label!r} has no surface (labels: {self.labels.tolist()})")
        return _core.label_surface(self.vertices, self.faces, self.face_labels, int(label))

    def write(self, folder: "os.PathLike[str] | str", format: str = "ply", *,
              force: bool = False) -> List[Path]:
        """Write each label's closed surface to ``folder / label_<L>.<format>``.

        Nothing else in `folder` is touched: a new folder appears with all the files at once;
        an existing one gets only these files, each written beside its name and renamed into
        place once all are complete, so that a failed write leaves the folder as it was.

        Parameters
        ----------
        folder : str or os.PathLike
            The folder; its parent must exist.
        format : {"ply", "off", "obj", "stl"}
            The surfaces' format.
        force : bool
            Replace the ``label_<L>`` files that exist; without it they are refused.

        Returns
        -------
        list of pathlib.Path
            The files written, in the order of `labels`.

        Raises
        ------
        ValueError
            Before anything is written: `folder` is an existing file, a surface's file exists
            (without `force`) or is a folder, an unknown `format`; or a file cannot be written.
        """
        format = str(format).lower().lstrip(".")
        if format not in ("ply", "off", "obj", "stl"):
            raise ValueError(f"format must be ply, off, obj or stl (got {format!r})")
        folder = Path(os.fspath(folder))
        names = [f"label_{label}.{format}" for label in self.labels.tolist()]
        surfaces = [self.surface(label) for label in self.labels.tolist()]
        _core.write_files_into_folder("", str(folder), names, surfaces, bool(force))
        return [folder / name for name in names]

    def __repr__(self):
        fairing = "not faired" if self.report is None else self.report.status.value.lower()
        return (f"LabelSurfaces({len(self.labels)} label{'s' if len(self.labels) != 1 else ''} "
                f"{self.labels.tolist()[:10]}{'...' if len(self.labels) > 10 else ''}, "
                f"{len(self.vertices)} points, {len(self.faces)} triangles, {fairing})")


def label_surfaces(labels: ArrayLike, spacing: Sequence[float] = (1, 1, 1),
                   origin: Sequence[float] = (0, 0, 0), *,
                   affine: Optional[ArrayLike] = None,
                   fair: bool = True,
                   background: int = 0,
                   labels_to_mesh: Optional[Sequence[int]] = None,
                   epsilon: Optional[float] = None,
                   objective: Optional[str] = None,
                   max_iterations: Optional[int] = None,
                   progress: Progress = None) -> LabelSurfaces:
    """The surfaces of a 3-D label map, faired together within their voxels.

    Multi-label surface nets (``CGAL::Polygon_mesh_processing::label_surface_nets()``): a point
    at the centre of each cube of 8 voxel centres whose labels differ (or of each part of it
    that a sheet of the surface occupies, moved where triangles would cross), two triangles for
    each pair of neighbouring voxels with different labels. Then, with `fair`, all the interfaces are faired
    at once (``constrained_fairing_of_interfaces()``): each point stays in its box (its dual cell
    shrunk by `LABEL_BOX_MARGIN` of the spacing, or the part of it that its sheet occupies
    where a label's voxels meet only along an edge or at a corner, smaller around a point moved
    to part crossing triangles of the nets; exactly in double), the
    interfaces stay shared, the surfaces never touch themselves or each other, and the junction
    lines where three labels meet are faired as curves.

    Parameters
    ----------
    labels : array_like, shape (I, J, K)
        The label of each voxel, any integer dtype (a boolean mask is label 1); voxel ``[i, j, k]`` has its centre at
        ``origin + (i, j, k) * spacing``. Never modified.
    spacing : sequence of 3 floats
        The distance between voxel centres along each axis, positive (NIfTI's ``pixdim``).
    origin : sequence of 3 floats
        The centre of voxel ``[0, 0, 0]``.
    affine : array_like, shape (4, 4), optional
        Instead of `spacing` and `origin`: the map from voxel indices to world coordinates
        (a NIfTI image's ``affine``, as `read_label_map` returns it), which may also rotate and
        mirror the axes. The surfaces are computed and faired in the voxels' own frame (spacing
        the lengths of the affine's columns) and then moved into the world, so that each point
        stays in its voxel; where the affine mirrors, the faces are turned so that normals still
        point from ``face_labels[f, 0]`` into ``face_labels[f, 1]``. A sheared affine is applied
        as it is, after the fairing.
    fair : bool
        Fair the surfaces (default); ``False`` returns the surface nets.
    background : int
        The label of the outside (also of everything outside the array): it gets no surface.
    labels_to_mesh : sequence of int, optional
        The labels to make surfaces of; the others count as `background`. Default: all.
    epsilon : float, optional
        A cap on how far a point moves; default: no cap beyond the voxel box.
    objective : {None, "fairest", "accurate"}
        As in `fair`.
    max_iterations : int, optional
        As in `fair`.
    progress : None, True or callable, optional
        As in `fair`.

    Returns
    -------
    LabelSurfaces

    Raises
    ------
    InputError
        (a ValueError) `labels` not 3-D or not integers, `spacing` not positive and finite,
        `origin` not finite, `affine` not a finite (4, 4) array whose first three columns are
        independent, or given with `spacing` or `origin` (``INVALID_ARGUMENT``); a map with
        nothing but background (``NO_FACES``).

    Examples
    --------
    >>> import numpy as np
    >>> import cgal_constrained_fairing as cf
    >>> labels = np.zeros((20, 20, 20), np.uint8)
    >>> labels[5:15, 5:15, 5:15] = 1
    >>> labels[5:15, 5:15, 10:15] = 2
    >>> r = cf.label_surfaces(labels, spacing=(0.5, 0.5, 1.5))
    >>> V, F = r.surface(2)     # closed and outward, sharing its points with label 1's
    """
    L = np.asarray(labels)
    if L.ndim != 3:
        raise invalid(f"labels must be a 3-D array (got {L.ndim} dimensions)")
    if L.dtype.kind == "b":  # a mask: label 1 inside
        L = L.astype(np.uint8)
    if L.dtype.kind not in "iu":
        raise invalid(f"labels must have an integer or boolean dtype (got {L.dtype})")
    frame = None
    if affine is not None:
        if tuple(spacing) != (1, 1, 1) or tuple(origin) != (0, 0, 0):
            raise invalid("give either affine, or spacing and origin")
        frame = _Frame(affine)
        spacing = frame.spacing
    h, o = _checked_spacing(spacing, origin)
    L = L.astype(np.int64)  # a copy: the user's array is never touched
    if labels_to_mesh is not None:
        L[~np.isin(L, np.asarray(labels_to_mesh, dtype=np.int64))] = background
    V, F, FL, H = _core.label_surface_nets(np.ascontiguousarray(L), h.tolist(), o.tolist(), int(background))
    present = np.unique(FL)
    present = present[present != background]
    if F.shape[0] == 0:
        if labels_to_mesh is not None:
            raise InputError(Defect.NO_FACES, f"none of labels_to_mesh {list(labels_to_mesh)} is "
                             f"in the label map (its labels: {_labels_of(labels, background)})")
        raise InputError(Defect.NO_FACES, "the label map holds nothing but the background label")
    report = None
    W = V.copy()
    if fair:
        cap = _core.label_map_epsilon(h.tolist()) if epsilon is None else epsilon
        W, report = fair_interfaces(V, F, FL, cap, box_half_extents=H, objective=objective,
                                    max_iterations=max_iterations, progress=progress)
    if frame is not None:
        W, V, F = frame.to_world(W), frame.to_world(V), frame.faces(F)
    return LabelSurfaces(W, F, FL, V, H, report, present)


def _checked_spacing(spacing, origin) -> Tuple[np.ndarray, np.ndarray]:
    """`spacing` and `origin` as arrays of 3 floats, checked."""
    h = numbers_array(spacing, "spacing", [(3,)])
    o = numbers_array(origin, "origin", [(3,)])
    if not (np.isfinite(h).all() and (h > 0).all()):
        raise invalid(f"spacing must be three positive finite numbers (got {h.tolist()})")
    if not np.isfinite(o).all():
        raise invalid(f"origin must be three finite numbers (got {o.tolist()})")
    return h, o


def _labels_of(labels, background) -> list:
    """The labels of a map other than the background, the first twenty."""
    present = np.unique(np.asarray(labels))
    present = present[present != background].tolist()
    return present[:20] + (["..."] if len(present) > 20 else [])


class _Frame:
    """An affine split into the voxels' spacing and the rigid move (or mirror) into the world,
    as the command-line tool splits it."""

    def __init__(self, affine):
        A = numbers_array(affine, "affine", [(4, 4)])
        error, spacing, axes, translation, self.mirrors = _core.voxel_frame(A[:3].tolist())
        if error:
            raise invalid(f"{error} (got {A[:3, :3].tolist()})")
        self.spacing = np.array(spacing)
        self.axes = np.array(axes)
        self.translation = np.array(translation)

    def to_world(self, points: np.ndarray) -> np.ndarray:
        return points @ self.axes.T + self.translation

    def faces(self, faces: np.ndarray) -> np.ndarray:
        return np.ascontiguousarray(faces[:, [0, 2, 1]]) if self.mirrors else faces


def fair_interfaces(vertices: ArrayLike, faces: ArrayLike, face_labels: ArrayLike,
                    epsilon: Optional[float] = None, *,
                    box_half_extents: Optional[ArrayLike] = None,
                    box_centers: Optional[ArrayLike] = None,
                    tolerance: Optional[ArrayLike] = None,
                    fixed: Optional[ArrayLike] = None,
                    objective: Optional[str] = None,
                    fidelity_weight: Optional[float] = None,
                    max_iterations: Optional[int] = None,
                    energy_decrease_threshold: Optional[float] = None,
                    sliver_barrier_weight: Optional[float] = None,
                    initial_smoothing_steps: Optional[int] = None,
                    progress: Progress = None) -> Tuple[np.ndarray, Report]:
    """Fair a multi-label triangle soup, all its interfaces at once, within a bound.

    ``CGAL::Polygon_mesh_processing::constrained_fairing_of_interfaces()``: the soup's triangles
    each separate two labels (`face_labels`, the normal pointing from the first's region into
    the second's), as `label_surfaces` makes them; each interface is faired by the bending energy,
    the junction lines where three labels meet as curves; points where lines end or branch, or
    where four labels meet, stay.

    Parameters
    ----------
    vertices, faces : array_like
        As in `fair`; the soup need not be a manifold.
    face_labels : array_like, shape (m, 2)
        The two labels of each face, different, any integer dtype.
    epsilon : float, optional
        The bound of every point, and the cap of the boxes; default: the largest box diagonal
        (so only the boxes bound) when boxes are given. Required otherwise.
    box_half_extents, box_centers, tolerance, fixed, objective, fidelity_weight, max_iterations,
    energy_decrease_threshold, sliver_barrier_weight, initial_smoothing_steps, progress
        As in `fair`.

    Returns
    -------
    new_vertices : numpy.ndarray
        ``(n, 3)`` float64.
    report : Report

    Raises
    ------
    InputError
        (a ValueError) As `fair`; also a face with the same label on both sides
        (``INVALID_FACE``) and two faces of one interface running the same way through their
        shared edge (``INCONSISTENT_ORIENTATION``). The input arrays are never modified.
    """
    V = vertices_array(vertices)
    n = V.shape[0]
    F = np.ascontiguousarray(np.asarray(faces))
    if F.ndim != 2 or F.shape[1] != 3 or F.dtype.kind not in "iu":
        raise invalid(f"faces must be an (m, 3) integer array (got shape {F.shape}, dtype {F.dtype})")
    F = F.astype(np.int64)
    FL = np.asarray(face_labels)
    if FL.shape != (F.shape[0], 2) or FL.dtype.kind not in "iu":
        raise invalid(f"face_labels must be an ({F.shape[0]}, 2) integer array "
                      f"(got shape {FL.shape}, dtype {FL.dtype})")
    FL = np.ascontiguousarray(FL, dtype=np.int64)
    tolerance, fixed, box_half_extents, box_centers = bound_arrays(n, tolerance, fixed, box_half_extents,
                                                                   box_centers)
    if epsilon is None:
        if box_half_extents is None:
            raise invalid("epsilon is needed without box_half_extents")
        epsilon = 2 * float(np.linalg.norm(box_half_extents, axis=1).max(initial=0))
    options = call_options(epsilon, objective=objective, fidelity_weight=fidelity_weight,
                           sliver_barrier_weight=sliver_barrier_weight,
                           energy_decrease_threshold=energy_decrease_threshold,
                           max_iterations=max_iterations,
                           initial_smoothing_steps=initial_smoothing_steps)
    with _Progress(progress, options) as callback:
        outcome = _core.fair_interfaces(V, F, FL, options, tolerance, fixed, box_half_extents,
                                        box_centers, callback)
    return result_of(outcome)
