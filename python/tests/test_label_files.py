"""Label map files: `read_label_map`, `label_surfaces` with an affine, and the batch on them."""

import gzip
import os
import subprocess
import sys
import tarfile
from pathlib import Path

import numpy as np
import pytest

import cgal_constrained_fairing as cf

nibabel = pytest.importorskip("nibabel")


def two_labels(shape=(14, 12, 10)):
    """A box of label 3 with a slab of label 7 on its top; int16, as segmentations often are."""
    labels = np.zeros(shape, np.int16)
    labels[3:11, 3:9, 2:8] = 3
    labels[3:11, 3:9, 6:8] = 7
    return labels


# Voxel axes rotated by 30 degrees about z, mirrored in x, spacings 0.8, 0.8, 2.5 and an origin.
ANGLE = np.radians(30)
ROTATION = np.array([[np.cos(ANGLE), -np.sin(ANGLE), 0],
                     [np.sin(ANGLE), np.cos(ANGLE), 0],
                     [0, 0, 1]])
AFFINE = np.eye(4)
AFFINE[:3, :3] = ROTATION @ np.diag([-1, 1, 1]) @ np.diag([0.8, 0.8, 2.5])
AFFINE[:3, 3] = [10, -20, 5]


def save_nifti(path, labels, affine):
    image = nibabel.Nifti1Image(labels, affine, dtype=labels.dtype)
    image.set_sform(affine, code=1)
    image.set_qform(affine, code=1)
    nibabel.save(image, str(path))


# The affine of an INR file's voxel sizes and origin, which float32 (NIfTI's) holds exactly.
INR_SIZES = (0.5, 0.75, 2.5)
INR_ORIGIN = (10.0, -20.0, 5.25)
INR_AFFINE = np.diag([*INR_SIZES, 1.0])
INR_AFFINE[:3, 3] = INR_ORIGIN


def save_inr(path, labels, sizes=INR_SIZES, origin=INR_ORIGIN, big_endian=False, fields=()):
    """An INRIMAGE-4 file as CGAL's ImageIO writes it: the header padded to 256 bytes, the
    voxels x fastest; gzip-compressed for a .gz name. `fields` replace or add header lines."""
    kind = {"u": "unsigned fixed", "i": "signed fixed", "f": "float"}[labels.dtype.kind]
    header = {"XDIM": labels.shape[0], "YDIM": labels.shape[1], "ZDIM": labels.shape[2],
              "VDIM": 1, "TYPE": kind, "PIXSIZE": f"{8 * labels.dtype.itemsize} bits",
              "SCALE": "2**0", "CPU": "sun" if big_endian else "decm",
              "VX": sizes[0], "VY": sizes[1], "VZ": sizes[2],
              "TX": origin[0], "TY": origin[1], "TZ": origin[2]}
    header.update(fields)
    text = "#INRIMAGE-4#{\n" + "".join(f"{key}={value}\n" for key, value in header.items())
    text += "\n" * ((252 - len(text)) % 256) + "##}\n"
    order = ">" if big_endian else "<"
    data = text.encode() + labels.astype(labels.dtype.newbyteorder(order)).tobytes(order="F")
    with (gzip.open if str(path).endswith(".gz") else open)(path, "wb") as file:
        file.write(data)


def triangles_of(V, F):
    """The mesh as an (m, 3, 3) array of its triangles' corners, whatever its numbering: each
    triangle started at its smallest corner (orientation kept), the triangles sorted; the order
    is taken on the corners rounded to 1e-9, so that the last bits do not change it."""
    corners = V[F]
    key = lambda p: tuple(np.round(p, 9))  # noqa: E731
    turned = [np.roll(t, -min(range(3), key=lambda c: key(t[c])), axis=0) for t in corners]
    return np.array(sorted(turned, key=lambda t: tuple(np.round(t.ravel(), 9))))


def volume(V, F):
    a, b, c = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    return np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6


def is_closed(F):
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    return bool((counts % 2 == 0).all())


@pytest.mark.parametrize("name", ["map.nii", "map.nii.gz", "map.npy"])
def test_read_label_map(tmp_path, name):
    labels = two_labels()
    path = tmp_path / name
    if name.endswith(".npy"):
        np.save(path, labels)
        affine = np.eye(4)
    else:
        save_nifti(path, labels, AFFINE)
        affine = AFFINE
    read, read_affine = cf.read_label_map(path)
    assert read.dtype.kind in "iu" and np.array_equal(read, labels)
    assert np.allclose(read_affine, affine, atol=1e-6)


