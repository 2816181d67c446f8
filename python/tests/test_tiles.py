"""fair_tiled: one mesh faired as tiles with frozen ghosts on a Dask cluster.

One tile is the in-core call bit for bit (the start and the lines along the normals are the
whole call's); many tiles keep the bound exactly in double, the faces byte for byte, the
vertices' properties and order, end their sweeps below 0.5 % of epsilon, and lower the energy
from the start; their seams end as close to the whole call's points as their interiors (the
first sweep's overlap); a tile's band descends as its whole mesh would with the rest frozen; bad
requests leave every file as it was and nothing of the run behind.
"""

import functools
import hashlib
import os
import resource
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import cgal_constrained_fairing as cf
from cgal_constrained_fairing import _core
from cgal_constrained_fairing._fairing import call_options, result_of
from cgal_constrained_fairing.tiles import BYTES_PER_TRIANGLE, MOTION_TOLERANCE, fair_tiled
from cgal_constrained_fairing.tiles import _partition, _ply_map, _sweeps

from conftest import icosphere, lost_once, noisy

# The small meshes here are cut into tiles smaller than their 18 rings of ghosts, which
# fair_tiled warns of (test_tiles_too_small_for_their_ghosts_warn).
pytestmark = pytest.mark.filterwarnings("ignore:tiles of .* rings of ghosts")


@pytest.fixture(scope="module")
def scan(tmp_path_factory):
    """A noisy sphere of 20,480 triangles as binary PLY with colours and a float property."""
    V, F = icosphere(5)
    V = noisy(V, F, 0.25)
    rng = np.random.default_rng(3)
    properties = cf.MeshProperties(
        vertex={"red": rng.integers(0, 256, len(V)).astype(np.uint8),
                "confidence": rng.random(len(V)).astype(np.float32)},
        face={"quality": rng.random(len(F)).astype(np.float32)})
    path = tmp_path_factory.mktemp("scan") / "scan.ply"
    cf.write_mesh(path, V, F, properties=properties)
    eps = 0.25 * cf.mean_edge_length(V, F)
    return path, V, F, properties, eps


def budget(F, parts):
    """A tile memory that cuts the mesh of faces `F` into about `parts` tiles."""
    return len(F) * BYTES_PER_TRIANGLE // parts


def digest(path):
    return hashlib.sha256(path.read_bytes()).hexdigest()


def face_block(path):
    mapped = _ply_map.map_ply(path)
    offset, length = mapped.face_block
    return path.read_bytes()[offset:offset + length]


def test_one_tile_is_the_in_core_call(client, scan, tmp_path):
    path, V, F, _, eps = scan
    report = fair_tiled(path, tmp_path / "out.ply", eps, client=client, tile_memory="1GiB")
    W, _ = cf.fair(V, F, eps)
    out, out_faces = cf.read_mesh(tmp_path / "out.ply")
    assert len(report.colour) == 1
    assert np.array_equal(out, W)
    assert np.array_equal(out_faces, F)


def test_tiles_keep_bound_faces_properties_and_converge(client, scan, tmp_path):
    path, V, F, properties, eps = scan
    before = digest(path)
    out_path = tmp_path / "out.ply"
    report = fair_tiled(path, out_path, eps, client=client, tile_memory=budget(F, 8))
    assert digest(path) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.ply"]
    assert len(report.colour) >= 8 and report.colour.max() >= 1
    assert report.tile.shape == (len(V),) and set(np.unique(report.tile)) == set(
        range(len(report.colour)))
    assert report.converged and report.motion[-1] <= MOTION_TOLERANCE
    W, out_faces, carried = cf.read_mesh(out_path, properties=True)
    assert (np.linalg.norm(W - V, axis=1) <= eps).all()
    assert face_block(out_path) == face_block(path)
    assert np.array_equal(out_faces, F)
    for name, values in properties.vertex.items():
        assert np.array_equal(carried.vertex[name], values)
    assert np.array_equal(carried.face["quality"], properties.face["quality"])
    assert np.array_equal(carried.vertex["deviation"], np.linalg.norm(W - V, axis=1))
    assert report.max_deviation == pytest.approx(carried.vertex["deviation"].max(), rel=0, abs=0)
    _, input_energy = cf.fair(V, F, eps, max_iterations=0)
    _, whole = cf.fair(V, F, eps)
    tiled = cf.fair(W, F, eps, max_iterations=0)[1]
    assert tiled.initial_energy < input_energy.initial_energy
    assert tiled.initial_energy <= 1.05 * whole.final_energy


