"""`fair` and the measures on numpy arrays: the bound, the options, bad input, the callback,
threads, Ctrl-C, and identity with the C++ programs on the same meshes."""

import os
import re
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import cgal_constrained_fairing as cf
from cgal_constrained_fairing import _core
from conftest import BAD_INPUT, DATA, ROOT, icosphere, noisy


@pytest.fixture(scope="module")
def elephant():
    return cf.read_mesh(DATA / "elephant_noisy.off")


def distances(W, V):
    return np.sqrt(((W - V) ** 2).sum(axis=1))


def bending_energy(V, F):
    """The bending energy summed hinge by hinge from its formula, with no regularization.

    Each interior edge ``ab`` between triangles of normals ``N1``, ``N2`` (of length twice
    their areas) adds ``3/4 |ab|^2 |N1/|N1| - N2/|N2||^2 / (|N1| + |N2|)``.
    """
    N = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    length = np.linalg.norm(N, axis=1)
    a = F.ravel()
    b = np.roll(F, -1, axis=1).ravel()
    face = np.repeat(np.arange(len(F)), 3)
    n = len(V)
    order = np.argsort(a * n + b)
    sorted_keys = (a * n + b)[order]
    # each interior edge once, from its halfedge with a < b to the opposite one b -> a
    first = np.flatnonzero(a < b)
    where = np.searchsorted(sorted_keys, b[first] * n + a[first])
    found = (where < len(sorted_keys)) & (sorted_keys[np.minimum(where, len(a) - 1)] == b[first] * n + a[first])
    h, o = first[found], order[where[found]]
    f1, f2 = face[h], face[o]
    d = N[f1] / length[f1, None] - N[f2] / length[f2, None]
    ab2 = ((V[b[h]] - V[a[h]]) ** 2).sum(axis=1)
    return float((0.75 * ab2 * (d ** 2).sum(axis=1) / (length[f1] + length[f2])).sum())


def test_the_bound_holds_exactly_in_double(elephant):
    V, F = elephant
    eps = 0.25 * cf.mean_edge_length(V, F)
    W, report = cf.fair(V, F, eps)
    d2 = ((W - V) ** 2).sum(axis=1)
    assert (d2 <= eps * eps).all() and (np.sqrt(d2) <= eps).all()
    assert report.status in (cf.Status.CONVERGED, cf.Status.ITERATION_LIMIT_REACHED)
    assert report.final_energy < report.initial_energy
    assert report.final_bending_energy < 0.5 * report.initial_bending_energy
    assert np.array_equal(report.deviation, distances(W, V))
    assert report.max_deviation == report.deviation.max()
    assert report.at_bound.dtype == bool and report.at_bound.sum() == report.number_of_vertices_at_bound
    assert W.dtype == np.float64 and W.shape == V.shape and W.flags.c_contiguous
    assert not np.shares_memory(W, V)


def test_the_box_bound_holds_per_coordinate(elephant):
    V, F = elephant
    eps = 0.25 * cf.mean_edge_length(V, F)
    W, _ = cf.fair(V, F, eps, bound="box")
    assert (np.abs(W - V) <= eps).all()
    assert distances(W, V).max() > eps  # a cube lets a vertex go further than the ball


def test_known_minimizer_a_noisy_plane_becomes_flat():
    # A grid in z = 0 with noise in z below epsilon: a flat surface lies within the bound and
    # has zero bending energy, so the minimum is (nearly) flat.
    k = 30
    x, y = np.meshgrid(np.arange(k, dtype=float), np.arange(k, dtype=float))
    rng = np.random.default_rng(3)
    V = np.stack([x.ravel(), y.ravel(), rng.uniform(-0.1, 0.1, k * k)], axis=1)
    i = (np.arange(k - 1)[:, None] * k + np.arange(k - 1)[None, :]).ravel()
    F = np.concatenate([np.stack([i, i + 1, i + k + 1], 1), np.stack([i, i + k + 1, i + k], 1)])
    W, report = cf.fair(V, F, 0.5, max_iterations=2000)
    assert report.final_bending_energy < 1e-3 * report.initial_bending_energy
    assert np.abs(W[:, 2] - W[:, 2].mean()).max() < 0.1


