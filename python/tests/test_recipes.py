"""The recipes of python/examples: with meshio, and with Open3D or, where Open3D is not
installed, a stand-in for the part of its API that the recipe uses."""

import runpy
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import cgal_constrained_fairing as cf
from conftest import DATA

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def recipe(name):
    return runpy.run_path(str(EXAMPLES / name))


def test_meshio_recipe_fairs_within_the_bound_and_keeps_the_rest(tmp_path):
    meshio = pytest.importorskip("meshio")
    source = meshio.read(DATA / "elephant_noisy.off")
    source.point_data["label"] = np.arange(len(source.points), dtype=np.int32)
    meshio.write(tmp_path / "in.vtu", source)
    eps, report = recipe("fair_with_meshio.py")["fair_file"](tmp_path / "in.vtu", tmp_path / "out.vtu")
    out = meshio.read(tmp_path / "out.vtu")
    V = source.points
    d = np.sqrt(((out.points - V) ** 2).sum(axis=1))
    assert (d <= eps).all() and report.final_energy < report.initial_energy
    assert np.array_equal(out.points, cf.fair(V, source.get_cells_type("triangle"), eps)[0])
    assert np.array_equal(out.point_data["label"], source.point_data["label"])


def test_meshio_recipe_from_the_command_line(tmp_path):
    pytest.importorskip("meshio")
    done = subprocess.run([sys.executable, str(EXAMPLES / "fair_with_meshio.py"),
                           str(DATA / "head.off"), str(tmp_path / "head.ply"), "0.3"],
                          capture_output=True, text=True, check=True)
    V, F = cf.read_mesh(DATA / "head.off")
    eps = 0.3 * cf.mean_edge_length(V, F)
    W, _ = cf.read_mesh(tmp_path / "head.ply")
    assert f"epsilon {eps:.6g}" in done.stdout
    assert (np.sqrt(((W - V) ** 2).sum(axis=1)) <= eps).all()


class _Open3dStandIn:
    """The part of Open3D's API that the recipe uses, where Open3D (python3-open3d, which the
    README does not install) is absent: a mesh holds its vertices and triangles as arrays."""

    class TriangleMesh:
        def __init__(self, vertices, triangles):
            self.vertices, self.triangles, self.normals = vertices, triangles, None

        def compute_vertex_normals(self):
            self.normals = np.zeros_like(np.asarray(self.vertices))

        def has_vertex_normals(self):
            return self.normals is not None

    class utility:
        @staticmethod
        def Vector3dVector(array):
            return np.array(array, dtype=np.float64)


def test_open3d_recipe(monkeypatch):
    try:
        import open3d as o3d
        mesh = o3d.io.read_triangle_mesh(str(DATA / "elephant_noisy.off"))
    except ImportError:
        monkeypatch.setitem(sys.modules, "open3d", _Open3dStandIn)
        mesh = _Open3dStandIn.TriangleMesh(*cf.read_mesh(DATA / "elephant_noisy.off"))
    V = np.asarray(mesh.vertices).copy()
    eps, report = recipe("fair_with_open3d.py")["fair_mesh"](mesh)
    W = np.asarray(mesh.vertices)
    assert (np.sqrt(((W - V) ** 2).sum(axis=1)) <= eps).all()
    assert np.array_equal(W, cf.fair(V, np.asarray(mesh.triangles), eps)[0])
    assert mesh.has_vertex_normals() and report.number_of_iterations > 0
