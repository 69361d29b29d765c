"""Read triangle meshes from PLY, OBJ, STL, legacy VTK and VTP files, without VTK.

Only numpy and the standard library are used, so the scanline renderer can load a scene
with no VTK installed.  Every reader returns a :class:`lab.mesh.Mesh`:

- polygons are fan-triangulated by :func:`lab.mesh.fan_triangulate`; polygons with fewer
  than 3 vertices are skipped;
- triangle strips are split with alternating winding, as VTK's ``vtkTriangleStrip``:
  strip ``v0 v1 v2 v3 v4`` gives ``(0, 1, 2), (2, 1, 3), (2, 3, 4)``;
- polygon triangles come before strip triangles (VTK's cell order);
- point normals are scaled to unit length (zero normals stay zero).

Supported
---------
PLY (:func:`read_ply`)
    ``ascii``, ``binary_little_endian`` and ``binary_big_endian``.  ``element vertex``
    with x, y, z of any numeric type and optional nx, ny, nz; ``element face`` with the
    list ``vertex_indices`` (or ``vertex_index``).  Other elements and properties, list
    or scalar, are skipped.
OBJ (:func:`read_obj`)
    ``v``, ``vn`` and ``f`` (``i``, ``i/t``, ``i//n``, ``i/t/n``, negative indices).  Points
    are the ``v`` rows as given.  Point normals only if every face corner has a normal and
    each point is always paired with the same one (points of no face get zero normals).
    Other statements (``vt``, ``o``, ``g``, ``s``, ``usemtl``, ``mtllib``, ``l``) are ignored.
STL (:func:`read_stl`)
    ascii and binary.  Exactly equal vertices are merged (first-occurrence order), so a
    closed STL gives a closed mesh.  No point normals (facet normals are not those).
Legacy VTK (:func:`read_vtk_legacy`)
    ``DATASET POLYDATA``, ASCII or BINARY (big-endian); POINTS; POLYGONS and
    TRIANGLE_STRIPS in the classic layout (counts inline) and the 5.1 layout (OFFSETS and
    CONNECTIVITY); POINT_DATA NORMALS.  Other sections and attributes are skipped.
VTP (:func:`read_vtp`)
    VTK XML PolyData: ascii, binary (base64 with UInt32 or UInt64 headers, optionally
    ``vtkZLibDataCompressor``) and appended data (raw or base64), either byte order, one
    or more pieces; Points, Polys, Strips, and point normals (``PointData Normals="..."``
    or a 3-component array named ``Normals``).

Not supported: colours, texture coordinates, vertices and lines (ignored); other VTK
datasets; other VTP compressors (LZ4, LZMA); OBJ materials and groups (ignored).

Any problem raises :class:`MeshFileError`, whose one-line message starts with the path.
"""
from __future__ import annotations

import base64
import contextlib
import re
import struct
import xml.etree.ElementTree as ET
import zlib
from pathlib import Path

import numpy as np

from lab.mesh import Mesh, fan_triangulate

__all__ = ["MeshFileError", "read_mesh", "read_ply", "read_obj", "read_stl", "read_vtk_legacy", "read_vtp"]


class MeshFileError(ValueError):
    """A mesh file that cannot be read; the message is ``"<path>: <what is wrong>"``."""


def read_mesh(path) -> Mesh:
    """Read a mesh file, choosing the reader by the suffix (any case).

    Parameters
    ----------
    path : str or os.PathLike, a ``.ply``, ``.obj``, ``.stl``, ``.vtk`` or ``.vtp`` file.

    Returns
    -------
    Mesh

    Raises
    ------
    MeshFileError
        Unknown suffix, missing or unreadable file, or anything wrong in it.
    """
    readers = {".ply": read_ply, ".obj": read_obj, ".stl": read_stl, ".vtk": read_vtk_legacy, ".vtp": read_vtp}
    suffix = Path(path).suffix.lower()
    if suffix not in readers:
        raise MeshFileError(f"{path}: unknown mesh file suffix {suffix!r} (known: {', '.join(readers)})")
    return readers[suffix](path)


# ---------------------------------------------------------------------------------------
# Shared helpers


