"""The command-line tool and the files a user has: nothing it did not write is deleted or
replaced, a PLY input's properties come out again, soups are repaired when asked, and the
command line reads as users write it."""

import os
import re
import signal
import subprocess
from pathlib import Path

import numpy as np
import pytest

import cgal_constrained_fairing as cf

from conftest import BAD_INPUT, DATA

TOOL = os.environ.get("CONSTRAINED_FAIRING_TOOL")
pytestmark = pytest.mark.skipif(TOOL is None, reason="CONSTRAINED_FAIRING_TOOL names no built tool")
nibabel = pytest.importorskip("nibabel")


def run(*arguments, cwd=None, timeout=300):
    return subprocess.run([TOOL, *map(str, arguments)], capture_output=True, text=True, cwd=cwd,
                          timeout=timeout)


def snapshot(folder: Path):
    """Every file under `folder`, hidden ones too, with its bytes."""
    return {p.relative_to(folder): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def assert_kept(before, folder: Path):
    """Every file of `before` is still under `folder`, byte for byte."""
    after = snapshot(folder)
    for path, content in before.items():
        assert path in after, f"{path} was deleted"
        assert after[path] == content, f"{path} was changed"


def cube_map(path: Path, size=20):
    labels = np.zeros((size, size, size), np.uint8)
    labels[5:11, 5:11, 5:11] = 1
    nibabel.save(nibabel.Nifti1Image(labels, np.eye(4)), str(path))


@pytest.fixture
def user_folder(tmp_path):
    """A user's folder: a label map, notes, and a subfolder with a file."""
    cube_map(tmp_path / "seg.nii.gz")
    (tmp_path / "notes.txt").write_text("my notes\n")
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "keep.txt").write_text("keep\n")
    return tmp_path


def test_label_map_into_the_current_folder_keeps_everything(user_folder):
    before = snapshot(user_folder)
    done = run("seg.nii.gz", ".", cwd=user_folder)
    assert done.returncode == 0, done.stderr
    assert_kept(before, user_folder)
    added = set(snapshot(user_folder)) - set(before)
    assert added == {Path("label_1.ply")}, added


def test_label_map_into_a_folder_with_a_users_file(user_folder):
    results = user_folder / "results"
    results.mkdir()
    (results / "mine.ply").write_text("a user's file\n")
    before = snapshot(user_folder)
    done = run("seg.nii.gz", "results", cwd=user_folder)
    assert done.returncode == 0, done.stderr
    assert_kept(before, user_folder)
    assert (results / "label_1.ply").is_file()


def test_label_map_output_that_is_the_input_or_a_file_is_refused(user_folder):
    before = snapshot(user_folder)
    for out, message in (("seg.nii.gz", "OUT is IN"), ("./seg.nii.gz", "OUT is IN"),
                         ("notes.txt", "is an existing file")):
        done = run("seg.nii.gz", out, cwd=user_folder)
        assert done.returncode != 0 and message in done.stderr, (out, done.stderr)
        assert done.stderr.count("\n") == 1
        assert snapshot(user_folder) == before


def test_an_existing_label_file_is_replaced_only_with_force(user_folder):
    assert run("seg.nii.gz", "out", cwd=user_folder).returncode == 0
    (user_folder / "out" / "mine.txt").write_text("mine\n")
    before = snapshot(user_folder)
    done = run("seg.nii.gz", "out", cwd=user_folder)
    assert done.returncode != 0 and "label_1.ply exists: --force" in done.stderr
    assert snapshot(user_folder) == before
    (user_folder / "out" / "label_1.ply").write_text("stale\n")
    done = run("--force", "seg.nii.gz", "out", cwd=user_folder)
    assert done.returncode == 0, done.stderr
    assert (user_folder / "out" / "mine.txt").read_text() == "mine\n"
    V, F = cf.read_mesh(user_folder / "out" / "label_1.ply")
    assert len(F) > 0
    # A folder where a label's file would go is never replaced.
    (user_folder / "out" / "label_1.ply").unlink()
    (user_folder / "out" / "label_1.ply").mkdir()
    done = run("--force", "seg.nii.gz", "out", cwd=user_folder)
    assert done.returncode != 0 and "is a folder" in done.stderr


