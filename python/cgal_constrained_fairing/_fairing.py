"""`fair` and the measures of a mesh, on numpy arrays."""

# The annotations stay text: help(fair) shows ``ArrayLike``, not numpy's expansion of it.
from __future__ import annotations

import collections
import sys
import time
import warnings
from typing import Callable, Optional, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike

from . import _core
from ._arrays import (_as_array, bound_arrays, choice_argument, count_argument, faces_array,
                      flag_argument, indices_array, invalid, number_argument, selection_array,
                      vertices_array)
from ._errors import Defect, InputError
from ._report import Report, Status

DEFAULT_NEIGHBORS = 32
"""The C++ default of ``number_of_neighbors``: a point set's neighbours per point."""

NOISE_FIT_NEIGHBORS = 14
"""The fewest neighbours of the noise estimate's cubic fit (ten coefficients and a margin)."""

_METHODS = ("quasi_newton", "active_set_newton", "projected_gradient")
_UINT_MAX = 2**32 - 1

Progress = Union[None, bool, Callable[[int, float], Optional[bool]]]


def fair(vertices: ArrayLike, faces: ArrayLike, epsilon: float, *,
         bound: Optional[str] = None,
         box_half_extents: Optional[ArrayLike] = None,
         box_centers: Optional[ArrayLike] = None,
         tolerance: Optional[ArrayLike] = None,
         fixed: Optional[ArrayLike] = None,
         region: Optional[ArrayLike] = None,
         feature_edges: Optional[ArrayLike] = None,
         objective: Optional[str] = None,
         fidelity_weight: Optional[float] = None,
         method: Optional[str] = None,
         max_iterations: Optional[int] = None,
         energy_decrease_threshold: Optional[float] = None,
         sliver_barrier_weight: Optional[float] = None,
         tangential_motion: Optional[bool] = None,
         feature_angle: Optional[float] = None,
         initial_smoothing_steps: Optional[int] = None,
         conjugate_gradient_iterations: Optional[int] = None,
         progress: Progress = None) -> Tuple[np.ndarray, Report]:
    """Fair a triangle mesh: remove its noise while every vertex stays within `epsilon`.

    Minimizes the discrete bending energy of the mesh (Hildebrandt and Polthier, "Constraint-based
    fairing of surface meshes", SGP 2007) over vertex positions ``p`` with
    ``|p - p0| <= epsilon``, ``p0`` the input position; by default over the positions along the
    normals of a smoothed start only (see `tangential_motion`). Set `epsilon` to the accuracy of
    the data (a scanner's precision, the voxel size of an isosurface): noise and terracing go,
    that accuracy stays. The connectivity does not change. This is
    ``CGAL::Polygon_mesh_processing::constrained_fairing()``, called on the ``CGAL::Surface_mesh``
    that a C++ program builds from the same arrays: the result is bit-identical to that call's,
    and to the command-line tool's.

    The bound holds exactly in double precision, with no tolerance::

        np.linalg.norm(new_vertices - vertices, axis=1) <= epsilon   # all True

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
        The vertex positions, of any floating-point dtype (computed in float64). A float64
        C-contiguous array is read without a copy. Never modified.
    faces : array_like, shape (m, 3)
        The triangles, as indices into `vertices` (any integer dtype). The mesh must be manifold
        and consistently oriented; it may have borders and isolated vertices (which stay).
    epsilon : float
        The largest distance a vertex may move, in the units of `vertices`; it caps every other
        size below. ``mean_edge_length(vertices, faces)`` gives a scale (a quarter of it is a
        good start for noise) and ``estimate_noise_level(vertices, faces)`` estimates it.
    bound : {None, "ball", "box"}
        The set each vertex stays in: ``"ball"``, the ball of radius `epsilon` (what "within
        epsilon" means), or ``"box"``, the cube of half-side `epsilon` of the paper (each
        coordinate within `epsilon`). Default: ``"box"`` if `box_half_extents` or `box_centers`
        is given, ``"ball"`` otherwise. ``"ball"`` with box arrays raises (``BOX_WITH_BALL``).
    box_half_extents : array_like, shape (3,) or (n, 3), optional
        The half-extents of the box along x, y and z, for every vertex or for each one (a voxel's
        half size, for surfaces extracted from volumes), each capped by the vertex's tolerance.
    box_centers : array_like, shape (n, 3), optional
        Each vertex's box centre (its voxel cell), instead of its input position; each input
        position must lie in its box (``OUTSIDE_BOX`` otherwise).
    tolerance : array_like, shape (n,), optional
        Each vertex's own tolerance (a scanner's per-point accuracy), capped by `epsilon`; ``0``
        pins the vertex.
    fixed : array_like, optional
        The vertices that must not move: a boolean mask of shape ``(n,)``, or an array of
        vertex indices. Their coordinates come out bit-identical.
    region : array_like, optional
        Fair only these faces (a boolean mask of shape ``(m,)`` or face indices, each listed
        once): only vertices whose faces all lie in the region move, so its border stays.
    feature_edges : array_like, shape (k, 2), optional
        Creases to keep sharp, as pairs of vertex indices (any integer dtype), each an edge of
        the mesh; those `feature_angle` detects are added to them.
    objective : {None, "fairest", "accurate"}
        ``"fairest"`` (the default) minimizes the bending energy alone: the fairest surface within the bound.
        ``"accurate"`` adds a fidelity term towards a denoised copy of the input: closer to the
        true surface of a noisy scan, a little less fair. Not for surfaces extracted from
        volumes.
    fidelity_weight : float, optional
        The weight of the fidelity term of ``objective="accurate"`` (default 10000); larger keeps
        nearer the denoised input, ``0`` is the fairest objective.
    method : {None, "quasi_newton", "active_set_newton", "projected_gradient"}
        The optimization method: the default projected quasi-Newton method, or the paper's
        active set Newton method and its explicit projected gradient method.
    max_iterations : int, optional
        The largest number of iterations (default 1000 for the default method, 200 for the
        paper's); ``0`` returns the input positions.
    energy_decrease_threshold : float, optional
        Stop when the relative energy decrease per iteration falls below this (averaged over 50
        iterations for the default method; default 1.25e-4, and 1e-3 for the paper's methods);
        ``0`` runs all `max_iterations`. The default method also waits until the extrapolated
        decrease still to come is at most 1 % of the energy and, along the normals, until what
        the surface has left to move across itself is at most 0.5 % of `epsilon` (RMS).
    sliver_barrier_weight : float, optional
        The weight of the barrier against slivers (default 1, per triangle); ``0`` minimizes the
        paper's energy alone, which leaves needle-shaped triangles.
    tangential_motion : bool, optional
        Whether the vertices may also slide along the surface. By default they do not with the
        default method, the ball bound and the fairest objective: each moves along the normal of
        the smoothed start,
        which keeps the surface nearer the true one and converges in far fewer iterations on
        large meshes; with the box bound (voxel cells), the accurate objective and the paper's
        methods they slide.
    feature_angle : float, optional
        Keep creases sharp: the edges across which the bilaterally filtered face normals are more
        than this many degrees apart (strictly between 0 and 180) are detected as creases; the
        energy has no hinge across them, and the curves they form are faired as curves within the
        same bound. Unset, only `feature_edges` are creases. ``report.feature_edges`` lists the
        creases used.
    initial_smoothing_steps : int, optional
        Steps of bounded Taubin smoothing that make the starting point (default 16 for the
        default method, 0 for the paper's methods).
    conjugate_gradient_iterations : int, optional
        Conjugate gradient iterations per Newton step (``"active_set_newton"`` only, default 1).
    progress : None, True or callable, optional
        ``progress(iteration, energy)`` is called after each iteration, with the iteration's
        number (from 1) and the objective reached; returning ``False`` stops the run, and the
        result is that iterate (status ``CANCELLED``). An exception it raises stops the run and
        is raised. ``True`` shows a progress bar (tqdm, when installed; a line on stderr
        otherwise): the iterations, the energy, and the energy's relative decrease per
        iteration that the stopping rule measures, beside its threshold.

    Returns
    -------
    new_vertices : numpy.ndarray
        ``(n, 3)`` float64, a new array: the faired positions.
    report : Report
        What was done: status, iterations, energies before and after, the largest deviation,
        the vertices at their bound, the folds, and each vertex's ``deviation`` and ``at_bound``.

    Raises
    ------
    InputError
        (a ValueError) The input was rejected: ``error.defect`` names the kind (`Defect`) and
        the message the first vertex or face concerned. Wrong shapes or dtypes, face indices out
        of range, non-manifold or inconsistently oriented meshes, NaN or infinite coordinates,
        ``epsilon <= 0``, bad weights, tolerances or boxes.
    RuntimeError
        The sparse linear solver failed (``method="active_set_newton"`` only).
    KeyboardInterrupt
        Ctrl-C during the run, which stops within a fraction of a second.

    Notes
    -----
    The GIL is released during the computation, so calls from several threads run at once; the
    library's loops also run in parallel with TBB (`set_max_threads` limits them), with results
    bit-identical for any number of threads.

    Examples
    --------
    >>> import numpy as np
    >>> import cgal_constrained_fairing as cf
    >>> V, F = cf.read_mesh("scan.ply")                                # doctest: +SKIP
    >>> eps = 0.25 * cf.mean_edge_length(V, F)                        # doctest: +SKIP
    >>> W, report = cf.fair(V, F, eps)                                # doctest: +SKIP
    >>> bool((np.linalg.norm(W - V, axis=1) <= eps).all())            # doctest: +SKIP
    True
    """
    V = vertices_array(vertices)
    n = V.shape[0]
    F = faces_array(faces, n)
    options = call_options(epsilon, bound=bound, method=method, objective=objective,
                           fidelity_weight=fidelity_weight,
                           sliver_barrier_weight=sliver_barrier_weight,
                           tangential_motion=tangential_motion,
                           feature_angle=feature_angle,
                           energy_decrease_threshold=energy_decrease_threshold,
                           max_iterations=max_iterations,
                           initial_smoothing_steps=initial_smoothing_steps,
                           conjugate_gradient_iterations=conjugate_gradient_iterations)

    tolerance, fixed, box_half_extents, box_centers = bound_arrays(n, tolerance, fixed, box_half_extents,
                                                                   box_centers)
    if region is not None:
        region = _region_indices(region, F.shape[0])
    if feature_edges is not None:
        feature_edges = _edge_pairs(feature_edges, F, n)

    with _Progress(progress, options) as callback:
        outcome = _core.fair(V, F, options, tolerance, fixed, box_half_extents, box_centers,
                             region, feature_edges, callback)
    return result_of(outcome)