@contextlib.contextmanager
def _reading(path):
    """Yield the bytes of ``path``; turn any error inside the block into MeshFileError."""
    try:
        yield Path(path).read_bytes()
    except MeshFileError:
        raise
    except OSError as exc:
        raise MeshFileError(f"{path}: cannot read file: {exc.strerror or exc}") from None
    except ET.ParseError as exc:
        raise MeshFileError(f"{path}: not valid XML: {exc}") from None
    except (ValueError, IndexError, KeyError, TypeError, struct.error, zlib.error, OverflowError) as exc:
        message = " ".join(str(exc).split()) or type(exc).__name__
        raise MeshFileError(f"{path}: {message}") from None


def _mesh(points, triangles, normals=None) -> Mesh:
    """Check points, triangles and normals, make normals unit length, build the Mesh."""
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    triangles = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    if not np.isfinite(points).all():
        raise ValueError("point coordinates contain NaN or infinity")
    if len(triangles) == 0:
        raise ValueError("no triangles")
    if triangles.min() < 0 or triangles.max() >= len(points):
        bad = triangles[(triangles < 0) | (triangles >= len(points))][0]
        raise ValueError(f"point index {bad} out of range (there are {len(points)} points)")
    if normals is not None:
        normals = np.asarray(normals, dtype=np.float64).reshape(-1, 3)
        if len(normals) != len(points):
            raise ValueError(f"{len(normals)} normals for {len(points)} points")
        if not np.isfinite(normals).all():
            raise ValueError("normals contain NaN or infinity")
        length = np.linalg.norm(normals, axis=1, keepdims=True)
        normals = np.divide(normals, length, out=np.zeros_like(normals), where=length > 0)
    return Mesh(points, triangles, normals)


def _split_counted(flat, n_cells):
    """Cells stored as ``[k, i1..ik, k, ...]`` -> (offsets, connectivity)."""
    flat = np.asarray(flat).astype(np.int64)
    starts = np.empty(n_cells, dtype=np.int64)
    pos = 0
    for cell in range(n_cells):
        if pos >= len(flat):
            raise ValueError(f"cell list ends after {cell} of {n_cells} cells")
        if flat[pos] < 0:
            raise ValueError(f"negative cell size {flat[pos]}")
        starts[cell] = pos
        pos += 1 + int(flat[pos])
    if pos != len(flat):
        raise ValueError(f"cell sizes add up to {pos} values, not {len(flat)}")
    keep = np.ones(len(flat), dtype=bool)
    keep[starts] = False
    return np.concatenate([[0], np.cumsum(flat[starts])]), flat[keep]


def _cells(offsets, connectivity):
    """Index arrays of cells given by offsets (from 0) into connectivity."""
    offsets = np.asarray(offsets).astype(np.int64)
    connectivity = np.asarray(connectivity).astype(np.int64)
    if len(offsets) and (offsets[0] != 0 or (np.diff(offsets) < 0).any() or offsets[-1] > len(connectivity)):
        raise ValueError("cell offsets are not increasing from 0 within the connectivity")
    return [connectivity[a:b] for a, b in zip(offsets[:-1], offsets[1:])]


def _polygon_triangles(offsets, connectivity) -> np.ndarray:
    """Fan triangles of polygons (see :func:`_cells`); fewer than 3 vertices are skipped."""
    sizes = np.diff(offsets)
    if len(sizes) and (sizes == 3).all() and offsets[0] == 0 and offsets[-1] <= len(connectivity):
        return np.asarray(connectivity[: offsets[-1]], dtype=np.int64).reshape(-1, 3)  # all triangles
    return fan_triangulate(_cells(offsets, connectivity))


def _strip_triangles(offsets, connectivity) -> np.ndarray:
    """Triangles of strips, every second one flipped to keep the winding, as VTK does."""
    tris = []
    for s in _cells(offsets, connectivity):
        for i in range(len(s) - 2):
            tris.append((s[i], s[i + 1], s[i + 2]) if i % 2 == 0 else (s[i + 1], s[i], s[i + 2]))
    return np.array(tris, dtype=np.int64).reshape(-1, 3)


# ---------------------------------------------------------------------------------------
# PLY

_PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
              "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
              "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}


def _ply_type(name):
    if name not in _PLY_TYPES:
        raise ValueError(f"unknown PLY property type {name!r}")
    return np.dtype(_PLY_TYPES[name])


