"""Fair an Open3D triangle mesh in place, then recompute its normals.

    python3 fair_with_open3d.py IN OUT [RELATIVE_EPS]

Open3D (Debian: python3-open3d) reads and writes PLY, STL, OBJ, OFF, glTF; its vertices and
triangles are numpy-compatible buffers, so the call is a copy in and a copy out.
"""

import sys

import numpy as np
import open3d as o3d

import cgal_constrained_fairing as cf


def fair_mesh(mesh, relative_eps=0.25):
    """Fair `mesh` (an ``open3d.geometry.TriangleMesh``) in place; returns (epsilon, report)."""
    V = np.asarray(mesh.vertices)
    F = np.asarray(mesh.triangles)
    eps = relative_eps * cf.mean_edge_length(V, F)
    W, report = cf.fair(V, F, eps)
    mesh.vertices = o3d.utility.Vector3dVector(W)
    mesh.compute_vertex_normals()
    return eps, report


if __name__ == "__main__":
    mesh = o3d.io.read_triangle_mesh(sys.argv[1])
    eps, report = fair_mesh(mesh, *map(float, sys.argv[3:4]))
    o3d.io.write_triangle_mesh(sys.argv[2], mesh)
    print(f"epsilon {eps:.6g}")
    print(report)