def _threshold_argument(value):
    threshold = number_argument(value, "energy_decrease_threshold")
    if not threshold >= 0:
        raise invalid(f"energy_decrease_threshold must be non-negative (got {threshold})")
    return threshold


# How each named setting of the library (``_core.named_settings()``, the table of
# ``Fairing_settings.h``) is read from its keyword; test_defaults.py checks that the two agree.
SETTING_ARGUMENTS = {
    "max_iterations": lambda v: count_argument(v, "max_iterations", _UINT_MAX),
    "energy_decrease_threshold": _threshold_argument,
    "initial_smoothing_steps": lambda v: count_argument(v, "initial_smoothing_steps"),
    "conjugate_gradient_iterations": lambda v: count_argument(v, "conjugate_gradient_iterations"),
    "objective": lambda v: getattr(_core.Objective, choice_argument(
        v, "objective", ("fairest", "accurate")).upper()),
    "fidelity_weight": lambda v: number_argument(v, "fidelity_weight",
                                                 Defect.INVALID_FIDELITY_WEIGHT),
    "sliver_barrier_weight": lambda v: number_argument(v, "sliver_barrier_weight",
                                                       Defect.INVALID_SLIVER_BARRIER_WEIGHT),
    "tangential_motion": lambda v: flag_argument(v, "tangential_motion"),
    "feature_angle": lambda v: number_argument(v, "feature_angle", Defect.INVALID_FEATURE_ANGLE),
}


