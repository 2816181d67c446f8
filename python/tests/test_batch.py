"""The batch of mesh files on a Dask cluster: `fair_files` and its command line."""

import csv
import multiprocessing
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import cgal_constrained_fairing as cf

distributed = pytest.importorskip("distributed")

# Raised by the Tornado that Debian's distributed 2022.12 runs on, not by the package.
pytestmark = pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")

from cgal_constrained_fairing.batch import COLUMNS, fair_files  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
DATA = Path(os.environ.get("CONSTRAINED_FAIRING_DATA_DIR", ROOT / "data"))
BAD_INPUT = ROOT / "test" / "bad_input"

GOOD = ("head.off", "elephant_noisy.off", "elephant.off")
DONE = ("converged", "iteration_limit_reached")


def copy_inputs(folder, good=GOOD, bad=True):
    """Copy bundled meshes into `folder`, and with `bad` a non-manifold mesh and a file that is
    no mesh at all; the paths in order, the bad ones last."""
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for name in good:
        paths.append(folder / name)
        shutil.copyfile(DATA / name, paths[-1])
    if bad:
        paths.append(folder / "non_manifold_edge.off")
        shutil.copyfile(BAD_INPUT / "non_manifold_edge.off", paths[-1])
        paths.append(folder / "notes.off")
        paths[-1].write_text("shopping list\n- milk\n- 3 eggs\n")
    return paths


def read_report(out_dir):
    """The header and the rows of out_dir/report.csv, as text."""
    with open(out_dir / "report.csv", newline="") as stream:
        reader = csv.reader(stream)
        header = next(reader)
        return header, [dict(zip(header, cells)) for cells in reader]


def expected_epsilon(eps, V, F):
    """The epsilon that `fair_files` should use, computed as the brief of `eps` says."""
    if eps == "auto":
        return cf.estimate_noise_level(V, F)
    if isinstance(eps, str) and eps.endswith("h"):
        return float(eps[:-1]) * cf.mean_edge_length(V, F)
    return float(eps)


def check_outputs(rows, paths, out_dir, eps, **fair_options):
    """Each good input's output is what `fair` gives here, bit for bit, and its row says so."""
    for row, path in zip(rows, paths):
        V, F = cf.read_mesh(path)
        epsilon = expected_epsilon(eps, V, F)
        W, report = cf.fair(V, F, epsilon, **fair_options)
        assert row["path"] == str(path)
        assert row["status"] == report.status.value.lower()
        assert row["status"] in DONE
        assert row["error"] is None
        assert row["epsilon"] == epsilon
        assert (row["vertices"], row["faces"]) == (len(V), len(F))
        assert row["iterations"] == report.number_of_iterations
        assert row["initial_bending_energy"] == report.initial_bending_energy
        assert row["final_bending_energy"] == report.final_bending_energy
        assert row["initial_energy"] == report.initial_energy
        assert row["final_energy"] == report.final_energy
        assert row["max_deviation"] == report.max_deviation <= epsilon
        assert row["output"] == str(out_dir / path.name)
        W2, F2 = cf.read_mesh(row["output"])
        assert np.array_equal(W2, W)
        assert np.array_equal(F2, F)
        assert (np.linalg.norm(W2 - V, axis=1) <= epsilon).all()


def no_partial_files(out_dir):
    return not [p.name for p in out_dir.iterdir() if ".partial" in p.name]


def child_processes():
    return {p.pid for p in multiprocessing.active_children()}


def test_local_cluster_started_and_closed(tmp_path):
    # Before the module's cluster exists, so that the two do not share the cores.
    paths = copy_inputs(tmp_path / "in", good=GOOD[:2], bad=False)
    before = child_processes()
    rows = fair_files(paths, tmp_path / "out", workers=2, progress=False)
    assert child_processes() <= before, "the batch's worker processes are still running"
    check_outputs(rows, paths, tmp_path / "out", "0.25h")
    assert all(row["worker"].startswith("tcp://") for row in rows)
    assert all(row["seconds"] > 0 for row in rows)


@pytest.fixture(scope="module")
def first_run(client, tmp_path_factory):
    """A batch of three good meshes and two bad files: its inputs, output folder and rows."""
    folder = tmp_path_factory.mktemp("batch")
    paths = copy_inputs(folder / "in")
    rows = fair_files(paths, folder / "out", client, progress=False)
    return paths, folder / "out", rows