def _ply_ascii_element(tokens, pos, count, props):
    """Read one element from ASCII tokens: ({name: values}, next position).

    Scalar properties give one value per record; list properties give the counted form
    ``[k, v1..vk, k, ...]``.
    """
    if all(ctype is None for _, ctype, _ in props):
        n = count * len(props)
        if pos + n > len(tokens):
            raise ValueError("file ends inside the PLY data")
        table = np.array(tokens[pos:pos + n]).astype(np.float64).reshape(count, len(props))
        return {name: table[:, i] for i, (name, _, _) in enumerate(props)}, pos + n
    columns = {name: [] for name, _, _ in props}
    for _ in range(count):
        for name, ctype, _ in props:
            n = 1 if ctype is None else 1 + int(tokens[pos]) if pos < len(tokens) else 1
            columns[name].extend(tokens[pos:pos + n])
            pos += n
    if pos > len(tokens):
        raise ValueError("file ends inside the PLY data")
    return {name: np.array(v).astype(np.float64) for name, v in columns.items()}, pos


def _ply_binary_element(buf, pos, count, props, order):
    """Read one element from binary data: ({name: values}, next position), as above."""
    # Fast path: if every record has the list lengths of the first one, records are fixed size.
    layout, p = [], pos
    for name, ctype, vtype in props:
        if ctype is None:
            layout.append((name, vtype.newbyteorder(order)))
            p += vtype.itemsize
        else:
            k = int(np.frombuffer(buf, ctype.newbyteorder(order), 1, p)[0]) if count else 0
            layout += [(name + "#", ctype.newbyteorder(order)), (name, vtype.newbyteorder(order), (k,))]
            p += ctype.itemsize + k * vtype.itemsize
    record = np.dtype(layout)
    if pos + count * record.itemsize <= len(buf):
        rec = np.frombuffer(buf, record, count, pos)
        lists = [name for name, ctype, _ in props if ctype is not None]
        if all((rec[name + "#"] == rec[name + "#"][:1]).all() for name in lists):
            out = {name: rec[name] for name, ctype, _ in props if ctype is None}
            out.update({name: np.column_stack([rec[name + "#"], rec[name]]).ravel() for name in lists})
            return out, pos + count * record.itemsize
    # Slow path: record by record.
    columns = {name: [] for name, _, _ in props}
    for _ in range(count):
        for name, ctype, vtype in props:
            k = 1
            if ctype is not None:
                k = int(np.frombuffer(buf, ctype.newbyteorder(order), 1, pos)[0])
                columns[name].append(np.array([k]))
                pos += ctype.itemsize
            columns[name].append(np.frombuffer(buf, vtype.newbyteorder(order), k, pos))
            pos += k * vtype.itemsize
    return {name: np.concatenate(v) if v else np.zeros(0) for name, v in columns.items()}, pos


def read_ply(path) -> Mesh:
    """Read a PLY file (ascii or binary, either byte order).

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    Mesh
        Points from ``vertex`` x, y, z; normals from nx, ny, nz if all present; triangles
        fanned from the ``face`` lists.

    Raises
    ------
    MeshFileError
    """
    with _reading(path) as data:
        end = data.find(b"end_header")
        if not data.startswith(b"ply") or end < 0:
            raise ValueError("not a PLY file (no 'ply' ... 'end_header' header)")
        body = data[data.find(b"\n", end) + 1:] if b"\n" in data[end:] else b""
        fmt, elements = None, []
        for words in (line.split() for line in data[:end].decode("ascii", "replace").splitlines()[1:]):
            if words[:1] == ["format"]:
                fmt = words[1]
            elif words[:1] == ["element"]:
                elements.append((words[1], int(words[2]), []))
            elif words[:1] == ["property"] and elements:
                if words[1] == "list":
                    elements[-1][2].append((words[4], _ply_type(words[2]), _ply_type(words[3])))
                else:
                    elements[-1][2].append((words[2], None, _ply_type(words[1])))
        if fmt not in ("ascii", "binary_little_endian", "binary_big_endian"):
            raise ValueError(f"unsupported PLY format {fmt!r}")
        found, pos = {}, 0
        tokens = body.split() if fmt == "ascii" else None
        for name, count, props in elements:
            if fmt == "ascii":
                values, pos = _ply_ascii_element(tokens, pos, count, props)
            else:
                values, pos = _ply_binary_element(body, pos, count, props, "<" if "little" in fmt else ">")
            found[name] = (count, values)
        _, vertex = found.get("vertex", (0, {}))
        if not {"x", "y", "z"} <= vertex.keys():
            raise ValueError("no 'vertex' element with x, y, z properties")
        points = np.column_stack([vertex["x"], vertex["y"], vertex["z"]])
        normals = np.column_stack([vertex[c] for c in ("nx", "ny", "nz")]) if {"nx", "ny", "nz"} <= vertex.keys() else None
        n_faces, face = found.get("face", (0, {}))
        lists = [name for e, _, props in elements if e == "face" for name, ctype, _ in props if ctype is not None]
        key = next((k for k in ("vertex_indices", "vertex_index") if k in lists), None)
        if key is None:
            raise ValueError("no 'face' element with a vertex_indices list")
        return _mesh(points, _polygon_triangles(*_split_counted(face[key], n_faces)), normals)


