"""PLY reader: ascii and binary (either byte order); vertex x y z [nx ny nz] [u v], face lists."""
from __future__ import annotations

import numpy as np

from lab.mesh import Mesh
from lab.meshfiles._common import make_mesh, polygon_triangles, reading, split_counted


_PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
              "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
              "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}


# Vertex properties holding texture coordinates, in the order of preference of VTK's PLY
# reader (checked with VTK 9.7: a file with two pairs gives the first pair found here).
_PLY_TCOORDS = (("u", "v"), ("texture_u", "texture_v"), ("s", "t"))


def _ply_type(name):
    """numpy dtype of a PLY type name."""
    if name not in _PLY_TYPES:
        raise ValueError(f"unknown PLY property type {name!r}")
    return np.dtype(_PLY_TYPES[name])


def _ply_ascii_element(tokens, pos, count, props):
    """Read one element from ASCII tokens: ({name: values}, next position).

    Scalar properties give one value per record, parsed as their declared type (as VTK
    does); list properties give the counted form ``[k, v1..vk, k, ...]``.
    """
    # Fast path: if every record has the list lengths of the first one, records are equally long.
    widths, p = [], pos
    for _, ctype, _ in props:
        widths.append(1 if ctype is None or not count else 1 + int(tokens[p]))
        p += widths[-1]
    starts = np.cumsum([0] + widths[:-1])
    if pos + count * sum(widths) <= len(tokens):
        table = np.array(tokens[pos:pos + count * sum(widths)]).reshape(count, sum(widths))
        if all(ctype is None or (table[:, s].astype(np.int64) == w - 1).all()
               for s, w, (_, ctype, _) in zip(starts, widths, props)):
            return {name: table[:, s].astype(vtype) if ctype is None else table[:, s:s + w].astype(np.float64).ravel()
                    for s, w, (name, ctype, vtype) in zip(starts, widths, props)}, pos + count * sum(widths)
    # Slow path: record by record.
    columns = {name: [] for name, _, _ in props}
    for _ in range(count):
        for name, ctype, _ in props:
            if pos >= len(tokens):
                raise ValueError("file ends inside the PLY data")
            n = 1 if ctype is None else 1 + int(tokens[pos])
            columns[name].extend(tokens[pos:pos + n])
            pos += n
    types = {name: np.float64 if ctype is not None else vtype for name, ctype, vtype in props}
    return {name: np.array(v).astype(types[name]) for name, v in columns.items()}, pos


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
        Points from ``vertex`` x, y, z; normals from nx, ny, nz if all present; texture
        coordinates from u, v, else texture_u, texture_v, else s, t (VTK's choice), at
        the precision of the file (VTK rounds them to float32); triangles fanned from the
        ``face`` lists. Per-corner ``texcoord`` lists of faces are ignored (VTK splits
        points for them).

    Raises
    ------
    MeshFileError
    """
    with reading(path) as data:
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
            if {"vertex", "face"} <= found.keys():
                break  # later elements are not needed
            if fmt == "ascii":
                values, pos = _ply_ascii_element(tokens, pos, count, props)
            else:
                values, pos = _ply_binary_element(body, pos, count, props, "<" if "little" in fmt else ">")
            found[name] = (count, values)
        _, vertex = found.get("vertex", (0, {}))
        if not {"x", "y", "z"} <= vertex.keys():
            raise ValueError("no 'vertex' element with x, y, z properties")
        points = np.column_stack([vertex["x"], vertex["y"], vertex["z"]])
        normals = None
        if {"nx", "ny", "nz"} <= vertex.keys():
            normals = np.column_stack([vertex["nx"], vertex["ny"], vertex["nz"]])
        pair = next((p for p in _PLY_TCOORDS if set(p) <= vertex.keys()), None)
        tcoords = None if pair is None else np.column_stack([vertex[pair[0]], vertex[pair[1]]])
        n_faces, face = found.get("face", (0, {}))
        lists = [name for e, _, props in elements if e == "face" for name, ctype, _ in props if ctype is not None]
        key = next((k for k in ("vertex_indices", "vertex_index") if k in lists), None)
        if key is None:
            raise ValueError("no 'face' element with a vertex_indices list")
        return make_mesh(points, polygon_triangles(*split_counted(face[key], n_faces)), normals, tcoords)
