"""`fair_points` on numpy arrays: the bound in double, every point kept in its order, the
normals at the result, the isolated points, bad input rejected with the arrays untouched."""

import os
import subprocess

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


TOOL = os.environ.get("CONSTRAINED_FAIRING_TOOL")
needs_tool = pytest.mark.skipif(TOOL is None, reason="CONSTRAINED_FAIRING_TOOL names no built tool")


def run_tool(*arguments):
    return subprocess.run([TOOL, *map(str, arguments)], capture_output=True, text=True, timeout=300)


@needs_tool
def test_tool_gives_python_result(tmp_path):
    """An .xyz file through the tool: Python's points, bit for bit, in their order."""
    P, _ = noisy_sphere(2000, 4)
    np.savetxt(tmp_path / "scan.xyz", P, fmt="%.17g")
    done = run_tool("--eps", EPS, tmp_path / "scan.xyz", tmp_path / "out.xyz")
    assert done.returncode == 0, done.stderr
    Q, _ = cf.fair_points(P, EPS)
    assert np.array_equal(np.loadtxt(tmp_path / "out.xyz"), Q)


@needs_tool
def test_tool_carries_ply_properties(tmp_path):
    """A PLY point set's properties come out in their order and count, its normals faired."""
    P, N = noisy_sphere(2000, 5)
    confidence = np.linspace(0, 1, len(P))
    with open(tmp_path / "scan.ply", "w") as f:
        f.write("ply\nformat ascii 1.0\ncomment scanner 7\nelement vertex %d\n" % len(P)
                + "".join(f"property double {c}\n" for c in ("x", "y", "z", "nx", "ny", "nz"))
                + "property uchar red\nproperty double confidence\nend_header\n")
        for p, n, c in zip(P, N, confidence):
            f.write("%.17g %.17g %.17g %.17g %.17g %.17g 7 %.17g\n" % (*p, *n, c))
    done = run_tool("--eps", EPS, tmp_path / "scan.ply", tmp_path / "out.ply")
    assert done.returncode == 0, done.stderr
    Q, report = cf.fair_points(P, EPS, N)
    text = (tmp_path / "out.ply").read_bytes()
    assert b"comment scanner 7" in text and b"property uchar red" in text
    header, body = text.split(b"end_header\n", 1)
    names = [line.split()[-1].decode() for line in header.splitlines() if line.startswith(b"property")]
    assert names[:10] == ["x", "y", "z", "nx", "ny", "nz", "red", "confidence", "deviation", "at_bound"]
    record = np.dtype([(c, "<f8") for c in ("x", "y", "z", "nx", "ny", "nz")]
                      + [("red", "u1"), ("confidence", "<f8"), ("deviation", "<f8"), ("at_bound", "u1")])
    out = np.frombuffer(body[:record.itemsize * len(P)], dtype=record)
    assert np.array_equal(np.column_stack([out["x"], out["y"], out["z"]]), Q)
    assert np.array_equal(np.column_stack([out["nx"], out["ny"], out["nz"]]), report.normals)
    assert (out["red"] == 7).all() and np.array_equal(out["confidence"], confidence)
    assert np.array_equal(out["deviation"], report.deviation)


@needs_tool
def test_tool_refuses_relative_eps(tmp_path):
    P, _ = noisy_sphere(200, 6)
    np.savetxt(tmp_path / "scan.xyz", P, fmt="%.17g")
    done = run_tool("--eps", "0.25h", tmp_path / "scan.xyz", tmp_path / "out.xyz")
    assert done.returncode == 1 and "needs --eps as a distance" in done.stderr
    assert not (tmp_path / "out.xyz").exists()


def test_noise_estimate_of_points():
    P, _ = noisy_sphere(3000, 7)
    before = P.copy()
    estimate = cf.estimate_noise_level(P)
    assert np.array_equal(P, before)
    # Gaussian noise well under the points' spacing: about 2.2 sigma (the C++ documentation).
    assert 1.9 * SIGMA < estimate < 2.6 * SIGMA
    assert cf.estimate_noise_level(P[::-1]) == pytest.approx(estimate, rel=1e-12)
    assert cf.estimate_noise_level(P, neighbors=64) > 0
    with pytest.raises(cf.InputError) as error:
        cf.estimate_noise_level(P, neighbors=10)
    assert error.value.defect == cf.Defect.INVALID_NUMBER_OF_NEIGHBORS
    P[5, 1] = np.nan
    with pytest.raises(cf.InputError) as error:
        cf.estimate_noise_level(P)
    assert error.value.defect == cf.Defect.NON_FINITE_COORDINATE
    assert "point 5" in str(error.value)


@needs_tool
def test_tool_eps_auto_is_the_estimate(tmp_path):
    P, _ = noisy_sphere(2000, 8)
    np.savetxt(tmp_path / "scan.xyz", P, fmt="%.17g")
    done = run_tool("--eps", "auto", tmp_path / "scan.xyz", tmp_path / "out.xyz")
    assert done.returncode == 0, done.stderr
    assert "eps: auto" in done.stdout
    Q, report = cf.fair_points(P, cf.estimate_noise_level(P))
    assert np.array_equal(np.loadtxt(tmp_path / "out.xyz"), Q)


def test_point_set_files_round_trip(tmp_path):
    """read_points and write_points: each format's points and normals, and a PLY's properties
    and comments, come back as written; a mesh file is not a point set."""
    P, N = noisy_sphere(300, 9)
    properties = cf.MeshProperties(vertex={"red": (np.arange(300) % 256).astype(np.uint8),
                                           "confidence": np.linspace(0, 1, 300)},
                                   comments="scanner 7\n")
    for name, normals in (("a.xyz", None), ("a.pwn", N), ("a.off", None), ("a.ply", N)):
        cf.write_points(tmp_path / name, P, normals,
                        properties=properties if name.endswith(".ply") else None)
        assert cf.is_point_set_file(tmp_path / name)
        Q, M, carried = cf.read_points(tmp_path / name, properties=True)
        assert np.array_equal(Q, P)
        assert (M is None) == (normals is None) and (M is None or np.array_equal(M, N))
        if name.endswith(".ply"):
            assert list(carried.vertex)[-2:] == ["red", "confidence"]
            assert np.array_equal(carried.vertex["red"], properties.vertex["red"])
            assert carried.comments == "scanner 7\n"
    V = np.array([[0., 0, 0], [1, 0, 0], [0, 1, 0]])
    cf.write_mesh(tmp_path / "mesh.off", V, [[0, 1, 2]])
    assert not cf.is_point_set_file(tmp_path / "mesh.off")
    with pytest.raises(ValueError, match="needs|normals"):
        cf.write_points(tmp_path / "b.pwn", P)
    with pytest.raises(ValueError, match="extension"):
        cf.write_points(tmp_path / "b.stl", P)
