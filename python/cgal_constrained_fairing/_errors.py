"""The kinds of bad input, and the exception that names them."""

import enum


class Defect(str, enum.Enum):
    """What is wrong with an input that `fair` rejected.

    The members are those of the C++ ``Constrained_fairing_defect``, in the order the checks
    are made, and ``INVALID_ARGUMENT`` for an argument that is not even of the right kind (an
    array of the wrong shape or dtype, an unknown option). A member compares equal to its name,
    so ``error.defect == "NON_MANIFOLD_EDGE"`` holds as well as
    ``error.defect is Defect.NON_MANIFOLD_EDGE``.
    """

    NONE = "NONE"
    """The input was accepted."""
    INVALID_ARGUMENT = "INVALID_ARGUMENT"
    """An argument of the wrong type, shape, dtype or length, or an unknown option value."""
    EMPTY_MESH = "EMPTY_MESH"
    """The mesh has no vertex."""
    NO_FACES = "NO_FACES"
    """The mesh has no face."""
    INVALID_FACE = "INVALID_FACE"
    """A face refers to a vertex that does not exist, or twice to the same vertex."""
    BROKEN_STRUCTURE = "BROKEN_STRUCTURE"
    """The halfedge links disagree (not possible from arrays)."""
    NOT_TRIANGLE = "NOT_TRIANGLE"
    """A face is not a triangle (not possible from arrays)."""
    NON_MANIFOLD_EDGE = "NON_MANIFOLD_EDGE"
    """An edge with more than two faces."""
    INCONSISTENT_ORIENTATION = "INCONSISTENT_ORIENTATION"
    """Two neighbouring faces run through their shared edge in the same direction."""
    NON_MANIFOLD_VERTEX = "NON_MANIFOLD_VERTEX"
    """The faces around a vertex form more than one fan."""
    MESH_TOO_LARGE = "MESH_TOO_LARGE"
    """More vertices or faces than the solver's 32-bit indices hold."""
    NON_FINITE_COORDINATE = "NON_FINITE_COORDINATE"
    """A vertex has a NaN or infinite coordinate."""
    INVALID_EPSILON = "INVALID_EPSILON"
    """``epsilon`` is not a positive finite number."""
    INVALID_FIDELITY_WEIGHT = "INVALID_FIDELITY_WEIGHT"
    """``fidelity_weight`` is negative, NaN or infinite."""
    INVALID_SLIVER_BARRIER_WEIGHT = "INVALID_SLIVER_BARRIER_WEIGHT"
    """``sliver_barrier_weight`` is negative, NaN or infinite."""
    INVALID_FEATURE_ANGLE = "INVALID_FEATURE_ANGLE"
    """``feature_angle`` is not a number of degrees strictly between 0 and 180."""
    BOX_WITH_BALL = "BOX_WITH_BALL"
    """Box half-extents or centres were given with ``bound="ball"``."""
    INVALID_BOX_EXTENTS = "INVALID_BOX_EXTENTS"
    """A box half-extent is negative, NaN or infinite."""
    INVALID_TOLERANCE = "INVALID_TOLERANCE"
    """A per-vertex tolerance is negative, NaN or infinite."""
    INVALID_BOX_CENTER = "INVALID_BOX_CENTER"
    """A box centre has a NaN or infinite coordinate."""
    OUTSIDE_BOX = "OUTSIDE_BOX"
    """An input position lies outside its box."""
    NO_AREA = "NO_AREA"
    """Every triangle has zero area."""
    TOO_FEW_POINTS = "TOO_FEW_POINTS"
    """A point set has no more points than ``neighbors``."""
    INVALID_NUMBER_OF_NEIGHBORS = "INVALID_NUMBER_OF_NEIGHBORS"
    """``neighbors`` is less than 3."""
    DUPLICATE_POINTS = "DUPLICATE_POINTS"
    """Two points of a point set coincide."""
    INVALID_NORMAL = "INVALID_NORMAL"
    """A given normal is zero, NaN or infinite."""
    NO_SURFACE = "NO_SURFACE"
    """The points of a point set are all on one line."""
    METHOD_NEEDS_MESH = "METHOD_NEEDS_MESH"
    """A point set was given a method other than the default quasi-Newton method."""

    def __str__(self) -> str:
        return self.value


class InputError(ValueError):
    """The input was rejected before anything was computed; the input arrays are unchanged.

    Attributes
    ----------
    defect : Defect
        The kind of defect.
    message : str
        The library's one-line message, naming the first vertex or face concerned; also the
        exception's text.
    """

    def __init__(self, defect: Defect, message: str) -> None:
        super().__init__(message)
        self.defect = Defect(defect)
        self.message = message

    def __reduce__(self):
        # Pickled whole, so that it crosses process boundaries (Dask workers) with its defect.
        return (type(self), (self.defect, self.message))