def test_the_bending_energies_are_the_meshes(elephant):
    V, F = elephant
    W, report = cf.fair(V, F, 0.25 * cf.mean_edge_length(V, F), objective="accurate")
    assert report.number_of_degenerate_edges == 0  # else the plain sums would differ
    assert report.initial_bending_energy == pytest.approx(bending_energy(V, F), rel=1e-9)
    assert report.final_bending_energy == pytest.approx(bending_energy(W, F), rel=1e-9)
    # the accurate objective adds a positive fidelity term to the bending energy
    assert report.initial_energy > report.initial_bending_energy
    assert report.final_energy > report.final_bending_energy


def test_input_arrays_are_never_modified_and_read_only_input_works(elephant):
    V, F = elephant
    V = V.copy()
    F = F.copy()
    V.setflags(write=False)
    F.setflags(write=False)
    before = V.copy(), F.copy()
    W, _ = cf.fair(V, F, 0.1 * cf.mean_edge_length(V, F))
    assert np.array_equal(V, before[0]) and np.array_equal(F, before[1])
    assert W.flags.writeable


@pytest.mark.parametrize("vdtype,fdtype", [(np.float32, np.int32), (np.float64, np.uint32),
                                           (np.longdouble, np.int16), (np.float16, np.uint64)])
def test_any_float_and_integer_dtype_gives_the_float64_result(sphere, vdtype, fdtype):
    V, F = sphere
    V = V.astype(vdtype)
    F = F.astype(fdtype) if np.iinfo(fdtype).max >= F.max() else F
    W, _ = cf.fair(V, F, 0.05, max_iterations=20)
    W64, _ = cf.fair(V.astype(np.float64), F.astype(np.int64), 0.05, max_iterations=20)
    assert np.array_equal(W, W64)


def test_lists_are_read_as_arrays():
    V = [[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.1]]
    F = [[0, 1, 2], [1, 3, 2]]
    W, report = cf.fair(V, F, 0.01)
    assert W.shape == (4, 3) and report.max_deviation <= 0.01


def test_per_vertex_tolerance(sphere):
    V, F = sphere
    eps = 0.05
    rng = np.random.default_rng(7)
    t = rng.uniform(0, 2 * eps, len(V))  # above epsilon: capped by it
    t[::10] = 0                          # pinned
    W, report = cf.fair(V, F, eps, tolerance=t)
    d = distances(W, V)
    assert (d <= np.minimum(t, eps)).all()
    assert np.array_equal(W[::10], V[::10])
    assert not report.at_bound[::10].any()


def test_fixed_as_mask_and_as_indices_are_bit_identical(sphere):
    V, F = sphere
    rng = np.random.default_rng(11)
    indices = rng.choice(len(V), 200, replace=False)
    mask = np.zeros(len(V), dtype=bool)
    mask[indices] = True
    W_mask, r_mask = cf.fair(V, F, 0.05, fixed=mask)
    W_indices, r_indices = cf.fair(V, F, 0.05, fixed=indices.astype(np.int32))
    assert np.array_equal(W_mask, W_indices)
    assert np.array_equal(W_mask[mask], V[mask])
    assert r_mask.number_of_fixed_vertices == 200 == r_indices.number_of_fixed_vertices
    assert not r_mask.at_bound[mask].any()


def test_boxes_with_centres(sphere):
    V, F = sphere
    h = np.array([0.02, 0.03, 0.01])
    rng = np.random.default_rng(5)
    C = V + rng.uniform(-0.5, 0.5, V.shape) * h  # each input inside its box
    W, report = cf.fair(V, F, 0.05, box_half_extents=h, box_centers=C)
    assert (np.abs(W - C) <= h).all()
    W_rows, _ = cf.fair(V, F, 0.05, box_half_extents=np.tile(h, (len(V), 1)), box_centers=C)
    assert np.array_equal(W, W_rows)
    assert report.number_of_vertices_at_bound > 0
    with pytest.raises(ValueError) as outside:
        cf.fair(V, F, 0.05, box_half_extents=h, box_centers=V + 2 * h)
    assert outside.value.defect == "OUTSIDE_BOX"
    with pytest.raises(ValueError) as ball:
        cf.fair(V, F, 0.05, bound="ball", box_half_extents=h)
    assert ball.value.defect is cf.Defect.BOX_WITH_BALL


