"""OFF and OBJ triangle meshes converted to binary PLY a block of lines at a time.

A mesh too large for one process is converted with the memory of one block: the vertices and
the faces go to files of their own as they are parsed, then follow the PLY header. Only what
the whole-file reader (`read_mesh`, CGAL's) would read alike is taken: OFF's plain vertex and
triangle lines, OBJ's ``v`` and ``f`` lines of three corners; any other content (polygons,
colours, relative indices, ...) is `NotStreamed` and the file is read whole instead.
"""

import shutil
import warnings
from pathlib import Path
from typing import BinaryIO, Iterator, List

import numpy as np

# Lines parsed at a time: about 50 MB of text, and its arrays.
BLOCK_LINES = 1 << 20
LINE_BYTES = 48  # about a vertex's or a face's line


class NotStreamed(Exception):
    """The file holds what only the whole-file reader takes."""


def convert_streamed(in_path: Path, out_path: Path) -> None:
    """`in_path` (``.off`` or ``.obj``) as a binary PLY mesh at `out_path`, a new file, positions
    in double; NotStreamed if it holds more than plain vertices and triangles. The files it
    makes are new (an existing one is an error, never replaced), and it removes only those."""
    suffix = in_path.suffix.lower()
    if suffix not in (".off", ".obj"):
        raise NotStreamed(suffix)
    vertices_path = out_path.with_name(out_path.name + ".vertices")
    faces_path = out_path.with_name(out_path.name + ".faces")
    made = []
    try:
        with open(in_path, "rb") as text, _new(vertices_path, made) as vertices, \
                _new(faces_path, made) as faces:
            parse = _parse_off if suffix == ".off" else _parse_obj
            counts = parse(text, vertices, faces)
        with _new(out_path, made) as out:
            _assemble(out, counts, vertices_path, faces_path)
        made.remove(out_path)
    finally:
        for path in made:
            path.unlink()


def _new(path: Path, made: List[Path]) -> BinaryIO:
    """`path` created for writing (FileExistsError if it exists), noted in `made`."""
    f = open(path, "xb")
    made.append(path)
    return f


def _blocks(text: BinaryIO) -> Iterator[List[bytes]]:
    """The file's lines, a block at a time, each ending with its newline."""
    while True:
        lines = text.readlines(BLOCK_LINES * LINE_BYTES)
        if not lines:
            return
        if not lines[-1].endswith(b"\n"):
            lines[-1] += b"\n"
        yield lines


def _numbers(lines: List[bytes], per_line: int, dtype) -> np.ndarray:
    """The lines' numbers as rows of `per_line`; NotStreamed unless each line holds that many
    numbers and nothing else."""
    data = b"".join(lines)
    if (_words_per_line(data, len(lines)) != per_line).any():
        raise NotStreamed("lines of other lengths")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # numpy warns of text it stops at
        try:
            values = np.fromstring(data.decode("ascii"), dtype=dtype, sep=" ")
        except (DeprecationWarning, ValueError, UnicodeDecodeError) as error:
            raise NotStreamed(str(error)) from None
    if values.size != per_line * len(lines):
        raise NotStreamed("words that are not numbers")
    return values.reshape(-1, per_line)


def _words_per_line(data: bytes, lines: int) -> np.ndarray:
    """The whitespace-separated words of each of the `lines` lines of `data`."""
    b = np.frombuffer(data, np.uint8)
    newline = b == ord("\n")
    space = newline | (b == ord(" ")) | (b == ord("\t")) | (b == ord("\r"))
    starts = ~space & np.concatenate(([True], space[:-1]))
    line = np.cumsum(newline, dtype=np.int32) - newline
    return np.bincount(line[starts], minlength=lines)


