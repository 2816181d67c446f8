"""What a user reads: signatures, reprs, warnings for keywords without effect, and messages."""

import inspect
import warnings

import numpy as np
import pytest

import cgal_constrained_fairing as cf


def test_signatures_name_array_like_not_its_expansion():
    for function in (cf.fair, cf.label_surfaces, cf.fair_interfaces, cf.write_mesh):
        text = str(inspect.signature(function))
        assert "ArrayLike" in text or function is cf.write_mesh
        assert "_SupportsArray" not in text and "Union[" not in text, text[:200]
        assert len(text) < 1500


def test_label_surfaces_repr_is_short():
    labels = np.zeros((12, 12, 12), np.uint8)
    labels[3:9, 3:9, 3:9] = 1
    labels[3:9, 3:9, 6:9] = 2
    result = cf.label_surfaces(labels)
    text = repr(result)
    assert text.startswith("LabelSurfaces(2 labels [1, 2], ") and "array(" not in text
    assert len(text) < 200
    one = cf.label_surfaces(labels == 1)
    assert repr(one).startswith("LabelSurfaces(1 label [1], ")


def test_keywords_without_effect_warn(sphere):
    V, F = sphere
    eps = 0.1 * cf.mean_edge_length(V, F)
    with pytest.warns(UserWarning, match="fidelity_weight has no effect without objective='accurate'"):
        cf.fair(V, F, eps, fidelity_weight=2.0, max_iterations=2)
    with pytest.warns(UserWarning, match="conjugate_gradient_iterations has no effect"):
        cf.fair(V, F, eps, conjugate_gradient_iterations=5, max_iterations=2)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        cf.fair(V, F, eps, objective="accurate", fidelity_weight=2.0, max_iterations=2)
        cf.fair(V, F, eps, method="active_set_newton", conjugate_gradient_iterations=5,
                max_iterations=2)


def test_an_absent_label_to_mesh_is_named():
    labels = np.zeros((10, 10, 10), np.uint8)
    labels[2:6, 2:6, 2:6] = 1
    labels[5:8, 5:8, 5:8] = 2
    with pytest.raises(cf.InputError, match=r"none of labels_to_mesh \[3\] is in the label map "
                                            r"\(its labels: \[1, 2\]\)"):
        cf.label_surfaces(labels, labels_to_mesh=[3])


def test_numbers_in_messages_read_back(sphere):
    V, F = sphere
    with pytest.raises(cf.InputError, match=r"\(got -1e-09\)"):
        cf.fair(V, F, -1e-9)
    with pytest.raises(cf.InputError, match=r"\(got 0\)"):
        cf.fair(V, F, 0.0)
    with pytest.raises(cf.InputError) as error:
        cf.fair(V, F, 1.0, feature_angle=180.25)
    assert "(180.25)" in error.value.message and "000000" not in error.value.message