def test_seams_are_as_close_to_the_whole_call_as_interiors(client, scan, tmp_path):
    # The first sweep's overlap: without it (ghosts frozen at the smoothed start), the vertices
    # within a ring of a tile border were 2.7 times farther from the whole call's points than
    # those beyond 3 rings (2.1 in 16 tiles), in 8 sweeps instead of 3.
    path, V, F, _, eps = scan
    report = fair_tiled(path, tmp_path / "out.ply", eps, client=client, tile_memory=budget(F, 8))
    T, _ = cf.read_mesh(tmp_path / "out.ply")
    W, _ = cf.fair(V, F, eps)
    border = border_vertices(report.tile, F)
    rings = _partition.Rings(F, len(V))
    near, far = rings.within(border, 1), ~rings.within(border, 3)
    distance = np.linalg.norm(T - W, axis=1) / eps
    rms = [np.sqrt(np.mean(np.square(distance[part]))) for part in (near, far)]
    assert far.sum() > 1000 and rms[0] <= 1.5 * rms[1]


def border_vertices(tile, F):
    """The vertices with a neighbour in another tile."""
    edges = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    border = np.zeros(len(tile), bool)
    border[edges[tile[edges[:, 0]] != tile[edges[:, 1]]].ravel()] = True
    return border


def test_crossing_cuts_give_the_same_result(client, scan, tmp_path, monkeypatch):
    # Where the tile borders lie does not show in the result: cells cut across their second
    # widest extent put borders across the first cut's tiles, and where the first had a border
    # and the second none (22 % of the first's border vertices here), the two results are as
    # close as elsewhere (0.013 epsilon RMS).
    path, V, F, _, eps = scan
    first = fair_tiled(path, tmp_path / "first.ply", eps, client=client, tile_memory=budget(F, 8))
    crossing = functools.partial(_partition.kd_tiles, across=1)
    monkeypatch.setattr(_partition, "kd_tiles", crossing)
    second = fair_tiled(path, tmp_path / "second.ply", eps, client=client,
                        tile_memory=budget(F, 8))
    borders = [border_vertices(report.tile, F) for report in (first, second)]
    rings = _partition.Rings(F, len(V))
    # The first cut's border vertices 3 rings or more from the second's.
    apart = borders[0] & ~rings.within(borders[1], 3)
    T1, T2 = (cf.read_mesh(tmp_path / name)[0] for name in ("first.ply", "second.ply"))
    distance = np.linalg.norm(T1 - T2, axis=1) / eps
    assert apart.sum() >= 200
    for part in (slice(None), apart):
        assert np.sqrt(np.mean(np.square(distance[part]))) <= 0.02


def test_other_formats_are_converted(client, scan, tmp_path):
    path, V, F, _, eps = scan
    off = tmp_path / "scan.off"
    cf.write_mesh(off, V, F)
    fair_tiled(off, tmp_path / "out.ply", eps, client=client, tile_memory=budget(F, 4))
    W, out_faces = cf.read_mesh(tmp_path / "out.ply")
    assert np.array_equal(out_faces, F)
    assert (np.linalg.norm(W - V, axis=1) <= eps).all()