def call_options(epsilon, bound=None, method=None, **settings):
    """The options of a call as `fair` takes them, checked, in the compiled module's form: the
    named `settings` that are not None are set, the others keep the library's defaults."""
    options = _core.Options()
    options.epsilon = number_argument(epsilon, "epsilon", Defect.INVALID_EPSILON)
    options.bound = "" if bound is None else choice_argument(bound, "bound", ("ball", "box"))
    if method is not None:
        options.method = getattr(_core.Method, choice_argument(method, "method", _METHODS).upper())
    options.given = {name: SETTING_ARGUMENTS[name](value)
                     for name, value in settings.items() if value is not None}
    _warn_without_effect(options.given, options.method)
    return options


def _warn_without_effect(given, method) -> None:
    """A warning for each keyword that the call takes but that changes nothing in it."""
    accurate = given.get("objective") == _core.Objective.ACCURATE
    if "fidelity_weight" in given and not accurate:
        warnings.warn("fidelity_weight has no effect without objective='accurate'", UserWarning,
                      stacklevel=4)
    if "conjugate_gradient_iterations" in given and method != _core.Method.ACTIVE_SET_NEWTON:
        warnings.warn("conjugate_gradient_iterations has no effect without "
                      "method='active_set_newton'", UserWarning, stacklevel=4)