# ---------------------------------------------------------------------------------------
# OBJ


def _obj_index(text, count, what):
    """0-based index of a 1-based (or negative, relative) OBJ index among ``count`` items."""
    i = int(text)
    if i == 0:
        raise ValueError(f"{what} index 0 (OBJ indices start at 1)")
    return i - 1 if i > 0 else count + i


def read_obj(path) -> Mesh:
    """Read a Wavefront OBJ file: ``v``, ``vn`` and ``f`` statements.

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    Mesh
        Points are the ``v`` rows; faces are fan-triangulated; normals only if each point
        used by a face is always paired with one and the same ``vn``.

    Raises
    ------
    MeshFileError
    """
    with _reading(path) as data:
        v, vn, faces, corners = [], [], [], []  # corners: (point, normal or -1)
        for number, line in enumerate(data.decode("utf-8", "replace").splitlines(), 1):
            words = line.split()
            try:
                if words[:1] in (["v"], ["vn"]):
                    if len(words) < 4:
                        raise ValueError("fewer than 3 coordinates")
                    (v if words[0] == "v" else vn).append([float(x) for x in words[1:4]])
                elif words[:1] == ["f"]:
                    face = []
                    for corner in words[1:]:
                        parts = corner.split("/")
                        face.append(_obj_index(parts[0], len(v), "vertex"))
                        has_normal = len(parts) > 2 and parts[2]
                        corners.append((face[-1], _obj_index(parts[2], len(vn), "normal") if has_normal else -1))
                    faces.append(face)
            except ValueError as exc:
                raise ValueError(f"line {number}: {exc}") from None
        corners = np.array(corners, dtype=np.int64).reshape(-1, 2)
        point_of, normal_of = corners[:, 0], corners[:, 1]
        if len(corners) and (point_of.min() < 0 or point_of.max() >= len(v)):
            bad = point_of[(point_of < 0) | (point_of >= len(v))][0]
            raise ValueError(f"a face refers to vertex {bad + 1}, but there are {len(v)}")
        normals = None
        if vn and len(corners) and (normal_of >= 0).all():
            if normal_of.max() >= len(vn):
                raise ValueError(f"a face refers to normal {normal_of.max() + 1}, but there are {len(vn)}")
            pairing = np.full(len(v), -1)
            pairing[point_of] = normal_of
            if (pairing[point_of] == normal_of).all():  # each point has one normal
                normals = np.zeros((len(v), 3))
                normals[pairing >= 0] = np.array(vn)[pairing[pairing >= 0]]
        return _mesh(np.array(v).reshape(-1, 3), fan_triangulate(faces), normals)


# ---------------------------------------------------------------------------------------
# STL