def test_outputs_are_those_of_fair(first_run):
    paths, out_dir, rows = first_run
    check_outputs(rows[:len(GOOD)], paths[:len(GOOD)], out_dir, "0.25h")


def test_bad_files_have_error_rows_and_no_output(first_run):
    paths, out_dir, rows = first_run
    non_manifold, not_a_mesh = rows[len(GOOD):]
    for row in (non_manifold, not_a_mesh):
        assert row["status"] == "error"
        assert row["output"] is None
        assert not (out_dir / Path(row["path"]).name).exists()
    assert non_manifold["error"].startswith("NON_MANIFOLD_EDGE: ")
    with pytest.raises(cf.InputError) as error:
        cf.fair(*cf.read_mesh(paths[-2]), 1.0)
    assert non_manifold["error"] == f"NON_MANIFOLD_EDGE: {error.value.message}"
    assert (non_manifold["vertices"], non_manifold["faces"]) == tuple(
        len(A) for A in cf.read_mesh(paths[-2]))
    assert not_a_mesh["error"].startswith("ValueError: ")
    assert not_a_mesh["vertices"] is None
    assert no_partial_files(out_dir)


def test_unreadable_files_are_error_rows(client, tmp_path, capsys):
    folder = tmp_path / "in"
    folder.mkdir()
    garbage = folder / "garbage.ply"
    garbage.write_bytes(np.random.default_rng(7).integers(0, 256, 4000, np.uint8).tobytes())
    empty = folder / BAD_INPUT.joinpath("not_a_mesh.stl").name
    shutil.copyfile(BAD_INPUT / "not_a_mesh.stl", empty)
    paths = [folder / "missing.off", garbage, empty]
    rows = fair_files(paths, tmp_path / "out", client, progress=True)
    assert [row["status"] for row in rows] == ["error"] * 3
    assert rows[0]["error"].startswith("FileNotFoundError: ")
    assert rows[1]["error"].startswith("ValueError: ")
    with pytest.raises(cf.InputError) as error:
        cf.mean_edge_length(*cf.read_mesh(empty))
    assert rows[2]["error"] == f"{error.value.defect.value}: {error.value.message}"
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["report.csv"]
    assert "fairing files" in capsys.readouterr().err


def test_report_file(first_run, client):
    paths, out_dir, rows = first_run
    header, table = read_report(out_dir)
    assert tuple(header) == COLUMNS
    assert [row["path"] for row in table] == [str(p) for p in paths]
    assert len(rows) == len(paths)
    workers = set(client.scheduler_info()["workers"])
    for row, cells in zip(rows, table):
        assert set(row) == set(COLUMNS)
        assert row["worker"] in workers
        for column in COLUMNS:
            value = row[column]
            # Floats at full precision: they read back exactly.
            if isinstance(value, float):
                assert float(cells[column]) == value
            else:
                assert cells[column] == ("" if value is None else str(value))


def test_rerun_skips_done_files_and_retries_failed_ones(client, tmp_path):
    paths = copy_inputs(tmp_path / "in", good=GOOD[:2])
    out_dir = tmp_path / "out"
    first = fair_files(paths, out_dir, client, progress=False)
    outputs = [out_dir / p.name for p in paths[:2]]
    old = 1_000_000_000
    for output in outputs:
        os.utime(output, (old, old))
    # The file that was no mesh is one now: a retry succeeds.
    shutil.copyfile(DATA / GOOD[0], paths[-1])

    second = fair_files(paths, out_dir, client, progress=False)
    assert [os.stat(o).st_mtime for o in outputs] == [old, old]
    assert second[:2] == first[:2]
    assert second[2]["status"] == "error"
    assert second[2]["error"] == first[2]["error"]
    assert second[3]["status"] in DONE
    check_outputs(second[3:], paths[3:], out_dir, "0.25h")
    _, table = read_report(out_dir)
    assert [row["status"] for row in table] == [row["status"] for row in second]

    # Without the report, an output is not known to be the batch's: it is not replaced.
    os.remove(out_dir / "report.csv")
    third = fair_files(paths, out_dir, client, progress=False)
    assert [row["status"] for row in third] == ["error"] * 4
    for row, path in zip(third[:2] + third[3:], paths[:2] + paths[3:]):
        assert row["error"].startswith("FileExistsError: ") and "force" in row["error"]
    assert third[2]["error"] == first[2]["error"]
    assert [os.stat(o).st_mtime for o in outputs] == [old, old]

    forced = fair_files(paths, out_dir, client, force=True, progress=False)
    assert all(os.stat(o).st_mtime != old for o in outputs)
    check_outputs(forced[:2] + forced[3:], paths[:2] + paths[3:], out_dir, "0.25h")
    assert forced[2]["status"] == "error"
    assert no_partial_files(out_dir)


