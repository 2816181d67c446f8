"""`fair_points` on numpy arrays: the bound in double, every point kept in its order, the
normals at the result, the isolated points, bad input rejected with the arrays untouched."""

import numpy as np
import pytest

import cgal_constrained_fairing as cf

SIGMA = 0.01
EPS = 3 * SIGMA


def noisy_sphere(n, seed):
    """n points on the unit sphere, Gaussian noise of SIGMA, and the sphere's normals."""
    rng = np.random.default_rng(seed)
    d = rng.normal(size=(n, 3))
    d /= np.linalg.norm(d, axis=1)[:, None]
    return d + SIGMA * rng.normal(size=(n, 3)), d


def rms_to_sphere(P):
    return float(np.sqrt(((np.linalg.norm(P, axis=1) - 1) ** 2).mean()))


@pytest.mark.parametrize("objective", ["fairest", "accurate"])
def test_closer_within_the_bound(objective):
    P, N = noisy_sphere(3000, 1)
    before = (P.copy(), N.copy())
    Q, report = cf.fair_points(P, EPS, N, objective=objective)
    assert Q.shape == P.shape and Q.dtype == np.float64
    assert np.array_equal(P, before[0]) and np.array_equal(N, before[1])
    assert (np.sqrt(((Q - P) ** 2).sum(axis=1)) <= EPS).all()
    assert report.final_energy <= report.initial_energy
    assert rms_to_sphere(Q) < 0.6 * rms_to_sphere(P)
    assert np.allclose(np.linalg.norm(report.normals, axis=1), 1)
    assert ((report.normals * N).sum(axis=1) > 0.9).all()
    assert report.number_of_isolated_points == 0


def test_estimated_normals_and_an_outlier():
    P, _ = noisy_sphere(3000, 2)
    P = np.vstack([P, [0, 0, 5]])
    Q, report = cf.fair_points(P, EPS)
    assert report.normals is None
    assert report.number_of_isolated_points == 1 and np.array_equal(Q[-1], P[-1])
    assert rms_to_sphere(Q[:-1]) < 0.6 * rms_to_sphere(P[:-1])


def test_bad_input_untouched():
    P, N = noisy_sphere(200, 3)
    P[150] = P[20]
    before = P.copy()
    with pytest.raises(cf.InputError) as error:
        cf.fair_points(P, EPS, N)
    assert error.value.defect == cf.Defect.DUPLICATE_POINTS
    assert str(error.value).endswith("points 20 and 150 coincide")
    assert np.array_equal(P, before)
    with pytest.raises(cf.InputError) as error:
        cf.fair_points(P[:32], EPS)
    assert error.value.defect == cf.Defect.TOO_FEW_POINTS
    with pytest.raises(cf.InputError) as error:
        cf.fair_points(P, EPS, N[:10])
    assert "normals" in str(error.value)
    with pytest.raises(cf.InputError) as error:
        cf.fair_points(P, EPS, neighbors=2)
    assert error.value.defect == cf.Defect.INVALID_NUMBER_OF_NEIGHBORS