def read_stl(path) -> Mesh:
    """Read an STL file, binary or ascii, merging exactly equal vertices.

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    Mesh
        Points in order of first occurrence; one triangle per facet; no point normals.

    Raises
    ------
    MeshFileError
    """
    with _reading(path) as data:
        n = struct.unpack_from("<I", data, 80)[0] if len(data) >= 84 else -1
        ascii_stl = data.lstrip()[:5].lower() == b"solid" and b"endloop" in data
        if len(data) == 84 + 50 * n or (n > 0 and len(data) > 84 + 50 * n and not ascii_stl):
            facet = np.dtype([("normal", "<f4", 3), ("corners", "<f4", (3, 3)), ("attribute", "<u2")])
            corners = np.frombuffer(data, facet, n, 84)["corners"].reshape(-1, 3)
        elif ascii_stl:
            text = data.decode("ascii", "replace")
            corners = np.array(re.findall(r"^\s*vertex\s+(\S+)\s+(\S+)\s+(\S+)", text, re.M), dtype=np.float64)
            if len(corners) != 3 * len(re.findall(r"^\s*endloop\b", text, re.M)):
                raise ValueError("an ascii STL facet without exactly 3 vertices")
        else:
            raise ValueError("not an STL file (neither binary nor ascii 'solid')")
        corners = corners.reshape(-1, 3).astype(np.float64)
        _, first, inverse = np.unique(corners, axis=0, return_index=True, return_inverse=True)
        order = np.argsort(first)  # unique points by first occurrence
        rank = np.empty_like(order)
        rank[order] = np.arange(len(order))
        return _mesh(corners[first[order]], rank[inverse.reshape(-1)].reshape(-1, 3))


# ---------------------------------------------------------------------------------------
# Legacy VTK

_VTK_TYPES = {"bit": "u1", "unsigned_char": "u1", "char": "i1", "signed_char": "i1", "unsigned_short": "u2",
              "short": "i2", "unsigned_int": "u4", "int": "i4", "unsigned_long": "u8", "long": "i8",
              "vtktypeint64": "i8", "vtktypeuint64": "u8", "vtkidtype": "i4", "float": "f4", "double": "f8"}