@pytest.mark.parametrize("eps", ["auto", 0.02, "0.02", "0.25h"],
                         ids=["auto", "number", "numeric string", "0.25h"])
def test_eps(client, tmp_path, eps):
    paths = copy_inputs(tmp_path / "in", good=GOOD[:2], bad=False)
    rows = fair_files(paths, tmp_path / "out", client, eps=eps, progress=False)
    check_outputs(rows, paths, tmp_path / "out", eps)


def test_auto_eps_of_a_tiny_mesh_is_an_error(client, tmp_path):
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])
    F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    assert cf.estimate_noise_level(V, F) <= 0
    (tmp_path / "in").mkdir()
    path = tmp_path / "in" / "tetrahedron.ply"
    cf.write_mesh(path, V, F)
    [row] = fair_files([path], tmp_path / "out", client, eps="auto", progress=False)
    assert row["status"] == "error"
    assert "noise level" in row["error"] and "give eps" in row["error"]
    assert not (tmp_path / "out" / path.name).exists()


def test_fair_options_reach_fair(client, tmp_path):
    paths = copy_inputs(tmp_path / "in", good=GOOD[1:2], bad=False)
    options = dict(objective="accurate", max_iterations=3)
    rows = fair_files(paths, tmp_path / "out", client, progress=False, **options)
    check_outputs(rows, paths, tmp_path / "out", "0.25h", **options)
    assert rows[0]["status"] == "iteration_limit_reached"


def test_refusals_before_anything_is_written(tmp_path):
    paths = copy_inputs(tmp_path / "in", good=GOOD[:1], bad=False)
    other = tmp_path / "other"
    other.mkdir()
    shutil.copyfile(paths[0], other / paths[0].name)
    out_dir = tmp_path / "out"
    # No client is given: a cluster started by mistake would only slow the test down.
    with pytest.raises(ValueError, match="file name"):
        fair_files([paths[0], other / paths[0].name], out_dir, progress=False)
    with pytest.raises(ValueError, match="overwrite"):
        fair_files(paths, tmp_path / "in", progress=False)
    with pytest.raises(ValueError, match="eps"):
        fair_files(paths, out_dir, eps="a quarter", progress=False)
    with pytest.raises(ValueError, match="eps"):
        fair_files(paths, out_dir, eps=-1.0, progress=False)
    with pytest.raises(TypeError, match="epsilon"):
        fair_files(paths, out_dir, epsilon=1.0, progress=False)
    assert not out_dir.exists()
    assert sorted(p.name for p in (tmp_path / "in").iterdir()) == [paths[0].name]


def run_cli(*args):
    package_parent = str(Path(cf.__file__).resolve().parents[1])
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [package_parent] + [p for p in [env.get("PYTHONPATH")] if p])
    return subprocess.run([sys.executable, "-m", "cgal_constrained_fairing.batch", *args],
                          env=env, capture_output=True, text=True, timeout=120)