def test_read_label_map_takes_whole_floats_and_refuses_the_rest(tmp_path):
    labels = two_labels().astype(np.float32)
    save_nifti(tmp_path / "float.nii.gz", labels, np.eye(4))
    read, _ = cf.read_label_map(tmp_path / "float.nii.gz")
    assert read.dtype.kind == "i" and np.array_equal(read, labels)
    labels[5, 5, 5] = 0.5
    save_nifti(tmp_path / "fraction.nii.gz", labels, np.eye(4))
    with pytest.raises(ValueError, match="whole numbers"):
        cf.read_label_map(tmp_path / "fraction.nii.gz")
    np.save(tmp_path / "flat.npy", np.zeros((4, 4), np.uint8))
    with pytest.raises(ValueError, match="3-D"):
        cf.read_label_map(tmp_path / "flat.npy")
    (tmp_path / "broken.nii.gz").write_bytes(b"not gzip at all")
    with pytest.raises(ValueError, match="not a valid NIfTI file"):
        cf.read_label_map(tmp_path / "broken.nii.gz")
    (tmp_path / "labels.txt").write_text("1 2 3")
    with pytest.raises(ValueError, match="label map must be"):
        cf.read_label_map(tmp_path / "labels.txt")
    with pytest.raises(FileNotFoundError):
        cf.read_label_map(tmp_path / "missing.nii")


@pytest.mark.parametrize("name, dtype, big_endian", [
    ("map.inr", np.uint8, False), ("map.inr.gz", np.int16, True), ("MAP.INR", np.uint32, True),
    ("map.inr.gz", np.int64, False), ("map.inr", np.float32, True), ("map.inr", np.float64, False),
])
def test_read_label_map_inr_as_nifti(tmp_path, name, dtype, big_endian):
    """An INR file and the NIfTI file of the same map, voxel sizes and origin: the same labels and
    affine, so the same surfaces, bit for bit."""
    labels = two_labels().astype(dtype)
    save_inr(tmp_path / name, labels, big_endian=big_endian)
    save_nifti(tmp_path / "map.nii.gz", labels, INR_AFFINE)
    read, affine = cf.read_label_map(tmp_path / name)
    nifti, nifti_affine = cf.read_label_map(tmp_path / "map.nii.gz")
    assert read.dtype == np.int64 and read.shape == labels.shape
    assert np.array_equal(read, labels) and np.array_equal(read, nifti)
    assert np.array_equal(affine, INR_AFFINE) and np.array_equal(affine, nifti_affine)
    ours, theirs = cf.label_surfaces(read, affine=affine), cf.label_surfaces(nifti, affine=nifti_affine)
    for field in ("vertices", "faces", "face_labels", "box_half_extents", "labels"):
        assert np.array_equal(getattr(ours, field), getattr(theirs, field)), field


@pytest.mark.parametrize("name, fields, message", [
    ("vector.inr", {"VDIM": 3}, "VDIM=3: a label map has one value per voxel"),
    ("type.inr", {"TYPE": "complex"}, "unknown TYPE=complex"),
    ("bits.inr.gz", {"PIXSIZE": "12 bits"}, "PIXSIZE=12 bits: not a type of voxels"),
    ("cpu.inr", {"CPU": "vax"}, "unknown CPU=vax"),
    ("size.inr", {"VY": "-1"}, "VY=-1 is not a positive voxel size"),
    ("truncated.inr", {"ZDIM": 20}, "truncated (14 x 12 x 20 voxels announced)"),
])
def test_read_label_map_refuses_bad_inr(tmp_path, name, fields, message):
    save_inr(tmp_path / name, two_labels(), fields=fields)
    with pytest.raises(ValueError) as error:
        cf.read_label_map(tmp_path / name)
    assert str(error.value).startswith(f"{tmp_path / name}: ") and message in str(error.value)


def test_read_label_map_names_the_inr_voxel_that_is_no_label(tmp_path):
    voxels = two_labels().astype(np.float32)
    voxels[4, 5, 6] = 2.5
    save_inr(tmp_path / "fraction.inr", voxels)
    with pytest.raises(ValueError, match=r"voxel \(4, 5, 6\) is not a whole number"):
        cf.read_label_map(tmp_path / "fraction.inr")


