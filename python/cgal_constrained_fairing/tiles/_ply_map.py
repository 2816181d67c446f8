"""A binary PLY triangle mesh read and written through memory maps, a block at a time.

The vertex and face elements are numpy record arrays over the file itself, so that a mesh
larger than memory is read in place; the output keeps the input's header, properties and face
block byte for byte, with the positions in double (the bound holds in double) and the
``deviation`` and ``at_bound`` columns of the library's other front ends.
"""

import dataclasses
import os
from pathlib import Path
from typing import List, Tuple

import numpy as np

from .._errors import Defect, InputError

_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2",
          "int16": "i2", "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4",
          "uint": "u4", "uint32": "u4", "float": "f4", "float32": "f4", "double": "f8",
          "float64": "f8"}

# The rows read or written at a time, so that no step holds more than a block (a block of faces
# with its corners' points is about 100 bytes a row).
BLOCK_ROWS = 1 << 18


@dataclasses.dataclass
class Element:
    """One element of the header: its name, count, record dtype and header lines."""

    name: str
    count: int
    dtype: np.dtype
    lines: List[bytes]


@dataclasses.dataclass
class PlyMap:
    """A binary PLY file's header and its vertex and face records, mapped."""

    path: Path
    header_end: int
    format_line: bytes
    comments: List[bytes]
    vertex: Element
    face: Element

    @property
    def byte_order(self) -> str:
        return "<" if b"little" in self.format_line else ">"

    def vertices(self) -> np.ndarray:
        return np.memmap(self.path, dtype=self.vertex.dtype, mode="r", offset=self.header_end,
                         shape=(self.vertex.count,))

    def faces(self) -> np.ndarray:
        """The faces' records; field ``"corners"`` holds each triangle's three indices."""
        offset = self.header_end + self.vertex.count * self.vertex.dtype.itemsize
        return np.memmap(self.path, dtype=self.face.dtype, mode="r", offset=offset,
                         shape=(self.face.count,))

    @property
    def face_block(self) -> Tuple[int, int]:
        """Where the face records lie in the file: offset and length in bytes."""
        offset = self.header_end + self.vertex.count * self.vertex.dtype.itemsize
        return offset, self.face.count * self.face.dtype.itemsize


def is_binary_ply(path: Path) -> bool:
    with open(path, "rb") as f:
        head = f.read(64)
    return head.startswith(b"ply") and b"format binary_" in head


def map_ply(path: Path) -> PlyMap:
    """The binary PLY file `path` mapped, or ValueError naming what it holds that is not a
    mesh of vertices and faces."""
    with open(path, "rb") as f:
        lines = []
        while True:
            line = f.readline()
            if not line:
                raise _defect(path, "its header has no end_header line")
            lines.append(line)
            if line.strip() == b"end_header":
                break
        header_end = f.tell()
    format_line = next((ln for ln in lines if ln.startswith(b"format ")), b"")
    if b"binary_little_endian" not in format_line and b"binary_big_endian" not in format_line:
        raise _defect(path, "it is not a binary PLY file")
    order = "<" if b"little" in format_line else ">"
    elements = _elements(path, lines, order)
    names = [e.name for e in elements]
    if names != ["vertex", "face"]:
        raise _defect(path, f"it holds the elements {names}, not vertex then face")
    mapped = PlyMap(path, header_end, format_line,
                    [ln for ln in lines if ln.startswith(b"comment")], *elements)
    size = header_end + sum(e.count * e.dtype.itemsize for e in elements)
    if os.path.getsize(path) < size:
        raise _defect(path, "the file is shorter than its header says")
    return mapped


def _elements(path: Path, lines: List[bytes], order: str) -> List[Element]:
    elements: List[Element] = []
    for line in lines:
        words = line.split()
        if words[:1] == [b"element"]:
            elements.append(Element(words[1].decode(), int(words[2]), None, [line]))
            fields = []
        elif words[:1] == [b"property"] and elements:
            elements[-1].lines.append(line)
            fields.extend(_fields(path, elements[-1].name, words, order))
            elements[-1].dtype = np.dtype(fields)
    for e in elements:
        if e.dtype is None:
            raise _defect(path, f"its element {e.name} has no property")
    vertex_fields = elements[0].dtype.names if elements else ()
    if not {"x", "y", "z"} <= set(vertex_fields or ()):
        raise _defect(path, "its vertices have no x, y and z")
    if len(elements) > 1 and "corners" not in elements[1].dtype.names:
        raise _defect(path, "its faces have no vertex_indices list")
    return elements


def _fields(path: Path, element: str, words: List[bytes], order: str):
    if words[1] != b"list":
        return [(words[2].decode(), order + _TYPES[words[1].decode()])]
    if element != "face" or words[4] not in (b"vertex_indices", b"vertex_index"):
        raise _defect(path, f"its {element} element has a list property {words[4].decode()}")
    # A triangle mesh's lists all have three entries; checked when the faces are read.
    return [("count", order + _TYPES[words[2].decode()]),
            ("corners", order + _TYPES[words[3].decode()], (3,))]


