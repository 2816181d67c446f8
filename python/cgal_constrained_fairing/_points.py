"""Point sets faired within a bound: ``fair_points``, on numpy arrays."""

from __future__ import annotations

import dataclasses
from typing import Optional, Tuple

import numpy as np
from numpy.typing import ArrayLike

from . import _core
from ._arrays import bound_arrays, count_argument, numbers_array, vertices_array
from ._fairing import DEFAULT_NEIGHBORS, Progress, _Progress, call_options, result_of
from ._report import Report

@dataclasses.dataclass(frozen=True, repr=False)
class PointsReport(Report):
    """What `fair_points` did: the fields of `Report`, and two of a point set's own.

    Attributes
    ----------
    number_of_isolated_points : int
        Points with no usable neighbourhood (outliers far from the others, or whose neighbours
        are on a line), kept where they are; counted in ``number_of_fixed_vertices`` too.
    normals : numpy.ndarray or None
        ``(n, 3)`` float64: the unit normals at the result, oriented as the given ones; None
        when no normals were given.
    """

    number_of_isolated_points: int = 0
    normals: Optional[np.ndarray] = None


def fair_points(points: ArrayLike, epsilon: float, normals: Optional[ArrayLike] = None, *,
                neighbors: int = DEFAULT_NEIGHBORS, bound: Optional[str] = None,
                objective: Optional[str] = None, fidelity_weight: Optional[float] = None,
                tangential_motion: Optional[bool] = None,
                energy_decrease_threshold: Optional[float] = None,
                max_iterations: Optional[int] = None,
                initial_smoothing_steps: Optional[int] = None,
                tolerance: Optional[ArrayLike] = None, fixed: Optional[ArrayLike] = None,
                box_half_extents: Optional[ArrayLike] = None,
                box_centers: Optional[ArrayLike] = None,
                progress: Optional[Progress] = None) -> Tuple[np.ndarray, PointsReport]:
    """Fair a point set while keeping every point within `epsilon` of its input position.

    The C++ ``constrained_fairing_of_points()``: the bending energy of each point's tangent fan
    (its neighbours' Delaunay triangulation in its tangent plane) is minimized under the bound;
    every point is kept, in its order.

    Parameters
    ----------
    points : array_like
        ``(n, 3)`` coordinates; never modified.
    epsilon : float
        The largest distance a point may move.
    normals : array_like, optional
        ``(n, 3)`` normals, which orient the result's; estimated (CGAL's jet fit, oriented along
        a spanning tree) when None.
    neighbors : int
        The neighbours of each point, for its normal and its fan (at least 3).
    bound, objective, fidelity_weight, tangential_motion, energy_decrease_threshold, \
max_iterations, initial_smoothing_steps, tolerance, fixed, box_half_extents, box_centers, progress
        As for `fair`, per point.

    Returns
    -------
    points : numpy.ndarray
        ``(n, 3)`` float64, the faired points, in the input's order.
    report : PointsReport
        What the call did, with the normals at the result when normals were given.

    Raises
    ------
    InputError
        (a ValueError) As `fair`; also ``TOO_FEW_POINTS``, ``INVALID_NUMBER_OF_NEIGHBORS``,
        ``DUPLICATE_POINTS``, ``INVALID_NORMAL``, ``NO_SURFACE``; an array of the wrong shape.
    """
    P = vertices_array(points)
    n = P.shape[0]
    N = None if normals is None else numbers_array(normals, "normals", [(n, 3)])
    neighbors = count_argument(neighbors, "neighbors")
    options = call_options(epsilon, bound=bound, objective=objective,
                           fidelity_weight=fidelity_weight, tangential_motion=tangential_motion,
                           energy_decrease_threshold=energy_decrease_threshold,
                           max_iterations=max_iterations,
                           initial_smoothing_steps=initial_smoothing_steps)
    tolerance, fixed, box_half_extents, box_centers = bound_arrays(n, tolerance, fixed, box_half_extents,
                                                                   box_centers, "point")
    with _Progress(progress, options) as callback:
        outcome = _core.fair_points(P, N, neighbors, options, tolerance, fixed, box_half_extents,
                                    box_centers, callback)
    Q, report = result_of(outcome)
    fields = dataclasses.asdict(report)
    return Q, PointsReport(**fields, number_of_isolated_points=outcome["number_of_isolated_points"],
                           normals=outcome.get("normals"))
