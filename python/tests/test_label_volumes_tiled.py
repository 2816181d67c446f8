"""label_surfaces_tiled: a label volume's surfaces made by chunks and faired as tiles on Dask.

The chunks' nets, their points named by the voxel grid, are the whole volume's nets bit for bit
(points, boxes, triangles and their labels), on random voxels and anisotropic spacings; the
tiled surfaces are the in-core call's triangles with points within 0.1 voxel of its points and
within their boxes, every label's surface closed and oriented; two chunk sizes agree as
closely; zarr, TIFF and NIfTI volumes give the array's files; outputs never replace what the
run did not write; a lost task or a killed worker changes no file, a full disk or a scheduler
that cannot be reached leaves none.
"""

import itertools
import os
import signal
import threading
import time
import warnings
from pathlib import Path

import numpy as np
import pytest

import cgal_constrained_fairing as cf
from cgal_constrained_fairing.tiles import label_surfaces_tiled
from cgal_constrained_fairing import _core
from cgal_constrained_fairing.tiles import _label_chunks as lc

from conftest import lost_once

SPACING = (0.8, 1.0, 1.3)


def chunked_nets(L, size, spacing):
    """The nets of every chunk of `size` cells of `L`, concatenated."""
    parts = []
    cells = lc.cell_shape(L.shape)
    for lo in itertools.product(*[range(0, c, size) for c in cells]):
        lo = np.array(lo)
        hi = np.minimum(lo + size, cells)
        a, b = lc.block_of(lo, hi, L.shape)
        block = L[a[0]:b[0], a[1]:b[1], a[2]:b[2]]
        parts.append(lc.chunk_nets(block, a, lo, hi, L.shape, spacing, (0.5, -2, 3), 0))
    return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}


def rows(triangles, face_labels):
    """Triangles with their labels as a set, each rotated to start at its least corner."""
    T = np.asarray(triangles)
    turn = (np.argmin(T, axis=1)[:, None] + np.arange(3)) % 3
    T = np.take_along_axis(T, turn, 1)
    return {tuple(t) + tuple(l) for t, l in zip(T.tolist(), np.asarray(face_labels).tolist())}


class Voronoi:
    """Touching cells of `cells` labels, a sheet one voxel thick and a tube across them, and
    each point's distance to the true surfaces (bisector planes, the sheet's sides, the tube's
    cylinder), in voxels."""

    def __init__(self, shape, cells, seed):
        rng = np.random.default_rng(seed)
        self.shape, self.seeds = shape, rng.uniform(0, 1, (cells, 3)) * shape
        self.sheet, self.centre, self.radius = shape[2] // 3, np.array(shape[:2]) / 2, 2.5
        grid = np.stack(np.meshgrid(*[np.arange(s) for s in shape], indexing="ij"), -1)
        d = np.linalg.norm(grid[..., None, :] - self.seeds, axis=-1)
        L = (np.argmin(d, axis=-1) + 1).astype(np.uint16)
        L[:, :, self.sheet] = cells + 1
        L[np.linalg.norm(grid[..., :2] - self.centre, axis=-1) <= self.radius] = cells + 2
        L[:2] = 0
        self.labels = L

    def distance(self, points, spacing):
        p = np.asarray(points) / spacing
        squares = np.square(p[:, None, :] - self.seeds).sum(axis=-1)
        i = np.argsort(squares, axis=1)[:, :2]
        d2 = np.take_along_axis(squares, i, 1)
        gap = np.linalg.norm(self.seeds[i[:, 0]] - self.seeds[i[:, 1]], axis=1)
        d = (d2[:, 1] - d2[:, 0]) / (2 * gap)
        d = np.minimum(d, np.abs(np.abs(p[:, 2] - self.sheet) - 0.5))
        d = np.minimum(d, np.abs(np.linalg.norm(p[:, :2] - self.centre, axis=1) - self.radius))
        return np.minimum(d, np.abs(p[:, 0] - 1.5))