def test_label_surfaces_in_world_coordinates():
    labels = two_labels()
    spacing = np.linalg.norm(AFFINE[:3, :3], axis=0)
    local = cf.label_surfaces(labels, spacing=spacing)
    world = cf.label_surfaces(labels, affine=AFFINE)
    axes = AFFINE[:3, :3] / spacing
    # The same fairing, moved into the world; the mirror turns the faces.
    assert np.allclose(world.vertices, local.vertices @ axes.T + AFFINE[:3, 3], rtol=0, atol=1e-12)
    assert np.array_equal(world.faces, local.faces[:, [0, 2, 1]])
    assert np.array_equal(world.face_labels, local.face_labels)
    # Each point in its box: back in voxel units, within its half-extents of its net point.
    inverse = np.linalg.inv(AFFINE)
    to_voxels = lambda P: P @ inverse[:3, :3].T + inverse[:3, 3]  # noqa: E731
    moved = to_voxels(world.vertices) - to_voxels(world.unfaired_vertices)
    assert (np.abs(moved) <= world.box_half_extents / spacing + 1e-9).all()
    for label in (3, 7):
        V, F = world.surface(label)
        assert is_closed(F) and volume(V, F) > 0
    # A rigid move keeps the volumes.
    for label in (3, 7):
        before = volume(*local.surface(label))
        assert abs(volume(*world.surface(label)) - before) < 1e-9 * before


@pytest.mark.parametrize("affine, message", [
    (np.zeros((4, 4)), "independent"),
    (np.full((4, 4), np.nan), "finite"),
    (np.eye(3), "affine"),
])
def test_bad_affines(affine, message):
    with pytest.raises(cf.InputError, match=message) as error:
        cf.label_surfaces(two_labels(), affine=affine)
    assert error.value.defect == cf.Defect.INVALID_ARGUMENT
    with pytest.raises(cf.InputError, match="either affine"):
        cf.label_surfaces(two_labels(), spacing=(1, 1, 2), affine=np.eye(4))


TOOL = os.environ.get("CONSTRAINED_FAIRING_TOOL")