def test_the_box_without_extents_is_the_cube_of_epsilon(sphere):
    V, F = sphere
    W, _ = cf.fair(V, F, 0.05, bound="box", max_iterations=30)
    W_h, _ = cf.fair(V, F, 0.05, box_half_extents=[0.05] * 3, max_iterations=30)
    assert np.array_equal(W, W_h)


def test_region_moves_only_its_inner_vertices(sphere):
    V, F = sphere
    region = np.flatnonzero(V[F].mean(axis=1)[:, 2] > 0)  # the upper half
    W, report = cf.fair(V, F, 0.05, region=region)
    outside = np.ones(len(V), dtype=bool)
    outside[F[region].ravel()] = False
    assert np.array_equal(W[outside], V[outside])
    assert not np.array_equal(W, V)
    mask = np.zeros(len(F), dtype=bool)
    mask[region] = True
    W_mask, _ = cf.fair(V, F, 0.05, region=mask)
    assert np.array_equal(W, W_mask)


def test_the_options_reach_the_library(sphere):
    V, F = sphere
    _, capped = cf.fair(V, F, 0.05, max_iterations=7, energy_decrease_threshold=0)
    assert capped.number_of_iterations == 7 and capped.status == "ITERATION_LIMIT_REACHED"
    _, newton = cf.fair(V, F, 0.05, method="active_set_newton", max_iterations=5,
                        conjugate_gradient_iterations=3)
    assert newton.number_of_cg_iterations > 0
    _, accurate = cf.fair(V, F, 0.05, objective="accurate", fidelity_weight=100)
    _, fairest = cf.fair(V, F, 0.05)
    assert accurate.final_energy > accurate.final_bending_energy
    assert fairest.final_bending_energy < accurate.final_bending_energy
    _, no_barrier = cf.fair(V, F, 0.05, sliver_barrier_weight=0)
    assert no_barrier.final_energy == no_barrier.final_bending_energy
    # A limit of any size costs no memory in proportion to it.
    _, unlimited = cf.fair(V, F, 0.05, max_iterations=4_000_000_000)
    assert unlimited.status == "CONVERGED"
    W0, untouched = cf.fair(V, F, 0.05, max_iterations=0)
    assert np.array_equal(W0, V) and untouched.number_of_iterations == 0
    Ws, _ = cf.fair(V, F, 0.05, initial_smoothing_steps=0, max_iterations=3)
    Wd, _ = cf.fair(V, F, 0.05, max_iterations=3)
    assert not np.array_equal(Ws, Wd)
    # Sliding vertices reach a lower bending energy than the normal offsets of the default.
    _, sliding = cf.fair(V, F, 0.05, tangential_motion=True)
    _, along_normals = cf.fair(V, F, 0.05, tangential_motion=np.bool_(False))
    assert sliding.final_bending_energy < along_normals.final_bending_energy
    assert along_normals.final_bending_energy == fairest.final_bending_energy
    with pytest.raises(ValueError, match="tangential_motion must be True or False"):
        cf.fair(V, F, 0.05, tangential_motion=1)


def test_the_report_has_every_field_of_the_cpp_result(sphere):
    V, F = sphere
    _, report = cf.fair(V, F, 0.05)
    for name in ("status", "message", "defect", "number_of_iterations", "number_of_cg_iterations",
                 "number_of_energy_evaluations", "initial_energy", "final_energy",
                 "initial_bending_energy", "final_bending_energy", "max_deviation", "number_of_vertices_at_bound",
                 "number_of_fixed_vertices", "number_of_folded_faces", "number_of_unfolded_faces",
                 "number_of_degenerate_edges", "deviation", "at_bound"):
        assert hasattr(report, name), name
    assert report.defect is cf.Defect.NONE and report.message == ""
    text = repr(report)
    assert f"{report.number_of_iterations} iterations" in text and "deviation at most" in text


def test_defects_are_those_of_the_library():
    # The C++ enum, in its order, as the module binds it and as Python names it.
    header = (ROOT / "include/CGAL/Polygon_mesh_processing/Constrained_fairing_result.h").read_text()
    body = re.search(r"enum class Constrained_fairing_defect\s*\{(.*?)\};", header, re.S).group(1)
    cpp = re.findall(r"^\s*([A-Z_]+),?\s*$", body, re.M)
    assert cpp[0] == "NONE" and len(cpp) > 10
    assert [name for name, value in sorted(_core.Defect.__members__.items(),
                                          key=lambda item: int(item[1]))] == cpp
    assert [d.name for d in cf.Defect if d.name != "INVALID_ARGUMENT"] == cpp