def voronoi(shape, cells, seed):
    return Voronoi(shape, cells, seed).labels


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_chunks_give_the_whole_volumes_nets(seed):
    rng = np.random.default_rng(seed)
    L = rng.integers(0, 3 + seed, (17, 19, 15))
    whole = lc.chunk_nets(L, (0, 0, 0), (0, 0, 0), lc.cell_shape(L.shape), L.shape, SPACING,
                          (0.5, -2, 3), 0)
    chunks = chunked_nets(L, 8, SPACING)
    a, b = np.argsort(chunks["keys"]), np.argsort(whole["keys"])
    assert np.array_equal(chunks["keys"][a], whole["keys"][b])
    assert np.array_equal(chunks["points"][a], whole["points"][b])
    assert np.array_equal(chunks["boxes"][a], whole["boxes"][b])
    assert len(chunks["triangles"]) == len(whole["triangles"])
    assert rows(chunks["triangles"], chunks["face_labels"]) == rows(whole["triangles"], whole["face_labels"])


def test_keys_order_the_points_as_the_in_core_call():
    L = voronoi((20, 18, 22), 6, 5)
    r = cf.label_surfaces(L, SPACING, fair=False)
    whole = lc.chunk_nets(L, (0, 0, 0), (0, 0, 0), lc.cell_shape(L.shape), L.shape, SPACING,
                          (0, 0, 0), 0)
    assert np.all(np.diff(whole["keys"]) > 0)
    assert np.array_equal(whole["points"], r.unfaired_vertices)


@pytest.fixture(scope="module")
def phantom():
    return Voronoi((44, 40, 46), 10, 7)


@pytest.fixture(scope="module")
def volume(phantom):
    return phantom.labels


@pytest.fixture(scope="module")
def in_core(volume):
    return cf.label_surfaces(volume, SPACING)


def read_surfaces(folder):
    return {int(p.stem.split("_")[1]): cf.read_mesh(p) for p in sorted(Path(folder).glob("label_*.ply"))}


def closed_and_oriented(F):
    edges = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    directed = {tuple(e) for e in edges.tolist()}
    return len(directed) == len(edges) and all((b, a) in directed for a, b in directed)


@pytest.fixture(scope="module")
def tiled(volume, client, tmp_path_factory):
    out = tmp_path_factory.mktemp("tiled") / "surfaces"
    report = label_surfaces_tiled(volume, out, SPACING, client=client, chunk_cells=16)
    return out, report


def in_core_surface(r, label):
    """`label`'s surface of the in-core call `r`, its soup in the canonical order."""
    T, FL = lc.canonical_triangles(r.faces, r.face_labels)
    return _core.label_surface(r.vertices, T, FL, label)


def test_one_chunk_is_the_in_core_call_bit_for_bit(volume, in_core, client, tmp_path):
    report = label_surfaces_tiled(volume, tmp_path / "one", SPACING, client=client, chunk_cells=48)
    assert report.chunks == (1, 1, 1) and report.sweeps == 1
    for label, (V, F) in read_surfaces(tmp_path / "one").items():
        U, G = in_core_surface(in_core, label)
        assert np.array_equal(F, G) and np.array_equal(V, U)


def test_tiles_give_the_in_core_triangles_closer_to_the_truth(phantom, in_core, tiled):
    out, report = tiled
    assert report.chunks == (3, 3, 3) and report.sweeps >= 2 and report.converged
    assert report.motion[-1] < report.motion[1]
    assert report.points == len(in_core.vertices) and report.triangles == len(in_core.faces)
    surfaces = read_surfaces(out)
    assert sorted(surfaces) == in_core.labels.tolist()
    for label, (V, F) in surfaces.items():
        U, G = in_core_surface(in_core, label)
        assert np.array_equal(F, G)
        assert closed_and_oriented(F)
    # The in-core call stops where its objective falls slowly, points still drifting along the
    # surfaces (design notes, "Label volumes in tiles"): the tiles are judged by the truth.
    tiled_points = np.concatenate([V for V, _ in surfaces.values()])
    in_core_points = np.concatenate([in_core_surface(in_core, L)[0] for L in surfaces])
    rms = [np.sqrt(np.mean(phantom.distance(P, SPACING) ** 2)) for P in (tiled_points, in_core_points)]
    assert rms[0] <= 1.02 * rms[1]