def test_enough_tiles_for_the_workers(client, scan, tmp_path, monkeypatch):
    # Two tiles by memory, on 2 single-threaded workers: at least 4 a thread, unless tiles of
    # SMALLEST_TILE triangles would be fewer; a mesh that fits one tile stays one, in core.
    import cgal_constrained_fairing.tiles as tiles
    path, V, F, _, eps = scan
    monkeypatch.setattr(tiles, "SMALLEST_TILE", 1000)
    report = fair_tiled(path, tmp_path / "out.ply", eps, client=client, tile_memory=budget(F, 2))
    assert len(report.colour) >= tiles.TILES_PER_SLOT * 2
    monkeypatch.setattr(tiles, "SMALLEST_TILE", len(F) // 3)
    report = fair_tiled(path, tmp_path / "out.ply", eps, client=client, tile_memory=budget(F, 2))
    assert len(report.colour) < tiles.TILES_PER_SLOT * 2
    report = fair_tiled(path, tmp_path / "out.ply", eps, client=client, tile_memory="1GiB")
    assert len(report.colour) == 1


def test_relative_and_estimated_eps_come_from_the_tiles(client, scan, tmp_path, monkeypatch):
    # "h" and "auto" are the whole mesh's, measured from the tiles' parts: the client never
    # builds the whole mesh (its measures of the whole mesh are made to fail here).
    path, V, F, _, _ = scan
    whole = {"h": 0.25 * cf.mean_edge_length(V, F), "auto": cf.estimate_noise_level(V, F)}

    def whole_mesh(*_):
        raise AssertionError("the whole mesh measured in the client")
    monkeypatch.setattr(_core, "mean_edge_length", whole_mesh)
    monkeypatch.setattr(_core, "estimate_noise_level", whole_mesh)
    for eps, kind in (("0.25h", "h"), ("auto", "auto")):
        report = fair_tiled(path, tmp_path / "out.ply", eps, client=client,
                            tile_memory=budget(F, 8))
        assert len(report.colour) >= 8
        assert report.epsilon == pytest.approx(whole[kind], rel=1e-12)
        W, _ = cf.read_mesh(tmp_path / "out.ply")
        assert (np.linalg.norm(W - V, axis=1) <= report.epsilon).all()


def test_refusals_leave_files_as_they_were(client, scan, tmp_path):
    path, V, F, _, eps = scan
    before = digest(path)
    with pytest.raises(ValueError, match="is the input"):
        fair_tiled(path, path, eps, client=client)
    with pytest.raises(ValueError, match="writes PLY"):
        fair_tiled(path, tmp_path / "out.off", eps, client=client)
    (tmp_path / "folder.ply").mkdir()
    with pytest.raises(ValueError, match="is a folder"):
        fair_tiled(path, tmp_path / "folder.ply", eps, client=client)
    (tmp_path / "folder.ply").rmdir()
    with pytest.raises(ValueError, match="does not take 'feature_angle'"):
        fair_tiled(path, tmp_path / "out.ply", eps, client=client, feature_angle=30)
    with pytest.raises(ValueError, match="eps must be positive"):
        fair_tiled(path, tmp_path / "out.ply", -1.0, client=client)
    with pytest.raises(cf.InputError, match="sliver_barrier_weight"):
        fair_tiled(path, tmp_path / "out.ply", eps, client=client, sliver_barrier_weight=-1)
    assert digest(path) == before
    assert list(tmp_path.iterdir()) == []


def test_a_defect_in_a_tile_is_an_input_error(client, tmp_path):
    V, F = icosphere(3)
    # Two faces through one edge the wrong way round: inconsistent orientation.
    F = F.copy()
    F[0] = F[0][::-1]
    bad = tmp_path / "bad.ply"
    cf.write_mesh(bad, V, F)
    with pytest.raises(cf.InputError) as error:
        fair_tiled(bad, tmp_path / "out.ply", 0.01, client=client, tile_memory=budget(F, 4))
    assert error.value.defect == cf.Defect.INCONSISTENT_ORIENTATION
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.ply"]


def test_command_line(scan, tmp_path, capsys):
    # In a process of its own, as users run it: its local cluster's client is no default one.
    from cgal_constrained_fairing.tiles._command_line import main
    path, V, F, _, eps = scan
    out = tmp_path / "out.ply"
    environment = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(Path(cf.__file__).resolve().parents[1])] + [p for p in [os.environ.get("PYTHONPATH")] if p]))
    run = subprocess.run([sys.executable, "-m", "cgal_constrained_fairing.tiles", str(path), str(out),
                          "--eps", "0.25h", "--tile-memory", str(budget(F, 4))],
                         env=environment, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "converged=True" in run.stdout
    W, out_faces = cf.read_mesh(out)
    assert np.array_equal(out_faces, F)
    assert (np.linalg.norm(W - V, axis=1) <= eps).all()
    assert main([str(path), str(tmp_path / "out.off")]) == 1
    assert "writes PLY" in capsys.readouterr().out
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.ply"]


def test_a_scheduler_that_cannot_be_reached_is_a_clear_error(scan, tmp_path, capsys):
    import dask
    import socket
    from cgal_constrained_fairing.tiles._command_line import main
    path, _, _, _, _ = scan
    with socket.socket() as s:  # a port nothing listens on
        s.bind(("127.0.0.1", 0))
        address = f"tcp://127.0.0.1:{s.getsockname()[1]}"
    (tmp_path / "out.ply").write_bytes(b"an earlier output")
    with dask.config.set({"distributed.comm.timeouts.connect": "2s"}):
        assert main([str(path), str(tmp_path / "out.ply"), "--scheduler", address]) == 1
    said = capsys.readouterr().out
    assert said.startswith("error: ") and address in said and "nothing written" in said
    assert [p.name for p in tmp_path.iterdir()] == ["out.ply"]
    assert (tmp_path / "out.ply").read_bytes() == b"an earlier output"


@pytest.mark.filterwarnings("default")
def test_tiles_too_small_for_their_ghosts_warn(client, scan, tmp_path):
    path, V, F, _, eps = scan
    with pytest.warns(UserWarning, match="more than tile_memory"):
        fair_tiled(path, tmp_path / "out.ply", eps, client=client, tile_memory=budget(F, 8))
    assert (tmp_path / "out.ply").exists()


def test_work_dir_keeps_what_was_there(client, scan, tmp_path):
    path, V, F, _, eps = scan
    work = tmp_path / "work"
    work.mkdir()
    (work / "notes.txt").write_text("a user's file")
    (work / "sub").mkdir()
    out = tmp_path / "out.ply"
    out.write_bytes(b"an earlier output")
    fair_tiled(path, out, eps, client=client, tile_memory=budget(F, 4), work_dir=work)
    assert sorted(p.name for p in work.iterdir()) == ["notes.txt", "sub"]
    assert (work / "notes.txt").read_text() == "a user's file"
    assert np.array_equal(cf.read_mesh(out)[1], F)


def test_a_failed_write_leaves_the_earlier_output(client, scan, tmp_path, monkeypatch):
    path, V, F, _, eps = scan
    out = tmp_path / "out.ply"
    out.write_bytes(b"an earlier output")

    def fails(mapped, partial, *arrays):
        partial.write_bytes(b"half an output")
        raise OSError("No space left on device")
    monkeypatch.setattr(_ply_map, "write_ply", fails)
    with pytest.raises(OSError, match="No space left"):
        fair_tiled(path, out, eps, client=client, tile_memory=budget(F, 4))
    assert out.read_bytes() == b"an earlier output"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.ply"]


def limit_file_size(size):
    """Files of this process may grow to `size` bytes at most (the kernel refuses the write
    beyond, as a full disk would); the limit before, to restore."""
    before = resource.getrlimit(resource.RLIMIT_FSIZE)
    resource.setrlimit(resource.RLIMIT_FSIZE, (size, before[1]))
    return before


def test_a_file_system_that_refuses_writes_leaves_no_output(client, scan, tmp_path, monkeypatch):
    # The workers cannot write the tiles' files, then the client cannot write the output: each
    # time an error naming the file, the earlier output as it was, nothing of the run left.
    import distributed
    path, V, F, _, eps = scan
    out = tmp_path / "out.ply"
    out.write_bytes(b"an earlier output")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster, set_as_default=False) as limited:
        limited.run(limit_file_size, 10000)
        with pytest.raises(OSError, match=r"File too large: .*tiles"):
            fair_tiled(path, out, eps, client=limited, tile_memory=budget(F, 4))
    assert out.read_bytes() == b"an earlier output"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.ply"]
    write = cf.tiles._Run.write

    def write_when_full(run, out_path):
        before = limit_file_size(100000)  # the run's arrays are written, the output is larger
        try:
            write(run, out_path)
        finally:
            resource.setrlimit(resource.RLIMIT_FSIZE, before)
    monkeypatch.setattr(cf.tiles._Run, "write", write_when_full)
    with pytest.raises(OSError, match=r"File too large: .*out\.ply"):
        fair_tiled(path, out, eps, client=client, tile_memory=budget(F, 4))
    assert out.read_bytes() == b"an earlier output"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.ply"]


