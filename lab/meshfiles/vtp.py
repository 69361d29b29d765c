"""VTK XML PolyData (``.vtp``) reader: ascii, base64 binary (maybe zlib), appended raw or base64."""
from __future__ import annotations

import base64
import re
import xml.etree.ElementTree as ET
import zlib

import numpy as np

from lab.mesh import Mesh
from lab.meshfiles._common import make_mesh, polygon_triangles, reading, strip_triangles


_VTP_TYPES = {"Int8": "i1", "UInt8": "u1", "Int16": "i2", "UInt16": "u2", "Int32": "i4", "UInt32": "u4",
              "Int64": "i8", "UInt64": "u8", "Float32": "f4", "Float64": "f8"}


def _vtp_dtype(name, order):
    """numpy dtype of a VTK XML type name, in the file's byte order."""
    if name not in _VTP_TYPES:
        raise ValueError(f"unknown VTK XML data type {name!r}")
    return np.dtype(_VTP_TYPES[name]).newbyteorder(order)


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
    if point_data is None:
        return None
    arrays = point_data.findall("DataArray")
    named = [a for a in arrays if a.get("Name") == point_data.get("Normals")]
    fallback = [a for a in arrays if a.get("Name") == "Normals" and a.get("NumberOfComponents") == "3"]
    return (named or fallback or [None])[0]


def _vtp_tcoords_array(piece):
    """The 2-component PointData DataArray named by ``TCoords="..."`` (VTK's active one), or None."""
    point_data = piece.find("PointData")
    if point_data is None or point_data.get("TCoords") is None:
        return None
    named = [a for a in point_data.findall("DataArray") if a.get("Name") == point_data.get("TCoords")]
    return named[0] if named and named[0].get("NumberOfComponents", "1") == "2" else None


def read_vtp(path) -> Mesh:
    """Read a VTK XML PolyData (``.vtp``) file.

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    Mesh
        Points of all pieces; triangles of Polys, then of Strips; point normals if every
        piece has them; texture coordinates (the 2-component PointData array named by the
        ``TCoords`` attribute) if every piece has them.

    Raises
    ------
    MeshFileError
    """
    with reading(path) as data:
        start = data.find(b"<AppendedData")
        appended, encoding = b"", "raw"
        if start >= 0:  # raw appended bytes are not XML: cut them off after the '_'
            underscore = data.find(b"_", data.find(b">", start))
            if underscore < 0:
                raise ValueError("AppendedData without its '_' marker")
            encoding = ET.fromstring(data[start:data.index(b">", start)] + b"/>").get("encoding", "raw")
            data, appended = data[:underscore] + b"</AppendedData></VTKFile>", data[underscore + 1:]
        root = ET.fromstring(data)
        if root.tag != "VTKFile" or root.get("type") != "PolyData":
            raise ValueError("not a VTK XML PolyData file")
        if root.get("compressor", "vtkZLibDataCompressor") != "vtkZLibDataCompressor":
            raise ValueError(f"unsupported compressor {root.get('compressor')!r}")
        order = "<" if root.get("byte_order", "LittleEndian") == "LittleEndian" else ">"
        header = _vtp_dtype(root.get("header_type", "UInt32"), order)

        def array(element, what):
            if element is None:
                raise ValueError(f"no {what} DataArray")
            dtype = _vtp_dtype(element.get("type"), order)
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

        points, polys, strips, normals, tcoords = [], [], [], [], []
        for piece in root.iter("Piece"):
            base = sum(len(p) for p in points)
            points.append(array(piece.find("Points/DataArray"), "Points").reshape(-1, 3))
            polys.append(polygon_triangles(*cells(piece, "Polys")) + base)
            strips.append(strip_triangles(*cells(piece, "Strips")) + base)
            found = _vtp_normals_array(piece)
            normals.append(None if found is None else array(found, "Normals"))
            found = _vtp_tcoords_array(piece)
            tcoords.append(None if found is None else array(found, "TCoords"))
        if not points:
            raise ValueError("no Piece")
        normals = None if any(n is None for n in normals) else np.concatenate(normals)
        tcoords = None if any(t is None for t in tcoords) else np.concatenate(tcoords)
        return make_mesh(np.concatenate(points), np.concatenate(polys + strips), normals, tcoords)
