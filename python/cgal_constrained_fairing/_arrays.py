"""The arguments of the package's functions, checked and turned into what the C++ module reads.

Each converter returns a C-contiguous array of the module's dtype, the argument itself when it
is one already (no copy), and raises `InputError` naming the argument otherwise. Values (NaN
coordinates, negative tolerances, ...) are the library's to check, so that its messages are
the same in C++ and in Python.
"""

import operator

import numpy as np

from ._errors import Defect, InputError

_INT64_MAX = np.iinfo(np.int64).max


def invalid(message):
    """An `InputError` of kind ``INVALID_ARGUMENT``."""
    return InputError(Defect.INVALID_ARGUMENT, message)


def _as_array(value, name, dtype=None):
    if isinstance(value, np.ndarray):
        return value
    try:
        return np.asarray(value, dtype=dtype)
    except (TypeError, ValueError) as error:
        raise invalid(f"{name} cannot be read as an array ({error})") from None


def vertices_array(vertices):
    """``(n, 3)`` float64 from an array of any floating-point dtype."""
    V = _as_array(vertices, "vertices", np.float64)
    if V.ndim == 1 and V.size == 0:
        V = V.reshape(0, 3)
    if V.ndim != 2 or V.shape[1] != 3:
        raise invalid(f"vertices must be an (n, 3) array (got shape {V.shape})")
    if V.dtype.kind != "f":
        raise invalid(f"vertices must have a floating-point dtype (got {V.dtype})")
    return np.ascontiguousarray(V, dtype=np.float64)


def faces_array(faces, n):
    """``(m, 3)`` int64 from an array of any integer dtype; `n` is the number of vertices."""
    F = _as_array(faces, "faces")
    if F.ndim == 1 and F.size == 0:
        F = F.reshape(0, 3).astype(np.int64)
    if F.ndim != 2 or F.shape[1] != 3:
        raise invalid(f"faces must be an (m, 3) array of vertex indices (got shape {F.shape})")
    if F.dtype.kind not in "iu":
        raise invalid(f"faces must have an integer dtype (got {F.dtype})")
    beyond = F > np.uint64(_INT64_MAX) if F.dtype.kind == "u" else None
    if beyond is not None and beyond.any():
        # Beyond int64: named here, since the conversion below would wrap it.
        face = int(np.argmax(beyond.any(axis=1)))
        vertex = int(F[face][beyond[face]][0])
        raise InputError(Defect.INVALID_FACE,
                         f"face {face} refers to vertex {vertex}, but there are {n} vertices")
    return np.ascontiguousarray(F, dtype=np.int64)


def numbers_array(value, name, shapes):
    """float64 of one of `shapes` (tuples, with ``"n"`` for the number of vertices) from real
    numbers of any dtype."""
    A = _as_array(value, name, None)
    if A.dtype.kind not in "fiu":
        raise invalid(f"{name} must hold real numbers (got dtype {A.dtype})")
    if A.shape not in shapes:
        raise invalid(f"{name} must have shape {' or '.join(str(s) for s in shapes)} "
                      f"(got {A.shape})")
    return np.ascontiguousarray(A, dtype=np.float64)


def selection_array(value, name, count, what):
    """A choice among `count` items (``what``: "vertex" or "face"): a boolean mask of shape
    ``(count,)`` or an array of distinct indices. Returns the mask."""
    A = _as_array(value, name, None)
    if A.dtype.kind == "b":
        if A.shape != (count,):
            raise invalid(f"{name} as a mask must have shape ({count},), one per {what} "
                          f"(got {A.shape})")
        return np.ascontiguousarray(A, dtype=bool)
    indices = indices_array(A, name, count, what)
    mask = np.zeros(count, dtype=bool)
    mask[indices] = True
    return mask


def indices_array(value, name, count, what):
    """int64 indices into `count` items (``what``: "vertex" or "face"), each listed once, in
    the order given."""
    A = _as_array(value, name, None)
    if A.ndim == 1 and A.size == 0:
        return np.zeros(0, dtype=np.int64)
    if A.ndim != 1 or A.dtype.kind not in "iu":
        raise invalid(f"{name} must be a boolean mask or a 1-d array of {what} indices "
                      f"(got shape {A.shape}, dtype {A.dtype})")
    bad = (A < 0) | (A >= count)
    if bad.any():
        raise invalid(f"{name} holds {what} index {A[bad][0]}, but there are {count}")
    if np.unique(A).size != A.size:
        raise invalid(f"{name} lists a {what} more than once")
    return np.ascontiguousarray(A, dtype=np.int64)


def count_argument(value, name, largest=None):
    """A non-negative integer, at most `largest`."""
    try:
        count = operator.index(value)
    except TypeError:
        raise invalid(f"{name} must be an integer (got {value!r})") from None
    if count < 0 or (largest is not None and count > largest):
        bound = f" and at most {largest}" if largest is not None else ""
        raise invalid(f"{name} must be non-negative{bound} (got {count})")
    return count


def number_argument(value, name, defect=Defect.INVALID_ARGUMENT):
    """A real number; its value is checked by the library."""
    try:
        return float(value)
    except (TypeError, ValueError):
        raise InputError(defect, f"{name} must be a number (got {value!r})") from None


def flag_argument(value, name):
    """``True`` or ``False`` (Python's or numpy's)."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise invalid(f"{name} must be True or False (got {value!r})")


def choice_argument(value, name, choices):
    """One of the strings `choices`, in any case."""
    if isinstance(value, str) and value.lower() in choices:
        return value.lower()
    raise invalid(f"{name} must be one of {', '.join(repr(c) for c in choices)} (got {value!r})")


def bound_arrays(n, tolerance, fixed, box_half_extents, box_centers, item="vertex"):
    """The per-point arrays of a call's bound, checked for `n` points (`item` names one in
    messages): float64 tolerances ``(n,)``, the fixed points as a mask, box half-extents
    ``(n, 3)`` (one triple for all broadcast), box centres ``(n, 3)``; each None if not given."""
    if tolerance is not None:
        tolerance = numbers_array(tolerance, "tolerance", [(n,)])
    if fixed is not None:
        fixed = selection_array(fixed, "fixed", n, item)
    if box_half_extents is not None:
        box_half_extents = numbers_array(box_half_extents, "box_half_extents", [(3,), (n, 3)])
        if box_half_extents.shape == (3,):
            box_half_extents = np.ascontiguousarray(np.broadcast_to(box_half_extents, (n, 3)))
    if box_centers is not None:
        box_centers = numbers_array(box_centers, "box_centers", [(n, 3)])
    return tolerance, fixed, box_half_extents, box_centers