def test_rings_are_those_of_the_faces():
    V, F = icosphere(4)
    rings = _partition.Rings(F, len(V))
    rng = np.random.default_rng(5)
    for start in (V[:, 0] > 0.6, rng.random(len(V)) < 0.01, np.zeros(len(V), bool)):
        reached = start.copy()
        for count in range(6):
            assert np.array_equal(rings.within(start, count), reached)
            # One ring more: every vertex of a face with a vertex reached.
            reached = reached.copy()
            reached[F[reached[F].any(axis=1)].ravel()] = True


def test_kd_cells_are_of_equal_counts_from_a_sample(monkeypatch):
    V, _ = icosphere(6)
    monkeypatch.setattr(_partition, "BLOCK_ROWS", 5000)  # several blocks
    for count, sample, spread in ((8, len(V), 3), (12, len(V), 4), (8, 4096, 0.15 * len(V) / 8)):
        monkeypatch.setattr(_partition, "CUT_SAMPLE", sample)
        tiles = _partition.kd_tiles(V, count)
        counts = np.bincount(tiles.tile, minlength=tiles.count)
        assert tiles.count == count and counts.max() - counts.min() <= spread
        for t in range(tiles.count):
            members = V[tiles.tile == t]
            assert np.array_equal(tiles.boxes[t], [members.min(axis=0), members.max(axis=0)])
    crossing = _partition.kd_tiles(V, 8, across=1)
    assert not np.array_equal(crossing.tile, tiles.tile)