@pytest.mark.parametrize("vertices,faces,what", [
    (np.zeros((4, 3), dtype=np.int64), [[0, 1, 2]], "floating-point dtype"),
    (np.zeros((4, 3), dtype=complex), [[0, 1, 2]], "floating-point dtype"),
    (np.zeros((4, 2)), [[0, 1, 2]], "(n, 3)"),
    (np.zeros(12), [[0, 1, 2]], "(n, 3)"),
    (np.zeros((4, 3)), np.array([[0, 1, 2]], dtype=float), "integer dtype"),
    (np.zeros((4, 3)), np.array([[True, False, True]]), "integer dtype"),
    (np.zeros((4, 3)), [[0, 1, 2, 3]], "(m, 3)"),
    (np.zeros((4, 3)), [0, 1, 2], "(m, 3)"),
    ([["a", "b", "c"]], [[0, 1, 2]], "cannot be read as an array"),
])
def test_shape_and_dtype_errors(vertices, faces, what):
    with pytest.raises(ValueError, match=what.replace("(", r"\(").replace(")", r"\)")) as error:
        cf.fair(vertices, faces, 0.1)
    assert error.value.defect is cf.Defect.INVALID_ARGUMENT


@pytest.mark.parametrize("options,what", [
    (dict(tolerance=np.ones(5)), "tolerance must have shape"),
    (dict(tolerance=np.array(["x"] * 4)), "tolerance must hold real numbers"),
    (dict(fixed=np.ones(5, dtype=bool)), "fixed as a mask must have shape"),
    (dict(fixed=[7]), "vertex index 7"),
    (dict(fixed=[1, 1]), "more than once"),
    (dict(fixed=np.zeros((2, 2), dtype=int)), "1-d array"),
    (dict(box_half_extents=[1, 2]), "box_half_extents must have shape"),
    (dict(box_centers=np.zeros((3, 3))), "box_centers must have shape"),
    (dict(region=[5]), "face index 5"),
    (dict(bound="cube"), "bound must be one of"),
    (dict(objective="smooth"), "objective must be one of"),
    (dict(method="newton"), "method must be one of"),
    (dict(max_iterations=-1), "max_iterations must be non-negative"),
    (dict(max_iterations=2**32), "max_iterations must be non-negative"),
    (dict(max_iterations=2.5), "max_iterations must be an integer"),
    (dict(energy_decrease_threshold=-1), "energy_decrease_threshold must be non-negative"),
    (dict(energy_decrease_threshold=float("nan")), "energy_decrease_threshold must be non-negative"),
    (dict(progress="yes"), "progress must be None, True or a callable"),
])
def test_option_errors(options, what):
    V = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]])
    F = np.array([[0, 1, 2], [1, 3, 2]])
    with pytest.raises(ValueError, match=what) as error:
        cf.fair(V, F, 0.1, **options)
    assert error.value.defect is cf.Defect.INVALID_ARGUMENT


SQUARE = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]])