def check_triangles(mapped: PlyMap) -> None:
    faces = mapped.faces()
    for begin in range(0, len(faces), BLOCK_ROWS):
        counts = faces["count"][begin:begin + BLOCK_ROWS]
        bad = np.flatnonzero(counts != 3)
        if bad.size:
            raise InputError(Defect.NOT_TRIANGLE,
                             f"{mapped.path}: face {begin + bad[0]} has {counts[bad[0]]} corners; "
                             "tiles need a triangle mesh")


def output_vertex_dtype(mapped: PlyMap) -> np.dtype:
    """The output's vertex records: the input's, positions in double, then ``deviation``
    (double) and ``at_bound`` (uchar) unless the input has them."""
    order = mapped.byte_order
    fields = []
    for name in mapped.vertex.dtype.names:
        kind = mapped.vertex.dtype.fields[name][0]
        fields.append((name, order + "f8") if name in ("x", "y", "z") else (name, kind))
    names = mapped.vertex.dtype.names
    if "deviation" not in names:
        fields.append(("deviation", order + "f8"))
    if "at_bound" not in names:
        fields.append(("at_bound", "u1"))
    return np.dtype(fields)


def write_ply(mapped: PlyMap, out_path: Path, points, deviation, at_bound) -> None:
    """The input `mapped` with its vertices' positions, ``deviation`` and ``at_bound`` from the
    arrays (row per vertex, read a block at a time) and its face block copied byte for byte."""
    dtype = output_vertex_dtype(mapped)
    with open(out_path, "wb") as out:
        out.write(_output_header(mapped, dtype))
        source = mapped.vertices()
        for begin in range(0, mapped.vertex.count, BLOCK_ROWS):
            end = min(begin + BLOCK_ROWS, mapped.vertex.count)
            block = np.zeros(end - begin, dtype)
            for name in mapped.vertex.dtype.names:
                block[name] = source[name][begin:end]
            for axis, name in enumerate("xyz"):
                block[name] = points[begin:end, axis]
            block["deviation"] = deviation[begin:end]
            block["at_bound"] = at_bound[begin:end]
            out.write(block.tobytes())
        offset, length = mapped.face_block
        with open(mapped.path, "rb") as source_file:
            source_file.seek(offset)
            _copy_bytes(source_file, out, length)


def _output_header(mapped: PlyMap, dtype: np.dtype) -> bytes:
    lines = [b"ply\n", mapped.format_line, *mapped.comments, mapped.vertex.lines[0]]
    names = dtype.names
    for line in mapped.vertex.lines[1:]:
        name = line.split()[-1].decode()
        lines.append(b"property double " + name.encode() + b"\n" if name in "xyz" else line)
    if "deviation" not in mapped.vertex.dtype.names and "deviation" in names:
        lines.append(b"property double deviation\n")
    if "at_bound" not in mapped.vertex.dtype.names and "at_bound" in names:
        lines.append(b"property uchar at_bound\n")
    lines.extend(mapped.face.lines)
    lines.append(b"end_header\n")
    return b"".join(lines)


def _copy_bytes(source, target, length: int) -> None:
    remaining = length
    while remaining > 0:
        chunk = source.read(min(remaining, 1 << 24))
        if not chunk:
            raise OSError(f"{source.name} ended early")
        target.write(chunk)
        remaining -= len(chunk)


def convert_to_ply(read_mesh, in_path: Path, out_path: Path) -> None:
    """A mesh file of another format written once as binary PLY, its PLY properties kept."""
    V, F, properties = read_mesh(in_path, properties=True)
    vertex = [("x", "<f8"), ("y", "<f8"), ("z", "<f8")]
    vertex += [(name, values.dtype.newbyteorder("<")) for name, values in properties.vertex.items()]
    records = np.zeros(len(V), np.dtype(vertex))
    for axis, name in enumerate("xyz"):
        records[name] = V[:, axis]
    for name, values in properties.vertex.items():
        records[name] = values
    faces = np.zeros(len(F), np.dtype([("count", "u1"), ("corners", "<i4", (3,))]))
    faces["count"] = 3
    faces["corners"] = F
    header = [b"ply\n", b"format binary_little_endian 1.0\n", f"element vertex {len(V)}\n".encode()]
    header += [f"property {_ply_name(records.dtype.fields[n][0])} {n}\n".encode()
               for n in records.dtype.names]
    header += [f"element face {len(F)}\n".encode(), b"property list uchar int vertex_indices\n",
               b"end_header\n"]
    with open(out_path, "wb") as out:
        out.write(b"".join(header))
        out.write(records.tobytes())
        out.write(faces.tobytes())


def _ply_name(dtype: np.dtype) -> str:
    code = dtype.newbyteorder("=").str[1:]
    return next(name for name, c in _TYPES.items() if c == code)


def _defect(path: Path, what: str) -> ValueError:
    return ValueError(f"{path}: cannot be read as a mesh in tiles: {what}")