def test_candidate_faces_are_those_with_a_corner_in_each_box(monkeypatch):
    V, F = icosphere(4)
    rng = np.random.default_rng(8)
    centres, halves = rng.uniform(-1, 1, (20, 3)), rng.uniform(0.05, 0.8, (20, 3))
    boxes = np.concatenate([np.stack([centres - halves, centres + halves], axis=1),
                            [[[2, 2, 2], [3, 3, 3]], [[-1, -1, 0], [1, 1, 0]]]])
    monkeypatch.setattr(_partition, "BLOCK_ROWS", 1000)  # blocks of several grid cells
    found = _partition.candidate_faces(F, V, boxes)
    for box, faces in zip(boxes, found):
        inside = ((V[F] >= box[0]) & (V[F] <= box[1])).all(axis=2).any(axis=1)
        assert np.array_equal(faces, np.flatnonzero(inside))
    assert len(found[-2]) == 0 and 0 < len(found[-1]) < len(F)


def tile_and_band(V, F, count, t):
    """Tile `t` of `count` k-d tiles of the mesh (V, F), with its band."""
    rings = _sweeps.ghost_rings(16)
    tiles = _partition.kd_tiles(V, count)
    box = _partition.grown(tiles.boxes[t], 10.0)
    mesh = _partition.tile_mesh(t, tiles, F, V, rings, box, np.arange(len(F)))
    return mesh, _partition.band_mesh(mesh, rings)