def result_of(outcome):
    """The new vertices and the `Report` of a call of the compiled module; raises on failure."""
    status = outcome["status"].name
    if status == "INVALID_INPUT":
        raise InputError(outcome["defect"].name, outcome["message"])
    if status == "LINEAR_SOLVER_FAILED":
        raise RuntimeError(outcome["message"])
    fields = {name: outcome[name] for name in Report.__dataclass_fields__}
    fields["status"] = Status(status)
    fields["defect"] = Defect.NONE
    return outcome["vertices"], Report(**fields)


def _edge_pairs(value, F, n):
    """``(k, 2)`` int64 vertex pairs, each an edge of the triangles `F` on `n` vertices."""
    A = _as_array(value, "feature_edges")
    if A.size == 0:
        return np.zeros((0, 2), dtype=np.int64)
    if A.ndim != 2 or A.shape[1] != 2 or A.dtype.kind not in "iu":
        raise invalid(f"feature_edges must be a (k, 2) array of vertex indices "
                      f"(got shape {A.shape}, dtype {A.dtype})")
    bad = (A < 0) | (A >= n)
    if bad.any():
        raise invalid(f"feature_edges holds vertex index {A[bad][0]}, but there are {n} vertices")
    sides = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    pairs = np.sort(A.astype(np.int64), axis=1)
    known = np.isin(pairs[:, 0] * n + pairs[:, 1], sides[:, 0] * n + sides[:, 1])
    if not known.all():
        k = int(np.flatnonzero(~known)[0])
        raise invalid(f"feature_edges[{k}] = ({A[k, 0]}, {A[k, 1]}) is not an edge of the mesh")
    return np.ascontiguousarray(A, dtype=np.int64)


def _region_indices(region, m):
    A = np.asarray(region)
    if A.dtype.kind == "b":
        return np.flatnonzero(selection_array(A, "region", m, "face")).astype(np.int64)
    return indices_array(A, "region", m, "face")


class _Decrease:
    """What the stopping rule measures, as the iterations come: the relative energy decrease per
    iteration averaged over its window (``Stopping_rule.h``), against the threshold below which
    the rule may stop the run."""

    def __init__(self, options):
        defaults = _core.default_settings(options.method)
        self.window = defaults["energy_decrease_window"]
        self.threshold = options.given.get("energy_decrease_threshold",
                                           defaults["energy_decrease_threshold"])
        self._energies = collections.deque(maxlen=self.window + 1)

    def push(self, energy):
        self._energies.append(energy)

    def text(self):
        """``"decrease 3.1e-04/it (threshold 0.000125)"`` once a window is full, else ``""``."""
        if len(self._energies) <= self.window or not self._energies[0] > 0:
            return ""
        rate = (self._energies[0] - self._energies[-1]) / (self.window * self._energies[0])
        return f"decrease {rate:.2g}/it (threshold {self.threshold:.3g})"


class _Progress:
    """The callback that `fair` hands to the library for its `progress` argument. The bar
    counts iterations with no total while the stopping rule has not stopped them (how many
    remain is not known), shows what the rule measures against its threshold (`_Decrease`), says
    so before the first (the input's check and the smoothed start), and ends at 100 % at the
    iteration where the call stopped."""

    def __init__(self, progress, options):
        self._progress = progress
        self._bar = None
        self._shown = 0.0
        self._decrease = _Decrease(options)

    def __enter__(self):
        if self._progress is None or self._progress is False:
            return None
        if callable(self._progress):
            return self._progress
        if self._progress is not True:
            raise invalid(f"progress must be None, True or a callable (got {self._progress!r})")
        try:
            from tqdm import tqdm
        except ImportError:
            self._write("fairing: checking the input and starting")
            return self._line
        self._bar = tqdm(total=None, desc="fairing (checking, starting)", unit="it")
        return self._tick

    def __exit__(self, kind, *exc):
        if self._bar is not None:
            if kind is None:
                self._bar.total = self._bar.n
                self._bar.set_description("fairing", refresh=False)
                self._bar.refresh()
            self._bar.close()
        elif self._shown:
            sys.stderr.write("\r\x1b[K")
            sys.stderr.flush()
        return False

    def _status(self, energy):
        self._decrease.push(energy)
        return ", ".join(part for part in (f"energy {energy:.6g}", self._decrease.text()) if part)

    def _tick(self, iteration, energy):
        if self._bar.n == 0:
            self._bar.set_description("fairing", refresh=False)
        self._bar.update(iteration - self._bar.n)
        self._bar.set_postfix_str(self._status(energy), refresh=False)

    def _line(self, iteration, energy):
        status = self._status(energy)
        if time.monotonic() - self._shown >= 0.5:
            self._write(f"fairing: iteration {iteration}, {status}")

    def _write(self, text):
        self._shown = time.monotonic()
        sys.stderr.write(f"\r{text}\x1b[K")
        sys.stderr.flush()


