"""The batch's `eps`: checked once for the batch, then turned into each file's epsilon.

A text is read by the library's one grammar of tolerances (``front_end/Epsilon_grammar.h``),
which the command-line tool's ``--eps`` reads too: ``"0.002"``, ``"0.25h"``, ``"h"`` or
``"auto"``, in any case, with blanks around.
"""

import math
from typing import Tuple, Union

from .. import _core
from .._fairing import estimate_noise_level, mean_edge_length

Eps = Union[str, float, int]

DEFAULT_EPS = _core.default_epsilon
"""The tolerance of a batch that names none, as the command-line tool's."""


def parse_eps(eps: Eps) -> Tuple[str, float]:
    """``("h", x)``, ``("auto", 0.0)`` or ``("value", epsilon)``; ValueError if malformed."""
    if isinstance(eps, str):
        return _core.parse_epsilon(eps)
    if isinstance(eps, (int, float)) and not isinstance(eps, bool):
        if not (math.isfinite(eps) and eps > 0):
            raise ValueError(f"eps must be positive and finite (got {eps!r})")
        return ("value", float(eps))
    raise ValueError(f"eps must be a number, a number followed by h, or auto (got {eps!r})")


def mesh_epsilon(eps: Tuple[str, float], V, F) -> float:
    """The epsilon of the mesh ``(V, F)`` for a `parse_eps` result; ValueError if none."""
    kind, value = eps
    if kind == "h":
        return value * mean_edge_length(V, F)
    if kind == "auto":
        noise = estimate_noise_level(V, F)
        if not noise > 0:
            raise ValueError("cannot estimate the noise level of so small a mesh; give eps")
        return noise
    return value


def points_epsilon(eps: Tuple[str, float], P) -> float:
    """The epsilon of the point set `P` for a `parse_eps` result; ValueError if none."""
    kind, value = eps
    if kind == "h":
        raise ValueError("a point set has no edges for h; give eps as a distance or auto")
    if kind == "auto":
        noise = estimate_noise_level(P)
        if not noise > 0:
            raise ValueError("cannot estimate the noise level of so few points; give eps")
        return noise
    return value