def test_a_band_descends_as_its_tile_with_the_rest_frozen(scan):
    _, V, F, _, eps = scan
    mesh, band = tile_and_band(V, F, 4, 0)
    ghosts = ~mesh.owned
    assert ghosts[band.vertices].sum() == ghosts.sum()  # every ghost is in the band
    assert band.free.any() and not band.free.all()
    assert np.array_equal(band.seam & ~band.free, np.zeros_like(band.seam))
    free = np.zeros(len(mesh.vertices), bool)
    free[band.vertices[band.free]] = True
    assert not (free & ghosts).any()
    # From a state of the whole call, ten iterations of the band and of the tile with only the
    # band's vertices free: the same points, up to rounding.
    current, _ = cf.fair(V, F, eps, max_iterations=30)
    options = call_options(eps)

    def descend(vertices, faces, owned):
        outcome = _core.fair_tile(np.ascontiguousarray(V[vertices]),
                                  np.ascontiguousarray(current[vertices]), faces, owned,
                                  np.zeros(len(vertices), bool), options, 10)
        return result_of(outcome)[0]
    whole = descend(mesh.vertices, mesh.local_faces, free)[band.vertices[band.free]]
    part = descend(mesh.vertices[band.vertices], band.local_faces, band.free)[band.free]
    assert np.abs(part - current[mesh.vertices[band.vertices[band.free]]]).max() > 1e-3 * eps
    assert np.abs(part - whole).max() <= 1e-9 * eps


def test_a_scheduler_without_workers_is_a_clear_error(scan, tmp_path, monkeypatch):
    import distributed
    import cgal_constrained_fairing.tiles as tiles
    path, V, F, _, eps = scan
    monkeypatch.setattr(tiles, "WORKER_WAIT_SECONDS", 1)
    with distributed.LocalCluster(n_workers=0, dashboard_address=None) as cluster, \
            distributed.Client(cluster, set_as_default=False) as empty:
        with pytest.raises(TimeoutError, match="no Dask worker joined the scheduler"):
            fair_tiled(path, tmp_path / "out.ply", eps, client=empty)
    assert list(tmp_path.iterdir()) == []


def test_a_task_lost_after_its_write_is_run_again_with_the_same_result(scan, tmp_path, monkeypatch):
    # A worker lost after a task wrote its file but before Dask heard of it: Dask runs the task
    # again (its retries), which writes the same file; the output is the same bit for bit. The
    # loss is marked in a file.
    import distributed
    path, V, F, _, eps = scan
    marker = tmp_path / "lost"
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster, set_as_default=False) as in_process:
        fair_tiled(path, tmp_path / "kept.ply", eps, client=in_process, tile_memory=budget(F, 8))
        monkeypatch.setattr(_sweeps, "fair_tile", lost_once(_sweeps.fair_tile, marker, (0, 2)))
        fair_tiled(path, tmp_path / "lost.ply", eps, client=in_process, tile_memory=budget(F, 8))
    assert marker.read_text() == "tile 0, sweep 2"
    assert (tmp_path / "lost.ply").read_bytes() == (tmp_path / "kept.ply").read_bytes()


def test_a_worker_killed_mid_sweep_leaves_the_result_unchanged(scan, tmp_path):
    # A worker process killed while it runs a tile's descent: its nanny starts another, Dask
    # runs the lost task again, and the output is the same bit for bit.
    import distributed
    path, V, F, _, eps = scan
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster, set_as_default=False) as client:
        fair_tiled(path, tmp_path / "kept.ply", eps, client=client, tile_memory=budget(F, 8))
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
        fair_tiled(path, tmp_path / "lost.ply", eps, client=client, tile_memory=budget(F, 8))
        killer.join(timeout=10)
        after = client.run(os.getpid)
    assert killed and before[killed[0]] not in after.values()
    assert (tmp_path / "lost.ply").read_bytes() == (tmp_path / "kept.ply").read_bytes()