@pytest.mark.parametrize("vertices,faces,epsilon,defect,message", [
    (np.zeros((0, 3)), np.zeros((0, 3), dtype=int), 0.1, "EMPTY_MESH", "the mesh is empty"),
    ([], [], 0.1, "EMPTY_MESH", "the mesh is empty"),
    (SQUARE, np.zeros((0, 3), dtype=int), 0.1, "NO_FACES", "the mesh has no faces"),
    (SQUARE, [[0, 1, 4]], 0.1, "INVALID_FACE", "face 0 refers to vertex 4, but there are 4 vertices"),
    (SQUARE, [[0, 1, 2], [1, 3, -1]], 0.1, "INVALID_FACE", "face 1 refers to vertex -1"),
    (SQUARE, np.array([[0, 1, 2], [1, 3, 2**63 + 5]], dtype=np.uint64), 0.1, "INVALID_FACE",
     "face 1 refers to vertex 9223372036854775813"),
    (SQUARE, [[0, 1, 1]], 0.1, "INVALID_FACE", "face 0 refers to vertex 1 twice"),
    (SQUARE, [[0, 1, 2], [0, 1, 3]], 0.1, "INCONSISTENT_ORIENTATION",
     "faces 0 and 1 are oriented inconsistently: both run from vertex 0 to vertex 1"),
    (SQUARE, [[0, 1, 2], [0, 1, 3], [1, 0, 3]], 0.1, "NON_MANIFOLD_EDGE",
     "the edge between vertices 0 and 1 has 3 faces"),
    (np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]]),
     [[0, 1, 2], [0, 3, 4]], 0.1, "NON_MANIFOLD_VERTEX", "vertex 0 is non-manifold"),
    (np.array([[0.0, 0, 0], [1, 0, 0], [0, np.nan, 0], [1, 1, 0]]), [[0, 1, 2], [1, 3, 2]], 0.1,
     "NON_FINITE_COORDINATE", "vertex 2 has a NaN or infinite coordinate"),
    (SQUARE, [[0, 1, 2], [1, 3, 2]], 0, "INVALID_EPSILON", "epsilon must be a positive"),
    (SQUARE, [[0, 1, 2], [1, 3, 2]], -1, "INVALID_EPSILON", "epsilon must be a positive"),
    (SQUARE, [[0, 1, 2], [1, 3, 2]], float("inf"), "INVALID_EPSILON", "epsilon must be a positive"),
    (SQUARE, [[0, 1, 2], [1, 3, 2]], "abc", "INVALID_EPSILON", "epsilon must be a number"),
    (SQUARE * 0, [[0, 1, 2], [1, 3, 2]], 0.1, "NO_AREA", "all triangles of the mesh have zero area"),
])
def test_bad_meshes_raise_with_their_defect_and_leave_the_input_alone(
        vertices, faces, epsilon, defect, message):
    V = np.array(vertices, dtype=float) if not isinstance(vertices, list) else vertices
    before = np.array(V, copy=True)
    with pytest.raises(ValueError, match=message) as error:
        cf.fair(V, faces, epsilon)
    assert isinstance(error.value, cf.InputError)
    assert error.value.defect == defect and error.value.message == str(error.value)
    assert np.array_equal(np.asarray(V), before, equal_nan=True)


@pytest.mark.parametrize("name,defect", [("non_manifold_edge.off", "NON_MANIFOLD_EDGE"),
                                         ("non_manifold_vertex.off", "NON_MANIFOLD_VERTEX"),
                                         ("inconsistent_orientation.off", "INCONSISTENT_ORIENTATION"),
                                         ("zero_area.off", "NO_AREA"),
                                         ("nan.ply", "NON_FINITE_COORDINATE")])
def test_the_bundled_bad_files(name, defect):
    V, F = cf.read_mesh(BAD_INPUT / name)
    with pytest.raises(cf.InputError) as error:
        cf.fair(V, F, 0.1)
    assert error.value.defect == defect


def test_per_vertex_values_are_checked_by_the_library(sphere):
    V, F = sphere
    t = np.full(len(V), 0.01)
    t[17] = np.nan
    with pytest.raises(ValueError, match="vertex 17 has a negative, NaN or infinite tolerance") as e:
        cf.fair(V, F, 0.05, tolerance=t)
    assert e.value.defect == "INVALID_TOLERANCE"
    with pytest.raises(ValueError) as e:
        cf.fair(V, F, 0.05, box_half_extents=[0.01, -1, 0.01])
    assert e.value.defect == "INVALID_BOX_EXTENTS"
    with pytest.raises(ValueError) as e:
        cf.fair(V, F, 0.05, objective="accurate", fidelity_weight=-1)
    assert e.value.defect == "INVALID_FIDELITY_WEIGHT"
    with pytest.raises(ValueError) as e:
        cf.fair(V, F, 0.05, sliver_barrier_weight=float("nan"))
    assert e.value.defect == "INVALID_SLIVER_BARRIER_WEIGHT"


def test_measures(elephant):
    V, F = elephant
    edges = np.unique(np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1),
                      axis=0)
    h = np.linalg.norm(V[edges[:, 0]] - V[edges[:, 1]], axis=1).mean()
    assert cf.mean_edge_length(V, F) == pytest.approx(h, rel=1e-12)
    level = cf.estimate_noise_level(V, F)
    assert 0 < level < h
    with pytest.raises(ValueError) as error:
        cf.mean_edge_length(V, F[:, ::-1][:1].repeat(2, axis=0))
    assert error.value.defect == "INCONSISTENT_ORIENTATION"
    with pytest.raises(ValueError) as error:
        cf.estimate_noise_level(np.zeros((0, 3)), [])
    assert error.value.defect == "EMPTY_MESH"