def test_command_line(client, tmp_path):
    paths = copy_inputs(tmp_path / "in", good=GOOD[:2])
    out_dir = tmp_path / "out"
    scheduler = client.scheduler.address
    good = [str(p) for p in paths[:2]]

    done = run_cli(*good, "-o", str(out_dir), "--scheduler", scheduler, "--eps", "0.3h")
    assert done.returncode == 0, done.stderr
    assert f"2 faired, 0 skipped, 0 failed; report: {out_dir / 'report.csv'}" in done.stdout
    header, table = read_report(out_dir)
    assert tuple(header) == COLUMNS
    assert [row["path"] for row in table] == good
    workers = set(client.scheduler_info()["workers"])
    for row, path in zip(table, paths):
        V, F = cf.read_mesh(path)
        assert float(row["epsilon"]) == 0.3 * cf.mean_edge_length(V, F)
        assert row["worker"] in workers
        W, _ = cf.fair(V, F, float(row["epsilon"]))
        assert np.array_equal(cf.read_mesh(out_dir / path.name)[0], W)

    failed = run_cli(*map(str, paths), "-o", str(out_dir), "--scheduler", scheduler,
                     "--eps", "0.3h")
    assert failed.returncode == 1, failed.stderr
    assert "0 faired, 2 skipped, 2 failed" in failed.stdout
    assert "NON_MANIFOLD_EDGE" in failed.stderr and str(paths[-1]) in failed.stderr
    _, table = read_report(out_dir)
    assert [row["status"] for row in table][2:] == ["error", "error"]
    assert no_partial_files(out_dir)

    both = run_cli(*good, "-o", str(tmp_path / "elsewhere"), "--workers", "1",
                   "--scheduler", scheduler)
    assert both.returncode == 2
    assert not (tmp_path / "elsewhere").exists()


def test_command_line_feature_angle(client, tmp_path):
    paths = copy_inputs(tmp_path / "in", good=GOOD[:1], bad=False)
    out_dir = tmp_path / "out"
    done = run_cli(str(paths[0]), "-o", str(out_dir), "--scheduler", client.scheduler.address,
                   "--feature-angle", "30")
    assert done.returncode == 0, done.stderr
    V, F = cf.read_mesh(paths[0])
    W, _ = cf.fair(V, F, 0.25 * cf.mean_edge_length(V, F), feature_angle=30)
    assert np.array_equal(cf.read_mesh(out_dir / paths[0].name)[0], W)


def test_threads_limit_the_library_in_each_worker(client, tmp_path):
    paths = copy_inputs(tmp_path / "in", good=GOOD[:2], bad=False)
    rows = fair_files(paths, tmp_path / "out", client, threads=1, progress=False)
    check_outputs(rows, paths, tmp_path / "out", "0.25h")
    workers = {row["worker"] for row in rows}
    limits = client.run(cf.max_threads, workers=list(workers))
    assert set(limits.values()) == {1} or not cf._core.with_tbb
    # Without `threads`, a client's cluster is not limited again.
    fair_files(paths, tmp_path / "out", client, force=True, progress=False)
    limits = client.run(cf.max_threads, workers=list(workers))
    assert all(limit == os.cpu_count() for limit in limits.values()) or not cf._core.with_tbb
    with pytest.raises(ValueError, match="threads"):
        fair_files(paths, tmp_path / "out2", client, threads=0)