def _parse_off(text: BinaryIO, vertices: BinaryIO, faces: BinaryIO):
    words: List[bytes] = []
    for line in text:
        words += line.split(b"#")[0].split()
        if len(words) >= 4:
            break
    if len(words) != 4 or words[0] != b"OFF" or not all(w.isdigit() for w in words[1:]):
        raise NotStreamed("an OFF header of another kind")
    n, m = int(words[1]), int(words[2])
    if 0 in (n, m):
        raise NotStreamed("no vertex or no face")
    rows = [0, 0]
    for lines in _blocks(text):
        lines = [line for line in lines if line.strip()]
        if any(b"#" in line for line in lines):
            raise NotStreamed("comments among the data")
        take = min(len(lines), n - rows[0])
        if take:
            vertices.write(_numbers(lines[:take], 3, np.float64).astype("<f8").tobytes())
            rows[0] += take
        if len(lines) > take:
            corners = _numbers(lines[take:], 4, np.int64)
            if (corners[:, 0] != 3).any():
                raise NotStreamed("faces other than triangles")
            _write_faces(faces, corners[:, 1:], n)
            rows[1] += len(corners)
    if rows != [n, m]:
        raise NotStreamed("counts other than the header's")
    return rows


def _parse_obj(text: BinaryIO, vertices: BinaryIO, faces: BinaryIO):
    # Indices are of the file's vertices in order, wherever a face line lies: the faces are
    # checked against the count at the end.
    rows, largest = [0, 0], -1
    for lines in _blocks(text):
        points, triangles = _obj_records(lines)
        if points:
            vertices.write(_numbers(points, 3, np.float64).astype("<f8").tobytes())
            rows[0] += len(points)
        if triangles:
            if any(b"/" in line for line in triangles):  # v/vt/vn: the vertex alone
                triangles = [b" ".join(w.split(b"/")[0] for w in line.split()) + b"\n"
                             for line in triangles]
            corners = _numbers(triangles, 3, np.int64) - 1
            if (corners < 0).any():
                raise NotStreamed("relative or zero indices")
            largest = max(largest, int(corners.max()))
            faces.write(_face_records(corners).tobytes())
            rows[1] += len(corners)
    if largest >= rows[0] or 0 in rows:
        raise NotStreamed("no vertex, no face or a face beyond the vertices")
    return rows


# The OBJ statements that CGAL's reader passes over, as this one does.
_OBJ_IGNORED = {b"vt", b"vn", b"vp", b"bevel", b"lod", b"ctech", b"c_interp", b"usemap",
                b"usemtl", b"stech", b"d_interp", b"mtllib", b"shadow_obj", b"trace_obj", b"o",
                b"g", b"s"}


def _obj_records(lines: List[bytes]):
    """The words after ``v`` and after ``f`` of each such line; NotStreamed for a statement
    that CGAL's reader would not pass over, or a face line of tabs, which it reads otherwise."""
    points, triangles = [], []
    for line in lines:
        words = line.split(None, 1)
        if not words or words[0].startswith(b"#") or words[0] in _OBJ_IGNORED:
            continue
        rest = words[1] if len(words) > 1 else b"\n"
        if words[0] == b"v":
            points.append(rest)
        elif words[0] == b"f" and b"\t" not in rest:
            triangles.append(rest)
        else:
            raise NotStreamed(f"the OBJ statement {words[0][:20]!r}")
    return points, triangles


_FACE = np.dtype([("count", "u1"), ("corners", "<i4", (3,))])


def _face_records(corners: np.ndarray) -> np.ndarray:
    if corners.size and corners.max() > np.iinfo(np.int32).max:
        raise NotStreamed("indices beyond a PLY int")
    records = np.zeros(len(corners), _FACE)
    records["count"] = 3
    records["corners"] = corners
    return records


def _write_faces(faces: BinaryIO, corners: np.ndarray, n: int) -> None:
    if corners.size and (corners.min() < 0 or corners.max() >= n):
        raise NotStreamed("a face refers to a vertex that does not exist")
    faces.write(_face_records(corners).tobytes())


def _assemble(out: BinaryIO, counts, vertices_path: Path, faces_path: Path) -> None:
    header = (b"ply\nformat binary_little_endian 1.0\n"
              + f"element vertex {counts[0]}\n".encode()
              + b"property double x\nproperty double y\nproperty double z\n"
              + f"element face {counts[1]}\n".encode()
              + b"property list uchar int vertex_indices\nend_header\n")
    out.write(header)
    for part in (vertices_path, faces_path):
        with open(part, "rb") as source:
            shutil.copyfileobj(source, out, BLOCK_LINES * LINE_BYTES)