def test_tiled_points_stay_in_their_boxes(volume, tiled):
    out, _ = tiled
    nets = cf.label_surfaces(volume, SPACING, fair=False)
    boxes = cf.LabelSurfaces(nets.box_half_extents, nets.faces, nets.face_labels, nets.vertices,
                             nets.box_half_extents, None, nets.labels)
    for label, (V, F) in read_surfaces(out).items():
        U, _ = in_core_surface(nets, label)
        H, _ = in_core_surface(boxes, label)
        assert np.all(np.abs(V - U) <= H)


def test_two_chunk_sizes_agree(volume, client, tiled, tmp_path):
    out, _ = tiled
    report = label_surfaces_tiled(volume, tmp_path / "s", SPACING, client=client, chunk_cells=(24, 20, 16))
    assert report.chunks == (2, 3, 3)
    first, second = read_surfaces(out), read_surfaces(tmp_path / "s")
    assert sorted(first) == sorted(second)
    for label in first:
        assert np.array_equal(first[label][1], second[label][1])
    d = np.concatenate([np.linalg.norm((first[L][0] - second[L][0]) / SPACING, axis=1) for L in first])
    assert np.sqrt(np.mean(d ** 2)) <= 0.1


@pytest.mark.parametrize("kind", ["zarr", "tiff", "nifti"])
def test_volume_files_give_the_arrays_surfaces(kind, client, tmp_path):
    L = voronoi((20, 18, 22), 5, 11)
    path = tmp_path / {"zarr": "v.zarr", "tiff": "v.tif", "nifti": "v.nii.gz"}[kind]
    if kind == "zarr":
        zarr = pytest.importorskip("zarr")
        zarr.save_array(str(path), L, chunks=(8, 8, 8))
    elif kind == "tiff":
        pytest.importorskip("tifffile").imwrite(path, L)
    else:
        nibabel = pytest.importorskip("nibabel")
        nibabel.save(nibabel.Nifti1Image(L, np.eye(4)), str(path))
    label_surfaces_tiled(path, tmp_path / "a", client=client, chunk_cells=16)
    label_surfaces_tiled(L, tmp_path / "b", client=client, chunk_cells=16)
    for name in sorted(p.name for p in (tmp_path / "b").iterdir()):
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes()


def test_outputs_never_replace_what_the_run_did_not_write(client, tmp_path):
    L = voronoi((20, 18, 22), 3, 2)
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    (out / "label_2.ply").write_text("kept")
    with pytest.raises(FileExistsError, match="label_2.ply"):
        label_surfaces_tiled(L, out, client=client, chunk_cells=16)
    assert sorted(p.name for p in out.iterdir()) == ["label_2.ply", "notes.txt"]
    assert (out / "label_2.ply").read_text() == "kept"
    label_surfaces_tiled(L, out, client=client, chunk_cells=16, force=True)
    names = sorted(p.name for p in out.iterdir())
    assert names == sorted(["notes.txt"] + [f"label_{k}.ply" for k in range(1, 6)])
    assert (out / "notes.txt").read_text() == "mine"
    (tmp_path / "file").write_text("x")
    with pytest.raises(ValueError, match="is a file"):
        label_surfaces_tiled(L, tmp_path / "file", client=client, chunk_cells=16)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["file", "out"]


def test_bad_volumes_and_outputs_are_refused(client, tmp_path):
    L = voronoi((20, 18, 22), 3, 2)
    with pytest.raises(ValueError, match="3 dimensions"):
        label_surfaces_tiled(L[0], tmp_path / "a", client=client, chunk_cells=16)
    with pytest.raises(ValueError, match="integers"):
        label_surfaces_tiled(L.astype(np.float32), tmp_path / "a", client=client, chunk_cells=16)
    with pytest.raises(ValueError, match="at least 16"):
        label_surfaces_tiled(L, tmp_path / "a", client=client, chunk_cells=8)
    with pytest.raises(ValueError, match="nothing but the background"):
        label_surfaces_tiled(np.zeros_like(L), tmp_path / "a", client=client, chunk_cells=16)
    zarr = pytest.importorskip("zarr")
    zarr.save_array(str(tmp_path / "v.zarr"), L)
    before = sorted(p.name for p in (tmp_path / "v.zarr").iterdir())
    with pytest.raises(ValueError, match="is the input volume or lies in it"):
        label_surfaces_tiled(tmp_path / "v.zarr", tmp_path / "v.zarr" / "s", client=client)
    assert sorted(p.name for p in (tmp_path / "v.zarr").iterdir()) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["v.zarr"]