def snapshot(folder):
    """Every file under `folder` with its bytes."""
    return {p.relative_to(folder): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def test_force_never_replaces_an_input(client, tmp_path):
    """A label map's output folder that holds the map itself: the run adds its label files,
    with or without --force, and the map and the user's files stay as they were."""
    nibabel = pytest.importorskip("nibabel")
    seg = tmp_path / "seg"
    seg.mkdir()
    labels = np.zeros((16, 16, 16), np.uint8)
    labels[4:10, 4:10, 4:10] = 1
    nibabel.save(nibabel.Nifti1Image(labels, np.eye(4)), str(seg / "seg.nii.gz"))
    (seg / "notes.txt").write_text("mine\n")
    before = snapshot(tmp_path)
    scheduler = client.scheduler.address
    done = run_cli(str(seg / "seg.nii.gz"), "-o", str(tmp_path), "--scheduler", scheduler)
    assert done.returncode == 0, done.stderr
    assert "1 faired" in done.stdout
    after = snapshot(tmp_path)
    assert all(after[path] == content for path, content in before.items())
    assert set(after) - set(before) == {Path("seg/label_1.ply"), Path("report.csv")}
    forced = run_cli(str(seg / "seg.nii.gz"), "-o", str(tmp_path), "--scheduler", scheduler,
                     "--force")
    assert forced.returncode == 0, forced.stderr
    again = snapshot(tmp_path)
    assert all(again[path] == content for path, content in before.items())


def test_an_output_the_batch_did_not_write_is_not_replaced(client, tmp_path):
    paths = copy_inputs(tmp_path / "in", good=GOOD[:1], bad=False)
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    (out_dir / GOOD[0]).write_text("a user's file\n")
    [row] = fair_files(paths, out_dir, client, progress=False)
    assert row["status"] == "error" and row["error"].startswith("FileExistsError: ")
    assert (out_dir / GOOD[0]).read_text() == "a user's file\n"
    [row] = fair_files(paths, out_dir, client, force=True, progress=False)
    check_outputs([row], paths, out_dir, "0.25h")


def test_rerun_with_other_options_fairs_again(client, tmp_path):
    paths = copy_inputs(tmp_path / "in", good=GOOD[:2], bad=False)
    out_dir = tmp_path / "out"
    first = fair_files(paths, out_dir, client, eps="auto", progress=False)
    check_outputs(first, paths, out_dir, "auto")
    same = fair_files(paths, out_dir, client, eps="auto", progress=False)
    assert same == first
    other = fair_files(paths, out_dir, client, eps="0.5h", progress=False)
    check_outputs(other, paths, out_dir, "0.5h")
    assert [row["options"] for row in other] != [row["options"] for row in first]
    # A rerun on a subset keeps the other files' rows.
    subset = fair_files(paths[:1], out_dir, client, eps="0.3h", progress=False)
    check_outputs(subset, paths[:1], out_dir, "0.3h")
    _, table = read_report(out_dir)
    assert sorted(row["path"] for row in table) == sorted(str(p) for p in paths)
    kept = next(row for row in table if row["path"] == str(paths[1]))
    assert float(kept["epsilon"]) == other[1]["epsilon"]


def test_a_failed_rerun_leaves_the_earlier_output(client, tmp_path):
    paths = copy_inputs(tmp_path / "in", good=GOOD[:1], bad=False)
    out_dir = tmp_path / "out"
    fair_files(paths, out_dir, client, progress=False)
    before = (out_dir / GOOD[0]).read_bytes()
    paths[0].write_text("no longer a mesh\n")
    [row] = fair_files(paths, out_dir, client, eps="0.3h", progress=False)
    assert row["status"] == "error"
    assert (out_dir / GOOD[0]).read_bytes() == before
    assert no_partial_files(out_dir)


def test_ply_properties_survive_the_batch(client, tmp_path):
    V, F = cf.read_mesh(DATA / "head.off")
    properties = cf.MeshProperties(
        vertex={"red": (np.arange(len(V)) % 256).astype(np.uint8),
                "confidence": np.linspace(0, 1, len(V), dtype=np.float32)},
        face={"segment": (np.arange(len(F)) % 3).astype(np.int32)}, comments="scanner 7\n")
    (tmp_path / "in").mkdir()
    path = tmp_path / "in" / "scan.ply"
    cf.write_mesh(path, V, F, properties=properties)
    [row] = fair_files([path], tmp_path / "out", client, progress=False)
    W, G, carried = cf.read_mesh(tmp_path / "out" / "scan.ply", properties=True)
    assert list(carried.vertex) == ["red", "confidence", "deviation", "at_bound"]
    for name, values in properties.vertex.items():
        assert carried.vertex[name].dtype == values.dtype
        assert np.array_equal(carried.vertex[name], values)
    assert np.array_equal(carried.face["segment"], properties.face["segment"])
    assert np.array_equal(G, F)
    assert np.array_equal(carried.vertex["deviation"], np.linalg.norm(W - V, axis=1))
    assert (carried.vertex["deviation"] <= row["epsilon"]).all()
    assert carried.comments == "scanner 7\n"


def descendants(pid):
    """The process ids below `pid`, from /proc."""
    children = {}
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue
        children.setdefault(int(fields[1]), []).append(int(entry.name))
    found, stack = [], [pid]
    while stack:
        for child in children.get(stack.pop(), []):
            found.append(child)
            stack.append(child)
    return found


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="needs /proc to see the workers")
def test_ctrl_c_is_one_line(tmp_path):
    """Ctrl-C on a terminal reaches the whole process group, the workers too: the batch says
    one line, and no worker a traceback."""
    import signal
    import time
    paths = copy_inputs(tmp_path / "in", good=("bunny00.off", "elephant_noisy.off"), bad=False)
    package_parent = str(Path(cf.__file__).resolve().parents[1])
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [package_parent] + [p for p in [os.environ.get("PYTHONPATH")] if p]))
    process = subprocess.Popen(
        [sys.executable, "-m", "cgal_constrained_fairing.batch", *map(str, paths), "-o",
         str(tmp_path / "out"), "--workers", "1", "--accurate"],
        env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        start_new_session=True)
    deadline = time.monotonic() + 60
    while len(descendants(process.pid)) < 2 and time.monotonic() < deadline:
        time.sleep(0.05)  # the nanny and its worker
    time.sleep(0.5)
    os.killpg(process.pid, signal.SIGINT)
    out, err = process.communicate(timeout=120)
    if process.returncode == 0:
        pytest.skip("the batch ended before it was interrupted")
    assert process.returncode == 130, err
    assert err.splitlines() == [f"interrupted; report: {tmp_path / 'out' / 'report.csv'}"], err


