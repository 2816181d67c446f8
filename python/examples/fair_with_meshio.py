"""Fair a mesh file of any format meshio reads, keeping the file's other data.

    python3 fair_with_meshio.py IN OUT [RELATIVE_EPS]

meshio (Debian: python3-meshio) reads and writes STL, PLY, OBJ, OFF, VTK, VTU, Gmsh, ...; the
triangles are faired within RELATIVE_EPS (default 0.25) times the mean edge length, and the
other cells and data are written back unchanged.
"""

import sys

import meshio

import cgal_constrained_fairing as cf


def fair_file(path_in, path_out, relative_eps=0.25):
    """Fair the triangles of `path_in` into `path_out`; returns (epsilon, report)."""
    mesh = meshio.read(path_in)
    triangles = mesh.get_cells_type("triangle")
    eps = relative_eps * cf.mean_edge_length(mesh.points, triangles)
    mesh.points, report = cf.fair(mesh.points, triangles, eps)
    meshio.write(path_out, mesh)
    return eps, report


if __name__ == "__main__":
    eps, report = fair_file(sys.argv[1], sys.argv[2], *map(float, sys.argv[3:4]))
    print(f"epsilon {eps:.6g}")
    print(report)