def test_a_task_lost_after_its_write_is_run_again_with_the_same_result(tmp_path, monkeypatch):
    # A worker lost after a descent wrote its file but before Dask heard of it: Dask runs the
    # task again, which reads what the first run read (the sweep's points become the chunk's
    # only once its colour is done) and writes the same file.
    import distributed
    from cgal_constrained_fairing.tiles import _label_tiles
    L = voronoi((20, 18, 36), 5, 4)
    marker = tmp_path / "lost.marker"
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster, set_as_default=False) as in_process:
        label_surfaces_tiled(L, tmp_path / "kept", client=in_process, chunk_cells=16)
        monkeypatch.setattr(_label_tiles, "fair_tile", lost_once(_label_tiles.fair_tile, marker, (0, 2)))
        label_surfaces_tiled(L, tmp_path / "lost", client=in_process, chunk_cells=16)
    assert marker.read_text() == "tile 0, sweep 2"
    for path in (tmp_path / "kept").iterdir():
        assert (tmp_path / "lost" / path.name).read_bytes() == path.read_bytes()


def test_a_worker_killed_mid_sweep_leaves_the_result_unchanged(tmp_path):
    # A worker process killed while it runs a tile's descent: its nanny starts another, Dask
    # runs the lost task again from the files of the sweep before, and every file is the same
    # bit for bit.
    import distributed
    L = voronoi((20, 18, 36), 5, 4)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster, set_as_default=False) as client:
        label_surfaces_tiled(L, tmp_path / "kept", client=client, chunk_cells=16)
        before = client.run(os.getpid)
        killed = []

        def kill_one_descent():
            while not killed:
                for worker, keys in client.processing().items():
                    if any(str(key).startswith("fair_tile") for key in keys):
                        os.kill(before[worker], signal.SIGKILL)
                        killed.append(worker)
                        return
                time.sleep(0.01)
        killer = threading.Thread(target=kill_one_descent, daemon=True)
        killer.start()
        label_surfaces_tiled(L, tmp_path / "lost", client=client, chunk_cells=16)
        killer.join(timeout=10)
        after = client.run(os.getpid)
    assert killed and before[killed[0]] not in after.values()
    names = sorted(p.name for p in (tmp_path / "kept").iterdir())
    assert names == sorted(p.name for p in (tmp_path / "lost").iterdir())
    for name in names:
        assert (tmp_path / "lost" / name).read_bytes() == (tmp_path / "kept" / name).read_bytes()


def test_a_scheduler_that_cannot_be_reached_is_a_clear_error(tmp_path, capsys):
    import dask
    import socket
    from cgal_constrained_fairing.tiles._command_line import main
    np.save(tmp_path / "seg.npy", voronoi((20, 18, 22), 3, 2))
    with socket.socket() as s:  # a port nothing listens on
        s.bind(("127.0.0.1", 0))
        address = f"tcp://127.0.0.1:{s.getsockname()[1]}"
    (tmp_path / "s").mkdir()
    (tmp_path / "s" / "label_1.ply").write_bytes(b"an earlier output")
    with dask.config.set({"distributed.comm.timeouts.connect": "2s"}):
        assert main([str(tmp_path / "seg.npy"), str(tmp_path / "s"), "--scheduler", address]) == 1
    said = capsys.readouterr().out
    assert said.startswith("error: ") and address in said and "nothing written" in said
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s", "seg.npy"]
    assert [p.name for p in (tmp_path / "s").iterdir()] == ["label_1.ply"]
    assert (tmp_path / "s" / "label_1.ply").read_bytes() == b"an earlier output"


def test_a_full_disk_leaves_no_output(tmp_path, monkeypatch):
    import errno
    import distributed
    from cgal_constrained_fairing.tiles import _label_tiles
    L = voronoi((20, 18, 22), 3, 2)

    def full(path, *arguments, **keywords):
        raise OSError(errno.ENOSPC, "No space left on device")
    monkeypatch.setattr(_label_tiles, "write_mesh", full)
    (tmp_path / "out").mkdir()
    (tmp_path / "out" / "notes.txt").write_text("mine")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster, set_as_default=False) as in_process:
        for out in (tmp_path / "new", tmp_path / "out"):
            with pytest.raises(OSError, match="No space left on device.*label_1.ply"):
                label_surfaces_tiled(L, out, client=in_process, chunk_cells=16)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["notes.txt"]