def test_a_ply_soup_that_is_no_mesh_is_named_as_an_off_one(client, tmp_path):
    """A PLY input is read with its properties, and its defect is the library's name for it,
    as for any other format."""
    V, F = cf.read_mesh(BAD_INPUT / "non_manifold_edge.off")
    (tmp_path / "in").mkdir()
    path = tmp_path / "in" / "non_manifold_edge.ply"
    cf.write_mesh(path, V, F)
    with pytest.raises(cf.InputError) as error:
        cf.read_mesh(path, properties=True)
    assert error.value.defect == cf.Defect.NON_MANIFOLD_EDGE
    assert "repair=True" in error.value.message
    [row] = fair_files([path], tmp_path / "out", client, progress=False)
    assert row["status"] == "error" and row["error"].startswith("NON_MANIFOLD_EDGE: ")


@pytest.mark.skipif(not os.environ.get("CONSTRAINED_FAIRING_TOOL"), reason="needs the built tool")
def test_point_sets_in_a_batch_are_the_tools(client, tmp_path):
    """A face-less PLY with properties and an .xyz beside a mesh: each point set's output is the
    command-line tool's, byte for byte; an eps in h is an error row for a point set only."""
    rng = np.random.default_rng(4)
    d = rng.normal(size=(1500, 3))
    d /= np.linalg.norm(d, axis=1)[:, None]
    P = d + 0.01 * rng.normal(size=d.shape)
    (tmp_path / "in").mkdir()
    ply, xyz = tmp_path / "in" / "scan.ply", tmp_path / "in" / "dots.xyz"
    cf.write_points(ply, P, d, properties=cf.MeshProperties(
        vertex={"red": (np.arange(len(P)) % 256).astype(np.uint8)}, comments="scanner 7\n"))
    cf.write_points(xyz, P)
    [mesh] = copy_inputs(tmp_path / "in", good=GOOD[1:2], bad=False)
    inputs = {p: p.read_bytes() for p in (ply, xyz, mesh)}
    rows = fair_files([ply, xyz, mesh], tmp_path / "out", client, eps="auto", progress=False,
                      objective="accurate")
    assert [row["status"] in DONE for row in rows] == [True, True, True]
    assert all(p.read_bytes() == data for p, data in inputs.items())
    assert no_partial_files(tmp_path / "out")
    assert rows[0]["epsilon"] == cf.estimate_noise_level(P)
    tool = os.environ["CONSTRAINED_FAIRING_TOOL"]
    for path in (ply, xyz):
        made = tmp_path / ("tool" + path.suffix)
        subprocess.run([tool, "--eps", "auto", "--accurate", path, made], check=True,
                       capture_output=True)
        assert made.read_bytes() == (tmp_path / "out" / path.name).read_bytes()
    rows = fair_files([xyz, mesh], tmp_path / "out_h", client, eps="0.25h", progress=False)
    assert rows[0]["status"] == "error" and "no edges for h" in rows[0]["error"]
    assert rows[1]["status"] in DONE
    rows = fair_files([xyz], tmp_path / "out_k", client, eps=0.03, progress=False, neighbors=16,
                      region=None)
    assert rows[0]["status"] == "error" and "point sets do not take: region" in rows[0]["error"]