def _measure(measure, vertices, faces):
    V = vertices_array(vertices)
    F = faces_array(faces, V.shape[0])
    value, defect, message = measure(V, F)
    if defect.name != "NONE":
        raise InputError(defect.name, message)
    return value


def mean_edge_length(vertices: ArrayLike, faces: ArrayLike) -> float:
    """The mean edge length ``h`` of a triangle mesh: the unit of relative tolerances.

    The command-line tool's ``--eps 0.25h`` is ``0.25 * mean_edge_length(V, F)``, bit for bit.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
        Vertex positions, any floating-point dtype.
    faces : array_like, shape (m, 3)
        Triangles as vertex indices, any integer dtype; manifold and consistently oriented.

    Returns
    -------
    float
        The mean length of the mesh's edges, each counted once.

    Raises
    ------
    InputError
        As `fair`, for the arrays and the mesh they make.
    """
    return _measure(_core.mean_edge_length, vertices, faces)


def estimate_noise_level(vertices: ArrayLike, faces: Optional[ArrayLike] = None, *,
                         neighbors: int = DEFAULT_NEIGHBORS) -> float:
    """Estimate the noise level of a triangle mesh or a point set, a value for `epsilon`.

    The radius ``r`` of noise uniform in a ball that would give the surface's roughness,
    measured by the deviation of each vertex from a cubic fitted to its neighbours: a mesh
    vertex's two rings (``CGAL::Polygon_mesh_processing::estimate_noise_level()``), or, without
    `faces`, a point's `neighbors` nearest points (``estimate_noise_level_of_points()``, for
    `fair_points`; about ``2.2 sigma`` for Gaussian noise of ``sigma`` up to about the points'
    spacing, and lower for stronger noise). The command-line tool's ``--eps auto``. Meant for
    scans; on fewer than a few hundred vertices it may be 0.

    Parameters
    ----------
    vertices : array_like
        As in `mean_edge_length`, or a point set's ``(n, 3)`` coordinates.
    faces : array_like, optional
        As in `mean_edge_length`; None for a point set.
    neighbors : int
        A point set's neighbours per point, at least 14; ignored for a mesh.

    Returns
    -------
    float
        The estimated noise radius, in the units of `vertices`.

    Raises
    ------
    InputError
        As `mean_edge_length`; for a point set, ``NON_FINITE_COORDINATE`` and
        ``INVALID_NUMBER_OF_NEIGHBORS``.
    """
    if faces is not None:
        return _measure(_core.estimate_noise_level, vertices, faces)
    P = vertices_array(vertices)
    neighbors = count_argument(neighbors, "neighbors")
    if neighbors < NOISE_FIT_NEIGHBORS:
        raise InputError(Defect.INVALID_NUMBER_OF_NEIGHBORS,
                         f"the noise estimate needs at least {NOISE_FIT_NEIGHBORS} neighbours per point "
                         f"(got {neighbors})")
    if not np.isfinite(P).all():
        row = int(np.flatnonzero(~np.isfinite(P).all(axis=1))[0])
        raise InputError(Defect.NON_FINITE_COORDINATE, f"point {row} has a NaN or infinite coordinate")
    return _core.estimate_noise_level_of_points(P, neighbors)


def set_max_threads(threads: int) -> None:
    """Limit the threads of the library's parallel loops (TBB) in this process.

    Parameters
    ----------
    threads : int
        The largest number of threads; ``0`` lifts the limit (all cores). Results are
        bit-identical for any number of threads.
    """
    _core.set_max_threads(count_argument(threads, "threads"))


def max_threads() -> int:
    """The largest number of threads the library's parallel loops use (1 without TBB)."""
    return _core.max_threads()