def oriented_triangles(V, F):
    """A surface's triangles as a set of corner coordinates (to 1e-9), each from its least."""
    rows = set()
    for f in np.round(V, 9)[F].tolist():
        first = min(range(3), key=lambda c: f[c])
        rows.add(tuple(tuple(f[(first + c) % 3]) for c in range(3)))
    return rows


def test_a_nifti_files_affine_places_the_surfaces(client, tmp_path):
    # A mirrored x axis, voxel sizes and a translation: the surfaces are the in-core call's
    # given the file's affine, in the world, oriented outward.
    nibabel = pytest.importorskip("nibabel")
    L = voronoi((20, 18, 22), 4, 6)
    affine = np.diag([-0.8, 1.0, 1.3, 1.0])
    affine[:3, 3] = [12.0, -3.0, 5.5]
    nibabel.save(nibabel.Nifti1Image(L, affine), str(tmp_path / "seg.nii.gz"))
    report = label_surfaces_tiled(tmp_path / "seg.nii.gz", tmp_path / "s", client=client, chunk_cells=32)
    assert report.chunks == (1, 1, 1)
    labels, stored = cf.read_label_map(tmp_path / "seg.nii.gz")  # the header's float32 affine
    r = cf.label_surfaces(labels, affine=stored)
    surfaces = read_surfaces(tmp_path / "s")
    assert sorted(surfaces) == r.labels.tolist()
    for label, (V, F) in surfaces.items():
        assert oriented_triangles(V, F) == oriented_triangles(*r.surface(label))
    with pytest.raises(ValueError, match="either affine, or spacing and origin"):
        label_surfaces_tiled(L, tmp_path / "t", (1, 1, 1), affine=affine, client=client)


def test_command_line(tmp_path, capsys):
    import subprocess
    import sys
    zarr = pytest.importorskip("zarr")
    L = voronoi((20, 18, 22), 3, 2)
    zarr.save_array(str(tmp_path / "seg.zarr"), L, chunks=(10, 10, 10))
    environment = dict(__import__("os").environ, PYTHONPATH=str(Path(cf.__file__).resolve().parents[1]))
    run = subprocess.run([sys.executable, "-m", "cgal_constrained_fairing.tiles", str(tmp_path / "seg.zarr"),
                          str(tmp_path / "s"), "--spacing", "0.5", "0.5", "2", "--chunk-cells", "16"],
                         env=environment, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "5 labels" in run.stdout and "converged=True" in run.stdout
    r = cf.label_surfaces(L, (0.5, 0.5, 2))
    assert sorted(read_surfaces(tmp_path / "s")) == r.labels.tolist()
    from cgal_constrained_fairing.tiles._command_line import main
    with pytest.raises(SystemExit):
        main([str(tmp_path / "seg.zarr"), str(tmp_path / "t"), "--eps", "0.1"])
    assert "--eps is for meshes" in capsys.readouterr().err
    assert not (tmp_path / "t").exists()


def test_chunks_shrink_to_fit_the_tile_memory(volume, client, tmp_path):
    from cgal_constrained_fairing.tiles._label_volumes import BYTES_PER_TRIANGLE
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the sized chunks fit
        report = label_surfaces_tiled(volume, tmp_path / "a", SPACING, client=client, tile_memory="150MB")
    assert report.chunks != (1, 1, 1)
    cells = np.prod(np.asarray(volume.shape) + 1)
    density = report.triangles / cells  # the mean, at most the densest chunk's
    size = report.chunk_cells[0]
    assert 16 < size < 45 and (size + 22) ** 3 * density * BYTES_PER_TRIANGLE <= 150e6
    with pytest.warns(UserWarning, match="more than tile_memory .60000000.; give fewer chunk_cells"):
        fixed = label_surfaces_tiled(volume, tmp_path / "b", SPACING, client=client, chunk_cells=48,
                                     tile_memory="60MB")
    assert fixed.chunks == (1, 1, 1)