def test_progress_is_called_each_iteration_and_false_cancels(sphere):
    V, F = sphere
    seen = []

    def progress(iteration, energy):
        seen.append((iteration, energy))
        return False if iteration == 5 else None

    W, report = cf.fair(V, F, 0.05, progress=progress)
    assert report.status is cf.Status.CANCELLED
    assert [i for i, _ in seen] == [1, 2, 3, 4, 5]
    assert report.number_of_iterations == 5 and report.final_energy == seen[-1][1]
    assert distances(W, V).max() <= 0.05
    _, full = cf.fair(V, F, 0.05, progress=lambda i, e: True)
    assert full.number_of_iterations > 5


def test_an_exception_in_progress_stops_the_run_and_is_raised(sphere):
    V, F = sphere

    def progress(iteration, energy):
        if iteration == 3:
            raise ZeroDivisionError("from the callback")

    with pytest.raises(ZeroDivisionError, match="from the callback"):
        cf.fair(V, F, 0.05, progress=progress)


def test_progress_true_shows_a_bar(sphere, capsys):
    V, F = sphere
    W, report = cf.fair(V, F, 0.05, progress=True)
    W0, _ = cf.fair(V, F, 0.05)
    assert np.array_equal(W, W0)
    shown = capsys.readouterr().err
    assert "fairing" in shown
    pytest.importorskip("tqdm")
    # It ends at 100 %, at the iteration where the stopping rule stopped the call.
    last = shown.replace("\r", "\n").strip().splitlines()[-1]
    assert "100%" in last and f"{report.number_of_iterations}/{report.number_of_iterations}" in last
    # and with what the stopping rule measured last, against its threshold
    assert report.number_of_iterations > 50 and "(threshold 0.000125)" in last


def test_progress_shows_the_stopping_rules_measure():
    from cgal_constrained_fairing._fairing import _Decrease, call_options
    decrease = _Decrease(call_options(1.0, energy_decrease_threshold=1e-3))
    assert decrease.window == 50 and decrease.threshold == 1e-3
    for k in range(50):
        decrease.push(0.99 ** k)
        assert decrease.text() == ""  # not a whole window yet
    decrease.push(0.99 ** 50)
    # the window's relative decrease per iteration, (E[-51] - E[-1]) / (50 E[-51])
    assert decrease.text() == f"decrease {(1 - 0.99 ** 50) / 50:.2g}/it (threshold 0.001)"