class _Legacy:
    """A cursor over a legacy VTK file: keyword lines, each followed by ASCII or binary data."""

    def __init__(self, data, pos, binary):
        self.data, self.pos, self.binary = data, pos, binary

    def line(self):
        """Words of the next non-blank line; [] at the end of the file."""
        while self.pos < len(self.data):
            end = self.data.find(b"\n", self.pos)
            end = len(self.data) if end < 0 else end
            words = self.data[self.pos:end].decode("latin-1").split()
            self.pos = end + 1
            if words:
                return words
        return []

    def values(self, n, vtk_type):
        """The next ``n`` values of a VTK type (big-endian when binary)."""
        if vtk_type.lower() not in _VTK_TYPES:
            raise ValueError(f"unsupported legacy VTK data type {vtk_type!r}")
        dtype = np.dtype(_VTK_TYPES[vtk_type.lower()]).newbyteorder(">")
        if self.binary:
            nbytes = (n + 7) // 8 if vtk_type == "bit" else n * dtype.itemsize
            values = np.frombuffer(self.data, dtype, nbytes // dtype.itemsize, self.pos)
            self.pos += nbytes
            return values
        words = self.data[self.pos:].split(None, n)
        if len(words) < n:
            raise ValueError("file ends inside a data array")
        self.pos = len(self.data) - (len(words[n]) if len(words) > n else 0)
        return np.array(words[:n]).astype(np.float64 if dtype.kind == "f" else np.int64)

    def cells(self, n, size):
        """(offsets, connectivity) of a cell section, classic or 5.1 (OFFSETS) layout."""
        start = self.pos
        words = self.line()
        if words[:1] != ["OFFSETS"]:
            self.pos = start
            return _split_counted(self.values(size, "int"), n)
        offsets = self.values(n, words[1])
        words = self.line()
        if words[:1] != ["CONNECTIVITY"]:
            raise ValueError("OFFSETS without CONNECTIVITY")
        return offsets, self.values(size, words[1])


def read_vtk_legacy(path) -> Mesh:
    """Read a legacy ``.vtk`` file holding ``DATASET POLYDATA``, ASCII or BINARY.

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    Mesh
        Triangles of POLYGONS, then of TRIANGLE_STRIPS; normals from POINT_DATA NORMALS.

    Raises
    ------
    MeshFileError
    """
    with _reading(path) as data:
        head = data.split(b"\n", 3)
        if not data.startswith(b"# vtk DataFile") or len(head) < 4:
            raise ValueError("not a legacy VTK file (no '# vtk DataFile' header)")
        mode = head[2].strip().upper()
        if mode not in (b"ASCII", b"BINARY"):
            raise ValueError(f"third line must be ASCII or BINARY, not {head[2].strip()[:20]!r}")
        f = _Legacy(data, len(data) - len(head[3]), mode == b"BINARY")
        words = f.line()
        if [w.upper() for w in words[:2]] != ["DATASET", "POLYDATA"]:
            raise ValueError(f"only DATASET POLYDATA is supported, not {' '.join(words)[:40]!r}")
        points = normals = None
        polys, strips = (np.zeros(1), np.zeros(0)), (np.zeros(1), np.zeros(0))
        n_values, point_data = 0, False  # tuples per attribute in the current *_DATA section
        byte = "unsigned_char" if f.binary else "float"
        sizes = {"VECTORS": 3, "NORMALS": 3, "TENSORS": 9, "TENSORS6": 6}  # components; type in words[2]
        while words := f.line():
            key = words[0].upper()
            if key == "POINTS":
                points = f.values(3 * int(words[1]), words[2])
            elif key in ("VERTICES", "LINES", "POLYGONS", "TRIANGLE_STRIPS"):
                cells = f.cells(int(words[1]), int(words[2]))
                polys = cells if key == "POLYGONS" else polys
                strips = cells if key == "TRIANGLE_STRIPS" else strips
            elif key in ("POINT_DATA", "CELL_DATA"):
                n_values, point_data = int(words[1]), key == "POINT_DATA"
            elif key in sizes:
                values = f.values(sizes[key] * n_values, words[2])
                if key == "NORMALS" and point_data and normals is None:
                    normals = values
            elif key == "SCALARS":
                if f.line()[:1] != ["LOOKUP_TABLE"]:
                    raise ValueError("SCALARS without LOOKUP_TABLE")
                f.values(n_values * (int(words[3]) if len(words) > 3 else 1), words[2])
            elif key in ("GLOBAL_IDS", "PEDIGREE_IDS"):
                f.values(n_values, words[2])
            elif key == "TEXTURE_COORDINATES":
                f.values(n_values * int(words[2]), words[3])
            elif key == "COLOR_SCALARS":
                f.values(n_values * int(words[2]), byte)
            elif key == "LOOKUP_TABLE":
                f.values(4 * int(words[2]), byte)
            elif key == "FIELD":
                for _ in range(int(words[2])):
                    array = f.line()
                    if array[:1] != ["NULL_ARRAY"]:
                        f.values(int(array[1]) * int(array[2]), array[3])
            elif key == "METADATA":  # information keys, up to an empty line
                end = re.compile(rb"\n[ \t\r]*\n").search(data, f.pos - 1)
                f.pos = len(data) if end is None else end.end()
            else:
                raise ValueError(f"unexpected keyword {words[0][:40]!r}")
        if points is None:
            raise ValueError("no POINTS")
        triangles = np.concatenate([_polygon_triangles(*polys), _strip_triangles(*strips)])
        return _mesh(points, triangles, normals)


# ---------------------------------------------------------------------------------------
# VTP (VTK XML PolyData)

_VTP_TYPES = {"Int8": "i1", "UInt8": "u1", "Int16": "i2", "UInt16": "u2", "Int32": "i4", "UInt32": "u4",
              "Int64": "i8", "UInt64": "u8", "Float32": "f4", "Float64": "f8"}


def _b64decode(text):
    """Decode base64 made of separately padded chunks (VTK encodes header and data apart)."""
    text = re.sub(rb"\s+", b"", text)
    return b"".join(base64.b64decode(chunk, validate=True) for chunk in re.findall(rb"[^=]*=*", text) if chunk)


def _vtp_unpack(raw, dtype, header, compressed):
    """Values of one binary DataArray: a size header, then plain or zlib-blocked bytes."""
    if not compressed:
        nbytes = int(np.frombuffer(raw, header, 1)[0])
        body = raw[header.itemsize:header.itemsize + nbytes]
        if len(body) != nbytes:
            raise ValueError("binary data array is truncated")
    else:
        n_blocks = int(np.frombuffer(raw, header, 1)[0])
        pos = (3 + n_blocks) * header.itemsize
        blocks = []
        for size in np.frombuffer(raw, header, n_blocks, 3 * header.itemsize).astype(np.int64):
            blocks.append(zlib.decompress(raw[pos:pos + size]))
            pos += size
        body = b"".join(blocks)
    return np.frombuffer(body[: len(body) // dtype.itemsize * dtype.itemsize], dtype)


def _vtp_normals_array(piece):
    """The PointData DataArray named by ``Normals="..."``, else a 3-component "Normals"."""
    point_data = piece.find("PointData")
    arrays = [] if point_data is None else point_data.findall("DataArray")
    named = [a for a in arrays if a.get("Name") == point_data.get("Normals")]
    fallback = [a for a in arrays if a.get("Name") == "Normals" and a.get("NumberOfComponents") == "3"]
    return (named or fallback or [None])[0]


def read_vtp(path) -> Mesh:
    """Read a VTK XML PolyData (``.vtp``) file.

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    Mesh
        Points of all pieces; triangles of Polys, then of Strips; point normals if every
        piece has them.

    Raises
    ------
    MeshFileError
    """
    with _reading(path) as data:
        start = data.find(b"<AppendedData")
        appended, encoding = b"", "raw"
        if start >= 0:  # raw appended bytes are not XML: cut them off after the '_'
            underscore = data.index(b"_", data.index(b">", start))
            encoding = ET.fromstring(data[start:data.index(b">", start)] + b"/>").get("encoding", "raw")
            data, appended = data[:underscore] + b"</AppendedData></VTKFile>", data[underscore + 1:]
        root = ET.fromstring(data)
        if root.tag != "VTKFile" or root.get("type") != "PolyData":
            raise ValueError("not a VTK XML PolyData file")
        if root.get("compressor", "vtkZLibDataCompressor") != "vtkZLibDataCompressor":
            raise ValueError(f"unsupported compressor {root.get('compressor')!r}")
        order = "<" if root.get("byte_order", "LittleEndian") == "LittleEndian" else ">"
        header = np.dtype(_VTP_TYPES[root.get("header_type", "UInt32")]).newbyteorder(order)

        def array(element, what):
            if element is None:
                raise ValueError(f"no {what} DataArray")
            dtype = np.dtype(_VTP_TYPES[element.get("type")]).newbyteorder(order)
            fmt = element.get("format")
            if fmt == "ascii":
                return np.array((element.text or "").split()).astype(dtype.newbyteorder("="))
            if fmt == "binary":
                raw = _b64decode((element.text or "").encode())
            elif fmt == "appended":
                raw = appended[int(element.get("offset")):]
                raw = raw if encoding == "raw" else _b64decode(raw.split(b"<")[0])
            else:
                raise ValueError(f"unknown DataArray format {fmt!r}")
            return _vtp_unpack(raw, dtype, header, root.get("compressor") is not None)

        def cells(piece, kind):
            n = int(piece.get(f"NumberOf{kind}", 0))
            if n == 0:
                return np.zeros(1, np.int64), np.zeros(0, np.int64)
            offsets = array(piece.find(f"{kind}/DataArray[@Name='offsets']"), f"{kind} offsets")
            connectivity = array(piece.find(f"{kind}/DataArray[@Name='connectivity']"), f"{kind} connectivity")
            if len(offsets) == n:  # end offsets of each cell (the usual layout)
                offsets = np.concatenate([[0], offsets])
            return offsets, connectivity

        points, polys, strips, normals = [], [], [], []
        for piece in root.iter("Piece"):
            base = sum(len(p) for p in points)
            points.append(array(piece.find("Points/DataArray"), "Points").reshape(-1, 3))
            polys.append(_polygon_triangles(*cells(piece, "Polys")) + base)
            strips.append(_strip_triangles(*cells(piece, "Strips")) + base)
            found = _vtp_normals_array(piece)
            normals.append(None if found is None else array(found, "Normals"))
        if not points:
            raise ValueError("no Piece")
        normals = None if any(n is None for n in normals) else np.concatenate(normals)
        return _mesh(np.concatenate(points), np.concatenate(polys + strips), normals)