def test_an_interrupted_run_leaves_earlier_outputs(tmp_path):
    """Ctrl-C during the fairing of a larger map: the earlier outputs stay as they were, and
    no partial file is left."""
    labels = np.zeros((70, 70, 70), np.uint8)
    grid = np.indices(labels.shape)
    labels[((grid - 35) ** 2).sum(axis=0) < 30 ** 2] = 1
    labels[((grid - 30) ** 2).sum(axis=0) < 12 ** 2] = 2
    nibabel.save(nibabel.Nifti1Image(labels, np.eye(4)), str(tmp_path / "big.nii"))
    out = tmp_path / "out"
    out.mkdir()
    for name in ("label_1.ply", "label_2.ply"):
        (out / name).write_text(f"earlier {name}\n")
    before = snapshot(tmp_path)
    process = subprocess.Popen([TOOL, "--force", "big.nii", "out"], cwd=tmp_path,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    # Interrupted in the fairing: at its first progress line, iteration 100.
    line = process.stderr.readline()
    assert line.startswith("iteration "), line
    process.send_signal(signal.SIGINT)
    process.communicate(timeout=300)
    if process.returncode == 0:
        pytest.skip("the run ended before it was interrupted")
    assert snapshot(tmp_path) == before


def write_scan(path: Path):
    """head.off as an ASCII PLY with colours (uchar), a float confidence and a face property,
    and a header comment."""
    V, F = cf.read_mesh(DATA / "head.off")
    n, m = len(V), len(F)
    with open(path, "w") as stream:
        stream.write(f"ply\nformat ascii 1.0\ncomment scanner 7\nelement vertex {n}\n"
                     "property float x\nproperty float y\nproperty float z\n"
                     "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                     "property uchar alpha\nproperty float confidence\n"
                     f"element face {m}\nproperty list uchar int vertex_indices\n"
                     "property int segment\nend_header\n")
        for i, v in enumerate(V.astype(np.float32)):
            stream.write(f"{v[0]!r} {v[1]!r} {v[2]!r} {i % 256} {3 * i % 256} {7 * i % 256} 200 "
                         f"{np.float32(i / n)!r}\n")
        for j, f in enumerate(F):
            stream.write(f"3 {f[0]} {f[1]} {f[2]} {j % 5}\n")
    return n, m


def test_ply_properties_survive_the_tool(tmp_path):
    n, m = write_scan(tmp_path / "scan.ply")
    done = run(tmp_path / "scan.ply", tmp_path / "out.ply")
    assert done.returncode == 0, done.stderr
    V, F, given = cf.read_mesh(tmp_path / "scan.ply", properties=True)
    W, G, carried = cf.read_mesh(tmp_path / "out.ply", properties=True)
    assert np.array_equal(F, G) and len(W) == n
    assert list(carried.vertex) == ["red", "green", "blue", "alpha", "confidence", "deviation",
                                    "at_bound"]
    for name, values in given.vertex.items():
        assert carried.vertex[name].dtype == values.dtype and np.array_equal(carried.vertex[name], values)
    assert carried.face["segment"].dtype == np.int32
    assert np.array_equal(carried.face["segment"], np.arange(m) % 5)
    moved = np.linalg.norm(W - V, axis=1)
    assert np.array_equal(carried.vertex["deviation"], moved)
    assert "scanner 7" in carried.comments


def test_ply_output_of_an_upper_case_name(tmp_path):
    write_scan(tmp_path / "SCAN.PLY")
    done = run("SCAN.PLY", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "SCAN_faired.PLY (with deviation and at_bound)" in done.stdout
    done = run("SCAN.PLY", "OUT.PLY", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "deviation" in cf.read_mesh(tmp_path / "OUT.PLY", properties=True)[2].vertex


def test_command_line_forms(tmp_path):
    head = tmp_path / "head.off"
    head.write_bytes((DATA / "head.off").read_bytes())
    spaced = run("--eps", "0.01", head, tmp_path / "a.off")
    joined = run("--eps=0.01", head, tmp_path / "b.off")
    assert spaced.returncode == 0 and joined.returncode == 0, joined.stderr
    assert (tmp_path / "a.off").read_bytes() == (tmp_path / "b.off").read_bytes()
    negative = run("--eps", "-0.01", head, tmp_path / "c.off")
    assert negative.returncode != 0 and "must be positive (got '-0.01')" in negative.stderr
    assert not (tmp_path / "c.off").exists()
    # --in-place without OUT replaces IN, and nothing else is written.
    done = run("--in-place", "--eps", "0.01", "head.off", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert head.read_bytes() == (tmp_path / "a.off").read_bytes()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.off", "b.off", "head.off"]


def soup_file(path: Path, V, F):
    with open(path, "w") as stream:
        stream.write(f"OFF\n{len(V)} {len(F)} 0\n")
        for v in V:
            stream.write(f"{v[0]!r} {v[1]!r} {v[2]!r}\n")
        for f in F:
            stream.write(f"{len(f)} {' '.join(map(str, f))}\n")


def defective_soups():
    """A sphere's soup with each defect that --repair mends, and whether the tool refuses it
    without --repair (duplicate points only crack the mesh open)."""
    from conftest import icosphere
    V, F = icosphere(2)
    F = [list(f) for f in F]
    n = len(V)
    turned = [list(f) for f in F]
    turned[3] = turned[3][::-1]
    copies = np.vstack([V, V[:5]])
    cracked = [[v + n if v < 5 and k % 2 else v for v in f] for k, f in enumerate(F)]
    # A second sphere whose vertex 3, the antipode of vertex 0, is moved onto vertex 0 and
    # shares it: the spheres touch at one non-manifold vertex.
    touching = np.vstack([V, V + 2 * V[0]])
    second = [[0 if v == 3 else v + n for v in f] for f in F]
    return {
        "inconsistent_orientation": (V, turned, True),
        "duplicate_points": (copies, cracked, False),
        "duplicate_face": (V, F + [F[7]], True),
        "non_manifold_vertex": (touching, F + second, True),
    }


@pytest.mark.parametrize("defect", sorted(defective_soups()))
def test_repair_makes_a_mesh_of_a_defective_soup(tmp_path, defect):
    V, F, refused_without = defective_soups()[defect]
    soup_file(tmp_path / "soup.off", V, F)
    if refused_without:
        refused = run("--eps", "0.05", tmp_path / "soup.off", tmp_path / "out.off")
        assert refused.returncode != 0 and "--repair" in refused.stderr, refused.stderr
    done = run("--repair", "--eps", "0.05", tmp_path / "soup.off", tmp_path / "out.ply")
    assert done.returncode == 0, done.stderr
    assert "note: repaired:" in done.stdout
    W, G, carried = cf.read_mesh(tmp_path / "out.ply", properties=True)
    # Every point of the result, copies included, within eps of an input point at whose
    # position it started: its deviation, and the distance to the nearest input point.
    assert (carried.vertex["deviation"] <= 0.05).all()
    nearest = np.sqrt(((W[:, None, :] - np.asarray(V)[None, :, :]) ** 2).sum(axis=2)).min(axis=1)
    assert (nearest <= 0.05).all()


def test_repair_keeps_a_bad_index_an_error(tmp_path):
    done = run("--repair", "--eps", "0.1", BAD_INPUT / "face_index_out_of_range.ply", tmp_path / "o.off")
    assert done.returncode != 0 and "refers to vertex" in done.stderr
    assert "--repair" not in done.stderr


def test_a_terminal_sees_the_phases_before_the_iterations(tmp_path):
    """On a terminal the tool shows what it does from the start (reading, checking and
    starting), then the iterations."""
    import pty
    main, side = pty.openpty()
    process = subprocess.Popen([TOOL, DATA / "elephant_noisy.off", tmp_path / "out.off"],
                               stdout=subprocess.PIPE, stderr=side)
    os.close(side)
    shown = b""
    while True:
        try:
            chunk = os.read(main, 4096)
        except OSError:  # the tool closed its end
            break
        if not chunk:
            break
        shown += chunk
    process.communicate(timeout=120)
    os.close(main)
    text = shown.decode()
    assert process.returncode == 0
    phases = [text.find(word) for word in ("reading ", "checking and starting", "fairing: iteration",
                                           "writing ")]
    assert all(at >= 0 for at in phases) and phases == sorted(phases), text


def test_a_log_sees_the_stopping_rules_measure(tmp_path):
    """Off a terminal, every 100 iterations: the iteration, the energy, and the relative decrease
    per iteration over the stopping rule's window against its threshold."""
    done = run(DATA / "elephant_noisy.off", tmp_path / "out.off")
    assert done.returncode == 0, done.stderr
    lines = [line for line in done.stderr.splitlines() if line.startswith("iteration ")]
    assert lines and all(re.search(r", decrease [-0-9.e+]+/it \(threshold 0.000125\), ", line) for line in lines), lines


CGAL_DATA = Path("/usr/share/doc/libcgal-dev/data.tar.gz")  # Debian's libcgal-demo


@pytest.mark.skipif(not CGAL_DATA.is_file(), reason="needs CGAL's demo data (libcgal-demo)")
@pytest.mark.parametrize("name", ["pig.stl", "polygon_mesh.off"])
def test_repair_fairs_cgals_demo_meshes(tmp_path, name):
    """Two of CGAL's demo meshes that are soups with non-manifold vertices: refused with the
    hint, faired with --repair within the bound, and Python's repair gives the tool's mesh."""
    import tarfile
    with tarfile.open(CGAL_DATA) as archive:
        member = archive.getmember(f"data/meshes/{name}")
        (tmp_path / name).write_bytes(archive.extractfile(member).read())
    refused = run(tmp_path / name, tmp_path / "refused.off")
    assert refused.returncode != 0 and "--repair" in refused.stderr
    done = run("--repair", tmp_path / name, tmp_path / "out.ply")
    assert done.returncode == 0, done.stderr
    assert "points duplicated at non-manifold" in done.stdout
    V, F, repaired = cf.read_mesh(tmp_path / name, repair=True)
    assert repaired.repair.startswith("repaired: ")
    W, G, carried = cf.read_mesh(tmp_path / "out.ply", properties=True)
    assert np.array_equal(F, G)
    eps = 0.25 * cf.mean_edge_length(V, F)
    assert (np.linalg.norm(W - V, axis=1) <= eps).all()
    assert np.array_equal(W, cf.fair(V, F, eps)[0])


def test_a_polygons_property_goes_to_each_of_its_triangles(tmp_path):
    """A grid of 3 x 3 quads, each with its own face value: each triangle of the output
    carries its quad's value."""
    n = 4
    points = [(i, j, 0.1 * ((i * 7 + j * 3) % 5)) for j in range(n) for i in range(n)]
    quads = [(j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i)
             for j in range(n - 1) for i in range(n - 1)]
    with open(tmp_path / "quads.ply", "w") as stream:
        stream.write(f"ply\nformat ascii 1.0\nelement vertex {len(points)}\nproperty double x\n"
                     "property double y\nproperty double z\n"
                     f"element face {len(quads)}\nproperty list uchar int vertex_indices\n"
                     "property ushort segment\nend_header\n")
        for p in points:
            stream.write(f"{p[0]} {p[1]} {p[2]}\n")
        for k, q in enumerate(quads):
            stream.write(f"4 {' '.join(map(str, q))} {100 + k}\n")
    done = run(tmp_path / "quads.ply", tmp_path / "out.ply")
    assert done.returncode == 0, done.stderr
    assert "9 faces with more than three vertices were triangulated" in done.stdout
    W, G, carried = cf.read_mesh(tmp_path / "out.ply", properties=True)
    segment = carried.face["segment"]
    assert segment.dtype == np.uint16 and len(segment) == 18
    for triangle, value in zip(G, segment):
        quad = set(quads[value - 100])
        assert set(triangle.tolist()) <= quad, (triangle, quad)
    assert sorted(np.unique(segment, return_counts=True)[1].tolist()) == [2] * 9