@pytest.mark.skipif(TOOL is None, reason="CONSTRAINED_FAIRING_TOOL names no built tool")
@pytest.mark.parametrize("name, header", [
    ("sform.nii.gz", "sform"), ("qform.nii", "qform"), ("sizes.nii.gz", "none"),
    ("big_endian.nii", "big endian"), ("float_labels.nii.gz", "float"),
])
def test_tool_reads_label_maps_as_python_does(tmp_path, name, header):
    """The tool's NIfTI-1 reader (zlib) against nibabel's: the same labels and affine, so the
    same surfaces, bit for bit."""
    labels = two_labels()
    affine = AFFINE
    if header == "float":
        labels = labels.astype(np.float32)
    image = nibabel.Nifti1Image(labels, affine)
    image.set_sform(affine, code=1 if header != "qform" and header != "none" else 0)
    image.set_qform(affine, code=1 if header == "qform" else 0)
    if header == "none":
        image.header.set_zooms((0.8, 0.8, 2.5))
    if header == "big endian":
        image = nibabel.Nifti1Image(labels.astype(">i2"), affine,
                                    header=image.header.as_byteswapped(">"))
        image.set_sform(affine, code=1)
    nibabel.save(image, str(tmp_path / name))
    out = tmp_path / "out"
    done = subprocess.run([TOOL, "--label-format", "off", str(tmp_path / name), str(out)],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert "2 labels" in done.stdout
    read, read_affine = cf.read_label_map(tmp_path / name)
    expected = cf.label_surfaces(read, affine=read_affine)
    for label in (3, 7):
        V, F = cf.read_mesh(out / f"label_{label}.off")
        W, G = expected.surface(label)
        # The same triangles, numbered in another order where the affine mirrors (the tool
        # turns each label's mesh, Python the soup it is made from), and the same points but
        # for the rounding of the move into the world.
        assert np.allclose(triangles_of(V, F), triangles_of(W, G), rtol=0, atol=1e-12)
        assert is_closed(F) and volume(V, F) > 0


@pytest.mark.skipif(TOOL is None, reason="CONSTRAINED_FAIRING_TOOL names no built tool")
def test_tool_rejects_bad_label_maps(tmp_path):
    (tmp_path / "broken.nii.gz").write_bytes(b"\x1f\x8b broken")
    (tmp_path / "short.nii").write_bytes(b"\0" * 100)
    nibabel.save(nibabel.Nifti1Image(np.zeros((4, 4, 4), np.uint8), np.eye(4)),
                 str(tmp_path / "empty.nii"))
    full = nibabel.Nifti1Image(two_labels(), np.eye(4))
    nibabel.save(full, str(tmp_path / "full.nii"))
    (tmp_path / "truncated.nii").write_bytes((tmp_path / "full.nii").read_bytes()[:900])
    for name, message in (("broken.nii.gz", "not a NIfTI-1 file"), ("short.nii", "not a NIfTI-1 file"),
                          ("empty.nii", "nothing but the background"), ("truncated.nii", "truncated"),
                          ("missing.nii", "cannot open")):
        out = tmp_path / f"out_{name}"
        done = subprocess.run([TOOL, str(tmp_path / name), str(out)], capture_output=True, text=True,
                              timeout=60)
        assert done.returncode != 0 and message in done.stderr, (name, done.stderr)
        assert not out.exists()
    done = subprocess.run([TOOL, "--eps", "0.5", str(tmp_path / "full.nii")], capture_output=True,
                          text=True, timeout=60, cwd=tmp_path)
    assert done.returncode != 0 and "only --accurate" in done.stderr


@pytest.mark.skipif(TOOL is None, reason="CONSTRAINED_FAIRING_TOOL names no built tool")
def test_tool_reads_inr_and_npy_as_nifti(tmp_path):
    """The tool on an .inr.gz and on a .npy: the same surface files, byte for byte, as on the
    NIfTI file of the same map and affine; the same surfaces as Python's; outputs named after
    the map (seg.inr.gz -> seg_surfaces)."""
    labels = two_labels()
    save_inr(tmp_path / "seg.inr.gz", labels, big_endian=True)
    save_nifti(tmp_path / "seg.nii", labels, INR_AFFINE)
    np.save(tmp_path / "grains.npy", np.asfortranarray(labels.astype(np.uint16)))
    save_nifti(tmp_path / "grains.nii", labels, np.eye(4))
    outputs = {}
    for name in ("seg.inr.gz", "seg.nii", "grains.npy", "grains.nii"):
        run = tmp_path / name.replace(".", "_")
        run.mkdir()
        done = subprocess.run([TOOL, "--label-format", "off", str(tmp_path / name)], capture_output=True,
                              text=True, timeout=300, cwd=run)
        assert done.returncode == 0, done.stderr
        stem = name.split(".")[0]
        assert os.listdir(run) == [f"{stem}_surfaces"]
        outputs[name] = {f: (run / f"{stem}_surfaces" / f).read_bytes() for f in ("label_3.off", "label_7.off")}
    assert outputs["seg.inr.gz"] == outputs["seg.nii"]
    assert outputs["grains.npy"] == outputs["grains.nii"]
    for name, affine in (("seg.inr.gz", INR_AFFINE), ("grains.npy", np.eye(4))):
        read, read_affine = cf.read_label_map(tmp_path / name)
        assert np.array_equal(read_affine, affine)
        expected = cf.label_surfaces(read, affine=read_affine)
        for label in (3, 7):
            V, F = cf.read_mesh(tmp_path / name.replace(".", "_") / f"{name.split('.')[0]}_surfaces"
                                / f"label_{label}.off")
            W, G = expected.surface(label)
            assert np.allclose(triangles_of(V, F), triangles_of(W, G), rtol=0, atol=1e-12)


@pytest.mark.skipif(TOOL is None, reason="CONSTRAINED_FAIRING_TOOL names no built tool")
def test_tool_rejects_bad_inr_and_npy(tmp_path):
    save_inr(tmp_path / "vector.inr", two_labels(), fields={"VDIM": 2})
    (tmp_path / "magic.inr.gz").write_bytes(gzip.compress(b"#INRIMAGE-5#{\n##}\n"))
    np.save(tmp_path / "complex.npy", two_labels().astype(np.complex64))
    (tmp_path / "short.npy").write_bytes((b"\x93NUMPY\x01\x00" + b"\x76\x00" + b"{'descr'"))
    for name, message in (("vector.inr", "VDIM=2: a label map has one value per voxel"),
                          ("magic.inr.gz", "not an INRIMAGE-4 file"),
                          ("complex.npy", "dtype '<c8' is not a label map's"),
                          ("short.npy", "truncated header")):
        out = tmp_path / f"out_{name}"
        done = subprocess.run([TOOL, str(tmp_path / name), str(out)], capture_output=True, text=True,
                              timeout=60)
        assert done.returncode != 0, name
        assert done.stderr.startswith(f"error: {tmp_path / name}: ") and message in done.stderr, done.stderr
        assert done.stderr.count("\n") == 1
        assert not out.exists()


CGAL_DATA = Path("/usr/share/doc/libcgal-dev/data.tar.gz")
LIVER = Path("/tmp/cgaldata/data/images/liver.inr.gz")


@pytest.mark.skipif(not LIVER.exists() and not CGAL_DATA.exists(),
                    reason="no CGAL data (libcgal-dev's data.tar.gz)")
def test_cgal_liver_as_nifti(tmp_path):
    """CGAL's liver: its four labels and voxel sizes; the NIfTI file of the same map and voxel
    sizes gives the same labels, and the affine but for NIfTI's float32."""
    liver = LIVER
    if not liver.exists():
        with tarfile.open(CGAL_DATA) as data:
            (tmp_path / "liver.inr.gz").write_bytes(
                data.extractfile("data/images/liver.inr.gz").read())
        liver = tmp_path / "liver.inr.gz"
    labels, affine = cf.read_label_map(liver)
    assert labels.shape == (438, 353, 165)
    assert np.unique(labels).tolist() == [0, 84, 85, 127, 255]
    assert np.array_equal(affine, np.diag([0.617188, 0.617188, 1.33333, 1.0]))
    image = nibabel.Nifti1Image(labels.astype(np.uint8), None)
    image.header.set_zooms((0.617188, 0.617188, 1.33333))
    nibabel.save(image, str(tmp_path / "liver.nii.gz"))
    nifti, nifti_affine = cf.read_label_map(tmp_path / "liver.nii.gz")
    assert np.array_equal(nifti, labels)
    assert np.allclose(nifti_affine, affine, rtol=1e-7, atol=0)


distributed = pytest.importorskip("distributed")


@pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")
def test_batch_writes_one_surface_per_label_in_world_coordinates(tmp_path):
    from cgal_constrained_fairing.batch import fair_files
    inputs = tmp_path / "in"
    inputs.mkdir()
    labels = two_labels()
    save_nifti(inputs / "scan.nii.gz", labels, AFFINE)
    np.save(inputs / "grains.npy", labels.astype(np.uint32))
    (inputs / "broken.nii").write_bytes(b"\0" * 400)
    out = tmp_path / "out"
    rows = fair_files([inputs / "scan.nii.gz", inputs / "grains.npy", inputs / "broken.nii"], out,
                      workers=2, label_format="off")
    assert [row["status"] for row in rows[:2]] == ["converged", "converged"]
    assert rows[2]["status"] == "error" and "broken.nii" in rows[2]["error"]
    assert not (out / "broken").exists()
    for row, name, path in ((rows[0], "scan", "scan.nii.gz"), (rows[1], "grains", "grains.npy")):
        assert row["labels"] == 2 and row["output"] == str(out / name) and row["epsilon"] is None
        # NIfTI-1 stores the affine in float32: the one read back is the map's.
        read, affine = cf.read_label_map(inputs / path)
        expected = cf.label_surfaces(read, affine=affine)
        assert row["vertices"] == len(expected.vertices) and row["faces"] == len(expected.faces)
        assert sorted(os.listdir(out / name)) == ["label_3.off", "label_7.off"]
        for label in (3, 7):
            V, F = cf.read_mesh(out / name / f"label_{label}.off")
            W, G = expected.surface(label)
            assert np.array_equal(V, W) and np.array_equal(F, G)
            assert is_closed(F) and volume(V, F) > 0
    # Run again: the maps done are skipped (their rows kept as they were), the broken one is
    # tried again.
    written = os.stat(out / "scan" / "label_3.off").st_mtime_ns
    again = fair_files([inputs / "scan.nii.gz", inputs / "grains.npy", inputs / "broken.nii"], out,
                       workers=1, label_format="off")
    assert again[:2] == rows[:2] and again[2]["status"] == "error"
    assert os.stat(out / "scan" / "label_3.off").st_mtime_ns == written


def test_batch_refuses_what_label_maps_do_not_take(tmp_path):
    from cgal_constrained_fairing.batch import fair_files
    np.save(tmp_path / "a.npy", two_labels())
    with pytest.raises(ValueError, match="label maps do not take: fidelity_weight"):
        fair_files([tmp_path / "a.npy"], tmp_path / "out", fidelity_weight=10.0)
    save_nifti(tmp_path / "a.nii", two_labels(), np.eye(4))
    with pytest.raises(ValueError, match="output file name 'a'"):
        fair_files([tmp_path / "a.npy", tmp_path / "a.nii"], tmp_path / "out")
    with pytest.raises(ValueError, match="label_format"):
        fair_files([tmp_path / "a.npy"], tmp_path / "out", label_format="vtk")
    assert not (tmp_path / "out").exists()


@pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")
def test_batch_command_line_on_a_label_map(tmp_path):
    save_nifti(tmp_path / "seg.nii.gz", two_labels(), AFFINE)
    done = subprocess.run([sys.executable, "-m", "cgal_constrained_fairing.batch",
                           str(tmp_path / "seg.nii.gz"), "-o", str(tmp_path / "out"),
                           "--workers", "1"],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert "1 faired, 0 skipped, 0 failed" in done.stdout
    assert sorted(os.listdir(tmp_path / "out" / "seg")) == ["label_3.ply", "label_7.ply"]
    assert Path(tmp_path / "out" / "report.csv").read_text().splitlines()[0].endswith(",labels,options")


ATLAS = Path("/usr/share/mricron/templates/HarvardOxford-cort-maxprob-thr0-1mm.nii.gz")


@pytest.mark.skipif(TOOL is None, reason="CONSTRAINED_FAIRING_TOOL names no built tool")
@pytest.mark.skipif(not ATLAS.exists(), reason="no Harvard-Oxford atlas (Debian's mricron-data)")
def test_tool_and_python_agree_on_an_atlas(tmp_path):
    """A real segmentation, the block of 40^3 voxels of the Harvard-Oxford cortical atlas with the
    most labels (corners on a grid of 20): the same surfaces from the tool and from Python, each
    closed, outward and a manifold as the nets make it, no two points at one position."""
    labels, affine = cf.read_label_map(ATLAS)
    n = 40
    corners = [(a, b, c) for a in range(0, labels.shape[0] - n + 1, n // 2)
               for b in range(0, labels.shape[1] - n + 1, n // 2)
               for c in range(0, labels.shape[2] - n + 1, n // 2)]
    held = [len(np.unique(labels[a:a + n, b:b + n, c:c + n])) for a, b, c in corners]
    a, b, c = corners[int(np.argmax(held))]
    block = np.ascontiguousarray(labels[a:a + n, b:b + n, c:c + n])
    moved = affine.copy()
    moved[:3, 3] = affine[:3, :3] @ (a, b, c) + affine[:3, 3]
    save_nifti(tmp_path / "block.nii.gz", block, moved)
    out = tmp_path / "out"
    done = subprocess.run([TOOL, "--label-format", "off", str(tmp_path / "block.nii.gz"), str(out)],
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    expected = cf.label_surfaces(block, affine=moved)
    assert len(expected.labels) >= 10
    assert len(np.unique(expected.vertices, axis=0)) == len(expected.vertices)
    for label in expected.labels:
        W, G = expected.surface(label)
        assert len(np.unique(W, axis=0)) == len(W), "a point split: not a manifold as made"
        assert is_closed(G) and volume(W, G) > 0
        V, F = cf.read_mesh(out / f"label_{label}.off")
        assert np.allclose(triangles_of(V, F), triangles_of(W, G), rtol=0, atol=1e-12)


@pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")
def test_batch_on_an_inr_file(tmp_path):
    from cgal_constrained_fairing.batch import fair_files
    save_inr(tmp_path / "cgal.inr.gz", two_labels().astype(np.uint8))
    rows = fair_files([tmp_path / "cgal.inr.gz"], tmp_path / "out", workers=1, label_format="off")
    assert rows[0]["status"] == "converged" and rows[0]["output"] == str(tmp_path / "out" / "cgal")
    labels, affine = cf.read_label_map(tmp_path / "cgal.inr.gz")
    assert np.array_equal(affine, INR_AFFINE)
    expected = cf.label_surfaces(labels, affine=affine)
    for label in (3, 7):
        V, F = cf.read_mesh(tmp_path / "out" / "cgal" / f"label_{label}.off")
        W, G = expected.surface(label)
        assert np.array_equal(V, W) and np.array_equal(F, G)

