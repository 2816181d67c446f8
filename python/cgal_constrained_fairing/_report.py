"""What a call of `fair` did."""

import dataclasses
import enum

import numpy as np

from ._errors import Defect


class Status(str, enum.Enum):
    """How a call of `fair` ended; the failures of the C++ call are raised instead."""

    CONVERGED = "CONVERGED"
    """The relative energy decrease fell below the threshold, or no feasible direction
    decreases the energy any more."""
    ITERATION_LIMIT_REACHED = "ITERATION_LIMIT_REACHED"
    """``max_iterations`` iterations were done; the result is the last iterate."""
    CANCELLED = "CANCELLED"
    """The progress callback returned ``False``; the result is the last iterate."""

    def __str__(self) -> str:
        return self.value


@dataclasses.dataclass(frozen=True, repr=False)
class Report:
    """What `fair` did: the fields of the C++ ``Constrained_fairing_result`` and two arrays.

    Attributes
    ----------
    status : Status
        How the call ended.
    message : str
        Empty on success (the C++ message of a failure is the exception's).
    defect : Defect
        Always ``Defect.NONE`` here: a defect is raised as `InputError`.
    number_of_iterations : int
        Iterations done (accepted quasi-Newton steps with the default method).
    number_of_cg_iterations : int
        Conjugate gradient iterations (``method="active_set_newton"`` only).
    number_of_energy_evaluations : int
        Evaluations of the objective, the main cost of the default method.
    initial_energy, final_energy : float
        The objective on the input and on the output: the bending energy plus the barrier
        against slivers, plus the fidelity term for ``objective="accurate"``.
    initial_bending_energy, final_bending_energy : float
        The bending energy alone, the paper's measure of fairness, of the input and of the
        output.
    max_deviation : float
        The largest distance of an output vertex to its input position.
    number_of_vertices_at_bound : int
        Vertices that could move and ended on the boundary of their ball or box.
    number_of_fixed_vertices : int
        Vertices that could not move (``fixed``, a tolerance of 0, outside the ``region`` or
        on its border).
    number_of_folded_faces : int
        Faces still turned over against their neighbours at the end.
    number_of_unfolded_faces : int
        Folded faces that the fold repair undid.
    number_of_feature_edges : int
        Edges kept as creases (given in ``feature_edges`` or detected by ``feature_angle``),
        across which the energy has no hinge.
    feature_edges : numpy.ndarray
        ``(k, 2)`` int64: those edges as vertex pairs, the smaller index first, in increasing
        order (empty for label maps).
    number_of_degenerate_edges : int
        Interior edges left out of the energy because a triangle of theirs is degenerate in
        the input.
    deviation : numpy.ndarray
        ``(n,)`` float64: each vertex's distance to its input position.
    at_bound : numpy.ndarray
        ``(n,)`` bool: whether each vertex that could move ended on its bound.
    """

    status: Status
    message: str
    defect: Defect
    number_of_iterations: int
    number_of_cg_iterations: int
    number_of_energy_evaluations: int
    initial_energy: float
    final_energy: float
    initial_bending_energy: float
    final_bending_energy: float
    max_deviation: float
    number_of_vertices_at_bound: int
    number_of_fixed_vertices: int
    number_of_folded_faces: int
    number_of_unfolded_faces: int
    number_of_feature_edges: int
    number_of_degenerate_edges: int
    feature_edges: np.ndarray
    deviation: np.ndarray
    at_bound: np.ndarray

    def __repr__(self) -> str:
        lines = [
            f"Report({self.status.value.lower().replace('_', ' ')} after "
            f"{self.number_of_iterations} iterations, "
            f"{self.number_of_energy_evaluations} energy evaluations",
            f"  bending energy {self.initial_bending_energy:.6g} -> "
            f"{self.final_bending_energy:.6g}, objective {self.initial_energy:.6g} -> "
            f"{self.final_energy:.6g}",
            f"  deviation at most {self.max_deviation:.6g}; {self.number_of_vertices_at_bound} of "
            f"{self.deviation.shape[0]} vertices at the bound, {self.number_of_fixed_vertices} fixed",
        ]
        if self.number_of_folded_faces or self.number_of_unfolded_faces:
            lines.append(f"  {self.number_of_unfolded_faces} faces unfolded, "
                         f"{self.number_of_folded_faces} left folded")
        if self.number_of_feature_edges:
            lines.append(f"  {self.number_of_feature_edges} edges kept as creases")
        if self.number_of_degenerate_edges:
            lines.append(f"  {self.number_of_degenerate_edges} edges with a degenerate "
                         "triangle left out of the energy")
        return "\n".join(lines) + ")"