def test_calls_from_two_threads_at_once(sphere, elephant):
    cases = [(sphere[0], sphere[1], 0.05), (elephant[0], elephant[1], 0.005)]
    expected = [cf.fair(*case)[0] for case in cases]
    results = [None, None]
    barrier = threading.Barrier(2)

    def run(k):
        barrier.wait()
        results[k] = cf.fair(*cases[k])[0]

    threads = [threading.Thread(target=run, args=(k,)) for k in range(2)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(timeout=120)
    assert all(np.array_equal(r, e) for r, e in zip(results, expected))


def test_files_read_from_four_threads_at_once(tmp_path):
    # What a Dask worker with several threads does: every read, bad files included, gives what
    # it gives alone (the readers touch no process-wide stream while the GIL is released).
    (tmp_path / "notes.off").write_text("shopping list\n- milk\n")
    (tmp_path / "truncated.ply").write_bytes((BAD_INPUT / "nan.ply").read_bytes()[:120])
    (tmp_path / "mesh.unknown").write_text("OFF\n0 0 0\n")
    paths = sorted(str(p) for p in BAD_INPUT.iterdir()) + [str(DATA / "head.off")] + \
        [str(tmp_path / name) for name in ("notes.off", "truncated.ply", "mesh.unknown", "no.off")]

    def outcome(path):
        try:
            V, F = cf.read_mesh(path)
            return ("read", V.shape, F.shape)
        except (ValueError, OSError) as error:
            return (type(error).__name__, str(error))

    alone = [outcome(path) for path in paths]
    assert any(o[0] == "ValueError" for o in alone) and any(o[0] == "read" for o in alone)
    results = [[] for _ in range(4)]
    barrier = threading.Barrier(4)

    def run(k):
        barrier.wait()
        for _ in range(25):
            results[k].append([outcome(path) for path in paths])

    threads = [threading.Thread(target=run, args=(k,)) for k in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(timeout=300)
    assert all(rounds == [alone] * 25 for rounds in results)


def test_the_gil_is_released_while_it_computes():
    # While a call runs in another thread, this thread's Python code runs at once: with the
    # GIL held, it would wait for the call's next check of Ctrl-C, a fifth of a second away.
    V, F = icosphere(6)
    V = noisy(V, F, 0.3)
    thread = threading.Thread(target=cf.fair, args=(V, F, 0.004),
                              kwargs=dict(max_iterations=200, energy_decrease_threshold=0))
    thread.start()
    time.sleep(0.3)  # into the iterations
    waits = []
    while thread.is_alive() and len(waits) < 20:
        start = time.perf_counter()
        time.sleep(0.01)  # gives the GIL up, and takes it back to return
        waits.append(time.perf_counter() - start - 0.01)
    thread.join()
    assert len(waits) >= 5, "the call ended before it could be observed"
    assert sorted(waits)[len(waits) // 2] < 0.05


def test_results_do_not_depend_on_the_number_of_threads(sphere):
    V, F = sphere
    W, _ = cf.fair(V, F, 0.05)
    cf.set_max_threads(1)
    try:
        assert cf.max_threads() == 1 or not _core.with_tbb
        W1, _ = cf.fair(V, F, 0.05)
    finally:
        cf.set_max_threads(0)
    assert np.array_equal(W, W1)


def test_ctrl_c_stops_a_running_call_within_a_second(tmp_path):
    # A child process fairs a large sphere with no callback; SIGINT must end it with
    # KeyboardInterrupt well before the call would have finished.
    script = textwrap.dedent("""
        import sys, time
        sys.path.insert(0, sys.argv[1])
        from conftest import icosphere, noisy
        import cgal_constrained_fairing as cf
        V, F = icosphere(7)
        V = noisy(V, F, 0.3)
        print("start", flush=True)
        try:
            cf.fair(V, F, 0.002, max_iterations=100000, energy_decrease_threshold=0)
        except KeyboardInterrupt:
            print("interrupted", flush=True)
            sys.exit(3)
    """)
    child = subprocess.Popen([sys.executable, "-c", script, os.path.dirname(__file__)],
                             stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "start"
    time.sleep(2.0)  # past the set-up, into the iterations
    assert child.poll() is None
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=30)
    waited = time.monotonic() - sent
    assert child.returncode == 3 and "interrupted" in out
    assert waited < 1.0, f"stopped {waited:.2f} s after Ctrl-C"


def cpp_program(variable):
    path = os.environ.get(variable)
    if not path or not os.path.exists(path):
        pytest.skip(f"{variable} is not set to a built program")
    return path


@pytest.mark.parametrize("name,options", [("head.off", []), ("elephant_noisy.off", ["--accurate"]),
                                          ("elephant_noisy.off", ["--box"]),
                                          ("head.off", ["--tangential-motion"]),
                                          ("head.off", ["--feature-angle", "30"])])
def test_identical_to_the_command_line_tool(tmp_path, name, options):
    tool = cpp_program("CONSTRAINED_FAIRING_TOOL")
    out = tmp_path / "faired.off"
    subprocess.run([tool, "--eps", "0.25h", *options, str(DATA / name), str(out)], check=True,
                   stdout=subprocess.DEVNULL)
    V, F = cf.read_mesh(DATA / name)
    W, _ = cf.fair(V, F, 0.25 * cf.mean_edge_length(V, F),
                   objective="accurate" if "--accurate" in options else "fairest",
                   bound="box" if "--box" in options else None,
                   tangential_motion=True if "--tangential-motion" in options else None,
                   feature_angle=30 if "--feature-angle" in options else None)
    W_tool, F_tool = cf.read_mesh(out)
    assert np.array_equal(F_tool, F)
    assert np.array_equal(W_tool, W)


def test_creases_detected_and_given_are_the_same_call(elephant):
    V, F = elephant
    eps = 0.25 * cf.mean_edge_length(V, F)
    W, report = cf.fair(V, F, eps, feature_angle=30)
    E = report.feature_edges
    assert E.dtype == np.int64 and E.shape == (report.number_of_feature_edges, 2) and len(E) > 0
    assert (E[:, 0] < E[:, 1]).all() and (np.diff(E[:, 0] * len(V) + E[:, 1]) > 0).all()
    # the creases found, given back, are the same call, bit for bit
    W_given, given = cf.fair(V, F, eps, feature_edges=E[:, ::-1])
    assert np.array_equal(W_given, W) and np.array_equal(given.feature_edges, E)
    _, plain = cf.fair(V, F, eps)
    assert plain.number_of_feature_edges == 0 and plain.feature_edges.shape == (0, 2)


@pytest.mark.parametrize("feature_edges,what", [
    ([[0, 3]], r"feature_edges\[0\] = \(0, 3\) is not an edge of the mesh"),
    ([[0, 1], [0, 9]], "feature_edges holds vertex index 9, but there are 4 vertices"),
    ([0, 1], r"feature_edges must be a \(k, 2\) array of vertex indices"),
    ([[0.0, 1.0]], r"feature_edges must be a \(k, 2\) array of vertex indices"),
])
def test_feature_edge_errors(feature_edges, what):
    F = np.array([[0, 1, 2], [1, 3, 2]])
    before = SQUARE.copy()
    with pytest.raises(ValueError, match=what) as error:
        cf.fair(SQUARE, F, 0.1, feature_edges=feature_edges)
    assert error.value.defect is cf.Defect.INVALID_ARGUMENT
    assert np.array_equal(SQUARE, before)


@pytest.mark.parametrize("angle", [0, 180, -5, float("nan")])
def test_feature_angle_out_of_range(angle):
    with pytest.raises(ValueError, match="feature_angle must be a number of degrees") as error:
        cf.fair(SQUARE, [[0, 1, 2], [1, 3, 2]], 0.1, feature_angle=angle)
    assert error.value.defect is cf.Defect.INVALID_FEATURE_ANGLE


def test_identical_to_the_default_cpp_call(tmp_path):
    # The example calls constrained_fairing(mesh, eps) with no named parameter.
    example = cpp_program("CONSTRAINED_FAIRING_EXAMPLE")
    V, F = cf.read_mesh(DATA / "elephant_noisy.off")
    eps = 0.3 * cf.mean_edge_length(V, F)
    subprocess.run([example, str(DATA / "elephant_noisy.off"), repr(eps)], check=True, cwd=tmp_path,
                   stdout=subprocess.DEVNULL)
    W, _ = cf.fair(V, F, eps)
    assert np.array_equal(cf.read_mesh(tmp_path / "faired.off")[0], W)


def test_read_and_write_keep_every_bit(tmp_path, elephant):
    V, F = elephant
    W = V + np.random.default_rng(2).normal(0, 1e-3, V.shape)
    for ext in (".off", ".obj", ".ply"):
        cf.write_mesh(tmp_path / f"m{ext}", W, F)
        W2, F2 = cf.read_mesh(tmp_path / f"m{ext}")
        assert np.array_equal(W2, W) and np.array_equal(F2, F), ext
    with pytest.raises(FileNotFoundError):
        cf.read_mesh(tmp_path / "missing.off")
    (tmp_path / "garbage.off").write_text("not a mesh\n")
    with pytest.raises(ValueError, match="cannot read"):
        cf.read_mesh(tmp_path / "garbage.off")
    with pytest.raises(ValueError, match="extension"):
        cf.write_mesh(tmp_path / "m.txt", W, F)


def test_quads_are_triangulated_on_reading():
    V, F = cf.read_mesh(BAD_INPUT / "quad.off")
    assert F.shape == (3, 3)  # the quad's two triangles and the triangle


def test_help_is_a_page_to_work_from():
    doc = cf.fair.__doc__
    for section in ("Parameters", "Returns", "Raises", "Examples", "epsilon", "tolerance", "fixed",
                    "box_half_extents", "box_centers", "progress", "KeyboardInterrupt"):
        assert section in doc, section
    for function in (cf.mean_edge_length, cf.estimate_noise_level, cf.read_mesh, cf.write_mesh):
        assert "Parameters" in function.__doc__ and "Raises" in function.__doc__, function
    for function in (cf.mean_edge_length, cf.estimate_noise_level, cf.read_mesh):
        assert "Returns" in function.__doc__, function
