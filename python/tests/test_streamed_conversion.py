"""OFF and OBJ meshes converted to binary PLY a block of lines at a time, for fair_tiled.

The converted file holds the whole-file reader's vertices and faces bit for bit, across blocks
of a few lines; what only the whole-file reader takes is refused with nothing left behind; a
file already there is neither replaced nor removed; the memory is a block's, not the mesh's.
"""

import tracemalloc

import numpy as np
import pytest

import cgal_constrained_fairing as cf
from cgal_constrained_fairing.tiles import _ply_map, _streamed_conversion
from cgal_constrained_fairing.tiles._streamed_conversion import NotStreamed, convert_streamed

from conftest import icosphere, noisy


@pytest.fixture
def small_blocks(monkeypatch):
    monkeypatch.setattr(_streamed_conversion, "BLOCK_LINES", 7)


def mesh():
    V, F = icosphere(2)
    return noisy(V, F, 0.25), F


def converted(path, tmp_path, name="converted.ply"):
    out = tmp_path / name
    convert_streamed(path, out)
    return mapped_mesh(out)


def mapped_mesh(out):
    mapped = _ply_map.map_ply(out)
    records = mapped.vertices()
    V = np.stack([records[name] for name in "xyz"], axis=1)
    return V, np.asarray(mapped.faces()["corners"], np.int64)


def off_text(V, F, header="OFF\n", newline="\n"):
    lines = [header + f"{len(V)} {len(F)} 0"]
    lines += [" ".join(repr(float(x)) for x in p) for p in V]
    lines += ["3 " + " ".join(str(i) for i in f) for f in F]
    return newline.join(lines) + newline


def obj_text(V, F, corner="{}"):
    lines = ["# a scan", "mtllib scan.mtl", "o scan"]
    lines += ["v " + " ".join(repr(float(x)) for x in p) for p in V[: len(V) // 2]]
    lines += ["vt 0.5 0.5", "vn 0 0 1"]
    lines += ["f " + " ".join(corner.format(i + 1) for i in f) for f in F[: len(F) // 2]]
    # Vertices after faces: indices stay those of the file's vertices in order.
    lines += ["v\t" + " ".join(repr(float(x)) for x in p) for p in V[len(V) // 2:]]
    lines += ["f " + " ".join(corner.format(i + 1) for i in f) for f in F[len(F) // 2:]]
    return "\n".join(lines)  # no newline at the end


@pytest.mark.parametrize("name, text", [
    ("written.off", None),
    ("commented.off", lambda V, F: off_text(V, F, header="OFF # a header comment\n\n")),
    ("windows.off", lambda V, F: off_text(V, F, newline="\r\n")),
    ("written.obj", None),
    ("textured.obj", lambda V, F: obj_text(V, F, corner="{0}/{0}/{0}")),
    ("plain.obj", lambda V, F: obj_text(V, F)),
    ("indented.obj", lambda V, F: obj_text(V, F).replace("\nv ", "\n  v ")),
])
def test_the_whole_file_readers_vertices_and_faces(small_blocks, tmp_path, name, text):
    V, F = mesh()
    path = tmp_path / name
    if text is None:
        cf.write_mesh(path, V, F)
    else:
        path.write_text(text(V, F))
    W, G = converted(path, tmp_path)
    whole_V, whole_F = cf.read_mesh(path)
    assert np.array_equal(W, whole_V) and np.array_equal(W, V)
    assert np.array_equal(G, whole_F) and np.array_equal(G, F)


@pytest.mark.parametrize("name, text", [
    ("quads.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"),
    ("coloured_faces.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n"),
    ("coloured.off", "COFF\n3 1 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n3 0 1 2\n"),
    ("short_and_long.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 2 3\n2 1 3\n"),
    ("counts.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
    ("commented_data.off", "OFF\n3 1 0\n0 0 0\n1 0 0 # a corner\n0 1 0\n3 0 1 2\n"),
    ("relative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"),
    ("coloured.obj", "v 0 0 0 1 0 0\nv 1 0 0 1 0 0\nv 0 1 0 1 0 0\nf 1 2 3\n"),
    ("quads.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"),
    ("beyond.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"),
    ("unknown.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nxyz 1\nf 1 2 3\n"),
    ("tabs.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf\t1\t2\t3\n"),
    ("scan.stl", "solid s\nendsolid s\n"),
])
def test_what_only_the_whole_file_reader_takes_is_refused(small_blocks, tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    with pytest.raises(NotStreamed):
        convert_streamed(path, tmp_path / "converted.ply")
    assert [p.name for p in tmp_path.iterdir()] == [name]


@pytest.mark.parametrize("suffix", [".off", ".obj"])
def test_memory_is_a_blocks(monkeypatch, tmp_path, suffix):
    V, F = icosphere(6)
    path = tmp_path / f"sphere{suffix}"
    cf.write_mesh(path, V, F)
    monkeypatch.setattr(_streamed_conversion, "BLOCK_LINES", 256)
    tracemalloc.start()
    try:
        convert_streamed(path, tmp_path / "converted.ply")
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < (V.nbytes + F.nbytes) / 4
    W, G = mapped_mesh(tmp_path / "converted.ply")
    assert np.array_equal(W, V) and np.array_equal(G, F)


@pytest.mark.parametrize("taken", ["converted.ply", "converted.ply.vertices",
                                   "converted.ply.faces"])
def test_a_file_there_is_neither_replaced_nor_removed(tmp_path, taken):
    V, F = mesh()
    path = tmp_path / "scan.off"
    cf.write_mesh(path, V, F)
    (tmp_path / taken).write_bytes(b"a user's file")
    with pytest.raises(FileExistsError):
        convert_streamed(path, tmp_path / "converted.ply")
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(["scan.off", taken])
    assert (tmp_path / taken).read_bytes() == b"a user's file"
